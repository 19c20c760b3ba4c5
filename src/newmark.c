/* newmark.c — Newmark and HHT-alpha steps of a fricreg_structure, the friction implicit:
 * Newton on the exact tangent (fricreg_ctx_tangent) with a backtracking line search.
 *
 * Unknown: the acceleration x at the step's end, with u1 = u_pred + beta dt^2 x and
 * v1 = v_pred + gamma dt x. Residual (Hilber, Hughes & Taylor 1977; alpha = 0 is Newmark):
 *   R(x) = M x + (1 + alpha)(C v1 + K u1 - p~1 - J^T f1) - alpha (C v + K u - p~ - J^T f),
 * f1 = f(J v1, G (p~1 - C v1 - K u1)), G = J M^-1. Its Jacobian, chained through zdot and
 * a_free: dR/dx = M + (1 + alpha)(S - J^T (gamma dt F_z J - F_a G S)), S = gamma dt C +
 * beta dt^2 K. */
#include <math.h>
#include <string.h>

#include <gsl/gsl_blas.h>
#include <gsl/gsl_linalg.h>

#include "gsl_guard.h"
#include "structure_internal.h"

#define STATE_LIMIT 1e100     /* |state| beyond this: diverged */
#define ARMIJO 1e-4           /* sufficient decrease of the residual's 2-norm */
#define MAX_CUTS 30           /* halvings of one Newton direction */
#define MAX_RUN_STEPS 2147483648.0

/* a_free = G w and zdot = J v, then f from the context: the friction at a state whose
 * net non-friction force is w = p~ - C v - K u. */
static int friction(fricreg_structure *s, const gsl_vector *w, const gsl_vector *v, gsl_vector *f)
{
    gsl_blas_dgemv(CblasNoTrans, 1.0, s->G, w, 0.0, s->afree);
    gsl_blas_dgemv(CblasNoTrans, 1.0, s->J, v, 0.0, s->zdot);
    return fricreg_ctx_eval(s->ctx, s->m, s->zdot->data, s->afree->data, f->data, NULL);
}

/* w = p~ - C v - K u */
static void net_force(const fricreg_structure *s, const gsl_vector *ptil, const gsl_vector *u,
                      const gsl_vector *v, gsl_vector *w)
{
    gsl_vector_memcpy(w, ptil);
    gsl_blas_dgemv(CblasNoTrans, -1.0, s->C, v, 1.0, w);
    gsl_blas_dgemv(CblasNoTrans, -1.0, s->K, u, 1.0, w);
}

int fr_structure_equilibrium(fricreg_structure *s)
{
    fr_structure_effective_load(s, s->t, s->ptil);
    net_force(s, s->ptil, s->u, s->v, s->work);
    int status = friction(s, s->work, s->v, s->f);
    if (status != FRICREG_OK)
        return fr_sfail(s, status, "step: friction at t = %g: %s", s->t,
                        fricreg_ctx_errmsg(s->ctx));
    /* M a = w + J^T f */
    gsl_blas_dgemv(CblasTrans, 1.0, s->J, s->f, 1.0, s->work);
    gsl_linalg_cholesky_solve(s->L, s->work, s->a);
    s->ready = 1;
    return FRICREG_OK;
}

/* u1, v1 from the unknown x; then f1 and the residual R. */
static int residual(fricreg_structure *s, double dt, const gsl_vector *x, gsl_vector *R)
{
    gsl_vector_memcpy(s->u1, s->up);
    gsl_blas_daxpy(s->beta * dt * dt, x, s->u1);
    gsl_vector_memcpy(s->v1, s->vp);
    gsl_blas_daxpy(s->gamma * dt, x, s->v1);
    net_force(s, s->ptil1, s->u1, s->v1, s->work);
    int status = friction(s, s->work, s->v1, s->f1);
    if (status != FRICREG_OK)
        return status;
    gsl_blas_dgemv(CblasTrans, 1.0, s->J, s->f1, 1.0, s->work); /* w1 + J^T f1 */
    gsl_vector_memcpy(R, s->hist);
    gsl_vector_scale(R, -s->alpha);
    gsl_blas_daxpy(-(1.0 + s->alpha), s->work, R);
    gsl_blas_dgemv(CblasNoTrans, 1.0, s->M, x, 1.0, R);
    return FRICREG_OK;
}

static double norm_inf(const gsl_vector *x)
{
    double m = 0.0;
    for (size_t k = 0; k < x->size; k++) {
        double a = fabs(gsl_vector_get(x, k));
        if (!(a <= m)) /* NaN propagates */
            m = a;
    }
    return m;
}

/* S = gamma dt C + beta dt^2 K and G S, kept while dt and the model hold. */
static void form_S(fricreg_structure *s, double dt)
{
    if (s->S_dt == dt)
        return;
    gsl_matrix_memcpy(s->S, s->C);
    gsl_matrix_scale(s->S, s->gamma * dt);
    gsl_matrix_memcpy(s->A, s->K);
    gsl_matrix_scale(s->A, s->beta * dt * dt);
    gsl_matrix_add(s->S, s->A);
    gsl_blas_dgemm(CblasNoTrans, CblasNoTrans, 1.0, s->G, s->S, 0.0, s->GS);
    s->S_dt = dt;
}

