/* SPDX-License-Identifier: GPL-3.0-or-later */
/* mex_fit.c — the gateway's commands on a fit (fricreg_fit.h): one command per C call, the
 * fit held in the handle table (mex_handles.h). matlab/fricreg_fit_backbone.m and
 * matlab/fricreg_backbone.m put them together. A failed call raises fricreg:<NAME> with the
 * fit's own message (fricreg_fit_errmsg). */
#include <math.h>
#include <string.h>

#include "mex_args.h"
#include "mex_fit.h"
#include "mex_handles.h"
#include "fricreg_fit.h"

#define NP FRICREG_FIT_NPARAMS

static const char *const param_names[NP] = {"fs", "kt", "chi", "beta", "zeta0", "k0"};

static fricreg_fit *fit_of(const mxArray *a, const char *cmd, size_t **levels)
{
    return mexh_get(a, MEXH_FIT, cmd, levels);
}

static void check(fricreg_fit *fit, int status, const char *cmd)
{
    if (status != FRICREG_OK)
        mexa_status(status, cmd, fricreg_fit_errmsg(fit));
}

/* A name of a list, or its index; raises fricreg:EINVAL naming the list. */
static int choose(const mxArray *a, const char *cmd, const char *what, const char *const names[],
                  int count)
{
    char name[32], list[256] = "";
    mexa_string(a, cmd, what, name, sizeof name);
    for (int i = 0; i < count; i++) {
        if (strcmp(name, names[i]) == 0)
            return i;
        mexa_append(list, sizeof list, i ? ", " : "");
        mexa_append(list, sizeof list, names[i]);
    }
    mexa_error("fricreg:EINVAL", "%s: %s '%s' is not one of %s (FRICREG_EINVAL)", cmd, what, name,
               list);
    return -1;
}

static int param_of(const mxArray *a, const char *cmd)
{
    return choose(a, cmd, "parameter", param_names, NP);
}

static int kind_of(const mxArray *a, const char *cmd)
{
    static const char *const kinds[] = {"displacement", "velocity", "acceleration"};
    return choose(a, cmd, "kind", kinds, 3); /* the values of enum fricreg_fit_amplitude */
}

void mexfit_create(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    fricreg_fit *fit = NULL;
    int status;
    (void)prhs;
    mexa_nargs("fit_create", nrhs, 0, 0, nlhs, 1);
    status = fricreg_fit_create(&fit);
    if (status != FRICREG_OK)
        mexa_status(status, "fit_create", NULL);
    plhs[0] = mxCreateDoubleScalar(mexh_add(MEXH_FIT, fit));
}

void mexfit_set_sensor(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    const char *cmd = "fit_set_sensor";
    fricreg_fit *fit;
    (void)plhs;
    mexa_nargs(cmd, nrhs, 2, 2, nlhs, 0);
    fit = fit_of(prhs[0], cmd, NULL);
    check(fit, fricreg_fit_set_sensor(fit, mexa_scalar(prhs[1], cmd, "sensor")), cmd);
}

/* fit_set_levels(h, kind, amplitude, freq_hz, zeta): three vectors of one length n. */
void mexfit_set_levels(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    const char *cmd = "fit_set_levels";
    const double *a, *f, *z;
    size_t n, *levels;
    fricreg_fit *fit;
    int kind;
    (void)plhs;
    mexa_nargs(cmd, nrhs, 5, 5, nlhs, 0);
    fit = fit_of(prhs[0], cmd, &levels);
    kind = kind_of(prhs[1], cmd);
    a = mexa_vector(prhs[2], cmd, "amplitude", (size_t)-1, &n);
    f = mexa_vector(prhs[3], cmd, "freq_hz", n, NULL);
    z = mexa_vector(prhs[4], cmd, "zeta", n, NULL);
    check(fit, fricreg_fit_set_levels(fit, n, kind, a, f, z), cmd);
    *levels = n;
}

