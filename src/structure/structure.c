/* SPDX-License-Identifier: GPL-3.0-or-later */
/* structure.c — fricreg_structure: life cycle, the setters of everything but the model
 * matrices (model.c), and the getters. The set-up of a model is prepare.c, the integrators
 * newmark.c, central_difference.c and structure_ode.c, the energy balance energy.c. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/companion_estimate.h" /* FR_ANSWER_RTOL */
#include "base/gsl_mem.h"
#include "base/sparse_factor.h"
#include "law/law.h"
#include "structure_internal.h"
#include "base/free_all.h"

/* Sanity bounds: 2^40 degrees of freedom (memory runs out long before), and the context's
 * 2^26 contacts. */
#define MAX_DOF ((size_t)1 << 40)
#define MAX_CONTACTS ((size_t)1 << 26)

/* ---- Life cycle --------------------------------------------------------------------------- */

void fricreg_structure_free(fricreg_structure *s)
{
    if (s == NULL)
        return;
    gsl_vector *vectors[] = {
        s->r,          s->p,          s->Mr,      s->u,          s->v,
        s->a,          s->ptil,       s->x,       s->u1,         s->v1,
        s->ptil1,      s->hist,       s->up,      s->vp,         s->work,
        s->yb,         s->dx,         s->xt,      s->spread,     s->a_held,
        s->f,          s->f1,         s->zdot,    s->afree,      s->fk,
        s->G,          s->df,         s->ft,      s->Gt,         s->z0,
        s->af0,        s->mwork,      s->mwork2,  s->f_held,     s->at_start.weff,
        s->at_start.w, s->at_fk.weff, s->at_fk.w, s->at_df.weff, s->at_df.w,
        s->at_ft.weff, s->at_ft.w};
    for (size_t k = 0; k < sizeof vectors / sizeof *vectors; k++)
        free(vectors[k]); /* gsl_mem.h: one block each */
    cholmod_sparse **model[] = {&s->M, &s->K, &s->C, &s->Jt, &s->Cd};
    for (size_t k = 0; k < sizeof model / sizeof *model; k++)
        cholmod_l_free_sparse(model[k], &s->cc);
    fr_cfactor_free(&s->mass, &s->cc);
    fr_cfactor_free(&s->step, &s->cc);
    fr_newton_matrix_free(&s->newton, &s->cc);
    fr_contact_sparse_free(&s->sparse, &s->cc);
    fr_elements_free(s);
    fr_cholmod_finish(&s->cc);
    fricreg_ctx_free(s->ctx);
    FR_FREE_ALL(s->mun, s->stopped, s->ground.x, s->load.x, s->energy.per_contact, s->peak,
                s->ode_atol);
    fricreg_structure_free(s->companion);
    fricreg_structure_free(s->confirm);
    free(s);
}

/* Every GSL vector on fricreg's own memory (gsl_mem.h): none of GSL's allocators, which
 * report a failed malloc to GSL's error handler. The model starts as M = I, K = C = 0. */
static int allocate(fricreg_structure *s)
{
    size_t n = s->n, m = s->m;
    gsl_vector **nv[] = {&s->r,    &s->p,  &s->Mr, &s->u,     &s->v,      &s->a,     &s->ptil,
                         &s->x,    &s->u1, &s->v1, &s->ptil1, &s->hist,   &s->up,    &s->vp,
                         &s->work, &s->yb, &s->dx, &s->xt,    &s->spread, &s->a_held};
    for (size_t k = 0; k < sizeof nv / sizeof *nv; k++)
        if ((*nv[k] = fr_gsl_vector_new(n)) == NULL)
            return 0;
    gsl_vector **mv[] = {&s->f,          &s->f1,         &s->zdot,
                         &s->afree,      &s->fk,         &s->G,
                         &s->df,         &s->ft,         &s->Gt,
                         &s->z0,         &s->af0,        &s->mwork,
                         &s->mwork2,     &s->f_held,     &s->at_start.weff,
                         &s->at_start.w, &s->at_fk.weff, &s->at_fk.w,
                         &s->at_df.weff, &s->at_df.w,    &s->at_ft.weff,
                         &s->at_ft.w};
    for (size_t k = 0; k < sizeof mv / sizeof *mv; k++)
        if ((*mv[k] = fr_gsl_vector_new(m)) == NULL)
            return 0;
    s->mun = malloc(m * sizeof *s->mun);
    s->stopped = calloc(m, sizeof *s->stopped);
    s->energy.per_contact = calloc(m, sizeof *s->energy.per_contact);
    s->peak = calloc(n, sizeof *s->peak);
    if (!(s->mun && s->stopped && s->energy.per_contact && s->peak) ||
        fricreg_ctx_create(m, &s->ctx) != FRICREG_OK || fr_cholmod_start(&s->cc) != FRICREG_OK)
        return 0;
    s->M = cholmod_l_speye(n, n, CHOLMOD_REAL, &s->cc);
    s->K = cholmod_l_spzeros(n, n, 0, CHOLMOD_REAL, &s->cc);
    s->C = cholmod_l_spzeros(n, n, 0, CHOLMOD_REAL, &s->cc);
    if (!(s->M && s->K && s->C))
        return 0;
    s->M->stype = s->K->stype = s->C->stype = 1;
    return 1;
}

