/* SPDX-License-Identifier: GPL-3.0-or-later */
/* mex_structure.c — the gateway's commands that build a structure stepped in time
 * (fricreg_structure.h): its creation, the model's matrices, the contacts and their law, the
 * ground motion and the load, the joint elements, the initial state and the settings. One
 * command per C call; a failed call raises fricreg:<NAME> with the structure's own message
 * (fricreg_structure_errmsg). The run is in mex_structure_run.c.
 *
 * Layout: the library's matrices are row-major, MATLAB's column-major: a dense M, K, C or J is
 * copied at the boundary; a sparse one is passed as MATLAB keeps it, compressed sparse columns
 * from 0, its indices copied to int64_t. Without contacts (m = 0) the library's structure holds
 * one contact of bound 0 on dof 1, whose force is exactly 0, as Python's Structure and
 * fricreg-sim structure without --contacts; it is not shown. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "mex_args.h"
#include "mex_element.h"
#include "mex_handles.h"
#include "mex_structure.h"

mexst *mexst_of(const mxArray *a, const char *cmd)
{
    return mexh_get(a, MEXH_STRUCTURE, cmd, NULL);
}

void mexst_check(const mexst *d, int status, const char *cmd)
{
    if (status != FRICREG_OK)
        mexa_status(status, cmd, fricreg_structure_errmsg(d->s));
}

void mexst_free(void *object)
{
    mexst *d = object;
    if (d != NULL) {
        fricreg_structure_free(d->s);
        free(d);
    }
}

/* h = st_create(ndof, m): a structure of ndof dofs and m contacts (m = 0: none shown). */
void mexst_create(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    static const int64_t ptr[2] = {0, 1}, ind[1] = {0};
    static const double one = 1.0, zero = 0.0;
    const char *cmd = "st_create";
    fricreg_structure *s = NULL;
    mexst *d;
    size_t ndof, m;
    int status;
    mexa_nargs(cmd, nrhs, 2, 2, nlhs, 1);
    ndof = mexa_count(prhs[0], cmd, "ndof", 0, (size_t)1 << 40);
    m = mexa_count(prhs[1], cmd, "m", 0, (size_t)1 << 40);
    status = fricreg_structure_create(ndof, m > 0 ? m : 1, &s);
    if (status != FRICREG_OK)
        mexa_status(status, cmd,
                    status == FRICREG_EINVAL ? "ndof 1..2^40, m (the contacts) 0..2^26" : NULL);
    if (m == 0) { /* the library's one contact, on dof 1, of bound 0: no friction */
        status = fricreg_structure_set_matrix(s, FRICREG_CONTACTS, 1, ndof, FRICREG_MATRIX_CSR, ptr,
                                              ind, &one);
        if (status == FRICREG_OK)
            status = fricreg_structure_set_bounds(s, 1, &zero);
        if (status != FRICREG_OK) {
            fricreg_structure_free(s);
            mexa_status(status, cmd, NULL);
        }
    }
    d = calloc(1, sizeof *d);
    if (d == NULL) {
        fricreg_structure_free(s);
        mexa_status(FRICREG_ENOMEM, cmd, NULL);
    }
    d->s = s;
    d->ndof = ndof;
    d->m = m;
    plhs[0] = mxCreateDoubleScalar(mexh_add(MEXH_STRUCTURE, d));
}

/* st_set_matrix(h, which, A): which 'mass', 'stiffness', 'damping' (ndof x ndof) or 'contacts'
 * (J, m x ndof), full or sparse. */
