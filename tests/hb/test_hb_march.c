/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_hb_march.c — Check suite for harmonic balance on element types it knows only by their
 * eval (fricreg_hb_add_elements of a type without an AFT of HB's own: the march of
 * src/joint/aft_march.c), so that a new law of fricreg_element.h runs in HB from its one file.
 *
 * Where the numbers come from:
 *   - spring (f = k u, no state: the exact tangent) on a 2-dof block is the linear system
 *     with k J^T J added to K: its harmonic 1 equals the closed form
 *     X = (K + k J^T J - Omega^2 M + i Omega C)^-1 (pc - i ps) to 1e-12, the others are 0;
 *   - jenkins_2d on a block moved along one axis only is the 1-D Jenkins element, whose HB
 *     AFT is exact (fricreg_aft_iwan_exact): the marched law's harmonics agree to 2e-4 of
 *     their scale at H = 3 (N = 512 samples; measured below 5e-5: the samples' lag after
 *     Richardson's extrapolation), while slipping, swept and solved once from the exact
 *     element's solution (the case valgrind runs);
 *   - jenkins_2d on a 2-D orbit equals HB's own sampled 3-D contact element (contact_3d with
 *     kn = 0 and n0 mu = mun: the same disk at a constant normal force, its normal row on a
 *     dof of its own) to 1e-9 of the scale: the same return mapping at the same samples, one
 *     marched by eval, the other by fricreg_aft_jenkins_2d_normal_sampled; and its Jacobian is
 *     Newton's: a solve from the solution at a nearby Ω converges in 6 iterations (5 measured;
 *     test_aft_march checks the Jacobian itself against differences);
 *   - a model mixing a spring, a marched jenkins_2d and an exact Jenkins element on decoupled
 *     blocks: each block equals its own model to 1e-12 of its scale;
 *   - stability of a marched model is Hill's method (the monodromy refused with a message), a
 *     continuation, a truncation error (the clone at 2H + 1) and a backbone run;
 *   - NLvib's chain with jenkins_2d elements continued through the onset of stick: each dof's
 *     peak equals the exact jenkins run's to 2e-4 in RMS (chain_through_stick);
 *   - dahl (a law with state not built from sliders: its own state tangents, marched through
 *     the orbit's turns) on one dof at three frequencies: the dissipation per period from HB's
 *     power balance equals the law's loop on the same orbit marched in time at 2^15 samples a
 *     period to 1e-6 (measured 7e-9, the time march's own trapezoid error). */
#include <check.h>
#include <complex.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg_element.h"
#include "fricreg_hb.h"
#include "hb_chain.h"
#include "quiet_check.h"

#define H 3
#define NC (2 * H + 1)

static fricreg_hb *driver(size_t n, size_t me, const double *M, const double *K, const double *C,
                          const double *pc, const double *ps)
{
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(n, me, H, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, n, M), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, n, K), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_damping(hb, n, C), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_excitation(hb, n, pc, ps), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_newton(hb, 1e-12, 50), FRICREG_OK);
    return hb;
}

static void add(fricreg_hb *hb, const char *name, size_t n, const double *J, const double *p)
{
    ck_assert_int_eq(fricreg_hb_add_elements(hb, fricreg_element_lookup(name), 1, n, J, p),
                     FRICREG_OK);
}

/* The largest |a - b| over n entries, and the largest |b| into *scale. */
static double largest_difference(const double *a, const double *b, size_t n, double *scale)
{
    double d = 0.0;
    *scale = 0.0;
    for (size_t i = 0; i < n; i++) {
        d = fmax(d, fabs(a[i] - b[i]));
        *scale = fmax(*scale, fabs(b[i]));
    }
    return d;
}

/* The 2-dof block: masses 1 and 1.2 coupled by K, Rayleigh damping. */
static const double M2[4] = {1.0, 0.0, 0.0, 1.2}, K2[4] = {3.0, -1.0, -1.0, 2.0};

static void damping(const double *M, const double *K, size_t n, double *C)
{
    for (size_t i = 0; i < n * n; i++)
        C[i] = 0.02 * M[i] + 0.01 * K[i];
}