int fricreg_structure_create(size_t ndof, size_t m, fricreg_structure **out)
{
    if (out == NULL)
        return FRICREG_ENULL;
    if (ndof == 0 || m == 0 || ndof > MAX_DOF || m > MAX_CONTACTS)
        return FRICREG_EINVAL;
    fricreg_structure *s = calloc(1, sizeof *s);
    if (s == NULL)
        return FRICREG_ENOMEM;
    s->n = ndof;
    s->m = m;
    int ok = allocate(s);
    if (!ok) {
        fricreg_structure_free(s);
        return FRICREG_ENOMEM;
    }
    for (size_t i = 0; i < m; i++)
        s->mun[i] = 1.0;
    gsl_vector_set_all(s->r, 1.0); /* every DOF moves with the ground, as the CLI's default */
    s->bound_scale = -1.0;
    s->alpha = 0.0;
    s->beta = 0.25;
    s->gamma = 0.5;
    s->newton_tol = 1e-10;
    s->newton_max = 50;
    s->max_steps = -1; /* the law's default (fr_law_max_adaptive_steps) */
    s->tol_scale = 1.0;
    s->answer_rtol = FR_ANSWER_RTOL;
    s->companions = FRICREG_COMPANIONS_AUTO;
    s->screen_peak_err = s->screen_dissipation_err = NAN;
    s->fresh = 1;
    *out = s;
    return FRICREG_OK;
}

int fricreg_structure_set_observer(fricreg_structure *s, fricreg_structure_observer fn, void *user)
{
    if (s == NULL || s->running)
        return fr_structure_refuse(s, "set_observer");
    s->observer = fn;
    s->observer_user = user;
    return FRICREG_OK;
}

int fricreg_structure_set_max_steps(fricreg_structure *s, int64_t max_steps)
{
    if (s == NULL || s->running)
        return fr_structure_refuse(s, "set_max_steps");
    if (max_steps < 0)
        return fr_fail(s, FRICREG_EINVAL,
                       "set_max_steps: max_steps = %lld must be >= 0 (0: no bound)",
                       (long long)max_steps);
    s->max_steps = max_steps;
    fr_structure_changed(s, FR_CHANGED_MAX_STEPS);
    return FRICREG_OK;
}

/* ---- Validation ---------------------------------------------------------------------------- */

static int all_finite(const double x[], size_t len, size_t *bad)
{
    for (size_t k = 0; k < len; k++)
        if (!isfinite(x[k])) {
            *bad = k;
            return 0;
        }
    return 1;
}

/* ---- Model setters (the matrices: model.c) ------------------------------------------------ */

int fricreg_structure_set_rayleigh(fricreg_structure *s, double a0, double a1)
{
    if (s == NULL || s->running)
        return fr_structure_refuse(s, "set_rayleigh");
    if (!isfinite(a0) || !isfinite(a1))
        return fr_fail(s, FRICREG_ENONFINITE, "set_rayleigh: a0 = %g or a1 = %g is not finite", a0,
                       a1);
    if (a0 < 0.0 || a1 < 0.0)
        return fr_fail(s, FRICREG_EINVAL, "set_rayleigh: a0 = %g and a1 = %g must be >= 0", a0, a1);
    s->rayleigh = 1;
    s->a0 = a0;
    s->a1 = a1;
    fr_structure_changed(s, FR_CHANGED_MODEL);
    return FRICREG_OK;
}

/* The context's own message: it names the function (set_bounds, set_law), which is the
 * structure's too. */
static int ctx_failed(fricreg_structure *s, int status)
{
    return fr_fail(s, status, "%s", fricreg_ctx_errmsg(s->ctx));
}

