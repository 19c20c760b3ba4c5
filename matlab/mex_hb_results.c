/* SPDX-License-Identifier: GPL-3.0-or-later */
/* mex_hb_results.c — the gateway's solving commands on a harmonic-balance driver
 * (fricreg_hb.h) and what they return: a solution at one frequency, a branch in the frequency
 * or in the excitation level with its stability, Floquet multipliers and bifurcations, a
 * nonlinear mode's backbone, a peak. One C
 * solving call per command, then its getters; a failed call raises fricreg:<NAME> with the
 * driver's message (the points a failed continuation kept stay in the driver, unread).
 *
 * Layout: the library keeps Fourier coefficients row after row, (x0, a_1, b_1, ..., a_H, b_H)
 * a row; MATLAB gets them as arrays whose last dimension is the coefficient: q rows x (2H + 1),
 * x ndof x (2H + 1), a branch's x npoints x ndof x (2H + 1), copied at the boundary. Indices
 * are MATLAB's, from 1: a mode, a dof, the point before a bifurcation. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "mex_args.h"
#include "mex_hb.h"

/* Optional guess q0 (rows x nc) in argument a (absent or []: NULL), as the library's row-major
 * copy. */
static const double *guess(const mexhb *d, int nrhs, const mxArray *prhs[], int at, const char *cmd)
{
    size_t nc = (size_t)(2 * d->harmonics + 1);
    double *q0;
    if (nrhs <= at || mxIsEmpty(prhs[at])) {
        if (nrhs > at)
            mexa_real(prhs[at], cmd, "guess");
        return NULL;
    }
    mexa_real(prhs[at], cmd, "guess");
    if (!mexa_is_size(prhs[at], d->rows, nc))
        mexa_error("fricreg:size",
                   "%s: guess must be rows x (2H + 1) = %lux%lu (a row of q per "
                   "row of the elements' J), not %dx%d",
                   cmd, (unsigned long)d->rows, (unsigned long)nc, (int)mxGetM(prhs[at]),
                   (int)mxGetN(prhs[at]));
    q0 = mexa_scratch(d->rows * nc);
    mexa_to_rows(mxGetPr(prhs[at]), q0, d->rows, nc);
    return q0;
}

/* A stored point's (or, k = FRICREG_HB_SOLUTION, the solution's) stability into stable[i],
 * mu_max[i]. */
static void stability_of(const mexhb *d, size_t k, mxLogical *stable, double *mu_max,
                         const char *cmd)
{
    int s = 0;
    double mu = 0.0;
    mexhb_check(d, fricreg_hb_point_stability(d->hb, k, &s, &mu), cmd);
    *stable = s != 0;
    *mu_max = mu;
}

/* A multiplier's modulus and its place in the library's order: the sort key. */
typedef struct {
    double modulus;
    size_t at;
} ranked;

/* By decreasing modulus, ties in the library's order (Python's stable argsort of -|mu|). */
static int by_modulus(const void *a, const void *b)
{
    const ranked *x = a, *y = b;
    if (x->modulus != y->modulus)
        return x->modulus < y->modulus ? 1 : -1;
    return x->at < y->at ? -1 : x->at > y->at;
}

/* Scratch for the multipliers of one point: 2 ndof exponents (Re, Im) and their ranks. */
typedef struct {
    double *exponents;
    ranked *rank;
} floquet;

static floquet floquet_scratch(const mexhb *d)
{
    floquet f;
    f.exponents = mexa_scratch(4 * d->ndof);
    f.rank = mxCalloc(2 * d->ndof, sizeof *f.rank);
    return f;
}

/* The Floquet multipliers mu = exp(2 pi lambda / omega) of stored point k (or the solution,
 * FRICREG_HB_SOLUTION) at its frequency omega, from fricreg_hb_point_exponents, by decreasing
 * modulus, into row `row` of the complex n x (2 ndof) array (re, im): column-major. */
