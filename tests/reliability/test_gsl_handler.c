/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_gsl_handler.c — fricreg leaves GSL's process-wide error handler alone (docs/reliability.md).
 *
 * The program installs its own GSL handler once, which counts its calls, then runs every
 * entry-point family — laws, a context with dense W (positive definite, singular, indefinite,
 * near 1e308), the tangent and stick stiffness, a 2-D context (dense W, well and badly
 * conditioned, and anisotropic blocks; eval at rest, in the band and sliding, the tangent,
 * Stribeck friction, refused W, a singular W), simulations of each system with explicit and
 * implicit GSL steppers (and a run the step guard refuses), the AFT of a Jenkins element (its
 * polynomial roots, Brent and FFT over random, degenerate and extreme displacements), the
 * exact solver (solved, refused, near overflow), a
 * structure (indefinite and singular mass, Newmark, central difference, a GSL stepper) — and
 * after each call checks that the handler in place is still the program's
 * (gsl_set_error_handler returns the one it replaces) and that it was never called: fricreg's
 * own failures come back as status codes, not through GSL's handler. It also counts every
 * call fricreg makes to gsl_set_error_handler and gsl_set_error_handler_off: this program
 * defines both (exported with -rdynamic, so they interpose on libgsl's for libfricreg too) and
 * passes them on. The previous code swapped the handler around every call and put it back,
 * which only a second thread could see; here the count catches it in one. */
#define _GNU_SOURCE
#include <check.h>
#include <dlfcn.h>
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_eigen.h>
#include <gsl/gsl_errno.h>

#include "fricreg_aft.h"
#include "fricreg_disk_ctx.h"
#include "fricreg_exact.h"
#include "fricreg_hb.h"
#include "fricreg_sim.h"
#include "fricreg_stribeck.h"
#include "fricreg_structure.h"

static int handler_calls, handler_swaps;

typedef gsl_error_handler_t *set_handler_fn(gsl_error_handler_t *);
typedef gsl_error_handler_t *set_handler_off_fn(void);

/* libgsl's gsl_set_error_handler, for this program's own calls (not counted). */
static gsl_error_handler_t *real_set_handler(gsl_error_handler_t *handler)
{
    set_handler_fn *real = (set_handler_fn *)dlsym(RTLD_NEXT, "gsl_set_error_handler");
    ck_assert_ptr_nonnull(real);
    return real(handler);
}

/* The interposed pair: anyone else's call (fricreg's) is counted, then passed on. */
gsl_error_handler_t *gsl_set_error_handler(gsl_error_handler_t *handler)
{
    handler_swaps++;
    return real_set_handler(handler);
}

gsl_error_handler_t *gsl_set_error_handler_off(void)
{
    handler_swaps++;
    set_handler_off_fn *real = (set_handler_off_fn *)dlsym(RTLD_NEXT, "gsl_set_error_handler_off");
    ck_assert_ptr_nonnull(real);
    return real();
}

/* LAPACK's dgeev reports a QR that does not converge by INFO > 0 (Hill's eigenvalues,
 * src/floquet/eigenvalues.c): no finite balanced matrix is known to provoke it, so this program's
 * interposed copy (exported, as the pair above) returns INFO = 1 without converging when
 * nonsymm_fails is set; otherwise it passes on. */
static int nonsymm_fails;

typedef void dgeev_fn(const char *, const char *, const int *, double *, const int *, double *,
                      double *, double *, const int *, double *, const int *, double *, const int *,
                      int *, size_t, size_t);

void dgeev_(const char *jobvl, const char *jobvr, const int *n, double *a, const int *lda,
            double *wr, double *wi, double *vl, const int *ldvl, double *vr, const int *ldvr,
            double *work, const int *lwork, int *info, size_t jobvl_len, size_t jobvr_len);

void dgeev_(const char *jobvl, const char *jobvr, const int *n, double *a, const int *lda,
            double *wr, double *wi, double *vl, const int *ldvl, double *vr, const int *ldvr,
            double *work, const int *lwork, int *info, size_t jobvl_len, size_t jobvr_len)
{
    if (nonsymm_fails && *lwork != -1) {
        *info = 1;
        return;
    }
    dgeev_fn *real = (dgeev_fn *)dlsym(RTLD_NEXT, "dgeev_");
    ck_assert_ptr_nonnull(real);
    real(jobvl, jobvr, n, a, lda, wr, wi, vl, ldvl, vr, ldvr, work, lwork, info, jobvl_len,
         jobvr_len);
}

static void users_handler(const char *reason, const char *file, int line, int gsl_errno)
{
    (void)reason, (void)file, (void)line, (void)gsl_errno;
    handler_calls++;
}

/* The handler is still the program's, fricreg never set it, and never reported to it. */
#define assert_handler_intact(what)                                                       \
    do {                                                                                  \
        gsl_error_handler_t *now = real_set_handler(users_handler);                       \
        ck_assert_msg(now == users_handler, "%s: GSL's handler was replaced", what);      \
        ck_assert_msg(handler_swaps == 0, "%s: fricreg set GSL's handler %d times", what, \
                      handler_swaps);                                                     \
        ck_assert_msg(handler_calls == 0, "%s: GSL's handler was called %d times", what,  \
                      handler_calls);                                                     \
    } while (0)

static void setup(void)
{
    real_set_handler(users_handler);
    handler_calls = handler_swaps = 0;
}

/* The AFT's GSL calls (gsl_poly_complex_solve, Brent, the radix-2 FFT) over 400 random
 * displacements at H = 1 ... 7, from 1e-300 to 1e300 in scale, and degenerate ones
 * (constant, a flat inflection, a flat reversal, stuck, mun = 0). */
START_TEST(aft)
{
    fricreg_aft *a = NULL;
    ck_assert_int_eq(fricreg_aft_create(7, 64, &a), FRICREG_OK);
    double u[15], f[15], jac[225];
    unsigned long seed = 2385;
    for (int t = 0; t < 400; t++) {
        int H = 1 + t % 7;
        double scale = t % 5 == 0 ? 1e-300 : (t % 5 == 1 ? 1e300 : 1.0);
        for (int j = 0; j < 15; j++) {
            seed = seed * 6364136223846793005UL + 1442695040888963407UL;
            double r = (double)(seed >> 11) / 9007199254740992.0 * 2.0 - 1.0;
            u[j] = j <= 2 * H ? scale * r / (1 + (j + 1) / 2) : 0.0;
        }
        if (t % 11 == 0) /* u' = (1 - cos)(cos + 1/2): a flat inflection at 0 */
            for (int j = 0; j < 15; j++)
                u[j] = j == 2 ? 0.5 * scale : (j == 4 ? -0.25 * scale : 0.0);
        if (t % 13 == 0) /* u' = -(4/3) sin^3: flat reversals */
            for (int j = 0; j < 15; j++)
                u[j] = j == 1 ? scale : (j == 5 ? -scale / 9 : 0.0);
        if (t % 17 == 0)
            for (int j = 1; j < 15; j++)
                u[j] = 0.0;
        double kt = scale > 1.0 ? 1e-10 : 2.385, mun = t % 19 == 0 ? 0.0 : 0.7 * (t % 3 + 1);
        mun *= scale < 1.0 ? 1e-300 : 1.0;
        ck_assert_msg(fricreg_aft_jenkins_exact(a, kt, mun, 15, u, f, jac) == FRICREG_OK,
                      "case %d: %s", t, fricreg_aft_errmsg(a));
        assert_handler_intact("fricreg_aft_jenkins_exact");
        ck_assert_int_eq(fricreg_aft_jenkins_sampled(a, kt, mun, 15, u, f, jac), FRICREG_OK);
        assert_handler_intact("fricreg_aft_jenkins_sampled");
    }
    fricreg_aft_free(a);
}
END_TEST

/* The HB driver's GSL calls (complex LU of K and D_h, real LU of Newton's matrix): singular
 * K, a singular D_1 (undamped, at a natural frequency), a singular Newton matrix's neighbour
 * (entries near 1e300) and a continuation must all come back as statuses. */
START_TEST(harmonic_balance)
{
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(2, 1, 5, &hb), FRICREG_OK);
    const double J[2] = {1.0, -1.0}, kt[1] = {2.385}, mun[1] = {0.3}, pc[2] = {0.7, 0.0},
                 ps[2] = {0.0, 0.0}, K2[4] = {2.0, 0.0, 0.0, 2.0}, K[4] = {3.1, -1.2, -1.2, 1.2},
                 Kbig[4] = {1e300, 0.0, 0.0, 1e300};
    double q[11], x[22];
    ck_assert_int_eq(fricreg_hb_set_elements(hb, 1, 2, J, kt, mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_excitation(hb, 2, pc, ps), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_solve(hb, 1.0, 11, NULL, q), FRICREG_ESINGULAR); /* K = 0 */
    assert_handler_intact("fricreg_hb_solve, K singular");
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 2, K2), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_solve(hb, sqrt(2.0), 11, NULL, q), FRICREG_ESINGULAR);
    assert_handler_intact("fricreg_hb_solve, D_1 singular");
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 2, Kbig), FRICREG_OK);
    (void)fricreg_hb_solve(hb, 1.0, 11, NULL, q);
    assert_handler_intact("fricreg_hb_solve, K near 1e300");
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 2, K), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_rayleigh(hb, 0.02, 0.01), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_solve(hb, 1.3, 11, NULL, q), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_displacement(hb, 2, 11, x), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_continue(hb, 0.3, 2.5, 11, NULL), FRICREG_OK);
    assert_handler_intact("fricreg_hb_continue");
    fricreg_hb_free(hb);
}
END_TEST

