/* SPDX-License-Identifier: GPL-3.0-or-later */
/* fricreg_mex.c — the MEX gateway of fricreg for MATLAB (R2017b and later, `mex -R2017b`) and
 * Octave (`mkoctfile --mex`): one C99 file set written against the C MEX API both compile
 * (real doubles through mxGetPr, mxCreateDoubleMatrix, mxGetString, mexErrMsgIdAndTxt,
 * mexAtExit). The .m files beside it (fricreg_law_eval.m, ...) are the surfaces a user calls;
 * they call this gateway with a command string first:
 *
 *   fricreg_mex('version')                       -> [text, number]
 *   fricreg_mex('law_names'), ('element_types')  -> cell arrays of names
 *   fricreg_mex('element_info', name)            -> [dim, nparams, nstate]
 *   fricreg_mex('law_eval', law, v, f_eq, mun, eps)            -> f
 *   fricreg_mex('element_eval', name, params, u [, state])     -> [f, dfdu, state_out, dfdp]
 *   fricreg_mex('fit_create') -> handle; fit_set_*, fit_run, fit_params, ... (mex_fit.c)
 *   fricreg_mex('hb_create', ndof, m, H) -> handle; hb_set_*, hb_add_elements (mex_hb.c);
 *     hb_set_element_param, hb_get_element_param (mex_hb.c); hb_solve, hb_continue,
 *     hb_continue_level, hb_nma, hb_peak (mex_hb_results.c); hb_truncation_error,
 *     hb_nma_sensitivities, hb_modal_participation (mex_hb_estimates.c)
 *   fricreg_mex('aft', kind, samples, params, coefficients) -> [f, jac] (mex_aft.c)
 *   fricreg_mex('st_create', ndof, m) -> handle; st_set_*, st_add_elements (mex_structure.c);
 *     st_run (mex_structure_run.c)
 *   fricreg_mex('free', handle), ('free_all'), ('handles') -> the live objects' count
 *
 * Layout: MATLAB stores arrays column-major; the library takes tables of points row-major,
 * point after point. Where the two differ (a table with more than one column) the gateway
 * copies at the boundary (mexa_to_rows, mexa_to_cols), and says so at each copy; a vector or a
 * one-column table is passed as it lies. Every input is checked (real, full, non-complex
 * double; sizes) before the library is called; the library's own checks (ranges, NaN) raise
 * fricreg:<STATUS> with its message (mex_args.h). Nothing is printed. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mex_aft.h"
#include "mex_args.h"
#include "mex_element.h"
#include "mex_fit.h"
#include "mex_handles.h"
#include "mex_hb.h"
#include "mex_structure.h"
#include "fricreg.h"
#include "fricreg_element.h"

/* ---- version, names, handles -------------------------------------------------------------- */

static void cmd_version(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    mxArray *out[2];
    (void)prhs;
    mexa_nargs("version", nrhs, 0, 0, nlhs, 2);
    out[0] = mxCreateString(fricreg_version());
    out[1] = mxCreateDoubleScalar((double)fricreg_version_number());
    mexa_outputs(nlhs, plhs, out, 2);
}

static void cmd_law_names(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    int n = 0;
    (void)prhs;
    mexa_nargs("law_names", nrhs, 0, 0, nlhs, 1);
    while (fricreg_law_name(n + 1) != NULL) /* laws are numbered 1, 2, ... without gaps */
        n++;
    plhs[0] = mxCreateCellMatrix(1, (mwSize)n);
    for (int i = 0; i < n; i++)
        mxSetCell(plhs[0], (mwIndex)i, mxCreateString(fricreg_law_name(i + 1)));
}

static void cmd_element_types(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    size_t n = fricreg_element_count();
    (void)prhs;
    mexa_nargs("element_types", nrhs, 0, 0, nlhs, 1);
    plhs[0] = mxCreateCellMatrix(1, (mwSize)n);
    for (size_t i = 0; i < n; i++)
        mxSetCell(plhs[0], (mwIndex)i, mxCreateString(fricreg_element_name(fricreg_element_at(i))));
}

static void cmd_free(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    (void)plhs;
    mexa_nargs("free", nrhs, 1, 1, nlhs, 0);
    mexh_free(prhs[0], "free");
}

static void cmd_free_all(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    (void)plhs;
    (void)prhs;
    mexa_nargs("free_all", nrhs, 0, 0, nlhs, 0);
    mexh_free_all();
    mexaft_release();
}

