/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_contact3d.c — Check suite for the 3-D contact element: a 2-D Jenkins element (the
 * tangential plane) with a normal load and lift-off, alone (fricreg_jenkins of dim 2 with
 * fricreg_jenkins_set_normal) and as a joint of a fricreg_structure
 * (fricreg_structure_set_jenkins_2d_normal).
 *
 * Where the numbers come from:
 *   - on one tangential axis under a constant normal force the element is the 1-D Jenkins
 *     element of bound mu N: the same return mapping (|d| of (d, 0) is |d| exactly), so bit for
 *     bit alone; in a structure whose normal dof rests at its equilibrium, to rounding;
 *   - a circular orbit u = r (cos th, sin th): in steady sliding the slider runs on a circle of
 *     radius r_w with the spring u - w (length a = mu N/kt) along the slider's velocity, so
 *     r^2 = r_w^2 + a^2 and a cycle dissipates mu N 2 pi r_w, r_w = sqrt(r^2 - a^2) (not
 *     r - a, a radial lag); the time-discrete radial return moves the slider along chords,
 *     r^2 = r_w^2 + a^2 + 2 r_w a sin(dth/2), first order in the step;
 *   - lift-off: an independent time march of the rule (N = max(0, n0 + kn g), separated:
 *     w = u, f = 0; closed: the radial return) written here;
 *   - the exact tangent against centred differences of the force;
 *   - the structure against the standalone element driven by the structure's own q and g;
 *   - the error estimate's companion against a structure set up by hand at eps/2, dt/2. */
#include <check.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg_jenkins.h"
#include "fricreg_structure.h"
#include "quiet_check.h"

static const double PI = 3.14159265358979323846;

/* One element of dim 2 with the normal law (mu, n0, kn) and kt. */
static fricreg_jenkins *element(double kt, double mu, double n0, double kn)
{
    fricreg_jenkins *j = NULL;
    double one = 1.0;
    ck_assert_int_eq(fricreg_jenkins_create(2, 1, &j), FRICREG_OK);
    ck_assert_int_eq(fricreg_jenkins_set_params(j, 1, &kt, &one), FRICREG_OK);
    ck_assert_int_eq(fricreg_jenkins_set_normal(j, 1, &mu, &n0, &kn), FRICREG_OK);
    return j;
}

/* (a) alone: u = (A sin t, 0), g = 0, bound mu n0, against the 1-D element of mun = mu n0. */
START_TEST(one_axis_is_jenkins_1d)
{
    const double kt = 1.7, mu = 0.35, n0 = 2.385, kn = 40.0, mun = mu * n0, A = 1.3;
    fricreg_jenkins *j3 = element(kt, mu, n0, kn), *j1 = NULL;
    ck_assert_int_eq(fricreg_jenkins_create(1, 1, &j1), FRICREG_OK);
    ck_assert_int_eq(fricreg_jenkins_set_params(j1, 1, &kt, &mun), FRICREG_OK);
    int slips = 0;
    for (int k = 0; k <= 1000; k++) {
        double x = A * sin(0.0137 * k), u[2] = {x, 0.0}, g = 0.0, f[2], N, t[4], tg[2], f1, t1;
        ck_assert_int_eq(fricreg_jenkins_trial_normal(j3, 1, u, &g, f, &N, t, tg), FRICREG_OK);
        ck_assert_int_eq(fricreg_jenkins_trial(j1, 1, &x, &f1, &t1), FRICREG_OK);
        ck_assert_double_eq(f[0], f1);
        ck_assert_double_eq(f[1], 0.0);
        ck_assert_double_eq(t[0], t1 == 0.0 ? 0.0 : kt); /* slip: (I - n n^T)_xx = 0 */
        ck_assert_double_eq(N, n0);
        slips += fabs(f1) == mun;
        ck_assert_int_eq(fricreg_jenkins_commit(j3), FRICREG_OK);
        ck_assert_int_eq(fricreg_jenkins_commit(j1), FRICREG_OK);
        double w3[2], w1;
        fricreg_jenkins_get_slider(j3, 1, w3);
        fricreg_jenkins_get_slider(j1, 1, &w1);
        ck_assert_double_eq(w3[0], w1);
        ck_assert_double_eq(w3[1], 0.0);
    }
    ck_assert_int_gt(slips, 100);
    fricreg_jenkins_free(j3);
    fricreg_jenkins_free(j1);
}
END_TEST

/* Steady dissipation per cycle on the orbit u = r (cos th, sin th), g = 0, nsamp samples a
 * cycle, booked as the structure does: sum (w1 - w) . (f + f1)/2 over the last of 8 cycles. */