/* The stability by method (enum fricreg_hb_stability_method): a solve and a continuation with
 * stability on; the QR's failure (interposed above) comes back as FRICREG_EINTEGRATOR with a
 * message naming the matrix (why), the kept solution's stability untouched. */
static void stability_qr_fails(int method, const char *why)
{
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(2, 1, 3, &hb), FRICREG_OK);
    const double J[2] = {1.0, -1.0}, kt[1] = {2.385}, mun[1] = {0.3}, pc[2] = {0.7, 0.0},
                 ps[2] = {0.0, 0.0}, K[4] = {3.1, -1.2, -1.2, 1.2};
    double q[7];
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 2, K), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_rayleigh(hb, 0.02, 0.01), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_elements(hb, 1, 2, J, kt, mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_excitation(hb, 2, pc, ps), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stability_method(hb, method), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stability(hb, 1), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_solve(hb, 1.3, 7, NULL, q), FRICREG_OK);
    assert_handler_intact("fricreg_hb_solve, stability on");
    int stable = -1, stable2 = -1;
    double mu = -1.0, mu2 = -1.0;
    ck_assert_int_eq(fricreg_hb_point_stability(hb, FRICREG_HB_SOLUTION, &stable, &mu), FRICREG_OK);
    ck_assert_int_eq(stable, 1); /* damped (Rayleigh): |mu| < 1 */
    ck_assert(mu < 1.0);
    nonsymm_fails = 1;
    ck_assert_int_eq(fricreg_hb_solve(hb, 1.5, 7, NULL, q), FRICREG_EINTEGRATOR);
    ck_assert_int_eq(fricreg_hb_errcode(hb), FRICREG_EINTEGRATOR);
    ck_assert_msg(strstr(fricreg_hb_errmsg(hb), why) != NULL, "%s", fricreg_hb_errmsg(hb));
    ck_assert_int_eq(fricreg_hb_point_stability(hb, FRICREG_HB_SOLUTION, &stable2, &mu2),
                     FRICREG_OK);
    ck_assert_int_eq(stable2, stable);
    ck_assert_double_eq(mu2, mu); /* the solution at 1.3 is kept */
    ck_assert_int_eq(fricreg_hb_continue(hb, 0.3, 2.5, 7, NULL), FRICREG_EINTEGRATOR);
    nonsymm_fails = 0;
    ck_assert_int_eq(fricreg_hb_continue(hb, 0.3, 2.5, 7, NULL), FRICREG_OK);
    assert_handler_intact("fricreg_hb_continue, stability on");
    fricreg_hb_free(hb);
}

