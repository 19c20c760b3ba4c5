/* SPDX-License-Identifier: GPL-3.0-or-later */
/* structure.c — fricreg_structure: life cycle, model setters, getters, and the set-up that
 * turns the model into a fricreg context (M's Cholesky factor, G = J M^-1, W = J M^-1 J^T).
 * The integrator is newmark.c, the energy balance energy.c. */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_blas.h>
#include <gsl/gsl_machine.h>
#include <gsl/gsl_linalg.h>

#include "base/eigen.h"
#include "base/gsl_mem.h"
#include "law/law.h"
#include "structure_internal.h"

#define MAX_SIZE ((size_t)1 << 15)

#define SYMMETRY_RTOL 1e-12

/* ---- Life cycle --------------------------------------------------------------------------- */

void fricreg_structure_free(fricreg_structure *s)
{
    if (s == NULL)
        return;
    void *blocks[] = {s->M,    s->K,      s->C,     s->J,    s->L,          s->G,           s->W,
                      s->S,    s->GS,     s->A,     s->Fz,   s->Fa,         s->T1,          s->r,
                      s->p,    s->Mr,     s->u,     s->v,    s->a,          s->ptil,        s->f,
                      s->x,    s->dx,     s->xt,    s->u1,   s->v1,         s->guess,       s->R,
                      s->Rt,   s->ptil1,  s->hist,  s->up,   s->vp,         s->work,        s->f1,
                      s->zdot, s->afree,  s->mwork, s->perm, s->eigen_work, s->eigenvalues, s->tau,
                      s->norm, s->a_held, s->f_held};
    for (size_t k = 0; k < sizeof blocks / sizeof *blocks; k++)
        free(blocks[k]); /* gsl_mem.h: one block each */
    fricreg_ctx_free(s->ctx);
    free(s->mun);
    free(s->stopped);
    free(s->stick_perm);
    free(s->ground.x);
    free(s->load.x);
    free(s->energy.per_contact);
    free(s);
}

/* Every GSL object on fricreg's own memory (gsl_mem.h): none of GSL's allocators, which report
 * a failed malloc to GSL's error handler. */
static int allocate(fricreg_structure *s)
{
    size_t n = s->n, m = s->m;
    gsl_matrix **nn[] = {&s->M, &s->K, &s->C, &s->L, &s->S, &s->A};
    for (size_t k = 0; k < sizeof nn / sizeof *nn; k++)
        if ((*nn[k] = fr_gsl_matrix_new(n, n)) == NULL)
            return 0;
    gsl_matrix **mn[] = {&s->J, &s->G, &s->GS, &s->T1};
    for (size_t k = 0; k < sizeof mn / sizeof *mn; k++)
        if ((*mn[k] = fr_gsl_matrix_new(m, n)) == NULL)
            return 0;
    gsl_matrix **mm[] = {&s->W, &s->Fz, &s->Fa};
    for (size_t k = 0; k < sizeof mm / sizeof *mm; k++)
        if ((*mm[k] = fr_gsl_matrix_new(m, m)) == NULL)
            return 0;
    gsl_vector **nv[] = {&s->r,     &s->p,    &s->Mr,  &s->u,     &s->v,     &s->a,
                         &s->ptil,  &s->x,    &s->dx,  &s->xt,    &s->u1,    &s->v1,
                         &s->guess, &s->R,    &s->Rt,  &s->ptil1, &s->hist,  &s->up,
                         &s->vp,    &s->work, &s->tau, &s->norm,  &s->a_held};
    for (size_t k = 0; k < sizeof nv / sizeof *nv; k++)
        if ((*nv[k] = fr_gsl_vector_new(n)) == NULL)
            return 0;
    gsl_vector **mv[] = {&s->f, &s->f1, &s->zdot, &s->afree, &s->mwork, &s->f_held};
    for (size_t k = 0; k < sizeof mv / sizeof *mv; k++)
        if ((*mv[k] = fr_gsl_vector_new(m)) == NULL)
            return 0;
    s->perm = fr_gsl_permutation_new(n);
    s->eigen_work = fr_gsl_eigen_symm_new(n);
    s->eigenvalues = fr_gsl_vector_new(n);
    s->mun = malloc(m * sizeof *s->mun);
    s->stopped = calloc(m, sizeof *s->stopped);
    s->stick_perm = malloc(m * sizeof *s->stick_perm);
    s->energy.per_contact = calloc(m, sizeof *s->energy.per_contact);
    return s->perm && s->eigen_work && s->eigenvalues && s->mun && s->stopped && s->stick_perm &&
           s->energy.per_contact && fricreg_ctx_create(m, &s->ctx) == FRICREG_OK;
}

