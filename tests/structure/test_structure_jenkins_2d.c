/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_structure_jenkins_2d.c — Check suite for 2-D Jenkins elements as joints of a
 * fricreg_structure (fricreg_structure_set_jenkins_2d, _csr).
 *
 * Where the numbers come from:
 *   - an element whose motion stays on one axis is the 1-D element of set_jenkins on that row:
 *     the same histories to 1e-14 of the amplitude (Newmark, HHT-alpha, central difference,
 *     and beside a friction contact of bound > 0, the joint step);
 *   - the closed form of a 2-D Jenkins element on a circle of radius A in steady state: the
 *     slider runs on a circle of radius r_w with the spring q - w perpendicular to it
 *     (associative flow: w' parallel to f, |f| = mun), so A^2 = r_w^2 + (mun/kt)^2 and one
 *     cycle dissipates mun 2 pi r_w, r_w = sqrt(A^2 - (mun/kt)^2);
 *   - the standalone fricreg_jenkins (dim 2) driven by the structure's own displacements
 *     J_e u after each step gives the structure's forces and sliders to rounding;
 *   - average-acceleration Newmark's discrete energy balance closes with the elements'
 *     dissipation (FRICREG_SVALUE_JENKINS). */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg_jenkins.h"
#include "fricreg_structure.h"
#include "quiet_check.h"

static const double PI = 3.14159265358979323846;

/* A structure of n dofs, M, K, C dense, one contact on J0 of bound mu0, load p sin(omega t)
 * sampled every dt for nsteps steps. */
static fricreg_structure *make(size_t n, const double *M, const double *K, const double *C,
                               const double *J0, double mu0, const double *p, double omega,
                               double dt, int nsteps)
{
    fricreg_structure *s = NULL;
    ck_assert_int_eq(fricreg_structure_create(n, 1, &s), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_mass(s, n, M), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_stiffness(s, n, K), FRICREG_OK);
    if (C != NULL)
        ck_assert_int_eq(fricreg_structure_set_damping(s, n, C), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_contacts(s, 1, n, J0), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_bounds(s, 1, &mu0), FRICREG_OK);
    double *g = malloc(((size_t)nsteps + 1) * sizeof *g);
    ck_assert_ptr_nonnull(g);
    for (int k = 0; k <= nsteps; k++)
        g[k] = sin(omega * k * dt);
    ck_assert_int_eq(fricreg_structure_set_load(s, n, p, 0.0, dt, (size_t)nsteps + 1, g),
                     FRICREG_OK);
    free(g);
    ck_assert_int_eq(fricreg_structure_set_newton(s, 1e-13, 50), FRICREG_OK);
    return s;
}

/* Two uncoupled dofs, the load on x only: y stays at 0 and the 2-D element (rows x, y) moves on
 * its x axis only, the 1-D element on row x. Schemes: Newmark, HHT-alpha, central difference,
 * Newmark beside a contact (on y, where nothing moves... on x: bound > 0) of the joint step. */
START_TEST(one_axis_is_the_1d_element)
{
    const double M[4] = {1.3, 0.0, 0.0, 0.9}, K[4] = {2.385, 0.0, 0.0, 1.7},
                 C[4] = {0.12, 0.0, 0.0, 0.05}, p[2] = {0.6, 0.0}, J2[4] = {1.0, 0.0, 0.0, 1.0},
                 J1[2] = {1.0, 0.0}, kt = 1.7, mun = 0.35;
    const double omega = 1.5, dt = 2.0 * PI / omega / 256;
    const int nsteps = 256 * 20;
    for (int scheme = 0; scheme < 4; scheme++) {
        double mu0 = scheme == 3 ? 0.05 : 0.0;
        fricreg_structure *a = make(2, M, K, C, J1, mu0, p, omega, dt, nsteps),
                          *b = make(2, M, K, C, J1, mu0, p, omega, dt, nsteps);
        ck_assert_int_eq(fricreg_structure_set_jenkins_2d(a, 1, 2, J2, &kt, &mun), FRICREG_OK);
        ck_assert_int_eq(fricreg_structure_set_jenkins(b, 1, 2, J1, &kt, &mun), FRICREG_OK);
        if (scheme == 1) {
            ck_assert_int_eq(fricreg_structure_set_hht(a, -0.1), FRICREG_OK);
            ck_assert_int_eq(fricreg_structure_set_hht(b, -0.1), FRICREG_OK);
        } else if (scheme == 2) {
            ck_assert_int_eq(fricreg_structure_set_central_difference(a), FRICREG_OK);
            ck_assert_int_eq(fricreg_structure_set_central_difference(b), FRICREG_OK);
        }
        double amp = 0.0, du = 0.0, df = 0.0, dw = 0.0, wmax = 0.0;
        for (int k = 1; k <= nsteps; k++) {
            QUIET_OK(fricreg_structure_step(a, dt));
            QUIET_OK(fricreg_structure_step(b, dt));
            double ua[2], ub[2], fa[2], wa[2], fb, wb;
            fricreg_structure_get_state(a, 2, ua, NULL, NULL);
            fricreg_structure_get_state(b, 2, ub, NULL, NULL);
            QUIET_OK(fricreg_structure_get_jenkins_2d_state(a, 1, fa, wa, NULL));
            QUIET_OK(fricreg_structure_get_jenkins_state(b, 1, &fb, &wb, NULL));
            QUIET_CHECK(ua[1] == 0.0);
            QUIET_CHECK(fa[1] == 0.0);
            QUIET_CHECK(wa[1] == 0.0);
            amp = fmax(amp, fabs(ub[0]));
            wmax = fmax(wmax, fabs(wb));
            du = fmax(du, fabs(ua[0] - ub[0]));
            df = fmax(df, fabs(fa[0] - fb));
            dw = fmax(dw, fabs(wa[0] - wb));
        }
        double Da, Db;
        fricreg_structure_get_value(a, FRICREG_SVALUE_JENKINS, &Da);
        fricreg_structure_get_value(b, FRICREG_SVALUE_JENKINS, &Db);
        if (getenv("JENKINS_PRINT"))
            fprintf(stderr,
                    "one axis, scheme %d: |du| %.2e of %.3g, |df| %.2e, |dw| %.2e of %.3g, "
                    "D %.12g vs %.12g\n",
                    scheme, du, amp, df, dw, wmax, Da, Db);
        ck_assert(wmax > 0.1 * amp); /* the slider slipped */
        ck_assert_msg(du <= 1e-14 * amp, "scheme %d: |du| %g of %g", scheme, du, amp);
        ck_assert_msg(df <= 1e-14 * mun, "scheme %d: |df| %g", scheme, df);
        ck_assert_msg(dw <= 1e-14 * amp, "scheme %d: |dw| %g", scheme, dw);
        ck_assert_double_eq_tol(Da, Db, 1e-13 * Db);
        fricreg_structure_free(a);
        fricreg_structure_free(b);
    }
}
END_TEST

/* A mass on an isotropic stiff spring kg (2 dofs), started on the circle u = A (cos, sin) at
 * its natural frequency: the element (J_e = I) between the mass and the ground sees a circle of
 * radius |u| ~ A (the element's force mun moves it by mun/kg, its dissipation shrinks it by
 * ~1e-5 per cycle: the closed form takes each cycle's mean radius). */
START_TEST(circle_closed_form)
{
    const double kg = 1e6, mass = 1.0, kt = 3.0, mun = 0.5, A = 0.4;
    const double M[4] = {mass, 0.0, 0.0, mass}, K[4] = {kg, 0.0, 0.0, kg}, J[4] = {1, 0, 0, 1},
                 J0[2] = {1.0, 0.0}, p[2] = {0.0, 0.0};
    const double omega = sqrt(kg / mass), T = 2.0 * PI / omega;
    const int N = 2000, cycles = 4;
    const double dt = T / N;
    for (int scheme = 0; scheme < 2; scheme++) { /* Newmark; beside a contact of bound > 0 */
        double mu0 = scheme == 1 ? 1e-3 : 0.0;
        fricreg_structure *s = make(2, M, K, NULL, J0, mu0, p, omega, dt, 1);
        ck_assert_int_eq(fricreg_structure_set_jenkins_2d(s, 1, 2, J, &kt, &mun), FRICREG_OK);
        double u0[2] = {A, 0.0}, v0[2] = {0.0, A * omega};
        ck_assert_int_eq(fricreg_structure_set_initial(s, 2, u0, v0), FRICREG_OK);
        double Dprev = 0.0, worst = 0.0, fworst = 0.0;
        for (int c = 1; c <= cycles; c++) {
            double rsum = 0.0;
            for (int k = 0; k < N; k++) {
                ck_assert_int_eq(fricreg_structure_step(s, dt), FRICREG_OK);
                double u[2], f[2];
                fricreg_structure_get_state(s, 2, u, NULL, NULL);
                fricreg_structure_get_jenkins_2d_state(s, 1, f, NULL, NULL);
                rsum += hypot(u[0], u[1]);
                if (c > 1)
                    fworst = fmax(fworst, fabs(hypot(f[0], f[1]) - mun));
            }
            /* the discrete cycle: N steps of dth; the radial return's flow (w1 - w) is parallel
             * to f1, along the chord, which leaves the circle at dth/2 outward of the
             * tangent, so that A^2 = r_w^2 + a^2 + 2 r_w a sin(dth/2) (a = mun/kt); each step
             * dissipates the chord 2 r_w sin(dth/2) times mun (1 + cos dth)/2 (f and f1 dth
             * apart) */
            double D, r = rsum / N, a = mun / kt, rw = sqrt(r * r - a * a);
            double dth = 2.0 * atan(0.5 * omega * dt), sh = sin(0.5 * dth);
            double rwd = -a * sh + sqrt(a * a * sh * sh - a * a + r * r);
            double discrete = N * 2.0 * rwd * sh * mun * 0.5 * (1.0 + cos(dth));
            fricreg_structure_get_jenkins_2d_state(s, 1, NULL, NULL, &D);
            double got = D - Dprev, want = mun * 2.0 * PI * rw;
            Dprev = D;
            if (getenv("JENKINS_PRINT"))
                fprintf(stderr,
                        "circle, scheme %d, cycle %d: D %.10g, closed form %.10g (rel %.2e), "
                        "discrete %.10g (rel %.2e); (A - mun/kt) would give %.6g\n",
                        scheme, c, got, want, fabs(got / want - 1.0), discrete,
                        fabs(got / discrete - 1.0), mun * 2.0 * PI * (r - mun / kt));
            if (c > 1) {
                worst = fmax(worst, fabs(got / discrete - 1.0));
                /* the scheme's first-order lag: r_w - r_wd ~ a dth/2 */
                ck_assert_msg(fabs(got / want - 1.0) <= 1.1 * a * 0.5 * dth / rw,
                              "cycle %d: %.10g, closed form %.10g", c, got, want);
            }
        }
        if (getenv("JENKINS_PRINT"))
            fprintf(stderr, "circle, scheme %d: worst rel %.2e, max ||f| - mun| %.2e\n", scheme,
                    worst, fworst);
        ck_assert_msg(worst <= 1e-5, "scheme %d: dissipation off the closed form by %g", scheme,
                      worst);
        ck_assert_msg(fworst <= 1e-12 * mun, "full slip: |f| off mun by %g", fworst);
        double residual, input, initial;
        fricreg_structure_get_value(s, FRICREG_SVALUE_RESIDUAL, &residual);
        fricreg_structure_get_value(s, FRICREG_SVALUE_INITIAL, &initial);
        fricreg_structure_get_value(s, FRICREG_SVALUE_INPUT, &input);
        ck_assert_msg(fabs(residual) <= 1e-9 * initial, "residual %g of %g", residual, initial);
        fricreg_structure_free(s);
    }
}
END_TEST

/* Three dofs, two 2-D elements on general rows of J_e: after each step the standalone
 * fricreg_jenkins (dim 2) at q = J_e u from its own committed sliders gives the structure's
 * forces and sliders; the energy balance closes. */
START_TEST(standalone_at_the_structures_displacements)
{
    const double M[9] = {1.0, 0.0, 0.0, 0.0, 1.5, 0.0, 0.0, 0.0, 0.8},
                 K[9] = {3.0, -1.0, 0.0, -1.0, 2.5, -0.7, 0.0, -0.7, 1.9},
                 Je[12] = {1.0, -1.0, 0.0, 0.3, 0.5, 1.0, 0.0, 1.0, -0.4, -0.6, 0.2, 1.0},
                 J0[3] = {0.0, 1.0, 0.0}, p[3] = {0.9, -0.4, 0.6}, kt[2] = {2.0, 1.2},
                 mun[2] = {0.3, 0.2};
    const double omega = 1.1, dt = 0.01;
    const int nsteps = 3000;
    for (int scheme = 0; scheme < 4; scheme++) {
        double mu0 = scheme == 3 ? 0.1 : 0.0;
        fricreg_structure *s = make(3, M, K, NULL, J0, mu0, p, omega, dt, nsteps);
        ck_assert_int_eq(fricreg_structure_set_newton(s, 1e-15, 50), FRICREG_OK);
        ck_assert_int_eq(fricreg_structure_set_jenkins_2d(s, 2, 3, Je, kt, mun), FRICREG_OK);
        if (scheme == 1)
            ck_assert_int_eq(fricreg_structure_set_hht(s, -0.05), FRICREG_OK);
        else if (scheme == 2)
            ck_assert_int_eq(fricreg_structure_set_central_difference(s), FRICREG_OK);
        fricreg_jenkins *j = NULL;
        ck_assert_int_eq(fricreg_jenkins_create(2, 2, &j), FRICREG_OK);
        ck_assert_int_eq(fricreg_jenkins_set_params(j, 2, kt, mun), FRICREG_OK);
        double df = 0.0, dw = 0.0, wmax = 0.0, slips = 0.0;
        for (int k = 1; k <= nsteps; k++) {
            ck_assert_int_eq(fricreg_structure_step(s, dt), FRICREG_OK);
            double u[3], q[4] = {0}, f[4], w[4], fr[4], wr[4], wprev[4];
            fricreg_structure_get_state(s, 3, u, NULL, NULL);
            for (int r = 0; r < 4; r++)
                for (int c = 0; c < 3; c++)
                    q[r] += Je[3 * r + c] * u[c];
            ck_assert_int_eq(fricreg_structure_get_jenkins_2d_state(s, 2, f, w, NULL), FRICREG_OK);
            ck_assert_int_eq(fricreg_jenkins_get_slider(j, 2, wprev), FRICREG_OK);
            ck_assert_int_eq(fricreg_jenkins_trial(j, 2, q, fr, NULL), FRICREG_OK);
            ck_assert_int_eq(fricreg_jenkins_commit(j), FRICREG_OK);
            ck_assert_int_eq(fricreg_jenkins_get_slider(j, 2, wr), FRICREG_OK);
            for (int r = 0; r < 4; r++) {
                df = fmax(df, fabs(f[r] - fr[r]));
                dw = fmax(dw, fabs(w[r] - wr[r]));
                wmax = fmax(wmax, fabs(wr[r]));
                slips += wr[r] != wprev[r];
            }
        }
        double residual, input, D, Dsum[2];
        fricreg_structure_get_value(s, FRICREG_SVALUE_RESIDUAL, &residual);
        fricreg_structure_get_value(s, FRICREG_SVALUE_INPUT, &input);
        fricreg_structure_get_value(s, FRICREG_SVALUE_JENKINS, &D);
        ck_assert_int_eq(fricreg_structure_get_jenkins_state(s, 2, NULL, NULL, Dsum), FRICREG_OK);
        if (getenv("JENKINS_PRINT"))
            fprintf(stderr,
                    "standalone, scheme %d: |df| %.2e, |dw| %.2e of %.3g, %g slipping "
                    "components; D %.6g, input %.6g, residual %.2e\n",
                    scheme, df, dw, wmax, slips, D, input, residual);
        ck_assert(slips > 100.0);
        ck_assert_msg(df <= 1e-13 * mun[0], "scheme %d: |df| %g", scheme, df);
        ck_assert_msg(dw <= 1e-13 * wmax, "scheme %d: |dw| %g of %g", scheme, dw, wmax);
        ck_assert_double_eq_tol(Dsum[0] + Dsum[1], D, 1e-14 * D);
        ck_assert(D > 0.05 * input);
        if (scheme == 0 || scheme == 3) /* average acceleration: the discrete balance is exact */
            ck_assert_msg(fabs(residual) <= 1e-9 * input, "scheme %d: residual %g of input %g",
                          scheme, residual, input);
        fricreg_jenkins_free(j);
        fricreg_structure_free(s);
    }
}
END_TEST

/* Newton stops within its tolerance of the radial return's force, which is on the circle while
 * the element slips: its iterate lies on the tangent and so outside the disk (by 1e-9 relative
 * here, at any tolerance from 1e-2 to 1e-8: one Newton step is taken). The force the structure
 * feels and reports is held to the bound, |f| <= mun (resp. mu N, N from get_normal_forces)
 * to rounding, at every step of a slipping run with a loose tolerance: Newmark and the joint
 * step, the 2-D element and the 3-D contact. */
START_TEST(slipping_force_within_its_bound)
{
    const double M[4] = {1.0, 0.0, 0.0, 1.2}, K[4] = {2.0, 0.3, 0.3, 1.5}, J0[2] = {1.0, -1.0},
                 p[2] = {0.9, 0.6}, J[4] = {1.0, 0.0, 0.0, 1.0}, Jn[2] = {0.0, 0.5}, kt = 3.0,
                 mun = 0.3, n0 = 1.0, kn = 5.0, eps = 2.220446049250313e-16;
    const double omega = 1.3, dt = 0.02;
    const int nsteps = 3000;
    for (int scheme = 0; scheme < 4; scheme++) { /* bit 0: beside a contact; bit 1: normal law */
        int normal = scheme >= 2;
        fricreg_structure *s = make(2, M, K, NULL, J0, scheme % 2 ? 0.05 : 0.0, p, omega, dt,
                                    nsteps);
        ck_assert_int_eq(fricreg_structure_set_newton(s, 1e-4, 50), FRICREG_OK);
        if (normal)
            ck_assert_int_eq(fricreg_structure_set_jenkins_2d_normal(s, 1, 2, J, Jn, &kt, &mun, &n0,
                                                                     &kn),
                             FRICREG_OK);
        else
            ck_assert_int_eq(fricreg_structure_set_jenkins_2d(s, 1, 2, J, &kt, &mun), FRICREG_OK);
        double worst = 0.0;
        int slipping = 0, separated = 0;
        for (int k = 1; k <= nsteps; k++) {
            ck_assert_int_eq(fricreg_structure_step(s, dt), FRICREG_OK);
            double f[2], N = 1.0;
            ck_assert_int_eq(fricreg_structure_get_jenkins_2d_state(s, 1, f, NULL, NULL),
                             FRICREG_OK);
            if (normal)
                ck_assert_int_eq(fricreg_structure_get_normal_forces(s, 1, &N), FRICREG_OK);
            double bound = mun * N, r = hypot(f[0], f[1]);
            ck_assert(N >= 0.0); /* 0: lifted off, and then f = 0 */
            ck_assert_msg(r <= bound * (1.0 + 4.0 * eps),
                          "scheme %d, step %d: |f| = %.17g beyond its bound %.17g by %.2e", scheme,
                          k, r, bound, r / bound - 1.0);
            worst = bound > 0.0 ? fmax(worst, r / bound - 1.0) : worst;
            slipping += bound > 0.0 && r >= bound * (1.0 - 1e-12);
            separated += N == 0.0;
        }
        if (getenv("JENKINS_PRINT"))
            fprintf(
                stderr,
                "bound, scheme %d: %d steps slipping, %d separated, worst |f|/bound - 1 = %.2e\n",
                scheme, slipping, separated, worst);
        ck_assert_int_ge(slipping, 100);
        fricreg_structure_free(s);
    }
}
END_TEST

/* The CSR setter builds the same elements as the dense one; refusals and getters. */
START_TEST(csr_and_refusals)
{
    const double M[9] = {1.0, 0.0, 0.0, 0.0, 1.5, 0.0, 0.0, 0.0, 0.8},
                 K[9] = {3.0, -1.0, 0.0, -1.0, 2.5, -0.7, 0.0, -0.7, 1.9},
                 Je[6] = {1.0, -1.0, 0.0, 0.3, 0.5, 1.0}, J0[3] = {0.0, 1.0, 0.0},
                 p[3] = {0.9, -0.4, 0.6}, kt = 2.0, mun = 0.3;
    const double omega = 1.1, dt = 0.01;
    fricreg_structure *a = make(3, M, K, NULL, J0, 0.0, p, omega, dt, 500),
                      *b = make(3, M, K, NULL, J0, 0.0, p, omega, dt, 500);
    int64_t rowptr[3] = {0, 2, 5}, colind[5] = {0, 1, 0, 1, 2};
    double values[5] = {1.0, -1.0, 0.3, 0.5, 1.0};
    ck_assert_int_eq(fricreg_structure_set_jenkins_2d(a, 1, 3, Je, &kt, &mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_jenkins_2d_csr(b, 1, 3, 0, rowptr, colind, values, &kt,
                                                          &mun),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_run(a, dt, 5.0), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_run(b, dt, 5.0), FRICREG_OK);
    double fa[2], wa[2], fb[2], wb[2];
    fricreg_structure_get_jenkins_2d_state(a, 1, fa, wa, NULL);
    fricreg_structure_get_jenkins_2d_state(b, 1, fb, wb, NULL);
    for (int r = 0; r < 2; r++) {
        ck_assert_double_eq(fa[r], fb[r]);
        ck_assert_double_eq(wa[r], wb[r]);
    }
    ck_assert(fabs(wa[0]) + fabs(wa[1]) > 0.0);
    /* the 1-D getters refuse 2-D elements' f and w (of 2 me), the 2-D one 1-D elements; D
     * alone is read by both; run_ode refuses elements */
    double f[2] = {-1.0, -1.0}, D1 = -1.0, D2 = -2.0;
    ck_assert_int_eq(fricreg_structure_get_iwan_state(a, 1, 1, f, NULL, NULL), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_structure_get_jenkins_state(a, 1, f, NULL, NULL), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_structure_get_jenkins_state(a, 1, NULL, f, NULL), FRICREG_EINVAL);
    ck_assert_double_eq(f[0], -1.0);
    ck_assert_double_eq(f[1], -1.0);
    ck_assert_int_eq(fricreg_structure_get_jenkins_state(a, 1, NULL, NULL, &D1), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_get_jenkins_2d_state(a, 1, NULL, NULL, &D2), FRICREG_OK);
    ck_assert(D1 > 0.0 && D1 == D2);
    ck_assert_int_eq(fricreg_structure_get_jenkins_2d_state(a, 2, f, NULL, NULL), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_structure_get_jenkins_2d_state(a, 1, NULL, NULL, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_structure_get_normal_forces(a, 1, f), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_structure_run_ode(a, FRICREG_INT_RK4, 0.01, 0.0, 0.0, 5.1),
                     FRICREG_EINVAL);
    /* a zero row (the element's y axis) is refused, the elements in force kept */
    const double Jz[6] = {1.0, -1.0, 0.0, 0.0, 0.0, 0.0}, bad = -1.0;
    ck_assert_int_eq(fricreg_structure_set_jenkins_2d(a, 1, 3, Jz, &kt, &mun), FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_structure_errmsg(a), "row 1 of J_e is zero"));
    ck_assert_int_eq(fricreg_structure_set_jenkins_2d(a, 1, 3, Je, &bad, &mun), FRICREG_EINVAL);
    double fa2[2];
    ck_assert_int_eq(fricreg_structure_get_jenkins_2d_state(a, 1, fa2, NULL, NULL), FRICREG_OK);
    ck_assert_double_eq(fa2[0], fa[0]);
    /* the CSR setter reads 2 me rows: rowptr[2 me + 1] */
    int64_t short_ptr[3] = {0, 2, 2};
    ck_assert_int_eq(fricreg_structure_set_jenkins_2d_csr(b, 1, 3, 0, short_ptr, colind, values,
                                                          &kt, &mun),
                     FRICREG_EINVAL);
    /* me = 0 removes them; 1-D elements replace them */
    ck_assert_int_eq(fricreg_structure_set_jenkins_2d(a, 0, 3, NULL, NULL, NULL), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_get_jenkins_2d_state(a, 1, f, NULL, NULL), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_structure_get_jenkins_2d_state(a, 0, f, NULL, NULL), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_step(a, dt), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_jenkins(b, 1, 3, Je, &kt, &mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_step(b, dt), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_get_iwan_state(b, 1, 1, f, NULL, NULL), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_get_jenkins_2d_state(b, 1, f, NULL, NULL), FRICREG_EINVAL);
    fricreg_structure_free(a);
    fricreg_structure_free(b);
}
END_TEST

/* The error estimate's companion (fricreg_structure_set_error_estimate) copies the 2-D elements
 * with their two rows each: its estimates are 3 |q - q_c| bit for bit against a structure set up
 * by hand at eps / 2 and run at dt / 2, the element beside a contact of bound > 0. */
START_TEST(error_estimate_companion)
{
    const double M[4] = {1.3, 0.0, 0.0, 0.9}, K[4] = {2.385, 0.4, 0.4, 1.7}, p[2] = {0.6, 0.3},
                 J2[4] = {1.0, 0.0, 0.0, 1.0}, J0[2] = {1.0, -1.0}, kt = 1.7, mun = 0.35,
                 eps = 1e-2;
    const double omega = 1.5, dt = 2.0 * PI / omega / 128;
    const int nsteps = 128 * 4;
    fricreg_structure *s = make(2, M, K, NULL, J0, 0.05, p, omega, dt, nsteps),
                      *c = make(2, M, K, NULL, J0, 0.05, p, omega, dt, nsteps);
    ck_assert_int_eq(fricreg_structure_set_law(s, FRICREG_LAW_QUINN, eps), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_law(c, FRICREG_LAW_QUINN, 0.5 * eps), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_jenkins_2d(s, 1, 2, J2, &kt, &mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_jenkins_2d(c, 1, 2, J2, &kt, &mun), FRICREG_OK);
    /* one companion: 3 |q - q_c| against a companion made by hand (the two companions'
     * estimate from the same first companion: test_structure_error.c) */
    ck_assert_int_eq(fricreg_structure_set_error_estimate(s, FRICREG_ESTIMATE_ONE_COMPANION),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_error_companions(s, FRICREG_COMPANIONS_FINER),
                     FRICREG_OK); /* the finer estimator, not the default's screen */
    ck_assert_int_eq(fricreg_structure_run(s, dt, nsteps * dt), FRICREG_OK);
    double t = 0.0;
    ck_assert_int_eq(fricreg_structure_get_value(s, FRICREG_SVALUE_TIME, &t), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_run(c, 0.5 * dt, t), FRICREG_OK);
    double u[2], uc[2], err[2], w[2];
    ck_assert_int_eq(fricreg_structure_get_peak_displacement(s, 2, u), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_get_peak_displacement(c, 2, uc), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_get_peak_displacement_error(s, 2, err), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_get_jenkins_2d_state(c, 1, NULL, w, NULL), FRICREG_OK);
    ck_assert(fabs(w[0]) > 0.0 && fabs(w[1]) > 0.0); /* the companion's slider moved on both axes */
    for (int i = 0; i < 2; i++) {
        ck_assert(err[i] > 0.0);
        ck_assert_double_eq(err[i], 3.0 * fabs(u[i] - uc[i]));
    }
    fricreg_structure_free(c);
    fricreg_structure_free(s);
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("structure_jenkins_2d");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, one_axis_is_the_1d_element);
    tcase_add_test(tc, circle_closed_form);
    tcase_add_test(tc, standalone_at_the_structures_displacements);
    tcase_add_test(tc, slipping_force_within_its_bound);
    tcase_add_test(tc, csr_and_refusals);
    tcase_add_test(tc, error_estimate_companion);
    suite_add_tcase(s, tc);
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
