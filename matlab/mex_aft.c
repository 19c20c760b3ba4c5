/* SPDX-License-Identifier: GPL-3.0-or-later */
/* mex_aft.c — the gateway's command aft: the alternating frequency–time method of one element
 * (fricreg_aft.h), exact or sampled, with its Jacobian when asked for. No handle: the gateway
 * keeps the workspace of the last call (its H and N) and reuses it while they repeat, and frees
 * it when the MEX file is cleared (mexaft_release, at exit). Measured (docs/matlab.md, "AFT"):
 * creating and freeing a workspace costs 0.8 us at H = 5, 11 us at H = 20 and 69 us at H = 40
 * (N = 0) against an exact evaluation's 4, 27 and 103 us, so a workspace made per call would
 * cost up to 40 % more where a harmonic-balance loop calls the AFT again and again at one H.
 * A workspace of more than MEXAFT_KEEP_SAMPLES samples (O(N H) doubles) is made for its call
 * only and freed before it returns, so no large buffer outlives its call.
 *
 *   [f, jac] = fricreg_mex('aft', kind, samples, params, coefficients)
 *     kind          'jenkins' (params [kt mun], dim 1), 'iwan' ([k_1..k_ns phi_1..phi_ns],
 *                   dim 1), 'jenkins_normal' ([kt mu n0 kn], dim 2: rows u, g) or
 *                   'jenkins_2d_normal' ([kt mu n0 kn], dim 3: rows ux, uy, g; sampled only)
 *     samples       N: 0 for the exact path, else the sampled one at N samples a period
 *     coefficients  dim x n, n = 2H + 1 (dim 1: a vector of n, row or column)
 *     f             dim x n (dim 1: the shape of coefficients): the forces, the normal force
 *                   N last; jac (dim n) x (dim n), jac(a n + i, c n + j) = df_a[i]/du_c[j]
 *                   (from 1: jac((a - 1) n + i, (c - 1) n + j)), computed only when asked for.
 * Layout: the library's coefficient rows and Jacobian are row-major, MATLAB's column-major:
 * a table of more than one row is copied at the boundary; a vector is passed as it lies. */
#include <stdio.h>
#include <string.h>

#include "mex_args.h"
#include "mex_aft.h"
#include "fricreg_aft.h"

enum { AFT_JENKINS, AFT_IWAN, AFT_NORMAL, AFT_2D };

/* The most samples of a workspace kept across calls (2^16 at H = 40: about 21 MB). */
#define MEXAFT_KEEP_SAMPLES 65536

static fricreg_aft *kept; /* the last call's workspace, or NULL */

void mexaft_release(void)
{
    fricreg_aft_free(kept);
    kept = NULL;
}

/* A workspace of H harmonics and N samples: the kept one where it fits, else a new one, kept
 * where N is small; NULL with the status in *status. */
static fricreg_aft *workspace(int harmonics, size_t samples, int *status)
{
    fricreg_aft *aft = NULL;
    *status = FRICREG_OK;
    if (kept != NULL && fricreg_aft_harmonics(kept) == harmonics &&
        fricreg_aft_samples(kept) == samples)
        return kept;
    *status = fricreg_aft_create(harmonics, samples, &aft);
    if (*status != FRICREG_OK)
        return NULL;
    if (samples <= MEXAFT_KEEP_SAMPLES) {
        mexaft_release();
        kept = aft;
    }
    return aft;
}

static const struct {
    const char *name;
    size_t dim, nparams; /* nparams 0: the Iwan element's 2 ns */
    const char *layout;
} kinds[] = {
    {"jenkins", 1, 2, "[kt mun]"},
    {"iwan", 1, 0, "[k_1..k_ns phi_1..phi_ns]"},
    {"jenkins_normal", 2, 4, "[kt mu n0 kn]"},
    {"jenkins_2d_normal", 3, 4, "[kt mu n0 kn]"},
};

static int kind_of(const mxArray *a, const char *cmd)
{
    char name[32];
    mexa_string(a, cmd, "kind", name, sizeof name);
    for (int i = 0; i < 4; i++)
        if (strcmp(name, kinds[i].name) == 0)
            return i;
    mexa_error("fricreg:EINVAL",
               "%s: '%s' is not an AFT (one of jenkins, iwan, jenkins_normal, "
               "jenkins_2d_normal) (FRICREG_EINVAL)",
               cmd, name);
    return -1;
}

/* The library's call for the kind; p the parameters, u the coefficients row-major (dim x n),
 * out the forces row-major (dim x n). */
static int evaluate(fricreg_aft *aft, int kind, int exact, const double *p, size_t np, size_t n,
                    const double *u, double *out, double *jac)
{
    switch (kind) {
    case AFT_JENKINS:
        return (exact ? fricreg_aft_jenkins_exact : fricreg_aft_jenkins_sampled)(aft, p[0], p[1], n,
                                                                                 u, out, jac);
    case AFT_IWAN:
        return (exact ? fricreg_aft_iwan_exact
                      : fricreg_aft_iwan_sampled)(aft, np / 2, p, p + np / 2, n, u, out, jac);
    case AFT_NORMAL:
        return (exact ? fricreg_aft_jenkins_normal_exact
                      : fricreg_aft_jenkins_normal_sampled)(aft, p[0], p[1], p[2], p[3], n, u,
                                                            u + n, out, out + n, jac);
    default: /* the 3-D contact: sampled only (the library refuses N = 0) */
        return fricreg_aft_jenkins_2d_normal_sampled(aft, p[0], p[1], p[2], p[3], n, u, u + 2 * n,
                                                     out, out + 2 * n, jac);
    }
}

