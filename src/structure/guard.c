/* SPDX-License-Identifier: GPL-3.0-or-later */
/* guard.c — what the step guard (src/ode/step_guard.c, the drivers' one guard) reads of a
 * structure: its highest natural frequency, its largest viscous damping rate and the stick
 * zone's stiffness, each cached until what it depends on changes; and whether the structure
 * is stable (K and C positive semidefinite), which GSL's LU-based implicit steppers need. */
#include <math.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_machine.h>

#include "base/eigen.h"
#include "base/sparse_ops.h"
#include "ctx/ctx_driver.h"
#include "law/law.h"
#include "ode/step_guard.h"
#include "structure_internal.h"

#define STABLE_RTOL 1e-10
/* Up to this order the rates are M^-1 K's and M^-1 C's eigenvalues (dense, O(n^3), once per
 * model); beyond, Gershgorin bounds (O(nnz)). */
#define DENSE_RATES_MAX 2048

/* ---- Exact: the eigenvalues of L^-1 P X P^T L^-T (P M P^T = L L^T), X = K or C ----------- */

/* L^-1 P X P^T L^-T into e->a (row-major, symmetric): the forward half of M's factor applied to
 * X's columns, then to the rows of the result. s->yb, s->work: scratch. */
static void congruence(fricreg_structure *s, const cholmod_sparse *X, struct fr_eigen *e)
{
    size_t n = s->n;
    double *col = s->work->data, *y = s->yb->data;
    for (size_t j = 0; j < n; j++) { /* row j of e->a = (L^-1 P X e_j)^T */
        for (size_t k = 0; k < n; k++)
            col[k] = k == j ? 1.0 : 0.0;
        fr_sym_mult(X, 1.0, col, 0.0, y);
        fr_cfactor_forward(&s->mass, y, e->a + j * n, &s->cc);
    }
    for (size_t j = 0; j < n; j++) { /* its columns, by the same half */
        for (size_t k = 0; k < n; k++)
            col[k] = e->a[k * n + j];
        fr_cfactor_forward(&s->mass, col, y, &s->cc);
        for (size_t k = 0; k < n; k++)
            e->a[k * n + j] = y[k];
    }
}

/* The largest eigenvalue of M^-1 X into *max (0 if none is positive); 1 if none is below
 * -STABLE_RTOL times the largest magnitude (X positive semidefinite to rounding: a rigid-body
 * mode of K gives an eigenvalue of order 1e-16 of either sign). Where the matrix overflows
 * (K near DBL_MAX, or a mass far below K's scale), *max is +Inf (no fixed explicit step is
 * stable) and stability is not known: 0. By fr_eigen_solve, whose scaling keeps GSL's
 * iteration from looping on such a matrix (fuzz finding). -1: no memory. */
static int exact_rate(fricreg_structure *s, const cholmod_sparse *X, double *max)
{
    struct fr_eigen e;
    if (fr_eigen_alloc(&e, s->n) != 0)
        return -1;
    congruence(s, X, &e);
    int psd = 0;
    *max = INFINITY;
    if (fr_eigen_solve(&e) == GSL_SUCCESS) {
        double lo = e.eval[0], hi = e.eval[0];
        for (size_t k = 1; k < s->n; k++) {
            lo = fmin(lo, e.eval[k]);
            hi = fmax(hi, e.eval[k]);
        }
        *max = fmax(hi, 0.0);
        psd = !(lo < -STABLE_RTOL * fmax(fabs(lo), fabs(hi)));
    }
    fr_eigen_free(&e);
    return psd;
}

/* ---- Bounds: Gershgorin's discs of D^-1/2 X D^-1/2, D = diag(M) ---------------------------- */

/* The discs of X scaled by M's diagonal: the largest right end into *hi, the smallest left
 * end into *lo. */
static void scaled_discs(const fricreg_structure *s, const cholmod_sparse *X, double *lo,
                         double *hi)
{
    const SuiteSparse_long *Mp = s->M->p, *Mi = s->M->i, *Xp = X->p, *Xi = X->i;
    const double *Mx = s->M->x, *Xx = X->x;
    double *d = s->work->data, *center = s->yb->data, *radius = s->dx->data;
    for (size_t k = 0; k < s->n; k++)
        d[k] = center[k] = radius[k] = 0.0;
    for (size_t j = 0; j < s->n; j++)
        for (SuiteSparse_long p = Mp[j]; p < Mp[j + 1]; p++)
            if ((size_t)Mi[p] == j)
                d[j] = 1.0 / sqrt(Mx[p]);
    for (size_t j = 0; j < s->n; j++)
        for (SuiteSparse_long p = Xp[j]; p < Xp[j + 1]; p++) {
            size_t i = (size_t)Xi[p];
            double x = Xx[p] * d[i] * d[j];
            if (i == j) {
                center[j] += x;
            } else {
                radius[i] += fabs(x);
                radius[j] += fabs(x);
            }
        }
    *lo = INFINITY;
    *hi = -INFINITY;
    for (size_t k = 0; k < s->n; k++) {
        *lo = fmin(*lo, center[k] - radius[k]);
        *hi = fmax(*hi, center[k] + radius[k]);
    }
}

