/* SPDX-License-Identifier: GPL-3.0-or-later */
/* mex_hb_estimates.c — the gateway's commands that judge a solved point of a harmonic-balance
 * driver (fricreg_hb.h) rather than solve anew: the truncation error of a point of the forced
 * response (fricreg_hb_truncation_error), the exact sensitivities of a backbone point in the
 * model's parameters (fricreg_hb_nma_point_sensitivities) and the stuck modes' shares in one of
 * its harmonics (fricreg_hb_nma_modal_participation). A failed call raises
 * fricreg:<NAME> with the driver's message.
 *
 * Indices are MATLAB's, from 1: points, elements, and an element's parameter in its type's
 * layout (jenkins 1 kt, 2 mun); the library's from 0. */
#include <math.h>

#include "mex_args.h"
#include "mex_hb.h"

/* [rms_error, amplitude_error] = hb_truncation_error(h, point): point from 1 along the last
 * branch, or 0 for the last solution; each 1 x ndof, displacement units. */
void mexhb_truncation_error(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    const char *cmd = "hb_truncation_error";
    mxArray *out[2];
    size_t point;
    mexhb *d;
    mexa_nargs(cmd, nrhs, 2, 2, nlhs, 2);
    d = mexhb_of(prhs[0], cmd);
    point = mexa_count(prhs[1], cmd, "point", 0, (size_t)1 << 40);
    out[0] = mexa_matrix(1, d->ndof);
    out[1] = mexa_matrix(1, d->ndof);
    /* 1 x ndof rows: MATLAB's storage is the library's vector order, written in place */
    mexhb_check(d,
                fricreg_hb_truncation_error(d->hb, point == 0 ? FRICREG_HB_SOLUTION : point - 1,
                                            d->ndof, mxGetPr(out[0]), mxGetPr(out[1])),
                cmd);
    mexa_outputs(nlhs, plhs, out, 2);
}

/* Entry i of a vector of whole numbers >= lo (fricreg:EINVAL naming it where not). */
static size_t whole(const double *v, size_t i, const char *cmd, const char *name, double lo)
{
    if (!(v[i] >= lo && v[i] <= 1e15 && v[i] == floor(v[i])))
        mexa_error("fricreg:EINVAL",
                   "%s: %s(%lu) = %g must be a whole number >= %g (FRICREG_EINVAL)", cmd, name,
                   (unsigned long)i + 1, v[i], lo);
    return (size_t)v[i];
}

/* [domega, dzeta, damp] = hb_nma_sensitivities(h, point, kind, first, count, index,
 * amplitudes): the derivatives of backbone point `point` (from 1) in np parameters, kind(k)
 * an enum fricreg_hb_nma_param (0 element, 1 damping, 2 amplitude); for an element parameter
 * first(k) (from 1), count(k) and index(k) (from 1); for the damping index(k) 1 zeta_k, 2 a0,
 * 3 a1; the other entries ignored. domega, dzeta np x 1; damp np x ndof (d|X_1,j|/dp_k) only
 * when amplitudes is true, else []. */
void mexhb_nma_sensitivities(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    static const char *const names[] = {"kind", "first", "count", "index"};
    const char *cmd = "hb_nma_sensitivities";
    const double *v[4];
    size_t np = 0, point, *first, *count, *index;
    int *kind, amplitudes;
    double *damp = NULL;
    mxArray *out[3];
    mexhb *d;
    mexa_nargs(cmd, nrhs, 7, 7, nlhs, 3);
    d = mexhb_of(prhs[0], cmd);
    point = mexa_count(prhs[1], cmd, "point", 1, (size_t)1 << 40) - 1; /* MATLAB's from 1 */
    v[0] = mexa_vector(prhs[2], cmd, names[0], (size_t)-1, &np);
    for (int j = 1; j < 4; j++)
        v[j] = mexa_vector(prhs[3 + j - 1], cmd, names[j], np, NULL);
    amplitudes = mxIsLogical(prhs[6]) && mxGetNumberOfElements(prhs[6]) == 1
                     ? (int)mxIsLogicalScalarTrue(prhs[6])
                     : (int)mexa_count(prhs[6], cmd, "amplitudes", 0, 1);
    kind = mxCalloc(np + 1, sizeof *kind);
    first = mxCalloc(np + 1, sizeof *first);
    count = mxCalloc(np + 1, sizeof *count);
    index = mxCalloc(np + 1, sizeof *index);
    for (size_t k = 0; k < np; k++) {
        kind[k] = (int)whole(v[0], k, cmd, names[0], 0); /* the library judges the kind */
        if (kind[k] == FRICREG_HB_NMA_PARAM_ELEMENT) {
            first[k] = whole(v[1], k, cmd, names[1], 1) - 1;
            count[k] = whole(v[2], k, cmd, names[2], 0);
            index[k] = whole(v[3], k, cmd, names[3], 1) - 1;
        } else if (kind[k] == FRICREG_HB_NMA_PARAM_DAMPING) {
            index[k] = whole(v[3], k, cmd, names[3], 1) - 1;
        }
    }
    out[0] = mexa_matrix(np, 1);
    out[1] = mexa_matrix(np, 1);
    out[2] = mexa_matrix(amplitudes ? np : 0, amplitudes ? d->ndof : 0);
    if (amplitudes)
        damp = mexa_scratch(np * d->ndof);
    mexhb_check(d,
                fricreg_hb_nma_point_sensitivities(d->hb, point, np, kind, first, count, index,
                                                   mxGetPr(out[0]), mxGetPr(out[1]), d->ndof, damp),
                cmd);
    if (amplitudes) /* a copy: np x ndof row-major to column-major */
        mexa_to_cols(damp, mxGetPr(out[2]), np, d->ndof);
    mexa_outputs(nlhs, plhs, out, 3);
}

/* fraction = hb_modal_participation(h, point, harmonic): each stuck linear mode's share (1 x
 * ndof, the lowest first, summing to 1) in harmonic h (0..H) of backbone point `point` (from
 * 1) (fricreg_hb_nma_modal_participation). */
void mexhb_modal_participation(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    const char *cmd = "hb_modal_participation";
    size_t point;
    int harmonic;
    mxArray *out;
    mexhb *d;
    mexa_nargs(cmd, nrhs, 3, 3, nlhs, 1);
    d = mexhb_of(prhs[0], cmd);
    point = mexa_count(prhs[1], cmd, "point", 1, (size_t)1 << 40) - 1; /* MATLAB's from 1 */
    harmonic = (int)mexa_count(prhs[2], cmd, "harmonic", 0, 1000000);
    out = mexa_matrix(1, d->ndof);
    mexhb_check(d,
                fricreg_hb_nma_modal_participation(d->hb, point, harmonic, d->ndof, mxGetPr(out)),
                cmd);
    plhs[0] = out;
}