START_TEST(spring_is_linear)
{
    static const double J[2] = {1.0, -1.0}, k = 0.7, pc[2] = {0.5, 0.0}, ps[2] = {0.0, 0.3};
    double C[4], x[2 * NC], q[NC];
    damping(M2, K2, 2, C);
    fricreg_hb *hb = driver(2, 1, M2, K2, C, pc, ps);
    add(hb, "spring", 2, J, &k);
    for (double omega = 0.8; omega < 2.0; omega += 0.5) {
        ck_assert_int_eq(fricreg_hb_solve(hb, omega, NC, NULL, q), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_displacement(hb, 2, NC, x), FRICREG_OK);
        double complex D[4], P[2] = {pc[0] - I * ps[0], pc[1] - I * ps[1]};
        for (int i = 0; i < 4; i++)
            D[i] = K2[i] + k * J[i / 2] * J[i % 2] - omega * omega * M2[i] + I * omega * C[i];
        double complex det = D[0] * D[3] - D[1] * D[2];
        double complex X[2] = {(D[3] * P[0] - D[1] * P[1]) / det,
                               (D[0] * P[1] - D[2] * P[0]) / det};
        for (int d = 0; d < 2; d++)
            for (int c = 0; c < NC; c++) {
                double want = c == 1 ? creal(X[d]) : c == 2 ? -cimag(X[d]) : 0.0;
                ck_assert_msg(fabs(x[d * NC + c] - want) <= 1e-12 * cabs(X[0]),
                              "Omega %g dof %d coefficient %d: %.17g, closed form %.17g", omega, d,
                              c, x[d * NC + c], want);
            }
    }
    fricreg_hb_free(hb);
}
END_TEST

/* A block of two dofs x, y with jenkins_2d on both (marched), or jenkins on x (exact). */
START_TEST(disk_on_a_line_is_jenkins)
{
    static const double M[4] = {1.0, 0.0, 0.0, 1.0}, K[4] = {2.0, 0.0, 0.0, 3.0};
    static const double pc[2] = {0.5, 0.0}, ps[2] = {0.0, 0.0}, p[2] = {1.5, 0.2};
    static const double J2[4] = {1.0, 0.0, 0.0, 1.0}, J1[2] = {1.0, 0.0};
    double C[4], xm[2 * NC], xe[2 * NC], q[2 * NC], qe[NC], worst = 0.0;
    damping(M, K, 2, C);
    fricreg_hb *marched = driver(2, 1, M, K, C, pc, ps), *exact = driver(2, 1, M, K, C, pc, ps);
    add(marched, "jenkins_2d", 2, J2, p);
    add(exact, "jenkins", 2, J1, p);
    for (double omega = 0.9; omega < 2.0; omega += 0.4) { /* the slider slips at each */
        /* each solve from the last (the default start's routes cost a marched law
         * thousands of Jacobians) */
        ck_assert_int_eq(fricreg_hb_solve(marched, omega, 2 * NC, omega > 0.9 ? q : NULL, q),
                         FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_solve(exact, omega, NC, NULL, qe), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_displacement(marched, 2, NC, xm), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_displacement(exact, 2, NC, xe), FRICREG_OK);
        double scale, d = largest_difference(xm, xe, 2 * NC, &scale);
        ck_assert_double_gt(1.5 * fabs(xe[1]), p[1] / p[0]); /* beyond the slip amplitude */
        worst = fmax(worst, d / scale);
        ck_assert_msg(d <= 2e-4 * scale, "Omega %g: %g of %g", omega, d, scale);
    }
    printf("disk_on_a_line_is_jenkins: worst %.3g of the scale\n", worst);
    fricreg_hb_free(marched);
    fricreg_hb_free(exact);
}
END_TEST

/* The same from the exact element's solution as a guess (its x rows, y at rest): one marched
 * solve, the march of a law with state and its implicit Jacobian in a case small enough for
 * valgrind. */
