/* SPDX-License-Identifier: GPL-3.0-or-later */
/* stress_cond.c — conditioning of W: where fricreg_ctx_eval declares FRICREG_ESINGULAR, and
 * how accurate the near-stick forces are just before it.
 *
 * W = Q diag(1, ..., 1/kappa) Q^T with Q a random orthogonal matrix (GSL's QR of a random
 * matrix), m = 2 and 3, kappa = 1e4 ... 1e16. All contacts at rest (zdot = 0) with a_free =
 * -W f* for f* in [-1, 1]^m and bounds mun = 1e3, so the forces are interior: under both
 * partitions f solves W f = -a_free (the consistent QP's unconstrained minimum; the paper's
 * f_eq, which law (4) returns at v = 0 inside the bound). The reference solves that system with
 * the W and a_free actually stored, by Cramer's rule in binary128 (__float128, 113 bits; long
 * double where the compiler has none): products of doubles are exact there, so its error,
 * ~kappa 1e-34, is far below the double solve's ~kappa 1e-16. Errors are measured in the
 * Jacobi-scaled norm max_i sqrt(W_ii) |f_i - x_i| / max_i sqrt(W_ii) |x_i| that the factor
 * works in (src/ctx/factor.c), so badly scaled but regular W (diag(1, 1e-14)) count as regular. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_linalg.h>

#include "stress.h"

#if defined(__SIZEOF_FLOAT128__)
__extension__ typedef __float128 wide;
#else
typedef long double wide;
#endif

#define MAX_M 3
#define QP_MAX_M 8
#define MUN 1e3
#define EPS 1e-3
#define UNIT_ROUNDOFF (DBL_EPSILON / 2)

/* ---- the reference: Cramer's rule for m = 1, 2, 3 in wide precision ----------------------- */

static wide det3(const wide A[9])
{
    return A[0] * (A[4] * A[8] - A[5] * A[7]) - A[1] * (A[3] * A[8] - A[5] * A[6]) +
           A[2] * (A[3] * A[7] - A[4] * A[6]);
}

static wide det(size_t m, const wide A[])
{
    if (m == 1)
        return A[0];
    if (m == 2)
        return A[0] * A[3] - A[1] * A[2];
    return det3(A);
}

/* x = W^-1 r: x_j = det(W with column j replaced by r) / det W. */
static void reference_solve(size_t m, const double W[], const double r[], double x[])
{
    wide A[MAX_M * MAX_M], Aj[MAX_M * MAX_M];
    for (size_t k = 0; k < m * m; k++)
        A[k] = W[k];
    wide d = det(m, A);
    for (size_t j = 0; j < m; j++) {
        memcpy(Aj, A, m * m * sizeof *A);
        for (size_t i = 0; i < m; i++)
            Aj[i * m + j] = r[i];
        x[j] = (double)(det(m, Aj) / d);
    }
}

/* ---- test matrices --------------------------------------------------------------------- */

/* A random orthogonal m x m Q (row-major) from the QR factorization of a uniform matrix. */
static int random_orthogonal(size_t m, uint64_t *rng, double Q[])
{
    gsl_matrix *A = gsl_matrix_alloc(m, m), *q = gsl_matrix_alloc(m, m),
               *R = gsl_matrix_alloc(m, m);
    gsl_vector *tau = gsl_vector_alloc(m);
    int status = A && q && R && tau ? GSL_SUCCESS : GSL_ENOMEM;
    for (size_t k = 0; status == GSL_SUCCESS && k < m * m; k++)
        A->data[k / m * A->tda + k % m] = stress_uniform(rng, -1.0, 1.0);
    if (status == GSL_SUCCESS)
        status = gsl_linalg_QR_decomp(A, tau);
    if (status == GSL_SUCCESS)
        status = gsl_linalg_QR_unpack(A, tau, q, R);
    for (size_t k = 0; status == GSL_SUCCESS && k < m * m; k++)
        Q[k] = gsl_matrix_get(q, k / m, k % m);
    gsl_matrix_free(A), gsl_matrix_free(q), gsl_matrix_free(R), gsl_vector_free(tau);
    return status;
}

