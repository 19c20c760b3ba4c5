/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_aft_march.c — white box: the march of an element's eval (src/joint/aft_march.c), the
 * AFT harmonic balance runs a law without one of its own on.
 *
 * Where the numbers come from:
 *   - a slider stuck all period is centred: f = kt (u - (u_max + u_min) / 2) at the samples,
 *     the exact 1-D AFT's choice (aft_exact.c), a closed form the march meets to 1e-14 of kt u;
 *     a 2-D slider at its orbit's enclosing circle's centre, the 3-D contact's sampled AFT's
 *     choice at a constant normal force, which the march equals (forces to 1e-14 of kt, the
 *     Jacobian to 1e-12);
 *   - the Jacobian is the exact derivative of the sampled march: it equals central differences
 *     of the march's own forces (step 1e-7) to 1e-8 of the sliders' stiffness (measured 5.4e-10:
 *     the differences' own error), on orbits
 *     where every slider sticks, where one barely slips (its periodic state contracts slowly,
 *     so the implicit function theorem's (I - Psi)^-1 matters), where all slip, and on an Iwan
 *     element whose sliders do some of each; for jenkins_2d, iwan_2d and jenkins_3d; and for
 *     dahl, whose state is not a slider's (its own state tangents chained), on a soft and a
 *     saturated loop. */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg_aft.h"
#include "fricreg_element.h"
#include "joint/aft_march.h"

#define H 3
#define NC (2 * H + 1)
#define TWO_PI 6.283185307179586
#define SAMPLES 512 /* 64 (2H + 1), rounded up to a power of two, as harmonic balance's */

/* u[dim NC]: an orbit with a mean and three harmonics in each component, times scale. */
static void orbit(int dim, double scale, double *u)
{
    static const double shape[3][NC] = {{0.1, 0.8, 0.2, 0.1, 0.0, 0.0, 0.03},
                                        {-0.05, 0.0, 0.5, 0.0, 0.04, 0.05, 0.0},
                                        {0.02, 0.3, -0.1, 0.0, 0.0, 0.02, 0.01}};
    for (int d = 0; d < dim; d++)
        for (int j = 0; j < NC; j++)
            u[d * NC + j] = scale * shape[d][j];
}

struct bench {
    fricreg_aft *aft;
    struct fr_aft_march *w;
};

static struct bench bench_new(void)
{
    struct bench b;
    ck_assert_int_eq(fricreg_aft_create(H, SAMPLES, &b.aft), FRICREG_OK);
    ck_assert_int_eq(fr_aft_march_create(SAMPLES, NC, 3 * 4, &b.w), FRICREG_OK);
    return b;
}

static void bench_free(struct bench b)
{
    fr_aft_march_free(b.w);
    fricreg_aft_free(b.aft);
}

/* jenkins_2d at kt 20, mun 1 on an orbit along x alone, small enough to stick. */
START_TEST(stuck_slider_is_centred)
{
    struct bench b = bench_new();
    const fricreg_element_type *T = fricreg_element_lookup("jenkins_2d");
    const double p[2] = {20.0, 1.0};
    double u[2 * NC] = {0}, f[2 * NC], us[SAMPLES], want[SAMPLES], x[SAMPLES];
    orbit(1, 0.04, u); /* kt (u_max - u_min) / 2 = 0.8 mun or so: stuck */
    double lo = INFINITY, hi = -INFINITY;
    for (size_t n = 0; n < SAMPLES; n++) {
        double th = TWO_PI * (double)n / SAMPLES;
        us[n] = u[0];
        for (int h = 1; h <= H; h++)
            us[n] += u[2 * h - 1] * cos(h * th) + u[2 * h] * sin(h * th);
        lo = fmin(lo, us[n]);
        hi = fmax(hi, us[n]);
    }
    ck_assert_double_lt(p[0] * (hi - lo) / 2.0, p[1]);
    for (size_t n = 0; n < SAMPLES; n++)
        want[n] = p[0] * (us[n] - 0.5 * (hi + lo));
    ck_assert_int_eq(fr_aft_march(b.aft, b.w, T, p, u, f, NULL), FRICREG_OK);
    for (size_t n = 0; n < SAMPLES; n++) { /* the forces back at the samples */
        double th = TWO_PI * (double)n / SAMPLES;
        x[n] = f[0];
        for (int h = 1; h <= H; h++)
            x[n] += f[2 * h - 1] * cos(h * th) + f[2 * h] * sin(h * th);
        ck_assert_msg(fabs(x[n] - want[n]) <= 1e-14 * p[0] * hi,
                      "sample %zu: %.17g, closed form %.17g", n, x[n], want[n]);
    }
    for (int j = 0; j < NC; j++)
        ck_assert_double_eq(f[NC + j], 0.0); /* y at rest */
    bench_free(b);
}
END_TEST

/* jenkins_2d stuck on a 2-D orbit whose per-component middle is not its centre: the march
 * centres the slider in the orbit's smallest enclosing circle, as the 3-D contact's sampled AFT
 * does at a constant normal force (kn = 0, mu n0 = mun), which it then equals, forces and
 * Jacobian. */
START_TEST(stuck_disk_is_the_contacts)
{
    struct bench b = bench_new();
    const fricreg_element_type *T = fricreg_element_lookup("jenkins_2d");
    const double p[2] = {20.0, 1.0}, mu = 0.5, n0 = 2.0;
    double u[2 * NC], g[NC] = {0}, f[2 * NC], fc[2 * NC], nf[NC];
    double *J = malloc(4 * NC * NC * sizeof *J), *Jc = malloc(9 * NC * NC * sizeof *Jc);
    ck_assert_ptr_nonnull(J);
    ck_assert_ptr_nonnull(Jc);
    orbit(2, 0.05, u); /* kt r = 0.88 mun: stuck, the circle's centre off each component's middle */
    ck_assert_int_eq(fr_aft_march(b.aft, b.w, T, p, u, f, J), FRICREG_OK);
    ck_assert_int_eq(fricreg_aft_jenkins_2d_normal_sampled(b.aft, p[0], mu, n0, 0.0, NC, u, g, fc,
                                                           nf, Jc),
                     FRICREG_OK);
    double worst = 0.0, worst_jac = 0.0;
    for (int i = 0; i < 2 * NC; i++) {
        worst = fmax(worst, fabs(f[i] - fc[i]));
        for (int j = 0; j < 2 * NC; j++)
            worst_jac = fmax(worst_jac, fabs(J[i * 2 * NC + j] - Jc[i * 3 * NC + j]));
    }
    ck_assert_msg(worst <= 1e-14 * p[0] && worst_jac <= 1e-12 * p[0],
                  "forces %g, Jacobian %g from the contact's", worst, worst_jac);
    free(J);
    free(Jc);
    bench_free(b);
}
END_TEST

/* The largest |J - central differences| over the Jacobian of type at u. */
static double jacobian_error(struct bench b, const fricreg_element_type *T, const double *p,
                             const double *u)
{
    size_t m = (size_t)fricreg_element_dim(T) * NC;
    double *J = malloc(m * m * sizeof *J), fp[3 * NC], fm[3 * NC], f[3 * NC], up[3 * NC];
    ck_assert_ptr_nonnull(J);
    ck_assert_int_eq(fr_aft_march(b.aft, b.w, T, p, u, f, J), FRICREG_OK);
    double worst = 0.0;
    for (size_t c = 0; c < m; c++) {
        double h = 1e-7;
        memcpy(up, u, m * sizeof *u);
        up[c] = u[c] + h;
        ck_assert_int_eq(fr_aft_march(b.aft, b.w, T, p, up, fp, NULL), FRICREG_OK);
        up[c] = u[c] - h;
        ck_assert_int_eq(fr_aft_march(b.aft, b.w, T, p, up, fm, NULL), FRICREG_OK);
        for (size_t r = 0; r < m; r++)
            worst = fmax(worst, fabs(J[r * m + c] - (fp[r] - fm[r]) / (2.0 * h)));
    }
    free(J);
    return worst;
}

START_TEST(jacobian_is_the_marchs)
{
    struct bench b = bench_new();
    const double disk[2] = {20.0, 1.0}, iwan[6] = {20.0, 10.0, 5.0, 0.2, 1.0, 3.0};
    const double dahl[2] = {20.0, 1.0}; /* sigma, fc */
    const struct {
        const char *name;
        size_t ns;
        const double *p;
        double scale, ksum;
    } cases[] = {{"jenkins_2d", 1, disk, 0.04, 20.0},  /* stuck */
                 {"jenkins_2d", 1, disk, 0.066, 20.0}, /* barely slipping */
                 {"jenkins_2d", 1, disk, 1.0, 20.0},   /* slipping */
                 {"jenkins_3d", 1, disk, 0.04, 20.0},  {"jenkins_3d", 1, disk, 1.0, 20.0},
                 {"iwan_2d", 3, iwan, 0.2, 35.0}, /* some sliders stick, some slip */
                 {"dahl", 1, dahl, 0.04, 20.0},   /* sigma A / fc near 1: a soft loop */
                 {"dahl", 1, dahl, 1.0, 20.0}};   /* saturated near fc */
    double worst = 0.0;
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const fricreg_element_type *T =
            fricreg_element_sliders(fricreg_element_lookup(cases[i].name), cases[i].ns);
        double u[3 * NC];
        orbit(fricreg_element_dim(T), cases[i].scale, u);
        double e = jacobian_error(b, T, cases[i].p, u);
        worst = fmax(worst, e / cases[i].ksum);
        ck_assert_msg(e <= 1e-8 * cases[i].ksum, "%s at scale %g: |J - differences| %g",
                      cases[i].name, cases[i].scale, e);
    }
    printf("jacobian_is_the_marchs: worst %.3g of the stiffness\n", worst);
    bench_free(b);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("aft_march");
    TCase *tc = tcase_create("march");
    tcase_add_test(tc, stuck_slider_is_centred);
    tcase_add_test(tc, stuck_disk_is_the_contacts);
    tcase_add_test(tc, jacobian_is_the_marchs);
    suite_add_tcase(s, tc);
    SRunner *sr = srunner_create(s);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