void mexst_set_matrix(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    static const char *const names[] = {"mass", "stiffness", "damping", "contacts"};
    static const int codes[] = {FRICREG_MASS, FRICREG_STIFFNESS, FRICREG_DAMPING, FRICREG_CONTACTS};
    const char *cmd = "st_set_matrix";
    const mxArray *a;
    mexst *d;
    size_t rows, n;
    int which, status;
    (void)plhs;
    mexa_nargs(cmd, nrhs, 3, 3, nlhs, 0);
    d = mexst_of(prhs[0], cmd);
    which = mexa_pick(prhs[1], cmd, "matrix", names, 4);
    a = prhs[2];
    n = d->ndof;
    rows = which == 3 ? d->m : n;
    if (!mxIsDouble(a) || mxIsComplex(a))
        mexa_error("fricreg:type", "%s: %s must be a real double matrix, not %s%s", cmd,
                   names[which], mxIsComplex(a) ? "complex " : "", mxGetClassName(a));
    if (!mexa_is_size(a, rows, n) || rows == 0)
        mexa_error("fricreg:size", "%s: %s must be %s x ndof = %lux%lu, not %dx%d", cmd,
                   names[which], which == 3 ? "m" : "ndof", (unsigned long)rows, (unsigned long)n,
                   (int)mxGetM(a), (int)mxGetN(a));
    if (mxIsSparse(a)) { /* MATLAB's own compressed sparse columns, zero-based */
        const mwIndex *jc = mxGetJc(a), *ir = mxGetIr(a);
        size_t nnz = (size_t)jc[n];
        int64_t *ptr = mxCalloc(n + 1, sizeof *ptr), *ind = mxCalloc(nnz + 1, sizeof *ind);
        for (size_t j = 0; j <= n; j++)
            ptr[j] = (int64_t)jc[j];
        for (size_t k = 0; k < nnz; k++)
            ind[k] = (int64_t)ir[k];
        status = fricreg_structure_set_matrix(d->s, codes[which], rows, n, FRICREG_MATRIX_CSC, ptr,
                                              ind, mxGetPr(a));
    } else { /* a copy: column-major to the library's row-major */
        double *copy = mexa_scratch(rows * n);
        mexa_to_rows(mxGetPr(a), copy, rows, n);
        status = fricreg_structure_set_matrix(d->s, codes[which], rows, n, FRICREG_MATRIX_DENSE,
                                              NULL, NULL, copy);
    }
    mexst_check(d, status, cmd);
}

/* st_set_rayleigh(h, a0, a1): C = a0 M + a1 K. */
void mexst_set_rayleigh(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    const char *cmd = "st_set_rayleigh";
    mexst *d;
    double a0, a1;
    (void)plhs;
    mexa_nargs(cmd, nrhs, 3, 3, nlhs, 0);
    d = mexst_of(prhs[0], cmd);
    a0 = mexa_scalar(prhs[1], cmd, "a0");
    a1 = mexa_scalar(prhs[2], cmd, "a1");
    mexst_check(d, fricreg_structure_set_rayleigh(d->s, a0, a1), cmd);
}

/* st_set_bounds(h, mun): the contacts' bounds mu N, a vector of m. */
void mexst_set_bounds(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    const char *cmd = "st_set_bounds";
    mexst *d;
    const double *mun;
    (void)plhs;
    mexa_nargs(cmd, nrhs, 2, 2, nlhs, 0);
    d = mexst_of(prhs[0], cmd);
    mun = mexa_vector(prhs[1], cmd, "mun", d->m, NULL);
    if (d->m > 0)
        mexst_check(d, fricreg_structure_set_bounds(d->s, d->m, mun), cmd);
}

/* eps = st_set_law(h, law, eps): law a name (fricreg_law_name's) or a code; eps [] for
 * fricreg-sim's default, 1 % of the ground record's peak velocity or 1e-3 without a record
 * (read after the record is set). Returns the eps in force. */
void mexst_set_law(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    const char *cmd = "st_set_law";
    mexst *d;
    double eps, pgv = 0.0;
    int law;
    mexa_nargs(cmd, nrhs, 3, 3, nlhs, 1);
    d = mexst_of(prhs[0], cmd);
    if (mxIsChar(prhs[1])) {
        char name[32];
        mexa_string(prhs[1], cmd, "law", name, sizeof name);
        law = fricreg_law_from_name(name);
        if (law == 0)
            mexa_error("fricreg:EINVAL",
                       "%s: '%s' is not a law (fricreg_mex('law_names')) "
                       "(FRICREG_EINVAL)",
                       cmd, name);
    } else {
        law = (int)mexa_count(prhs[1], cmd, "law", 0, 1000);
    }
    if (mxIsEmpty(prhs[2])) {
        fricreg_structure_get_value(d->s, FRICREG_SVALUE_GROUND_PGV, &pgv);
        eps = pgv > 0.0 ? 0.01 * pgv : 1e-3;
    } else {
        eps = mexa_scalar(prhs[2], cmd, "eps");
    }
    mexst_check(d, fricreg_structure_set_law(d->s, law, eps), cmd);
    plhs[0] = mxCreateDoubleScalar(eps);
}

