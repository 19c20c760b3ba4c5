/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_element_energy.c — Check suite for fricreg_element_energy (fricreg_element.h): the
 * energies of one increment that a host books.
 *
 * Where the numbers come from:
 *   - closed-form hysteresis loops under u = A sin(2 pi i / N), N a multiple of 4 so that the
 *     samples hit the turning points: a Jenkins slider (k, b) dissipates 4 b (A - b/k) a cycle
 *     when A > b/k and nothing below; an Iwan type sums that over its slipping sliders; a
 *     contact_3d under a constant preload n0 is a slider of bound mu n0 along any tangential
 *     line (the radial return keeps the line);
 *   - the stored energy at a turning point: b^2 / (2 k) a slipping slider, k A^2 / 2 a stuck
 *     one that never slipped, plus n0^2 / (2 kn) the normal spring;
 *   - a spring: k u^2 / 2, no dissipation; an open contact: neither;
 *   - the header's failure promises: each status, and nothing written. */
#include <check.h>
#include <math.h>

#include "fricreg_element.h"
#include "quiet_check.h"

#define SENTINEL (-777.125)
#define STEPS 64 /* per cycle: a multiple of 4 */
#define CYCLES 3
#define TWO_PI 6.283185307179586

/* The dissipation of each cycle of u(t) = A sin(2 pi t) along direction dir[dim] (a normal
 * type's g fixed at 0, its last component) from a virgin state, into per_cycle[CYCLES], and
 * the stored energy at the last positive turning point into *stored_at_turn. */
static void march_loop(const fricreg_element_type *t, const double *p, double A, const double *dir,
                       double *per_cycle, double *stored_at_turn)
{
    double w[3 * FRICREG_ELEMENT_MAX_SLIDERS], f[3], u[3] = {0.0, 0.0, 0.0};
    int dim = fricreg_element_dim(t);
    ck_assert_int_eq(fricreg_element_init(t, p, w), FRICREG_OK);
    for (int c = 0; c < CYCLES; c++) {
        per_cycle[c] = 0.0;
        for (int i = 1; i <= STEPS; i++) {
            double s = A * sin(TWO_PI * i / STEPS), d, e;
            for (int a = 0; a < dim; a++)
                u[a] = s * dir[a];
            QUIET_OK(fricreg_element_energy(t, p, w, u, &d, &e));
            QUIET_OK(fricreg_element_eval(t, p, w, u, f, NULL, NULL, w));
            QUIET_ASSERT(d >= 0.0, "dissipation %g < 0", d);
            per_cycle[c] += d;
            if (i == STEPS / 4)
                *stored_at_turn = e;
        }
    }
}

static void assert_close(double got, double want, double tol)
{
    ck_assert_msg(fabs(got - want) <= tol * fmax(1.0, fabs(want)), "%.17g, closed form %.17g", got,
                  want);
}

START_TEST(test_jenkins_loops)
{
    const fricreg_element_type *t = fricreg_element_lookup("jenkins");
    const double k = 2.0, b = 0.7, p[2] = {k, b}, one = 1.0;
    const double amplitudes[] = {0.2, 0.35, 1.0, 3.0}; /* stuck, at b/k, slipping */
    for (size_t i = 0; i < sizeof amplitudes / sizeof amplitudes[0]; i++) {
        double A = amplitudes[i], D[CYCLES], E = 0.0;
        march_loop(t, p, A, &one, D, &E);
        double slips = A > b / k;
        for (int c = 1; c < CYCLES; c++) /* the first cycle starts virgin */
            assert_close(D[c], slips ? 4.0 * b * (A - b / k) : 0.0, 1e-13);
        assert_close(E, slips ? b * b / (2.0 * k) : 0.5 * k * A * A, 1e-14);
    }
}
END_TEST

START_TEST(test_iwan_loops)
{
    enum { NS = 4 };
    const fricreg_element_type *t = fricreg_element_sliders(fricreg_element_lookup("iwan"), NS);
    const double k[NS] = {1.0, 2.0, 3.0, 4.0}, phi[NS] = {0.1, 0.8, 0.9, 4.0};
    double p[2 * NS], one = 1.0;
    for (int s = 0; s < NS; s++) {
        p[s] = k[s];
        p[NS + s] = phi[s];
    }
    const double A = 0.5; /* phi/k = 0.1, 0.4, 0.3, 1.0: three slip, one stays stuck */
    double D[CYCLES], E = 0.0, want_D = 0.0, want_E = 0.0;
    march_loop(t, p, A, &one, D, &E);
    for (int s = 0; s < NS; s++) {
        int slips = A > phi[s] / k[s];
        want_D += slips ? 4.0 * phi[s] * (A - phi[s] / k[s]) : 0.0;
        want_E += slips ? phi[s] * phi[s] / (2.0 * k[s]) : 0.5 * k[s] * A * A;
    }
    for (int c = 1; c < CYCLES; c++)
        assert_close(D[c], want_D, 1e-13);
    assert_close(E, want_E, 1e-14);
}
END_TEST

