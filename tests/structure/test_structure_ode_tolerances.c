/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_structure_ode_tolerances.c — fricreg_structure_run_ode's absolute tolerances per
 * component: the rule from eps (FRICREG_ATOL_FROM_EPS) holds the dissipation of a stick-slip
 * run where one atol = rtol does not, its values are the closed form from eps and J, the set
 * ones replace run_ode's atol, and the error estimate's companion runs them at / 16.
 *
 * The structure: a 3-dof chain (M = I, springs 1 from the ground to dof 0, dof 0 to 1, 1 to 2;
 * Rayleigh C = 0.02 K), contact 0 between dof 0 and the ground (J row (1, 0, 0), mun 0.5),
 * contact 1 between dofs 1 and 2 (J row (0, 1, -1), mun 0.3), law (4) at eps = 1e-5, a load
 * sin(0.8 t) on dof 2 over 4 periods: both contacts stick and slip. Measured (D_i's error
 * relative to the reference, msbdf at rtol 1e-11 under the rule, which rk8pd at rtol 1e-11
 * under the rule confirms to 2.5e-8 and 2e-9):
 *
 *   integrator rtol   atol = rtol (D_0, D_1)   FRICREG_ATOL_FROM_EPS (D_0, D_1)
 *   msbdf      1e-4   +8.3e-4, +2.5            +1.0e-6, +1.1e-5
 *   msbdf      1e-6   +5.7e-3, +1.7e-1         +1.0e-6, +1.1e-5
 *   msbdf      1e-8   -8.7e-6, +8.7e-5         -2.9e-8, +1.1e-5
 *   rkf45      1e-4   +2.5e-4, -5.0e-3         +4.4e-8, -2.2e-9
 *   rkf45      1e-6   -1.1e-5, -1.3e-4         +4.4e-8, -2.2e-9
 *   rkf45      1e-8   +1.7e-8, +5.9e-8         +6.2e-8, +5.7e-8
 *
 * The test asserts the rtol = 1e-6 row with margins: the rule within 5e-5 (msbdf) and 1e-6
 * (rkf45), atol = rtol beyond 1e-3 (msbdf) and 5e-6 (rkf45) on the worse contact. */
#include <check.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg_structure.h"
#include "structure/structure_internal.h" /* the companion and its tolerance scale */

#define NDOF 3
#define NC 2
#define DIM (2 * NDOF + 2 + NC)
#define EPS 1e-5
#define OMEGA 0.8
#define PI 3.14159265358979323846
#define T_END (4.0 * 2.0 * PI / OMEGA)
#define DT_REC 0.005

/* The chain with lengths in units of 1/L m (L = 1000: mm): u, v, eps and atol times L; M,
 * C and K over L (forces in N); J, mun and rtol the same. */