static void cmd_handles(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    (void)prhs;
    mexa_nargs("handles", nrhs, 0, 0, nlhs, 1);
    plhs[0] = mxCreateDoubleScalar((double)mexh_count());
}

/* [dim, nparams, nstate] = element_info(name): a type's components, its parameters (an Iwan
 * type's with one slider) and its state variables. */
static void cmd_element_info(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    const fricreg_element_type *type;
    mxArray *out[3];
    mexa_nargs("element_info", nrhs, 1, 1, nlhs, 3);
    type = mexe_first(prhs[0], "element_info");
    out[0] = mxCreateDoubleScalar((double)fricreg_element_dim(type));
    out[1] = mxCreateDoubleScalar((double)fricreg_element_nparams(type));
    out[2] = mxCreateDoubleScalar((double)fricreg_element_nstate(type));
    mexa_outputs(nlhs, plhs, out, 3);
}

/* ---- the laws on arrays (fricreg_law_eval_batch) ------------------------------------------ */

/* The law's code from its name or its number; an unknown name raises fricreg:EINVAL naming the
 * laws (an unknown number is the library's to refuse). */
static int law_code(const mxArray *a, const char *cmd)
{
    char name[32], list[160] = "";
    int code;
    if (!mxIsChar(a))
        return (int)mexa_count(a, cmd, "law", 0, 1000);
    mexa_string(a, cmd, "law", name, sizeof name);
    code = fricreg_law_from_name(name);
    if (code != 0)
        return code;
    for (int i = 1; fricreg_law_name(i) != NULL; i++) {
        mexa_append(list, sizeof list, i > 1 ? ", " : "");
        mexa_append(list, sizeof list, fricreg_law_name(i));
    }
    mexa_error("fricreg:EINVAL", "%s: '%s' is not a law (one of %s, or its code) (FRICREG_EINVAL)",
               cmd, name, list);
    return 0;
}

static int same_size(const mxArray *a, const mxArray *b)
{
    mwSize n = mxGetNumberOfDimensions(a);
    return n == mxGetNumberOfDimensions(b) &&
           memcmp(mxGetDimensions(a), mxGetDimensions(b), (size_t)n * sizeof(mwSize)) == 0;
}

/* Which input fricreg_law_eval_batch refused: it returns the status alone. */
static void law_why(int status, int law, double eps, size_t m, const double *const in[3], char *why,
                    size_t len)
{
    static const char *const names[3] = {"v", "f_eq", "mun"};
    why[0] = '\0';
    if (status == FRICREG_ENULL && fricreg_law_name(law) != NULL) {
        snprintf(why, len, "the law %s needs f_eq", fricreg_law_name(law));
    } else if (status == FRICREG_EINVAL) {
        if (fricreg_law_name(law) == NULL)
            snprintf(why, len, "law = %d is not a law's code", law);
        else if (!(eps >= DBL_MIN))
            snprintf(why, len, "eps = %g must be >= DBL_MIN (%g)", eps, DBL_MIN);
        for (size_t i = 0; why[0] == '\0' && i < m; i++)
            if (in[2][i] < 0.0)
                snprintf(why, len, "mun(%lu) = %g must be >= 0", (unsigned long)i + 1, in[2][i]);
    } else if (status == FRICREG_ENONFINITE) {
        for (int k = 0; k < 3 && why[0] == '\0'; k++)
            for (size_t i = 0; in[k] != NULL && i < m; i++)
                if (!isfinite(in[k][i])) {
                    snprintf(why, len, "%s(%lu) = %g is not finite", names[k], (unsigned long)i + 1,
                             in[k][i]);
                    break;
                }
        if (why[0] == '\0')
            snprintf(why, len, "eps = %g is not finite", eps);
    }
}

/* f = law_eval(law, v, f_eq, mun, eps): v, f_eq and mun real double arrays of one size, or
 * scalars (expanded); f_eq [] for the laws that do not read it; f of that size. Elementwise:
 * the arrays are passed as they lie, only an expanded scalar is copied. */
