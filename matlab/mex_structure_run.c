/* SPDX-License-Identifier: GPL-3.0-or-later */
/* mex_structure_run.c — the gateway's command st_run: a structure stepped to t_end by Newmark,
 * HHT-alpha or central differences in one fricreg_structure_run call, its time series recorded
 * by an observer (fricreg_structure_set_observer), and what the structure's getters report at
 * the run's end, as one struct: Python's StructureResult. The library's accuracy warnings
 * (fricreg_structure_warning_count, _get_warning) are in the result's field warnings and are
 * also raised as warning('fricreg:accuracy', 'name: message'), each code once until the next
 * st_set_initial (Python's AccuracyWarning). */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mex_args.h"
#include "mex_structure.h"

/* The time series: rows of (t, u[nout], v[nout], f[m]) at the output dofs, malloc'd (the observer cannot raise a
 * MATLAB error: it runs inside the library), freed before any error or warning is raised. */
typedef struct {
    double *rows;
    size_t count, cap, nout, m;
    const size_t *dofs; /* the output dofs, from 0 */
    long steps, every;
    int nomem;
} recorder;

static size_t width(const recorder *r)
{
    return 1 + 2 * r->nout + r->m;
}

static int push(recorder *r, double t, const double *u, const double *v, const double *f)
{
    double *row;
    if (r->count == r->cap) {
        size_t cap = r->cap ? 2 * r->cap : 256;
        double *bigger = realloc(r->rows, cap * width(r) * sizeof *bigger);
        if (bigger == NULL) {
            r->nomem = 1;
            return 1;
        }
        r->rows = bigger;
        r->cap = cap;
    }
    row = r->rows + width(r) * r->count++;
    row[0] = t;
    for (size_t j = 0; j < r->nout; j++) {
        row[1 + j] = u[r->dofs[j]];
        row[1 + r->nout + j] = v[r->dofs[j]];
    }
    if (r->m > 0)
        memcpy(row + 1 + 2 * r->nout, f, r->m * sizeof *row);
    return 0;
}

static int observe(void *user, double t, size_t ndof, const double u[], const double v[], size_t m,
                   const double f[])
{
    recorder *r = user;
    (void)ndof;
    (void)m;
    return ++r->steps % r->every == 0 ? push(r, t, u, v, f) : 0;
}

/* The state now as a row, unless the last row is at this time already. */
static void push_now(recorder *r, const mexst *d)
{
    double *u = mexa_scratch(2 * d->ndof), *f = mexa_scratch(d->m > 0 ? d->m : 1), t = 0.0;
    fricreg_structure_get_value(d->s, FRICREG_SVALUE_TIME, &t);
    if (r->count > 0 && r->rows[width(r) * (r->count - 1)] == t)
        return;
    fricreg_structure_get_state(d->s, d->ndof, u, u + d->ndof, NULL);
    fricreg_structure_get_forces(d->s, d->m > 0 ? d->m : 1, f);
    push(r, t, u, u + d->ndof, f);
}

/* Columns of the time series: rows' column first .. first + cols - 1 as nrows x cols. */
static mxArray *series(const recorder *r, size_t first, size_t cols)
{
    mxArray *a = mexa_matrix(r->count, cols);
    double *x = mxGetPr(a);
    for (size_t i = 0; i < r->count; i++)
        for (size_t c = 0; c < cols; c++)
            x[i + r->count * c] = r->rows[width(r) * i + first + c];
    return a;
}

static mxArray *row_vector(size_t n, double **data)
{
    mxArray *a = mexa_matrix(1, n);
    *data = mxGetPr(a);
    return a;
}

