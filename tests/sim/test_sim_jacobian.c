/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_sim_jacobian.c — white box: the analytic Jacobian of the drivers' ODE
 * (src/sim/sim_jacobian.c) against central differences of its right-hand side.
 *
 * Law (4) is piecewise linear in (zdot, a_free) and each system linear in (x, v, f), so on one
 * piece the right-hand side is linear in x and v, except D' = -w zdot . f, which is quadratic:
 * central differences are exact there up to rounding, about 1e-16 |rhs| / h = 1e-10 for
 * h = 1e-6. The tanh law is smooth: its central difference errs by h^2 f'''/6, below 1e-8
 * relative for eps = 0.0713. A column counts as away from kinks when the analytic Jacobians'
 * rows of x' and v' (constant on a piece) at y - h e_j, y and y + h e_j agree, i.e. the
 * difference stencil stays on one piece; the
 * test demands that most columns qualify, so it cannot pass by skipping them all.
 *
 * Links the static library and includes src/ headers: the right-hand side and the Jacobian
 * are internal (sim_internal.h). */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>

#include "sim/sim_internal.h"

#define STEP 1e-6        /* central-difference step, times max(|y_j|, 1) */
#define TOL 1e-6         /* relative to the Jacobian's largest entry */
#define SAME_PIECE 1e-12 /* Jacobians this close (relative) lie on one piece */
#define SAMPLES 40

/* A reproducible uniform in [lo, hi): 64-bit LCG (Knuth's MMIX constants). */
static double uniform(unsigned long long *s, double lo, double hi)
{
    *s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
    return lo + (hi - lo) * (double)(*s >> 11) * (1.0 / 9007199254740992.0);
}

struct case_ {
    int system, law, partition;
    double eps;
    int param;
    double value; /* one parameter off the paper's value (param 0: none) */
    int smooth;   /* tanh: no pieces, every stencil is checked */
};

struct scratch {
    size_t dim;
    double *J, *dJ, *Jp, *Jm, *dtp, *dtm, *fp, *fm, *y1, *fd, *fdt;
};

static void scratch_alloc(struct scratch *w, size_t dim)
{
    w->dim = dim;
    w->J = malloc(dim * dim * sizeof(double));
    w->Jp = malloc(dim * dim * sizeof(double));
    w->Jm = malloc(dim * dim * sizeof(double));
    w->fd = malloc(dim * dim * sizeof(double));
    w->dJ = malloc(dim * sizeof(double));
    w->dtp = malloc(dim * sizeof(double));
    w->dtm = malloc(dim * sizeof(double));
    w->fp = malloc(dim * sizeof(double));
    w->fm = malloc(dim * sizeof(double));
    w->y1 = malloc(dim * sizeof(double));
    w->fdt = malloc(dim * sizeof(double));
    ck_assert(w->J && w->Jp && w->Jm && w->fd && w->dJ && w->dtp && w->dtm && w->fp && w->fm &&
              w->y1 && w->fdt);
}

static void scratch_free(struct scratch *w)
{
    free(w->J), free(w->Jp), free(w->Jm), free(w->fd), free(w->dJ), free(w->dtp);
    free(w->dtm), free(w->fp), free(w->fm), free(w->y1), free(w->fdt);
}

/* A simulation of `c`, run for one step so that its context and buffers exist. */
static fricreg_sim *make_sim(const struct case_ *c)
{
    fricreg_sim *sim = NULL;
    ck_assert_int_eq(fricreg_sim_create(c->system, &sim), FRICREG_OK);
    if (c->param)
        ck_assert_int_eq(fricreg_sim_set_param(sim, c->param, c->value), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_law(sim, c->law, c->eps), FRICREG_OK);
    if (c->system == FRICREG_SYSTEM_TWOBLOCK)
        ck_assert_int_eq(fricreg_sim_set_partition(sim, c->partition), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_integrator(sim, FRICREG_INT_RK4, 1e-3, 0.0, 0.0), FRICREG_OK);
    int status = fricreg_sim_run(sim, 1e-3);
    ck_assert_msg(status == FRICREG_OK, "%s", fricreg_sim_errmsg(sim));
    return sim;
}

/* A random state whose contact velocities lie within 1.5 eps of zero for about two thirds of
 * the contacts (the near-stick zone and its edges), the rest sliding. */
static void random_state(fricreg_sim *sim, double t, unsigned long long *seed, double y[])
{
    size_t n = sim->ndof, m = sim->m;
    double zdot_target[64], zdot_buf[64], a_free[64], zero[64] = {0};
    ck_assert_uint_le(m, 64);
    for (size_t i = 0; i < n; i++)
        y[i] = uniform(seed, -0.8, 0.8) / (double)n;
    for (size_t i = 0; i < m; i++)
        zdot_target[i] = uniform(seed, 0.0, 1.0) < 0.67 ? uniform(seed, -1.5, 1.5) * sim->eps
                                                        : uniform(seed, -0.9, 0.9);
    /* zdot = Zv v + zdot_0(t): zdot_0 from v = 0, then Zv v = target - zdot_0 solved by the
     * systems' own structure (Zv = 1, I, or unit lower bidiagonal for the two blocks). */
    const double *zdot0 = sim->sys.type->contacts(&sim->sys, t, y, zero, zdot_buf, a_free);
    double *v = y + n;
    for (size_t i = 0; i < n; i++)
        v[i] = zdot_target[i] - zdot0[i] +
               (sim->sys.type->id == FRICREG_SYSTEM_TWOBLOCK && i > 0 ? v[i - 1] : 0.0);
    y[2 * n] = uniform(seed, -3.0, 3.0);
}

static double max_abs(size_t len, const double a[])
{
    double s = 0.0;
    for (size_t k = 0; k < len; k++)
        s = fmax(s, fabs(a[k]));
    return s;
}

static int same_matrix(size_t len, const double a[], const double b[], double scale)
{
    for (size_t k = 0; k < len; k++)
        if (fabs(a[k] - b[k]) > SAME_PIECE * scale)
            return 0;
    return 1;
}

static void jacobian_at(fricreg_sim *sim, double t, const double y[], double J[], double dt[])
{
    ck_assert_int_eq(fr_sim_jacobian(t, y, J, dt, sim), GSL_SUCCESS);
}

static void rhs_at(fricreg_sim *sim, double t, const double y[], double f[])
{
    ck_assert_int_eq(fr_sim_rhs(t, y, f, sim), GSL_SUCCESS);
}

struct tally {
    int columns, checked, stick_columns; /* stick: a contact in the band, a nonzero tangent */
    double worst, worst_fd;
};

/* Column j (j = dim: the t column) of the analytic Jacobian against central differences,
 * and against the forward-difference Jacobian kept in the library. */
static void check_column(fricreg_sim *sim, struct scratch *w, double t, const double y[], size_t j,
                         double scale, int smooth, struct tally *tl)
{
    size_t dim = w->dim;
    int is_t = j == dim;
    double h = STEP * fmax(fabs(is_t ? t : y[j]), 1.0);
    memcpy(w->y1, y, dim * sizeof *y);
    tl->columns++;
    if (!is_t)
        w->y1[j] = y[j] + h;
    jacobian_at(sim, is_t ? t + h : t, w->y1, w->Jp, w->dtp);
    rhs_at(sim, is_t ? t + h : t, w->y1, w->fp);
    if (!is_t)
        w->y1[j] = y[j] - h;
    jacobian_at(sim, is_t ? t - h : t, w->y1, w->Jm, w->dtm);
    rhs_at(sim, is_t ? t - h : t, w->y1, w->fm);
    /* The rows of x' and v' are constant on a piece; D's row is linear in y (D' quadratic). */
    size_t piecewise = (dim - 1) * dim;
    if (!smooth && (!same_matrix(piecewise, w->Jp, w->J, scale) ||
                    !same_matrix(piecewise, w->Jm, w->J, scale)))
        return; /* a kink within the stencil */
    tl->checked++;
    for (size_t i = 0; i < dim; i++) {
        double analytic = is_t ? w->dJ[i] : w->J[i * dim + j];
        double central = (w->fp[i] - w->fm[i]) / (2.0 * h);
        double forward = is_t ? w->fdt[i] : w->fd[i * dim + j];
        tl->worst = fmax(tl->worst, fabs(central - analytic) / scale);
        tl->worst_fd = fmax(tl->worst_fd, fabs(forward - analytic) / scale);
        ck_assert_msg(fabs(central - analytic) <= TOL * scale,
                      "d rhs_%zu / d %s%zu: analytic %.10g, central %.10g (scale %g)", i,
                      is_t ? "t" : "y_", j, analytic, central, scale);
    }
}

/* Whether some contact at y sits in the band with a nonzero tangent. */
static int in_stick_zone(const fricreg_sim *sim)
{
    for (size_t i = 0; i < sim->m; i++)
        if (fabs(sim->zdot[i]) < sim->eps)
            return 1;
    return 0;
}

static void check_case(const struct case_ *c, unsigned long long seed)
{
    fricreg_sim *sim = make_sim(c);
    size_t dim = 2 * sim->ndof + 1;
    struct scratch w;
    struct tally tl = {0, 0, 0, 0.0, 0.0};
    scratch_alloc(&w, dim);
    double y[2 * 64 + 1];
    for (int s = 0; s < SAMPLES; s++) {
        double t = uniform(&seed, 0.0, 40.0);
        random_state(sim, t, &seed, y);
        ck_assert_int_eq(fr_sim_jacobian_fd(t, y, w.fd, w.fdt, sim), GSL_SUCCESS);
        jacobian_at(sim, t, y, w.J, w.dJ);
        int stick = in_stick_zone(sim);
        double scale = fmax(max_abs(dim * dim, w.J), max_abs(dim, w.dJ));
        for (size_t j = 0; j <= dim; j++) {
            int before = tl.checked;
            check_column(sim, &w, t, y, j, scale, c->smooth, &tl);
            tl.stick_columns += stick && tl.checked > before;
        }
    }
    printf("system %d law %d partition %d: %d of %d columns off kinks (%d in the stick zone), "
           "worst |central - analytic| %.2e, |forward - analytic| %.2e (of max |J|)\n",
           c->system, c->law, c->partition, tl.checked, tl.columns, tl.stick_columns, tl.worst,
           tl.worst_fd);
    fflush(stdout);
    /* Most stencils miss every kink (a kink is a set of measure zero; the stencil 2h wide),
     * and many sample the band, where the slope is 2 mun/eps. */
    ck_assert_int_ge(tl.checked, (int)(0.8 * tl.columns));
    ck_assert_int_ge(tl.stick_columns, tl.columns / 4);
    /* Forward differences, step 1.5e-8: wrong by about that step times the curvature of D'. */
    ck_assert_double_le(tl.worst_fd, 1e-5);
    scratch_free(&w);
    fricreg_sim_free(sim);
}

START_TEST(oscillator_matches_central_differences)
{
    struct case_ c = {
        FRICREG_SYSTEM_OSCILLATOR, FRICREG_LAW_QUINN, 0, 0.0713, FRICREG_PARAM_A, 2.385};
    check_case(&c, 11);
}
END_TEST

START_TEST(chain_matches_central_differences)
{
    struct case_ c = {FRICREG_SYSTEM_CHAIN, FRICREG_LAW_QUINN, 0, 0.0713, FRICREG_PARAM_N, 7.0};
    check_case(&c, 12);
}
END_TEST

START_TEST(twoblock_consistent_matches_central_differences)
{
    struct case_ c = {FRICREG_SYSTEM_TWOBLOCK,
                      FRICREG_LAW_QUINN,
                      FRICREG_PARTITION_CONSISTENT,
                      0.0713,
                      FRICREG_PARAM_K,
                      2.385};
    check_case(&c, 13);
}
END_TEST

START_TEST(twoblock_paper_matches_central_differences)
{
    struct case_ c = {FRICREG_SYSTEM_TWOBLOCK, FRICREG_LAW_QUINN,
                      FRICREG_PARTITION_PAPER, 0.0713,
                      FRICREG_PARAM_K,         2.385};
    check_case(&c, 14);
}
END_TEST

/* The smooth law and the velocity-limited one: the tangent's slip slopes. */
START_TEST(twoblock_other_laws_match_central_differences)
{
    struct case_ tanh_law = {FRICREG_SYSTEM_TWOBLOCK,
                             FRICREG_LAW_TANH,
                             FRICREG_PARTITION_CONSISTENT,
                             0.0713,
                             FRICREG_PARAM_BELT_AMP,
                             1.37,
                             1};
    struct case_ limited = {FRICREG_SYSTEM_TWOBLOCK,      FRICREG_LAW_VELOCITY_LIMITED,
                            FRICREG_PARTITION_CONSISTENT, 0.0713,
                            FRICREG_PARAM_BELT_AMP,       1.37};
    check_case(&tanh_law, 15);
    check_case(&limited, 16);
}
END_TEST

/* The chain's fused pass (src/sim/systems/chain.c) against the plain loops it replaced: x' = v and
 * u'' = a_free + f to the bit, the power v . f summed in 8 partial sums within the rounding
 * bound of both orders, 2 n u sum |v_i f_i| (u = 2^-53), at sizes with and without a tail.
 * contacts() passes v itself as zdot, with no copy. */
START_TEST(chain_fused_pass_matches_plain_loops)
{
    const size_t sizes[] = {13, 32, 1003};
    unsigned long long seed = 20261121;
    for (size_t c = 0; c < sizeof sizes / sizeof sizes[0]; c++) {
        size_t n = sizes[c], slot = 0;
        struct fr_system sys;
        fr_system_init(&sys, &fr_chain_type);
        ck_assert_ptr_nonnull(fr_system_param(&fr_chain_type, FRICREG_PARAM_N, &slot));
        sys.p[slot] = (double)n;
        double u[1003], v[1003], a_free[1003], f[1003], zbuf[1003], dydt[2 * 1003];
        for (size_t i = 0; i < n; i++) {
            u[i] = uniform(&seed, -0.37, 0.41);
            v[i] = uniform(&seed, -2.385, 2.385);
            f[i] = uniform(&seed, -1.0, 1.0);
        }
        const double *zdot = fr_chain_type.contacts(&sys, 3.17, u, v, zbuf, a_free);
        ck_assert_ptr_eq(zdot, v);
        double power = fr_chain_type.bodies(&sys, 3.17, u, v, zdot, a_free, f, dydt);
        double plain = 0.0, magnitude = 0.0;
        for (size_t i = 0; i < n; i++) {
            ck_assert(dydt[i] == v[i]);
            ck_assert(dydt[n + i] == a_free[i] + f[i]);
            plain += v[i] * f[i];
            magnitude += fabs(v[i] * f[i]);
        }
        ck_assert_double_eq_tol(power, plain, 2.0 * (double)n * 0x1p-53 * magnitude);
    }
}
END_TEST

static Suite *sim_jacobian_suite(void)
{
    Suite *s = suite_create("sim_jacobian");
    TCase *tc = tcase_create("central_differences");
    tcase_add_test(tc, oscillator_matches_central_differences);
    tcase_add_test(tc, chain_matches_central_differences);
    tcase_add_test(tc, twoblock_consistent_matches_central_differences);
    tcase_add_test(tc, twoblock_paper_matches_central_differences);
    tcase_add_test(tc, twoblock_other_laws_match_central_differences);
    tcase_add_test(tc, chain_fused_pass_matches_plain_loops);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    SRunner *sr = srunner_create(sim_jacobian_suite());
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