START_TEST(test_contact_3d_loop_under_preload)
{
    const fricreg_element_type *t = fricreg_element_lookup("contact_3d");
    const double kt = 5.0, mu = 0.3, kn = 7.0, n0 = 2.0, b = mu * n0;
    const double p[5] = {kt, mu, kn, n0, 0.0};
    const double dir[3] = {cos(0.5), sin(0.5), 0.0}; /* a tangential line at 0.5 rad, g = 0 */
    const double A = 0.4;
    double D[CYCLES], E = 0.0;
    march_loop(t, p, A, dir, D, &E);
    for (int c = 1; c < CYCLES; c++)
        assert_close(D[c], 4.0 * b * (A - b / kt), 1e-13);
    assert_close(E, b * b / (2.0 * kt) + n0 * n0 / (2.0 * kn), 1e-14);

    /* open (n0 + kn g < 0): the springs released, nothing dissipated or stored */
    double w[2] = {0.3, -0.1}, u[3] = {1.0, 1.0, -1.0}, d = SENTINEL, e = SENTINEL;
    ck_assert_int_eq(fricreg_element_energy(t, p, w, u, &d, &e), FRICREG_OK);
    ck_assert(d == 0.0 && e == 0.0);

    /* kn = 0: a constant normal load, no normal spring to hold energy */
    const double p0[5] = {kt, mu, 0.0, n0, 0.0};
    double w0[2] = {0.0, 0.0}, u0[3] = {0.01, 0.0, 0.5};
    ck_assert_int_eq(fricreg_element_energy(t, p0, w0, u0, &d, &e), FRICREG_OK);
    assert_close(e, 0.5 * kt * 0.01 * 0.01, 1e-15);
    ck_assert(d == 0.0);
}
END_TEST

START_TEST(test_spring)
{
    const fricreg_element_type *t = fricreg_element_lookup("spring");
    const double p[1] = {3.0}, u[1] = {-0.5}, no_state[1] = {0.0}; /* nstate 0 */
    double d = SENTINEL, e = SENTINEL;
    ck_assert_int_eq(fricreg_element_energy(t, p, no_state, u, &d, &e), FRICREG_OK);
    ck_assert(d == 0.0);
    assert_close(e, 0.375, 1e-16);
}
END_TEST

/* Every failure returns its status and writes nothing. */
START_TEST(test_failures_write_nothing)
{
    const fricreg_element_type *t = fricreg_element_lookup("jenkins");
    const double p[2] = {2.0, 0.7}, w[1] = {0.0}, u[1] = {1.0};
    double d = SENTINEL, e = SENTINEL;
    ck_assert_int_eq(fricreg_element_energy(NULL, p, w, u, &d, &e), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_element_energy(t, NULL, w, u, &d, &e), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_element_energy(t, p, NULL, u, &d, &e), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_element_energy(t, p, w, NULL, &d, &e), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_element_energy(t, p, w, u, NULL, &e), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_element_energy(t, p, w, u, &d, NULL), FRICREG_ENULL);
    const double bad_k[2] = {0.0, 0.7}, nan_u[1] = {NAN};
    ck_assert_int_eq(fricreg_element_energy(t, bad_k, w, u, &d, &e), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_element_energy(t, p, w, nan_u, &d, &e), FRICREG_ENONFINITE);
    /* a force of 1e200 in stick: its spring energy 1e400 / 2 overflows */
    const double huge_b[2] = {1.0, 1e300}, far[1] = {1e200};
    ck_assert_int_eq(fricreg_element_energy(t, huge_b, w, far, &d, &e), FRICREG_ENONFINITE);
    ck_assert(d == SENTINEL && e == SENTINEL);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("element_energy");
    TCase *tc = tcase_create("core");
    tcase_add_test(tc, test_jenkins_loops);
    tcase_add_test(tc, test_iwan_loops);
    tcase_add_test(tc, test_contact_3d_loop_under_preload);
    tcase_add_test(tc, test_spring);
    tcase_add_test(tc, test_failures_write_nothing);
    suite_add_tcase(s, tc);
    SRunner *sr = srunner_create(s);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? 0 : 1;
}