static double orbit_dissipation(double kt, double mun, double r, int nsamp)
{
    fricreg_jenkins *j = element(kt, 1.0, mun, 3.0);
    double u[2] = {r, 0.0}, g = 0.0, f[2], fprev[2], w[2], wprev[2], D = 0.0;
    ck_assert_int_eq(fricreg_jenkins_trial_normal(j, 1, u, &g, fprev, NULL, NULL, NULL),
                     FRICREG_OK);
    fricreg_jenkins_commit(j);
    fricreg_jenkins_get_slider(j, 1, wprev);
    for (int c = 0; c < 8; c++) {
        D = 0.0;
        for (int k = 1; k <= nsamp; k++) {
            double th = 2.0 * PI * k / nsamp;
            u[0] = r * cos(th);
            u[1] = r * sin(th);
            QUIET_OK(fricreg_jenkins_trial_normal(j, 1, u, &g, f, NULL, NULL, NULL));
            fricreg_jenkins_commit(j);
            fricreg_jenkins_get_slider(j, 1, w);
            for (int a = 0; a < 2; a++) {
                D += (w[a] - wprev[a]) * 0.5 * (fprev[a] + f[a]);
                wprev[a] = w[a];
                fprev[a] = f[a];
            }
        }
    }
    fricreg_jenkins_free(j);
    return D;
}

/* (b) the circular orbit: the discrete closed form to rounding, the continuous one at first
 * order in the step. */
START_TEST(orbit_closed_form)
{
    const double kt = 3.0, mun = 0.5, r = 0.4, a = mun / kt, rw = sqrt(r * r - a * a);
    const double want = 2.0 * PI * rw * mun; /* 1.14235... */
    double err[5];
    for (int l = 0; l < 5; l++) {
        int nsamp = 100 << l;
        double D = orbit_dissipation(kt, mun, r, nsamp);
        double dth = 2.0 * PI / nsamp, sh = sin(0.5 * dth);
        double rwd = -a * sh + sqrt(a * a * sh * sh + r * r - a * a);
        double discrete = nsamp * 2.0 * rwd * sh * mun * 0.5 * (1.0 + cos(dth));
        err[l] = fabs(D / want - 1.0);
        if (getenv("CONTACT3D_PRINT"))
            fprintf(stderr,
                    "orbit %d samples: D %.12g, closed form %.12g (rel %.3e), discrete %.12g "
                    "(rel %.2e); r - a would give %.6g\n",
                    nsamp, D, want, err[l], discrete, fabs(D / discrete - 1.0),
                    2.0 * PI * (r - a) * mun);
        ck_assert_msg(fabs(D / discrete - 1.0) <= 1e-12, "%d samples: %.15g vs discrete %.15g",
                      nsamp, D, discrete);
        ck_assert_msg(err[l] <= 1.1 * a * 0.5 * dth / rw, "%d samples: rel %g", nsamp, err[l]);
        if (l > 0) { /* first order: the error halves with the step */
            double order = log2(err[l - 1] / err[l]);
            ck_assert_msg(order > 0.95 && order < 1.05, "order %g", order);
        }
    }
}
END_TEST

/* Independent march of the 3-D contact rule for one element, state w[2]. */
static void hand_step(double kt, double mu, double n0, double kn, const double u[2], double g,
                      double w[2], double f[2], double *N)
{
    double nc = n0 + kn * g;
    *N = nc > 0.0 ? nc : 0.0;
    if (nc < 0.0) {
        w[0] = u[0];
        w[1] = u[1];
        f[0] = f[1] = 0.0;
        return;
    }
    double t0 = kt * (u[0] - w[0]), t1 = kt * (u[1] - w[1]), tn = sqrt(t0 * t0 + t1 * t1);
    double b = mu * *N;
    if (tn <= b) {
        f[0] = t0;
        f[1] = t1;
        return;
    }
    f[0] = b * t0 / tn;
    f[1] = b * t1 / tn;
    w[0] = u[0] - f[0] / kt;
    w[1] = u[1] - f[1] / kt;
}

/* (c) lift-off: g = 0.5 sin(1.3 t) - 0.1 opens the contact (n0 = 1, kn = 4: open below
 * g = -0.25) and closes it again every cycle, with a tangential ellipse; the element follows
 * the hand march, and on each re-contact starts from an unloaded spring at the re-contact
 * point. */