/* W = Q diag(s) Q^T, symmetric by construction (the upper triangle mirrored). */
static void spectral_matrix(size_t m, const double Q[], const double s[], double W[])
{
    for (size_t i = 0; i < m; i++)
        for (size_t j = i; j < m; j++) {
            double sum = 0.0;
            for (size_t k = 0; k < m; k++)
                sum += Q[i * m + k] * s[k] * Q[j * m + k];
            W[i * m + j] = W[j * m + i] = sum;
        }
}

/* ---- one evaluation against the reference ------------------------------------------------ */

struct outcome {
    int status;      /* of set_coupling_dense, else of eval */
    int untouched;   /* on failure, f kept its sentinel */
    int has_message; /* on failure, a message */
    int interior;    /* the reference lies inside the bounds: the case measures the solve */
    double error;    /* scaled-norm relative error on success */
};

static double scaled_error(size_t m, const double W[], const double f[], const double x[])
{
    double num = 0.0, den = 0.0;
    for (size_t i = 0; i < m; i++) {
        double w = sqrt(W[i * m + i]);
        num = fmax(num, w * fabs(f[i] - x[i]));
        den = fmax(den, w * fabs(x[i]));
    }
    return num / den;
}

static struct outcome evaluate(size_t m, const double W[], const double fstar[], int partition)
{
    struct outcome o = {0, 1, 1, 1, NAN};
    double a_free[MAX_M], rhs[MAX_M], x[MAX_M], zdot[MAX_M] = {0}, mun[MAX_M];
    double f[MAX_M], sentinel = 12345.678;
    for (size_t i = 0; i < m; i++) {
        double sum = 0.0;
        for (size_t j = 0; j < m; j++)
            sum += W[i * m + j] * fstar[j];
        a_free[i] = -sum;
        rhs[i] = sum; /* -a_free, exactly */
        mun[i] = MUN;
        f[i] = sentinel;
    }
    reference_solve(m, W, rhs, x);
    for (size_t i = 0; i < m; i++)
        o.interior = o.interior && fabs(x[i]) < MUN;
    fricreg_ctx *ctx = NULL;
    o.status = fricreg_ctx_create(m, &ctx);
    if (o.status == FRICREG_OK)
        o.status = fricreg_ctx_set_law(ctx, FRICREG_LAW_QUINN, EPS);
    if (o.status == FRICREG_OK)
        o.status = fricreg_ctx_set_bounds(ctx, m, mun);
    if (o.status == FRICREG_OK)
        o.status = fricreg_ctx_set_partition(ctx, partition);
    if (o.status == FRICREG_OK)
        o.status = fricreg_ctx_set_coupling_dense(ctx, m, W);
    if (o.status == FRICREG_OK)
        o.status = fricreg_ctx_eval(ctx, m, zdot, a_free, f, NULL);
    if (o.status == FRICREG_OK) {
        o.error = scaled_error(m, W, f, x);
    } else {
        for (size_t i = 0; i < m; i++)
            o.untouched = o.untouched && f[i] == sentinel;
        o.has_message = ctx != NULL && fricreg_ctx_errmsg(ctx)[0] != '\0';
    }
    fricreg_ctx_free(ctx);
    return o;
}

/* ---- the sweep ------------------------------------------------------------------------- */

struct decade {
    int ok, singular, other, skipped;
    double worst_error, worst_ratio; /* error, and error / (kappa u) */
};

static void record(struct decade *d, const struct outcome *o, double kappa)
{
    if (!o->interior) {
        d->skipped++;
    } else if (o->status == FRICREG_OK) {
        d->ok++;
        d->worst_error = fmax(d->worst_error, o->error);
        d->worst_ratio = fmax(d->worst_ratio, o->error / (kappa * UNIT_ROUNDOFF));
    } else if (o->status == FRICREG_ESINGULAR) {
        d->singular++;
    } else {
        d->other++;
    }
}