/* An error estimate (getter and quantity), a struct with error and kind, or [] without one. */
static mxArray *estimate(const mexst *d, int quantity, size_t n)
{
    static const char *fields[] = {"error", "kind"};
    static const char *const kinds[] = {"", "asymptotic", "bound", "assumed"};
    double *err = mexa_scratch(n);
    int *kind = mxCalloc(n + 1, sizeof *kind), status;
    mxArray *out, *names;
    if (quantity == FRICREG_EST_PEAK_DISPLACEMENT)
        status = fricreg_structure_get_peak_displacement_error(d->s, n, err);
    else if (quantity == FRICREG_EST_DISSIPATION)
        status = n > 0 ? fricreg_structure_get_dissipation_error(d->s, n, err) : FRICREG_OK;
    else
        status = n > 0 ? fricreg_structure_get_jenkins_dissipation_error(d->s, n, err) : FRICREG_OK;
    if (status == FRICREG_OK && n > 0)
        status = fricreg_structure_get_error_kind(d->s, quantity, n, kind);
    if (status != FRICREG_OK ||
        fricreg_structure_get_peak_displacement_error(d->s, d->ndof, mexa_scratch(d->ndof)) !=
            FRICREG_OK)
        return mexa_matrix(0, 0);
    out = mxCreateStructMatrix(1, 1, 2, fields);
    names = mxCreateCellMatrix(1, (mwSize)n);
    for (size_t i = 0; i < n; i++)
        mxSetCell(names, (mwIndex)i,
                  mxCreateString(kind[i] >= 1 && kind[i] <= 3 ? kinds[kind[i]] : "unknown"));
    mxSetField(out, 0, "error", mexa_matrix(1, n));
    memcpy(mxGetPr(mxGetField(out, 0, "error")), err, n * sizeof *err);
    mxSetField(out, 0, "kind", names);
    return out;
}

static mxArray *energy(const mexst *d)
{
    static const char *names[] = {"initial", "input",    "kinetic",  "strain",
                                  "viscous", "friction", "elements", "residual"};
    static const int which[] = {FRICREG_SVALUE_INITIAL, FRICREG_SVALUE_INPUT,
                                FRICREG_SVALUE_KINETIC, FRICREG_SVALUE_STRAIN,
                                FRICREG_SVALUE_VISCOUS, FRICREG_SVALUE_FRICTION,
                                FRICREG_SVALUE_JENKINS, FRICREG_SVALUE_RESIDUAL};
    mxArray *out = mxCreateStructMatrix(1, 1, 8, names);
    for (int k = 0; k < 8; k++) {
        double value = 0.0;
        fricreg_structure_get_value(d->s, which[k], &value);
        mxSetField(out, 0, names[k], mxCreateDoubleScalar(value));
    }
    return out;
}

static mxArray *stats(const mexst *d)
{
    static const char *names[] = {"steps", "newton_iterations", "newton_max", "newton_failures",
                                  "line_search_cuts"};
    mxArray *out = mxCreateStructMatrix(1, 1, 5, names);
    for (int k = 0; k < 5; k++) {
        int64_t value = 0;
        fricreg_structure_get_stat(d->s, k, &value); /* enum fricreg_structure_stat, 0..4 */
        mxSetField(out, 0, names[k], mxCreateDoubleScalar((double)value));
    }
    return out;
}

/* The elements' forces now, a cell of one me x dim array per set, and their dissipations. */
static void elements(const mexst *d, mxArray **forces, mxArray **dissipation)
{
    size_t me = fricreg_structure_element_count(d->s), nf = 0, at = 0;
    double *f, *D;
    for (size_t k = 0; k < d->nsets; k++)
        nf += d->set_me[k] * d->set_dim[k];
    f = mexa_scratch(nf);
    *dissipation = row_vector(me, &D);
    if (me > 0)
        fricreg_structure_get_elements(d->s, me, f, NULL, D);
    *forces = mxCreateCellMatrix(1, (mwSize)d->nsets);
    for (size_t k = 0; k < d->nsets; k++) {
        mxArray *a = mexa_matrix(d->set_me[k], d->set_dim[k]);
        mexa_to_cols(f + at, mxGetPr(a), d->set_me[k], d->set_dim[k]);
        at += d->set_me[k] * d->set_dim[k];
        mxSetCell(*forces, (mwIndex)k, a);
    }
}

