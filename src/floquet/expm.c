/* SPDX-License-Identifier: GPL-3.0-or-later */
/* expm.c — the matrix exponential by scaling and squaring with Padé approximants (N. J. Higham,
 * "The scaling and squaring method for the matrix exponential revisited", SIAM J. Matrix Anal.
 * Appl. 26(4), 2005, Alg. 2.3; MATLAB's expm to R2015): for ‖A‖₁ ≤ θ_m, m = 3, 5, 7 or 9, the
 * [m/m] approximant r_m(A) = (V − U)⁻¹ (V + U), exact to the unit roundoff in backward error;
 * beyond θ₉, A scaled by 2^-s, s = max(0, ⌈log2(‖A‖₁/θ₁₃)⌉), the [13/13] one and the result
 * squared s times. m = 3, 5, 7, 9, 13 take 2, 3, 4, 5, 6 products and one solve (BLAS dgemm,
 * LAPACK dgesv) in the caller's workspace: a short piece of the monodromy, of small norm, costs
 * a third of a long one's approximant.
 *
 * Why not a library's: LAPACK has no matrix exponential, and GSL's gsl_linalg_exponential_ss (a
 * Taylor series) allocates its scratch through GSL, whose failure reaches the process-wide
 * error handler (docs/reliability.md). */
#include <math.h>
#include <string.h>

#include "base/lapack.h"
#include "expm.h"

/* The degrees m below 13, their θ_m, and the coefficients b₀ .. b_m of their [m/m] Padé
 * approximants (Higham 2005, Table 2.3 and eq. 2.4). */
static const double THETA[4] = {1.495585217958292e-2, 2.539398330063230e-1, 9.504178996162932e-1,
                                2.097847961257068};
static const double PADE_LOW[4][10] = {{120.0, 60.0, 12.0, 1.0},
                                       {30240.0, 15120.0, 3360.0, 420.0, 30.0, 1.0},
                                       {17297280.0, 8648640.0, 1995840.0, 277200.0, 25200.0, 1512.0,
                                        56.0, 1.0},
                                       {17643225600.0, 8821612800.0, 2075673600.0, 302702400.0,
                                        30270240.0, 2162160.0, 110880.0, 3960.0, 90.0, 1.0}};

/* θ₁₃ and the coefficients b₀ .. b₁₃ of the [13/13] Padé approximant. */
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

/* E = r(A) = (V − U)⁻¹ (V + U) from V and U (A2 and E as scratch): dgesv's INFO. */
static int pade_solve(int n, double *U, double *V, double *A2, double *E, int *piv)
{
    size_t pp = (size_t)n * (size_t)n;
    int info = 0;
    for (size_t i = 0; i < pp; i++) { /* (V − U) X = V + U: X into E */
        A2[i] = V[i] - U[i];
        E[i] = V[i] + U[i];
    }
    dgesv_(&n, &n, A2, &n, piv, E, &n, &info);
    return info;
}

/* r_m(A) into E for m = 3, 5, 7, 9 (degree index d = 0 .. 3): the even powers A², .., A^(m−1),
 * V = Σ b_2k A^2k and U = A Σ b_(2k+1) A^2k (Higham 2005, eq. 2.4 and Alg. 2.3). */
static int pade_low(const double *A, size_t p, int d, double *E, double *work, int *piv)
{
    size_t pp = p * p, top = (size_t)d + 1; /* the even powers A^2 .. A^(2 top) */
    int n = (int)p;
    const double *b = PADE_LOW[d];
    double *pow = work, *U = work + 4 * pp, *V = work + 5 * pp; /* pow: A², A⁴, A⁶, A⁸ */
    product(n, A, A, pow);
    for (size_t k = 1; k < top; k++) /* A^(2k+2) = A^2k A² */
        product(n, pow + (k - 1) * pp, pow, pow + k * pp);
    for (size_t i = 0; i < pp; i++) {
        double v = 0.0, u = 0.0;
        for (size_t k = 0; k < top; k++) {
            v += b[2 * k + 2] * pow[k * pp + i];
            u += b[2 * k + 3] * pow[k * pp + i];
        }
        V[i] = v;
        E[i] = u;
    }
    for (size_t i = 0; i < p; i++) {
        V[i * p + i] += b[0];
        E[i * p + i] += b[1];
    }
    product(n, A, E, U);
    return pade_solve(n, U, V, pow, E, piv);
}

/* ‖A‖₁, the largest column sum (of A^T's rows alike: the bounds hold), or infinity. */
static double norm1(const double *A, size_t p)
{
    double norm = 0.0;
    for (size_t j = 0; j < p; j++) {
        double sum = 0.0;
        for (size_t i = 0; i < p; i++)
            sum += fabs(A[j * p + i]);
        if (!(sum < INFINITY))
            return INFINITY;
        norm = fmax(norm, sum);
    }
    return norm;
}

