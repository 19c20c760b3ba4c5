/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_hb_unilateral.c — Check suite for the stability of a unilateral spring's forced response
 * by the exact monodromy (fricreg_hb_set_stability, fricreg_hb_point_stability,
 * fricreg_hb_bifurcations; fricreg_hb_stability.h), where a stiff contact switches.
 *
 * The model is NLvib's example 03 (M. Krack, J. Gross, NLvib 1.3,
 * EXAMPLES/03_twoDOFoscillator_unilateralSpring: ChainOfOscillators with mi = (1, 1),
 * ki = (0, 1, 1), di = 0.03 ki, Fex1 = (0, 0.1), a unilateral spring of stiffness 100 and gap 1
 * on dof 1), as matlab/fricreg_nlvib_frf.m maps it: M = I, K = [1 −1; −1 2], C = 0.03 K,
 * p_c = (0, 0.1), one jenkins_normal element on J_t = J_n = (1, 0) with kt = 100, mu = 0,
 * kn = 100, n0 = −kn gap = −100 (N = max(0, 100 (x_1 − 1))), H = 21, from Ω = 0.8 down to 0.5;
 * and the same with mu = 1e-6, whose slider joins the monodromy's state (its touchdowns, slips
 * and the short sticks at its reversals are switches of the orbit too). The response hardens
 * and overhangs between a turning point where the orbit grazes the spring (0.65344) and one at
 * 0.75563: the middle branch between them is a saddle, one real multiplier above 1 (NLvib's own
 * shooting finds it unstable throughout).
 *
 * Until the exact monodromy took its switch instants from the exact orbit (src/floquet/orbit.c),
 * it called that branch stable from 0.698 to 0.726 (mu_max 0.84 to 0.87, "bifurcations" BP and
 * PD at its ends): the contact lasts about half the spring's own period, so the product of the
 * pieces' exponentials turns with √kn times the contact's duration, and the H = 21 orbit's
 * 0.2200 rad of contact (the exact orbit's: 0.2099) put the multiplier 1.87 at 0.85.
 *
 * Where the numbers come from: an event-driven shooting of the frictionless model, independent
 * of the HB (GSL's rk8pd at T/2000 between the contact's switches, each located by bisection to
 * 1e-14 T: tests/support/event_period.c), Newton on the period map from the HB orbit's state,
 * the monodromy by central differences (steps 1e-7). Measured (HB_PRINT=1) at the middle
 * branch's points between 0.70 and 0.73 rad/s (2026-11-29): at Ω = 0.70647, 0.71406, 0.72287 the
 * shooting's mu_max is 2.057518167, 1.867381194, 1.668186097; the exact monodromy's is within
 * 2.6e-8 of it at the six points compared (with mu = 1e-6: 7.0e-7, the friction's own effect),
 * Hill's (FRICREG_HB_STABILITY_HILL, the same orbits) within 1.7e-4. Asserted: the monodromy to
 * 1e-6 (mu = 1e-6: 1e-5), Hill's to 1e-3. Without orbit.c both fail at their first check (a BP
 * located at 0.698262 on the middle branch). */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_complex_math.h>
#include <gsl/gsl_eigen.h>
#include <gsl/gsl_errno.h>

#include "event_period.h"
#include "fricreg_hb.h"
#include "orbit_state.h"

#define H 21
#define NC (2 * H + 1)
#define NQ (2 * NC)
#define MAXP 400
static const double PI = 3.14159265358979323846;
static const double KM[4] = {1, -1, -1, 2}, DAMP = 0.03, KN = 100.0, GAP = 1.0, P2 = 0.1;

/* The model with friction coefficient mu (0: the adapter's; 1e-6: a slider in the state). */
static fricreg_hb *make(int method, double mu0)
{
    const double M[4] = {1, 0, 0, 1}, J[2] = {1, 0}, kt[1] = {KN}, mu[1] = {mu0},
                 n0[1] = {-KN * GAP}, kn[1] = {KN}, pc[2] = {0.0, P2}, ps[2] = {0.0, 0.0};
    double C[4];
    for (int i = 0; i < 4; i++)
        C[i] = DAMP * KM[i];
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(2, 1, H, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, 2, M), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 2, KM), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_damping(hb, 2, C), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_normal_elements(hb, 1, 2, J, J, kt, mu, n0, kn), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_excitation(hb, 2, pc, ps), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stability_method(hb, method), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stability(hb, 1), FRICREG_OK);
    return hb;
}