/* The Newton direction dx = -(dR/dx)^-1 R at the last evaluated point, by GSL's LU. */
static int newton_direction(fricreg_structure *s, double dt)
{
    int status = fricreg_ctx_tangent(s->ctx, s->m, s->Fz->data, s->Fa->data);
    if (status != FRICREG_OK)
        return status;
    double w = 1.0 + s->alpha;
    gsl_blas_dgemm(CblasNoTrans, CblasNoTrans, s->gamma * dt, s->Fz, s->J, 0.0, s->T1);
    gsl_blas_dgemm(CblasNoTrans, CblasNoTrans, -1.0, s->Fa, s->GS, 1.0, s->T1);
    gsl_matrix_memcpy(s->A, s->S);
    gsl_blas_dgemm(CblasTrans, CblasNoTrans, -w, s->J, s->T1, w, s->A);
    gsl_matrix_add(s->A, s->M);
    int signum;
    if (gsl_linalg_LU_decomp(s->A, s->perm, &signum) != GSL_SUCCESS)
        return FRICREG_ESINGULAR;
    for (size_t k = 0; k < s->n; k++)
        if (gsl_matrix_get(s->A, k, k) == 0.0)
            return FRICREG_ESINGULAR;
    if (gsl_linalg_LU_solve(s->A, s->perm, s->R, s->dx) != GSL_SUCCESS)
        return FRICREG_ESINGULAR;
    gsl_vector_scale(s->dx, -1.0);
    return FRICREG_OK;
}

/* The step's force scale: the largest entry of |M a| and |C v + K u - p~ - J^T f| at its
 * start (hist), |p~1| at its end, and |J|^T mun. */
static double force_scale(fricreg_structure *s)
{
    gsl_blas_dgemv(CblasNoTrans, 1.0, s->M, s->a, 0.0, s->work);
    double scale = fmax(norm_inf(s->work), norm_inf(s->ptil1));
    scale = fmax(scale, norm_inf(s->hist));
    for (size_t k = 0; k < s->n; k++) {
        double sum = 0.0;
        for (size_t i = 0; i < s->m; i++)
            sum += fabs(gsl_matrix_get(s->J, i, k)) * s->mun[i];
        scale = fmax(scale, sum);
    }
    return scale > 0.0 ? scale : 1e-300;
}

/* Backtracking on ||R||_2 along dx from x; on success x, R and the context's last
 * evaluation are at the accepted point. Returns 0 if no cut decreased the residual. */
static int line_search(fricreg_structure *s, double dt, double *phi)
{
    double lambda = 1.0;
    for (int cut = 0; cut <= MAX_CUTS; cut++) {
        gsl_vector_memcpy(s->xt, s->x);
        gsl_blas_daxpy(lambda, s->dx, s->xt);
        if (residual(s, dt, s->xt, s->Rt) == FRICREG_OK) {
            double phi_t = gsl_blas_dnrm2(s->Rt);
            if (phi_t <= (1.0 - ARMIJO * lambda) * *phi) {
                gsl_vector_memcpy(s->x, s->xt);
                gsl_vector_memcpy(s->R, s->Rt);
                *phi = phi_t;
                return 1;
            }
        }
        s->stats[FRICREG_SSTAT_LINE_SEARCH_CUTS]++;
        lambda *= 0.5;
    }
    return 0;
}

/* Newton from x = a: returns a status, and *converged and *iters. On return the context's
 * last evaluation, u1, v1 and f1 are at x. */
static int newton(fricreg_structure *s, double dt, int *converged, int *iters)
{
    gsl_vector_memcpy(s->x, s->a);
    int status = residual(s, dt, s->x, s->R);
    if (status != FRICREG_OK)
        return fr_sfail(s, status, "step: friction at t = %g: %s", s->t + dt,
                        fricreg_ctx_errmsg(s->ctx));
    double tol = s->newton_tol * force_scale(s);
    double phi = gsl_blas_dnrm2(s->R);
    *iters = 0;
    *converged = norm_inf(s->R) <= tol;
    while (!*converged && *iters < s->newton_max) {
        if (!isfinite(phi))
            break;
        if (newton_direction(s, dt) != FRICREG_OK)
            break;
        ++*iters;
        if (!line_search(s, dt, &phi)) {
            residual(s, dt, s->x, s->R); /* back to x: the step's best point */
            break;
        }
        *converged = norm_inf(s->R) <= tol;
    }
    if (!isfinite(phi))
        return fr_sfail(s, FRICREG_EDIVERGED, "step: the residual at t = %g is not finite",
                        s->t + dt);
    return FRICREG_OK;
}