START_TEST(disk_from_a_guess)
{
    static const double M[4] = {1.0, 0.0, 0.0, 1.0}, K[4] = {2.0, 0.0, 0.0, 3.0};
    static const double pc[2] = {0.5, 0.0}, ps[2] = {0.0, 0.0}, p[2] = {1.5, 0.2};
    static const double J2[4] = {1.0, 0.0, 0.0, 1.0}, J1[2] = {1.0, 0.0};
    double C[4], xm[2 * NC], xe[2 * NC], q[2 * NC] = {0}, qe[NC];
    damping(M, K, 2, C);
    fricreg_hb *marched = driver(2, 1, M, K, C, pc, ps), *exact = driver(2, 1, M, K, C, pc, ps);
    add(marched, "jenkins_2d", 2, J2, p);
    add(exact, "jenkins", 2, J1, p);
    ck_assert_int_eq(fricreg_hb_solve(exact, 1.3, NC, NULL, qe), FRICREG_OK);
    memcpy(q, qe, sizeof qe);
    ck_assert_int_eq(fricreg_hb_solve(marched, 1.3, 2 * NC, q, q), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_displacement(marched, 2, NC, xm), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_displacement(exact, 2, NC, xe), FRICREG_OK);
    double scale, d = largest_difference(xm, xe, 2 * NC, &scale);
    ck_assert_msg(d <= 2e-4 * scale, "%g of %g", d, scale);
    fricreg_hb_free(marched);
    fricreg_hb_free(exact);
}
END_TEST