/* st_set_influence(h, r): the ground motion's influence vector, ndof. */
void mexst_set_influence(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    const char *cmd = "st_set_influence";
    mexst *d;
    (void)plhs;
    mexa_nargs(cmd, nrhs, 2, 2, nlhs, 0);
    d = mexst_of(prhs[0], cmd);
    mexst_check(d,
                fricreg_structure_set_influence(d->s, d->ndof,
                                                mexa_vector(prhs[1], cmd, "influence", d->ndof,
                                                            NULL)),
                cmd);
}

/* st_set_ground_accel(h, t0, dt_rec, ag): a record of n >= 2 samples (ag [] removes it). */
void mexst_set_ground_accel(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    const char *cmd = "st_set_ground_accel";
    mexst *d;
    const double *ag;
    double t0, dt_rec;
    size_t n = 0;
    (void)plhs;
    mexa_nargs(cmd, nrhs, 4, 4, nlhs, 0);
    d = mexst_of(prhs[0], cmd);
    t0 = mexa_scalar(prhs[1], cmd, "t0");
    dt_rec = mexa_scalar(prhs[2], cmd, "dt_rec");
    ag = mexa_vector(prhs[3], cmd, "ground_accel", (size_t)-1, &n);
    mexst_check(d, fricreg_structure_set_ground_accel(d->s, t0, dt_rec, n, ag), cmd);
}

/* st_set_load(h, p, t0, dt_rec, g): the load p g(t), p a vector of ndof, g a record of n >= 2
 * samples at t0 + k dt_rec, or [] for g = 1 (a constant load). */
void mexst_set_load(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    const char *cmd = "st_set_load";
    mexst *d;
    const double *p, *g;
    double t0, dt_rec;
    size_t n = 0;
    (void)plhs;
    mexa_nargs(cmd, nrhs, 5, 5, nlhs, 0);
    d = mexst_of(prhs[0], cmd);
    p = mexa_vector(prhs[1], cmd, "load", d->ndof, NULL);
    t0 = mexa_scalar(prhs[2], cmd, "t0");
    dt_rec = mexa_scalar(prhs[3], cmd, "dt_rec");
    g = mexa_vector(prhs[4], cmd, "load_history", (size_t)-1, &n);
    mexst_check(d, fricreg_structure_set_load(d->s, d->ndof, p, t0, dt_rec, n, g), cmd);
}

/* st_add_elements(h, type, J, params): me elements of one type (fricreg_structure_add_elements),
 * J (me dim) x ndof, params me x nparams (a row each) or a vector of nparams shared. */
