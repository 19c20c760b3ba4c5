/* SPDX-License-Identifier: GPL-3.0-or-later */
/* stick_predictor.c — Newton's first guess for a Newmark / HHT-alpha step: the acceleration
 * a at t, corrected so that the contacts inside the friction law's band at t keep their
 * velocities over the step.
 *
 * Why: at small eps the band (law (4): |zdot - xi| < eps/2) is only eps/(gamma dt) wide in the
 * step's acceleration. A sticking contact's velocity wanders inside it, and a, extrapolated
 * over dt, puts it outside: Newton then brings the sticking contacts back one at a time (a
 * stop each, newmark.c's first_trial), about an iteration per contact. On the ten-storey
 * building (examples/building/) at eps = 1e-4 m/s and dt = 0.01 s that was 10 iterations a
 * step through its 5 s of free vibration, all ten dampers sticking.
 *
 * The guess x = a + dx keeps J_S zdot over the step for the set S of contacts with
 * |f_i| < mun_i at t, with the smallest such correction in M's norm. For law (4), and (3),
 * that set is exactly the band (outside it, and on its edge, |f| = mun), found in O(m) where
 * the law's tangent at t would cost a context evaluation. z1 = z + dt J((1 - gamma) a +
 * gamma x) = z on S gives J_S dx = -J_S a/gamma, so dx = M^-1 J_S^T y = G_S^T y with
 * W_SS y = -J_S a/gamma (GSL's Cholesky). W_SS is positive definite unless rows of J_S are
 * dependent; then the guess stays a. Cost: O(m n + |S|^3), paid only where a is not already
 * within Newton's tolerance. Newton starts from whichever of a and this guess has the smaller
 * residual: for a smooth law (tanh) every contact is "in the band", and keeping velocities is
 * not always the better guess.
 *
 * W_SS is factored by GSL's pivoted LDL^T (Golub & Van Loan, Alg. 4.2.2), which takes a
 * semidefinite matrix without a word, where gsl_linalg_cholesky_decomp1 reports one to GSL's
 * error handler, whose default aborts: two contacts with equal rows of J (two dampers on one
 * storey) under law (3) or tanh, which the context does not refuse, aborted the step. A pivot
 * below FR_PREDICTOR_PIVOT_MIN of its row's diagonal, the context's singularity test
 * (src/ctx/factor.h), means W_SS is singular: no guess. */
#include <math.h>

#include <gsl/gsl_blas.h>
#include <gsl/gsl_linalg.h>

#include "structure_internal.h"

#define FR_PREDICTOR_PIVOT_MIN 1e-12

size_t fr_stick_mark(fricreg_structure *s)
{
    size_t k = 0;
    for (size_t i = 0; i < s->m; i++) {
        s->stopped[i] = fabs(gsl_vector_get(s->f, i)) < s->mun[i];
        k += s->stopped[i];
    }
    return k;
}

int fr_stick_predictor(fricreg_structure *s, size_t k)
{
    gsl_vector_memcpy(s->guess, s->a);
    if (k == 0)
        return 0;
    /* W_SS packed into s->Fa's storage, -J_S a/gamma into s->afree's (both scratch here). */
    gsl_matrix_view Wss = gsl_matrix_view_array(s->Fa->data, k, k);
    gsl_vector_view y = gsl_vector_subvector(s->afree, 0, k);
    gsl_blas_dgemv(CblasNoTrans, 1.0, s->J, s->a, 0.0, s->mwork);
    for (size_t i = 0, p = 0; i < s->m; i++) {
        if (!s->stopped[i])
            continue;
        gsl_vector_set(&y.vector, p, -gsl_vector_get(s->mwork, i) / s->gamma);
        for (size_t j = 0, q = 0; j < s->m; j++)
            if (s->stopped[j])
                gsl_matrix_set(&Wss.matrix, p, q++, gsl_matrix_get(s->W, i, j));
        p++;
    }
    gsl_vector_view diag = gsl_vector_subvector(s->mwork, 0, k); /* W_SS's diagonal */
    for (size_t p = 0; p < k; p++)
        gsl_vector_set(&diag.vector, p, gsl_matrix_get(&Wss.matrix, p, p));
    gsl_permutation perm = {k, s->stick_perm};
    if (gsl_linalg_pcholesky_decomp(&Wss.matrix, &perm) != GSL_SUCCESS)
        return 0;
    for (size_t p = 0; p < k; p++)
        if (!(gsl_matrix_get(&Wss.matrix, p, p) >
              FR_PREDICTOR_PIVOT_MIN * gsl_vector_get(&diag.vector, perm.data[p])))
            return 0; /* W_SS singular: rows of J_S dependent */
    if (gsl_linalg_pcholesky_svx(&Wss.matrix, &perm, &y.vector) != GSL_SUCCESS)
        return 0;
    for (size_t i = 0, p = 0; i < s->m; i++)
        if (s->stopped[i]) {
            gsl_vector_const_view g = gsl_matrix_const_row(s->G, i);
            gsl_blas_daxpy(gsl_vector_get(&y.vector, p++), &g.vector, s->guess);
        }
    return 1;
}