int fricreg_structure_create(size_t ndof, size_t m, fricreg_structure **out)
{
    if (out == NULL)
        return FRICREG_ENULL;
    if (ndof == 0 || m == 0 || ndof > MAX_SIZE || m > MAX_SIZE)
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
    gsl_matrix_set_identity(s->M);
    for (size_t i = 0; i < m; i++)
        s->mun[i] = 1.0;
    s->alpha = 0.0;
    s->beta = 0.25;
    s->gamma = 0.5;
    s->newton_tol = 1e-10;
    s->newton_max = 50;
    s->max_steps = -1; /* the law's default (fr_law_max_adaptive_steps) */
    s->fresh = 1;
    *out = s;
    return FRICREG_OK;
}

int fr_structure_busy(fricreg_structure *s, const char *who)
{
    return fr_fail(s, FRICREG_EINVAL, "%s: not allowed during a run (called from the observer)",
                   who);
}

int fricreg_structure_set_observer(fricreg_structure *s, fricreg_structure_observer fn, void *user)
{
    if (s == NULL)
        return FRICREG_ENULL;
    if (s->running)
        return fr_structure_busy(s, "set_observer");
    s->observer = fn;
    s->observer_user = user;
    return FRICREG_OK;
}

int fricreg_structure_set_max_steps(fricreg_structure *s, int64_t max_steps)
{
    if (s == NULL)
        return FRICREG_ENULL;
    if (s->running)
        return fr_structure_busy(s, "set_max_steps");
    if (max_steps < 0)
        return fr_fail(s, FRICREG_EINVAL,
                       "set_max_steps: max_steps = %lld must be >= 0 (0: no bound)",
                       (long long)max_steps);
    s->max_steps = max_steps;
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

/* The first (i, j) with |A_ij - A_ji| > SYMMETRY_RTOL sqrt(r_i r_j), r_i = max_k |A_ik| the
 * scale of row i (into scale[n], scratch), or 0 if A is symmetric. Against the rows' own
 * scales, not max|A|: a model mixing stiff and soft (or translational and rotational)
 * degrees of freedom has entries 1e12 apart, and max|A| let the soft block be asymmetric in
 * its first digit. sqrt(r_i r_j) is the scale of entry (i, j) under a diagonal change of
 * units D A D, as the context's sqrt(W_ii W_jj) is, and stays positive where a diagonal
 * entry is 0 (K with a rigid-body mode). */
static int asymmetric(const double A[], size_t n, double scale[], size_t *bi, size_t *bj)
{
    for (size_t i = 0; i < n; i++) {
        double r = 0.0;
        for (size_t k = 0; k < n; k++)
            r = fmax(r, fabs(A[i * n + k]));
        scale[i] = sqrt(r); /* sqrt(r_i) sqrt(r_j): no overflow of r_i r_j */
    }
    for (size_t i = 0; i < n; i++)
        for (size_t j = i + 1; j < n; j++)
            if (fabs(A[i * n + j] - A[j * n + i]) > SYMMETRY_RTOL * scale[i] * scale[j]) {
                *bi = i;
                *bj = j;
                return 1;
            }
    return 0;
}

/* Common checks of an n x n model matrix; name is "set_mass" etc. */
static int check_square(fricreg_structure *s, const char *name, size_t ndof, const double A[])
{
    size_t i, j;
    if (A == NULL)
        return fr_fail(s, FRICREG_ENULL, "%s: the matrix is NULL", name);
    if (ndof != s->n)
        return fr_fail(s, FRICREG_ESIZE, "%s: ndof = %zu, the structure has %zu", name, ndof, s->n);
    if (!all_finite(A, ndof * ndof, &i))
        return fr_fail(s, FRICREG_ENONFINITE, "%s: entry (%zu, %zu) is not finite", name, i / ndof,
                       i % ndof);
    if (asymmetric(A, ndof, s->work->data, &i, &j)) /* work: scratch between steps */
        return fr_fail(s, FRICREG_ENOTSYM,
                       "%s: entries (%zu, %zu) = %g and (%zu, %zu) = %g "
                       "differ: the matrix is not symmetric",
                       name, i, j, A[i * ndof + j], j, i, A[j * ndof + i]);
    return FRICREG_OK;
}

static void copy_matrix(gsl_matrix *dst, const double src[])
{
    gsl_matrix_const_view view = gsl_matrix_const_view_array(src, dst->size1, dst->size2);
    gsl_matrix_memcpy(dst, &view.matrix);
}

/* Every model change: W, G and the equilibrium acceleration are recomputed at the next step. */
static void model_changed(fricreg_structure *s)
{
    s->prepared = 0;
    s->ready = 0;
}

/* ---- Model setters ------------------------------------------------------------------------ */

/* Whether the symmetric M (row-major n x n) is positive definite with room for GSL's Cholesky
 * to succeed in floating point: a positive diagonal D and lambda_min(D^-1/2 M D^-1/2) above
 * 2 n (n + 1) eps (Demmel's sufficient condition, Higham, Accuracy and Stability of Numerical
 * Algorithms, 2nd ed., Thm. 10.14). Checked first because a failing gsl_linalg_cholesky_decomp1
 * reports to GSL's process-wide error handler, whose default aborts. Uses L and the eigenvalue
 * workspace as scratch; *lambda_min gets the scaled smallest eigenvalue (NaN: a diagonal
 * entry is not positive). */
static int cholesky_safe(fricreg_structure *s, const double M[], double *lambda_min)
{
    size_t n = s->n;
    *lambda_min = NAN;
    for (size_t i = 0; i < n; i++)
        if (!(M[i * n + i] > 0.0))
            return 0;
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++)
            gsl_matrix_set(s->L, i, j, M[i * n + j] / sqrt(M[i * n + i]) / sqrt(M[j * n + j]));
    /* fr_eigen_symm: a scaled entry beyond the doubles (M_ij = 1e300 beside M_ii = 1e-300)
     * would make GSL's iteration loop; it gives NaN, not positive definite */
    fr_eigen_symm(s->L, s->eigenvalues, s->eigen_work);
    *lambda_min = gsl_vector_min(s->eigenvalues);
    return *lambda_min > 2.0 * (double)n * (double)(n + 1) * GSL_DBL_EPSILON;
}