START_TEST(liftoff_hand_march)
{
    const double kt = 3.0, mu = 0.4, n0 = 1.0, kn = 4.0, dt = 0.01;
    fricreg_jenkins *j = element(kt, mu, n0, kn);
    double wh[2] = {0.0, 0.0}, worst = 0.0;
    int open = 0, slip = 0, closes = 0, was_open = 0;
    for (int k = 1; k <= 3000; k++) {
        double t = k * dt, u[2] = {0.9 * sin(0.7 * t), 0.5 * cos(1.1 * t) - 0.5},
               g = 0.5 * sin(1.3 * t) - 0.1, f[2], N, fh[2], Nh, uprev[2] = {wh[0], wh[1]};
        ck_assert_int_eq(fricreg_jenkins_trial_normal(j, 1, u, &g, f, &N, NULL, NULL), FRICREG_OK);
        fricreg_jenkins_commit(j);
        hand_step(kt, mu, n0, kn, u, g, wh, fh, &Nh);
        double w[2];
        fricreg_jenkins_get_slider(j, 1, w);
        worst = fmax(worst, fmax(fabs(f[0] - fh[0]), fabs(f[1] - fh[1])));
        worst = fmax(worst, fmax(fabs(w[0] - wh[0]), fabs(w[1] - wh[1])));
        ck_assert_double_eq(N, Nh);
        if (n0 + kn * g < 0.0) {
            open++;
            ck_assert_double_eq(f[0], 0.0);
            ck_assert_double_eq(w[0], u[0]); /* the memory reset */
            ck_assert_double_eq(w[1], u[1]);
        } else {
            slip += hypot(f[0], f[1]) >= mu * N * (1.0 - 1e-15) && N > 0.0;
            if (was_open) { /* re-contact: the spring unloaded at the last open point, its
                               * trial kt d returned onto the disk of the small N */
                double d0 = u[0] - uprev[0], d1 = u[1] - uprev[1], dn = hypot(d0, d1);
                double scale = kt * dn <= mu * N ? kt : mu * N / dn;
                closes++;
                ck_assert_double_eq_tol(f[0], scale * d0, 1e-15);
                ck_assert_double_eq_tol(f[1], scale * d1, 1e-15);
            }
        }
        was_open = n0 + kn * g < 0.0;
    }
    if (getenv("CONTACT3D_PRINT"))
        fprintf(stderr, "lift-off: %d steps open, %d slipping, %d closings, worst %.2e\n", open,
                slip, closes, worst);
    ck_assert_int_gt(open, 500);
    ck_assert_int_gt(slip, 100);
    ck_assert_int_ge(closes, 3);
    ck_assert_msg(worst <= 1e-14, "off the hand march by %g", worst); /* hypot vs sqrt */
    fricreg_jenkins_free(j);
}
END_TEST

/* The exact tangent [df/du df/dg; 0 dN/dg] against centred differences in each state. */
START_TEST(tangent_3x3)
{
    const double kt = 2.2, mu = 0.3, n0 = 1.5, kn = 5.0, h = 1e-6;
    /* committed w = (0.1, -0.05); stick, slip (off the axes), open */
    const double cases[3][3] = {{0.15, -0.02, 0.1}, {0.7, 0.45, 0.2}, {0.3, 0.1, -0.5}};
    for (int c = 0; c < 3; c++) {
        fricreg_jenkins *j = element(kt, mu, n0, kn);
        double w0[2] = {0.1, -0.05}, g0 = 0.0, f[2];
        /* put the slider at w0 by a stuck then an open step: open makes w = u */
        double gopen = -1.0;
        ck_assert_int_eq(fricreg_jenkins_trial_normal(j, 1, w0, &gopen, f, NULL, NULL, NULL),
                         FRICREG_OK);
        fricreg_jenkins_commit(j);
        double x[3] = {cases[c][0], cases[c][1], cases[c][2]}, t[4], tg[2], N;
        ck_assert_int_eq(fricreg_jenkins_trial_normal(j, 1, x, &x[2], f, &N, t, tg), FRICREG_OK);
        double T[3][3] = {{t[0], t[1], tg[0]},
                          {t[2], t[3], tg[1]},
                          {0.0, 0.0, n0 + kn * x[2] >= 0.0 ? kn : 0.0}};
        for (int b = 0; b < 3; b++) {
            double xp[3] = {x[0], x[1], x[2]}, xm[3] = {x[0], x[1], x[2]}, fp[3], fm[3];
            xp[b] += h;
            xm[b] -= h;
            fricreg_jenkins_trial_normal(j, 1, xp, &xp[2], fp, &fp[2], NULL, NULL);
            fricreg_jenkins_trial_normal(j, 1, xm, &xm[2], fm, &fm[2], NULL, NULL);
            for (int a = 0; a < 3; a++)
                ck_assert_msg(fabs((fp[a] - fm[a]) / (2 * h) - T[a][b]) <= 1e-6 * kn,
                              "case %d: dF%d/dx%d = %g, tangent %g", c, a, b,
                              (fp[a] - fm[a]) / (2 * h), T[a][b]);
        }
        (void)g0;
        fricreg_jenkins_free(j);
    }
}
END_TEST