static void cmd_law_eval(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    static const char *const names[3] = {"v", "f_eq", "mun"};
    const char *cmd = "law_eval";
    const mxArray *shape = NULL;
    const double *in[3];
    char why[200];
    size_t m;
    double eps;
    int law, status, has_feq;
    mexa_nargs(cmd, nrhs, 5, 5, nlhs, 1);
    law = law_code(prhs[0], cmd);
    for (int k = 0; k < 3; k++)
        mexa_real(prhs[1 + k], cmd, names[k]);
    eps = mexa_scalar(prhs[4], cmd, "eps");
    has_feq = !mxIsEmpty(prhs[2]); /* [] for none */
    for (int k = 0; k < 3; k++) {
        if ((k == 1 && !has_feq) || mxGetNumberOfElements(prhs[1 + k]) == 1)
            continue;
        if (shape == NULL)
            shape = prhs[1 + k];
        else if (!same_size(shape, prhs[1 + k]))
            mexa_error("fricreg:size",
                       "%s: v, f_eq and mun must have one size, or be scalars: %s is %dx%d, %s "
                       "%dx%d%s",
                       cmd, names[k], (int)mxGetM(prhs[1 + k]), (int)mxGetN(prhs[1 + k]),
                       shape == prhs[1] ? "v" : "f_eq", (int)mxGetM(shape), (int)mxGetN(shape),
                       mxGetNumberOfDimensions(shape) > 2 ? " (or more dimensions)" : "");
    }
    m = shape != NULL ? (size_t)mxGetNumberOfElements(shape) : 1;
    for (int k = 0; k < 3; k++) {
        if (k == 1 && !has_feq) {
            in[k] = NULL;
        } else if ((size_t)mxGetNumberOfElements(prhs[1 + k]) == m) {
            in[k] = mxGetPr(prhs[1 + k]);
        } else { /* a scalar against arrays: a copy, expanded */
            double *x = mexa_scratch(m), value = mxGetPr(prhs[1 + k])[0];
            for (size_t i = 0; i < m; i++)
                x[i] = value;
            in[k] = x;
        }
    }
    plhs[0] = shape != NULL ? mxCreateNumericArray(mxGetNumberOfDimensions(shape),
                                                   mxGetDimensions(shape), mxDOUBLE_CLASS, mxREAL)
                            : mexa_matrix(1, 1);
    status = fricreg_law_eval_batch(law, eps, m, in[0], in[1], in[2], mxGetPr(plhs[0]));
    if (status != FRICREG_OK) {
        law_why(status, law, eps, m, in, why, sizeof why);
        mexa_status(status, cmd, why);
    }
}

/* ---- elements on many points (fricreg_element_eval_batch) --------------------------------- */

/* dst, MATLAB's n x d1 x d2 (column-major), from src, C's [n][d1][d2] (row-major): the
 * boundary copy of the tangents and the derivatives. */
static void to_cols3(const double *src, double *dst, size_t n, size_t d1, size_t d2)
{
    for (size_t i = 0; i < n; i++)
        for (size_t a = 0; a < d1; a++)
            for (size_t j = 0; j < d2; j++)
                dst[i + n * (a + d1 * j)] = src[d1 * d2 * i + d2 * a + j];
}

/* [f, dfdu, state_out, dfdp] = element_eval(name, params, u [, state]):
 *   u        npoints x dim, one point a row;
 *   params   a vector of nparams (shared by every point) or npoints x nparams (a row each);
 *   state    npoints x nstate, or omitted / [] for the elements at rest (zeros);
 *   f        npoints x dim;   dfdu npoints x dim x dim, dfdu(i, a, c) = df_a/du_c;
 *   state_out npoints x nstate;   dfdp npoints x dim x nparams, dfdp(i, a, j) = df_a/dp_j.
 * dfdu and dfdp are computed only when asked for. */