/* An upper bound of M^-1 X's largest eigenvalue: lambda_max(X~) / lambda_min(M~) with the
 * scaled matrices' discs (+Inf when M~'s discs reach 0: no bound), and 1 if X~'s discs show
 * it positive semidefinite (0: not shown). */
static int bound_rate(fricreg_structure *s, const cholmod_sparse *X, double *max)
{
    double mlo, mhi, xlo, xhi;
    scaled_discs(s, s->M, &mlo, &mhi);
    scaled_discs(s, X, &xlo, &xhi);
    *max = mlo > 0.0 ? fmax(xhi, 0.0) / mlo : INFINITY;
    return xlo >= 0.0;
}

cholmod_sparse *fr_structure_stick_stiffness(fricreg_structure *s)
{
    cholmod_sparse *B = cholmod_l_copy_sparse(s->el.Jt, &s->cc);
    if (B == NULL)
        return NULL;
    const SuiteSparse_long *Bp = B->p;
    double *Bx = B->x;
    for (size_t i = 0; i < s->el.nc; i++)
        for (SuiteSparse_long p = Bp[i]; p < Bp[i + 1]; p++)
            Bx[p] *= sqrt(s->el.kstick[i]);
    cholmod_sparse *BBt = cholmod_l_aat(B, NULL, 0, 1, &s->cc);
    cholmod_l_free_sparse(&B, &s->cc);
    cholmod_sparse *upper = BBt == NULL ? NULL : cholmod_l_copy(BBt, 1, 1, &s->cc);
    cholmod_l_free_sparse(&BBt, &s->cc);
    double one[2] = {1.0, 0.0};
    cholmod_sparse *Ks = upper == NULL ? NULL : cholmod_l_add(s->K, upper, one, one, 1, 1, &s->cc);
    cholmod_l_free_sparse(&upper, &s->cc);
    return Ks;
}

int fr_structure_rates(fricreg_structure *s, const char *who)
{
    if (s->omega_valid)
        return FRICREG_OK;
    double omega2 = 0.0;
    int stiff_psd, damp_psd;
    cholmod_sparse *K = s->el.me > 0 ? fr_structure_stick_stiffness(s) : s->K;
    if (K == NULL)
        return fr_fail(s, FRICREG_ENOMEM, "%s: no memory for the sticking elements' stiffness",
                       who);
    if (s->n <= DENSE_RATES_MAX) {
        stiff_psd = exact_rate(s, K, &omega2);
        damp_psd = exact_rate(s, s->Cd, &s->damping_max);
    } else {
        stiff_psd = bound_rate(s, K, &omega2);
        damp_psd = bound_rate(s, s->Cd, &s->damping_max);
    }
    if (K != s->K)
        cholmod_l_free_sparse(&K, &s->cc);
    if (stiff_psd < 0 || damp_psd < 0)
        return fr_fail(s, FRICREG_ENOMEM, "%s: no memory for the model's eigenvalues", who);
    s->omega_max = sqrt(omega2);
    s->stable = stiff_psd && damp_psd;
    s->omega_valid = 1;
    return FRICREG_OK;
}

void fr_structure_rates_stale(fricreg_structure *s)
{
    s->omega_valid = 0;
    s->fundamental_valid = 0;
}

int fr_structure_stable(const fricreg_structure *s)
{
    return s->stable;
}

double fr_structure_newton_rate(const fricreg_structure *s)
{
    double slope = 0.0;
    const SuiteSparse_long *Wp = s->mass.D->p, *Wi = s->mass.D->i;
    const double *Wx = s->mass.D->x;
    for (size_t j = 0; j < s->m; j++)
        for (SuiteSparse_long p = Wp[j]; p < Wp[j + 1]; p++)
            if ((size_t)Wi[p] == j)
                slope = fmax(slope, Wx[p] * 2.0 * s->mun[j]);
    double eps = fmax(fr_ctx_eps(s->ctx), GSL_SQRT_DBL_EPSILON);
    return s->omega_max + s->damping_max + (double)s->m * slope / eps;
}

int fr_structure_guard(fricreg_structure *s, const struct fr_integrator *integ, double dt,
                       const char *who)
{
    if (s->unguarded)
        return FRICREG_OK;
    int status = fr_structure_rates(s, who);
    if (status != FRICREG_OK)
        return status;
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