/* (d) bad input: the normal law's kn < 0, mu < 0, non-finite entries; outputs untouched. */
START_TEST(bad_input_element)
{
    fricreg_jenkins *j = element(1.0, 0.3, 1.0, 2.0);
    double mu = 0.3, n0 = 1.0, kn = 2.0, bad = -1.0, nan = NAN, inf = INFINITY;
    ck_assert_int_eq(fricreg_jenkins_set_normal(j, 1, &mu, &n0, &bad), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_jenkins_set_normal(j, 1, &bad, &n0, &kn), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_jenkins_set_normal(j, 1, &mu, &nan, &kn), FRICREG_ENONFINITE);
    ck_assert_int_eq(fricreg_jenkins_set_normal(j, 1, &mu, &n0, &inf), FRICREG_ENONFINITE);
    ck_assert_int_eq(fricreg_jenkins_set_normal(j, 2, &mu, &n0, &kn), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_jenkins_set_normal(j, 1, NULL, &n0, &kn), FRICREG_ENULL);
    double u[2] = {0.1, 0.2}, g = nan, f[2] = {-7.0, -7.0}, N = -7.0;
    ck_assert_int_eq(fricreg_jenkins_trial_normal(j, 1, u, &g, f, &N, NULL, NULL),
                     FRICREG_ENONFINITE);
    u[1] = inf;
    g = 0.0;
    ck_assert_int_eq(fricreg_jenkins_trial_normal(j, 1, u, &g, f, &N, NULL, NULL),
                     FRICREG_ENONFINITE);
    ck_assert_double_eq(f[0], -7.0);
    ck_assert_double_eq(N, -7.0);
    ck_assert_ptr_nonnull(strstr(fricreg_jenkins_errmsg(j), "trial_normal"));
    fricreg_jenkins_free(j);
}
END_TEST

/* A structure of 3 dofs (M, K, C dense; C may be NULL), one contact on J0 of bound mu0, load
 * p sin(omega t) sampled every dt for nsteps steps; scheme 1 HHT-alpha -0.1, 2 central. */
static fricreg_structure *make(const double *M, const double *K, const double *C, const double *J0,
                               double mu0, const double *p, double omega, double dt, int nsteps,
                               int scheme)
{
    fricreg_structure *s = NULL;
    ck_assert_int_eq(fricreg_structure_create(3, 1, &s), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_mass(s, 3, M), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_stiffness(s, 3, K), FRICREG_OK);
    if (C != NULL)
        ck_assert_int_eq(fricreg_structure_set_damping(s, 3, C), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_contacts(s, 1, 3, J0), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_bounds(s, 1, &mu0), FRICREG_OK);
    double *g = malloc(((size_t)nsteps + 1) * sizeof *g);
    ck_assert_ptr_nonnull(g);
    for (int k = 0; k <= nsteps; k++)
        g[k] = sin(omega * k * dt);
    ck_assert_int_eq(fricreg_structure_set_load(s, 3, p, 0.0, dt, (size_t)nsteps + 1, g),
                     FRICREG_OK);
    free(g);
    ck_assert_int_eq(fricreg_structure_set_newton(s, 1e-14, 50), FRICREG_OK);
    if (scheme == 1)
        ck_assert_int_eq(fricreg_structure_set_hht(s, -0.1), FRICREG_OK);
    else if (scheme == 2)
        ck_assert_int_eq(fricreg_structure_set_central_difference(s), FRICREG_OK);
    return s;
}

/* (a) in a structure: dofs x, y, z uncoupled, the load on x only, the element's tangential
 * rows x, y and its normal row z, z started at its equilibrium under the preload,
 * z_eq = -n0/(K_z + kn), so N = n0 K_z/(K_z + kn) throughout: the 1-D element of
 * mun = mu N on row x gives the same x history (Newmark, HHT-alpha, central difference, and
 * beside a contact of bound > 0). */
