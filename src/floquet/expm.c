/* SPDX-License-Identifier: GPL-3.0-or-later */
/* expm.c — the matrix exponential by scaling and squaring with the [13/13] Padé approximant
 * (N. J. Higham, "The scaling and squaring method for the matrix exponential revisited", SIAM
 * J. Matrix Anal. Appl. 26(4), 2005, Alg. 2.3 at its largest degree; MATLAB's expm to R2015):
 * A is scaled by 2^-s, s = max(0, ⌈log2(‖A‖₁/θ₁₃)⌉), θ₁₃ = 5.37, where the approximant
 * r₁₃ = (V − U)⁻¹ (V + U) is exact to the unit roundoff in backward error, and the result
 * squared s times. Six products and one solve, then the s squarings: BLAS dgemm and LAPACK
 * dgesv, in the caller's workspace.
 *
 * Why not a library's: LAPACK has no matrix exponential, and GSL's gsl_linalg_exponential_ss (a
 * Taylor series) allocates its scratch through GSL, whose failure reaches the process-wide
 * error handler (docs/reliability.md). */
#include <math.h>
#include <string.h>

#include "base/lapack.h"
#include "expm.h"

/* θ₁₃ and the coefficients b₀ .. b₁₃ of the [13/13] Padé approximant (Higham 2005, Table 2.3
 * and eq. 2.4). */
static const double THETA13 = 5.371920351148152;
static const double PADE[14] = {64764752532480000.0,
                                32382376266240000.0,
                                7771770303897600.0,
                                1187353796428800.0,
                                129060195264000.0,
                                10559470521600.0,
                                670442572800.0,
                                33522128640.0,
                                1323241920.0,
                                40840800.0,
                                960960.0,
                                16380.0,
                                182.0,
                                1.0};

void fr_hb_product(size_t p, const double *X, const double *Y, double *Z)
{
    const double one = 1.0, zero = 0.0;
    int order = (int)p;
    dgemm_("N", "N", &order, &order, &order, &one, X, &order, Y, &order, &zero, Z, &order, 1, 1);
}

static void product(int p, const double *X, const double *Y, double *Z)
{
    fr_hb_product((size_t)p, X, Y, Z);
}

/* out = c6 A6 + c4 A4 + c2 A2 + c0 I. */
static void even_sum(size_t p, const double *A6, const double *A4, const double *A2,
                     const double c[4], double *out)
{
    for (size_t i = 0; i < p * p; i++)
        out[i] = c[3] * A6[i] + c[2] * A4[i] + c[1] * A2[i];
    for (size_t i = 0; i < p; i++)
        out[i * p + i] += c[0];
}

size_t fr_hb_expm_work(size_t p)
{
    return 6 * p * p;
}

int fr_hb_expm(const double *A, size_t p, double *E, double *work, int *piv)
{
    size_t pp = p * p;
    int n = (int)p, info = 0;
    double norm = 0.0; /* ‖A‖₁, the largest column sum (of A^T's rows alike: the bound holds) */
    for (size_t j = 0; j < p; j++) {
        double sum = 0.0;
        for (size_t i = 0; i < p; i++)
            sum += fabs(A[j * p + i]);
        if (!(sum < INFINITY))
            return -1;
        norm = fmax(norm, sum);
    }
    int s = norm > THETA13 ? (int)ceil(log2(norm / THETA13)) : 0;
    double *A1 = work, *A2 = A1 + pp, *A4 = A2 + pp, *A6 = A4 + pp, *U = A6 + pp, *V = U + pp;
    for (size_t i = 0; i < pp; i++)
        A1[i] = ldexp(A[i], -s);
    product(n, A1, A1, A2);
    product(n, A2, A2, A4);
    product(n, A2, A4, A6);
    /* V = A6 (b12 A6 + b10 A4 + b8 A2) + b6 A6 + b4 A4 + b2 A2 + b0 I; U = A1 (A6 (b13 A6 + b11 A4
     * + b9 A2) + b7 A6 + b5 A4 + b3 A2 + b1 I) (Higham 2005, eq. 2.4) */
    const double v_high[4] = {0.0, PADE[8], PADE[10], PADE[12]},
                 v_low[4] = {PADE[0], PADE[2], PADE[4], PADE[6]},
                 u_high[4] = {0.0, PADE[9], PADE[11], PADE[13]},
                 u_low[4] = {PADE[1], PADE[3], PADE[5], PADE[7]};
    even_sum(p, A6, A4, A2, v_high, E);
    product(n, A6, E, V);
    even_sum(p, A6, A4, A2, v_low, E);
    for (size_t i = 0; i < pp; i++)
        V[i] += E[i];
    even_sum(p, A6, A4, A2, u_high, E);
    product(n, A6, E, U);
    even_sum(p, A6, A4, A2, u_low, E);
    for (size_t i = 0; i < pp; i++)
        E[i] += U[i];
    product(n, A1, E, U);
    for (size_t i = 0; i < pp; i++) { /* (V − U) X = V + U: X into E */
        A2[i] = V[i] - U[i];
        E[i] = V[i] + U[i];
    }
    dgesv_(&n, &n, A2, &n, piv, E, &n, &info);
    if (info != 0)
        return info;
    for (int k = 0; k < s; k++) {
        product(n, E, E, A1);
        memcpy(E, A1, pp * sizeof *E);
    }
    return 0;
}
