/* SPDX-License-Identifier: GPL-3.0-or-later */
/* guard.c — what the step guard (src/ode/step_guard.c, the drivers' one guard) reads of a
 * structure: its highest natural frequency, its largest viscous damping rate and the stick
 * zone's stiffness, each cached until what it depends on changes; and whether the structure
 * is stable (K and C positive semidefinite), which GSL's LU-based implicit steppers need. */
#include <math.h>

#include <gsl/gsl_blas.h>
#include <gsl/gsl_eigen.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_machine.h>

#include "base/eigen.h"
#include "ctx/ctx_driver.h"
#include "law/law.h"
#include "ode/step_guard.h"
#include "structure_internal.h"

/* The eigenvalues of L^-1 X L^-T (M = L L^T), X = K or C, in s->A's storage: the omega^2 of
 * M^-1 K, or the decay rates of M^-1 C. Their largest into *max (0 if none is positive); 1 if
 * none is below -STABLE_RTOL times the largest magnitude (X positive semidefinite to
 * rounding: a rigid-body mode of K gives an eigenvalue of order 1e-16 of either sign). Where
 * L^-1 X L^-T overflows (K near DBL_MAX, or a mass far below K's scale), *max is +Inf (no
 * fixed explicit step is stable) and stability is not known: 0. By fr_eigen_symm, whose
 * scaling kept GSL's iteration from looping on such a matrix (fuzz finding). */
#define STABLE_RTOL 1e-10
static int generalized_eigenvalues(fricreg_structure *s, const gsl_matrix *X, double *max)
{
    gsl_matrix_memcpy(s->A, X);
    gsl_blas_dtrsm(CblasLeft, CblasLower, CblasNoTrans, CblasNonUnit, 1.0, s->L, s->A);
    gsl_blas_dtrsm(CblasRight, CblasLower, CblasTrans, CblasNonUnit, 1.0, s->L, s->A);
    if (fr_eigen_symm(s->A, s->eigenvalues, s->eigen_work) != GSL_SUCCESS) {
        *max = INFINITY;
        return 0;
    }
    double lo = gsl_vector_min(s->eigenvalues), hi = gsl_vector_max(s->eigenvalues);
    *max = fmax(hi, 0.0);
    return !(lo < -STABLE_RTOL * fmax(fabs(lo), fabs(hi)));
}

/* omega_max, the damping rate and stability, at the first use after fr_structure_prepare. */
static void model_rates(fricreg_structure *s)
{
    if (s->omega_valid)
        return;
    double omega2 = 0.0;
    int stiff_psd = generalized_eigenvalues(s, s->K, &omega2);
    int damp_psd = generalized_eigenvalues(s, s->C, &s->damping_max);
    s->omega_max = sqrt(omega2);
    s->stable = stiff_psd && damp_psd;
    s->omega_valid = 1;
}

int fr_structure_stable(fricreg_structure *s)
{
    model_rates(s);
    return s->stable;
}

double fr_structure_omega_max(fricreg_structure *s)
{
    model_rates(s);
    return s->omega_max;
}

double fr_structure_newton_rate(fricreg_structure *s)
{
    model_rates(s);
    double slope = 0.0;
    for (size_t i = 0; i < s->m; i++)
        slope = fmax(slope, gsl_matrix_get(s->W, i, i) * 2.0 * s->mun[i]);
    double eps = fmax(fr_ctx_eps(s->ctx), GSL_SQRT_DBL_EPSILON);
    return s->omega_max + s->damping_max + (double)s->m * slope / eps;
}

int fr_structure_guard(fricreg_structure *s, const struct fr_integrator *integ, double dt,
                       const char *who)
{
    if (s->unguarded)
        return FRICREG_OK;
    model_rates(s);
    int jumps = fr_law_jumps(fr_ctx_law(s->ctx));
    if (!s->stick_valid) { /* lambda * eps, the chord's for a law that jumps */
        if (fr_stiffness_times_eps(s->ctx, jumps, &s->stick_rate) != FRICREG_OK)
            return fr_fail(s, FRICREG_ENOMEM, "%s: %s", who, fricreg_ctx_errmsg(s->ctx));
        s->stick_valid = 1;
    }
    struct fr_guard_run run = {.integ = integ,
                               .dt = dt,
                               .eps = fr_ctx_eps(s->ctx),
                               .rate = s->stick_rate,
                               .omega = s->omega_max,
                               .damping = s->damping_max,
                               .jumps = jumps};
    return fr_step_guard(&run, &s->err, who);
}