/* Hill's method and the exact monodromy (stability_qr_fails), and the nonlinear modes' linear
 * mode: one whose reduced stiffness overflows (M = 1e-300, K = 1e300: L^-1 K L^-T = 1e600) is
 * FRICREG_ENONFINITE, as is (before it reaches GSL) its NaN. */
START_TEST(hill_and_modes)
{
    stability_qr_fails(FRICREG_HB_STABILITY_HILL, "Hill's matrix did not converge at Omega = 1.5");
    stability_qr_fails(FRICREG_HB_STABILITY_MONODROMY,
                       "the monodromy did not converge at Omega = 1.5");
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(1, 1, 1, &hb), FRICREG_OK);
    const double tiny = 1e-300, huge = 1e300, one = 1.0, kt1 = 2.0, mun1 = 3.0;
    ck_assert_int_eq(fricreg_hb_set_mass(hb, 1, &tiny), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 1, &huge), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_elements(hb, 1, 1, &one, &kt1, &mun1), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_nma(hb, 0, FRICREG_HB_NMA_DAMPING_MATRIX, 0.5, 10.0, 4),
                     FRICREG_ENONFINITE);
    ck_assert_ptr_nonnull(strstr(fricreg_hb_errmsg(hb), "overflows"));
    assert_handler_intact("fricreg_hb_nma, reduced stiffness overflows");
    fricreg_hb_free(hb);
}
END_TEST

START_TEST(laws)
{
    double f = 0.0;
    for (int law = FRICREG_LAW_COULOMB; law <= FRICREG_LAW_QUINN; law++) {
        ck_assert_int_eq(fricreg_law_eval(law, 0.2385, 0.7, 1.3, 0.01, &f), FRICREG_OK);
        ck_assert_int_ne(fricreg_law_eval(law, NAN, 0.7, 1.3, 0.01, &f), FRICREG_OK);
        ck_assert_int_ne(fricreg_law_eval(law, 0.0, 0.7, -1.0, 0.01, &f), FRICREG_OK);
        assert_handler_intact("fricreg_law_eval");
    }
}
END_TEST

/* A 3-contact context with W, evaluated at rest (near-stick block = all of W). */
static int ctx_with_W(const double W[9], int partition, int *eval_status)
{
    fricreg_ctx *ctx = NULL;
    ck_assert_int_eq(fricreg_ctx_create(3, &ctx), FRICREG_OK);
    const double mun[3] = {1.3, 0.7, 2.385}, zdot[3] = {0.0, 0.0, 0.0};
    const double a_free[3] = {0.5, -0.25, 3.0};
    double f[3], f_eq[3], Fz[9], Fa[9], lambda;
    fricreg_ctx_set_law(ctx, FRICREG_LAW_QUINN, 0.02);
    fricreg_ctx_set_bounds(ctx, 3, mun);
    fricreg_ctx_set_partition(ctx, partition);
    int status = fricreg_ctx_set_coupling_dense(ctx, 3, W);
    assert_handler_intact("fricreg_ctx_set_coupling_dense");
    *eval_status = fricreg_ctx_eval(ctx, 3, zdot, a_free, f, f_eq);
    assert_handler_intact("fricreg_ctx_eval");
    fricreg_ctx_tangent(ctx, 3, Fz, Fa);
    assert_handler_intact("fricreg_ctx_tangent");
    fricreg_ctx_stick_stiffness(ctx, &lambda);
    assert_handler_intact("fricreg_ctx_stick_stiffness");
    fricreg_ctx_free(ctx);
    return status;
}