static void multipliers_of(const mexhb *d, size_t k, double omega, floquet f, double *re,
                           double *im, size_t n, size_t row, const char *cmd)
{
    size_t ne = 2 * d->ndof;
    const double period = 2.0 * 3.14159265358979323846 / omega;
    mexhb_check(d, fricreg_hb_point_exponents(d->hb, k, ne, f.exponents), cmd);
    for (size_t j = 0; j < ne; j++) {
        f.rank[j].modulus = exp(period * f.exponents[2 * j]);
        f.rank[j].at = j;
    }
    qsort(f.rank, ne, sizeof *f.rank, by_modulus);
    for (size_t j = 0; j < ne; j++) {
        const double *e = f.exponents + 2 * f.rank[j].at;
        re[row + n * j] = f.rank[j].modulus * cos(period * e[1]);
        im[row + n * j] = f.rank[j].modulus * sin(period * e[1]);
    }
}

/* [q, x, stable, mu_max, multipliers] = hb_solve(h, omega [, q0]): q rows x nc, x ndof x nc;
 * stable a logical, mu_max the largest |Floquet multiplier| and multipliers the 1 x (2 ndof)
 * complex multipliers by decreasing modulus with stability on, else [], NaN and []. */
void mexhb_solve(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    const char *cmd = "hb_solve";
    const double *q0;
    double omega, *q, *x;
    size_t nc;
    mxArray *out[5];
    mexhb *d;
    mexa_nargs(cmd, nrhs, 2, 3, nlhs, 5);
    d = mexhb_of(prhs[0], cmd);
    omega = mexa_scalar(prhs[1], cmd, "omega");
    q0 = guess(d, nrhs, prhs, 2, cmd);
    nc = (size_t)(2 * d->harmonics + 1);
    q = mexa_scratch(d->rows * nc);
    mexhb_check(d, fricreg_hb_solve(d->hb, omega, d->rows * nc, q0, q), cmd);
    out[0] = mexa_matrix(d->rows, nc);
    mexa_to_cols(q, mxGetPr(out[0]), d->rows, nc);
    x = mexa_scratch(d->ndof * nc);
    mexhb_check(d, fricreg_hb_displacement(d->hb, d->ndof, nc, x), cmd);
    out[1] = mexa_matrix(d->ndof, nc);
    mexa_to_cols(x, mxGetPr(out[1]), d->ndof, nc);
    if (d->stability) {
        out[2] = mxCreateLogicalMatrix(1, 1);
        out[3] = mexa_matrix(1, 1);
        stability_of(d, FRICREG_HB_SOLUTION, mxGetLogicals(out[2]), mxGetPr(out[3]), cmd);
        out[4] = mxCreateDoubleMatrix(1, (mwSize)(2 * d->ndof), mxCOMPLEX);
        multipliers_of(d, FRICREG_HB_SOLUTION, omega, floquet_scratch(d), mxGetPr(out[4]),
                       mxGetPi(out[4]), 1, 0, cmd);
    } else {
        out[2] = mexa_matrix(0, 0);
        out[3] = mxCreateDoubleScalar(mxGetNaN());
        out[4] = mexa_matrix(0, 0);
    }
    mexa_outputs(nlhs, plhs, out, 5);
}

/* The coefficients c[ndof nc] (row-major) of point k into xs, npoints x ndof x nc. */
static void put_point(double *xs, const double *c, size_t k, size_t n, size_t ndof, size_t nc)
{
    for (size_t j = 0; j < ndof; j++)
        for (size_t i = 0; i < nc; i++)
            xs[k + n * (j + ndof * i)] = c[nc * j + i];
}

/* The located bifurcations as a 1 x nb struct array: kind ('TP', 'BP', 'PD', 'NS'), omega,
 * level, point (the stored point before it, from 1), rms (1 x ndof). */