START_TEST(structure_one_axis_is_jenkins_1d)
{
    const double M[9] = {1.3, 0, 0, 0, 0.9, 0, 0, 0, 1.1}, K[9] = {2.385, 0, 0, 0, 1.7, 0, 0, 0, 5},
                 C[9] = {0.12, 0, 0, 0, 0.05, 0, 0, 0, 0.2}, p[3] = {0.6, 0.0, 0.0},
                 Je[6] = {1, 0, 0, 0, 1, 0}, Jn[3] = {0, 0, 1}, J1[3] = {1, 0, 0}, kt = 1.7,
                 n0 = 2.0, kn = 40.0;
    const double Neq = n0 * K[8] / (K[8] + kn), mu = 0.35 / Neq, mun = mu * Neq;
    const double omega = 1.5, dt = 2.0 * PI / omega / 256;
    const int nsteps = 256 * 20;
    for (int scheme = 0; scheme < 4; scheme++) {
        double mu0 = scheme == 3 ? 0.05 : 0.0;
        fricreg_structure *a = make(M, K, C, J1, mu0, p, omega, dt, nsteps, scheme % 3),
                          *b = make(M, K, C, J1, mu0, p, omega, dt, nsteps, scheme % 3);
        ck_assert_int_eq(fricreg_structure_set_jenkins_2d_normal(a, 1, 3, Je, Jn, &kt, &mu, &n0,
                                                                 &kn),
                         FRICREG_OK);
        ck_assert_int_eq(fricreg_structure_set_jenkins(b, 1, 3, J1, &kt, &mun), FRICREG_OK);
        double u0[3] = {0.0, 0.0, -n0 / (K[8] + kn)}, v0[3] = {0.0, 0.0, 0.0};
        ck_assert_int_eq(fricreg_structure_set_initial(a, 3, u0, v0), FRICREG_OK);
        double amp = 0.0, du = 0.0, df = 0.0, dw = 0.0, dN = 0.0, wmax = 0.0;
        for (int k = 1; k <= nsteps; k++) {
            QUIET_OK(fricreg_structure_step(a, dt));
            QUIET_OK(fricreg_structure_step(b, dt));
            double ua[3], ub[3], fa[2], wa[2], N, fb, wb;
            fricreg_structure_get_state(a, 3, ua, NULL, NULL);
            fricreg_structure_get_state(b, 3, ub, NULL, NULL);
            QUIET_OK(fricreg_structure_get_jenkins_2d_state(a, 1, fa, wa, NULL));
            QUIET_OK(fricreg_structure_get_normal_forces(a, 1, &N));
            QUIET_OK(fricreg_structure_get_jenkins_state(b, 1, &fb, &wb, NULL));
            QUIET_CHECK(ua[1] == 0.0);
            QUIET_CHECK(fa[1] == 0.0);
            amp = fmax(amp, fabs(ub[0]));
            wmax = fmax(wmax, fabs(wb));
            du = fmax(du, fabs(ua[0] - ub[0]));
            df = fmax(df, fabs(fa[0] - fb));
            dw = fmax(dw, fabs(wa[0] - wb));
            dN = fmax(dN, fabs(N - Neq));
        }
        if (getenv("CONTACT3D_PRINT"))
            fprintf(stderr,
                    "structure one axis, scheme %d: |du| %.2e of %.3g, |df| %.2e, |dw| %.2e of "
                    "%.3g, |N - N_eq| %.2e of %.4g\n",
                    scheme, du, amp, df, dw, wmax, dN, Neq);
        ck_assert(wmax > 0.1 * amp); /* the slider slipped */
        ck_assert_msg(du <= 1e-12 * amp, "scheme %d: |du| %g of %g", scheme, du, amp);
        ck_assert_msg(df <= 1e-12 * mun, "scheme %d: |df| %g", scheme, df);
        ck_assert_msg(dw <= 1e-12 * amp, "scheme %d: |dw| %g", scheme, dw);
        ck_assert_msg(dN <= 1e-12 * Neq, "scheme %d: |dN| %g", scheme, dN);
        fricreg_structure_free(a);
        fricreg_structure_free(b);
    }
}
END_TEST

/* (b) in a structure: a mass on an isotropic spring of 1e6 in the tangential plane, started on
 * the circle r = 0.4 at its natural frequency, its normal dof resting at the preload's
 * equilibrium (N = n0 K_z/(K_z + kn)); the dissipation of cycles 2-4 against the discrete
 * closed form at the cycle's mean radius (the element's force moves the mass by mu N/kg) and
 * the continuous 2 pi r_w mu N at first order. */