/* The warnings judged now, a struct array of name and message; those not raised since the last
 * st_set_initial raised as fricreg:accuracy (after everything else is built: a warning made an
 * error by the caller then leaves nothing behind). */
static mxArray *warnings(mexst *d, int raise)
{
    static const char *fields[] = {"name", "message"};
    size_t count = fricreg_structure_warning_count(d->s);
    mxArray *out = mxCreateStructMatrix(1, (mwSize)count, 2, fields);
    for (size_t k = 0; k < count; k++) {
        char msg[512];
        int code = 0;
        const char *name;
        fricreg_structure_get_warning(d->s, k, &code, msg, sizeof msg);
        name = fricreg_warning_name(code);
        mxSetField(out, (mwIndex)k, "name", mxCreateString(name != NULL ? name : "unknown"));
        mxSetField(out, (mwIndex)k, "message", mxCreateString(msg));
        if (raise && code > 0 && code < 64 && !(d->warned & (1UL << code))) {
            d->warned |= 1UL << code;
            mexWarnMsgIdAndTxt("fricreg:accuracy", "%s: %s", name != NULL ? name : "unknown", msg);
        }
    }
    return out;
}

/* The output dofs: [] for all, else a vector of dofs from 1 (whole, in 1..ndof), from 0 in dofs
 * (mxMalloc'd); returns their count. */
static size_t output_dofs(const mxArray *a, const mexst *d, const char *cmd, size_t **dofs)
{
    const double *x;
    size_t n = 0;
    mexa_real(a, cmd, "output_dofs");
    if (mxIsEmpty(a)) {
        n = d->ndof;
        *dofs = mxCalloc(n, sizeof **dofs);
        for (size_t j = 0; j < n; j++)
            (*dofs)[j] = j;
        return n;
    }
    x = mexa_vector(a, cmd, "output_dofs", (size_t)-1, &n);
    *dofs = mxCalloc(n, sizeof **dofs);
    for (size_t j = 0; j < n; j++) {
        if (!(x[j] >= 1 && x[j] <= (double)d->ndof && x[j] == (double)(size_t)x[j]))
            mexa_error("fricreg:EINVAL",
                       "%s: output_dofs(%lu) = %g is not a dof (1..%lu) (FRICREG_EINVAL)", cmd,
                       (unsigned long)j + 1, x[j], (unsigned long)d->ndof);
        (*dofs)[j] = (size_t)x[j] - 1;
    }
    return n;
}

/* r = st_run(h, integrator, dt, t_end, every, alpha, output_dofs): integrator 'newmark'
 * (average acceleration), 'hht' (HHT-alpha with alpha) or 'central'; a row every every-th step
 * of the run, and the first and the last, with u and v at the output dofs ([] for all). */
