/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_structure_peak.c — fricreg_structure_get_peak_displacement takes in the turning points
 * between the step ends, against the closed form of a free undamped oscillator (m = 1,
 * k = omega^2, omega = 2 pi, from u = 0 at u' = 1: the peak 1 / omega at t = 1/4).
 *
 * Newmark's average acceleration moves the state round the energy ellipse by the angle
 * theta = 2 atan(omega dt / 2) a step, and between the ends along its own quadratic; a turning
 * point a fraction s of the step after its start puts the quadratic's vertex at
 * (1 + theta^4 s^2 (1 - s)^2 / 8 + O(theta^6)) / omega (expanding
 * cos a + sin^2 a / (2 cos(theta / 2) cos(a - theta / 2)), a = s theta): never below 1 / omega
 * and at most theta^4 / 128 above. The step ends alone fall short by up to (omega dt)^2 / 8.
 * GSL's RK4 in fixed steps (of h = 2 dt: the paper's method, fricreg_structure_run_ode): its
 * ends within O(h^5) a step of the circle, the cubic Hermite interpolant between them within
 * (omega h)^4 / 384 (its fourth derivative's bound). */
#include <check.h>
#include <math.h>
#include <stdlib.h>

#include "fricreg_structure.h"

#define PI 3.14159265358979323846
#define OMEGA (2.0 * PI)
#define T_END 0.5 /* past the first peak, before the second */

/* The free oscillator (no contact: its bound 0), stepped to T_END at dt = 1 / steps_per_period
 * by Newmark (integrator 0) or run_ode; its peak displacement times omega, minus 1. */
static double peak_error(int integrator, int steps_per_period)
{
    fricreg_structure *s = NULL;
    double k = OMEGA * OMEGA, one = 1.0, zero = 0.0, u0 = 0.0, v0 = 1.0, dt, peak;
    ck_assert_int_eq(fricreg_structure_create(1, 1, &s), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_stiffness(s, 1, &k), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_contacts(s, 1, 1, &one), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_bounds(s, 1, &zero), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_initial(s, 1, &u0, &v0), FRICREG_OK);
    dt = 1.0 / steps_per_period;
    if (integrator == 0)
        ck_assert_int_eq(fricreg_structure_run(s, dt, T_END), FRICREG_OK);
    else
        ck_assert_int_eq(fricreg_structure_run_ode(s, integrator, dt, 0.0, 0.0, T_END), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_get_peak_displacement(s, 1, &peak), FRICREG_OK);
    fricreg_structure_free(s);
    return peak * OMEGA - 1.0;
}

/* Steps per period that put the turning point at various fractions of a step. */
static const int steps_per_period[] = {10, 11, 13, 17, 23, 41, 97};
#define NSTEPS (sizeof steps_per_period / sizeof *steps_per_period)

START_TEST(test_newmark_vertex)
{
    for (size_t i = 0; i < NSTEPS; i++) {
        double theta = 2.0 * atan(OMEGA / steps_per_period[i] / 2.0);
        double err = peak_error(0, steps_per_period[i]);
        double bound = pow(theta, 4) * (1.0 + theta * theta) / 128.0; /* O(theta^6) margin */
        ck_assert_msg(err >= 0.0 && err <= bound, "%d steps a period: %g outside [0, %g]",
                      steps_per_period[i], err, bound);
    }
}
END_TEST

START_TEST(test_rk4_hermite)
{
    for (size_t i = 0; i < NSTEPS; i++) {
        double h = 2.0 * OMEGA / steps_per_period[i];
        double err = peak_error(FRICREG_INT_RK4, steps_per_period[i]);
        double bound = pow(h, 4) / 384.0 + pow(h, 5) / 100.0; /* RK4's own error: O(h^5) */
        ck_assert_msg(fabs(err) <= bound, "%d steps a period: |%g| above %g", steps_per_period[i],
                      err, bound);
    }
}
END_TEST

int main(void)
{
    Suite *suite = suite_create("structure_peak");
    TCase *tc = tcase_create("core");
    tcase_add_test(tc, test_newmark_vertex);
    tcase_add_test(tc, test_rk4_hermite);
    suite_add_tcase(suite, tc);
    SRunner *runner = srunner_create(suite);
    srunner_run_all(runner, CK_NORMAL);
    int failed = srunner_ntests_failed(runner);
    srunner_free(runner);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
