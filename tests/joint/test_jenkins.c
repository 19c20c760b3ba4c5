/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_jenkins.c — Check suite for the Jenkins elements (fricreg_jenkins.h): the return
 * mapping, its tangent, trial/commit, and the hysteresis it makes.
 *
 * Where the numbers come from:
 *   - 1-D loop under u = A sin t, A > mun/kt: after the first quarter the force runs between
 *     +-mun on a parallelogram of width 2A in u, whose sliding edges sit at f = +-mun and whose
 *     elastic edges have slope kt and height 2 mun; its area, the dissipation per cycle, is
 *     D = 2 mun (2A - 2 mun/kt) = 4 mun (A - mun/kt). The return mapping is exact at every
 *     sample (the element is rate independent and u monotone between samples but at the turns),
 *     so the trapezoid rule on f du errs only in the two intervals holding a kink and at the
 *     turns, where the samples miss u = +-A by O(h^2): the error falls like h^2.
 *   - 1-D with A <= mun/kt: never slides, f = kt u to the last bit, D = 0.
 *   - 2-D circular orbit u = A (cos t, sin t), kt A > mun: in the steady state the slider
 *     circles at radius r with the orbit's angular rate, and the force kt (u - w), of length
 *     mun, points along the slider's velocity (the slip rule), which is tangent to the slider's
 *     circle. So u = w + (mun/kt) t_hat with t_hat perpendicular to w: A^2 = r^2 + (mun/kt)^2,
 *     r = sqrt(A^2 - (mun/kt)^2) (not A - mun/kt: the lag is tangential, not radial). The
 *     dissipated power is f . w' = mun |w'| = mun r, so per revolution D = 2 pi mun r; over a
 *     closed steady loop that is also the integral of f . du (f . d(u - w) = d|f|^2/(2 kt)
 *     integrates to 0). Backward Euler on the slider converges to it like h only: each step's
 *     slip takes the direction at its end, and on a circle that direction turns by h within
 *     the step (measured order 1.04; the 1-D loop has no turning direction, hence h^2).
 *   - the tangent against centred differences of the trial force, away from |f_tr| = mun.
 *   - normal load: the bound is mu N with N = max(0, N0 + kn g). A constant N (kn = 0, or
 *     g = 0) is the fixed bound mun = mu N0; separated (N0 + kn g < 0): f = 0, tangents 0,
 *     the slider at u; sliding, f = mu N n, so df/dg = mu kn n, and df/du as with mun = mu N. */
#include <check.h>
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "fricreg_jenkins.h"
#include "quiet_check.h"

#define SENTINEL (-777.125)
static const double KT = 2.385, MUN = 0.7125, PI = 3.14159265358979323846;

static fricreg_jenkins *make(int dim, size_t n, double kt, double mun)
{
    fricreg_jenkins *j = NULL;
    ck_assert_int_eq(fricreg_jenkins_create(dim, n, &j), FRICREG_OK);
    double k[8], m[8];
    for (size_t i = 0; i < n; i++) {
        k[i] = kt;
        m[i] = mun;
    }
    ck_assert_int_eq(fricreg_jenkins_set_params(j, n, k, m), FRICREG_OK);
    return j;
}

/* The dissipation of cycle `cycle` (0-based) of u = A sin(pi/2 + t), sampled N times a
 * cycle from the peak t = 0, each sample a trial and a commit: the trapezoid rule on f du.
 * The largest |f - kt u| seen goes to *elastic_err if not NULL. */
static double loop_1d(double A, int N, int cycle, double *elastic_err)
{
    fricreg_jenkins *j = make(1, 1, KT, MUN);
    const double h = 2.0 * PI / N;
    double D = 0.0, u_prev = 0.0, f_prev = 0.0, worst = 0.0;
    for (long k = 0; k <= (long)N * (cycle + 1); k++) {
        double u = A * cos(h * (double)k), f, t;
        ck_assert_int_eq(fricreg_jenkins_trial(j, 1, &u, &f, &t), FRICREG_OK);
        ck_assert_int_eq(fricreg_jenkins_commit(j), FRICREG_OK);
        ck_assert(fabs(f) <= MUN);
        worst = fmax(worst, fabs(f - KT * u));
        if (k > (long)N * cycle)
            D += 0.5 * (f + f_prev) * (u - u_prev);
        u_prev = u;
        f_prev = f;
    }
    fricreg_jenkins_free(j);
    if (elastic_err)
        *elastic_err = worst;
    return D;
}

/* Least-squares slope of log(err) against log(N). */
static double rate(const int *N, const double *err, int m)
{
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (int k = 0; k < m; k++) {
        double x = log((double)N[k]), y = log(err[k]);
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
    }
    return -(m * sxy - sx * sy) / (m * sxx - sx * sx);
}

