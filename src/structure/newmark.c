/* SPDX-License-Identifier: GPL-3.0-or-later */
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

#include "ctx/ctx_driver.h"
#include "structure_internal.h"

#define ARMIJO 1e-4 /* sufficient decrease of the residual's 2-norm */
#define MAX_CUTS 30 /* halvings of one Newton direction */

/* u1, v1 from the unknown x; then f1 and the residual R. */
static int residual(fricreg_structure *s, double dt, const gsl_vector *x, gsl_vector *R)
{
    gsl_vector_memcpy(s->u1, s->up);
    gsl_blas_daxpy(s->beta * dt * dt, x, s->u1);
    gsl_vector_memcpy(s->v1, s->vp);
    gsl_blas_daxpy(s->gamma * dt, x, s->v1);
    fr_structure_net_force(s, s->ptil1, s->u1, s->v1, s->work);
    int status = fr_structure_friction(s, s->work, s->v1, s->f1);
    if (status != FRICREG_OK)
        return status;
    gsl_blas_dgemv(CblasTrans, 1.0, s->J, s->f1, 1.0, s->work); /* w1 + J^T f1 */
    gsl_vector_memcpy(R, s->hist);
    gsl_vector_scale(R, -s->alpha);
    gsl_blas_daxpy(-(1.0 + s->alpha), s->work, R);
    gsl_blas_dgemv(CblasNoTrans, 1.0, s->M, x, 1.0, R);
    return FRICREG_OK;
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

/* The Newton direction dx = -(dR/dx)^-1 R at the last evaluated point, by GSL's QR with
 * column pivoting on workspaces allocated at create: GSL 2.7's gsl_linalg_LU_decomp allocates
 * its pivot array on every call and uses it unchecked, so a failed malloc there crashed a
 * step (found by tests/alloc/test_alloc_failure.c); QRPT with a caller's norm vector
 * allocates nothing, at twice LU's flops. A zero on R's diagonal is a singular matrix. */
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
    if (gsl_linalg_QRPT_decomp(s->A, s->tau, s->perm, &signum, s->norm) != GSL_SUCCESS)
        return FRICREG_ESINGULAR;
    for (size_t k = 0; k < s->n; k++)
        if (gsl_matrix_get(s->A, k, k) == 0.0)
            return FRICREG_ESINGULAR;
    if (gsl_linalg_QRPT_solve(s->A, s->tau, s->perm, s->R, s->dx) != GSL_SUCCESS)
        return FRICREG_ESINGULAR;
    gsl_vector_scale(s->dx, -1.0);
    return FRICREG_OK;
}

/* The step's force scale: the largest entry of |M a| and |C v + K u - p~ - J^T f| at its
 * start (hist), |p~1| at its end, and |J|^T mun. */
static double force_scale(fricreg_structure *s)
{
    gsl_blas_dgemv(CblasNoTrans, 1.0, s->M, s->a, 0.0, s->work);
    double scale = fmax(fr_norm_inf(s->work), fr_norm_inf(s->ptil1));
    scale = fmax(scale, fr_norm_inf(s->hist));
    for (size_t k = 0; k < s->n; k++) {
        double sum = 0.0;
        for (size_t i = 0; i < s->m; i++)
            sum += fabs(gsl_matrix_get(s->J, i, k)) * s->mun[i];
        scale = fmax(scale, sum);
    }
    return scale > 0.0 ? scale : 1e-300;
}

/* The first trial step along dx: the largest fraction in (0, 1] that stops a slipping
 * contact (mun_i > 0 and df_i/dzdot_i = 0 at x: outside the law's band) at zdot_i = 0 where
 * the full step would take it across the whole band (from one side of zdot = 0 to beyond eps
 * on the other), each contact once a step. A Newton step from a slip piece is the root of
 * that piece's linearization; when the contact must stop, that root lies beyond the band,
 * which is only eps/(gamma dt) wide in the acceleration, so the full step jumps across it to
 * the other slip piece, and halving finds the band only after many cuts. Stopped at zdot_i =
 * 0, the contact is where the law holds it (f = the sticking force), and the next iteration
 * works on the band's own linearization; once a step, so that a contact that must reverse is
 * stopped only once. */
static double first_trial(fricreg_structure *s, double dt)
{
    gsl_blas_dgemv(CblasNoTrans, s->gamma * dt, s->J, s->dx, 0.0, s->mwork); /* dzdot/dlambda */
    double lambda = 1.0, eps = fr_ctx_eps(s->ctx);
    size_t first = s->m;
    for (size_t i = 0; i < s->m; i++) {
        double z = gsl_vector_get(s->zdot, i), z1 = z + gsl_vector_get(s->mwork, i);
        if (!s->stopped[i] && s->mun[i] > 0.0 && gsl_matrix_get(s->Fz, i, i) == 0.0 &&
            z * z1 < 0.0 && fabs(z1) >= eps && z / (z - z1) < lambda) {
            lambda = z / (z - z1);
            first = i;
        }
    }
    if (first < s->m)
        s->stopped[first] = 1;
    return lambda;
}

