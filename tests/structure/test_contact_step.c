/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_contact_step.c — Check suite for fricreg_ctx_solve_step (fricreg_structure.h): one
 * implicit step's contact forces for the user's own integrator.
 *
 * Expected numbers, each derived where it is used:
 *  - the step's equations: the returned f is the context's law at the step's end,
 *    f = F(zdot_pred + c W_eff f, a_pred - (W - W_eff) f), F from fricreg_ctx_eval itself, to
 *    the tolerance asked (on random symmetric positive definite W and W_eff, for law (4) with a
 *    coupled and a diagonal W, (3) and tanh: the continuous laws, whose step equations have a
 *    solution; Karnopp's force jumps at |zdot| = eps, where a step can have none);
 *  - fricreg_structure's own Newmark steps: the same forces, step after step, when the caller
 *    forms zdot_pred, a_pred, W and W_eff of the structure's step (Newmark, docstring);
 *  - plain Newton (FRICREG_STEP_PLAIN) on a step that reverses a sliding contact: it fails
 *    where the safeguarded one converges. */
#include <check.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_linalg.h>
#include <gsl/gsl_matrix.h>

#include "ctx/ctx_driver.h" /* fr_ctx_workspace: the solver the context keeps */
#include "fricreg.h"
#include "fricreg_structure.h"

#define MMAX 16

static double uniform(unsigned long *state)
{
    *state = *state * 6364136223846793005UL + 1442695040888963407UL;
    return (double)(*state >> 11) / 9007199254740992.0; /* [0, 1) */
}

/* A's nonzeros (m x m, row-major, symmetric) in compressed form: the row-major order read as
 * CSR, or (by_columns) as CSC, which for a symmetric A is the same arrays; whole, or the upper
 * (FRICREG_SPARSE_UPPER) or lower triangle; ONE_BASED adds 1 to the indices. For by_columns
 * the triangle flag names the triangle of the CSC reading: the other of the CSR's. */
static void compressed(size_t m, const double A[], int flags, int by_columns, int64_t ptr[],
                       int64_t ind[], double val[])
{
    int64_t base = (flags & FRICREG_SPARSE_ONE_BASED) ? 1 : 0, p = 0;
    int upper = (flags & FRICREG_SPARSE_UPPER) != 0, lower = (flags & FRICREG_SPARSE_LOWER) != 0;
    if (by_columns) { /* the CSC's upper triangle is the CSR reading's lower one */
        int t = upper;
        upper = lower;
        lower = t;
    }
    for (size_t i = 0; i < m; i++) {
        ptr[i] = p + base;
        for (size_t j = 0; j < m; j++)
            if ((i == j || A[i * m + j] != 0.0) && !(upper && j < i) && !(lower && j > i)) {
                ind[p] = (int64_t)j + base;
                val[p++] = A[i * m + j];
            }
    }
    ptr[m] = p + base;
}

/* The four ways a caller may give a matrix, in turn: CSR whole zero-based, CSR upper
 * one-based, CSC lower zero-based, CSC whole one-based. */
static const int way_flags[4] = {0, FRICREG_SPARSE_UPPER | FRICREG_SPARSE_ONE_BASED,
                                 FRICREG_SPARSE_LOWER, FRICREG_SPARSE_ONE_BASED};

/* fricreg_ctx_solve_step_csr or _csc (way k % 4) on the dense W and Weff's nonzeros; for
 * k % 8 >= 4, the same through fricreg_ctx_solve_step_matrix. */
static int solve_step_sparse(fricreg_ctx *ctx, size_t m, const double z0[], const double zp[],
                             const double ap[], const double W[], const double Weff[], double c,
                             double tol, int max_iter, int flags, double f[], int info[], int k)
{
    enum { CAP = 16 * 16 };
    int64_t wp[17], wi[CAP], ep[17], ei[CAP];
    double wv[CAP], ev[CAP];
    int sf = way_flags[k % 4], by_columns = k % 4 >= 2;
    ck_assert_int_le(m, 16);
    compressed(m, W, sf, by_columns, wp, wi, wv);
    compressed(m, Weff, sf, by_columns, ep, ei, ev);
    if (k % 8 >= 4)
        return fricreg_ctx_solve_step_matrix(
            ctx, m, z0, zp, ap, (by_columns ? FRICREG_MATRIX_CSC : FRICREG_MATRIX_CSR) | sf, wp, wi,
            wv, ep, ei, ev, c, tol, max_iter, flags, f, info);
    return by_columns ? fricreg_ctx_solve_step_csc(ctx, m, z0, zp, ap, sf, wp, wi, wv, ep, ei, ev,
                                                   c, tol, max_iter, flags, f, info)
                      : fricreg_ctx_solve_step_csr(ctx, m, z0, zp, ap, sf, wp, wi, wv, ep, ei, ev,
                                                   c, tol, max_iter, flags, f, info);
}

/* A = B B^T / m + shift I, B uniform in [-1, 1): symmetric positive definite, row-major. */
static void random_spd(size_t m, double scale, double shift, unsigned long *state, double A[])
{
    double B[MMAX * MMAX];
    for (size_t k = 0; k < m * m; k++)
        B[k] = 2.0 * uniform(state) - 1.0;
    for (size_t i = 0; i < m; i++)
        for (size_t j = 0; j < m; j++) {
            double s = 0.0;
            for (size_t k = 0; k < m; k++)
                s += B[i * m + k] * B[j * m + k];
            A[i * m + j] = scale * (s / (double)m + (i == j ? shift : 0.0));
        }
}

/* max_i |f_i - F_i| with F the context's law at the step's end for the forces f. */
static double law_residual(fricreg_ctx *ctx, size_t m, const double zp[], const double ap[],
                           const double W[], const double Weff[], double c, const double f[])
{
    double zdot[MMAX], afree[MMAX], F[MMAX], big = 0.0;
    for (size_t i = 0; i < m; i++) {
        double weff_f = 0.0, w_f = 0.0;
        for (size_t j = 0; j < m; j++) {
            weff_f += Weff[i * m + j] * f[j];
            w_f += W[i * m + j] * f[j];
        }
        zdot[i] = zp[i] + c * weff_f;
        afree[i] = ap[i] + (weff_f - w_f);
    }
    ck_assert_int_eq(fricreg_ctx_eval(ctx, m, zdot, afree, F, NULL), FRICREG_OK);
    for (size_t i = 0; i < m; i++)
        big = fmax(big, fabs(f[i] - F[i]));
    return big;
}

/* Random steps of m = 6 contacts: velocities around the band, free accelerations that hold
 * some contacts and break others away. law: the context's; diagonal: W diagonal. */
static void random_steps(int law, int diagonal)
{
    enum { M = 6, STEPS = 200 };
    const double eps = 1e-3, c = 0.005, tol = 1e-10;
    unsigned long state = 2385;
    fricreg_ctx *ctx = NULL, *twin = NULL; /* twin: the same calls by the sparse entries */
    ck_assert_int_eq(fricreg_ctx_create(M, &ctx), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_law(ctx, law, eps), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_create(M, &twin), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_law(twin, law, eps), FRICREG_OK);
    int converged = 0, iterations = 0;
    for (int step = 0; step < STEPS; step++) {
        double W[M * M], Weff[M * M], mun[M], z0[M], zp[M], ap[M], f[M], wd[M];
        random_spd(M, 1.0, 0.3, &state, W);
        if (diagonal) {
            for (size_t i = 0; i < M; i++) {
                wd[i] = W[i * M + i];
                for (size_t j = 0; j < M; j++)
                    W[i * M + j] = i == j ? wd[i] : 0.0;
            }
            ck_assert_int_eq(fricreg_ctx_set_coupling_diagonal(ctx, M, wd), FRICREG_OK);
            ck_assert_int_eq(fricreg_ctx_set_coupling_diagonal(twin, M, wd), FRICREG_OK);
        } else {
            ck_assert_int_eq(fricreg_ctx_set_coupling_dense(ctx, M, W), FRICREG_OK);
            ck_assert_int_eq(fricreg_ctx_set_coupling_dense(twin, M, W), FRICREG_OK);
        }
        random_spd(M, 0.05, 0.2, &state, Weff); /* K_eff stiffer than M: W_eff << W */
        for (size_t i = 0; i < M; i++) {
            mun[i] = 0.5 + uniform(&state);
            z0[i] = eps * (6.0 * uniform(&state) - 3.0);
            zp[i] = z0[i] + eps * (4.0 * uniform(&state) - 2.0);
            ap[i] = 3.0 * uniform(&state) - 1.5;
            f[i] = mun[i] * (2.0 * uniform(&state) - 1.0);
        }
        ck_assert_int_eq(fricreg_ctx_set_bounds(ctx, M, mun), FRICREG_OK);
        ck_assert_int_eq(fricreg_ctx_set_bounds(twin, M, mun), FRICREG_OK);
        int info[2] = {-1, -1}, info_sparse[2] = {-2, -2};
        double f_sparse[M];
        memcpy(f_sparse, f, sizeof f);
        /* the dense call, every third step through fricreg_ctx_solve_step_matrix */
        int status = step % 3 == 0
                         ? fricreg_ctx_solve_step_matrix(ctx, M, z0, zp, ap, FRICREG_MATRIX_DENSE,
                                                         NULL, NULL, W, NULL, NULL, Weff, c, tol,
                                                         50, 0, f, info)
                         : fricreg_ctx_solve_step(ctx, M, z0, zp, ap, W, Weff, c, tol, 50, 0, f,
                                                  info);
        ck_assert_msg(status == FRICREG_OK, "%s", fricreg_ctx_errmsg(ctx));
        /* The sparse entries on the same matrices: the dense call's forces, bit for bit. */
        status = solve_step_sparse(twin, M, z0, zp, ap, W, Weff, c, tol, 50, 0, f_sparse,
                                   info_sparse, step);
        ck_assert_msg(status == FRICREG_OK, "%s", fricreg_ctx_errmsg(twin));
        ck_assert_msg(memcmp(f, f_sparse, sizeof f) == 0, "step %d: sparse forces differ", step);
        ck_assert(memcmp(info, info_sparse, sizeof info) == 0);
        ck_assert_int_ge(info[0], 0);
        if (info[1]) {
            converged++;
            iterations += info[0];
            ck_assert_double_le(law_residual(ctx, M, zp, ap, W, Weff, c, f), 2.0 * tol);
        }
    }
    /* Every step converges, in a few iterations on average. */
    ck_assert_int_eq(converged, STEPS);
    ck_assert_int_le(iterations, 6 * STEPS);
    fricreg_ctx_free(ctx);
    fricreg_ctx_free(twin);
}

START_TEST(law_quinn_coupled)
{
    random_steps(FRICREG_LAW_QUINN, 0);
}
END_TEST

START_TEST(law_quinn_diagonal)
{
    random_steps(FRICREG_LAW_QUINN, 1);
}
END_TEST

START_TEST(law_velocity_limited)
{
    random_steps(FRICREG_LAW_VELOCITY_LIMITED, 0);
}
END_TEST

START_TEST(law_tanh)
{
    random_steps(FRICREG_LAW_TANH, 0);
}
END_TEST

/* ---- Against fricreg_structure's Newmark steps ------------------------------------------- */

enum { N = 3, MC = 2 };

/* A three-mass chain with two dampers: M, K dense SPD, Rayleigh C, J (2 x 3). */
static const double Mm[N * N] = {1.3, 0.2, 0.0, 0.2, 0.7, 0.1, 0.0, 0.1, 1.1};
static const double Km[N * N] = {240.0, -110.0, 0.0, -110.0, 230.0, -120.0, 0.0, -120.0, 120.0};
static const double Jm[MC * N] = {1.0, 0.0, 0.0, -1.0, 1.0, 0.0};
static const double ray0 = 0.35, ray1 = 0.0021, MUN[MC] = {2.385, 1.21};

/* X = A^-1 B (A n x n SPD, B n x k), row-major, by GSL's Cholesky. */
static void spd_solve(const double A[], size_t n, const double B[], size_t k, double X[])
{
    gsl_matrix *L = gsl_matrix_alloc(n, n);
    gsl_vector *x = gsl_vector_alloc(n);
    memcpy(L->data, A, n * n * sizeof *A);
    ck_assert_int_eq(gsl_linalg_cholesky_decomp1(L), 0);
    for (size_t col = 0; col < k; col++) {
        for (size_t i = 0; i < n; i++)
            x->data[i] = B[i * k + col];
        gsl_linalg_cholesky_svx(L, x);
        for (size_t i = 0; i < n; i++)
            X[i * k + col] = x->data[i];
    }
    gsl_vector_free(x);
    gsl_matrix_free(L);
}

/* y = A x, A rows x cols row-major. */
static void mult(const double A[], size_t rows, size_t cols, const double x[], double y[])
{
    for (size_t i = 0; i < rows; i++) {
        y[i] = 0.0;
        for (size_t j = 0; j < cols; j++)
            y[i] += A[i * cols + j] * x[j];
    }
}

/* W = J A^-1 J^T for A = M or K_eff. */
static void delassus(const double A[], double W[])
{
    double Jt[N * MC], X[N * MC];
    for (size_t i = 0; i < MC; i++)
        for (size_t k = 0; k < N; k++)
            Jt[k * MC + i] = Jm[i * N + k];
    spd_solve(A, N, Jt, MC, X);
    for (size_t i = 0; i < MC; i++)
        for (size_t j = 0; j < MC; j++) {
            double s = 0.0;
            for (size_t k = 0; k < N; k++)
                s += Jm[i * N + k] * X[k * MC + j];
            W[i * MC + j] = s;
        }
    double off = 0.5 * (W[1] + W[2]); /* symmetric to the last bit */
    W[1] = W[2] = off;
}

static void structure_steps(double eps, double *worst, int *iterations, int *steps, int *held,
                            int *sliding)
{
    const double dt = 0.01, beta = 0.25, gamma = 0.5;
    const double p[N] = {0.0, 0.0, 1.0};
    double g[401];
    for (int k = 0; k <= 400; k++)
        g[k] = 9.7 * sin(2.0 * 3.14159265358979323846 * 1.3 * dt * k);
    fricreg_structure *s = NULL;
    ck_assert_int_eq(fricreg_structure_create(N, MC, &s), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_mass(s, N, Mm), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_stiffness(s, N, Km), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_rayleigh(s, ray0, ray1), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_contacts(s, MC, N, Jm), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_bounds(s, MC, MUN), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_law(s, FRICREG_LAW_QUINN, eps), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_load(s, N, p, 0.0, dt, 401, g), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_newton(s, 1e-13, 50), FRICREG_OK);

    double C[N * N], Keff[N * N], W[MC * MC], Weff[MC * MC];
    for (size_t k = 0; k < N * N; k++) {
        C[k] = ray0 * Mm[k] + ray1 * Km[k];
        Keff[k] = Mm[k] + gamma * dt * C[k] + beta * dt * dt * Km[k];
    }
    delassus(Mm, W);
    delassus(Keff, Weff);
    fricreg_ctx *ctx = NULL;
    ck_assert_int_eq(fricreg_ctx_create(MC, &ctx), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_law(ctx, FRICREG_LAW_QUINN, eps), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_bounds(ctx, MC, MUN), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_coupling_dense(ctx, MC, W), FRICREG_OK);

    *worst = 0.0;
    *iterations = *steps = *held = *sliding = 0;
    ck_assert_int_eq(fricreg_structure_step(s, dt), FRICREG_OK); /* a(0) from the first step */
    for (int k = 2; k <= 400; k++) {
        double u[N], v[N], a[N], f[MC], fs[MC], up[N], vp[N], b[N], y[N], t1 = k * dt;
        ck_assert_int_eq(fricreg_structure_get_state(s, N, u, v, a), FRICREG_OK);
        ck_assert_int_eq(fricreg_structure_get_forces(s, MC, f), FRICREG_OK);
        for (size_t i = 0; i < N; i++) {
            up[i] = u[i] + dt * v[i] + (0.5 - beta) * dt * dt * a[i];
            vp[i] = v[i] + (1.0 - gamma) * dt * a[i];
        }
        double cv[N], ku[N];
        mult(C, N, N, vp, cv);
        mult(Km, N, N, up, ku);
        for (size_t i = 0; i < N; i++)
            b[i] = p[i] * g[k] - cv[i] - ku[i];
        spd_solve(Keff, N, b, 1, y);
        double ap[MC], zp[MC], z0[MC], jvp[MC];
        mult(Jm, MC, N, y, ap);
        mult(Jm, MC, N, vp, jvp);
        mult(Jm, MC, N, v, z0);
        for (size_t i = 0; i < MC; i++)
            zp[i] = jvp[i] + gamma * dt * ap[i];
        int info[2];
        ck_assert_int_eq(fricreg_ctx_solve_step(ctx, MC, z0, zp, ap, W, Weff, gamma * dt,
                                                1e-13 * MUN[0], 50, 0, f, info),
                         FRICREG_OK);
        ck_assert_int_eq(info[1], 1);
        ck_assert_int_eq(fricreg_structure_step(s, t1 - (k - 1) * dt), FRICREG_OK);
        ck_assert_int_eq(fricreg_structure_get_forces(s, MC, fs), FRICREG_OK);
        for (size_t i = 0; i < MC; i++) {
            *worst = fmax(*worst, fabs(f[i] - fs[i]) / MUN[i]);
            *held += fabs(fs[i]) < MUN[i];
            *sliding += fabs(fs[i]) == MUN[i];
        }
        *iterations += info[0];
        ++*steps;
    }
    fricreg_ctx_free(ctx);
    fricreg_structure_free(s);
}

START_TEST(equals_structure_steps)
{
    const double eps[] = {1e-3, 1e-4};
    for (size_t e = 0; e < 2; e++) {
        double worst;
        int iterations, steps, held, sliding;
        structure_steps(eps[e], &worst, &iterations, &steps, &held, &sliding);
        /* Both regimes are visited: contacts held inside their bounds and sliding at them. */
        ck_assert_int_ge(held, 50);
        ck_assert_int_ge(sliding, 50);
        /* The same equations to Newton's tolerance 1e-13 on both sides, solved on pieces of a
         * piecewise-linear law (one Newton step is exact on a piece): the forces agree to
         * rounding, 1e-12 of the bounds (measured: 8e-15 at eps = 1e-3, 1e-13 at 1e-4). */
        ck_assert_msg(worst <= 1e-12, "eps %g: forces differ by %g of the bounds", eps[e], worst);
        ck_assert_int_le(iterations, 2 * steps);
    }
}
END_TEST

/* One contact sliding into a stop: W = 2, W_eff = 1, c = 0.005, eps = 1e-3, zdot_pred = 0, a
 * guess at the bound f = -1. On the slip pieces the tangent is flat (F_z = 0), so plain Newton
 * steps to the other piece's force: from f = -1, zdot = -0.005 < -eps gives F = +1 and f = +1,
 * where zdot = +0.005 > eps gives F = -1 and f = -1 again: a 2-cycle, never converged. The stop
 * halves the first step (zdot reaches 0 at f = 0, inside the band), and the band's own piece
 * is linear: converged in at most 3 iterations. */
START_TEST(plain_newton_cycles)
{
    fricreg_ctx *ctx = NULL;
    ck_assert_int_eq(fricreg_ctx_create(1, &ctx), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_law(ctx, FRICREG_LAW_QUINN, 1e-3), FRICREG_OK);
    const double W = 2.0, Weff = 1.0, z0 = 0.001, zp = 0.0, ap = 0.3, c = 0.005;
    ck_assert_int_eq(fricreg_ctx_set_coupling_diagonal(ctx, 1, &W), FRICREG_OK);
    double f = -1.0;
    int info[2];
    ck_assert_int_eq(fricreg_ctx_solve_step(ctx, 1, &z0, &zp, &ap, &W, &Weff, c, 1e-12, 50,
                                            FRICREG_STEP_PLAIN, &f, info),
                     FRICREG_OK);
    int plain_converged = info[1];
    f = -1.0;
    ck_assert_int_eq(fricreg_ctx_solve_step(ctx, 1, &z0, &zp, &ap, &W, &Weff, c, 1e-12, 50, 0, &f,
                                            info),
                     FRICREG_OK);
    ck_assert_int_eq(info[1], 1);
    ck_assert_int_le(info[0], 3);
    ck_assert_double_le(law_residual(ctx, 1, &zp, &ap, &W, &Weff, c, &f), 1e-12);
    ck_assert_int_eq(plain_converged, 0);
    fricreg_ctx_free(ctx);
}
END_TEST

/* ---- The solver kept between calls ------------------------------------------------------ */

enum { MW = 12, RUN = 60 };

/* A symmetric banded m x m matrix, row-major: off-diagonals within `band` uniform in
 * [-0.3, 0.3) scale, diagonal scale (1 + 0.6 band + uniform): diagonally dominant, so positive
 * definite (Gershgorin); exactly symmetric. */
static void banded_spd(size_t m, size_t band, double scale, unsigned long *state, double A[])
{
    for (size_t i = 0; i < m; i++)
        for (size_t j = i; j < m; j++) {
            double a = j - i > band ? 0.0
                       : i == j     ? scale * (1.0 + 0.6 * (double)band + uniform(state))
                                    : scale * (0.6 * uniform(state) - 0.3);
            A[i * m + j] = A[j * m + i] = a;
        }
}

/* A context of MW contacts with the law, W (diagonal: its diagonal only) and the bounds. */
static fricreg_ctx *run_context(int law, int diagonal, const double W[], const double mun[])
{
    fricreg_ctx *ctx = NULL;
    double w[MW];
    for (size_t i = 0; i < MW; i++)
        w[i] = W[i * MW + i];
    ck_assert_int_eq(fricreg_ctx_create(MW, &ctx), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_law(ctx, law, 1e-3), FRICREG_OK);
    ck_assert_int_eq(diagonal ? fricreg_ctx_set_coupling_diagonal(ctx, MW, w)
                              : fricreg_ctx_set_coupling_dense(ctx, MW, W),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_bounds(ctx, MW, mun), FRICREG_OK);
    return ctx;
}

/* A run of steps on one context, whose solver is kept from call to call, against the same
 * steps each made with a solver built for the call, as every call built one before the solver
 * was kept: the same statuses, forces and info, bit for bit. The reference builds its solver
 * on a new context per step (fresh), or (fresh = 0) on a second context that has made the
 * same calls, whose solver fricreg_ctx_set_law drops before each: law (4) with a coupled W
 * warm-starts its QP from the context's previous evaluation, so a new context's evaluations
 * can differ from an old one's in the last bit (1.7e-16 at step 16 here), whatever the
 * solver. W_eff's values change every third step (between, the factor of the last stick set
 * is kept too), its pattern at steps 20 (a wider band: the solver is built again) and 40
 * (back); step 30 is refused (a NaN), step 31 has free accelerations of 1e300 (law (4) with a
 * coupled W fails inside the step: beyond its solve's range), and the steps after them are
 * compared as the others. The velocities and accelerations change the stick set from step to
 * step; each run's guess is its own previous forces. */
static void kept_against_built(int law, int diagonal, int fresh, int sparse)
{
    const double c = 0.005, tol = 1e-10;
    unsigned long state = 615;
    double W[MW * MW], Weff[MW * MW], mun[MW], f_kept[MW], f_built[MW];
    banded_spd(MW, diagonal ? 0 : 3, 1.0, &state, W);
    for (size_t i = 0; i < MW; i++)
        mun[i] = f_kept[i] = f_built[i] = 0.5 + uniform(&state);
    fricreg_ctx *kept = run_context(law, diagonal, W, mun);
    fricreg_ctx *built = fresh ? NULL : run_context(law, diagonal, W, mun);
    int converged = 0, held_min = MW, held_max = 0, failed_inside = 0;
    for (int step = 0; step < RUN; step++) {
        if (step % 3 == 0)
            banded_spd(MW, step >= 20 && step < 40 ? 2 : 1, 0.05, &state, Weff);
        double z0[MW], zp[MW], ap[MW];
        for (size_t i = 0; i < MW; i++) {
            z0[i] = 1e-3 * (6.0 * uniform(&state) - 3.0);
            zp[i] = z0[i] + 1e-3 * (4.0 * uniform(&state) - 2.0);
            ap[i] = 3.0 * uniform(&state) - 1.5;
        }
        if (step == 30)
            zp[7] = NAN;
        if (step == 31)
            for (size_t i = 0; i < MW; i++)
                ap[i] = i % 2 ? 1e300 : -1e300;
        int info_kept[2] = {-7, -7}, info_built[2] = {-7, -7};
        double f_before[MW];
        memcpy(f_before, f_kept, sizeof f_kept);
        int status_kept = sparse ? solve_step_sparse(kept, MW, z0, zp, ap, W, Weff, c, tol, 50, 0,
                                                     f_kept, info_kept, 0)
                                 : fricreg_ctx_solve_step(kept, MW, z0, zp, ap, W, Weff, c, tol, 50,
                                                          0, f_kept, info_kept);
        if (fresh)
            built = run_context(law, diagonal, W, mun);
        else
            ck_assert_int_eq(fricreg_ctx_set_law(built, law, 1e-3), FRICREG_OK);
        int status_built = fricreg_ctx_solve_step(built, MW, z0, zp, ap, W, Weff, c, tol, 50, 0,
                                                  f_built, info_built);
        if (fresh) {
            fricreg_ctx_free(built);
            built = NULL;
        }
        ck_assert_int_eq(status_kept, status_built);
        ck_assert_msg(memcmp(f_kept, f_built, sizeof f_kept) == 0, "step %d: forces differ", step);
        ck_assert_msg(memcmp(info_kept, info_built, sizeof info_kept) == 0,
                      "step %d: info {%d, %d} against {%d, %d}", step, info_kept[0], info_kept[1],
                      info_built[0], info_built[1]);
        if (status_kept != FRICREG_OK) { /* nothing written */
            ck_assert(step == 30 || step == 31);
            failed_inside += step == 31;
            ck_assert_int_eq(info_kept[0], -7);
            ck_assert(memcmp(f_kept, f_before, sizeof f_kept) == 0);
            continue;
        }
        converged += info_kept[1];
        int held = 0;
        for (size_t i = 0; i < MW; i++)
            held += fabs(f_kept[i]) < 0.9 * mun[i]; /* well inside the band */
        held_min = held < held_min ? held : held_min;
        held_max = held > held_max ? held : held_max;
    }
    fricreg_ctx_free(kept);
    fricreg_ctx_free(built);
    /* The run means something: its steps converge, the contacts well inside their bands change, and with law (4) on
     * a coupled W a step fails inside the solve. */
    ck_assert_int_eq(converged, RUN - 1 - failed_inside);
    ck_assert_int_lt(held_min, held_max);
    ck_assert_int_eq(failed_inside, law == FRICREG_LAW_QUINN && !diagonal);
}

START_TEST(kept_solver_quinn_coupled)
{
    kept_against_built(FRICREG_LAW_QUINN, 0, 0, 0);
}
END_TEST

START_TEST(kept_solver_quinn_diagonal)
{
    kept_against_built(FRICREG_LAW_QUINN, 1, 1, 0);
}
END_TEST

START_TEST(kept_solver_tanh)
{
    kept_against_built(FRICREG_LAW_TANH, 0, 1, 0);
}
END_TEST

/* The sparse entry's kept solver (CSR, its values refilled while W_eff's pattern stays, built
 * again at steps 20 and 40) against the dense call's solver built for each step: the same
 * statuses, forces and info, bit for bit. */
START_TEST(kept_sparse_quinn_coupled)
{
    kept_against_built(FRICREG_LAW_QUINN, 0, 0, 1);
}
END_TEST

START_TEST(kept_sparse_tanh)
{
    kept_against_built(FRICREG_LAW_TANH, 0, 1, 1);
}
END_TEST

/* The header's promise on the kept solver's memory: kept by a call and reused by the next with
 * the same patterns, kept through set_bounds, released by set_law and by a coupling setter
 * (then built again by the next call). fr_ctx_workspace (ctx_driver.h) shows it. */
START_TEST(kept_solver_released_by_setters)
{
    unsigned long state = 2385;
    double W[MW * MW], Weff[MW * MW], mun[MW], z0[MW], zp[MW], ap[MW], f[MW];
    banded_spd(MW, 3, 1.0, &state, W);
    banded_spd(MW, 1, 0.05, &state, Weff);
    for (size_t i = 0; i < MW; i++) {
        mun[i] = 0.5 + uniform(&state);
        z0[i] = zp[i] = 1e-3 * (2.0 * uniform(&state) - 1.0);
        ap[i] = uniform(&state) - 0.5;
    }
    fricreg_ctx *ctx = run_context(FRICREG_LAW_QUINN, 0, W, mun);
    int info[2];
#define STEP()                                                                                     \
    do {                                                                                           \
        memcpy(f, mun, sizeof f);                                                                  \
        ck_assert_int_eq(fricreg_ctx_solve_step(ctx, MW, z0, zp, ap, W, Weff, 0.005, 1e-10, 50, 0, \
                                                f, info),                                          \
                         FRICREG_OK);                                                              \
    } while (0)
    ck_assert_ptr_null(fr_ctx_workspace(ctx));
    STEP();
    void *kept = fr_ctx_workspace(ctx);
    ck_assert_ptr_nonnull(kept);
    Weff[0] *= 1.25; /* new values, same pattern */
    STEP();
    ck_assert_ptr_eq(fr_ctx_workspace(ctx), kept);
    ck_assert_int_eq(fricreg_ctx_set_bounds(ctx, MW, mun), FRICREG_OK);
    ck_assert_ptr_eq(fr_ctx_workspace(ctx), kept);
    ck_assert_int_eq(fricreg_ctx_set_law(ctx, FRICREG_LAW_QUINN, 1e-3), FRICREG_OK);
    ck_assert_ptr_null(fr_ctx_workspace(ctx));
    STEP();
    ck_assert_ptr_nonnull(fr_ctx_workspace(ctx));
    ck_assert_int_eq(fricreg_ctx_set_coupling_dense(ctx, MW, W), FRICREG_OK);
    ck_assert_ptr_null(fr_ctx_workspace(ctx));
    STEP();
    ck_assert_ptr_nonnull(fr_ctx_workspace(ctx));
#undef STEP
    fricreg_ctx_free(ctx); /* and the solver with it: valgrind, LeakSanitizer */
}
END_TEST

/* The sparse entry's kept solver: reused (the same workspace, nothing allocated) by a call with
 * the same index arrays and new values, dropped by the dense call's setters alike; and its
 * refusals, each leaving f and info as they were: a W_eff given whole whose (0, 1) and (1, 0)
 * differ by 2e-12 sqrt(W_00 W_11) (ENOTSYM; 0.5e-12 passes), a missing diagonal entry
 * (ENOTPSD), an entry below the diagonal with FRICREG_SPARSE_UPPER and W_00 not the context's
 * (EINVAL). */
START_TEST(sparse_kept_and_refused)
{
    enum { CAP = MW * MW };
    unsigned long state = 2385;
    double W[CAP], Weff[CAP], mun[MW], z0[MW], zp[MW], ap[MW], f[MW], g[MW];
    banded_spd(MW, 3, 1.0, &state, W);
    banded_spd(MW, 1, 0.05, &state, Weff);
    for (size_t i = 0; i < MW; i++) {
        mun[i] = 0.5 + uniform(&state);
        z0[i] = zp[i] = 1e-3 * (2.0 * uniform(&state) - 1.0);
        ap[i] = uniform(&state) - 0.5;
    }
    fricreg_ctx *ctx = run_context(FRICREG_LAW_QUINN, 0, W, mun);
    int64_t wp[MW + 1], wi[CAP], ep[MW + 1], ei[CAP];
    double wv[CAP], ev[CAP];
    compressed(MW, W, 0, 0, wp, wi, wv);
    compressed(MW, Weff, 0, 0, ep, ei, ev);
    int info[2];
#define SPARSE_STEP()                                                                            \
    fricreg_ctx_solve_step_csr(ctx, MW, z0, zp, ap, 0, wp, wi, wv, ep, ei, ev, 0.005, 1e-10, 50, \
                               0, f, info)
    memcpy(f, mun, sizeof f);
    ck_assert_int_eq(SPARSE_STEP(), FRICREG_OK);
    void *kept = fr_ctx_workspace(ctx);
    ck_assert_ptr_nonnull(kept);
    for (size_t k = 0; k < (size_t)ep[MW]; k++)
        ev[k] *= 1.25; /* new values, same pattern */
    memcpy(f, mun, sizeof f);
    ck_assert_int_eq(SPARSE_STEP(), FRICREG_OK);
    ck_assert_ptr_eq(fr_ctx_workspace(ctx), kept);
    ck_assert_int_eq(info[1], 1);
    for (size_t i = 0; i < MW; i++)
        for (size_t j = 0; j < MW; j++)
            Weff[i * MW + j] *= 1.25;
    ck_assert_double_le(law_residual(ctx, MW, zp, ap, W, Weff, 0.005, f), 2e-10);
    ck_assert_int_eq(fricreg_ctx_set_law(ctx, FRICREG_LAW_QUINN, 1e-3), FRICREG_OK);
    ck_assert_ptr_null(fr_ctx_workspace(ctx));

    /* Refusals: ev[1] is W_eff(0, 1), ev[ep[1]] W_eff(1, 0) (bands of 1). */
    memcpy(g, mun, sizeof g);
    memcpy(f, g, sizeof f);
    info[0] = info[1] = -7;
    double unit = sqrt(Weff[0]) * sqrt(Weff[MW + 1]), e01 = ev[1];
    ck_assert_int_eq(ei[1], 1);
    ck_assert_int_eq(ei[ep[1]], 0);
    ev[1] = e01 + 2e-12 * unit;
    ck_assert_int_eq(SPARSE_STEP(), FRICREG_ENOTSYM);
    ev[1] = e01 + 0.5e-12 * unit;
    ck_assert_int_eq(SPARSE_STEP(), FRICREG_OK);
    memcpy(f, g, sizeof f);
    info[0] = info[1] = -7;
    ev[1] = e01;
    int64_t diag_1 = wi[wp[1] + 1]; /* W's row 1 starts at column 0: (1, 1) second */
    ck_assert_int_eq(diag_1, 1);
    wi[wp[1] + 1] = 2; /* (1, 2) twice, (1, 1) missing */
    ck_assert_int_eq(SPARSE_STEP(), FRICREG_ENOTPSD);
    wi[wp[1] + 1] = 1;
    ck_assert_int_eq(fricreg_ctx_solve_step_csr(ctx, MW, z0, zp, ap, FRICREG_SPARSE_UPPER, wp, wi,
                                                wv, ep, ei, ev, 0.005, 1e-10, 50, 0, f, info),
                     FRICREG_EINVAL);
    wv[0] *= 1.0 + 1e-9;
    ck_assert_int_eq(SPARSE_STEP(), FRICREG_EINVAL);
    ck_assert(memcmp(f, g, sizeof f) == 0);
    ck_assert_int_eq(info[0], -7);
    ck_assert_int_eq(info[1], -7);
#undef SPARSE_STEP
    fricreg_ctx_free(ctx);
}
END_TEST

/* fricreg_ctx_solve_step_matrix's own refusals (its cases' are the dense and sparse calls'),
 * f and info untouched: a format both CSR and CSC, a dense one with a sparse flag, a dense
 * one without its values, no context. */
START_TEST(matrix_form_refusals)
{
    enum { M = 2 };
    double W[M * M] = {1.0, 0.0, 0.0, 1.0}, Weff[M * M] = {0.1, 0.0, 0.0, 0.1};
    double mun[M] = {1.0, 1.0}, z0[M] = {0.0, 0.0}, ap[M] = {0.5, -0.5}, f[M] = {0.25, -0.25};
    int info[2] = {-7, -7};
    fricreg_ctx *ctx = NULL;
    ck_assert_int_eq(fricreg_ctx_create(M, &ctx), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_law(ctx, FRICREG_LAW_QUINN, 1e-3), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_coupling_dense(ctx, M, W), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_bounds(ctx, M, mun), FRICREG_OK);
#define MATRIX_STEP(FORMAT, WV, EV)                                                           \
    fricreg_ctx_solve_step_matrix(ctx, M, z0, z0, ap, FORMAT, NULL, NULL, WV, NULL, NULL, EV, \
                                  0.005, 1e-10, 50, 0, f, info)
    ck_assert_int_eq(MATRIX_STEP(FRICREG_MATRIX_CSR | FRICREG_MATRIX_CSC, W, Weff), FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_ctx_errmsg(ctx), "both CSR and CSC"));
    ck_assert_int_eq(MATRIX_STEP(FRICREG_MATRIX_DENSE | FRICREG_SPARSE_ONE_BASED, W, Weff),
                     FRICREG_EINVAL);
    ck_assert_int_eq(MATRIX_STEP(FRICREG_MATRIX_DENSE, W, NULL), FRICREG_ENULL);
    ck_assert_int_eq(MATRIX_STEP(FRICREG_MATRIX_CSR, W, Weff), FRICREG_ENULL); /* no w_ptr */
    ck_assert(f[0] == 0.25 && f[1] == -0.25 && info[0] == -7 && info[1] == -7);
    ck_assert_int_eq(fricreg_ctx_solve_step_matrix(NULL, M, z0, z0, ap, FRICREG_MATRIX_DENSE, NULL,
                                                   NULL, W, NULL, NULL, Weff, 0.005, 1e-10, 50, 0,
                                                   f, info),
                     FRICREG_ENULL);
    ck_assert_int_eq(MATRIX_STEP(FRICREG_MATRIX_DENSE, W, Weff), FRICREG_OK);
    ck_assert_int_eq(info[1], 1);
#undef MATRIX_STEP
    fricreg_ctx_free(ctx);
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("contact_step");
    TCase *tc = tcase_create("core");
    tcase_add_test(tc, law_quinn_coupled);
    tcase_add_test(tc, law_quinn_diagonal);
    tcase_add_test(tc, law_velocity_limited);
    tcase_add_test(tc, law_tanh);
    tcase_add_test(tc, equals_structure_steps);
    tcase_add_test(tc, plain_newton_cycles);
    tcase_add_test(tc, kept_solver_quinn_coupled);
    tcase_add_test(tc, kept_solver_quinn_diagonal);
    tcase_add_test(tc, kept_solver_tanh);
    tcase_add_test(tc, kept_solver_released_by_setters);
    tcase_add_test(tc, kept_sparse_quinn_coupled);
    tcase_add_test(tc, kept_sparse_tanh);
    tcase_add_test(tc, sparse_kept_and_refused);
    tcase_add_test(tc, matrix_form_refusals);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    SRunner *sr = srunner_create(suite());
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