static void check_outcome(struct stress_tally *tally, const struct outcome *o, const char *what)
{
    stress_check(tally, o->status == FRICREG_OK || o->status == FRICREG_ESINGULAR,
                 "%s: status %d (OK or ESINGULAR expected)", what, o->status);
    if (o->status != FRICREG_OK)
        stress_check(tally, o->untouched && o->has_message,
                     "%s: refused with f modified or no message", what);
}

/* Regular but badly scaled: W = S C S with C = Q diag(1, 1/2, 1/4) Q^T (kappa(C) = 4) and
 * S = diag(1, 1e-7, 1e-14)^(1/2) etc.; and diag(1, 10^-k). Jacobi scaling makes them C or I:
 * they are regular whatever kappa(W) (up to 1e300 here) and must be solved to ~kappa(C) u. */
static void badly_scaled(struct stress_tally *tally, uint64_t *rng, double *worst)
{
    static const double tiny[] = {1e-14, 1e-100, 1e-300};
    for (size_t t = 0; t < sizeof tiny / sizeof tiny[0]; t++)
        for (int partition = FRICREG_PARTITION_CONSISTENT; partition <= FRICREG_PARTITION_PAPER;
             partition++) {
            double W[4] = {1.0, 0.0, 0.0, tiny[t]}, fstar[2] = {0.3183, -0.7071};
            struct outcome o = evaluate(2, W, fstar, partition);
            stress_check(tally, o.status == FRICREG_OK && o.error <= 4 * DBL_EPSILON,
                         "diag(1, %g), partition %d: status %d, error %g", tiny[t], partition,
                         o.status, o.error);
            *worst = fmax(*worst, o.status == FRICREG_OK ? o.error : INFINITY);

            double Q[9], C[9], Wc[9], s[3] = {1.0, 0.5, 0.25}, f3[3];
            random_orthogonal(3, rng, Q);
            spectral_matrix(3, Q, s, C);
            double d[3] = {1.0, sqrt(sqrt(tiny[t])), sqrt(tiny[t])};
            for (size_t i = 0; i < 3; i++) {
                f3[i] = stress_uniform(rng, -1.0, 1.0);
                for (size_t j = 0; j < 3; j++)
                    Wc[i * 3 + j] = d[i] * C[i * 3 + j] * d[j];
            }
            o = evaluate(3, Wc, f3, partition);
            /* the solve in scaled units: kappa(C) = 4 times a few roundings */
            stress_check(tally, o.status == FRICREG_OK && o.error <= 64 * DBL_EPSILON,
                         "S C S with diag(S^2) = (1, %g, %g), partition %d: status %d, error %g",
                         d[1] * d[1], tiny[t], partition, o.status, o.error);
            *worst = fmax(*worst, o.status == FRICREG_OK ? o.error : INFINITY);
        }
}

/* Redundant contacts: W = [[1, 1], [1, 1]] (rank 1): the forces are not unique. */
static void redundant(struct stress_tally *tally)
{
    double W[4] = {1.0, 1.0, 1.0, 1.0}, fstar[2] = {0.25, 0.5};
    for (int partition = FRICREG_PARTITION_CONSISTENT; partition <= FRICREG_PARTITION_PAPER;
         partition++) {
        struct outcome o = evaluate(2, W, fstar, partition);
        stress_check(tally, o.status == FRICREG_ESINGULAR && o.untouched && o.has_message,
                     "rank-1 W, partition %d: status %d", partition, o.status);
    }
}

/* ---- the consistent law at random near-stick sets ---------------------------------------- */

/* W = S Q diag(s) Q^T S, m = 2 ... 8, kappa(Q diag Q^T) up to 1e12, S = diag(10^[-3, 3]);
 * half the contacts at rest, the others anywhere in and just beyond the band, and a_free up
 * to 5 W_ii mun_i, so that many contacts are held at their bounds. The header's promise is
 * checked: each near-stick f_i is law (4) at (zdot_i, f_eq,i), f_eq as eval returns it, and
 * |f_i| <= mun_i; status OK, or ESINGULAR, which a W of condition below 1e8 must not get. */
struct qp_figures {
    int ok, singular, other, early_singular;
    double worst_law, worst_bound;
};