/* fit_set_deviations(h, sd_freq_hz, sd_zeta): vectors of the levels' length, or both []. */
void mexfit_set_deviations(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    const char *cmd = "fit_set_deviations";
    const double *sf, *sz;
    size_t n;
    fricreg_fit *fit;
    (void)plhs;
    mexa_nargs(cmd, nrhs, 3, 3, nlhs, 0);
    fit = fit_of(prhs[0], cmd, NULL);
    sf = mexa_vector(prhs[1], cmd, "sd_freq_hz", (size_t)-1, &n);
    sz = mexa_vector(prhs[2], cmd, "sd_zeta", n, NULL);
    check(fit, fricreg_fit_set_deviations(fit, n, sf, sz), cmd);
}

/* fit_set_free(h, name, start, lower, upper) */
void mexfit_set_free(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    const char *cmd = "fit_set_free";
    fricreg_fit *fit;
    int which;
    double start, lower, upper;
    (void)plhs;
    mexa_nargs(cmd, nrhs, 5, 5, nlhs, 0);
    fit = fit_of(prhs[0], cmd, NULL);
    which = param_of(prhs[1], cmd);
    start = mexa_scalar(prhs[2], cmd, "start");
    lower = mexa_scalar(prhs[3], cmd, "lower");
    upper = mexa_scalar(prhs[4], cmd, "upper");
    check(fit, fricreg_fit_set_free(fit, which, start, lower, upper), cmd);
}

/* fit_set_fixed(h, name, value) */
void mexfit_set_fixed(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    const char *cmd = "fit_set_fixed";
    fricreg_fit *fit;
    int which;
    (void)plhs;
    mexa_nargs(cmd, nrhs, 3, 3, nlhs, 0);
    fit = fit_of(prhs[0], cmd, NULL);
    which = param_of(prhs[1], cmd);
    check(fit, fricreg_fit_set_fixed(fit, which, mexa_scalar(prhs[2], cmd, "value")), cmd);
}

/* fit_set_starts(h, n): the library judges the range (1..1000). */
void mexfit_set_starts(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    const char *cmd = "fit_set_starts";
    fricreg_fit *fit;
    (void)plhs;
    mexa_nargs(cmd, nrhs, 2, 2, nlhs, 0);
    fit = fit_of(prhs[0], cmd, NULL);
    check(fit, fricreg_fit_set_starts(fit, mexa_count(prhs[1], cmd, "starts", 0, 1000000)), cmd);
}

void mexfit_run(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    fricreg_fit *fit;
    (void)plhs;
    mexa_nargs("fit_run", nrhs, 1, 1, nlhs, 0);
    fit = fit_of(prhs[0], "fit_run", NULL);
    check(fit, fricreg_fit_run(fit), "fit_run");
}

/* x = fit_params(h): 1 x 6, in the order fs, kt, chi, beta, zeta0, k0. */
void mexfit_params(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    fricreg_fit *fit;
    mexa_nargs("fit_params", nrhs, 1, 1, nlhs, 1);
    fit = fit_of(prhs[0], "fit_params", NULL);
    plhs[0] = mexa_matrix(1, NP);
    check(fit, fricreg_fit_get_params(fit, NP, mxGetPr(plhs[0])), "fit_params");
}

/* [cov, lower, upper] = fit_covariance(h): 6 x 6 and two 1 x 6. */
void mexfit_covariance(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    const char *cmd = "fit_covariance";
    double cov[NP * NP];
    mxArray *out[3];
    fricreg_fit *fit;
    mexa_nargs(cmd, nrhs, 1, 1, nlhs, 3);
    fit = fit_of(prhs[0], cmd, NULL);
    out[0] = mexa_matrix(NP, NP);
    out[1] = mexa_matrix(1, NP);
    out[2] = mexa_matrix(1, NP);
    check(fit, fricreg_fit_get_covariance(fit, NP, cov, mxGetPr(out[1]), mxGetPr(out[2])), cmd);
    /* a copy: C's row-major cov[i np + j] into MATLAB's column-major (i, j) */
    mexa_to_cols(cov, mxGetPr(out[0]), NP, NP);
    mexa_outputs(nlhs, plhs, out, 3);
}

/* [sv, vectors] = fit_identifiability(h): 6 x 1 (the p singular values first, then zeros) and
 * 6 x 6 (row k the k-th right singular vector; rows past p zero). */