START_TEST(contexts)
{
    static const double spd[9] = {2.0, 0.5, 0.1, 0.5, 1.5, 0.3, 0.1, 0.3, 1.2};
    static const double singular[9] = {1.0, 1.0, 0.0, 1.0, 1.0, 0.0, 0.0, 0.0, 2.385};
    static const double indefinite[9] = {1.0, 2.0, 0.0, 2.0, 1.0, 0.0, 0.0, 0.0, 1.0};
    static const double huge[9] = {1e307, 1e308, 0.0, 1e308, 1e307, 0.0, 0.0, 0.0, 1e308};
    static const double nonsym[9] = {2.0, 0.5, 0.1, 0.4, 1.5, 0.3, 0.1, 0.3, 1.2};
    int eval;
    for (int partition = FRICREG_PARTITION_CONSISTENT; partition <= FRICREG_PARTITION_PAPER;
         partition++) {
        ck_assert_int_eq(ctx_with_W(spd, partition, &eval), FRICREG_OK);
        ck_assert_int_eq(eval, FRICREG_OK);
        ck_assert_int_eq(ctx_with_W(singular, partition, &eval), FRICREG_OK);
        ck_assert_int_eq(eval, FRICREG_ESINGULAR); /* redundant contacts 1 and 2 */
        ck_assert_int_eq(ctx_with_W(indefinite, partition, &eval), FRICREG_ENOTPSD);
        ck_assert_int_eq(ctx_with_W(huge, partition, &eval), FRICREG_ENOTPSD);
        ck_assert_int_eq(ctx_with_W(nonsym, partition, &eval), FRICREG_ENOTSYM);
    }
}
END_TEST

/* 2-D contexts of 3 contacts (fricreg_disk_ctx.h): inputs at rest, in the band and sliding. */
#define DM 3
static const double DZDOT[3][2 * DM] = {{0.0, 0.0, 0.0, 0.0, 0.0, 0.0},
                                        {3e-3, -1e-3, 0.0, 5e-3, -2e-3, 0.0},
                                        {0.25, -0.5, 0.0, 0.0, 4e-3, 0.0}};
static const double DAFREE[3][2 * DM] = {{0.6, -0.35, 1.25, 0.4, -0.2, 0.9},
                                         {0.05, 0.02, -0.03, 0.01, 0.04, -0.06},
                                         {-0.75, 0.3, 0.2, 2.5, -1.0, 0.6}};

/* Evaluations at the three input sets, each with its tangent: every status is fricreg's. */
static void disk_evals(fricreg_disk_ctx *ctx, const char *what)
{
    double f[2 * DM], Fz[4 * DM * DM], Fa[4 * DM * DM];
    for (int p = 0; p < 3; p++) {
        int status = fricreg_disk_ctx_eval(ctx, DM, DZDOT[p], DAFREE[p], f);
        ck_assert_msg(status == FRICREG_OK, "%s, inputs %d: %s", what, p,
                      fricreg_disk_ctx_errmsg(ctx));
        assert_handler_intact("fricreg_disk_ctx_eval");
        status = fricreg_disk_ctx_tangent(ctx, DM, Fz, Fa);
        ck_assert_msg(status == FRICREG_OK, "%s, inputs %d: tangent %s", what, p,
                      fricreg_disk_ctx_errmsg(ctx));
        assert_handler_intact("fricreg_disk_ctx_tangent");
    }
}

/* Dense W: diagonally dominant (well conditioned), and 1e-4 I + u u^T (condition 3e4: the
 * Gauss-Seidel sweeps are slow and Newton's polish on the KKT conditions, GSL's QR, runs);
 * anisotropic blocks. Each with Coulomb bounds, then Stribeck friction, then force balance. */