/* Backtracking on ||R||_2 along dx from x, from the first trial (stop_slips) or from the full
 * step; on success x, R and the context's last evaluation are at the accepted point. Returns
 * 0 if no cut decreased the residual. */
static int line_search(fricreg_structure *s, double dt, int stop_slips, double *phi)
{
    double lambda = stop_slips ? first_trial(s, dt) : 1.0;
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

/* Newton iterations from x (its residual R evaluated, phi = ||R||_2) until the residual is
 * within tol, the step's iterations (*iters, counted on) run out, or the line search stalls.
 * At least one iteration unless R is exactly zero: a guess accepted within the tolerance
 * would leave a in error by up to tol, and a stick would creep by that times dt^2 every
 * step. On a linear piece of the law one iteration is exact. Returns ||R||_inf at x. */
static double iterate(fricreg_structure *s, double dt, double tol, int stop_slips, double *phi,
                      int *iters)
{
    int done = 0;
    double r = fr_norm_inf(s->R);
    while (r != 0.0 && (done == 0 || r > tol) && *iters < s->newton_max) {
        if (!isfinite(*phi))
            break;
        if (newton_direction(s, dt) != FRICREG_OK)
            break;
        ++*iters;
        ++done;
        if (!line_search(s, dt, stop_slips, phi)) {
            residual(s, dt, s->x, s->R); /* back to x: the best point */
            break;
        }
        r = fr_norm_inf(s->R);
    }
    return r;
}

/* x = the first guess (s->guess or s->a), its residual R and phi = ||R||_2. */
static int start_at(fricreg_structure *s, double dt, const gsl_vector *guess, double *phi)
{
    gsl_vector_memcpy(s->x, guess);
    int status = residual(s, dt, s->x, s->R);
    if (status != FRICREG_OK)
        return fr_fail(s, status, "step: friction at t = %g: %s", s->t + dt,
                       fricreg_ctx_errmsg(s->ctx));
    *phi = gsl_blas_dnrm2(s->R);
    return FRICREG_OK;
}

/* Newton from the previous acceleration a or, where a is not within tol, the stick
 * predictor's guess if its residual is smaller: returns a status, and *converged and *iters.
 * On return the context's last evaluation, u1, v1 and f1 are at x. Slipping contacts are
 * stopped at zdot = 0 (first_trial). Where a stop ends on a kink of the law (zdot = 0 is the
 * band's edge when |f_eq| >= mun) the line search can stall there: Newton then starts again
 * from a, without stops, with the iterations left. */
static int newton(fricreg_structure *s, double dt, int *converged, int *iters)
{
    double phi = 0.0;
    int status = start_at(s, dt, s->a, &phi);
    if (status != FRICREG_OK)
        return status;
    double tol = s->newton_tol * force_scale(s);
    if (fr_norm_inf(s->R) > tol && fr_stick_predictor(s, fr_stick_mark(s))) {
        double phi_a = phi;
        status = start_at(s, dt, s->guess, &phi);
        if (status == FRICREG_OK && !(phi < phi_a))
            status = start_at(s, dt, s->a, &phi);
        if (status != FRICREG_OK)
            return status;
    }
    memset(s->stopped, 0, s->m * sizeof *s->stopped);
    *iters = 0;
    double r = iterate(s, dt, tol, 1, &phi, iters);
    if (r > tol && isfinite(phi) && *iters < s->newton_max) {
        if ((status = start_at(s, dt, s->a, &phi)) != FRICREG_OK)
            return status;
        r = iterate(s, dt, tol, 0, &phi, iters);
    }
    *converged = r <= tol; /* also when the extra iteration stalls at the rounding floor */
    if (!isfinite(phi))
        return fr_fail(s, FRICREG_EDIVERGED, "step: the residual at t = %g is not finite",
                       s->t + dt);
    return FRICREG_OK;
}

int fr_newmark_solve(fricreg_structure *s, double dt, int *converged, int *iters)
{
    form_S(s, dt);
    /* Predictors, and the start's force C v + K u - p~ - J^T f (HHT's -alpha term). */
    double b = s->beta * dt * dt, g = s->gamma * dt;
    gsl_vector_memcpy(s->up, s->u);
    gsl_blas_daxpy(dt, s->v, s->up);
    gsl_blas_daxpy(0.5 * dt * dt - b, s->a, s->up);
    gsl_vector_memcpy(s->vp, s->v);
    gsl_blas_daxpy(dt - g, s->a, s->vp);
    fr_structure_net_force(s, s->ptil, s->u, s->v, s->hist);
    gsl_blas_dgemv(CblasTrans, 1.0, s->J, s->f, 1.0, s->hist);
    gsl_vector_scale(s->hist, -1.0);
    return newton(s, dt, converged, iters);
}