int fricreg_structure_set_bounds(fricreg_structure *s, size_t m, const double mun[])
{
    if (s == NULL || s->running)
        return fr_structure_refuse(s, "set_bounds");
    int status = fricreg_ctx_set_bounds(s->ctx, m, mun);
    if (status != FRICREG_OK)
        return ctx_failed(s, status);
    memcpy(s->mun, mun, m * sizeof *mun);
    fr_structure_changed(s, FR_CHANGED_BOUNDS);
    return FRICREG_OK;
}

int fricreg_structure_set_law(fricreg_structure *s, int law, double eps)
{
    if (s == NULL || s->running)
        return fr_structure_refuse(s, "set_law");
    int status = fricreg_ctx_set_law(s->ctx, law, eps);
    if (status != FRICREG_OK)
        return ctx_failed(s, status);
    fr_structure_changed(s, FR_CHANGED_LAW);
    return FRICREG_OK;
}

/* Checks a vector argument of length ndof. */
static int check_vector(fricreg_structure *s, const char *name, size_t ndof, const double x[])
{
    size_t k;
    if (x == NULL)
        return fr_fail(s, FRICREG_ENULL, "%s: the vector is NULL", name);
    if (ndof != s->n)
        return fr_fail(s, FRICREG_ESIZE, "%s: ndof = %zu, the structure has %zu", name, ndof, s->n);
    if (!all_finite(x, ndof, &k))
        return fr_fail(s, FRICREG_ENONFINITE, "%s: entry %zu is not finite", name, k);
    return FRICREG_OK;
}

int fricreg_structure_set_influence(fricreg_structure *s, size_t ndof, const double r[])
{
    if (s == NULL || s->running)
        return fr_structure_refuse(s, "set_influence");
    int status = check_vector(s, "set_influence", ndof, r);
    if (status != FRICREG_OK)
        return status;
    memcpy(s->r->data, r, ndof * sizeof *r);
    fr_structure_changed(s, FR_CHANGED_MODEL);
    return FRICREG_OK;
}

/* Validates and copies a record; rec is untouched on failure. */
static int set_record(fricreg_structure *s, const char *name, struct fr_record *rec, double t0,
                      double dt, size_t n, const double x[])
{
    if (n == 0) {
        free(rec->x);
        *rec = (struct fr_record){0};
        return FRICREG_OK;
    }
    if (x == NULL)
        return fr_fail(s, FRICREG_ENULL, "%s: the samples are NULL", name);
    if (n == 1)
        return fr_fail(s, FRICREG_EINVAL, "%s: a record needs n >= 2 samples (0 removes it)", name);
    size_t k;
    if (!isfinite(t0) || !isfinite(dt))
        return fr_fail(s, FRICREG_ENONFINITE, "%s: t0 = %g or dt_rec = %g is not finite", name, t0,
                       dt);
    if (!(dt > 0.0))
        return fr_fail(s, FRICREG_EINVAL, "%s: dt_rec = %g must be > 0", name, dt);
    if (!all_finite(x, n, &k))
        return fr_fail(s, FRICREG_ENONFINITE, "%s: sample %zu is not finite", name, k);
    double *copy = malloc(n * sizeof *copy);
    if (copy == NULL)
        return fr_fail(s, FRICREG_ENOMEM, "%s: no memory for %zu samples", name, n);
    memcpy(copy, x, n * sizeof *x);
    free(rec->x);
    *rec = (struct fr_record){.t0 = t0, .dt = dt, .n = n, .x = copy};
    return FRICREG_OK;
}

int fricreg_structure_set_ground_accel(fricreg_structure *s, double t0, double dt_rec, size_t n,
                                       const double ag[])
{
    if (s == NULL || s->running)
        return fr_structure_refuse(s, "set_ground_accel");
    /* The step's start keeps the load it began with (a holds the equation there): the
     * record is read at step ends only, so a caller may feed it step by step. */
    int status = set_record(s, "set_ground_accel", &s->ground, t0, dt_rec, n, ag);
    if (status == FRICREG_OK)
        fr_structure_changed(s, FR_CHANGED_GROUND);
    return status;
}

int fricreg_structure_set_load(fricreg_structure *s, size_t ndof, const double p[], double t0,
                               double dt_rec, size_t n, const double g[])
{
    if (s == NULL || s->running)
        return fr_structure_refuse(s, "set_load");
    int status = check_vector(s, "set_load", ndof, p);
    if (status != FRICREG_OK)
        return status;
    status = set_record(s, "set_load", &s->load, t0, dt_rec, n, g);
    if (status != FRICREG_OK)
        return status;
    memcpy(s->p->data, p, ndof * sizeof *p);
    fr_structure_changed(s, FR_CHANGED_LOAD);
    return FRICREG_OK; /* read at step ends only, as the ground motion */
}