START_TEST(disk_contexts)
{
    static const double u[2 * DM] = {1.0, 0.5, 0.8, -0.3, 0.6, 0.2};
    static const double mun[DM] = {1.3, 0.7, 2.385}, fs[DM] = {1.3, 0.9, 2.385};
    static const double fk[DM] = {0.8, 0.6, 1.5}, vs[DM] = {0.01, 0.02, 0.005};
    static const double delta[DM] = {1.0, 2.0, 0.5};
    double W[2][4 * DM * DM], w[4 * DM];
    for (int i = 0; i < 2 * DM; i++)
        for (int j = 0; j < 2 * DM; j++) {
            W[0][i * 2 * DM + j] = i == j ? 1.5 + 0.1 * i : 0.2 / (1.0 + abs(i - j));
            W[1][i * 2 * DM + j] = u[i] * u[j] + (i == j ? 1e-4 : 0.0);
        }
    for (int i = 0; i < DM; i++) {
        w[4 * i] = 1.25 + 0.1 * i;
        w[4 * i + 1] = w[4 * i + 2] = 0.3 - 0.05 * i;
        w[4 * i + 3] = 0.8 + 0.125 * i;
    }
    for (int coupling = 0; coupling < 3; coupling++) {
        fricreg_disk_ctx *ctx = NULL;
        ck_assert_int_eq(fricreg_disk_ctx_create(DM, &ctx), FRICREG_OK);
        ck_assert_int_eq(fricreg_disk_ctx_set_law(ctx, FRICREG_DISK_QUINN, 0.02), FRICREG_OK);
        ck_assert_int_eq(fricreg_disk_ctx_set_bounds(ctx, DM, mun), FRICREG_OK);
        int status = coupling < 2 ? fricreg_disk_ctx_set_coupling_dense(ctx, DM, W[coupling])
                                  : fricreg_disk_ctx_set_coupling_blocks(ctx, DM, w);
        ck_assert_msg(status == FRICREG_OK, "coupling %d: %s", coupling,
                      fricreg_disk_ctx_errmsg(ctx));
        assert_handler_intact("fricreg_disk_ctx_set_coupling");
        disk_evals(ctx, "Coulomb bounds");
        ck_assert_int_eq(fricreg_disk_ctx_set_stribeck(ctx, DM, fs, fk, vs, delta), FRICREG_OK);
        assert_handler_intact("fricreg_disk_ctx_set_stribeck");
        disk_evals(ctx, "Stribeck friction");
        ck_assert_int_eq(fricreg_disk_ctx_set_law(ctx, FRICREG_DISK_FORCE_BALANCE, 0.02),
                         FRICREG_OK);
        disk_evals(ctx, "force balance");
        fricreg_disk_ctx_free(ctx);
    }
}
END_TEST

/* W refused (indefinite, not symmetric, a block not positive definite) and a singular W
 * (two contacts with identical rows, accepted): the singular block comes back as
 * FRICREG_ESINGULAR from eval, or from the tangent where eval found a minimizer. */