void mexst_add_elements(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    const char *cmd = "st_add_elements";
    const fricreg_element_type *first, *type = NULL;
    const mxArray *pa, *ja;
    double *J, *params;
    size_t dim, me, np;
    mexst *d;
    (void)plhs;
    mexa_nargs(cmd, nrhs, 4, 4, nlhs, 0);
    d = mexst_of(prhs[0], cmd);
    first = mexe_first(prhs[1], cmd);
    ja = prhs[2];
    pa = prhs[3];
    mexa_real(ja, cmd, "J");
    mexa_real(pa, cmd, "params");
    dim = (size_t)fricreg_element_dim(first);
    if (mxGetNumberOfDimensions(ja) != 2 || mxGetM(ja) == 0 || (size_t)mxGetM(ja) % dim != 0 ||
        (size_t)mxGetN(ja) != d->ndof)
        mexa_error("fricreg:size",
                   "%s: J must be (me %lu) x ndof = (me %lu) x %lu (%s: %lu rows an element), "
                   "not %dx%d",
                   cmd, (unsigned long)dim, (unsigned long)dim, (unsigned long)d->ndof,
                   fricreg_element_name(first), (unsigned long)dim, (int)mxGetM(ja),
                   (int)mxGetN(ja));
    if (d->nsets == MEXST_MAX_SETS)
        mexa_error("fricreg:EINVAL", "%s: at most %d element sets (FRICREG_EINVAL)", cmd,
                   MEXST_MAX_SETS);
    me = (size_t)mxGetM(ja) / dim;
    if (mxGetNumberOfDimensions(pa) == 2 && (size_t)mxGetM(pa) == me &&
        (type = mexe_member(first, (size_t)mxGetN(pa))) != NULL) {
        np = (size_t)mxGetN(pa); /* a copy: me x np column-major to row-major */
        params = mexa_scratch(me * np);
        mexa_to_rows(mxGetPr(pa), params, me, np);
    } else if (mexa_is_vector(pa) &&
               (type = mexe_member(first, (size_t)mxGetNumberOfElements(pa))) != NULL) {
        np = (size_t)mxGetNumberOfElements(pa); /* shared: repeated, a row per element */
        params = mexa_scratch(me * np);
        for (size_t i = 0; i < me; i++)
            memcpy(params + np * i, mxGetPr(pa), np * sizeof *params);
    } else {
        mexe_bad_params(first, cmd,
                        "params must be me x nparams (a row an element) or a vector of nparams "
                        "(shared)",
                        (size_t)mxGetM(pa), (size_t)mxGetN(pa));
        return;
    }
    J = mexa_scratch(me * dim * d->ndof);
    mexa_to_rows(mxGetPr(ja), J, me * dim, d->ndof);
    mexst_check(d, fricreg_structure_add_elements(d->s, type, me, d->ndof, J, params), cmd);
    d->set_me[d->nsets] = me;
    d->set_dim[d->nsets] = dim;
    d->nsets++;
}

/* st_set_initial(h, u0, v0): restart at t = 0 from u0, v0 (vectors of ndof, [] for zeros); the
 * warnings already raised may be raised again. */
void mexst_set_initial(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    const char *cmd = "st_set_initial";
    const double *u0, *v0;
    double *zeros;
    mexst *d;
    (void)plhs;
    mexa_nargs(cmd, nrhs, 3, 3, nlhs, 0);
    d = mexst_of(prhs[0], cmd);
    zeros = mexa_scratch(d->ndof);
    u0 = mxIsEmpty(prhs[1]) ? zeros : mexa_vector(prhs[1], cmd, "u0", d->ndof, NULL);
    v0 = mxIsEmpty(prhs[2]) ? zeros : mexa_vector(prhs[2], cmd, "v0", d->ndof, NULL);
    if (mxIsEmpty(prhs[1]))
        mexa_real(prhs[1], cmd, "u0");
    if (mxIsEmpty(prhs[2]))
        mexa_real(prhs[2], cmd, "v0");
    mexst_check(d, fricreg_structure_set_initial(d->s, d->ndof, u0, v0), cmd);
    d->warned = 0;
}

/* st_set_newton(h, tol, max_iter) */
void mexst_set_newton(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    const char *cmd = "st_set_newton";
    mexst *d;
    double tol;
    int max_iter;
    (void)plhs;
    mexa_nargs(cmd, nrhs, 3, 3, nlhs, 0);
    d = mexst_of(prhs[0], cmd);
    tol = mexa_scalar(prhs[1], cmd, "tol");
    max_iter = (int)mexa_count(prhs[2], cmd, "max_iter", 0, 1000000);
    mexst_check(d, fricreg_structure_set_newton(d->s, tol, max_iter), cmd);
}

/* st_set_error_estimate(h, which): 'off', 'on' (two companions) or 'one' (1.6's one). */
void mexst_set_error_estimate(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    static const char *const names[] = {"off", "on", "one"};
    static const int codes[] = {FRICREG_ESTIMATE_OFF, FRICREG_ESTIMATE_TWO_COMPANIONS,
                                FRICREG_ESTIMATE_ONE_COMPANION};
    const char *cmd = "st_set_error_estimate";
    mexst *d;
    (void)plhs;
    mexa_nargs(cmd, nrhs, 2, 2, nlhs, 0);
    d = mexst_of(prhs[0], cmd);
    mexst_check(d,
                fricreg_structure_set_error_estimate(
                    d->s, codes[mexa_pick(prhs[1], cmd, "error_estimate", names, 3)]),
                cmd);
}