int fricreg_structure_set_mass(fricreg_structure *s, size_t ndof, const double M[])
{
    if (s == NULL)
        return FRICREG_ENULL;
    if (s->running)
        return fr_structure_busy(s, "set_mass");
    int status = check_square(s, "set_mass", ndof, M);
    if (status != FRICREG_OK)
        return status;
    /* Positive definite: GSL's Cholesky then succeeds (on a copy: M is kept as given). */
    double lambda_min;
    int safe = cholesky_safe(s, M, &lambda_min);
    s->prepared = 0; /* L held the kept M's factor: the next step refactors it */
    if (!safe)
        return fr_fail(s, FRICREG_ENOTPSD,
                       "set_mass: the mass matrix is not positive definite, or too close to "
                       "singular for a Cholesky factor (smallest eigenvalue %.3g of D^-1/2 M "
                       "D^-1/2, D its diagonal; needs > %.3g)",
                       lambda_min, 2.0 * (double)ndof * (double)(ndof + 1) * GSL_DBL_EPSILON);
    copy_matrix(s->L, M);
    gsl_linalg_cholesky_decomp1(s->L); /* cannot fail: cholesky_safe */
    copy_matrix(s->M, M);
    model_changed(s);
    return FRICREG_OK;
}

int fricreg_structure_set_stiffness(fricreg_structure *s, size_t ndof, const double K[])
{
    if (s == NULL)
        return FRICREG_ENULL;
    if (s->running)
        return fr_structure_busy(s, "set_stiffness");
    int status = check_square(s, "set_stiffness", ndof, K);
    if (status != FRICREG_OK)
        return status;
    copy_matrix(s->K, K);
    model_changed(s);
    return FRICREG_OK;
}

int fricreg_structure_set_damping(fricreg_structure *s, size_t ndof, const double C[])
{
    if (s == NULL)
        return FRICREG_ENULL;
    if (s->running)
        return fr_structure_busy(s, "set_damping");
    int status = check_square(s, "set_damping", ndof, C);
    if (status != FRICREG_OK)
        return status;
    copy_matrix(s->C, C);
    s->rayleigh = 0;
    model_changed(s);
    return FRICREG_OK;
}

