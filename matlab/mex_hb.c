/* SPDX-License-Identifier: GPL-3.0-or-later */
/* mex_hb.c — the gateway's commands that build a harmonic-balance driver (fricreg_hb.h): its
 * creation, the model's matrices, the elements, the excitation and the solver's settings. One
 * command per C call; a failed call raises fricreg:<NAME> with the driver's own message
 * (fricreg_hb_errmsg). The solves are in mex_hb_results.c.
 *
 * Layout: the library's matrices and J are row-major, MATLAB's column-major: J (rows x ndof)
 * and a dense M, K or C are copied at the boundary (a matrix's copy keeps a non-symmetric
 * one's error naming the entry MATLAB shows); a sparse matrix is passed as MATLAB keeps it,
 * compressed sparse columns from 0, its indices copied to int64_t. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "mex_args.h"
#include "mex_element.h"
#include "mex_handles.h"
#include "mex_hb.h"

mexhb *mexhb_of(const mxArray *a, const char *cmd)
{
    return mexh_get(a, MEXH_HB, cmd, NULL);
}

void mexhb_check(const mexhb *d, int status, const char *cmd)
{
    if (status != FRICREG_OK)
        mexa_status(status, cmd, fricreg_hb_errmsg(d->hb));
}

void mexhb_free(void *object)
{
    mexhb *d = object;
    if (d != NULL) {
        fricreg_hb_free(d->hb);
        free(d);
    }
}

/* h = hb_create(ndof, m, harmonics): a driver of ndof dofs, m elements, H harmonics. */
void mexhb_create(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    const char *cmd = "hb_create";
    fricreg_hb *hb = NULL;
    mexhb *d;
    size_t ndof, m;
    int harmonics, status;
    mexa_nargs(cmd, nrhs, 3, 3, nlhs, 1);
    /* the ranges are the library's to judge: whole numbers here, up to what a size_t holds */
    ndof = mexa_count(prhs[0], cmd, "ndof", 0, (size_t)1 << 40);
    m = mexa_count(prhs[1], cmd, "m", 0, (size_t)1 << 40);
    harmonics = (int)mexa_count(prhs[2], cmd, "harmonics", 0, 1000000);
    status = fricreg_hb_create(ndof, m, harmonics, &hb);
    if (status != FRICREG_OK)
        mexa_status(status, cmd,
                    status == FRICREG_EINVAL
                        ? "ndof 1..2^24, m (the elements) >= 1, harmonics 1..40"
                        : NULL);
    d = malloc(sizeof *d);
    if (d == NULL) {
        fricreg_hb_free(hb);
        mexa_status(FRICREG_ENOMEM, cmd, NULL);
    }
    d->hb = hb;
    d->ndof = ndof;
    d->m = m;
    d->rows = 0;
    d->harmonics = harmonics;
    d->stability = 0;
    plhs[0] = mxCreateDoubleScalar(mexh_add(MEXH_HB, d));
}

/* The ndof x ndof real array a, dense or sparse, given to fricreg_hb_set_matrix. */
static int set_matrix(mexhb *d, int which, const mxArray *a, const char *cmd, const char *name)
{
    size_t n = d->ndof;
    if (!mxIsDouble(a) || mxIsComplex(a))
        mexa_error("fricreg:type", "%s: %s must be a real double matrix, not %s%s", cmd, name,
                   mxIsComplex(a) ? "complex " : "", mxGetClassName(a));
    if (!mexa_is_size(a, n, n))
        mexa_error("fricreg:size", "%s: %s must be ndof x ndof = %lux%lu, not %dx%d", cmd, name,
                   (unsigned long)n, (unsigned long)n, (int)mxGetM(a), (int)mxGetN(a));
    if (mxIsSparse(a)) { /* MATLAB's own compressed sparse columns, zero-based */
        const mwIndex *jc = mxGetJc(a), *ir = mxGetIr(a);
        size_t nnz = (size_t)jc[n];
        int64_t *ptr = mxCalloc(n + 1, sizeof *ptr), *ind = mxCalloc(nnz + 1, sizeof *ind);
        for (size_t j = 0; j <= n; j++)
            ptr[j] = (int64_t)jc[j];
        for (size_t k = 0; k < nnz; k++)
            ind[k] = (int64_t)ir[k];
        return fricreg_hb_set_matrix(d->hb, which, n, n, FRICREG_MATRIX_CSC, ptr, ind, mxGetPr(a));
    } else { /* a copy: column-major to the library's row-major */
        double *rows = mexa_scratch(n * n);
        mexa_to_rows(mxGetPr(a), rows, n, n);
        return fricreg_hb_set_matrix(d->hb, which, n, n, FRICREG_MATRIX_DENSE, NULL, NULL, rows);
    }
}

