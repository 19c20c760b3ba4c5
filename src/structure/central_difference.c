/* SPDX-License-Identifier: GPL-3.0-or-later */
/* central_difference.c — the explicit central-difference step of a fricreg_structure, and the
 * step bounds that keep it stable.
 *
 *   u1 = u + dt v + dt^2/2 a,   v* = v + dt a,
 *   M a1 = p~1 - C v* - K u1 + J^T f(J v*, G (p~1 - C v* - K u1)),   v1 = v + dt (a + a1)/2.
 *
 * The friction and the damping see the explicit velocity v*, so nothing is solved but M's
 * Cholesky factor. Undamped, it is the classical three-term recurrence, stable for
 * dt omega_max < 2 (at 2 a double eigenvalue -1 grows linearly). In the stick zone of law
 * (4) a contact's velocity obeys zddot = -lambda zdot, lambda the stick-zone stiffness; on
 * (v, dt a) the step is then [[1 - h/2, (1 - h)/2], [-h, -h]], h = dt lambda, whose
 * eigenvalues stay in the unit disc for 0 < h < 1 (trace 1 - 3h/2, determinant -h/2:
 * Jury's 1 + trace + det > 0 is h < 1). */
#include <math.h>

#include <gsl/gsl_blas.h>
#include <gsl/gsl_eigen.h>
#include <gsl/gsl_linalg.h>

#include "structure_internal.h"

/* omega_max^2: the largest eigenvalue of L^-1 K L^-T (M = L L^T), in s->A's storage. */
static double largest_frequency_squared(fricreg_structure *s)
{
    gsl_matrix_memcpy(s->A, s->K);
    gsl_blas_dtrsm(CblasLeft, CblasLower, CblasNoTrans, CblasNonUnit, 1.0, s->L, s->A);
    gsl_blas_dtrsm(CblasRight, CblasLower, CblasTrans, CblasNonUnit, 1.0, s->L, s->A);
    gsl_eigen_symm(s->A, s->eigenvalues, s->eigen_work);
    return gsl_vector_max(s->eigenvalues);
}

double fr_structure_omega_max(fricreg_structure *s)
{
    if (!s->omega_valid) {
        s->omega_max = sqrt(fmax(largest_frequency_squared(s), 0.0));
        s->omega_valid = 1;
    }
    return s->omega_max;
}

static int check_step(fricreg_structure *s, double dt)
{
    if (dt * fr_structure_omega_max(s) >= 2.0)
        return fr_fail(s, FRICREG_ESTEP,
                       "step: dt = %g is not below the central "
                       "difference's bound 2/omega_max = %g (omega_max = %g)",
                       dt, 2.0 / s->omega_max, s->omega_max);
    if (!s->stick_valid) {
        int status = fricreg_ctx_stick_stiffness(s->ctx, &s->stick_rate);
        if (status != FRICREG_OK)
            return fr_fail(s, status, "step: stick-zone stiffness: %s", fricreg_ctx_errmsg(s->ctx));
        s->stick_valid = 1;
    }
    if (dt * s->stick_rate >= 1.0)
        return fr_fail(s, FRICREG_ESTEP,
                       "step: dt = %g times the stick-zone stiffness %g "
                       "is not below 1 (central difference): take dt < %g or a larger eps",
                       dt, s->stick_rate, 1.0 / s->stick_rate);
    return FRICREG_OK;
}

int fr_central_solve(fricreg_structure *s, double dt)
{
    int status = check_step(s, dt);
    if (status != FRICREG_OK)
        return status;
    gsl_vector_memcpy(s->u1, s->u);
    gsl_blas_daxpy(dt, s->v, s->u1);
    gsl_blas_daxpy(0.5 * dt * dt, s->a, s->u1);
    gsl_vector_memcpy(s->vp, s->v); /* v* */
    gsl_blas_daxpy(dt, s->a, s->vp);
    fr_structure_net_force(s, s->ptil1, s->u1, s->vp, s->work);
    status = fr_structure_friction(s, s->work, s->vp, s->f1);
    if (status != FRICREG_OK)
        return fr_fail(s, status, "step: friction at t = %g: %s", s->t + dt,
                       fricreg_ctx_errmsg(s->ctx));
    gsl_blas_dgemv(CblasTrans, 1.0, s->J, s->f1, 1.0, s->work);
    gsl_linalg_cholesky_solve(s->L, s->work, s->x);
    gsl_vector_memcpy(s->v1, s->v);
    gsl_blas_daxpy(0.5 * dt, s->a, s->v1);
    gsl_blas_daxpy(0.5 * dt, s->x, s->v1);
    return FRICREG_OK;
}