int fr_hb_expm(const double *A, size_t p, double *E, double *work, int *piv)
{
    size_t pp = p * p;
    int n = (int)p;
    double norm = norm1(A, p);
    if (!(norm < INFINITY))
        return -1;
    for (int d = 0; d < 4; d++)
        if (norm <= THETA[d])
            return pade_low(A, p, d, E, work, piv);
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
    int info = pade_solve(n, U, V, A2, E, piv);
    if (info != 0)
        return info;
    for (int k = 0; k < s; k++) {
        product(n, E, E, A1);
        memcpy(E, A1, pp * sizeof *E);
    }
    return 0;
}

double fr_hb_expm_powers(const double *A, size_t p, double *pow)
{
    size_t pp = p * p;
    int n = (int)p;
    double nu = norm1(A, p);
    if (!(nu < INFINITY) || nu == 0.0)
        return nu;
    double *N = pow, *N2 = N + pp, *N4 = N2 + pp, *N6 = N4 + pp, *N8 = N6 + pp;
    for (size_t i = 0; i < pp; i++)
        N[i] = A[i] / nu;
    product(n, N, N, N2);
    product(n, N2, N2, N4);
    product(n, N2, N4, N6);
    product(n, N4, N4, N8);
    return nu;
}

/* out = Σ_k c[k] N^(2k) over N^0 = I, N², N⁴, .., N^(2 top) (pow's). */
static void power_sum(size_t p, const double *pow, size_t top, const double *c, double *out)
{
    size_t pp = p * p;
    memset(out, 0, pp * sizeof *out);
    for (size_t k = 1; k <= top; k++)
        for (size_t i = 0; i < pp; i++)
            out[i] += c[k] * pow[k * pp + i];
    for (size_t i = 0; i < p; i++)
        out[i * p + i] += c[0];
}

int fr_hb_expm_at(const double *pow, double nu, size_t p, double t, double *E, double *work,
                  int *piv)
{
    size_t pp = p * p;
    int n = (int)p;
    double tau = t * nu; /* ‖t Â‖₁: e^(t Â) = e^(τ N) */
    if (!(tau < INFINITY))
        return -1;
    double *U = work, *V = U + pp, *W = V + pp, *S = W + pp;
    double cv[7], cu[7];
    if (tau == 0.0) {
        memset(E, 0, pp * sizeof *E);
        for (size_t i = 0; i < p; i++)
            E[i * p + i] = 1.0;
        return 0;
    }
    for (int d = 0; d < 4; d++) {
        if (tau > THETA[d])
            continue;
        /* V = Σ b_2k τ^2k N^2k, U = τ N Σ b_(2k+1) τ^2k N^2k (pade_low's with X = τ N) */
        const double *b = PADE_LOW[d];
        double x = 1.0;
        for (int k = 0; k <= d + 1; k++, x *= tau * tau) {
            cv[k] = b[2 * k] * x;
            cu[k] = b[2 * k + 1] * x;
        }
        power_sum(p, pow, (size_t)d + 1, cv, V);
        power_sum(p, pow, (size_t)d + 1, cu, W);
        product(n, pow, W, U);
        for (size_t i = 0; i < pp; i++)
            U[i] *= tau;
        return pade_solve(n, U, V, S, E, piv);
    }
    /* X = c N, c = τ/2^s: the [13/13] approximant as fr_hb_expm's, the scalars folded into the
     * sums (X⁶ (b12 X⁶ + ..) = N⁶ (b12 c¹² N⁶ + ..)), then s squarings */
    int s = tau > THETA13 ? (int)ceil(log2(tau / THETA13)) : 0;
    double c = ldexp(tau, -s), c2 = c * c, c4 = c2 * c2, c6 = c4 * c2, c8 = c4 * c4;
    const double vh[4] = {0.0, PADE[8] * c8, PADE[10] * c8 * c2, PADE[12] * c8 * c4},
                 vl[4] = {PADE[0], PADE[2] * c2, PADE[4] * c4, PADE[6] * c6},
                 uh[4] = {0.0, PADE[9] * c8, PADE[11] * c8 * c2, PADE[13] * c8 * c4},
                 ul[4] = {PADE[1], PADE[3] * c2, PADE[5] * c4, PADE[7] * c6};
    const double *N6 = pow + 3 * pp;
    power_sum(p, pow, 3, vh, W);
    product(n, N6, W, V);
    power_sum(p, pow, 3, vl, W);
    for (size_t i = 0; i < pp; i++)
        V[i] += W[i];
    power_sum(p, pow, 3, uh, W);
    product(n, N6, W, U);
    power_sum(p, pow, 3, ul, W);
    for (size_t i = 0; i < pp; i++)
        W[i] += U[i];
    product(n, pow, W, U);
    for (size_t i = 0; i < pp; i++)
        U[i] *= c;
    int info = pade_solve(n, U, V, S, E, piv);
    if (info != 0)
        return info;
    for (int k = 0; k < s; k++) {
        product(n, E, E, U);
        memcpy(E, U, pp * sizeof *E);
    }
    return 0;
}
