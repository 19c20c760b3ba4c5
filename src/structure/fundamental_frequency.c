/* SPDX-License-Identifier: GPL-3.0-or-later */
/* fundamental_frequency.c — the structure's lowest natural frequency omega_1, every element
 * sticking, for the warnings' check of dt against the fundamental period (warnings.c): inverse
 * iteration on CHOLMOD's Cholesky factor of K_stick, O(nnz(L)) per iteration at any size. The
 * step guard's dense eigen-solve (guard.c) cost O(n^3) after every run instead: 9 s of CPU at
 * 2 025 dof, for a warning. */
#include <math.h>

#include "base/sparse_factor.h"
#include "base/sparse_ops.h"
#include "structure_internal.h"

/* Inverse iteration's Rayleigh quotient converges as (lambda_1/lambda_2)^(2k): these stop it
 * once it moves by less than RQ_RTOL (the warning prints 4 digits), or after ITERATIONS_MAX
 * steps (two modes a few per cent apart), where the quotient, an upper bound of lambda_1, is
 * at worst within those per cent: ample for a warning at a tenth of the period. */
#define ITERATIONS_MAX 60
#define RQ_RTOL 1e-7

/* One step of inverse iteration, z = K^-1 M x normalised in M's norm (x <- z); its Rayleigh
 * quotient x^T M x / z^T M z = (z^T M x)/(z^T M z) (z^T K z = z^T M x). 0 if the solve failed. */
static double iterate(fricreg_structure *s, cholmod_factor *L, cholmod_dense *B, cholmod_dense **X,
                      cholmod_dense **Y, cholmod_dense **E)
{
    size_t n = s->n;
    double *x = s->work->data, *Mx = B->x, *Mz = s->yb->data;
    fr_sym_mult(s->M, 1.0, x, 0.0, Mx);
    if (!cholmod_l_solve2(CHOLMOD_A, L, B, NULL, X, NULL, Y, E, &s->cc))
        return 0.0;
    const double *z = (*X)->x;
    fr_sym_mult(s->M, 1.0, z, 0.0, Mz);
    double zMx = 0.0, zMz = 0.0;
    for (size_t k = 0; k < n; k++) {
        zMx += z[k] * Mx[k];
        zMz += z[k] * Mz[k];
    }
    if (!(zMz > 0.0 && zMx > 0.0))
        return 0.0;
    double scale = 1.0 / sqrt(zMz);
    for (size_t k = 0; k < n; k++)
        x[k] = z[k] * scale;
    return zMx / zMz;
}

/* lambda_1 of K x = lambda M x for K positive definite with factor L; 0 if not found. The start,
 * every DOF displaced alike, is not orthogonal to a ground-supported structure's first mode. */
static double smallest_eigenvalue(fricreg_structure *s, cholmod_factor *L)
{
    cholmod_dense *B = cholmod_l_allocate_dense(s->n, 1, s->n, CHOLMOD_REAL, &s->cc);
    cholmod_dense *X = NULL, *Y = NULL, *E = NULL;
    double lambda = 0.0;
    if (B != NULL) {
        gsl_vector_set_all(s->work, 1.0);
        double previous = 0.0;
        for (int k = 0; k < ITERATIONS_MAX; k++) {
            lambda = iterate(s, L, B, &X, &Y, &E);
            if (!(lambda > 0.0) || fabs(lambda - previous) <= RQ_RTOL * lambda)
                break;
            previous = lambda;
        }
    }
    cholmod_l_free_dense(&B, &s->cc);
    cholmod_l_free_dense(&X, &s->cc);
    cholmod_l_free_dense(&Y, &s->cc);
    cholmod_l_free_dense(&E, &s->cc);
    return isfinite(lambda) && lambda > 0.0 && s->cc.status == CHOLMOD_OK ? lambda : 0.0;
}

double fr_structure_fundamental_omega(fricreg_structure *s)
{
    if (s->fundamental_valid)
        return s->omega_min;
    s->omega_min = 0.0;
    cholmod_sparse *K = s->el.me > 0 ? fr_structure_stick_stiffness(s) : s->K;
    if (K == NULL)
        return 0.0;
    fr_cholmod_ordering(&s->cc, CHOLMOD_AMD, 0);
    cholmod_factor *L = cholmod_l_analyze(K, &s->cc);
    /* Not positive definite (a rigid-body mode, K = 0): not known until the model changes; no
     * memory: not known now, tried again at the next call. */
    if (L != NULL && cholmod_l_factorize(K, L, &s->cc)) {
        if (s->cc.status == CHOLMOD_OK)
            s->omega_min = sqrt(smallest_eigenvalue(s, L));
        s->fundamental_valid = s->cc.status == CHOLMOD_NOT_POSDEF || s->omega_min > 0.0;
    }
    cholmod_l_free_factor(&L, &s->cc);
    if (K != s->K)
        cholmod_l_free_sparse(&K, &s->cc);
    return s->omega_min;
}
