/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_hb_condensed.c — the condensed stability (FRICREG_HB_STABILITY_CONDENSED): the exact
 * monodromy of the model condensed onto the dofs the elements touch (Craig–Bampton, the interior
 * modes below 50 Ω) against the exact monodromy of the whole model, on one orbit.
 *
 * The model: a chain of n unit masses, springs s = (2n/π)² so that its first mode is near
 * 1 rad/s, fixed at one end; 10 Jenkins elements (kt = 1, μN = 0.05) to the ground at every
 * (n/10)-th dof; 0.1 cos Ωt on the free end; H = 3. Damping Rayleigh's, C = 0.2 ζ ω1 M +
 * 1.8 ζ/ω1 K with ζ = 0.02 (the higher a mode, the faster it decays), or one that falls with
 * frequency, C = 2 ζ ω1 (M − K/(8 s)) (positive semidefinite: K's eigenvalues are below 4 s),
 * so that the largest multiplier is that of the highest modes, which the condensed model leaves
 * out: it must count them. The reference, the exact monodromy of the whole model (monodromy.c),
 * on the same orbit. */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg_element.h"
#include "fricreg_hb.h"

#define NE 10
#define H 3
#define NC (2 * H + 1)
static const double PI = 3.14159265358979323846;

/* The chain's matrices and load; its first natural frequency (of the linear chain) in *w1. */
struct chain {
    size_t n;
    double *M, *K, *C, *J, *p, *ps, w1;
};

static struct chain chain_new(size_t n, int high_modes_least_damped)
{
    struct chain c = {.n = n};
    c.M = calloc(n * n, sizeof(double));
    c.K = calloc(n * n, sizeof(double));
    c.C = calloc(n * n, sizeof(double));
    c.J = calloc(NE * n, sizeof(double));
    c.p = calloc(n, sizeof(double));
    c.ps = calloc(n, sizeof(double));
    ck_assert(c.M && c.K && c.C && c.J && c.p && c.ps);
    double s = (2.0 * n / PI) * (2.0 * n / PI), zeta = 0.02;
    for (size_t i = 0; i < n; i++) {
        c.M[i * n + i] = 1.0;
        c.K[i * n + i] = i + 1 < n ? 2.0 * s : s;
        if (i > 0)
            c.K[i * n + i - 1] = c.K[(i - 1) * n + i] = -s;
    }
    /* the fixed-free chain's first mode: 2 sqrt(s) sin(π / (2 (2n + 1))) */
    c.w1 = 2.0 * sqrt(s) * sin(PI / (2.0 * (2.0 * n + 1.0)));
    /* a0 M − a1 K stays positive semidefinite: K's eigenvalues are below 4 s */
    double a0 = 2.0 * zeta * c.w1, a1 = -0.5 * a0 / (4.0 * s);
    if (!high_modes_least_damped)
        a0 = 0.2 * zeta * c.w1, a1 = 1.8 * zeta / c.w1;
    for (size_t i = 0; i < n * n; i++)
        c.C[i] = a0 * c.M[i] + a1 * c.K[i];
    for (size_t e = 0; e < NE; e++)
        c.J[e * n + (n / NE - 1) + e * (n - n / NE) / (NE - 1)] = 1.0;
    c.p[n - 1] = 0.1;
    return c;
}

static void chain_free(struct chain *c)
{
    free(c->M), free(c->K), free(c->C), free(c->J), free(c->p), free(c->ps);
}

static fricreg_hb *chain_hb(const struct chain *c)
{
    double params[2 * NE];
    for (size_t e = 0; e < NE; e++)
        params[2 * e] = 1.0, params[2 * e + 1] = 0.05;
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(c->n, NE, H, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, c->n, c->M), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, c->n, c->K), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_damping(hb, c->n, c->C), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_add_elements(hb, fricreg_element_lookup("jenkins"), NE, c->n, c->J,
                                             params),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_excitation(hb, c->n, c->p, c->ps), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stability(hb, 1), FRICREG_OK);
    return hb;
}

/* The largest multiplier by method at the orbit q (solved once, each method re-solving from it:
 * one Newton step that changes nothing). */
static double mu_by(fricreg_hb *hb, int method, double omega, double *q, int *stable)
{
    double mu = 0.0;
    ck_assert_int_eq(fricreg_hb_set_stability_method(hb, method), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_solve(hb, omega, NE * NC, q, q), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_point_stability(hb, FRICREG_HB_SOLUTION, stable, &mu), FRICREG_OK);
    return mu;
}

/* Ω over 0.8 to 1.3 ω1 (points first to last of 6), through the resonance where the sliders slip
 * (the fourth): the verdicts equal, the largest multipliers within tol of the whole model's. */