/* ---- The event-driven shooting ---------------------------------------------------------- */

struct phase {
    double omega;
    int closed;
};

static int rhs(double t, const double y[], double dy[], void *params)
{
    const struct phase *ph = params;
    double f[2] = {0.0, P2 * cos(ph->omega * t)};
    if (ph->closed)
        f[0] -= KN * (y[0] - GAP);
    for (int i = 0; i < 2; i++) {
        double a = f[i];
        for (int k = 0; k < 2; k++)
            a -= DAMP * KM[2 * i + k] * y[2 + k] + KM[2 * i + k] * y[k];
        dy[i] = y[2 + i];
        dy[2 + i] = a;
    }
    return GSL_SUCCESS;
}

/* Negative until the contact switches: a touchdown at x_1 = gap, an opening back there. */
static double until_switch(void *params, const double y[])
{
    const struct phase *ph = params;
    return ph->closed ? GAP - y[0] : y[0] - GAP;
}

static void switch_mode(void *params, double y[])
{
    struct phase *ph = params;
    (void)y;
    ph->closed = !ph->closed;
}

static void period(double omega, const double *z0, double *z)
{
    struct phase ph = {omega, z0[0] > GAP};
    struct event_system es = {{rhs, NULL, 4, &ph}, until_switch, switch_mode};
    event_period(&es, 0.0, 2.0 * PI / omega, z0, z);
}

/* The period map's Jacobian Phi[4 4] (row-major) at z by central differences. */
static void period_jacobian(double omega, const double *z, double *Phi)
{
    for (int j = 0; j < 4; j++) {
        double zp[4], zm[4], fp[4], fm[4], h = 1e-7;
        memcpy(zp, z, sizeof zp);
        memcpy(zm, z, sizeof zm);
        zp[j] += h, zm[j] -= h;
        period(omega, zp, fp);
        period(omega, zm, fm);
        for (int i = 0; i < 4; i++)
            Phi[4 * i + j] = (fp[i] - fm[i]) / (2.0 * h);
    }
}

/* The shooting's largest |multiplier| at the orbit Newton finds from the HB's x[2 NC]. */
static double shooting_mu_max(double omega, const double *x)
{
    double z[4], zn[4], r[4], Phi[16];
    orbit_state_at(2, H, x, omega, 0.0, z);
    for (int it = 0;; it++) {
        ck_assert_int_lt(it, 20);
        double res = 0.0;
        period(omega, z, zn);
        for (int i = 0; i < 4; i++)
            r[i] = zn[i] - z[i], res = fmax(res, fabs(r[i]));
        if (res <= 1e-12)
            break;
        period_jacobian(omega, z, Phi);
        shooting_newton_step(4, Phi, r, z);
    }
    period_jacobian(omega, z, Phi);
    gsl_matrix_view A = gsl_matrix_view_array(Phi, 4, 4);
    gsl_vector_complex *ev = gsl_vector_complex_alloc(4);
    gsl_eigen_nonsymm_workspace *w = gsl_eigen_nonsymm_alloc(4);
    ck_assert_int_eq(gsl_eigen_nonsymm(&A.matrix, ev, w), 0);
    double top = 0.0;
    for (int e = 0; e < 4; e++)
        top = fmax(top, gsl_complex_abs(gsl_vector_complex_get(ev, e)));
    gsl_eigen_nonsymm_free(w);
    gsl_vector_complex_free(ev);
    return top;
}

/* ---- The cases ------------------------------------------------------------------------ */

/* The branch's two turning points (the automatic method, the exact monodromy here): their
 * point indices into tp[2] in the branch's order. */
static void turning_points(fricreg_hb *hb, size_t tp[2], double omega_tp[2])
{
    size_t found = 0;
    for (size_t i = 0; i < fricreg_hb_bifurcations(hb); i++) {
        int type = -1;
        double omega = 0.0, rms[2];
        size_t point = 0;
        ck_assert_int_eq(fricreg_hb_bifurcation(hb, i, &type, &omega, &point, 2, rms), FRICREG_OK);
        if (type == FRICREG_HB_TP && found < 2)
            tp[found] = point, omega_tp[found++] = omega;
    }
    ck_assert_uint_eq(found, 2);
    if (tp[0] > tp[1]) {
        size_t t = tp[0];
        double o = omega_tp[0];
        tp[0] = tp[1], omega_tp[0] = omega_tp[1];
        tp[1] = t, omega_tp[1] = o;
    }
}