int fricreg_structure_set_initial(fricreg_structure *s, size_t ndof, const double u0[],
                                  const double v0[])
{
    if (s == NULL || s->running)
        return fr_structure_refuse(s, "set_initial");
    int status = check_vector(s, "set_initial", ndof, u0);
    if (status == FRICREG_OK)
        status = check_vector(s, "set_initial", ndof, v0);
    if (status != FRICREG_OK)
        return status;
    memcpy(s->u->data, u0, ndof * sizeof *u0);
    memcpy(s->v->data, v0, ndof * sizeof *v0);
    gsl_vector_set_zero(s->a);
    gsl_vector_set_zero(s->f);
    fr_elements_reset(s);
    s->t = 0.0;
    s->clock_k = 0;
    s->ready = 0;
    s->fresh = 1;
    fr_energy_reset(s);
    memset(s->stats, 0, sizeof s->stats);
    fr_warn_track_reset(s);
    fr_warnings_forget_delivered(&s->warnings); /* a new run: its warnings are news */
    for (size_t i = 0; i < ndof; i++)
        s->peak[i] = fabs(u0[i]);
    fr_structure_changed(s, FR_CHANGED_INITIAL); /* a new companion at its first step */
    return FRICREG_OK;
}

int fricreg_structure_set_newmark(fricreg_structure *s, double beta, double gamma)
{
    if (s == NULL || s->running)
        return fr_structure_refuse(s, "set_newmark");
    if (!isfinite(beta) || !isfinite(gamma))
        return fr_fail(s, FRICREG_ENONFINITE,
                       "set_newmark: beta = %g or gamma = %g is not "
                       "finite",
                       beta, gamma);
    if (!(beta > 0.0 && beta <= 0.5 && gamma >= 0.5 && gamma <= 1.0))
        return fr_fail(s, FRICREG_EINVAL,
                       "set_newmark: beta = %g must be in (0, 1/2] and "
                       "gamma = %g in [1/2, 1]",
                       beta, gamma);
    s->scheme = FR_SCHEME_NEWMARK;
    s->alpha = 0.0;
    s->beta = beta;
    s->gamma = gamma;
    fr_structure_changed(s, FR_CHANGED_SCHEME);
    return FRICREG_OK;
}

int fricreg_structure_set_hht(fricreg_structure *s, double alpha)
{
    if (s == NULL || s->running)
        return fr_structure_refuse(s, "set_hht");
    if (!isfinite(alpha))
        return fr_fail(s, FRICREG_ENONFINITE, "set_hht: alpha is not finite");
    if (!(alpha >= -1.0 / 3.0 && alpha <= 0.0))
        return fr_fail(s, FRICREG_EINVAL, "set_hht: alpha = %g must be in [-1/3, 0]", alpha);
    s->scheme = FR_SCHEME_NEWMARK;
    s->alpha = alpha;
    s->beta = (1.0 - alpha) * (1.0 - alpha) / 4.0;
    s->gamma = 0.5 - alpha;
    fr_structure_changed(s, FR_CHANGED_SCHEME);
    return FRICREG_OK;
}

int fricreg_structure_set_central_difference(fricreg_structure *s)
{
    if (s == NULL || s->running)
        return fr_structure_refuse(s, "set_central_difference");
    s->scheme = FR_SCHEME_CENTRAL;
    fr_structure_changed(s, FR_CHANGED_SCHEME);
    return FRICREG_OK;
}

int fricreg_structure_set_newton(fricreg_structure *s, double tol, int max_iter)
{
    if (s == NULL || s->running)
        return fr_structure_refuse(s, "set_newton");
    if (!isfinite(tol))
        return fr_fail(s, FRICREG_ENONFINITE, "set_newton: tol is not finite");
    if (!(tol > 0.0 && tol < 1.0) || max_iter < 1 || max_iter > 1000)
        return fr_fail(s, FRICREG_EINVAL,
                       "set_newton: tol = %g must be in (0, 1) and "
                       "max_iter = %d in [1, 1000]",
                       tol, max_iter);
    s->newton_tol = tol;
    s->newton_max = max_iter;
    fr_structure_changed(s, FR_CHANGED_NEWTON);
    return FRICREG_OK;
}