static int beyond_limit(const gsl_vector *x)
{
    return !(norm_inf(x) <= STATE_LIMIT);
}

/* One step from s->t to t1 (> s->t). */
static int step_to(fricreg_structure *s, double t1)
{
    double dt = t1 - s->t;
    gsl_error_handler_t *old = fr_gsl_quiet();
    int status = fr_structure_prepare(s);
    if (status == FRICREG_OK && !s->ready)
        status = fr_structure_equilibrium(s);
    if (status != FRICREG_OK) {
        fr_gsl_restore(old);
        return status;
    }
    if (s->fresh) {
        fr_energy_start(s);
        s->fresh = 0;
    }
    form_S(s, dt);
    /* Predictors, the load at t1, and the start's force C v + K u - p~ - J^T f (HHT). */
    double b = s->beta * dt * dt, g = s->gamma * dt;
    gsl_vector_memcpy(s->up, s->u);
    gsl_blas_daxpy(dt, s->v, s->up);
    gsl_blas_daxpy(0.5 * dt * dt - b, s->a, s->up);
    gsl_vector_memcpy(s->vp, s->v);
    gsl_blas_daxpy(dt - g, s->a, s->vp);
    fr_structure_effective_load(s, t1, s->ptil1);
    net_force(s, s->ptil, s->u, s->v, s->hist);
    gsl_blas_dgemv(CblasTrans, 1.0, s->J, s->f, 1.0, s->hist);
    gsl_vector_scale(s->hist, -1.0);

    int converged = 0, iters = 0;
    status = newton(s, dt, &converged, &iters);
    fr_gsl_restore(old);
    if (status != FRICREG_OK)
        return status;
    if (beyond_limit(s->u1) || beyond_limit(s->v1) || beyond_limit(s->x))
        return fr_sfail(s, FRICREG_EDIVERGED, "step: the state at t = %g is beyond 1e100", t1);

    fr_energy_step(s, s->u1, s->v1, s->ptil1, s->f1);
    gsl_vector_memcpy(s->u, s->u1);
    gsl_vector_memcpy(s->v, s->v1);
    gsl_vector_memcpy(s->a, s->x);
    gsl_vector_memcpy(s->ptil, s->ptil1);
    gsl_vector_memcpy(s->f, s->f1);
    s->t = t1;
    s->stats[FRICREG_SSTAT_STEPS]++;
    s->stats[FRICREG_SSTAT_NEWTON_ITERATIONS] += iters;
    if (iters > s->stats[FRICREG_SSTAT_NEWTON_MAX])
        s->stats[FRICREG_SSTAT_NEWTON_MAX] = iters;
    if (!converged)
        s->stats[FRICREG_SSTAT_NEWTON_FAILURES]++;
    return FRICREG_OK;
}

static int check_dt(fricreg_structure *s, const char *name, double dt)
{
    if (!isfinite(dt))
        return fr_sfail(s, FRICREG_ENONFINITE, "%s: dt is not finite", name);
    if (!(dt > 0.0))
        return fr_sfail(s, FRICREG_EINVAL, "%s: dt = %g must be > 0", name, dt);
    return FRICREG_OK;
}

int fricreg_structure_step(fricreg_structure *s, double dt)
{
    if (s == NULL)
        return FRICREG_ENULL;
    int status = check_dt(s, "step", dt);
    if (status != FRICREG_OK)
        return status;
    double t1 = s->t + dt;
    if (!(t1 > s->t))
        return fr_sfail(s, FRICREG_EINVAL, "step: dt = %g is lost against t = %g", dt, s->t);
    return step_to(s, t1);
}

int fricreg_structure_run(fricreg_structure *s, double dt, double t_end)
{
    if (s == NULL)
        return FRICREG_ENULL;
    int status = check_dt(s, "run", dt);
    if (status != FRICREG_OK)
        return status;
    if (!isfinite(t_end))
        return fr_sfail(s, FRICREG_ENONFINITE, "run: t_end is not finite");
    double t0 = s->t;
    if (!(t_end > t0))
        return fr_sfail(s, FRICREG_EINVAL, "run: t_end = %g must be after t = %g", t_end, t0);
    /* Steps that end within 1e-12 dt of t_end land on it: no sliver of a last step. */
    double steps = ceil((t_end - t0) / dt * (1.0 - 1e-12));
    if (steps > MAX_RUN_STEPS)
        return fr_sfail(s, FRICREG_EINVAL, "run: %g steps of dt = %g exceed 2^31", steps, dt);
    int64_t nsteps = steps < 1.0 ? 1 : (int64_t)steps;
    for (int64_t k = 1; k <= nsteps; k++) {
        double t1 = k == nsteps ? t_end : t0 + (double)k * dt;
        if (!(t1 > s->t))
            return fr_sfail(s, FRICREG_EINVAL, "run: dt = %g is lost against t = %g", dt, s->t);
        status = step_to(s, t1);
        if (status != FRICREG_OK)
            return status;
    }
    return FRICREG_OK;
}