static void qp_case(uint64_t *rng, struct qp_figures *q)
{
    size_t m = 2 + (size_t)stress_uniform(rng, 0.0, QP_MAX_M - 1);
    double kappa = stress_log_uniform(rng, 1.0, 1e12);
    double Q[QP_MAX_M * QP_MAX_M], C[QP_MAX_M * QP_MAX_M], W[QP_MAX_M * QP_MAX_M];
    double s[QP_MAX_M], d[QP_MAX_M], zdot[QP_MAX_M], a[QP_MAX_M], mun[QP_MAX_M];
    double f[QP_MAX_M], f_eq[QP_MAX_M], eps = stress_log_uniform(rng, 1e-3, 1.0);
    if (random_orthogonal(m, rng, Q) != GSL_SUCCESS) {
        q->other++;
        return;
    }
    for (size_t i = 0; i < m; i++) {
        s[i] = i == 0 ? 1.0 : i == m - 1 ? 1.0 / kappa : pow(kappa, -stress_uniform(rng, 0, 1));
        d[i] = stress_log_uniform(rng, 1e-3, 1e3);
    }
    spectral_matrix(m, Q, s, C);
    for (size_t i = 0; i < m; i++)
        for (size_t j = 0; j < m; j++)
            W[i * m + j] = d[i] * C[i * m + j] * d[j];
    for (size_t i = 0; i < m; i++) {
        mun[i] = stress_uniform(rng, 0.1, 3.0);
        zdot[i] = stress_uniform(rng, 0.0, 1.0) < 0.5 ? 0.0 : stress_uniform(rng, -1.2, 1.2) * eps;
        a[i] = stress_uniform(rng, -5.0, 5.0) * W[i * m + i] * mun[i];
    }
    fricreg_ctx *ctx = NULL;
    int status = fricreg_ctx_create(m, &ctx);
    if (status == FRICREG_OK)
        status = fricreg_ctx_set_law(ctx, FRICREG_LAW_QUINN, eps);
    if (status == FRICREG_OK)
        status = fricreg_ctx_set_bounds(ctx, m, mun);
    if (status == FRICREG_OK)
        status = fricreg_ctx_set_coupling_dense(ctx, m, W);
    if (status == FRICREG_OK)
        status = fricreg_ctx_eval(ctx, m, zdot, a, f, f_eq);
    fricreg_ctx_free(ctx);
    if (status == FRICREG_ESINGULAR) {
        q->singular++;
        q->early_singular += kappa < 1e8;
        return;
    }
    if (status != FRICREG_OK) {
        q->other++;
        return;
    }
    q->ok++;
    for (size_t i = 0; i < m; i++) {
        q->worst_bound = fmax(q->worst_bound, fabs(f[i]) / mun[i]);
        double law = NAN;
        if (fabs(zdot[i]) < eps &&
            fricreg_law_eval(FRICREG_LAW_QUINN, zdot[i], f_eq[i], mun[i], eps, &law) == FRICREG_OK)
            q->worst_law = fmax(q->worst_law, fabs(law - f[i]) / mun[i]);
        else if (fabs(zdot[i]) < eps)
            q->worst_law = INFINITY;
    }
}

static void qp_consistency(const struct stress_mode *mode, struct stress_tally *tally,
                           uint64_t *rng)
{
    struct qp_figures q = {0, 0, 0, 0, 0.0, 0.0};
    for (int k = 0; k < mode->qp_cases; k++)
        qp_case(rng, &q);
    printf("consistent law at random near-stick sets (m = 2..%d, kappa <= 1e12, rows scaled "
           "by 1e-3..1e3): %d cases, %d OK, %d ESINGULAR (%d below kappa 1e8), %d other; "
           "worst |f - law(zdot, f_eq)|/mun %.3g, worst |f|/mun %.17g\n",
           QP_MAX_M, mode->qp_cases, q.ok, q.singular, q.early_singular, q.other, q.worst_law,
           q.worst_bound);
    stress_check(tally, q.other == 0 && q.early_singular == 0,
                 "random near-stick sets: %d other statuses, %d ESINGULAR below kappa 1e8", q.other,
                 q.early_singular);
    /* f_eq is formed from the returned f: -(a_i + sum_j W_ij f_j)/W_ii, whose terms reach
     * 1e6 mun with rows scaled by 1e-3..1e3 (W_ij/W_ii ~ d_j/d_i), so its roundings are up to
     * ~1e6 m u mun ~ 1e-9 mun (measured 2.5e-15: the terms are rarely that large) */
    stress_check(tally, q.worst_law <= 1e-9 && q.worst_bound <= 1.0 + 4 * DBL_EPSILON,
                 "random near-stick sets: f off the law by %g mun, |f|/mun up to %.17g",
                 q.worst_law, q.worst_bound);
}