static fricreg_structure *chain_in(double L)
{
    fricreg_structure *s = NULL;
    double M[NDOF * NDOF] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    double K[NDOF * NDOF] = {2, -1, 0, -1, 2, -1, 0, -1, 1};
    for (size_t k = 0; k < NDOF * NDOF; k++)
        M[k] /= L, K[k] /= L;
    double J[NC * NDOF] = {1, 0, 0, 0, 1, -1}, mun[NC] = {0.5, 0.3}, p[NDOF] = {0, 0, 1};
    size_t nrec = (size_t)(T_END / DT_REC) + 3;
    double *g = malloc(nrec * sizeof *g);
    ck_assert_ptr_nonnull(g);
    for (size_t k = 0; k < nrec; k++)
        g[k] = sin(OMEGA * (double)k * DT_REC);
    ck_assert_int_eq(fricreg_structure_create(NDOF, NC, &s), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_mass(s, NDOF, M), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_stiffness(s, NDOF, K), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_rayleigh(s, 0.0, 0.02), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_contacts(s, NC, NDOF, J), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_bounds(s, NC, mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_law(s, FRICREG_LAW_QUINN, L * EPS), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_load(s, NDOF, p, 0.0, DT_REC, nrec, g), FRICREG_OK);
    free(g);
    return s;
}

static fricreg_structure *chain(void)
{
    return chain_in(1.0);
}

/* Each contact's dissipation over the run by run_ode. */
static void dissipation(int integrator, double rtol, double atol, double D[NC])
{
    fricreg_structure *s = chain();
    ck_assert_int_eq(fricreg_structure_run_ode(s, integrator, 1e-3, rtol, atol, T_END), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_get_dissipation(s, NC, D), FRICREG_OK);
    fricreg_structure_free(s);
}

static double worse_error(const double D[NC], const double ref[NC])
{
    return fmax(fabs(D[0] - ref[0]) / ref[0], fabs(D[1] - ref[1]) / ref[1]);
}

START_TEST(test_rule_holds_the_dissipation)
{
    double ref[NC], D[NC];
    dissipation(FRICREG_INT_MSBDF, 1e-11, FRICREG_ATOL_FROM_EPS, ref);
    ck_assert(ref[0] > 1.0 && ref[1] > 1.0); /* both contacts slip (5.549, 2.375) */

    dissipation(FRICREG_INT_MSBDF, 1e-6, FRICREG_ATOL_FROM_EPS, D);
    ck_assert_double_lt(worse_error(D, ref), 5e-5); /* measured 1.1e-5 */
    dissipation(FRICREG_INT_MSBDF, 1e-6, 1e-6, D);
    ck_assert_double_gt(worse_error(D, ref), 1e-3); /* measured 1.7e-1 */

    dissipation(FRICREG_INT_RKF45, 1e-6, FRICREG_ATOL_FROM_EPS, D);
    ck_assert_double_lt(worse_error(D, ref), 1e-6); /* measured 4.4e-8 */
    dissipation(FRICREG_INT_RKF45, 1e-6, 1e-6, D);
    ck_assert_double_gt(worse_error(D, ref), 5e-6); /* measured 1.3e-4 */
}
END_TEST

/* The closed form: dof 0 is read by contact 0 alone (sum |J_0k| = 1): 1e-3 eps; dofs 1 and 2
 * by contact 1 (sum |J_1k| = 2): 1e-3 eps / 2; every other component rtol; each velocity
 * level capped at rtol. */
static void rule(double rtol, double atol[DIM])
{
    for (size_t k = 0; k < DIM; k++)
        atol[k] = rtol;
    atol[NDOF] = fmin(1e-3 * EPS, rtol);
    atol[NDOF + 1] = atol[NDOF + 2] = fmin(1e-3 * EPS / 2.0, rtol);
}

START_TEST(test_rule_values)
{
    fricreg_structure *s = chain();
    double got[DIM], want[DIM];
    ck_assert_int_eq(fricreg_structure_get_ode_abs_tolerances(s, DIM, got), FRICREG_OK);
    for (size_t k = 0; k < DIM; k++)
        ck_assert(got[k] == 0.0);        /* no adaptive call yet */
    const double rtols[] = {1e-6, 6e-9}; /* 6e-9: the cap on dof 0 only */
    for (size_t r = 0; r < 2; r++) {
        ck_assert_int_eq(fricreg_structure_run_ode(s, FRICREG_INT_RKF45, 1e-3, rtols[r],
                                                   FRICREG_ATOL_FROM_EPS, 0.1 * (double)(r + 1)),
                         FRICREG_OK);
        ck_assert_int_eq(fricreg_structure_get_ode_abs_tolerances(s, DIM, got), FRICREG_OK);
        rule(rtols[r], want);
        for (size_t k = 0; k < DIM; k++)
            ck_assert_double_eq(got[k], want[k]);
    }
    ck_assert_double_eq(got[NDOF], 6e-9);
    ck_assert_double_eq(got[NDOF + 1], 5e-9);
    /* a scalar atol: in every component */
    ck_assert_int_eq(fricreg_structure_run_ode(s, FRICREG_INT_RKF45, 1e-3, 1e-6, 2e-7, 0.3),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_get_ode_abs_tolerances(s, DIM, got), FRICREG_OK);
    for (size_t k = 0; k < DIM; k++)
        ck_assert_double_eq(got[k], 2e-7);
    /* the rule follows eps */
    ck_assert_int_eq(fricreg_structure_run_ode(s, FRICREG_INT_RKF45, 1e-3, 1e-6,
                                               FRICREG_ATOL_FROM_EPS, 0.4),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_law(s, FRICREG_LAW_QUINN, 2.0 * EPS), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_get_ode_abs_tolerances(s, DIM, got), FRICREG_OK);
    ck_assert_double_eq(got[NDOF], 2e-3 * EPS);
    ck_assert_double_eq(got[NDOF + 2], 1e-3 * EPS);
    ck_assert_int_eq(fricreg_structure_get_ode_abs_tolerances(s, DIM - 1, got), FRICREG_ESIZE);
    fricreg_structure_free(s);
}
END_TEST

/* Set tolerances replace run_ode's atol: the rule's own levels set by hand hold the
 * dissipation as the rule does when run on alone (rtol = 0: no relative part anywhere), and
 * not with rtol = 1e-6 on top, whose relative part rtol |v| on velocities of order 1 is far
 * above the 1e-3 eps the stick needs (measured: the rule 1.1e-5, set and rtol = 0 1.1e-5,
 * set and rtol = 1e-6 4.2e-2). */
START_TEST(test_set_tolerances)
{
    double ref[NC], D[NC], want[DIM], got[DIM];
    dissipation(FRICREG_INT_MSBDF, 1e-11, FRICREG_ATOL_FROM_EPS, ref);
    fricreg_structure *s = chain();
    rule(1e-6, want);
    ck_assert_int_eq(fricreg_structure_set_ode_abs_tolerances(s, DIM, want), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_get_ode_abs_tolerances(s, DIM, got), FRICREG_OK);
    ck_assert_mem_eq(got, want, sizeof want); /* set: reported before any call */
    /* rtol = 0, atol = 1: adaptive on the set levels alone */
    ck_assert_int_eq(fricreg_structure_run_ode(s, FRICREG_INT_MSBDF, 1e-3, 0.0, 1.0, T_END),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_get_dissipation(s, NC, D), FRICREG_OK);
    ck_assert_double_lt(worse_error(D, ref), 5e-5);
    ck_assert_int_eq(fricreg_structure_set_initial(s, NDOF, (double[NDOF]){0}, (double[NDOF]){0}),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_run_ode(s, FRICREG_INT_MSBDF, 1e-3, 1e-6, 1e-6, T_END),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_get_dissipation(s, NC, D), FRICREG_OK);
    ck_assert_double_gt(worse_error(D, ref), 1e-3);
    /* n = 0 removes them: run_ode's atol again */
    ck_assert_int_eq(fricreg_structure_set_ode_abs_tolerances(s, 0, NULL), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_get_ode_abs_tolerances(s, DIM, got), FRICREG_OK);
    for (size_t k = 0; k < DIM; k++)
        ck_assert_double_eq(got[k], 1e-6);
    /* refused input changes nothing */
    double bad[DIM];
    memcpy(bad, want, sizeof bad);
    bad[4] = 0.0;
    ck_assert_int_eq(fricreg_structure_set_ode_abs_tolerances(s, DIM, bad), FRICREG_EINVAL);
    bad[4] = NAN;
    ck_assert_int_eq(fricreg_structure_set_ode_abs_tolerances(s, DIM, bad), FRICREG_ENONFINITE);
    ck_assert_int_eq(fricreg_structure_set_ode_abs_tolerances(s, DIM - 1, want), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_structure_set_ode_abs_tolerances(s, DIM, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_structure_get_ode_abs_tolerances(s, DIM, got), FRICREG_OK);
    for (size_t k = 0; k < DIM; k++)
        ck_assert_double_eq(got[k], 1e-6);
    /* run_ode: the rule needs rtol > 0; other negative atols are refused */
    ck_assert_int_eq(fricreg_structure_run_ode(s, FRICREG_INT_MSBDF, 1e-3, 0.0,
                                               FRICREG_ATOL_FROM_EPS, T_END + 1.0),
                     FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_structure_run_ode(s, FRICREG_INT_MSBDF, 1e-3, 1e-6, -2.0, T_END + 1.0),
                     FRICREG_EINVAL);
    fricreg_structure_free(s);
}
END_TEST

/* Whether the structure's checks raise `code` now. */
static int warns(fricreg_structure *s, int code)
{
    size_t n = fricreg_structure_warning_count(s);
    for (size_t k = 0; k < n; k++) {
        int got = 0;
        ck_assert_int_eq(fricreg_structure_get_warning(s, k, &got, NULL, 0), FRICREG_OK);
        if (got == code)
            return 1;
    }
    return 0;
}

/* FRICREG_WARN_TOL_LOOSE: contact 1 reads v_1 - v_2 (sum_j |J_1j| = 2), so one atol with rtol
 * holds it to 2 (atol + rtol): 4e-6 at atol = rtol = 1e-6, above 0.01 eps = 1e-7 (the run
 * that left D_1 0.17 off), and 4e-8 at 1e-8, below; the rule (1e-3 eps) never warns; set
 * tolerances of 1e-6 with rtol = 0 hold it to 2e-6. */
/* FRICREG_WARN_TOL_LOOSE's verdict does not depend on the unit of length: the chain in m and
 * in mm (atol and eps times 1000, rtol the same) warns at rtol = 1e-6 and not at 1e-8, atol =
 * 1e-10 m, as the level 2 atol + rtol max_i sum_j |J_ij| |v_j| says (the run's peak of that
 * sum is 2.8 m/s). Taking rtol times 1 velocity unit instead, the chain in mm would not
 * warn at 1e-6 (2 (1e-7 + 1e-6) against 1e-4). */
START_TEST(test_loose_tolerances_any_unit)
{
    const double rtol[2] = {1e-6, 1e-8}, t = T_END / 4.0, atol_m = 1e-10;
    for (int r = 0; r < 2; r++) {
        int verdict[2];
        for (int u = 0; u < 2; u++) {
            double L = u == 0 ? 1.0 : 1000.0;
            fricreg_structure *s = chain_in(L);
            ck_assert_int_eq(fricreg_structure_run_ode(s, FRICREG_INT_RKF45, 1e-3, rtol[r],
                                                       L * atol_m, t),
                             FRICREG_OK);
            verdict[u] = warns(s, FRICREG_WARN_TOL_LOOSE);
            double level = 2.0 * L * atol_m + rtol[r] * s->peak_dof_speed;
            ck_assert_int_eq(verdict[u], level > 1e-2 * L * EPS);
            fricreg_structure_free(s);
        }
        ck_assert_int_eq(verdict[0], verdict[1]);
        ck_assert_int_eq(verdict[0], r == 0);
    }
}
END_TEST

START_TEST(test_loose_tolerances_warn)
{
    fricreg_structure *s = chain();
    double zero[NDOF] = {0}, t = T_END / 4.0, atol[DIM];
    ck_assert_int_eq(fricreg_structure_run_ode(s, FRICREG_INT_MSBDF, 1e-3, 1e-6, 1e-6, t),
                     FRICREG_OK);
    ck_assert(warns(s, FRICREG_WARN_TOL_LOOSE));
    ck_assert_int_eq(fricreg_structure_set_initial(s, NDOF, zero, zero), FRICREG_OK);
    ck_assert(!warns(s, FRICREG_WARN_TOL_LOOSE)); /* set_initial starts the judged run anew */
    ck_assert_int_eq(fricreg_structure_run_ode(s, FRICREG_INT_MSBDF, 1e-3, 1e-8, 1e-8, t),
                     FRICREG_OK);
    ck_assert(!warns(s, FRICREG_WARN_TOL_LOOSE));
    ck_assert_int_eq(fricreg_structure_set_initial(s, NDOF, zero, zero), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_run_ode(s, FRICREG_INT_MSBDF, 1e-3, 1e-2,
                                               FRICREG_ATOL_FROM_EPS, t),
                     FRICREG_OK);
    ck_assert(!warns(s, FRICREG_WARN_TOL_LOOSE));
    for (size_t k = 0; k < DIM; k++)
        atol[k] = 1e-6;
    ck_assert_int_eq(fricreg_structure_set_ode_abs_tolerances(s, DIM, atol), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_run_ode(s, FRICREG_INT_MSBDF, 1e-3, 0.0, 1.0, 2.0 * t),
                     FRICREG_OK);
    ck_assert(warns(s, FRICREG_WARN_TOL_LOOSE));
    fricreg_structure_free(s);
}
END_TEST

/* The companion of s's one-companion estimate, run to T_END at msbdf, rtol 1e-6 and the rule
 * from eps: at eps times `level` with tolerances times `scale`, its levels are the closed form
 * there (the cap rtol x scale not reached), and the estimate 3 |D - D_c| is, bit for bit, that
 * of a structure run by hand at that eps and rtol with the same scale (white box: the scale is
 * internal). */
static void check_companion(const fricreg_structure *s, double level, double scale)
{
    double D[NC], err[NC], got[DIM], want[DIM], Dc[NC];
    ck_assert_int_eq(fricreg_structure_get_dissipation(s, NC, D), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_get_dissipation_error(s, NC, err), FRICREG_OK);
    ck_assert_ptr_nonnull(s->companion);
    ck_assert_int_eq(fricreg_structure_get_ode_abs_tolerances(s->companion, DIM, got), FRICREG_OK);
    for (size_t k = 0; k < DIM; k++)
        want[k] = 1e-6 * scale;
    want[NDOF] = 1e-3 * (level * EPS) * scale;
    want[NDOF + 1] = want[NDOF + 2] = 1e-3 * (level * EPS) / 2.0 * scale;
    for (size_t k = 0; k < DIM; k++)
        ck_assert_double_eq_tol(got[k], want[k], 1e-25);
    fricreg_structure *c = chain();
    ck_assert_int_eq(fricreg_structure_set_law(c, FRICREG_LAW_QUINN, level * EPS), FRICREG_OK);
    c->tol_scale = scale;
    ck_assert_int_eq(fricreg_structure_run_ode(c, FRICREG_INT_MSBDF, 1e-3, 1e-6 * scale,
                                               FRICREG_ATOL_FROM_EPS, T_END),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_get_dissipation(c, NC, Dc), FRICREG_OK);
    for (size_t i = 0; i < NC; i++)
        ck_assert_double_eq(err[i], 3.0 * fabs(D[i] - Dc[i]));
    fricreg_structure_free(c);
}

/* The companion of the error estimate runs the rule at its eps / 2 with tolerances / 16, as
 * fricreg_sim's (rule_scale); set tolerances reach it at the next call, at / 16 too. */
START_TEST(test_companion)
{
    fricreg_structure *s = chain();
    /* one companion: 3 |q - q_c| against a companion made by hand (the two companions'
     * estimate from the same first companion: test_structure_error.c) */
    ck_assert_int_eq(fricreg_structure_set_error_estimate(s, FRICREG_ESTIMATE_ONE_COMPANION),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_error_companions(s, FRICREG_COMPANIONS_FINER),
                     FRICREG_OK); /* the finer estimator, not the default's screen */
    ck_assert_int_eq(fricreg_structure_run_ode(s, FRICREG_INT_MSBDF, 1e-3, 1e-6,
                                               FRICREG_ATOL_FROM_EPS, T_END),
                     FRICREG_OK);
    check_companion(s, 0.5, 1.0 / 16.0);
    /* set tolerances reach the companion at the next call, applied at / 16 there */
    double mine[DIM], got[DIM];
    for (size_t k = 0; k < DIM; k++)
        mine[k] = 1e-7 * (double)(k + 1);
    ck_assert_int_eq(fricreg_structure_set_ode_abs_tolerances(s, DIM, mine), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_run_ode(s, FRICREG_INT_MSBDF, 1e-3, 1e-6,
                                               FRICREG_ATOL_FROM_EPS, 1.01 * T_END),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_get_ode_abs_tolerances(s->companion, DIM, got), FRICREG_OK);
    for (size_t k = 0; k < DIM; k++)
        ck_assert_double_eq(got[k], mine[k] / 16.0);
    fricreg_structure_free(s);
}
END_TEST

/* Coarser companions (fricreg_structure_set_error_companions) run the rule at 2 eps with
 * tolerances x 2, the path's own factor (src/structure/error_estimate.c, TOL_COARSER). */
START_TEST(test_coarser_companion)
{
    fricreg_structure *s = chain();
    ck_assert_int_eq(fricreg_structure_set_error_estimate(s, FRICREG_ESTIMATE_ONE_COMPANION),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_error_companions(s, FRICREG_COMPANIONS_COARSER),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_run_ode(s, FRICREG_INT_MSBDF, 1e-3, 1e-6,
                                               FRICREG_ATOL_FROM_EPS, T_END),
                     FRICREG_OK);
    check_companion(s, 2.0, 2.0);
    fricreg_structure_free(s);
}
END_TEST

int main(void)
{
    Suite *suite = suite_create("structure_ode_tolerances");
    TCase *tc = tcase_create("core"), *sweeps = tcase_create("sweeps");
    tcase_set_timeout(tc, 60);
    tcase_set_timeout(sweeps, 60);
    tcase_add_test(tc, test_rule_values);
    tcase_add_test(tc, test_set_tolerances);
    tcase_add_test(tc, test_companion);
    tcase_add_test(tc, test_coarser_companion);
    tcase_add_test(tc, test_loose_tolerances_warn);
    /* the rule's runs over tolerances and units: two thirds of the program's time (3 s), the
     * release tier's (structure_ode_tolerances_release); core runs them at one tolerance each */
    tcase_set_tags(sweeps, "release");
    tcase_add_test(sweeps, test_rule_holds_the_dissipation);
    tcase_add_test(sweeps, test_loose_tolerances_any_unit);
    suite_add_tcase(suite, tc);
    suite_add_tcase(suite, sweeps);
    SRunner *sr = srunner_create(suite);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