START_TEST(structure_orbit)
{
    const double kg = 1e6, kt = 3.0, n0 = 2.0, kn = 40.0, Kz = 5.0, r0 = 0.4;
    const double Neq = n0 * Kz / (Kz + kn), mu = 0.5 / Neq, mun = mu * Neq;
    const double M[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, K[9] = {kg, 0, 0, 0, kg, 0, 0, 0, Kz},
                 Je[6] = {1, 0, 0, 0, 1, 0}, Jn[3] = {0, 0, 1}, J0[3] = {1, 0, 0}, p[3] = {0, 0, 0};
    const double omega = sqrt(kg), dt = 2.0 * PI / omega / 2000;
    fricreg_structure *s = make(M, K, NULL, J0, 0.0, p, omega, dt, 1, 0);
    ck_assert_int_eq(fricreg_structure_set_jenkins_2d_normal(s, 1, 3, Je, Jn, &kt, &mu, &n0, &kn),
                     FRICREG_OK);
    double u0[3] = {r0, 0.0, -n0 / (Kz + kn)}, v0[3] = {0.0, r0 * omega, 0.0};
    ck_assert_int_eq(fricreg_structure_set_initial(s, 3, u0, v0), FRICREG_OK);
    double Dprev = 0.0, worst = 0.0;
    for (int c = 1; c <= 4; c++) {
        double rsum = 0.0;
        for (int k = 0; k < 2000; k++) {
            ck_assert_int_eq(fricreg_structure_step(s, dt), FRICREG_OK);
            double u[3];
            fricreg_structure_get_state(s, 3, u, NULL, NULL);
            rsum += hypot(u[0], u[1]);
        }
        double D, r = rsum / 2000, a = mun / kt, rw = sqrt(r * r - a * a);
        double dth = 2.0 * atan(0.5 * omega * dt), sh = sin(0.5 * dth);
        double rwd = -a * sh + sqrt(a * a * sh * sh - a * a + r * r);
        double discrete = 2000 * 2.0 * rwd * sh * mun * 0.5 * (1.0 + cos(dth));
        fricreg_structure_get_jenkins_2d_state(s, 1, NULL, NULL, &D);
        double got = D - Dprev, want = mun * 2.0 * PI * rw;
        Dprev = D;
        if (getenv("CONTACT3D_PRINT"))
            fprintf(stderr,
                    "structure orbit, cycle %d: D %.10g, closed form %.10g (rel %.2e), discrete "
                    "%.10g (rel %.2e)\n",
                    c, got, want, fabs(got / want - 1.0), discrete, fabs(got / discrete - 1.0));
        if (c > 1) {
            worst = fmax(worst, fabs(got / discrete - 1.0));
            ck_assert_msg(fabs(got / want - 1.0) <= 1.1 * a * 0.5 * dth / rw,
                          "cycle %d: %.10g, closed form %.10g", c, got, want);
        }
    }
    ck_assert_msg(worst <= 1e-5, "dissipation off the discrete closed form by %g", worst);
    fricreg_structure_free(s);
}
END_TEST

/* (c) in a structure: three coupled dofs, one element on general rows, a load that opens and
 * closes it; after each step the standalone element at the structure's q = J_e u, g = J_n u
 * from its own committed slider gives the structure's forces and slider (Newton with the
 * exact 3x3 tangent, tolerance 1e-14). */
START_TEST(structure_liftoff_standalone)
{
    const double M[9] = {1.0, 0.0, 0.0, 0.0, 1.5, 0.0, 0.0, 0.0, 0.8},
                 K[9] = {3.0, -1.0, 0.0, -1.0, 2.5, -0.7, 0.0, -0.7, 1.9},
                 Je[6] = {1.0, -1.0, 0.0, 0.3, 0.5, 0.2}, Jn[3] = {-0.1, 0.2, 1.0},
                 J0[3] = {0.0, 1.0, 0.0}, p[3] = {0.9, -0.6, 2.5}, kt = 3.0, mu = 0.4, n0 = 1.0,
                 kn = 4.0;
    const double omega = 1.1, dt = 0.005;
    const int nsteps = 6000;
    for (int scheme = 0; scheme < 4; scheme++) {
        double mu0 = scheme == 3 ? 0.1 : 0.0;
        fricreg_structure *s = make(M, K, NULL, J0, mu0, p, omega, dt, nsteps, scheme % 3);
        ck_assert_int_eq(fricreg_structure_set_jenkins_2d_normal(s, 1, 3, Je, Jn, &kt, &mu, &n0,
                                                                 &kn),
                         FRICREG_OK);
        fricreg_jenkins *j = element(kt, mu, n0, kn);
        double df = 0.0, dw = 0.0, dN = 0.0, fmaxv = 0.0, wmax = 0.0, Nmax = 0.0;
        int open = 0, slips = 0, iters = 0;
        for (int k = 1; k <= nsteps; k++) {
            QUIET_OK(fricreg_structure_step(s, dt));
            double u[3], q[2] = {0.0, 0.0}, g = 0.0, f[2], w[2], N, fr[2], wr[2], Nr, wprev[2];
            fricreg_structure_get_state(s, 3, u, NULL, NULL);
            for (int c = 0; c < 3; c++) {
                q[0] += Je[c] * u[c];
                q[1] += Je[3 + c] * u[c];
                g += Jn[c] * u[c];
            }
            QUIET_OK(fricreg_structure_get_jenkins_2d_state(s, 1, f, w, NULL));
            QUIET_OK(fricreg_structure_get_normal_forces(s, 1, &N));
            fricreg_jenkins_get_slider(j, 1, wprev);
            QUIET_OK(fricreg_jenkins_trial_normal(j, 1, q, &g, fr, &Nr, NULL, NULL));
            fricreg_jenkins_commit(j);
            fricreg_jenkins_get_slider(j, 1, wr);
            for (int a = 0; a < 2; a++) {
                df = fmax(df, fabs(f[a] - fr[a]));
                dw = fmax(dw, fabs(w[a] - wr[a]));
                wmax = fmax(wmax, fabs(wr[a]));
            }
            fmaxv = fmax(fmaxv, hypot(fr[0], fr[1]));
            dN = fmax(dN, fabs(N - Nr));
            Nmax = fmax(Nmax, Nr);
            open += n0 + kn * g < 0.0;
            slips += Nr > 0.0 && (wr[0] != wprev[0] || wr[1] != wprev[1]);
        }
        double residual, input;
        fricreg_structure_get_value(s, FRICREG_SVALUE_RESIDUAL, &residual);
        fricreg_structure_get_value(s, FRICREG_SVALUE_INPUT, &input);
        int64_t its = 0;
        ck_assert_int_eq(fricreg_structure_get_stat(s, FRICREG_SSTAT_NEWTON_ITERATIONS, &its),
                         FRICREG_OK);
        iters = (int)its;
        if (getenv("CONTACT3D_PRINT"))
            fprintf(stderr,
                    "structure lift-off, scheme %d: |df| %.2e of %.3g, |dw| %.2e of %.3g, |dN| "
                    "%.2e of %.3g; %d steps open, %d slipping; Newton %d; residual %.2e of "
                    "input %.3g\n",
                    scheme, df, fmaxv, dw, wmax, dN, Nmax, open, slips, iters, residual, input);
        ck_assert_int_gt(open, 300);
        ck_assert_int_gt(slips, 100);
        ck_assert_msg(df <= 1e-10 * fmaxv, "scheme %d: |df| %g", scheme, df);
        ck_assert_msg(dw <= 1e-10 * wmax, "scheme %d: |dw| %g", scheme, dw);
        ck_assert_msg(dN <= 1e-10 * Nmax, "scheme %d: |dN| %g", scheme, dN);
        fricreg_jenkins_free(j);
        fricreg_structure_free(s);
    }
}
END_TEST

/* (d) the structure's setter refuses bad input and keeps the elements in force. */
START_TEST(structure_refusals)
{
    const double M[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, K[9] = {2, 0, 0, 0, 2, 0, 0, 0, 2},
                 J0[3] = {1, 0, 0}, p[3] = {1, 0, 0}, Je[6] = {1, 0, 0, 0, 1, 0}, Jn[3] = {0, 0, 1},
                 Jz[3] = {0, 0, 0}, kt = 2.0, mu = 0.3, n0 = 1.0, kn = 5.0, neg = -1.0, zero = 0.0,
                 nan = NAN;
    fricreg_structure *s = make(M, K, NULL, J0, 0.0, p, 1.0, 0.01, 100, 0);
    ck_assert_int_eq(fricreg_structure_set_jenkins_2d_normal(s, 1, 3, Je, Jn, &kt, &mu, &n0, &kn),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_step(s, 0.01), FRICREG_OK);
    double N0;
    ck_assert_int_eq(fricreg_structure_get_normal_forces(s, 1, &N0), FRICREG_OK);
    ck_assert(N0 > 0.0);
    ck_assert_int_eq(fricreg_structure_set_jenkins_2d_normal(s, 1, 3, Je, Jn, &kt, &mu, &n0, &zero),
                     FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_structure_set_jenkins_2d_normal(s, 1, 3, Je, Jn, &kt, &mu, &n0, &neg),
                     FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_structure_set_jenkins_2d_normal(s, 1, 3, Je, Jn, &kt, &neg, &n0, &kn),
                     FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_structure_set_jenkins_2d_normal(s, 1, 3, Je, Jn, &neg, &mu, &n0, &kn),
                     FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_structure_set_jenkins_2d_normal(s, 1, 3, Je, Jn, &kt, &mu, &nan, &kn),
                     FRICREG_ENONFINITE);
    ck_assert_int_eq(fricreg_structure_set_jenkins_2d_normal(s, 1, 3, Je, Jz, &kt, &mu, &n0, &kn),
                     FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_structure_errmsg(s), "row 0 of J_n is zero"));
    ck_assert_int_eq(fricreg_structure_set_jenkins_2d_normal(s, 1, 2, Je, Jn, &kt, &mu, &n0, &kn),
                     FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_structure_set_jenkins_2d_normal(s, 1, 3, Je, NULL, &kt, &mu, &n0, &kn),
                     FRICREG_ENULL);
    ck_assert_int_eq(fricreg_structure_set_jenkins_2d_normal(NULL, 1, 3, Je, Jn, &kt, &mu, &n0,
                                                             &kn),
                     FRICREG_ENULL);
    double N1, f[2];
    ck_assert_int_eq(fricreg_structure_get_normal_forces(s, 1, &N1), FRICREG_OK);
    ck_assert_double_eq(N1, N0); /* the elements in force kept */
    ck_assert_int_eq(fricreg_structure_get_jenkins_state(s, 1, f, NULL, NULL), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_structure_set_jenkins_2d_normal(s, 0, 3, NULL, NULL, NULL, NULL, NULL,
                                                             NULL),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_get_normal_forces(s, 1, &N1), FRICREG_ESIZE);
    fricreg_structure_free(s);
}
END_TEST

/* The error estimate's companion copies the 3-D contact elements (two tangential rows and a
 * normal row each): its estimates are 3 |u - u_c| bit for bit against a structure set up by
 * hand at eps / 2 and run at dt / 2, the element beside a contact of bound > 0, opening and
 * closing. */
START_TEST(structure_error_estimate_companion)
{
    const double M[9] = {1.0, 0.0, 0.0, 0.0, 1.5, 0.0, 0.0, 0.0, 0.8},
                 K[9] = {3.0, -1.0, 0.0, -1.0, 2.5, -0.7, 0.0, -0.7, 1.9},
                 Je[6] = {1.0, -1.0, 0.0, 0.3, 0.5, 0.2}, Jn[3] = {-0.1, 0.2, 1.0},
                 J0[3] = {0.0, 1.0, 0.0}, p[3] = {0.9, -0.6, 2.5}, kt = 3.0, mu = 0.4, n0 = 1.0,
                 kn = 4.0, eps = 1e-2;
    const double omega = 1.1, dt = 0.01;
    const int nsteps = 1200;
    fricreg_structure *s = make(M, K, NULL, J0, 0.1, p, omega, dt, nsteps, 0),
                      *c = make(M, K, NULL, J0, 0.1, p, omega, dt, nsteps, 0);
    ck_assert_int_eq(fricreg_structure_set_law(s, FRICREG_LAW_QUINN, eps), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_law(c, FRICREG_LAW_QUINN, 0.5 * eps), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_jenkins_2d_normal(s, 1, 3, Je, Jn, &kt, &mu, &n0, &kn),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_jenkins_2d_normal(c, 1, 3, Je, Jn, &kt, &mu, &n0, &kn),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_error_estimate(s, FRICREG_ESTIMATE_ONE_COMPANION),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_error_companions(s, FRICREG_COMPANIONS_FINER),
                     FRICREG_OK); /* the finer estimator, not the default's screen */
    ck_assert_int_eq(fricreg_structure_run(s, dt, nsteps * dt), FRICREG_OK);
    double t = 0.0;
    ck_assert_int_eq(fricreg_structure_get_value(s, FRICREG_SVALUE_TIME, &t), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_run(c, 0.5 * dt, t), FRICREG_OK);
    double u[3], uc[3], err[3];
    ck_assert_int_eq(fricreg_structure_get_peak_displacement(s, 3, u), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_get_peak_displacement(c, 3, uc), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_get_peak_displacement_error(s, 3, err), FRICREG_OK);
    for (int i = 0; i < 3; i++) {
        ck_assert(err[i] > 0.0);
        ck_assert_double_eq(err[i], 3.0 * fabs(u[i] - uc[i]));
    }
    fricreg_structure_free(c);
    fricreg_structure_free(s);
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("contact3d");
    TCase *tc = tcase_create("element");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, one_axis_is_jenkins_1d);
    tcase_add_test(tc, orbit_closed_form);
    tcase_add_test(tc, liftoff_hand_march);
    tcase_add_test(tc, tangent_3x3);
    tcase_add_test(tc, bad_input_element);
    suite_add_tcase(s, tc);
    TCase *ts = tcase_create("structure");
    tcase_set_timeout(ts, 120);
    tcase_add_test(ts, structure_one_axis_is_jenkins_1d);
    tcase_add_test(ts, structure_orbit);
    tcase_add_test(ts, structure_liftoff_standalone);
    tcase_add_test(ts, structure_refusals);
    tcase_add_test(ts, structure_error_estimate_companion);
    suite_add_tcase(s, ts);
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