static void cmd_element_eval(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    const char *cmd = "element_eval";
    const fricreg_element_type *first, *type = NULL;
    const mxArray *pa, *ua;
    const double *params, *u, *state;
    double *f, *dfdu = NULL, *dfdp = NULL, *state_out;
    mxArray *out[4];
    size_t npoints, dim, np = 0, ns, stride = 0, bad = 0;
    int status, nout = nlhs < 3 ? 3 : nlhs;
    mexa_nargs(cmd, nrhs, 3, 4, nlhs, 4);
    first = mexe_first(prhs[0], cmd);
    pa = prhs[1];
    ua = prhs[2];
    mexa_real(pa, cmd, "params");
    mexa_real(ua, cmd, "u");
    dim = (size_t)fricreg_element_dim(first);
    if (mxGetNumberOfDimensions(ua) != 2 || (size_t)mxGetN(ua) != dim)
        mexa_error("fricreg:size", "%s: u must be npoints x %lu (%s: one point a row), not %dx%d",
                   cmd, (unsigned long)dim, fricreg_element_name(first), (int)mxGetM(ua),
                   (int)mxGetN(ua));
    npoints = (size_t)mxGetM(ua);
    if (mexa_is_vector(pa) &&
        (type = mexe_member(first, (size_t)mxGetNumberOfElements(pa))) != NULL) {
        np = (size_t)mxGetNumberOfElements(pa); /* shared: stride 0, the vector as it lies */
        params = mxGetPr(pa);
    } else if (mxGetNumberOfDimensions(pa) == 2 && (size_t)mxGetM(pa) == npoints && npoints > 0 &&
               (type = mexe_member(first, (size_t)mxGetN(pa))) != NULL) {
        np = stride = (size_t)mxGetN(pa);
        if (np == 1) {
            params = mxGetPr(pa);
        } else { /* a copy: npoints x np column-major to row-major */
            double *rows = mexa_scratch(npoints * np);
            mexa_to_rows(mxGetPr(pa), rows, npoints, np);
            params = rows;
        }
    } else {
        mexe_bad_params(first, cmd,
                        "params must be a vector of nparams (shared by the points) or npoints x "
                        "nparams (a row each)",
                        (size_t)mxGetM(pa), (size_t)mxGetN(pa));
        return;
    }
    ns = fricreg_element_nstate(type);
    if (nrhs < 4 || mxIsEmpty(prhs[3])) {
        if (nrhs == 4)
            mexa_real(prhs[3], cmd, "state");
        state = mexa_scratch(npoints * ns); /* at rest: zeros, as fricreg_element_init's */
    } else {
        mexa_real(prhs[3], cmd, "state");
        if (!mexa_is_size(prhs[3], npoints, ns))
            mexa_error("fricreg:size", "%s: state must be npoints x nstate = %lux%lu, not %dx%d",
                       cmd, (unsigned long)npoints, (unsigned long)ns, (int)mxGetM(prhs[3]),
                       (int)mxGetN(prhs[3]));
        if (ns == 1) {
            state = mxGetPr(prhs[3]);
        } else { /* a copy: npoints x nstate column-major to row-major */
            double *rows = mexa_scratch(npoints * ns);
            mexa_to_rows(mxGetPr(prhs[3]), rows, npoints, ns);
            state = rows;
        }
    }
    if (dim == 1) {
        u = mxGetPr(ua);
    } else { /* a copy: npoints x dim column-major to row-major */
        double *rows = mexa_scratch(npoints * dim);
        mexa_to_rows(mxGetPr(ua), rows, npoints, dim);
        u = rows;
    }
    out[0] = mexa_matrix(npoints, dim);
    out[1] = nlhs >= 2 ? mexa_array3(npoints, dim, dim) : mexa_matrix(0, 0);
    out[2] = mexa_matrix(npoints, ns);
    if (nout == 4)
        out[3] = mexa_array3(npoints, dim, np);
    /* outputs: written in place where the layouts agree (one column), else into scratch and
     * copied below; a type without state gets one double of scratch (the call reads none) */
    f = dim == 1 ? mxGetPr(out[0]) : mexa_scratch(npoints * dim);
    if (nlhs >= 2)
        dfdu = dim == 1 ? mxGetPr(out[1]) : mexa_scratch(npoints * dim * dim);
    if (nout == 4)
        dfdp = mexa_scratch(npoints * dim * np);
    state_out = ns == 1 ? mxGetPr(out[2]) : mexa_scratch(npoints * ns);
    status = fricreg_element_eval_batch(type, npoints, params, stride, state, u, f, dfdu, dfdp,
                                        state_out, &bad);
    if (status != FRICREG_OK) {
        char msg[256] = "", detail[300];
        if (bad < npoints) {
            fricreg_element_explain(type, params + stride * bad, state + ns * bad, u + dim * bad,
                                    msg, sizeof msg);
            snprintf(detail, sizeof detail, "point %lu: %s", (unsigned long)bad + 1, msg);
        } else {
            detail[0] = '\0';
        }
        mexa_status(status, cmd, detail);
    }
    if (dim > 1) { /* the copies back, row-major to MATLAB's column-major */
        mexa_to_cols(f, mxGetPr(out[0]), npoints, dim);
        if (dfdu != NULL)
            to_cols3(dfdu, mxGetPr(out[1]), npoints, dim, dim);
    }
    if (ns > 1)
        mexa_to_cols(state_out, mxGetPr(out[2]), npoints, ns);
    if (dfdp != NULL)
        to_cols3(dfdp, mxGetPr(out[3]), npoints, dim, np);
    /* the caller's order: f, dfdu, state_out, dfdp */
    mexa_outputs(nlhs, plhs, out, nout);
}