int fricreg_structure_set_rayleigh(fricreg_structure *s, double a0, double a1)
{
    if (s == NULL)
        return FRICREG_ENULL;
    if (s->running)
        return fr_structure_busy(s, "set_rayleigh");
    if (!isfinite(a0) || !isfinite(a1))
        return fr_fail(s, FRICREG_ENONFINITE, "set_rayleigh: a0 = %g or a1 = %g is not finite", a0,
                       a1);
    if (a0 < 0.0 || a1 < 0.0)
        return fr_fail(s, FRICREG_EINVAL, "set_rayleigh: a0 = %g and a1 = %g must be >= 0", a0, a1);
    s->rayleigh = 1;
    s->a0 = a0;
    s->a1 = a1;
    model_changed(s);
    return FRICREG_OK;
}

int fricreg_structure_set_contacts(fricreg_structure *s, size_t m, size_t ndof, const double J[])
{
    if (s == NULL)
        return FRICREG_ENULL;
    if (s->running)
        return fr_structure_busy(s, "set_contacts");
    if (J == NULL)
        return fr_fail(s, FRICREG_ENULL, "set_contacts: J is NULL");
    if (m != s->m || ndof != s->n)
        return fr_fail(s, FRICREG_ESIZE,
                       "set_contacts: J is %zu x %zu, the structure needs "
                       "%zu x %zu",
                       m, ndof, s->m, s->n);
    size_t k;
    if (!all_finite(J, m * ndof, &k))
        return fr_fail(s, FRICREG_ENONFINITE, "set_contacts: entry (%zu, %zu) is not finite",
                       k / ndof, k % ndof);
    for (size_t i = 0; i < m; i++) {
        int moves = 0;
        for (size_t j = 0; j < ndof; j++)
            moves |= J[i * ndof + j] != 0.0;
        if (!moves)
            return fr_fail(s, FRICREG_EINVAL,
                           "set_contacts: row %zu of J is zero: contact %zu "
                           "does not move",
                           i, i);
    }
    copy_matrix(s->J, J);
    s->contacts_set = 1;
    model_changed(s);
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
    if (s == NULL)
        return FRICREG_ENULL;
    if (s->running)
        return fr_structure_busy(s, "set_bounds");
    int status = fricreg_ctx_set_bounds(s->ctx, m, mun);
    if (status != FRICREG_OK)
        return ctx_failed(s, status);
    memcpy(s->mun, mun, m * sizeof *mun);
    s->ready = 0; /* W is unchanged: only the equilibrium at t is recomputed */
    return FRICREG_OK;
}

int fricreg_structure_set_law(fricreg_structure *s, int law, double eps)
{
    if (s == NULL)
        return FRICREG_ENULL;
    if (s->running)
        return fr_structure_busy(s, "set_law");
    int status = fricreg_ctx_set_law(s->ctx, law, eps);
    if (status != FRICREG_OK)
        return ctx_failed(s, status);
    s->ready = 0;
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
    if (s == NULL)
        return FRICREG_ENULL;
    if (s->running)
        return fr_structure_busy(s, "set_influence");
    int status = check_vector(s, "set_influence", ndof, r);
    if (status != FRICREG_OK)
        return status;
    memcpy(s->r->data, r, ndof * sizeof *r);
    model_changed(s);
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
    if (s == NULL)
        return FRICREG_ENULL;
    if (s->running)
        return fr_structure_busy(s, "set_ground_accel");
    /* The step's start keeps the load it began with (a holds the equation there): the
     * record is read at step ends only, so a caller may feed it step by step. */
    return set_record(s, "set_ground_accel", &s->ground, t0, dt_rec, n, ag);
}

int fricreg_structure_set_load(fricreg_structure *s, size_t ndof, const double p[], double t0,
                               double dt_rec, size_t n, const double g[])
{
    if (s == NULL)
        return FRICREG_ENULL;
    if (s->running)
        return fr_structure_busy(s, "set_load");
    int status = check_vector(s, "set_load", ndof, p);
    if (status != FRICREG_OK)
        return status;
    status = set_record(s, "set_load", &s->load, t0, dt_rec, n, g);
    if (status != FRICREG_OK)
        return status;
    memcpy(s->p->data, p, ndof * sizeof *p);
    return FRICREG_OK; /* read at step ends only, as the ground motion */
}

int fricreg_structure_set_initial(fricreg_structure *s, size_t ndof, const double u0[],
                                  const double v0[])
{
    if (s == NULL)
        return FRICREG_ENULL;
    if (s->running)
        return fr_structure_busy(s, "set_initial");
    int status = check_vector(s, "set_initial", ndof, u0);
    if (status == FRICREG_OK)
        status = check_vector(s, "set_initial", ndof, v0);
    if (status != FRICREG_OK)
        return status;
    memcpy(s->u->data, u0, ndof * sizeof *u0);
    memcpy(s->v->data, v0, ndof * sizeof *v0);
    gsl_vector_set_zero(s->a);
    gsl_vector_set_zero(s->f);
    s->t = 0.0;
    s->ready = 0;
    s->fresh = 1;
    fr_energy_reset(s);
    memset(s->stats, 0, sizeof s->stats);
    return FRICREG_OK;
}