/* hb_set_matrix(h, which, A): which 'mass', 'stiffness' or 'damping'; A ndof x ndof, full or
 * sparse. */
void mexhb_set_matrix(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    static const char *const names[] = {"mass", "stiffness", "damping"};
    static const int codes[] = {FRICREG_MASS, FRICREG_STIFFNESS, FRICREG_DAMPING};
    const char *cmd = "hb_set_matrix";
    mexhb *d;
    int which;
    (void)plhs;
    mexa_nargs(cmd, nrhs, 3, 3, nlhs, 0);
    d = mexhb_of(prhs[0], cmd);
    which = mexa_pick(prhs[1], cmd, "matrix", names, 3);
    mexhb_check(d, set_matrix(d, codes[which], prhs[2], cmd, names[which]), cmd);
}

/* hb_set_rayleigh(h, a0, a1): C = a0 M + a1 K. */
void mexhb_set_rayleigh(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    const char *cmd = "hb_set_rayleigh";
    mexhb *d;
    double a0, a1;
    (void)plhs;
    mexa_nargs(cmd, nrhs, 3, 3, nlhs, 0);
    d = mexhb_of(prhs[0], cmd);
    a0 = mexa_scalar(prhs[1], cmd, "a0");
    a1 = mexa_scalar(prhs[2], cmd, "a1");
    mexhb_check(d, fricreg_hb_set_rayleigh(d->hb, a0, a1), cmd);
}

/* J (rows x ndof) as the library's row-major copy; fricreg:size naming what it must be. */
static const double *j_rows(const mexhb *d, const mxArray *a, const char *cmd, size_t rows)
{
    double *copy;
    mexa_real(a, cmd, "J");
    if (!mexa_is_size(a, rows, d->ndof))
        mexa_error("fricreg:size",
                   "%s: J must be %lux%lu (a row per element's component, a "
                   "column per dof), not %dx%d",
                   cmd, (unsigned long)rows, (unsigned long)d->ndof, (int)mxGetM(a),
                   (int)mxGetN(a));
    copy = mexa_scratch(rows * d->ndof);
    mexa_to_rows(mxGetPr(a), copy, rows, d->ndof);
    return copy;
}

/* hb_set_jenkins(h, J, kt, mun): the driver's m Jenkins elements, J m x ndof, kt and mun
 * vectors of m (fricreg_hb_set_jenkins), replacing the elements held. */
void mexhb_set_jenkins(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    const char *cmd = "hb_set_jenkins";
    const double *J, *kt, *mun;
    mexhb *d;
    (void)plhs;
    mexa_nargs(cmd, nrhs, 4, 4, nlhs, 0);
    d = mexhb_of(prhs[0], cmd);
    J = j_rows(d, prhs[1], cmd, d->m);
    kt = mexa_vector(prhs[2], cmd, "kt", d->m, NULL);
    mun = mexa_vector(prhs[3], cmd, "mun", d->m, NULL);
    mexhb_check(d, fricreg_hb_set_jenkins(d->hb, d->m, d->ndof, J, kt, mun), cmd);
    d->rows = d->m;
}

/* hb_add_elements(h, type, J, params): me elements of one type (fricreg_hb_add_elements), J
 * (me dim) x ndof, params me x nparams (a row each) or a vector of nparams shared. */
