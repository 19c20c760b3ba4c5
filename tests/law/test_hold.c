/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_hold.c — the hold test on the 2-D law (fricreg_disk_eval, the default
 * FRICREG_DISK_QUINN): a block of mass M on an incline of angle theta, loaded in the incline's
 * plane by gravity along a direction phi of that plane,
 *     M v' = F + f,   F = M g sin(theta) (cos phi, sin phi),   mun = mu M g cos(theta),
 *     f_eq = -F (the force that makes the acceleration zero),
 * integrated with classical RK4 at a fixed step, the law's eps = 2 dt * 10 (so that the stick
 * zone's rate 2 mun/(M eps) times dt is 0.49, inside RK4's stability interval).
 *
 * What is measured, and where the expected values come from:
 *  - creep, in m/s, of a block that starts at rest with the load inside the friction disk
 *    (tan theta = 0.8 mu): the law gives f == f_eq exactly at v = 0, so F + f == 0 and the
 *    velocity stays exactly 0 — over 1e7 steps in one direction and 1e5 steps in each of 72
 *    directions through 360 degrees (isotropy: no direction creeps);
 *  - a block that slides into the stick (v0 = 0.05 m/s): it stops to rounding — its velocity
 *    falls to the level where 2 mun |v|/eps drops below an ulp of F, 1e-19 m/s here, and stays;
 *  - break-away as the incline tilts at a constant rate kappa: the block leaves rest (v != 0)
 *    at the first RK4 step with a stage past the exact angle atan(mu), so within kappa dt of it
 *    whatever eps is, and in every direction. */
#include <check.h>
#include <float.h>
#include <math.h>

#include "fricreg_disk.h"

#define MASS 2.385
#define GRAV 9.81
#define MU 0.5385
#define DT 1e-4
#define EPS (20 * DT)
#define PI 3.14159265358979323846

struct block {
    double x[2], v[2];
};

/* The load F and the bound mun at tilt theta, direction phi. */
static void load(double theta, double phi, double F[2], double *mun)
{
    double along = MASS * GRAV * sin(theta);
    F[0] = along * cos(phi);
    F[1] = along * sin(phi);
    *mun = MU * MASS * GRAV * cos(theta);
}

/* v' = (F + f)/M at velocity v; a failed evaluation is counted, not asserted here: Check's
 * assertions write to a pipe in fork mode, a system call per step. */
static long failed_evals = 0;
static void accel(const double F[2], double mun, const double v[2], double a[2])
{
    double feq[2] = {-F[0], -F[1]}, f[2] = {NAN, NAN};
    failed_evals += fricreg_disk_eval(FRICREG_DISK_QUINN, v, feq, mun, EPS, f) != FRICREG_OK;
    a[0] = (F[0] + f[0]) / MASS;
    a[1] = (F[1] + f[1]) / MASS;
}

/* One classical RK4 step of (x, v) with the loads F[s], bounds mun[s] at the step's start,
 * middle and end. */
static void rk4_step(struct block *b, const double F[3][2], const double mun[3])
{
    double k1[2], k2[2], k3[2], k4[2], v2[2], v3[2], v4[2];
    accel(F[0], mun[0], b->v, k1);
    for (int i = 0; i < 2; i++)
        v2[i] = b->v[i] + 0.5 * DT * k1[i];
    accel(F[1], mun[1], v2, k2);
    for (int i = 0; i < 2; i++)
        v3[i] = b->v[i] + 0.5 * DT * k2[i];
    accel(F[1], mun[1], v3, k3);
    for (int i = 0; i < 2; i++)
        v4[i] = b->v[i] + DT * k3[i];
    accel(F[2], mun[2], v4, k4);
    for (int i = 0; i < 2; i++) {
        b->x[i] += DT / 6.0 * (b->v[i] + 2.0 * v2[i] + 2.0 * v3[i] + v4[i]);
        b->v[i] += DT / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    }
}

/* The loads at the tilts of a step's start, middle and end. */
static void step_loads(const double theta[3], double phi, double F[3][2], double mun[3])
{
    for (int s = 0; s < 3; s++)
        load(theta[s], phi, F[s], &mun[s]);
}

/* Runs n steps at a fixed tilt; returns the largest |v| seen (m/s). */
static double hold(struct block *b, double theta, double phi, long n)
{
    const double th[3] = {theta, theta, theta};
    double F[3][2], mun[3], largest = 0.0;
    step_loads(th, phi, F, mun);
    failed_evals = 0;
    for (long k = 0; k < n; k++) {
        rk4_step(b, F, mun);
        largest = fmax(largest, hypot(b->v[0], b->v[1]));
    }
    ck_assert_int_eq(failed_evals, 0);
    return largest;
}