/* The samples hit the turns u = +-A (t = 0 and pi); the kinks, where sliding resumes at
 * u = +-(A - 2 mun/kt), sit at t_k = 2 pi (12 + 1/3)/100 after a turn, by the choice of
 * A = 2 (mun/kt)/(1 - cos t_k). On the grids N = 100 2^k a kink then lies 1/3 or 2/3 of the
 * way through its interval, where the trapezoid rule on the piecewise linear f(u) errs by
 * kt theta (1 - theta) du^2/2 with theta (1 - theta) = 2/9 on every grid: the error falls like
 * h^2 without the scatter of a kink anywhere in its interval. */
START_TEST(hysteresis_loop_1d)
{
    const double tk = 2.0 * PI * (12.0 + 1.0 / 3.0) / 100.0;
    const double A = 2.0 * (MUN / KT) / (1.0 - cos(tk)), exact = 4.0 * MUN * (A - MUN / KT);
    const int N[5] = {100, 200, 400, 800, 1600};
    double err[5];
    for (int k = 0; k < 5; k++) {
        double D = loop_1d(A, N[k], 1, NULL);
        err[k] = fabs(D - exact) / exact;
        printf("jenkins 1-D loop: N = %4d  D = %.12f  closed form %.12f  rel. error %.3e\n", N[k],
               D, exact, err[k]);
    }
    double p = rate(N, err, 5);
    printf("jenkins 1-D loop: observed order %.3f\n", p);
    ck_assert_double_le(err[4], 1e-5);
    ck_assert_msg(p > 1.9 && p < 2.1, "order %g, expected 2", p);
    /* kinks and turns anywhere in their intervals (A = 1.3, samples from t = 0.3125): still
     * within C h^2, C bounded from the two sources. A turn missed by up to h/2 in t shortens
     * the slider's excursion by eps <= A h^2/8, a relative error eps/(A - mun/kt) <= 0.162 h^2
     * for both turns together; a kink at theta in an interval du <= A h errs by
     * kt theta (1 - theta) du^2/2 <= kt A^2 h^2/8, relative (two kinks) kt A^2 h^2/(16 mun
     * (A - mun/kt)) = 0.353 h^2. So C = 0.52 (measured at most 0.28, at N = 800). */
    const double A2 = 1.3, exact2 = 4.0 * MUN * (A2 - MUN / KT);
    for (int k = 0; k < 5; k++) {
        fricreg_jenkins *j = make(1, 1, KT, MUN);
        const double h = 2.0 * PI / N[k];
        double D = 0.0, up = 0.0, fp = 0.0;
        for (long s = 0; s <= 2L * N[k]; s++) {
            double u = A2 * sin(0.3125 + h * (double)s), f;
            ck_assert_int_eq(fricreg_jenkins_trial(j, 1, &u, &f, NULL), FRICREG_OK);
            ck_assert_int_eq(fricreg_jenkins_commit(j), FRICREG_OK);
            if (s > N[k])
                D += 0.5 * (f + fp) * (u - up);
            up = u;
            fp = f;
        }
        fricreg_jenkins_free(j);
        double e = fabs(D - exact2) / exact2 / (h * h);
        printf("jenkins 1-D loop, kink anywhere: N = %4d  rel. error / h^2 = %.4f\n", N[k], e);
        ck_assert_double_le(e, 0.52);
    }
}
END_TEST

START_TEST(elastic_1d)
{
    double worst;
    const double A = 0.97 * MUN / KT;
    double D = loop_1d(A, 257, 1, &worst);
    ck_assert_double_eq(worst, 0.0); /* f = kt u exactly */
    ck_assert_double_le(fabs(D), 1e-15);
    /* exactly on the bound, A = mun/kt: still no slip */
    fricreg_jenkins *j = make(1, 1, 2.0, 0.75);
    double u = 0.375, f, t, w = SENTINEL;
    ck_assert_int_eq(fricreg_jenkins_trial(j, 1, &u, &f, &t), FRICREG_OK);
    ck_assert_double_eq(f, 0.75);
    ck_assert_double_eq(t, 2.0);
    ck_assert_int_eq(fricreg_jenkins_commit(j), FRICREG_OK);
    ck_assert_int_eq(fricreg_jenkins_get_slider(j, 1, &w), FRICREG_OK);
    ck_assert_double_eq(w, 0.0);
    fricreg_jenkins_free(j);
}
END_TEST