int fricreg_structure_set_newmark(fricreg_structure *s, double beta, double gamma)
{
    if (s == NULL)
        return FRICREG_ENULL;
    if (s->running)
        return fr_structure_busy(s, "set_newmark");
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
    s->S_dt = 0.0;
    return FRICREG_OK;
}

int fricreg_structure_set_hht(fricreg_structure *s, double alpha)
{
    if (s == NULL)
        return FRICREG_ENULL;
    if (s->running)
        return fr_structure_busy(s, "set_hht");
    if (!isfinite(alpha))
        return fr_fail(s, FRICREG_ENONFINITE, "set_hht: alpha is not finite");
    if (!(alpha >= -1.0 / 3.0 && alpha <= 0.0))
        return fr_fail(s, FRICREG_EINVAL, "set_hht: alpha = %g must be in [-1/3, 0]", alpha);
    s->scheme = FR_SCHEME_NEWMARK;
    s->alpha = alpha;
    s->beta = (1.0 - alpha) * (1.0 - alpha) / 4.0;
    s->gamma = 0.5 - alpha;
    s->S_dt = 0.0;
    return FRICREG_OK;
}

int fricreg_structure_set_central_difference(fricreg_structure *s)
{
    if (s == NULL)
        return FRICREG_ENULL;
    if (s->running)
        return fr_structure_busy(s, "set_central_difference");
    s->scheme = FR_SCHEME_CENTRAL;
    return FRICREG_OK;
}

int fricreg_structure_set_newton(fricreg_structure *s, double tol, int max_iter)
{
    if (s == NULL)
        return FRICREG_ENULL;
    if (s->running)
        return fr_structure_busy(s, "set_newton");
    if (!isfinite(tol))
        return fr_fail(s, FRICREG_ENONFINITE, "set_newton: tol is not finite");
    if (!(tol > 0.0 && tol < 1.0) || max_iter < 1 || max_iter > 1000)
        return fr_fail(s, FRICREG_EINVAL,
                       "set_newton: tol = %g must be in (0, 1) and "
                       "max_iter = %d in [1, 1000]",
                       tol, max_iter);
    s->newton_tol = tol;
    s->newton_max = max_iter;
    return FRICREG_OK;
}

/* ---- Set-up: M's factor, G = J M^-1, W = J M^-1 J^T, C, M r ------------------------------- */

/* W is diagonal when every off-diagonal entry is exactly zero (contacts on separate DOFs). */
static int diagonal(const gsl_matrix *W)
{
    for (size_t i = 0; i < W->size1; i++)
        for (size_t j = 0; j < W->size2; j++)
            if (i != j && gsl_matrix_get(W, i, j) != 0.0)
                return 0;
    return 1;
}

/* G and W, and W into the context: diagonal or dense. Uses s->mwork as scratch. */
static int couple(fricreg_structure *s)
{
    gsl_matrix *W = s->W;
    /* G = J M^-1: solve M G^T = J^T column by column with the Cholesky factor. */
    for (size_t i = 0; i < s->m; i++) {
        gsl_vector_const_view jrow = gsl_matrix_const_row(s->J, i);
        gsl_vector_view grow = gsl_matrix_row(s->G, i);
        gsl_linalg_cholesky_solve(s->L, &jrow.vector, &grow.vector);
    }
    /* W = G J^T, symmetrized: the two triangles differ only by rounding. */
    gsl_blas_dgemm(CblasNoTrans, CblasTrans, 1.0, s->G, s->J, 0.0, W);
    for (size_t i = 0; i < s->m; i++)
        for (size_t j = 0; j < i; j++) {
            double w = 0.5 * (gsl_matrix_get(W, i, j) + gsl_matrix_get(W, j, i));
            gsl_matrix_set(W, i, j, w);
            gsl_matrix_set(W, j, i, w);
        }
    /* J and M of scales too far apart: W beyond the double range (M = 1e-310 beside J = 1), or
     * a W_ii below the normal doubles (J = 1e-200 beside M = 1), which the context refuses
     * with the code of its own argument (ENONFINITE, EINVAL or ENOTPSD); one code here, named
     * after the contact. */
    for (size_t i = 0; i < s->m; i++) {
        double wii = gsl_matrix_get(W, i, i);
        int finite = 1;
        for (size_t j = 0; j < s->m; j++)
            finite = finite && isfinite(gsl_matrix_get(W, i, j));
        if (!finite || !(wii >= DBL_MIN))
            return fr_fail(s, FRICREG_EINVAL,
                           "W = J M^-1 J^T: contact %zu's W_ii = %g is %s: J and M are of scales "
                           "too far apart",
                           i, wii, finite ? "below DBL_MIN" : "beyond the double range");
    }
    int status;
    if (diagonal(W)) {
        for (size_t i = 0; i < s->m; i++)
            gsl_vector_set(s->mwork, i, gsl_matrix_get(W, i, i));
        status = fricreg_ctx_set_coupling_diagonal(s->ctx, s->m, s->mwork->data);
    } else {
        status = fricreg_ctx_set_coupling_dense(s->ctx, s->m, W->data);
    }
    if (status != FRICREG_OK)
        return fr_fail(s, status, "W = J M^-1 J^T: %s", fricreg_ctx_errmsg(s->ctx));
    return FRICREG_OK;
}