/* ---- dispatch ----------------------------------------------------------------------------- */

static const struct {
    const char *name;
    mex_command *run;
} commands[] = {
    {"version", cmd_version},
    {"law_names", cmd_law_names},
    {"element_types", cmd_element_types},
    {"element_info", cmd_element_info},
    {"law_eval", cmd_law_eval},
    {"element_eval", cmd_element_eval},
    {"fit_create", mexfit_create},
    {"fit_set_sensor", mexfit_set_sensor},
    {"fit_set_levels", mexfit_set_levels},
    {"fit_set_deviations", mexfit_set_deviations},
    {"fit_set_free", mexfit_set_free},
    {"fit_set_fixed", mexfit_set_fixed},
    {"fit_set_starts", mexfit_set_starts},
    {"fit_run", mexfit_run},
    {"fit_params", mexfit_params},
    {"fit_covariance", mexfit_covariance},
    {"fit_identifiability", mexfit_identifiability},
    {"fit_residuals", mexfit_residuals},
    {"fit_value", mexfit_value},
    {"fit_quantile", mexfit_quantile},
    {"fit_eval", mexfit_eval},
    {"hb_create", mexhb_create},
    {"hb_set_matrix", mexhb_set_matrix},
    {"hb_set_rayleigh", mexhb_set_rayleigh},
    {"hb_set_jenkins", mexhb_set_jenkins},
    {"hb_add_elements", mexhb_add_elements},
    {"hb_set_excitation", mexhb_set_excitation},
    {"hb_set_newton", mexhb_set_newton},
    {"hb_set_newton_solver", mexhb_set_newton_solver},
    {"hb_set_receptance", mexhb_set_receptance},
    {"hb_set_continuation", mexhb_set_continuation},
    {"hb_set_stability", mexhb_set_stability},
    {"hb_set_max_iterations", mexhb_set_max_iterations},
    {"hb_set_element_param", mexhb_set_element_param},
    {"hb_get_element_param", mexhb_get_element_param},
    {"hb_info", mexhb_info},
    {"hb_solve", mexhb_solve},
    {"hb_continue", mexhb_continue},
    {"hb_continue_level", mexhb_continue_level},
    {"hb_nma", mexhb_nma},
    {"hb_peak", mexhb_peak},
    {"hb_truncation_error", mexhb_truncation_error},
    {"hb_nma_sensitivities", mexhb_nma_sensitivities},
    {"hb_modal_participation", mexhb_modal_participation},
    {"aft", mexaft_eval},
    {"st_create", mexst_create},
    {"st_set_matrix", mexst_set_matrix},
    {"st_set_rayleigh", mexst_set_rayleigh},
    {"st_set_bounds", mexst_set_bounds},
    {"st_set_law", mexst_set_law},
    {"st_set_influence", mexst_set_influence},
    {"st_set_ground_accel", mexst_set_ground_accel},
    {"st_set_load", mexst_set_load},
    {"st_add_elements", mexst_add_elements},
    {"st_set_initial", mexst_set_initial},
    {"st_set_newton", mexst_set_newton},
    {"st_set_error_estimate", mexst_set_error_estimate},
    {"st_run", mexst_run},
    {"free", cmd_free},
    {"free_all", cmd_free_all},
    {"handles", cmd_handles},
};

/* Every object and the AFT's kept workspace freed: the MEX file cleared or MATLAB leaving. */
static void at_exit(void)
{
    mexh_free_all();
    mexaft_release();
}

void mexFunction(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    static int registered = 0;
    char name[32];
    if (!registered) { /* every object freed when the MEX file is cleared or MATLAB exits */
        mexAtExit(at_exit);
        registered = 1;
    }
    if (nrhs < 1)
        mexa_error("fricreg:nargs", "fricreg_mex: the first argument is a command, such as "
                                    "'law_eval' (the .m files beside it call it)");
    if (!mxIsChar(prhs[0]) || mxGetM(prhs[0]) > 1 ||
        (size_t)mxGetNumberOfElements(prhs[0]) >= sizeof name)
        mexa_error("fricreg:command", "fricreg_mex: the first argument must be a command's name");
    mxGetString(prhs[0], name, sizeof name);
    for (size_t i = 0; i < sizeof commands / sizeof commands[0]; i++)
        if (strcmp(name, commands[i].name) == 0) {
            commands[i].run(nlhs, plhs, nrhs - 1, prhs + 1);
            return;
        }
    mexa_error("fricreg:command", "fricreg_mex: unknown command '%s'", name);
}