/* The middle branch, between the grazing turning point and the upper one, is unstable at every
 * stored point by the exact monodromy (the automatic choice), and no bifurcation but the two
 * turning points is located on it; at three of its points mu_max is the event-driven
 * shooting's to 1e-6 and Hill's method's on the same orbit to 1e-3. */
START_TEST(middle_branch_is_a_saddle)
{
    const double mu0 = _i == 0 ? 0.0 : 1e-6, tol = _i == 0 ? 1e-6 : 1e-5;
    fricreg_hb *hb = make(FRICREG_HB_STABILITY_AUTO, mu0),
               *hill = make(FRICREG_HB_STABILITY_HILL, mu0);
    int method = -1;
    ck_assert_int_eq(fricreg_hb_get_stability_method(hb, &method), FRICREG_OK);
    ck_assert_int_eq(method, FRICREG_HB_STABILITY_MONODROMY);
    ck_assert_int_eq(fricreg_hb_continue(hb, 0.8, 0.5, NQ, NULL), FRICREG_OK);
    size_t tp[2], points = fricreg_hb_points(hb);
    double omega_tp[2];
    turning_points(hb, tp, omega_tp);
    ck_assert_double_eq_tol(omega_tp[0], 0.65344, 1e-4); /* the graze */
    ck_assert_double_eq_tol(omega_tp[1], 0.75563, 1e-4);
    for (size_t i = 0; i < fricreg_hb_bifurcations(hb); i++) {
        int type = -1;
        double omega = 0.0, rms[2];
        size_t point = 0;
        ck_assert_int_eq(fricreg_hb_bifurcation(hb, i, &type, &omega, &point, 2, rms), FRICREG_OK);
        ck_assert_msg(type == FRICREG_HB_TP || point <= tp[0] || point > tp[1],
                      "a bifurcation of type %d at %g on the middle branch", type, omega);
    }
    size_t unstable = 0, compared = 0;
    ck_assert_uint_lt(tp[1], points);
    for (size_t k = tp[0] + 1; k <= tp[1]; k++) {
        double omega = 0.0, rms[2], mu = 0.0;
        int stable = -1;
        ck_assert_int_eq(fricreg_hb_point(hb, k, &omega, 2, rms), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_point_stability(hb, k, &stable, &mu), FRICREG_OK);
        ck_assert_msg(stable == 0, "middle branch at Omega %.5f: stable, mu_max %.6f", omega, mu);
        unstable++;
        if (!(omega > 0.70 && omega < 0.73)) /* the stretch once called stable */
            continue;
        /* the same orbit by Hill's method: its q is J x, the tangential and normal rows both
         * x_1's coefficients */
        double x[2 * NC], q[NQ], mu_hill = 0.0;
        ck_assert_int_eq(fricreg_hb_point_displacement(hb, k, 2, NC, x), FRICREG_OK);
        memcpy(q, x, NC * sizeof *x);
        memcpy(q + NC, x, NC * sizeof *x);
        ck_assert_int_eq(fricreg_hb_solve(hill, omega, NQ, q, q), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_point_stability(hill, FRICREG_HB_SOLUTION, &stable, &mu_hill),
                         FRICREG_OK);
        ck_assert_int_eq(stable, 0);
        double ref = shooting_mu_max(omega, x);
        if (getenv("HB_PRINT"))
            fprintf(stderr,
                    "mu %g, Omega %.5f: monodromy %.9f, Hill %.9f, shooting %.9f (%.1e, %.1e)\n",
                    mu0, omega, mu, mu_hill, ref, mu / ref - 1.0, mu_hill / ref - 1.0);
        ck_assert_double_gt(ref, 1.5);
        ck_assert_double_le(fabs(mu - ref), tol * ref);
        ck_assert_double_le(fabs(mu_hill - ref), 1e-3 * ref);
        compared++;
    }
    ck_assert_uint_ge(unstable, 20);
    ck_assert_uint_ge(compared, 3);
    fricreg_hb_free(hill);
    fricreg_hb_free(hb);
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("hb_unilateral");
    TCase *tc = tcase_create("core");
    tcase_add_loop_test(tc, middle_branch_is_a_saddle, 0, 2);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    gsl_set_error_handler_off();
    SRunner *sr = srunner_create(suite());
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