START_TEST(trial_keeps_committed_state)
{
    for (int dim = 1; dim <= 2; dim++) {
        fricreg_jenkins *j = make(dim, 3, KT, MUN);
        const double u1[6] = {0.1, -2.3, 0.7, 0.05, -0.2, 1.9},
                     u2[6] = {1.1, 0.3, -0.4, 2.0, 0.0, 0.1};
        double f1[6], f2[6], t1[12], t2[12], w0[6], w1[6];
        /* a committed state off zero */
        ck_assert_int_eq(fricreg_jenkins_trial(j, 3, u1, f1, NULL), FRICREG_OK);
        ck_assert_int_eq(fricreg_jenkins_commit(j), FRICREG_OK);
        ck_assert_int_eq(fricreg_jenkins_get_slider(j, 3, w0), FRICREG_OK);
        ck_assert_int_eq(fricreg_jenkins_trial(j, 3, u2, f1, t1), FRICREG_OK);
        ck_assert_int_eq(fricreg_jenkins_trial(j, 3, u2, f2, t2), FRICREG_OK);
        ck_assert_mem_eq(f1, f2, 3 * (size_t)dim * sizeof f1[0]);
        ck_assert_mem_eq(t1, t2, 3 * (size_t)(dim * dim) * sizeof t1[0]);
        ck_assert_int_eq(fricreg_jenkins_get_slider(j, 3, w1), FRICREG_OK);
        ck_assert_mem_eq(w0, w1, 3 * (size_t)dim * sizeof w0[0]);
        /* a commit without a new trial after set_params keeps the committed state */
        const double k[3] = {KT, KT, KT}, m[3] = {MUN, MUN, MUN};
        ck_assert_int_eq(fricreg_jenkins_set_params(j, 3, k, m), FRICREG_OK);
        ck_assert_int_eq(fricreg_jenkins_commit(j), FRICREG_OK);
        ck_assert_int_eq(fricreg_jenkins_get_slider(j, 3, w1), FRICREG_OK);
        ck_assert_mem_eq(w0, w1, 3 * (size_t)dim * sizeof w0[0]);
        /* the trial's slider: f = kt (u - w) in every element, stick or slip */
        ck_assert_int_eq(fricreg_jenkins_trial(j, 3, u2, f1, NULL), FRICREG_OK);
        ck_assert_int_eq(fricreg_jenkins_commit(j), FRICREG_OK);
        ck_assert_int_eq(fricreg_jenkins_get_slider(j, 3, w1), FRICREG_OK);
        for (int k2 = 0; k2 < 3 * dim; k2++)
            ck_assert_double_eq_tol(f1[k2], KT * (u2[k2] - w1[k2]), 1e-14);
        /* f may alias u; reset puts the sliders at 0 */
        double u[6];
        memcpy(u, u2, sizeof u);
        ck_assert_int_eq(fricreg_jenkins_reset(j), FRICREG_OK);
        ck_assert_int_eq(fricreg_jenkins_trial(j, 3, u2, f1, NULL), FRICREG_OK);
        ck_assert_int_eq(fricreg_jenkins_trial(j, 3, u, u, NULL), FRICREG_OK);
        ck_assert_mem_eq(u, f1, 3 * (size_t)dim * sizeof u[0]);
        ck_assert_int_eq(fricreg_jenkins_get_slider(j, 3, w1), FRICREG_OK);
        for (int k2 = 0; k2 < 3 * dim; k2++)
            ck_assert_double_eq(w1[k2], 0.0);
        ck_assert_uint_eq(fricreg_jenkins_size(j), 3);
        ck_assert_int_eq(fricreg_jenkins_dim(j), dim);
        fricreg_jenkins_free(j);
    }
}
END_TEST

/* The tangent of element 0 at u against centred differences of the trial force. */
static void check_tangent(fricreg_jenkins *j, int dim, const double *u)
{
    double f[2], t[4], up[2], um[2], fp[2], fm[2];
    ck_assert_int_eq(fricreg_jenkins_trial(j, 1, u, f, t), FRICREG_OK);
    for (int b = 0; b < dim; b++) {
        double h = 1e-6 * fmax(1.0, fabs(u[b]));
        memcpy(up, u, sizeof up);
        memcpy(um, u, sizeof um);
        up[b] += h;
        um[b] -= h;
        ck_assert_int_eq(fricreg_jenkins_trial(j, 1, up, fp, NULL), FRICREG_OK);
        ck_assert_int_eq(fricreg_jenkins_trial(j, 1, um, fm, NULL), FRICREG_OK);
        for (int a = 0; a < dim; a++) {
            double fd = (fp[a] - fm[a]) / (up[b] - um[b]);
            ck_assert_msg(fabs(fd - t[dim * a + b]) <= 1e-6 * KT,
                          "dim %d, u = (%g, %g): df%d/du%d = %.12g, difference %.12g", dim, u[0],
                          dim == 2 ? u[1] : 0.0, a, b, t[dim * a + b], fd);
        }
    }
}