/* From rest inside the disk: 1e7 steps (1000 s), creep exactly 0 m/s, x unchanged. */
START_TEST(hold_from_rest_1e7_steps)
{
    struct block b = {{0.125, -0.375}, {0.0, 0.0}};
    double theta = atan(0.8 * MU), phi = 0.6180339887;
    ck_assert(hold(&b, theta, phi, 10000000) == 0.0);
    ck_assert(b.x[0] == 0.125 && b.x[1] == -0.375);
}
END_TEST

/* The load rotated through 360 degrees (72 directions, 1e5 steps each): no direction creeps.
 * Also just inside the bound (|F| = (1 - 1e-12) mun): still exactly 0. */
START_TEST(hold_is_isotropic)
{
    for (int k = 0; k < 72; k++) {
        double phi = (5.0 * k + 0.37) * PI / 180.0;
        struct block b = {{0.0, 0.0}, {0.0, 0.0}};
        ck_assert_msg(hold(&b, atan(0.8 * MU), phi, 100000) == 0.0, "creeps at phi = %g", phi);
        ck_assert(b.x[0] == 0.0 && b.x[1] == 0.0);
        struct block c = {{0.0, 0.0}, {0.0, 0.0}};
        ck_assert(hold(&c, atan((1 - 1e-12) * MU), phi, 1000) == 0.0);
    }
}
END_TEST

/* Sliding into the stick at v0 = 0.05 m/s (load inside the disk): the block stops within a
 * few cm and 0.1 s (|F| - mun = -0.2 mun decelerates it at 0.2 mu g cos(theta) ~ 0.95 m/s^2),
 * then its velocity decays at the rate 2 mun/(M eps) until the change 2 mun |v|/eps is below
 * an ulp of F: the residual creep is below 1e-18 m/s, in every direction. */
START_TEST(slide_into_stick)
{
    for (int k = 0; k < 12; k++) {
        double phi = (30.0 * k + 11.0) * PI / 180.0, th = atan(0.8 * MU);
        struct block b = {{0.0, 0.0}, {0.05 * cos(phi + 0.3), 0.05 * sin(phi + 0.3)}};
        hold(&b, th, phi, 100000); /* 10 s */
        double creep = hypot(b.v[0], b.v[1]);
        ck_assert_msg(creep <= 1e-18, "phi = %g: creep %.3g m/s", phi, creep);
        ck_assert(hypot(b.x[0], b.x[1]) < 0.01);
    }
}
END_TEST

/* Tilting at kappa = 0.02 rad/s from 0.9 atan(mu): the first step that leaves rest has its
 * start at or before the exact angle atan(mu) and its end after it (to an ulp-level margin in
 * the force comparison), in 8 directions. */
START_TEST(break_away_at_the_exact_angle)
{
    const double kappa = 0.02, exact = atan(MU), start = 0.9 * exact;
    for (int k = 0; k < 8; k++) {
        double phi = (45.0 * k + 7.0) * PI / 180.0;
        struct block b = {{0.0, 0.0}, {0.0, 0.0}};
        long n = 0;
        failed_evals = 0;
        for (; n < 1000000 && b.v[0] == 0.0 && b.v[1] == 0.0; n++) {
            double t = n * DT;
            const double th[3] = {start + kappa * t, start + kappa * (t + 0.5 * DT),
                                  start + kappa * (t + DT)};
            double F[3][2], mun[3];
            step_loads(th, phi, F, mun);
            rk4_step(&b, F, mun);
        }
        ck_assert(failed_evals == 0 && (b.v[0] != 0.0 || b.v[1] != 0.0));
        double t0 = (n - 1) * DT, th0 = start + kappa * t0, th1 = th0 + kappa * DT;
        ck_assert_msg(th0 <= exact + 1e-12 && th1 >= exact - 1e-12,
                      "phi = %g: left rest between %.15g and %.15g, exact %.15g", phi, th0, th1,
                      exact);
    }
}
END_TEST

static Suite *hold_suite(void)
{
    Suite *s = suite_create("hold");
    TCase *tc = tcase_create("hold");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, slide_into_stick);
    tcase_add_test(tc, break_away_at_the_exact_angle);
    suite_add_tcase(s, tc);
    /* 1.7e7 RK4 steps (3 s): the release tier's (hold_release) */
    TCase *holds = tcase_create("holds");
    tcase_set_timeout(holds, 120);
    tcase_set_tags(holds, "release");
    tcase_add_test(holds, hold_from_rest_1e7_steps);
    tcase_add_test(holds, hold_is_isotropic);
    suite_add_tcase(s, holds);
    return s;
}

int main(void)
{
    SRunner *sr = srunner_create(hold_suite());
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? 0 : 1;
}