int fr_structure_prepare(fricreg_structure *s)
{
    if (s->prepared)
        return FRICREG_OK;
    if (!s->contacts_set)
        return fr_fail(s, FRICREG_EINVAL,
                       "step: the contact matrix J was never set "
                       "(fricreg_structure_set_contacts)");
    gsl_matrix_memcpy(s->L, s->M);
    gsl_linalg_cholesky_decomp1(s->L); /* checked positive definite by set_mass */
    if (s->rayleigh) {
        gsl_matrix_memcpy(s->C, s->M);
        gsl_matrix_scale(s->C, s->a0);
        gsl_matrix_memcpy(s->A, s->K);
        gsl_matrix_scale(s->A, s->a1);
        gsl_matrix_add(s->C, s->A);
    }
    gsl_blas_dgemv(CblasNoTrans, 1.0, s->M, s->r, 0.0, s->Mr);
    int status = couple(s);
    if (status != FRICREG_OK)
        return status;
    s->S_dt = 0.0;
    s->omega_valid = 0;
    s->prepared = 1;
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

void fr_structure_effective_load(const fricreg_structure *s, double t, gsl_vector *ptil)
{
    double g = s->load.n == 0 ? 1.0 : fr_record_at(&s->load, t);
    double ag = fr_record_at(&s->ground, t);
    for (size_t k = 0; k < s->n; k++)
        gsl_vector_set(ptil, k, g * gsl_vector_get(s->p, k) - ag * gsl_vector_get(s->Mr, k));
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

int fricreg_structure_get_value(const fricreg_structure *s, int which, double *value)
{
    if (s == NULL || value == NULL)
        return FRICREG_ENULL;
    double kinetic = fr_energy_kinetic(s), strain = fr_energy_strain(s);
    const struct fr_energy *e = &s->energy;
    switch (which) {
    case FRICREG_SVALUE_TIME: *value = s->t; break;
    case FRICREG_SVALUE_INPUT: *value = e->input; break;
    case FRICREG_SVALUE_KINETIC: *value = kinetic; break;
    case FRICREG_SVALUE_STRAIN: *value = strain; break;
    case FRICREG_SVALUE_VISCOUS: *value = e->viscous; break;
    case FRICREG_SVALUE_FRICTION: *value = e->friction; break;
    case FRICREG_SVALUE_RESIDUAL:
        *value = e->initial + e->input - kinetic - strain - e->viscous - e->friction;
        break;
    case FRICREG_SVALUE_INITIAL: *value = e->initial; break;
    default: return FRICREG_EINVAL;
    }
    return FRICREG_OK;
}

int fricreg_structure_get_stat(const fricreg_structure *s, int which, int64_t *value)
{
    if (s == NULL || value == NULL)
        return FRICREG_ENULL;
    if (which < 0 || which >= FR_NSSTATS)
        return FRICREG_EINVAL;
    *value = s->stats[which];
    return FRICREG_OK;
}

int fricreg_structure_errcode(const fricreg_structure *s)
{
    return s ? s->err.code : FRICREG_OK;
}

const char *fricreg_structure_errmsg(const fricreg_structure *s)
{
    return s ? s->err.msg : "NULL structure";
}

size_t fricreg_structure_errmsg_copy(const fricreg_structure *s, char *buf, size_t len)
{
    return fr_error_copy(fricreg_structure_errmsg(s), buf, len);
}