static mxArray *bifurcations(const mexhb *d, const char *cmd)
{
    static const char *fields[] = {"kind", "omega", "level", "point", "rms"};
    static const char *const kinds[] = {"?", "TP", "BP", "PD", "NS"};
    size_t nb = fricreg_hb_bifurcations(d->hb);
    mxArray *s = mxCreateStructMatrix(1, (mwSize)nb, 5, fields);
    for (size_t i = 0; i < nb; i++) {
        mxArray *rms = mexa_matrix(1, d->ndof);
        double omega = 0.0, level = 0.0;
        size_t point = 0;
        int type = 0;
        mexhb_check(d,
                    fricreg_hb_bifurcation(d->hb, i, &type, &omega, &point, d->ndof, mxGetPr(rms)),
                    cmd);
        mexhb_check(d, fricreg_hb_bifurcation_level(d->hb, i, &level), cmd);
        mxSetField(s, (mwIndex)i, "kind", mxCreateString(kinds[type >= 1 && type <= 4 ? type : 0]));
        mxSetField(s, (mwIndex)i, "omega", mxCreateDoubleScalar(omega));
        mxSetField(s, (mwIndex)i, "level", mxCreateDoubleScalar(level));
        mxSetField(s, (mwIndex)i, "point", mxCreateDoubleScalar((double)point + 1.0));
        mxSetField(s, (mwIndex)i, "rms", rms);
    }
    return s;
}

/* The stored branch (fricreg_hb_continue's or fricreg_hb_continue_level's), npoints points, as
 * the outputs [omega, level, rms, x, stable, mu_max, bifurcations, multipliers]: omega, level
 * npoints x 1, rms npoints x ndof, x npoints x ndof x nc (recomputed per point: only when
 * asked), stable (logical), mu_max npoints x 1 and multipliers npoints x (2 ndof) complex (only
 * when asked) with stability on (else []), bifurcations a struct array. */
static void branch_outputs(const mexhb *d, int nlhs, mxArray *plhs[], const char *cmd)
{
    size_t n = fricreg_hb_points(d->hb), nc = (size_t)(2 * d->harmonics + 1);
    int floquet_asked = d->stability && nlhs >= 8;
    double *rms, *c = NULL;
    mxArray *out[8];
    floquet f = {NULL, NULL};
    out[0] = mexa_matrix(n, 1);
    out[1] = mexa_matrix(n, 1);
    out[2] = mexa_matrix(n, d->ndof);
    out[3] = nlhs >= 4 ? mexa_array3(n, d->ndof, nc) : mexa_matrix(0, 0);
    out[4] = d->stability ? mxCreateLogicalMatrix((mwSize)n, 1) : mexa_matrix(0, 0);
    out[5] = d->stability ? mexa_matrix(n, 1) : mexa_matrix(0, 0);
    out[7] = floquet_asked ? mxCreateDoubleMatrix((mwSize)n, (mwSize)(2 * d->ndof), mxCOMPLEX)
                           : mexa_matrix(0, 0);
    rms = mexa_scratch(d->ndof);
    if (nlhs >= 4)
        c = mexa_scratch(d->ndof * nc);
    if (floquet_asked)
        f = floquet_scratch(d);
    for (size_t k = 0; k < n; k++) {
        double *omega = mxGetPr(out[0]) + k;
        mexhb_check(d, fricreg_hb_point(d->hb, k, omega, d->ndof, rms), cmd);
        mexhb_check(d, fricreg_hb_point_level(d->hb, k, mxGetPr(out[1]) + k), cmd);
        for (size_t j = 0; j < d->ndof; j++)
            mxGetPr(out[2])[k + n * j] = rms[j];
        if (c != NULL) {
            mexhb_check(d, fricreg_hb_point_displacement(d->hb, k, d->ndof, nc, c), cmd);
            put_point(mxGetPr(out[3]), c, k, n, d->ndof, nc);
        }
        if (d->stability)
            stability_of(d, k, mxGetLogicals(out[4]) + k, mxGetPr(out[5]) + k, cmd);
        if (floquet_asked)
            multipliers_of(d, k, *omega, f, mxGetPr(out[7]), mxGetPi(out[7]), n, k, cmd);
    }
    out[6] = bifurcations(d, cmd);
    mexa_outputs(nlhs, plhs, out, 8);
}

/* [omega, level, rms, x, stable, mu_max, bifurcations, multipliers] = hb_continue(h, omega0,
 * omega1 [, q0]): the branch of fricreg_hb_continue in the frequency (branch_outputs). */