static void against_dense(const struct chain *c, fricreg_hb *hb, double tol, int first, int last)
{
    double q[NE * NC] = {0};
    ck_assert_int_eq(fricreg_hb_solve(hb, 0.8 * c->w1, NE * NC, NULL, q), FRICREG_OK);
    for (int i = first; i <= last; i++) {
        double omega = (0.8 + 0.1 * i) * c->w1;
        int dense_stable = 0, condensed_stable = 0;
        double dense = mu_by(hb, FRICREG_HB_STABILITY_MONODROMY, omega, q, &dense_stable);
        double condensed = mu_by(hb, FRICREG_HB_STABILITY_CONDENSED, omega, q, &condensed_stable);
        if (getenv("HB_PRINT"))
            fprintf(stderr, "Omega %.6f: whole model %.12f, condensed %.12f\n", omega, dense,
                    condensed);
        ck_assert_int_eq(condensed_stable, dense_stable);
        ck_assert_double_eq_tol(condensed, dense, tol);
    }
}

/* Rayleigh damping, 60 dofs: the interior modes below 50 Ω leave the largest multiplier within
 * 1.2e-5 of the whole model's (measured, at the resonance where the sliders slip; 1e-12 with
 * every mode kept, 4.2e-4 with those below 20-45 Ω, 2.4e-2 below 15 Ω: the segments' modes
 * between two sliders come in clusters at 19.8, 38.2, 54 ... rad/s). */
START_TEST(rayleigh_chain_equals_the_whole_model)
{
    struct chain c = chain_new(60, 0);
    fricreg_hb *hb = chain_hb(&c);
    against_dense(&c, hb, 5e-5, 0, 5);
    fricreg_hb_free(hb);
    chain_free(&c);
}
END_TEST

/* Damping that falls with frequency: the largest multiplier is the left-out modes', which the
 * condensed method adds from the structure's highest modes (1.3e-6 off at the resonance, 7e-10
 * elsewhere, measured; from the fixed-interface modes it was 4.8e-3 off, and without them it
 * reports the kept modes' smaller one). */
START_TEST(left_out_modes_keep_their_multipliers)
{
    struct chain c = chain_new(60, 1);
    fricreg_hb *hb = chain_hb(&c);
    against_dense(&c, hb, 2e-6, 0, 5);
    fricreg_hb_free(hb);
    chain_free(&c);
}
END_TEST

/* A model changed after a condensed solve is condensed anew: Rayleigh's damping replaced by the
 * falling one gives the new model's multipliers at the resonance, not the old reduction's. */
START_TEST(model_change_condenses_anew)
{
    struct chain r = chain_new(60, 0), m = chain_new(60, 1);
    fricreg_hb *hb = chain_hb(&r);
    double q[NE * NC] = {0};
    int stable = 0;
    ck_assert_int_eq(fricreg_hb_solve(hb, r.w1, NE * NC, NULL, q), FRICREG_OK);
    mu_by(hb, FRICREG_HB_STABILITY_CONDENSED, r.w1, q, &stable);
    ck_assert_int_eq(fricreg_hb_set_damping(hb, m.n, m.C), FRICREG_OK);
    against_dense(&m, hb, 2e-6, 3, 3);
    fricreg_hb_free(hb);
    chain_free(&r);
    chain_free(&m);
}
END_TEST

/* The automatic choice: condensed where the elements touch at most a quarter of 32 or more dofs
 * (10 of 60), the whole model's monodromy below 32 dofs (10 of 20); past 1024 dofs condensed
 * still (1500: until 1.9 Hill's method, which chain_hb's fricreg_hb_set_stability refused,
 * ndof (2H + 1) = 10500 over its 1024). */
START_TEST(auto_condenses_large_models_only)
{
    const size_t sizes[3] = {60, 20, 1500};
    const int want[3] = {FRICREG_HB_STABILITY_CONDENSED, FRICREG_HB_STABILITY_MONODROMY,
                         FRICREG_HB_STABILITY_CONDENSED};
    for (int k = 0; k < 3; k++) {
        int method = -1;
        struct chain c = chain_new(sizes[k], 0);
        fricreg_hb *hb = chain_hb(&c);
        ck_assert_int_eq(fricreg_hb_get_stability_method(hb, &method), FRICREG_OK);
        ck_assert_int_eq(method, want[k]);
        fricreg_hb_free(hb);
        chain_free(&c);
    }
}
END_TEST

static Suite *hb_condensed_suite(void)
{
    Suite *s = suite_create("hb_condensed");
    TCase *tc = tcase_create("core");
    tcase_add_test(tc, model_change_condenses_anew);
    tcase_add_test(tc, auto_condenses_large_models_only);
    suite_add_tcase(s, tc);
    /* the sweeps: natively and under ASan (valgrind runs the core: 200 s with them) */
    TCase *sweeps = tcase_create("sweeps");
    tcase_add_test(sweeps, rayleigh_chain_equals_the_whole_model);
    tcase_add_test(sweeps, left_out_modes_keep_their_multipliers);
    suite_add_tcase(s, sweeps);
    return s;
}

int main(void)
{
    SRunner *sr = srunner_create(hb_condensed_suite());
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