/* Dofs x, y, z (z the contact's normal, its own spring); forced on x and y, out of phase. */
START_TEST(disk_is_contact_at_fixed_normal)
{
    static const double M[9] = {1, 0, 0, 0, 1.2, 0, 0, 0, 1};
    static const double K[9] = {2, -0.5, 0, -0.5, 2.5, 0, 0, 0, 4};
    static const double pc[3] = {0.5, 0.0, 0.0}, ps[3] = {0.0, 0.4, 0.0};
    static const double J3[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, J2[6] = {1, 0, 0, 0, 1, 0};
    static const double n0 = 2.0, disk[2] = {1.5, 0.3}, contact[5] = {1.5, 0.15, 0.0, 2.0, 0.0};
    double C[9], xm[3 * NC], xc[3 * NC], q[2 * NC], qc[3 * NC], worst = 0.0;
    damping(M, K, 3, C);
    fricreg_hb *marched = driver(3, 1, M, K, C, pc, ps), *sampled = driver(3, 1, M, K, C, pc, ps);
    ck_assert_double_eq(contact[1] * n0, disk[1]);
    add(marched, "jenkins_2d", 3, J2, disk);
    add(sampled, "contact_3d", 3, J3, contact);
    for (double omega = 1.0; omega < 2.0; omega += 0.3) {
        ck_assert_int_eq(fricreg_hb_solve(marched, omega, 2 * NC, omega > 1.0 ? q : NULL, q),
                         FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_solve(sampled, omega, 3 * NC, NULL, qc), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_displacement(marched, 3, NC, xm), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_displacement(sampled, 3, NC, xc), FRICREG_OK);
        double scale, d = largest_difference(xm, xc, 2 * NC, &scale); /* x and y */
        worst = fmax(worst, d / scale);
        ck_assert_msg(d <= 1e-9 * scale, "Omega %g: %g of %g", omega, d, scale);
    }
    printf("disk_is_contact_at_fixed_normal: worst %.3g of the scale\n", worst);
    /* the marched Jacobian is Newton's: from the solution at 1.3, the one at 1.4 within 6
     * iterations to 1e-12 (measured 5, as with 1.8's earlier Jacobian by differences, which
     * took 34 without the implicit function theorem's term) */
    double q13[2 * NC];
    ck_assert_int_eq(fricreg_hb_solve(marched, 1.3, 2 * NC, q, q13), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_max_iterations(marched, 6), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_solve(marched, 1.4, 2 * NC, q13, q), FRICREG_OK);
    fricreg_hb_free(marched);
    fricreg_hb_free(sampled);
}
END_TEST

/* Three 2-dof blocks: a spring, a marched jenkins_2d on one row each, an exact Jenkins. */
#define NB 6
static fricreg_hb *mix_or_block(int block)
{
    static const double p_spring = 0.7, p_disk[2] = {1.5, 0.05}, p_jenkins[2] = {2.0, 0.1};
    static const double pc[NB] = {0.5, 0.2, 0.6, 0.1, 0.3, 0.4};
    double M[NB * NB] = {0}, K[NB * NB] = {0}, C[NB * NB], ps[NB] = {0};
    size_t n = block < 0 ? NB : 2;
    for (int b = 0; b < 3; b++) {
        size_t at = block < 0 ? 2 * (size_t)b : 0;
        if (block >= 0 && b != block)
            continue;
        for (int i = 0; i < 4; i++) {
            M[(at + (size_t)i / 2) * n + at + (size_t)i % 2] = M2[i];
            K[(at + (size_t)i / 2) * n + at + (size_t)i % 2] = K2[i];
        }
    }
    damping(M, K, n, C);
    const double *p = block < 0 ? pc : pc + 2 * block;
    fricreg_hb *hb = driver(n, block < 0 ? 3 : 1, M, K, C, p, ps);
    for (int b = 0; b < 3; b++) {
        if (block >= 0 && b != block)
            continue;
        double J[2 * NB] = {0};
        size_t at = block < 0 ? 2 * (size_t)b : 0;
        J[at] = 1.0;
        J[at + 1] = -1.0;
        if (b == 1) /* the disk's second row: the second mass alone */
            J[n + at + 1] = 1.0;
        if (b == 0)
            add(hb, "spring", n, J, &p_spring);
        else if (b == 1)
            add(hb, "jenkins_2d", n, J, p_disk);
        else
            add(hb, "jenkins", n, J, p_jenkins);
    }
    return hb;
}

START_TEST(mix_equals_blocks)
{
    fricreg_hb *mix = mix_or_block(-1);
    double x[NB * NC], xb[2 * NC], q[4 * NC], worst = 0.0;
    ck_assert_int_eq(fricreg_hb_solve(mix, 1.3, 4 * NC, NULL, q), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_displacement(mix, NB, NC, x), FRICREG_OK);
    for (int b = 0; b < 3; b++) {
        fricreg_hb *alone = mix_or_block(b);
        size_t nq = (b == 1 ? 2 : 1) * NC;
        ck_assert_int_eq(fricreg_hb_solve(alone, 1.3, nq, NULL, q), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_displacement(alone, 2, NC, xb), FRICREG_OK);
        double scale, d = largest_difference(x + 2 * (size_t)b * NC, xb, 2 * NC, &scale);
        worst = fmax(worst, d / scale);
        ck_assert_msg(d <= 1e-12 * scale, "block %d: %g of %g", b, d, scale);
        fricreg_hb_free(alone);
    }
    printf("mix_equals_blocks: worst %.3g of the scale\n", worst);
    fricreg_hb_free(mix);
}
END_TEST

START_TEST(stability_and_truncation)
{
    fricreg_hb *hb = mix_or_block(1);
    int method = -1, stable = -1;
    double mu_max = 0.0, rms[2], q[2 * NC];
    ck_assert_int_eq(fricreg_hb_get_stability_method(hb, &method), FRICREG_OK);
    ck_assert_int_eq(method, FRICREG_HB_STABILITY_HILL);
    ck_assert_int_eq(fricreg_hb_set_stability(hb, 1), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_newton(hb, 1e-10, 50), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_continue(hb, 1.2, 1.4, 2 * NC, NULL), FRICREG_OK);
    ck_assert_uint_gt(fricreg_hb_points(hb), 2);
    ck_assert_int_eq(fricreg_hb_point_stability(hb, 0, &stable, &mu_max), FRICREG_OK);
    ck_assert_int_eq(stable, 1); /* damped, forced away from its resonances */
    ck_assert_double_lt(mu_max, 1.0);
    ck_assert_int_eq(fricreg_hb_truncation_error(hb, 0, 2, rms, NULL), FRICREG_OK);
    ck_assert(rms[0] >= 0.0 && rms[0] < 1e-2);
    /* the nonlinear modes take a marched element (its stiffness at rest from its law) */
    ck_assert_int_eq(fricreg_hb_nma(hb, 0, FRICREG_HB_NMA_DAMPING_MATRIX, 0.01, 1.0, 6),
                     FRICREG_OK);
    ck_assert_uint_eq(fricreg_hb_nma_points(hb), 6);
    ck_assert_int_eq(fricreg_hb_set_stability_method(hb, FRICREG_HB_STABILITY_MONODROMY),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_solve(hb, 1.3, 2 * NC, NULL, q), FRICREG_EINVAL);
    fricreg_hb_free(hb);
}
END_TEST

/* NLvib's chain (hb_chain.h), marched and exact, at H = 7: the default continuation from 0.5
 * to 2 rad/s crosses the onset of stick near 1.3938, where
 * the march's exact Jacobian and centred stuck sliders (and the continuation's acceptance of
 * a fold too fine to resolve, fricreg_hb_set_continuation) carry it through; each dof's peak
 * then equals the exact AFT's to 2e-4 in RMS and 1e-3 in Omega (measured 6.3e-5 and 3.7e-4:
 * the samples' lag, as disk_on_a_line_is_jenkins's). Until 1.8 it stopped at 1.39377. */
START_TEST(chain_through_stick)
{
    fricreg_hb *marched = hb_chain(1, 0), *exact = hb_chain(0, 0);
    double worst_rms = 0.0, worst_omega = 0.0;
    ck_assert_ptr_nonnull(marched);
    ck_assert_ptr_nonnull(exact);
    ck_assert_int_eq(fricreg_hb_continue(exact, 0.5, 2.0, hb_chain_nq(0), NULL), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_continue(marched, 0.5, 2.0, hb_chain_nq(1), NULL), FRICREG_OK);
    for (size_t dof = 0; dof < 3; dof++) {
        double om_m, rms_m, om_e, rms_e;
        ck_assert_int_eq(fricreg_hb_peak(marched, dof, &om_m, &rms_m), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_peak(exact, dof, &om_e, &rms_e), FRICREG_OK);
        worst_rms = fmax(worst_rms, fabs(rms_m - rms_e) / rms_e);
        worst_omega = fmax(worst_omega, fabs(om_m - om_e) / om_e);
        ck_assert_msg(fabs(rms_m - rms_e) <= 2e-4 * rms_e && fabs(om_m - om_e) <= 1e-3 * om_e,
                      "dof %zu: peak %.9g at %.9g, exact %.9g at %.9g", dof, rms_m, om_m, rms_e,
                      om_e);
    }
    printf("chain_through_stick: peaks within %.3g in RMS, %.3g in Omega\n", worst_rms,
           worst_omega);
    fricreg_hb_free(marched);
    fricreg_hb_free(exact);
}
END_TEST

/* The dissipation per period of a dahl element on the periodic orbit u[NC] (H harmonics),
 * marched by its eval at 2^15 samples a period until the state repeats (to 1e-15 of the orbit's
 * scale): the trapezoid's sum of f du (its error 1e-9 of the loop at this step). */
static double dahl_loop_in_time(const double *p, const double *u)
{
    enum { STEPS = 1 << 15 };
    const fricreg_element_type *T = fricreg_element_lookup("dahl");
    static double x[STEPS + 1];
    double scale = 0.0, w[2] = {0.0, 0.0}, D = 0.0;
    for (int n = 0; n <= STEPS; n++) {
        double t = 6.283185307179586 * n / STEPS;
        x[n] = u[0];
        for (int h = 1; h <= H; h++)
            x[n] += u[2 * h - 1] * cos(h * t) + u[2 * h] * sin(h * t);
        scale = fmax(scale, fabs(x[n]));
    }
    for (int period = 0; period < 50; period++) {
        double f_prev = 0.0, last[2] = {w[0], w[1]};
        D = 0.0;
        for (int n = 0; n <= STEPS; n++) {
            double f[1];
            QUIET_OK(fricreg_element_eval(T, p, w, &x[n], f, NULL, NULL, w));
            if (n > 0)
                D += 0.5 * (f[0] + f_prev) * (x[n] - x[n - 1]);
            f_prev = f[0];
        }
        if (period > 0 && fabs(w[0] - last[0]) <= 1e-15 * scale &&
            fabs(w[1] - last[1]) <= 1e-15 * scale)
            break;
    }
    return D;
}

/* dahl (state not built from sliders, marched with its own state tangents) on one dof: the
 * dissipation per period harmonic balance gives, from its power balance (the load's input
 * minus the viscous loss), equals the law's own loop on the same orbit marched in time. */
START_TEST(dahl_loop_is_the_orbits)
{
    static const double M[1] = {1.0}, K[1] = {1.0}, C[1] = {0.02}, pc[1] = {0.4}, ps[1] = {0.0};
    static const double J[1] = {1.0}, p[2] = {2.0, 0.3}; /* sigma, fc */
    fricreg_hb *hb = driver(1, 1, M, K, C, pc, ps);
    add(hb, "dahl", 1, J, p);
    const double omegas[3] = {0.9, 1.2, 1.6};
    double q[NC] = {0.0}, guess[NC];
    for (int i = 0; i < 3; i++) { /* the next frequency from the last solution */
        double x[NC], omega = omegas[i];
        memcpy(guess, q, sizeof q);
        ck_assert_int_eq(fricreg_hb_solve(hb, omega, NC, i > 0 ? guess : NULL, q), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_displacement(hb, 1, NC, x), FRICREG_OK);
        double viscous = 0.0;
        for (int h = 1; h <= H; h++)
            viscous += h * h * (x[2 * h - 1] * x[2 * h - 1] + x[2 * h] * x[2 * h]);
        double D_hb = 0.5 * 6.283185307179586 * (pc[0] * x[2] - C[0] * omega * viscous);
        double D_time = dahl_loop_in_time(p, x);
        ck_assert_msg(fabs(D_hb - D_time) <= 1e-6 * D_time, "Omega %g: D %.12g HB, %.12g time",
                      omega, D_hb, D_time);
    }
    fricreg_hb_free(hb);
}
END_TEST

START_TEST(bad_law_refused)
{
    fricreg_hb *hb = NULL;
    static const double J[2] = {1.0, -1.0};
    double k = -1.0;
    ck_assert_int_eq(fricreg_hb_create(2, 1, H, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_add_elements(hb, fricreg_element_lookup("spring"), 1, 2, J, &k),
                     FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_hb_errmsg(hb), "element 0 (spring)"));
    ck_assert_uint_eq(fricreg_hb_element_count(hb), 0);
    fricreg_hb_free(hb);
}
END_TEST

static Suite *suite(void)
{
    /* release: the release tier's (hb_march_release), thousands of marched periods each: the
     * 2-D orbit at four frequencies (8 s) and the chain's continuation at H = 7 (16 s); the
     * quick tier marches the same law in axis and mix. The cases' timeout is the entry's
     * (CK_DEFAULT_TIMEOUT, five times longer in the sanitizer tree, where chain takes 90 s). */
    const struct {
        const char *name;
        const TTest *test;
        int release;
    } cases[] = {
        {"spring", spring_is_linear, 0},        {"spring", bad_law_refused, 0},
        {"dahl", dahl_loop_is_the_orbits, 0},   {"spring", disk_from_a_guess, 0},
        {"axis", disk_on_a_line_is_jenkins, 0}, {"orbit", disk_is_contact_at_fixed_normal, 1},
        {"mix", mix_equals_blocks, 0},          {"stability", stability_and_truncation, 0},
        {"chain", chain_through_stick, 1}};
    Suite *s = suite_create("hb_march");
    TCase *tc = NULL;
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        if (i == 0 || strcmp(cases[i].name, cases[i - 1].name) != 0) {
            tc = tcase_create(cases[i].name);
            if (cases[i].release)
                tcase_set_tags(tc, "release");
            suite_add_tcase(s, tc);
        }
        tcase_add_test(tc, cases[i].test);
    }
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