void mexhb_add_elements(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    const char *cmd = "hb_add_elements";
    const fricreg_element_type *first, *type = NULL;
    const mxArray *pa, *ja;
    const double *J, *params;
    size_t dim, me, np;
    mexhb *d;
    (void)plhs;
    mexa_nargs(cmd, nrhs, 4, 4, nlhs, 0);
    d = mexhb_of(prhs[0], cmd);
    first = mexe_first(prhs[1], cmd);
    ja = prhs[2];
    pa = prhs[3];
    mexa_real(ja, cmd, "J");
    mexa_real(pa, cmd, "params");
    dim = (size_t)fricreg_element_dim(first);
    if (mxGetNumberOfDimensions(ja) != 2 || (size_t)mxGetM(ja) % dim != 0 ||
        (size_t)mxGetN(ja) != d->ndof)
        mexa_error("fricreg:size",
                   "%s: J must be (me %lu) x ndof = (me %lu) x %lu (%s: %lu rows "
                   "an element), not %dx%d",
                   cmd, (unsigned long)dim, (unsigned long)dim, (unsigned long)d->ndof,
                   fricreg_element_name(first), (unsigned long)dim, (int)mxGetM(ja),
                   (int)mxGetN(ja));
    me = (size_t)mxGetM(ja) / dim;
    if (mxGetNumberOfDimensions(pa) == 2 && (size_t)mxGetM(pa) == me && me > 0 &&
        (type = mexe_member(first, (size_t)mxGetN(pa))) != NULL) {
        double *rows; /* a copy: me x np column-major to row-major */
        np = (size_t)mxGetN(pa);
        rows = mexa_scratch(me * np);
        mexa_to_rows(mxGetPr(pa), rows, me, np);
        params = rows;
    } else if (mexa_is_vector(pa) &&
               (type = mexe_member(first, (size_t)mxGetNumberOfElements(pa))) != NULL) {
        double *rows; /* one vector shared: repeated, a row per element */
        np = (size_t)mxGetNumberOfElements(pa);
        rows = mexa_scratch(me * np);
        for (size_t i = 0; i < me; i++)
            memcpy(rows + np * i, mxGetPr(pa), np * sizeof *rows);
        params = rows;
    } else {
        mexe_bad_params(first, cmd,
                        "params must be me x nparams (a row an element) or a vector of nparams "
                        "(shared)",
                        (size_t)mxGetM(pa), (size_t)mxGetN(pa));
        return;
    }
    J = j_rows(d, ja, cmd, me * dim);
    mexhb_check(d, fricreg_hb_add_elements(d->hb, type, me, d->ndof, J, params), cmd);
    d->rows += me * dim;
}

/* hb_set_excitation(h, pc, ps): p(t) = pc cos(Omega t) + ps sin(Omega t), vectors of ndof. */
void mexhb_set_excitation(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    const char *cmd = "hb_set_excitation";
    const double *pc, *ps;
    mexhb *d;
    (void)plhs;
    mexa_nargs(cmd, nrhs, 3, 3, nlhs, 0);
    d = mexhb_of(prhs[0], cmd);
    pc = mexa_vector(prhs[1], cmd, "pc", d->ndof, NULL);
    ps = mexa_vector(prhs[2], cmd, "ps", d->ndof, NULL);
    mexhb_check(d, fricreg_hb_set_excitation(d->hb, d->ndof, pc, ps), cmd);
}

/* hb_set_newton(h, tol, max_iter) */
void mexhb_set_newton(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    const char *cmd = "hb_set_newton";
    mexhb *d;
    double tol;
    (void)plhs;
    mexa_nargs(cmd, nrhs, 3, 3, nlhs, 0);
    d = mexhb_of(prhs[0], cmd);
    tol = mexa_scalar(prhs[1], cmd, "tol");
    mexhb_check(d,
                fricreg_hb_set_newton(d->hb, tol,
                                      (int)mexa_count(prhs[2], cmd, "max_iter", 0, 1000000)),
                cmd);
}

/* hb_set_newton_solver(h, solver): solver 'auto', 'dense' or 'capacitance' (enum
 * fricreg_hb_newton_solver's order). */
void mexhb_set_newton_solver(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    static const char *const solvers[] = {"auto", "dense", "capacitance"};
    const char *cmd = "hb_set_newton_solver";
    mexhb *d;
    (void)plhs;
    mexa_nargs(cmd, nrhs, 2, 2, nlhs, 0);
    d = mexhb_of(prhs[0], cmd);
    mexhb_check(d,
                fricreg_hb_set_newton_solver(d->hb, mexa_pick(prhs[1], cmd, "solver", solvers, 3)),
                cmd);
}

/* hb_set_receptance(h, method): method 'auto', 'lu' or 'modes' (enum fricreg_hb_receptance's
 * order). */
void mexhb_set_receptance(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    static const char *const methods[] = {"auto", "lu", "modes"};
    const char *cmd = "hb_set_receptance";
    mexhb *d;
    (void)plhs;
    mexa_nargs(cmd, nrhs, 2, 2, nlhs, 0);
    d = mexhb_of(prhs[0], cmd);
    mexhb_check(d, fricreg_hb_set_receptance(d->hb, mexa_pick(prhs[1], cmd, "method", methods, 3)),
                cmd);
}

/* hb_set_continuation(h, ds, ds_min, ds_max, max_points) */
void mexhb_set_continuation(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    const char *cmd = "hb_set_continuation";
    mexhb *d;
    double ds, ds_min, ds_max;
    (void)plhs;
    mexa_nargs(cmd, nrhs, 5, 5, nlhs, 0);
    d = mexhb_of(prhs[0], cmd);
    ds = mexa_scalar(prhs[1], cmd, "ds");
    ds_min = mexa_scalar(prhs[2], cmd, "ds_min");
    ds_max = mexa_scalar(prhs[3], cmd, "ds_max");
    mexhb_check(d,
                fricreg_hb_set_continuation(d->hb, ds, ds_min, ds_max,
                                            mexa_count(prhs[4], cmd, "max_points", 0,
                                                       (size_t)1 << 40)),
                cmd);
}