int fricreg_structure_set_contact_solver(fricreg_structure *s, int solver)
{
    if (s == NULL || s->running)
        return fr_structure_refuse(s, "set_contact_solver");
    if (solver != FRICREG_CONTACT_SOLVER_AUTO && solver != FRICREG_CONTACT_SOLVER_DENSE &&
        solver != FRICREG_CONTACT_SOLVER_SPARSE)
        return fr_fail(s, FRICREG_EINVAL,
                       "set_contact_solver: solver = %d is none of FRICREG_CONTACT_SOLVER_AUTO, "
                       "_DENSE, _SPARSE",
                       solver);
    s->contact_solver = solver;
    fr_structure_changed(s, FR_CHANGED_SCHEME); /* the step's factors anew, the path's */
    return FRICREG_OK;
}

int fricreg_structure_get_contact_solver(const fricreg_structure *s, int *solver)
{
    if (s == NULL || solver == NULL)
        return FRICREG_ENULL;
    /* AUTO is the dense path until the crossover is measured (fricreg_structure.h) */
    *solver = s->contact_solver == FRICREG_CONTACT_SOLVER_SPARSE ? FRICREG_CONTACT_SOLVER_SPARSE
                                                                 : FRICREG_CONTACT_SOLVER_DENSE;
    return FRICREG_OK;
}

/* ---- Excitation ---------------------------------------------------------------------------- */

double fr_record_at(const struct fr_record *rec, double t)
{
    if (rec->n == 0)
        return 0.0;
    /* Step times carry rounding: one within 1e-9 of a sample interval of either end is on it. */
    double pos = (t - rec->t0) / rec->dt, last = (double)(rec->n - 1);
    if (!(pos >= -1e-9) || pos > last + 1e-9)
        return 0.0;
    pos = fmin(fmax(pos, 0.0), last);
    size_t k = (size_t)pos;
    if (k >= rec->n - 1)
        return rec->x[rec->n - 1];
    double w = pos - (double)k;
    return (1.0 - w) * rec->x[k] + w * rec->x[k + 1];
}

/* The record's peak |a_g| and its peak velocity |integral of a_g| (trapezoidal from 0). */
void fr_record_peaks(const struct fr_record *rec, double *pga, double *pgv)
{
    double v = 0.0;
    *pga = rec->n > 0 ? fabs(rec->x[0]) : 0.0;
    *pgv = 0.0;
    for (size_t k = 1; k < rec->n; k++) {
        v += 0.5 * (rec->x[k - 1] + rec->x[k]) * rec->dt;
        *pga = fmax(*pga, fabs(rec->x[k]));
        *pgv = fmax(*pgv, fabs(v));
    }
}

void fr_structure_effective_load(const fricreg_structure *s, double t, gsl_vector *ptil)
{
    double g = s->load.n == 0 ? 1.0 : fr_record_at(&s->load, t);
    double ag = fr_record_at(&s->ground, t);
    const double *p = s->p->data, *mr = s->Mr->data;
    for (size_t k = 0; k < s->n; k++)
        ptil->data[k] = g * p[k] - ag * mr[k];
}

/* ---- Getters and errors -------------------------------------------------------------------- */

int fricreg_structure_get_state(const fricreg_structure *s, size_t ndof, double u[], double v[],
                                double a[])
{
    if (s == NULL || (u == NULL && v == NULL && a == NULL))
        return FRICREG_ENULL;
    if (ndof != s->n)
        return FRICREG_ESIZE;
    if (u)
        memcpy(u, s->u->data, ndof * sizeof *u);
    if (v)
        memcpy(v, s->v->data, ndof * sizeof *v);
    if (a)
        memcpy(a, s->a->data, ndof * sizeof *a);
    return FRICREG_OK;
}

int fricreg_structure_get_forces(const fricreg_structure *s, size_t m, double f[])
{
    if (s == NULL || f == NULL)
        return FRICREG_ENULL;
    if (m != s->m)
        return FRICREG_ESIZE;
    memcpy(f, s->f->data, m * sizeof *f);
    return FRICREG_OK;
}

int fricreg_structure_get_dissipation(const fricreg_structure *s, size_t m, double D[])
{
    if (s == NULL || D == NULL)
        return FRICREG_ENULL;
    if (m != s->m)
        return FRICREG_ESIZE;
    memcpy(D, s->energy.per_contact, m * sizeof *D);
    return FRICREG_OK;
}

FR_ERROR_GETTERS(fricreg_structure, "NULL structure")