START_TEST(tangent_against_differences)
{
    /* committed sliders off zero, then points in stick and in slip, 1e-3 away from the kink */
    for (int dim = 1; dim <= 2; dim++) {
        fricreg_jenkins *j = make(dim, 1, KT, MUN);
        const double u0[2] = {0.8125, -0.4375};
        double f[2];
        ck_assert_int_eq(fricreg_jenkins_trial(j, 1, u0, f, NULL), FRICREG_OK);
        ck_assert_int_eq(fricreg_jenkins_commit(j), FRICREG_OK);
        double w[2];
        ck_assert_int_eq(fricreg_jenkins_get_slider(j, 1, w), FRICREG_OK);
        int tried = 0;
        for (int k = 0; k < 40; k++) {
            double ang = 0.37 + 0.611 * k, rad = MUN / KT * (0.05 + 0.071 * k);
            double u[2] = {w[0] + rad * cos(ang), w[1] + (dim == 2 ? rad * sin(ang) : 0.0)};
            if (dim == 1)
                u[0] = w[0] + rad * (k % 2 ? -1.0 : 1.0);
            double ratio = KT * rad / MUN;
            if (fabs(ratio - 1.0) < 1e-3)
                continue;
            check_tangent(j, dim, u);
            tried++;
        }
        ck_assert_int_ge(tried, 38);
        fricreg_jenkins_free(j);
    }
}
END_TEST

/* Revolution `rev` (0-based) of u = A (cos t, sin t), N samples a revolution. */
static double orbit_2d(double A, int N, int rev, double *fnorm_err)
{
    fricreg_jenkins *j = make(2, 1, KT, MUN);
    const double h = 2.0 * PI / N;
    double D = 0.0, up[2] = {0, 0}, fp[2] = {0, 0}, worst = 0.0;
    for (long k = 0; k <= (long)N * (rev + 1); k++) {
        double u[2] = {A * cos(h * (double)k), A * sin(h * (double)k)}, f[2];
        QUIET_OK(fricreg_jenkins_trial(j, 1, u, f, NULL));
        QUIET_OK(fricreg_jenkins_commit(j));
        if (k > (long)N * rev) {
            D += 0.5 * ((f[0] + fp[0]) * (u[0] - up[0]) + (f[1] + fp[1]) * (u[1] - up[1]));
            worst = fmax(worst, fabs(hypot(f[0], f[1]) - MUN));
        }
        memcpy(up, u, sizeof up);
        memcpy(fp, f, sizeof fp);
    }
    fricreg_jenkins_free(j);
    *fnorm_err = worst;
    return D;
}

START_TEST(circular_orbit_2d)
{
    const double A = 1.3, rho = MUN / KT, exact = 2.0 * PI * MUN * sqrt(A * A - rho * rho);
    const int N[5] = {100, 200, 400, 800, 1600};
    double err[5], fn;
    for (int k = 0; k < 5; k++) {
        double D = orbit_2d(A, N[k], 5, &fn);
        ck_assert_double_le(fn, 1e-14); /* steady sliding: |f| = mun */
        err[k] = fabs(D - exact) / exact;
        printf("jenkins 2-D orbit: N = %4d  D = %.12f  closed form %.12f  rel. error %.3e\n", N[k],
               D, exact, err[k]);
    }
    /* the radial guess 2 pi mun (A - mun/kt) is 1.4 % off: the closed form above is the one */
    ck_assert_double_gt(fabs(2.0 * PI * MUN * (A - rho) - exact) / exact, 1e-2);
    double D4 = orbit_2d(A, 1600, 4, &fn); /* steady: revolutions 4 and 5 agree */
    ck_assert_double_le(fabs(D4 - exact) / exact, err[4] * (1.0 + 1e-6));
    ck_assert_double_ge(fabs(D4 - exact) / exact, err[4] * (1.0 - 1e-6));
    double p = rate(N, err, 5);
    printf("jenkins 2-D orbit: observed order %.3f\n", p);
    ck_assert_double_le(err[4], 5e-4);
    ck_assert_msg(p > 0.95 && p < 1.1, "order %g, expected 1", p);
}
END_TEST