/* hb_set_max_iterations(h, total): the Newton steps one solving call may take (0: no bound). */
void mexhb_set_max_iterations(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    const char *cmd = "hb_set_max_iterations";
    mexhb *d;
    (void)plhs;
    mexa_nargs(cmd, nrhs, 2, 2, nlhs, 0);
    d = mexhb_of(prhs[0], cmd);
    mexhb_check(d,
                fricreg_hb_set_max_iterations(d->hb, (int64_t)mexa_count(prhs[1], cmd, "total", 0,
                                                                         (size_t)1 << 52)),
                cmd);
}

/* hb_set_stability(h, enable, method): enable 0 or 1 (true, false), method 'auto', 'hill',
 * 'monodromy' or 'condensed' (enum fricreg_hb_stability_method's order). */
void mexhb_set_stability(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    static const char *const methods[] = {"auto", "hill", "monodromy", "condensed"};
    const char *cmd = "hb_set_stability";
    mexhb *d;
    int enable, method;
    (void)plhs;
    mexa_nargs(cmd, nrhs, 3, 3, nlhs, 0);
    d = mexhb_of(prhs[0], cmd);
    if (mxIsLogical(prhs[1]) && mxGetNumberOfElements(prhs[1]) == 1)
        enable = mxIsLogicalScalarTrue(prhs[1]) ? 1 : 0;
    else
        enable = (int)mexa_count(prhs[1], cmd, "enable", 0, 1);
    method = mexa_pick(prhs[2], cmd, "method", methods, 4);
    mexhb_check(d, fricreg_hb_set_stability_method(d->hb, method), cmd);
    mexhb_check(d, fricreg_hb_set_stability(d->hb, enable), cmd);
    d->stability = enable;
}

/* [ndof, rows, harmonics, elements, stability] = hb_info(h) */
void mexhb_info(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    mxArray *out[5];
    mexhb *d;
    mexa_nargs("hb_info", nrhs, 1, 1, nlhs, 5);
    d = mexhb_of(prhs[0], "hb_info");
    out[0] = mxCreateDoubleScalar((double)d->ndof);
    out[1] = mxCreateDoubleScalar((double)d->rows);
    out[2] = mxCreateDoubleScalar((double)d->harmonics);
    out[3] = mxCreateDoubleScalar((double)fricreg_hb_element_count(d->hb));
    out[4] = mxCreateLogicalScalar(d->stability != 0);
    mexa_outputs(nlhs, plhs, out, 5);
}

/* hb_set_element_param(h, first, count, index, value): parameter index (from 1, in the
 * elements' types' layouts) of the elements first .. first + count - 1 (from 1, in the order
 * added) to value (fricreg_hb_set_element_param). */
void mexhb_set_element_param(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    const char *cmd = "hb_set_element_param";
    size_t first, count, index;
    mexhb *d;
    (void)plhs;
    mexa_nargs(cmd, nrhs, 5, 5, nlhs, 0);
    d = mexhb_of(prhs[0], cmd);
    first = mexa_count(prhs[1], cmd, "first", 1, (size_t)1 << 40) - 1; /* MATLAB's from 1 */
    count = mexa_count(prhs[2], cmd, "count", 0, (size_t)1 << 40);
    index = mexa_count(prhs[3], cmd, "index", 1, (size_t)1 << 40) - 1;
    mexhb_check(d,
                fricreg_hb_set_element_param(d->hb, first, count, index,
                                             mexa_scalar(prhs[4], cmd, "value")),
                cmd);
}

/* value = hb_get_element_param(h, element, index): parameter index (from 1) of element (from
 * 1) (fricreg_hb_get_element_param). */
void mexhb_get_element_param(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    const char *cmd = "hb_get_element_param";
    size_t element, index;
    double value = 0.0;
    mexhb *d;
    mexa_nargs(cmd, nrhs, 3, 3, nlhs, 1);
    d = mexhb_of(prhs[0], cmd);
    element = mexa_count(prhs[1], cmd, "element", 1, (size_t)1 << 40) - 1;
    index = mexa_count(prhs[2], cmd, "index", 1, (size_t)1 << 40) - 1;
    mexhb_check(d, fricreg_hb_get_element_param(d->hb, element, index, &value), cmd);
    plhs[0] = mxCreateDoubleScalar(value);
}