START_TEST(disk_contexts_refused_and_singular)
{
    static const double indefinite[16] = {1, 0, 2, 0, 0, 1, 0, 2, 2, 0, 1, 0, 0, 2, 0, 1};
    static const double nonsym[16] = {1, 0, 0.5, 0, 0, 1, 0, 0.5, 0.4, 0, 1, 0, 0, 0.5, 0, 1};
    static const double blocks[8] = {1.0, 0.0, 0.0, 1.0, 1.0, 2.0, 2.0, 1.0};
    static const double singular[16] = {1, 0, 1, 0, 0, 1, 0, 1, 1, 0, 1, 0, 0, 1, 0, 1};
    static const double mun[2] = {1.0, 1.0}, zdot[4] = {0}, afree[4] = {0.1, 0.1, 0.1, 0.1};
    double f[4], T[16];
    fricreg_disk_ctx *ctx = NULL;
    ck_assert_int_eq(fricreg_disk_ctx_create(2, &ctx), FRICREG_OK);
    ck_assert_int_eq(fricreg_disk_ctx_set_coupling_dense(ctx, 2, indefinite), FRICREG_ENOTPSD);
    assert_handler_intact("fricreg_disk_ctx_set_coupling_dense, indefinite");
    ck_assert_int_eq(fricreg_disk_ctx_set_coupling_dense(ctx, 2, nonsym), FRICREG_ENOTSYM);
    assert_handler_intact("fricreg_disk_ctx_set_coupling_dense, not symmetric");
    ck_assert_int_eq(fricreg_disk_ctx_set_coupling_blocks(ctx, 2, blocks), FRICREG_ENOTPSD);
    assert_handler_intact("fricreg_disk_ctx_set_coupling_blocks, indefinite");
    ck_assert_int_eq(fricreg_disk_ctx_set_law(ctx, FRICREG_DISK_QUINN, 0.1), FRICREG_OK);
    ck_assert_int_eq(fricreg_disk_ctx_set_bounds(ctx, 2, mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_disk_ctx_set_coupling_dense(ctx, 2, singular), FRICREG_OK);
    int status = fricreg_disk_ctx_eval(ctx, 2, zdot, afree, f);
    assert_handler_intact("fricreg_disk_ctx_eval, singular W");
    if (status == FRICREG_OK) {
        status = fricreg_disk_ctx_tangent(ctx, 2, T, T);
        assert_handler_intact("fricreg_disk_ctx_tangent, singular W");
    }
    ck_assert_int_eq(status, FRICREG_ESINGULAR);
    fricreg_disk_ctx_free(ctx);
}
END_TEST

/* Each system with each stepper family: GSL's explicit rk4 (fixed), rkf45 (adaptive), the
 * implicit rk4imp and bsimp, the multistep msadams and msbdf; and runs that fail (a step too
 * large for the guard). */
START_TEST(simulations)
{
    static const int integrators[][2] = {{FRICREG_INT_RK4_GSL, 0}, {FRICREG_INT_RKF45, 1},
                                         {FRICREG_INT_RK4IMP, 0},  {FRICREG_INT_BSIMP, 1},
                                         {FRICREG_INT_MSADAMS, 1}, {FRICREG_INT_MSBDF, 1},
                                         {FRICREG_INT_RK4, 0}};
    const int system = FRICREG_SYSTEM_OSCILLATOR + _i;
    for (size_t k = 0; k < sizeof integrators / sizeof integrators[0]; k++) {
        fricreg_sim *sim = NULL;
        ck_assert_int_eq(fricreg_sim_create(system, &sim), FRICREG_OK);
        double rtol = integrators[k][1] ? 1e-6 : 0.0, atol = integrators[k][1] ? 1e-9 : 0.0;
        ck_assert_int_eq(fricreg_sim_set_integrator(sim, integrators[k][0], 0.005, rtol, atol),
                         FRICREG_OK);
        int status = fricreg_sim_run(sim, 2.385);
        ck_assert_msg(status == FRICREG_OK, "system %d, integrator %d: %s", system,
                      integrators[k][0], fricreg_sim_errmsg(sim));
        assert_handler_intact("fricreg_sim_run");
        fricreg_sim_free(sim);
    }
    fricreg_sim *sim = NULL;
    ck_assert_int_eq(fricreg_sim_create(system, &sim), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_integrator(sim, FRICREG_INT_RK4_GSL, 2.0, 0.0, 0.0),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_run(sim, 20.0), FRICREG_ESTEP); /* beyond the step guard */
    assert_handler_intact("fricreg_sim_run, refused step");
    fricreg_sim_free(sim);
}
END_TEST

START_TEST(exact_solver)
{
    fricreg_exact *ex = NULL;
    int status; /* checked after the handler: a report to it is what this test is for */
    ck_assert_int_eq(fricreg_exact_create(2.0, 0.5, 1.0, 0.0, 0.0, &ex), FRICREG_OK);
    status = fricreg_exact_run_cycles(ex, 20);
    assert_handler_intact("fricreg_exact_run");
    ck_assert_int_eq(status, FRICREG_OK);
    fricreg_exact_free(ex);
    ck_assert_int_eq(fricreg_exact_create(2.0, 1e-300, 1.0, 0.0, 0.0, &ex), FRICREG_OK);
    status = fricreg_exact_run_cycles(ex, 1);
    assert_handler_intact("fricreg_exact_run, refused");
    ck_assert_int_eq(status, FRICREG_EINVAL);
    fricreg_exact_free(ex);
    if (fricreg_exact_solve(1e308, 1e6, 0.0, -1e308, 1e308, 1.0, &ex) == FRICREG_OK)
        fricreg_exact_free(ex);
    assert_handler_intact("fricreg_exact_solve, near overflow");
}
END_TEST

/* Two masses on springs, one contact on the first: M, K, J. */
static fricreg_structure *structure(void)
{
    static const double M[4] = {2.0, 0.0, 0.0, 1.0}, K[4] = {30.0, -10.0, -10.0, 10.0};
    static const double J[2] = {1.0, 0.0}, mun[1] = {0.3}, p[2] = {0.0, 1.0};
    static const double load[3] = {0.0, 2.385, 0.0};
    fricreg_structure *s = NULL;
    ck_assert_int_eq(fricreg_structure_create(2, 1, &s), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_mass(s, 2, M), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_stiffness(s, 2, K), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_contacts(s, 1, 2, J), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_bounds(s, 1, mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_load(s, 2, p, 0.0, 0.5, 3, load), FRICREG_OK);
    return s;
}

START_TEST(structures)
{
    static const double indefinite[4] = {1.0, 2.0, 2.0, 1.0}, singular[4] = {1.0, 1.0, 1.0, 1.0};
    static const double negative[4] = {-1.0, 0.0, 0.0, 1.0};
    fricreg_structure *s = structure();
    /* each status checked after the handler: a report to it is what this test is for */
    int status = fricreg_structure_set_mass(s, 2, indefinite);
    assert_handler_intact("fricreg_structure_set_mass, indefinite");
    ck_assert_int_eq(status, FRICREG_ENOTPSD);
    status = fricreg_structure_set_mass(s, 2, singular);
    assert_handler_intact("fricreg_structure_set_mass, singular");
    ck_assert_int_eq(status, FRICREG_ENOTPSD);
    status = fricreg_structure_set_mass(s, 2, negative);
    assert_handler_intact("fricreg_structure_set_mass, negative");
    ck_assert_int_eq(status, FRICREG_ENOTPSD);
    ck_assert_int_eq(fricreg_structure_run(s, 0.01, 1.0), FRICREG_OK);
    assert_handler_intact("fricreg_structure_run, Newmark");
    ck_assert_int_eq(fricreg_structure_set_central_difference(s), FRICREG_OK);
    status = fricreg_structure_run(s, 0.01, 2.0);
    ck_assert_msg(status == FRICREG_OK || status == FRICREG_ESTEP, "%s",
                  fricreg_structure_errmsg(s));
    assert_handler_intact("fricreg_structure_run, central difference");
    ck_assert_int_eq(fricreg_structure_run_ode(s, FRICREG_INT_MSBDF, 0.01, 1e-6, 1e-9, 3.0),
                     FRICREG_OK);
    assert_handler_intact("fricreg_structure_run_ode, msbdf");
    ck_assert_int_eq(fricreg_structure_run_ode(s, FRICREG_INT_RK4IMP, 0.01, 0.0, 0.0, 4.0),
                     FRICREG_OK);
    assert_handler_intact("fricreg_structure_run_ode, rk4imp");
    fricreg_structure_free(s);
}
END_TEST

/* Two dampers on one storey (equal rows of J, so W = J M^-1 J^T is singular) under the laws
 * that do not read f_eq, which the context takes: Newton's stick predictor met the singular
 * W_SS, and GSL's Cholesky reported it to the handler (the default one aborted the step). It
 * now gives no guess, and the steps run. */
START_TEST(structure_redundant_contacts)
{
    static const double one = 1.0, J[2] = {1.0, 1.0}, mun[2] = {0.3, 0.2}, u0 = 1.0, v0 = 0.0;
    const int laws[] = {FRICREG_LAW_VELOCITY_LIMITED, FRICREG_LAW_TANH};
    for (size_t k = 0; k < sizeof laws / sizeof laws[0]; k++) {
        fricreg_structure *s = NULL;
        ck_assert_int_eq(fricreg_structure_create(1, 2, &s), FRICREG_OK);
        ck_assert_int_eq(fricreg_structure_set_mass(s, 1, &one), FRICREG_OK);
        ck_assert_int_eq(fricreg_structure_set_stiffness(s, 1, &one), FRICREG_OK);
        ck_assert_int_eq(fricreg_structure_set_contacts(s, 2, 1, J), FRICREG_OK);
        ck_assert_int_eq(fricreg_structure_set_bounds(s, 2, mun), FRICREG_OK);
        ck_assert_int_eq(fricreg_structure_set_law(s, laws[k], 0.01), FRICREG_OK);
        ck_assert_int_eq(fricreg_structure_set_initial(s, 1, &u0, &v0), FRICREG_OK);
        int status = fricreg_structure_run(s, 0.01, 2.0);
        ck_assert_msg(status == FRICREG_OK, "%s", fricreg_structure_errmsg(s));
        assert_handler_intact("fricreg_structure_run, two equal rows of J");
        fricreg_structure_free(s);
    }
}
END_TEST

/* GSL's steppers that iterate to the error level atol + rtol |y| per component (rk1imp, rk2imp,
 * rk4imp, msadams, msbdf) report a level of 0 to GSL's handler, whose default aborted (fuzz
 * finding, fuzz_structure: run_ode with rk2imp, rtol > 0, atol = 0, from rest): every start at
 * rest has a zero component, and the structure's energies and the simulations' dissipation start
 * at 0 anyway. Simulations and structures now refuse atol = 0 with them (FRICREG_EINVAL). */
START_TEST(iterating_steppers_without_atol)
{
    const int iterating[] = {FRICREG_INT_RK1IMP, FRICREG_INT_RK2IMP, FRICREG_INT_RK4IMP,
                             FRICREG_INT_MSADAMS, FRICREG_INT_MSBDF};
    for (size_t k = 0; k < sizeof iterating / sizeof iterating[0]; k++) {
        fricreg_sim *sim = NULL;
        ck_assert_int_eq(fricreg_sim_create(FRICREG_SYSTEM_OSCILLATOR, &sim), FRICREG_OK);
        ck_assert_int_eq(fricreg_sim_set_integrator(sim, iterating[k], 0.01, 1e-6, 0.0),
                         FRICREG_EINVAL);
        ck_assert_int_eq(fricreg_sim_run(sim, 1.0), FRICREG_OK); /* the default stepper */
        assert_handler_intact("fricreg_sim_set_integrator, atol = 0");
        fricreg_sim_free(sim);
        fricreg_structure *s = structure();
        ck_assert_int_eq(fricreg_structure_run_ode(s, iterating[k], 0.01, 1e-6, 0.0, 1.0),
                         FRICREG_EINVAL);
        assert_handler_intact("fricreg_structure_run_ode, atol = 0");
        fricreg_structure_free(s);
    }
    /* an explicit stepper is not refused: its step control divides by the error level instead
     * of reporting a zero one (this run meets one it cannot satisfy at t = 0.34 and fails,
     * FRICREG_EINTEGRATOR), and GSL's handler is not reached */
    fricreg_structure *s = structure();
    ck_assert_int_eq(fricreg_structure_run_ode(s, FRICREG_INT_RKF45, 0.01, 1e-6, 0.0, 1.0),
                     FRICREG_EINTEGRATOR);
    assert_handler_intact("fricreg_structure_run_ode, rkf45, atol = 0");
    fricreg_structure_free(s);
}
END_TEST

/* A stable structure whose damping dwarfs 1 (fuzz finding, fuzz_structure): C = 1e300
 * [[1, 1], [1, 1]] (positive semidefinite), M = I, rk1imp at dt = 1. Its Newton matrix
 * I + h C rounds to 1e300 [[1, 1], [1, 1]], exactly singular, and gsl_linalg_LU_solve reported
 * it to the handler (the default aborted). run_ode now refuses GSL's LU-based steppers where the
 * step times the stiffest rate exceeds 1e12 (FRICREG_EINVAL); at dt = 1e-3 with C = 1e3 [[1, 1],
 * [1, 1]] (a rate of 2e3 and more from the contact) it runs. */
START_TEST(lu_steppers_on_a_stiff_structure)
{
    const double J[2] = {1.0, 0.0}, u0[2] = {0.01, 0.0}, v0[2] = {0.0, 0.0};
    double C[4] = {1e300, 1e300, 1e300, 1e300};
    const int lu[] = {FRICREG_INT_RK1IMP, FRICREG_INT_RK2IMP, FRICREG_INT_RK4IMP, FRICREG_INT_BSIMP,
                      FRICREG_INT_MSBDF};
    for (size_t k = 0; k < sizeof lu / sizeof lu[0]; k++) {
        fricreg_structure *s = NULL;
        ck_assert_int_eq(fricreg_structure_create(2, 1, &s), FRICREG_OK);
        ck_assert_int_eq(fricreg_structure_set_contacts(s, 1, 2, J), FRICREG_OK);
        ck_assert_int_eq(fricreg_structure_set_damping(s, 2, C), FRICREG_OK);
        ck_assert_int_eq(fricreg_structure_set_initial(s, 2, u0, v0), FRICREG_OK);
        ck_assert_int_eq(fricreg_structure_run_ode(s, lu[k], 1.0, 0.0, 0.0, 3.0), FRICREG_EINVAL);
        assert_handler_intact("fricreg_structure_run_ode, I + h C singular in rounding");
        fricreg_structure_free(s);
    }
    C[0] = C[1] = C[2] = C[3] = 1e3;
    fricreg_structure *s = NULL;
    ck_assert_int_eq(fricreg_structure_create(2, 1, &s), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_contacts(s, 1, 2, J), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_damping(s, 2, C), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_initial(s, 2, u0, v0), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_run_ode(s, FRICREG_INT_RK1IMP, 1e-3, 0.0, 0.0, 0.1),
                     FRICREG_OK);
    assert_handler_intact("fricreg_structure_run_ode, rk1imp, C = 1e3");
    fricreg_structure_free(s);
}
END_TEST

/* A load of -DBL_MAX on a free mass (fuzz finding, fuzz_structure): bsimp at dt = 3.6e6 from
 * rest. The input work's row of the Jacobian holds the load (W_in' = v.p~), h times it is -Inf,
 * GSL's LU pivoted on it and met an exactly zero pivot further on, reported to the handler.
 * The structure now stops an implicit stepper whose Jacobian times the step has an entry beyond
 * 1e100 (FRICREG_EINTEGRATOR), before GSL factors it. */
START_TEST(lu_steppers_under_an_extreme_load)
{
    const double J[2] = {1.0, 0.0}, p[2] = {-DBL_MAX, -0.0122};
    fricreg_structure *s = NULL;
    ck_assert_int_eq(fricreg_structure_create(2, 1, &s), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_contacts(s, 1, 2, J), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_load(s, 2, p, 0.0, 0.0, 0, NULL), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_run_ode(s, FRICREG_INT_BSIMP, 3646850.5859375, 0.0, 0.0,
                                               3646850.5859375),
                     FRICREG_EINTEGRATOR);
    assert_handler_intact("fricreg_structure_run_ode, bsimp, load -DBL_MAX");
    fricreg_structure_free(s);
}
END_TEST

static Suite *handler_suite(void)
{
    Suite *s = suite_create("gsl_handler");
    TCase *tc = tcase_create("families");
    tcase_add_checked_fixture(tc, setup, NULL);
    tcase_set_timeout(tc, 120.0);
    tcase_add_test(tc, laws);
    tcase_add_test(tc, aft);
    tcase_add_test(tc, harmonic_balance);
    tcase_add_test(tc, hill_and_modes);
    tcase_add_test(tc, contexts);
    tcase_add_test(tc, disk_contexts);
    tcase_add_test(tc, disk_contexts_refused_and_singular);
    tcase_add_loop_test(tc, simulations, 0, 3);
    tcase_add_test(tc, exact_solver);
    tcase_add_test(tc, structures);
    tcase_add_test(tc, structure_redundant_contacts);
    tcase_add_test(tc, iterating_steppers_without_atol);
    tcase_add_test(tc, lu_steppers_on_a_stiff_structure);
    tcase_add_test(tc, lu_steppers_under_an_extreme_load);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    SRunner *sr = srunner_create(handler_suite());
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