void mexhb_continue(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    const char *cmd = "hb_continue";
    const double *q0;
    double omega0, omega1;
    mexhb *d;
    mexa_nargs(cmd, nrhs, 3, 4, nlhs, 8);
    d = mexhb_of(prhs[0], cmd);
    omega0 = mexa_scalar(prhs[1], cmd, "omega0");
    omega1 = mexa_scalar(prhs[2], cmd, "omega1");
    q0 = guess(d, nrhs, prhs, 3, cmd);
    mexhb_check(d,
                fricreg_hb_continue(d->hb, omega0, omega1, d->rows * (size_t)(2 * d->harmonics + 1),
                                    q0),
                cmd);
    branch_outputs(d, nlhs, plhs, cmd);
}

/* [omega, level, ...] = hb_continue_level(h, omega, level0, level1 [, q0]): the branch of
 * fricreg_hb_continue_level in the excitation level at the fixed omega (branch_outputs; level
 * each point's lambda). */
void mexhb_continue_level(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    const char *cmd = "hb_continue_level";
    const double *q0;
    double omega, level0, level1;
    mexhb *d;
    mexa_nargs(cmd, nrhs, 4, 5, nlhs, 8);
    d = mexhb_of(prhs[0], cmd);
    omega = mexa_scalar(prhs[1], cmd, "omega");
    level0 = mexa_scalar(prhs[2], cmd, "level0");
    level1 = mexa_scalar(prhs[3], cmd, "level1");
    q0 = guess(d, nrhs, prhs, 4, cmd);
    mexhb_check(d,
                fricreg_hb_continue_level(d->hb, omega, level0, level1,
                                          d->rows * (size_t)(2 * d->harmonics + 1), q0),
                cmd);
    branch_outputs(d, nlhs, plhs, cmd);
}

/* The backbone's special points as a 1 x ns struct array: kind ('fold', 'crossing'),
 * amplitude, omega, zeta, harmonic, mode (from 1). */
static mxArray *special_points(const mexhb *d, const char *cmd)
{
    static const char *fields[] = {"kind", "amplitude", "omega", "zeta", "harmonic", "mode"};
    size_t ns = fricreg_hb_nma_special_points(d->hb);
    mxArray *s = mxCreateStructMatrix(1, (mwSize)ns, 6, fields);
    for (size_t i = 0; i < ns; i++) {
        double a = 0.0, w = 0.0, z = 0.0;
        int type = 0, k = 0;
        size_t r = 0;
        mexhb_check(d, fricreg_hb_nma_special_point(d->hb, i, &type, &a, &w, &z, &k, &r), cmd);
        mxSetField(s, (mwIndex)i, "kind",
                   mxCreateString(type == FRICREG_HB_NMA_FOLD ? "fold" : "crossing"));
        mxSetField(s, (mwIndex)i, "amplitude", mxCreateDoubleScalar(a));
        mxSetField(s, (mwIndex)i, "omega", mxCreateDoubleScalar(w));
        mxSetField(s, (mwIndex)i, "zeta", mxCreateDoubleScalar(z));
        mxSetField(s, (mwIndex)i, "harmonic", mxCreateDoubleScalar((double)k));
        mxSetField(s, (mwIndex)i, "mode", mxCreateDoubleScalar((double)r + 1.0));
    }
    return s;
}

/* The mode (from 1) and the damping name of a backbone command's arguments. */
static void mode_damping(const mexhb *d, const mxArray *prhs[], const char *cmd, size_t *mode,
                         int *damping)
{
    char name[16];
    *mode = mexa_count(prhs[1], cmd, "mode", 1, d->ndof) - 1; /* MATLAB's from 1, C's from 0 */
    mexa_string(prhs[2], cmd, "damping", name, sizeof name);
    if (strcmp(name, "matrix") == 0)
        *damping = FRICREG_HB_NMA_DAMPING_MATRIX;
    else if (strcmp(name, "modal") == 0)
        *damping = FRICREG_HB_NMA_DAMPING_MODAL;
    else
        mexa_error("fricreg:EINVAL",
                   "%s: damping '%s' is not one of matrix, modal (FRICREG_EINVAL)", cmd, name);
}