void mexst_run(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    static const char *fields[] = {"times",
                                   "displacements",
                                   "velocities",
                                   "forces",
                                   "output_dofs",
                                   "t",
                                   "peak_displacement",
                                   "dissipation",
                                   "element_dissipation",
                                   "element_forces",
                                   "energy",
                                   "stats",
                                   "peak_displacement_error",
                                   "dissipation_error",
                                   "element_dissipation_error",
                                   "warnings"};
    const char *cmd = "st_run";
    recorder rec;
    size_t *dofs;
    mexst *d;
    mxArray *out, *forces, *diss;
    char scheme[16], msg[512];
    double dt, t_end, alpha, t = 0.0, *x;
    static const char *const schemes[] = {"newmark", "hht", "central"};
    int status = FRICREG_OK, which;
    mexa_nargs(cmd, nrhs, 7, 7, nlhs, 1);
    d = mexst_of(prhs[0], cmd);
    mexa_string(prhs[1], cmd, "integrator", scheme, sizeof scheme);
    dt = mexa_scalar(prhs[2], cmd, "dt");
    t_end = mexa_scalar(prhs[3], cmd, "t_end");
    memset(&rec, 0, sizeof rec);
    rec.every = (long)mexa_count(prhs[4], cmd, "output_every", 1, 1L << 30);
    alpha = mexa_scalar(prhs[5], cmd, "alpha");
    rec.nout = output_dofs(prhs[6], d, cmd, &dofs);
    rec.dofs = dofs;
    /* the scheme set only where it changes, as Python's Structure.run: a setter between two
     * runs would start the second one's grid anew (a continued run is one run bit for bit) */
    for (which = 0; which < 3 && strcmp(scheme, schemes[which]) != 0; which++)
        ;
    if (which == 3)
        mexa_error("fricreg:EINVAL",
                   "%s: integrator '%s' is not one of newmark, hht, central (FRICREG_EINVAL)", cmd,
                   scheme);
    if (which == 0 && d->scheme != 0)
        status = fricreg_structure_set_newmark(d->s, 0.25, 0.5);
    else if (which == 1 && (d->scheme != 1 || !(d->alpha == alpha)))
        status = fricreg_structure_set_hht(d->s, alpha);
    else if (which == 2 && d->scheme != 2)
        status = fricreg_structure_set_central_difference(d->s);
    mexst_check(d, status, cmd);
    d->scheme = which;
    d->alpha = alpha;
    rec.m = d->m;
    push_now(&rec, d);
    fricreg_structure_set_observer(d->s, observe, &rec);
    status = rec.nomem ? FRICREG_ENOMEM : fricreg_structure_run(d->s, dt, t_end);
    fricreg_structure_set_observer(d->s, NULL, NULL);
    snprintf(msg, sizeof msg, "%s", fricreg_structure_errmsg(d->s));
    push_now(&rec, d);
    if (status != FRICREG_OK || rec.nomem) {
        char detail[600];
        fricreg_structure_get_value(d->s, FRICREG_SVALUE_TIME, &t);
        free(rec.rows);
        snprintf(detail, sizeof detail, "after t = %.17g: %s", t,
                 status != FRICREG_OK ? msg : "out of memory for the time series");
        mexa_status(status != FRICREG_OK ? status : FRICREG_ENOMEM, cmd, detail);
    }
    out = mxCreateStructMatrix(1, 1, 16, fields);
    mxSetField(out, 0, "times", series(&rec, 0, 1));
    mxSetField(out, 0, "displacements", series(&rec, 1, rec.nout));
    mxSetField(out, 0, "velocities", series(&rec, 1 + rec.nout, rec.nout));
    mxSetField(out, 0, "forces", series(&rec, 1 + 2 * rec.nout, d->m));
    mxSetField(out, 0, "output_dofs", row_vector(rec.nout, &x));
    for (size_t j = 0; j < rec.nout; j++)
        x[j] = (double)dofs[j] + 1;
    free(rec.rows);
    fricreg_structure_get_value(d->s, FRICREG_SVALUE_TIME, &t);
    mxSetField(out, 0, "t", mxCreateDoubleScalar(t));
    mxSetField(out, 0, "peak_displacement", row_vector(d->ndof, &x));
    fricreg_structure_get_peak_displacement(d->s, d->ndof, x);
    mxSetField(out, 0, "dissipation", row_vector(d->m, &x));
    if (d->m > 0)
        fricreg_structure_get_dissipation(d->s, d->m, x);
    elements(d, &forces, &diss);
    mxSetField(out, 0, "element_dissipation", diss);
    mxSetField(out, 0, "element_forces", forces);
    mxSetField(out, 0, "energy", energy(d));
    mxSetField(out, 0, "stats", stats(d));
    mxSetField(out, 0, "peak_displacement_error",
               estimate(d, FRICREG_EST_PEAK_DISPLACEMENT, d->ndof));
    mxSetField(out, 0, "dissipation_error", estimate(d, FRICREG_EST_DISSIPATION, d->m));
    mxSetField(out, 0, "element_dissipation_error",
               estimate(d, FRICREG_EST_ELEMENT_DISSIPATION, fricreg_structure_element_count(d->s)));
    mxSetField(out, 0, "warnings", warnings(d, 0));
    plhs[0] = out;
    mxDestroyArray(warnings(d, 1)); /* judged anew (the same list), now raised */
}