void mexfit_identifiability(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    const char *cmd = "fit_identifiability";
    double vectors[NP * NP];
    mxArray *out[2];
    fricreg_fit *fit;
    mexa_nargs(cmd, nrhs, 1, 1, nlhs, 2);
    fit = fit_of(prhs[0], cmd, NULL);
    out[0] = mexa_matrix(NP, 1);
    out[1] = mexa_matrix(NP, NP);
    check(fit, fricreg_fit_get_identifiability(fit, NP, mxGetPr(out[0]), vectors), cmd);
    mexa_to_cols(vectors, mxGetPr(out[1]), NP, NP); /* a copy: row-major to MATLAB's */
    mexa_outputs(nlhs, plhs, out, 2);
}

/* [r_freq, r_zeta] = fit_residuals(h): n x 1 each, the levels in the order set. */
void mexfit_residuals(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    const char *cmd = "fit_residuals";
    size_t *levels;
    mxArray *out[2];
    fricreg_fit *fit;
    mexa_nargs(cmd, nrhs, 1, 1, nlhs, 2);
    fit = fit_of(prhs[0], cmd, &levels);
    out[0] = mexa_matrix(*levels, 1);
    out[1] = mexa_matrix(*levels, 1);
    check(fit, fricreg_fit_get_residuals(fit, *levels, mxGetPr(out[0]), mxGetPr(out[1])), cmd);
    mexa_outputs(nlhs, plhs, out, 2);
}

/* v = fit_value(h, name): a number of enum fricreg_fit_value by its name. */
void mexfit_value(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    static const char *const values[] = {
        "cost",       "residual_variance", "nfev",  "njev",     "iterations",
        "best_start", "starts_converged",  "nfree", "condition"};
    const char *cmd = "fit_value";
    fricreg_fit *fit;
    int which;
    double v = 0.0;
    mexa_nargs(cmd, nrhs, 2, 2, nlhs, 1);
    fit = fit_of(prhs[0], cmd, NULL);
    which = choose(prhs[1], cmd, "value", values, (int)(sizeof values / sizeof values[0]));
    check(fit, fricreg_fit_get_value(fit, which, &v), cmd);
    plhs[0] = mxCreateDoubleScalar(v);
}

void mexfit_quantile(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    fricreg_fit *fit;
    double q = 0.0;
    mexa_nargs("fit_quantile", nrhs, 1, 1, nlhs, 1);
    fit = fit_of(prhs[0], "fit_quantile", NULL);
    check(fit, fricreg_fit_get_quantile(fit, &q), "fit_quantile");
    plhs[0] = mxCreateDoubleScalar(q);
}

/* [freq_hz, zeta, modal, dfreq_dp, dzeta_dp] = fit_eval(h, p, kind, amplitude): the first
 * three of amplitude's shape (a vector), the derivatives n x 6, computed only when asked. */
void mexfit_eval(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    const char *cmd = "fit_eval";
    const double *p, *a;
    double *df = NULL, *dz = NULL;
    mxArray *out[5];
    size_t n;
    fricreg_fit *fit;
    int kind, nout = nlhs >= 4 ? 5 : 3;
    mexa_nargs(cmd, nrhs, 4, 4, nlhs, 5);
    fit = fit_of(prhs[0], cmd, NULL);
    p = mexa_vector(prhs[1], cmd, "params", NP, NULL);
    kind = kind_of(prhs[2], cmd);
    a = mexa_vector(prhs[3], cmd, "amplitude", (size_t)-1, &n);
    for (int k = 0; k < 3; k++)
        out[k] = mexa_matrix((size_t)mxGetM(prhs[3]), (size_t)mxGetN(prhs[3]));
    if (nout == 5) { /* scratch: C's n x 6 row-major, copied into MATLAB's below */
        df = mexa_scratch(n * NP);
        dz = mexa_scratch(n * NP);
    }
    check(fit,
          fricreg_fit_eval(fit, p, kind, n, a, mxGetPr(out[0]), mxGetPr(out[1]), mxGetPr(out[2]),
                           df, dz),
          cmd);
    if (nout == 5) {
        out[3] = mexa_matrix(n, NP);
        mexa_to_cols(df, mxGetPr(out[3]), n, NP);
        out[4] = mexa_matrix(n, NP);
        mexa_to_cols(dz, mxGetPr(out[4]), n, NP);
    }
    mexa_outputs(nlhs, plhs, out, nout);
}