/* [amplitude, omega, zeta, x, energy, special] = hb_nma(h, mode, damping, a0, a1, npoints,
 * through_folds) or hb_nma(h, mode, damping, amplitudes): the backbone of mode (from 1, the
 * lowest stuck mode 1) by fricreg_hb_nma (fricreg_hb_nma_continue with through_folds true) or
 * fricreg_hb_nma_at; amplitude, omega, zeta npoints x 1, x npoints x ndof x nc, energy
 * npoints x (H + 1) (only when asked), special a struct array. */
void mexhb_nma(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    const char *cmd = "hb_nma";
    size_t mode, n, nc;
    int damping, status;
    double *c = NULL;
    mxArray *out[6];
    mexhb *d;
    if (nrhs != 4)
        mexa_nargs(cmd, nrhs, 7, 7, nlhs, 6);
    mexa_nargs(cmd, nrhs, 4, 7, nlhs, 6);
    d = mexhb_of(prhs[0], cmd);
    mode_damping(d, prhs, cmd, &mode, &damping);
    if (nrhs == 4) {
        size_t na;
        const double *a = mexa_vector(prhs[3], cmd, "amplitudes", (size_t)-1, &na);
        status = fricreg_hb_nma_at(d->hb, mode, damping, na, a);
    } else {
        double a0 = mexa_scalar(prhs[3], cmd, "a0"), a1 = mexa_scalar(prhs[4], cmd, "a1");
        size_t npoints = mexa_count(prhs[5], cmd, "npoints", 0, (size_t)1 << 40);
        int folds = mxIsLogical(prhs[6]) && mxGetNumberOfElements(prhs[6]) == 1
                        ? (int)mxIsLogicalScalarTrue(prhs[6])
                        : (int)mexa_count(prhs[6], cmd, "through_folds", 0, 1);
        status = folds ? fricreg_hb_nma_continue(d->hb, mode, damping, a0, a1, npoints)
                       : fricreg_hb_nma(d->hb, mode, damping, a0, a1, npoints);
    }
    mexhb_check(d, status, cmd);
    n = fricreg_hb_nma_points(d->hb);
    nc = (size_t)(2 * d->harmonics + 1);
    for (int k = 0; k < 3; k++)
        out[k] = mexa_matrix(n, 1);
    out[3] = nlhs >= 4 ? mexa_array3(n, d->ndof, nc) : mexa_matrix(0, 0);
    out[4] = mexa_matrix(nlhs >= 5 ? n : 0, nlhs >= 5 ? (size_t)d->harmonics + 1 : 0);
    if (nlhs >= 4)
        c = mexa_scratch(d->ndof * nc);
    for (size_t i = 0; i < n; i++) {
        mexhb_check(d,
                    fricreg_hb_nma_point(d->hb, i, mxGetPr(out[0]) + i, mxGetPr(out[1]) + i,
                                         mxGetPr(out[2]) + i, d->ndof, nc, c),
                    cmd);
        if (c != NULL)
            put_point(mxGetPr(out[3]), c, i, n, d->ndof, nc);
        if (nlhs >= 5) {
            size_t nh = (size_t)d->harmonics + 1;
            double *e = mexa_scratch(nh);
            mexhb_check(d, fricreg_hb_nma_harmonic_energy(d->hb, i, nh, e), cmd);
            for (size_t h = 0; h < nh; h++)
                mxGetPr(out[4])[i + n * h] = e[h];
        }
    }
    out[5] = special_points(d, cmd);
    mexa_outputs(nlhs, plhs, out, 6);
}

/* [omega, rms] = hb_peak(h, dof): the largest RMS of dof (from 1) along the last branch. */
void mexhb_peak(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    const char *cmd = "hb_peak";
    mxArray *out[2];
    double omega = 0.0, rms = 0.0;
    size_t dof;
    mexhb *d;
    mexa_nargs(cmd, nrhs, 2, 2, nlhs, 2);
    d = mexhb_of(prhs[0], cmd);
    dof = mexa_count(prhs[1], cmd, "dof", 1, d->ndof) - 1; /* MATLAB's from 1 */
    mexhb_check(d, fricreg_hb_peak(d->hb, dof, &omega, &rms), cmd);
    out[0] = mxCreateDoubleScalar(omega);
    out[1] = mxCreateDoubleScalar(rms);
    mexa_outputs(nlhs, plhs, out, 2);
}