void mexaft_eval(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    const char *cmd = "aft";
    const mxArray *pa, *ca;
    const double *p, *u;
    double *f, *jac = NULL;
    mxArray *out[2];
    fricreg_aft *aft = NULL;
    size_t samples, np, dim, n;
    int kind, status, harmonics;
    char msg[512];
    mexa_nargs(cmd, nrhs, 4, 4, nlhs, 2);
    kind = kind_of(prhs[0], cmd);
    samples = mexa_count(prhs[1], cmd, "samples", 0, (size_t)1 << 40);
    pa = prhs[2];
    ca = prhs[3];
    mexa_real(pa, cmd, "params");
    mexa_real(ca, cmd, "coefficients");
    np = (size_t)mxGetNumberOfElements(pa);
    if (!mexa_is_vector(pa) || (kinds[kind].nparams != 0 && np != kinds[kind].nparams) ||
        (kinds[kind].nparams == 0 && np % 2 != 0))
        mexa_error("fricreg:size", "%s: %s's params must be a vector %s, not %dx%d", cmd,
                   kinds[kind].name, kinds[kind].layout, (int)mxGetM(pa), (int)mxGetN(pa));
    p = mxGetPr(pa);
    dim = kinds[kind].dim;
    if (dim == 1 && mexa_is_vector(ca))
        n = (size_t)mxGetNumberOfElements(ca);
    else if (mxGetNumberOfDimensions(ca) == 2 && (size_t)mxGetM(ca) == dim)
        n = (size_t)mxGetN(ca);
    else
        n = 0;
    if (n % 2 == 0 && dim == 1)
        mexa_error("fricreg:size",
                   "%s: %s's coefficients must be a vector of n = 2H + 1 (odd) numbers, not %dx%d",
                   cmd, kinds[kind].name, (int)mxGetM(ca), (int)mxGetN(ca));
    if (n % 2 == 0)
        mexa_error("fricreg:size",
                   "%s: %s's coefficients must be %lu x n, n = 2H + 1 (a row per component: "
                   "%s), not %dx%d",
                   cmd, kinds[kind].name, (unsigned long)dim, dim == 2 ? "u, g" : "ux, uy, g",
                   (int)mxGetM(ca), (int)mxGetN(ca));
    harmonics = n / 2 > 1000000 ? 1000000 : (int)(n / 2);
    if (dim == 1) {
        u = mxGetPr(ca);
    } else { /* a copy: dim x n column-major to row-major, a component's n coefficients a row */
        double *rows = mexa_scratch(dim * n);
        mexa_to_rows(mxGetPr(ca), rows, dim, n);
        u = rows;
    }
    out[0] = dim == 1 ? mxCreateNumericArray(2, mxGetDimensions(ca), mxDOUBLE_CLASS, mxREAL)
                      : mexa_matrix(dim, n);
    out[1] = mexa_matrix(nlhs >= 2 ? dim * n : 0, nlhs >= 2 ? dim * n : 0);
    f = dim == 1 ? mxGetPr(out[0]) : mexa_scratch(dim * n);
    if (nlhs >= 2)
        jac = mexa_scratch(dim * n * dim * n);
    aft = workspace(harmonics, samples, &status);
    if (aft == NULL) {
        snprintf(msg, sizeof msg,
                 "H = %d (from n = %lu coefficients), samples = %lu: H must be 1..%d, and N 0 "
                 "or a power of two with 2H + 2 <= N <= %d",
                 harmonics, (unsigned long)n, (unsigned long)samples, FRICREG_AFT_MAX_HARMONICS,
                 FRICREG_AFT_MAX_SAMPLES);
        mexa_status(status, cmd, status == FRICREG_EINVAL ? msg : NULL);
    }
    status = evaluate(aft, kind, samples == 0, p, np, n, u, f, jac);
    if (status != FRICREG_OK) { /* the message kept, the workspace freed, then the error */
        snprintf(msg, sizeof msg, "%s (%s): %s", kinds[kind].name,
                 samples == 0 && kind != AFT_2D ? "exact" : "sampled", fricreg_aft_errmsg(aft));
        if (aft != kept)
            fricreg_aft_free(aft);
        mexa_status(status, cmd, msg);
    }
    if (aft != kept)
        fricreg_aft_free(aft);
    if (dim > 1)
        mexa_to_cols(f, mxGetPr(out[0]), dim, n);
    if (jac != NULL)
        mexa_to_cols(jac, mxGetPr(out[1]), dim * n, dim * n);
    mexa_outputs(nlhs, plhs, out, 2);
}