int stress_conditioning(const struct stress_mode *mode)
{
    struct stress_tally tally = {0, 0};
    uint64_t rng = mode->seed ^ 0xC0DEull;
    double first_singular = INFINITY, last_all_ok = 0.0, worst_before = 0.0, worst_scaled = 0.0;
    printf("== conditioning of W: Q diag(1 .. 1/kappa) Q^T, m = 2 and 3, %d random Q each, both "
           "partitions, zdot = 0, interior forces; error vs a binary128 reference\n",
           mode->cond_samples);
    printf("%-8s %6s %10s %6s %8s %14s %14s\n", "kappa", "ok", "ESINGULAR", "other", "skipped",
           "worst error", "error/(kappa u)");
    for (int e = 4; e <= 16; e++) {
        double kappa = pow(10.0, e);
        struct decade d = {0};
        for (size_t m = 2; m <= MAX_M; m++)
            for (int k = 0; k < mode->cond_samples; k++) {
                double Q[MAX_M * MAX_M], W[MAX_M * MAX_M], s[MAX_M], fstar[MAX_M];
                stress_check(&tally, random_orthogonal(m, &rng, Q) == GSL_SUCCESS, "QR");
                for (size_t i = 0; i < m; i++) {
                    s[i] = pow(kappa, -(double)i / (double)(m - 1));
                    fstar[i] = stress_uniform(&rng, -1.0, 1.0);
                }
                spectral_matrix(m, Q, s, W);
                for (int partition = FRICREG_PARTITION_CONSISTENT;
                     partition <= FRICREG_PARTITION_PAPER; partition++) {
                    struct outcome o = evaluate(m, W, fstar, partition);
                    char what[64];
                    snprintf(what, sizeof what, "kappa 1e%d, m %zu, sample %d", e, m, k);
                    check_outcome(&tally, &o, what);
                    record(&d, &o, kappa);
                }
            }
        printf("1e%-6d %6d %10d %6d %8d %14.3g %14.3g\n", e, d.ok, d.singular, d.other, d.skipped,
               d.worst_error, d.worst_ratio);
        if (d.singular > 0 && kappa < first_singular)
            first_singular = kappa;
        if (d.singular == 0 && d.other == 0 && first_singular == INFINITY) {
            last_all_ok = kappa;
            worst_before = fmax(worst_before, d.worst_error);
        }
        /* backward-stable Cholesky: error <= c m kappa u; c = 10 covers the measured 1.5 */
        stress_check(&tally, d.worst_ratio <= 10.0 * MAX_M, "kappa 1e%d: error %g = %g kappa u", e,
                     d.worst_error, d.worst_ratio);
        if (e <= 8) /* a regular W of moderate condition is never called singular */
            stress_check(&tally, d.singular == 0 && d.other == 0, "kappa 1e%d: %d refused", e,
                         d.singular + d.other);
    }
    badly_scaled(&tally, &rng, &worst_scaled);
    redundant(&tally);
    qp_consistency(mode, &tally, &rng);
    printf("ESINGULAR first at kappa %.0e; all regular up to kappa %.0e, worst error there %.3g; "
           "badly scaled regular W (diag(1, 1e-14 .. 1e-300), S C S): worst error %.3g\n\n",
           first_singular, last_all_ok, worst_before, worst_scaled);
    return tally.failures;
}