START_TEST(bad_input)
{
    fricreg_jenkins *j = (fricreg_jenkins *)&j; /* a sentinel handle */
    fricreg_jenkins *keep = j;
    ck_assert_int_eq(fricreg_jenkins_create(1, 1, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_jenkins_create(3, 1, &j), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_jenkins_create(0, 1, &j), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_jenkins_create(2, 0, &j), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_jenkins_create(2, SIZE_MAX / 2, &j), FRICREG_EINVAL);
    ck_assert_ptr_eq(j, keep);

    j = make(2, 2, KT, MUN);
    const double kt[2] = {1.0, 2.0}, mun[2] = {0.5, 0.25}, u[4] = {0.1, 0.2, 0.3, 0.4};
    double bad[2], out[8], w[4];
    for (int k = 0; k < 8; k++)
        out[k] = SENTINEL;
    ck_assert_int_eq(fricreg_jenkins_set_params(NULL, 2, kt, mun), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_jenkins_set_params(j, 2, NULL, mun), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_jenkins_errcode(j), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_jenkins_set_params(j, 2, kt, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_jenkins_set_params(j, 3, kt, mun), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_jenkins_errcode(j), FRICREG_ESIZE);
    const double kt_bad[4] = {0.0, -1.0, NAN, INFINITY}, mun_bad[3] = {-1e-300, NAN, -INFINITY};
    const int kt_code[4] = {FRICREG_EINVAL, FRICREG_EINVAL, FRICREG_ENONFINITE, FRICREG_ENONFINITE};
    const int mun_code[3] = {FRICREG_EINVAL, FRICREG_ENONFINITE, FRICREG_ENONFINITE};
    for (int k = 0; k < 4; k++) {
        bad[0] = 1.0;
        bad[1] = kt_bad[k];
        ck_assert_int_eq(fricreg_jenkins_set_params(j, 2, bad, mun), kt_code[k]);
        ck_assert_int_eq(fricreg_jenkins_errcode(j), kt_code[k]);
        ck_assert_str_ne(fricreg_jenkins_errmsg(j), "");
    }
    for (int k = 0; k < 3; k++) {
        bad[0] = mun_bad[k];
        bad[1] = 0.0;
        ck_assert_int_eq(fricreg_jenkins_set_params(j, 2, kt, bad), mun_code[k]);
    }
    /* the message names the one condition that fails (a host code reads it): mun[1] < 0 beside a good kt */
    bad[0] = 0.5;
    bad[1] = -0.25;
    ck_assert_int_eq(fricreg_jenkins_set_params(j, 2, kt, bad), FRICREG_EINVAL);
    ck_assert_str_eq(fricreg_jenkins_errmsg(j), "set_params: mun[1] = -0.25 must be >= 0");
    bad[0] = 1.0;
    bad[1] = -2.0;
    ck_assert_int_eq(fricreg_jenkins_set_params(j, 2, bad, mun), FRICREG_EINVAL);
    ck_assert_str_eq(fricreg_jenkins_errmsg(j), "set_params: kt[1] = -2 must be > 0");
    /* nothing changed: the defaults of make() still hold (u = (0.1, 0.2) sticks with KT) */
    ck_assert_int_eq(fricreg_jenkins_trial(j, 2, u, out, NULL), FRICREG_OK);
    ck_assert_double_eq(out[0], KT * 0.1);
    for (int k = 0; k < 8; k++)
        out[k] = SENTINEL;

    ck_assert_int_eq(fricreg_jenkins_trial(NULL, 2, u, out, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_jenkins_trial(j, 2, NULL, out, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_jenkins_trial(j, 2, u, NULL, out), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_jenkins_trial(j, 1, u, out, out + 4), FRICREG_ESIZE);
    const double u_nan[4] = {0.1, 0.2, 0.3, NAN}, u_huge[4] = {0.1, 0.2, 1.5e308, 1.5e308};
    ck_assert_int_eq(fricreg_jenkins_trial(j, 2, u_nan, out, out + 4), FRICREG_ENONFINITE);
    ck_assert_int_eq(fricreg_jenkins_trial(j, 2, u_huge, out, out + 4), FRICREG_ENONFINITE);
    ck_assert_str_ne(fricreg_jenkins_errmsg(j), "");
    for (int k = 0; k < 8; k++)
        ck_assert_double_eq(out[k], SENTINEL);
    /* a stiff spring at a large but finite displacement still slides to |f| = mun */
    const double k_big[2] = {1e300, 1e300};
    const double u_big[4] = {1e10, -1e10, 0.0, 3e9};
    ck_assert_int_eq(fricreg_jenkins_set_params(j, 2, k_big, mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_jenkins_trial(j, 2, u_big, out, NULL), FRICREG_OK);
    ck_assert_double_eq_tol(hypot(out[0], out[1]), 0.5, 1e-15);
    ck_assert_double_eq_tol(out[3], 0.25, 1e-15);

    ck_assert_int_eq(fricreg_jenkins_get_slider(NULL, 2, w), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_jenkins_get_slider(j, 2, NULL), FRICREG_ENULL);
    w[0] = SENTINEL;
    ck_assert_int_eq(fricreg_jenkins_get_slider(j, 0, w), FRICREG_ESIZE);
    ck_assert_double_eq(w[0], SENTINEL);
    ck_assert_int_eq(fricreg_jenkins_commit(NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_jenkins_reset(NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_jenkins_errcode(NULL), FRICREG_OK);
    ck_assert_str_eq(fricreg_jenkins_errmsg(NULL), "NULL Jenkins elements");
    char buf[8];
    size_t len = fricreg_jenkins_errmsg_copy(j, buf, sizeof buf);
    ck_assert_uint_eq(len, strlen(fricreg_jenkins_errmsg(j)));
    ck_assert_uint_eq(strlen(buf), 7);
    ck_assert_uint_eq(fricreg_jenkins_size(NULL), 0);
    ck_assert_int_eq(fricreg_jenkins_dim(NULL), 0);
    fricreg_jenkins_free(j);
    fricreg_jenkins_free(NULL);
}
END_TEST

/* The normal law: mu = 0.4375, N0 = 1.625 (mu N0 = 0.7109375), kt = KT. */
static const double MU = 0.4375, N0 = 1.625, KN = 3.25;

START_TEST(normal_load_constant_preload)
{
    for (int dim = 1; dim <= 2; dim++) {
        /* kn = 0 with any g, and kn > 0 with g = 0: the fixed bound mu N0 */
        for (int variant = 0; variant < 2; variant++) {
            fricreg_jenkins *j = make(dim, 1, KT, MUN), *ref = make(dim, 1, KT, MU * N0);
            const double kn = variant ? KN : 0.0;
            ck_assert_int_eq(fricreg_jenkins_set_normal(j, 1, &MU, &N0, &kn), FRICREG_OK);
            for (int i = 0; i < 60; i++) {
                double u[2] = {0.9 * sin(0.37 * i), 0.6 * cos(0.23 * i)},
                       g = variant ? 0.0 : 5.0 * sin(0.71 * i) - 1.0;
                double f[2], fr[2], t[4], tr[4], tg[2], nf;
                ck_assert_int_eq(fricreg_jenkins_trial_normal(j, 1, u, &g, f, &nf, t, tg),
                                 FRICREG_OK);
                ck_assert_int_eq(fricreg_jenkins_trial(ref, 1, u, fr, tr), FRICREG_OK);
                for (int a = 0; a < dim; a++) {
                    ck_assert_double_eq_tol(f[a], fr[a], 1e-14);
                    if (!variant)
                        ck_assert_double_eq(tg[a], 0.0);
                }
                for (int a = 0; a < dim * dim; a++)
                    ck_assert_double_eq_tol(t[a], tr[a], 1e-14);
                ck_assert_double_eq(nf, N0);
                /* the plain trial is the one at g = 0 */
                ck_assert_int_eq(fricreg_jenkins_trial(j, 1, u, f, t), FRICREG_OK);
                for (int a = 0; a < dim; a++)
                    ck_assert_double_eq_tol(f[a], fr[a], 1e-14);
                ck_assert_int_eq(fricreg_jenkins_commit(j), FRICREG_OK);
                ck_assert_int_eq(fricreg_jenkins_commit(ref), FRICREG_OK);
            }
            fricreg_jenkins_free(j);
            fricreg_jenkins_free(ref);
        }
    }
}
END_TEST

START_TEST(normal_load_lift_off)
{
    for (int dim = 1; dim <= 2; dim++) {
        fricreg_jenkins *j = make(dim, 1, KT, MUN);
        ck_assert_int_eq(fricreg_jenkins_set_normal(j, 1, &MU, &N0, &KN), FRICREG_OK);
        /* sliding at g = 0.25: N = 1.625 + 0.8125 = 2.4375, |f| = mu N = 1.06640625 */
        double u[2] = {3.0, dim == 2 ? 4.0 : 0.0}, g = 0.25, f[2], nf, t[4], tg[2];
        double r = dim == 2 ? 5.0 : 3.0;
        ck_assert_int_eq(fricreg_jenkins_trial_normal(j, 1, u, &g, f, &nf, t, tg), FRICREG_OK);
        ck_assert_double_eq_tol(nf, 2.4375, 1e-15);
        ck_assert_double_eq_tol(hypot(f[0], dim == 2 ? f[1] : 0.0), 1.06640625, 1e-15);
        ck_assert_double_eq_tol(tg[0], MU * KN * u[0] / r, 1e-15);
        /* separated at g = -0.5625 (N0 + kn g = -0.203125): all zero, slider at u */
        g = -0.5625;
        for (int a = 0; a < 4; a++)
            t[a] = SENTINEL;
        ck_assert_int_eq(fricreg_jenkins_trial_normal(j, 1, u, &g, f, &nf, t, tg), FRICREG_OK);
        for (int a = 0; a < dim; a++) {
            ck_assert_double_eq(f[a], 0.0);
            ck_assert_double_eq(tg[a], 0.0);
        }
        for (int a = 0; a < dim * dim; a++)
            ck_assert_double_eq(t[a], 0.0);
        ck_assert_double_eq(nf, 0.0);
        ck_assert_int_eq(fricreg_jenkins_commit(j), FRICREG_OK);
        double w[2];
        ck_assert_int_eq(fricreg_jenkins_get_slider(j, 1, w), FRICREG_OK);
        for (int a = 0; a < dim; a++)
            ck_assert_double_eq(w[a], u[a]); /* the memory is reset: the spring unloaded */
        /* back in contact at u + du: the spring starts from the released position */
        double du = 0.01, u2[2] = {u[0] + du, u[1]};
        g = 0.0;
        ck_assert_int_eq(fricreg_jenkins_trial_normal(j, 1, u2, &g, f, &nf, t, tg), FRICREG_OK);
        ck_assert_double_eq_tol(f[0], KT * du, 1e-14);
        ck_assert_double_eq(t[0], KT);
        ck_assert_double_eq(tg[0], 0.0);
        /* set_params goes back to the fixed bound: no lift-off at any g */
        const double mun = 0.5;
        ck_assert_int_eq(fricreg_jenkins_set_params(j, 1, &KT, &mun), FRICREG_OK);
        g = -100.0;
        ck_assert_int_eq(fricreg_jenkins_trial_normal(j, 1, u2, &g, f, &nf, t, tg), FRICREG_OK);
        ck_assert_double_eq_tol(f[0], KT * du, 1e-14);
        ck_assert_double_eq(nf, 0.5);
        fricreg_jenkins_free(j);
    }
}
END_TEST

START_TEST(normal_load_tangent_against_differences)
{
    for (int dim = 1; dim <= 2; dim++) {
        fricreg_jenkins *j = make(dim, 1, KT, MUN);
        ck_assert_int_eq(fricreg_jenkins_set_normal(j, 1, &MU, &N0, &KN), FRICREG_OK);
        const double u0[2] = {0.8125, -0.4375};
        double g0 = 0.0625, f[2], w[2];
        ck_assert_int_eq(fricreg_jenkins_trial_normal(j, 1, u0, &g0, f, NULL, NULL, NULL),
                         FRICREG_OK);
        ck_assert_int_eq(fricreg_jenkins_commit(j), FRICREG_OK);
        ck_assert_int_eq(fricreg_jenkins_get_slider(j, 1, w), FRICREG_OK);
        int tried = 0, slipped = 0;
        for (int k = 0; k < 40; k++) {
            double ang = 0.37 + 0.611 * k, rad = 0.9 * (0.05 + 0.071 * k), g = 0.3 - 0.017 * k;
            double u[2] = {w[0] + rad * cos(ang), w[1] + (dim == 2 ? rad * sin(ang) : 0.0)};
            if (dim == 1)
                u[0] = w[0] + rad * (k % 2 ? -1.0 : 1.0);
            double nc = N0 + KN * g, ratio = KT * rad / (MU * nc);
            if (nc < 1e-3 || fabs(ratio - 1.0) < 1e-3)
                continue;
            double t[4], tg[2], fp[2], fm[2], h = 1e-7;
            ck_assert_int_eq(fricreg_jenkins_trial_normal(j, 1, u, &g, f, NULL, t, tg), FRICREG_OK);
            for (int b = 0; b < dim; b++) {
                double up[2] = {u[0], u[1]}, um[2] = {u[0], u[1]};
                up[b] += h;
                um[b] -= h;
                ck_assert_int_eq(fricreg_jenkins_trial_normal(j, 1, up, &g, fp, NULL, NULL, NULL),
                                 FRICREG_OK);
                ck_assert_int_eq(fricreg_jenkins_trial_normal(j, 1, um, &g, fm, NULL, NULL, NULL),
                                 FRICREG_OK);
                for (int a = 0; a < dim; a++)
                    ck_assert_double_eq_tol(t[dim * a + b], (fp[a] - fm[a]) / (2.0 * h), 1e-6 * KT);
            }
            double gp = g + h, gm = g - h;
            ck_assert_int_eq(fricreg_jenkins_trial_normal(j, 1, u, &gp, fp, NULL, NULL, NULL),
                             FRICREG_OK);
            ck_assert_int_eq(fricreg_jenkins_trial_normal(j, 1, u, &gm, fm, NULL, NULL, NULL),
                             FRICREG_OK);
            for (int a = 0; a < dim; a++)
                ck_assert_double_eq_tol(tg[a], (fp[a] - fm[a]) / (2.0 * h), 1e-6 * KT);
            slipped += ratio > 1.0;
            tried++;
        }
        ck_assert_int_ge(tried, 30);
        ck_assert_int_ge(slipped, 10);
        fricreg_jenkins_free(j);
    }
}
END_TEST

START_TEST(normal_load_bad_input)
{
    fricreg_jenkins *j = make(1, 2, KT, MUN);
    const double mu[2] = {0.5, 0.25}, n0[2] = {1.0, -0.5}, kn[2] = {2.0, 1.0};
    double bad[2], out[8];
    ck_assert_int_eq(fricreg_jenkins_set_normal(NULL, 2, mu, n0, kn), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_jenkins_set_normal(j, 2, mu, NULL, kn), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_jenkins_set_normal(j, 1, mu, n0, kn), FRICREG_ESIZE);
    const double mu_bad[3] = {-0.125, NAN, INFINITY};
    const int mu_code[3] = {FRICREG_EINVAL, FRICREG_ENONFINITE, FRICREG_ENONFINITE};
    for (int k = 0; k < 3; k++) {
        bad[0] = 0.5;
        bad[1] = mu_bad[k];
        ck_assert_int_eq(fricreg_jenkins_set_normal(j, 2, bad, n0, kn), mu_code[k]);
        ck_assert_str_ne(fricreg_jenkins_errmsg(j), "");
        ck_assert_int_eq(fricreg_jenkins_set_normal(j, 2, mu, n0, bad), mu_code[k]);
    }
    bad[0] = 1e300;
    bad[1] = 1e300; /* mu n0 overflows */
    const double big[2] = {1e10, 1e10};
    ck_assert_int_eq(fricreg_jenkins_set_normal(j, 2, big, bad, kn), FRICREG_ENONFINITE);
    /* nothing changed: the fixed bound MUN at any g */
    const double u[2] = {10.0, -10.0};
    double g[2] = {-100.0, -100.0};
    ck_assert_int_eq(fricreg_jenkins_trial_normal(j, 2, u, g, out, NULL, NULL, NULL), FRICREG_OK);
    ck_assert_double_eq(out[0], MUN);
    ck_assert_double_eq(out[1], -MUN);
    /* a contact open at g = 0 (n0 < 0): separated in the plain trial too */
    ck_assert_int_eq(fricreg_jenkins_set_normal(j, 2, mu, n0, kn), FRICREG_OK);
    ck_assert_int_eq(fricreg_jenkins_trial(j, 2, u, out, out + 2), FRICREG_OK);
    ck_assert_double_eq(out[0], 0.5 * 1.0);
    ck_assert_double_eq(out[1], 0.0);
    ck_assert_double_eq(out[3], 0.0);
    for (int k = 0; k < 8; k++)
        out[k] = SENTINEL;
    ck_assert_int_eq(fricreg_jenkins_trial_normal(j, 2, u, NULL, out, NULL, NULL, NULL),
                     FRICREG_ENULL);
    ck_assert_int_eq(fricreg_jenkins_trial_normal(j, 1, u, g, out, NULL, NULL, NULL),
                     FRICREG_ESIZE);
    g[1] = NAN;
    ck_assert_int_eq(fricreg_jenkins_trial_normal(j, 2, u, g, out, out + 2, out + 4, out + 6),
                     FRICREG_ENONFINITE);
    g[1] = 1e308;
    const double kn_big[2] = {2.0, 1e308};
    ck_assert_int_eq(fricreg_jenkins_set_normal(j, 2, mu, n0, kn_big), FRICREG_OK);
    ck_assert_int_eq(fricreg_jenkins_trial_normal(j, 2, u, g, out, out + 2, out + 4, out + 6),
                     FRICREG_ENONFINITE); /* N0 + kn g overflows */
    ck_assert_str_ne(fricreg_jenkins_errmsg(j), "");
    for (int k = 0; k < 8; k++)
        ck_assert_double_eq(out[k], SENTINEL);
    fricreg_jenkins_free(j);
}
END_TEST

static Suite *jenkins_suite(void)
{
    Suite *s = suite_create("jenkins");
    TCase *tc = tcase_create("core");
    tcase_add_test(tc, hysteresis_loop_1d);
    tcase_add_test(tc, elastic_1d);
    tcase_add_test(tc, trial_keeps_committed_state);
    tcase_add_test(tc, tangent_against_differences);
    tcase_add_test(tc, circular_orbit_2d);
    tcase_add_test(tc, bad_input);
    tcase_add_test(tc, normal_load_constant_preload);
    tcase_add_test(tc, normal_load_lift_off);
    tcase_add_test(tc, normal_load_tangent_against_differences);
    tcase_add_test(tc, normal_load_bad_input);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    SRunner *sr = srunner_create(jenkins_suite());
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? 0 : 1;
}
