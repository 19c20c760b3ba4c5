/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_aft_2d.c — Check suite for the sampled AFT of the 3-D contact element
 * (fricreg_aft_jenkins_2d_normal_sampled, fricreg_aft.h): a 2-D Jenkins element in the
 * tangential plane under a normal law with lift-off.
 *
 * Where the numbers come from:
 *   - on one tangential axis (uy = 0) the element is the 1-D one: fx and N equal
 *     fricreg_aft_jenkins_normal_sampled's to the bit (slipping both ways, lifting off, and
 *     stuck where the centred slider holds), fy = 0, and the Jacobian's (u, g) block equals
 *     the 1-D Jacobian to rounding, the uy columns not reaching fx;
 *   - a circular orbit of radius r under a constant N: the closed-form dissipation per period
 *     2 pi r_w mu N, r_w = sqrt(r^2 - (mu N/kt)^2), approached at first order in 1/N with the
 *     leading term 2 pi^2 mu N r_b/N (the return mapping drags the slider along chords), and 0
 *     below r = mu N/kt, where the slider sits at the centre;
 *   - against the time-domain element (fricreg_jenkins, dim 2, fricreg_jenkins_trial_normal
 *     and commit at the same samples), marched from a relaxed slider until the slider repeats,
 *     the last period's forces by a plain DFT written here: an elliptic orbit that slips, one
 *     that lifts off, a bound moving with g, a stuck orbit about its own centre, a slip barely
 *     past the threshold, and a stick that slips of the first periods placed;
 *   - the Jacobian against central differences of the same function (step 1e-6);
 *   - a slip along a line barely past the bound, all but neutral across the line: the stuck
 *     element's forces, u's means (translations) with zero columns, every entry finite. */
#include <check.h>
#include <math.h>
#include <string.h>

#include "fricreg_aft.h"
#include "fricreg_jenkins.h"
#include "quiet_check.h"

#define SENTINEL (-777.125)
#define H 3
#define NC (2 * H + 1)
#define NS 1024

static const double PI = 3.14159265358979323846;

static fricreg_aft *make(int harmonics, size_t samples)
{
    fricreg_aft *a = NULL;
    ck_assert_int_eq(fricreg_aft_create(harmonics, samples, &a), FRICREG_OK);
    return a;
}

static double at(const double *c, double th)
{
    double v = c[0];
    for (int h = 1; h <= H; h++)
        v += c[2 * h - 1] * cos(h * th) + c[2 * h] * sin(h * th);
    return v;
}

/* One case: kt, mu, n0, kn and the coefficients ux, uy, g. */
struct contact {
    double kt, mu, n0, kn;
    double u[2 * NC], g[NC];
    const char *what;
};

START_TEST(one_axis_is_the_1d_element)
{
    static const struct contact cases[] = {
        {2.385, 0.1, 7.0, 0.0, {0.3, 1.0, 0.0, 0.0, 0.2, 0.9, -0.1}, {0.4, 0.5, -0.2}, "slip"},
        {2.0, 0.5, 1.0, 1.0, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.5}, "lift-off"},
        {3.0, 0.4, 2.0, 0.3, {0.1, 1.2, 0.0, 0.0, 0.3}, {0.0, 0.76, -0.24}, "moving bound"},
        {2.385, 0.1, 300.0, 0.0, {0.3, 1.0, 0.0, 0.0, 0.2}, {0.0}, "stuck"},
    };
    fricreg_aft *a = make(H, NS);
    for (size_t c = 0; c < sizeof cases / sizeof *cases; c++) {
        const struct contact *k = &cases[c];
        double f[2 * NC], nf[NC], jac[9 * NC * NC], f1[NC], n1[NC], j1[4 * NC * NC];
        ck_assert_int_eq(fricreg_aft_jenkins_2d_normal_sampled(a, k->kt, k->mu, k->n0, k->kn, NC,
                                                               k->u, k->g, f, nf, jac),
                         FRICREG_OK);
        ck_assert_int_eq(fricreg_aft_jenkins_normal_sampled(a, k->kt, k->mu, k->n0, k->kn, NC, k->u,
                                                            k->g, f1, n1, j1),
                         FRICREG_OK);
        double scale = k->kt + k->mu * k->kn + k->kn;
        for (int i = 0; i < NC; i++) {
            ck_assert_msg(f[i] == f1[i] && nf[i] == n1[i], "%s: f[%d] = %.17g, 1-D %.17g", k->what,
                          i, f[i], f1[i]);
            ck_assert_double_eq(f[NC + i], 0.0);
            for (int j = 0; j < NC; j++) {
                const double *row = &jac[3 * NC * i], *nrow = &jac[3 * NC * (2 * NC + i)];
                ck_assert_msg(fabs(row[j] - j1[2 * NC * i + j]) <= 1e-13 * scale &&
                                  fabs(row[2 * NC + j] - j1[2 * NC * i + NC + j]) <=
                                      1e-13 * scale &&
                                  fabs(nrow[2 * NC + j] - j1[2 * NC * (NC + i) + NC + j]) <=
                                      1e-13 * scale,
                              "%s: jac row %d column %d differs from the 1-D one", k->what, i, j);
                ck_assert_double_eq(row[NC + j], 0.0);                /* dfx/duy */
                ck_assert_double_eq(jac[3 * NC * (NC + i) + j], 0.0); /* dfy/dux */
                ck_assert_double_eq(nrow[j], 0.0);                    /* dN/dux */
                ck_assert_double_eq(nrow[NC + j], 0.0);               /* dN/duy */
            }
        }
    }
    fricreg_aft_free(a);
}
END_TEST

/* The dissipation per period of the tangential forces, pi sum_h h (b_h fa_h - a_h fb_h) on
 * each axis. */
static double dissipation(const double *u, const double *f)
{
    double d = 0.0;
    for (int axis = 0; axis < 2; axis++)
        for (int h = 1; h <= H; h++) {
            const double *x = u + axis * NC, *y = f + axis * NC;
            d += PI * h * (x[2 * h] * y[2 * h - 1] - x[2 * h - 1] * y[2 * h]);
        }
    return d;
}

/* The circular orbit u = r (cos θ, sin θ) under N = n0 at ns samples: its dissipation. */
static double circular(size_t ns, double kt, double mu, double n0, double r)
{
    double u[2 * NC] = {0.0}, g[NC] = {0.0}, f[2 * NC], nf[NC];
    u[1] = r;      /* ux = r cos θ */
    u[NC + 2] = r; /* uy = r sin θ */
    fricreg_aft *a = make(H, ns);
    ck_assert_int_eq(fricreg_aft_jenkins_2d_normal_sampled(a, kt, mu, n0, 0.0, NC, u, g, f, nf,
                                                           NULL),
                     FRICREG_OK);
    ck_assert_double_eq_tol(nf[0], n0, 1e-14 * n0);
    fricreg_aft_free(a);
    return dissipation(u, f);
}

/* The return mapping at samples drags the slider along chords, one sample behind the
 * continuous element on a curved orbit: the error of the dissipation is first order in 1/N,
 * 2 pi^2 mu N r_b / N below the closed form (r_b = mu N/kt) at every radius. */
START_TEST(circular_orbit_dissipation)
{
    const double kt = 40.0, mu = 0.3, n0 = 5.0, rb = mu * n0 / kt; /* r_b = 0.0375 */
    const double radii[] = {0.0376, 0.04, 0.1, 1.0};
    for (size_t c = 0; c < sizeof radii / sizeof *radii; c++) {
        double r = radii[c], exact = 2.0 * PI * sqrt(r * r - rb * rb) * mu * n0;
        double e1 = exact - circular(1024, kt, mu, n0, r),
               e4 = exact - circular(4096, kt, mu, n0, r);
        double lead = 2.0 * PI * PI * mu * n0 * rb / 1024.0;
        ck_assert_msg(e1 > 0.0 && fabs(e1 / lead - 1.0) < 0.06 && fabs(e1 / e4 - 4.0) < 0.15,
                      "r = %g: errors %.6g (N = 1024), %.6g (4096), leading term %.6g", r, e1, e4,
                      lead);
    }
    ck_assert_double_lt(fabs(circular(1024, kt, mu, n0, 0.03)), 1e-15 * mu * n0); /* stuck */
}
END_TEST

/* The time-domain element at the NS samples, marched from a relaxed slider until the slider
 * at the period's end repeats (to 1e-15 of its scale; at most 4000 periods), the last
 * period's coefficients by a plain DFT. */
static void time_domain(const struct contact *k, double *f, double *nf)
{
    fricreg_jenkins *j = NULL;
    double one = 1.0, w[2] = {INFINITY, INFINITY}, wl[2]; /* no slider read yet */
    ck_assert_int_eq(fricreg_jenkins_create(2, 1, &j), FRICREG_OK);
    ck_assert_int_eq(fricreg_jenkins_set_params(j, 1, &k->kt, &one), FRICREG_OK);
    ck_assert_int_eq(fricreg_jenkins_set_normal(j, 1, &k->mu, &k->n0, &k->kn), FRICREG_OK);
    for (int p = 0; p < 4000; p++) {
        int last = p > 0 && fabs(w[0] - wl[0]) + fabs(w[1] - wl[1]) <= 1e-15;
        if (last) {
            memset(f, 0, 2 * NC * sizeof *f);
            memset(nf, 0, NC * sizeof *nf);
        }
        for (size_t n = 0; n < NS; n++) {
            double th = 2.0 * PI * (double)n / (double)NS, fn[2], nn;
            double un[2] = {at(k->u, th), at(k->u + NC, th)}, gn = at(k->g, th);
            QUIET_OK(fricreg_jenkins_trial_normal(j, 1, un, &gn, fn, &nn, NULL, NULL));
            QUIET_OK(fricreg_jenkins_commit(j));
            if (!last)
                continue;
            for (int i = 0; i < NC; i++) {
                int h = (i + 1) / 2;
                double b = i == 0 ? 1.0 / NS : 2.0 * (i % 2 ? cos(h * th) : sin(h * th)) / NS;
                f[i] += fn[0] * b;
                f[NC + i] += fn[1] * b;
                nf[i] += nn * b;
            }
        }
        if (last)
            break;
        wl[0] = w[0];
        wl[1] = w[1];
        ck_assert_int_eq(fricreg_jenkins_get_slider(j, 1, w), FRICREG_OK);
        ck_assert_int_lt(p, 3999);
    }
    fricreg_jenkins_free(j);
}

static const struct contact marched[] = {
    {3.0, 0.4, 2.0, 0.0, {0.1, 1.0, 0.0, 0.0, 0.2, 0.0, 0.0, 0.0, 0.0, 0.6}, {0.0}, "ellipse"},
    {2.0,
     0.5,
     1.0,
     1.0,
     {0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.5},
     {0.0, 0.0, 1.5},
     "lift-off"},
    {3.0,
     0.4,
     2.0,
     0.6,
     {0.1, 1.2, 0.0, 0.0, 0.3, 0, 0, 0, 0.0, 0.5, 0.1},
     {0.0, 0.76, -0.24},
     "moving bound"},
    {3.0, 0.4, 20.0, 0.0, {0.0, 0.5, 0.0, 0.0, 0.0, 0, 0, 0, 0.0, 0.3}, {0.0}, "stuck"},
    /* a slip barely past the threshold (r_b = 0.0375): the slider contracts slowly onto its
     * periodic state, which Newton's steps find */
    {40.0, 0.3, 5.0, 0.0, {0.0, 0.0385, 0.0, 0.001, 0, 0, 0, 0, 0.0, 0.0385}, {0.0}, "barely"},
    /* a bound moving with g that the centre of the orbit's enclosing circle misses (0.7 from
     * u at theta = pi, where mu N / kt = 0.5) but a slider beside it clears: the first periods
     * slip, then the element sticks throughout (an ellipse: the circle's support is one
     * diameter, a regular polygon of samples would leave it undefined) */
    {1.0, 1.0, 1.0, 1.0, {0.0, 0.7, 0.0, 0, 0, 0, 0, 0, 0.0, 0.4}, {0.0, 0.5}, "placed"},
};

START_TEST(against_the_time_domain_element)
{
    fricreg_aft *a = make(H, NS);
    for (size_t c = 0; c < sizeof marched / sizeof *marched; c++) {
        const struct contact *k = &marched[c];
        double f[2 * NC], nf[NC], ft[2 * NC], nft[NC], scale = k->mu * (fabs(k->n0) + 4 * k->kn);
        ck_assert_int_eq(fricreg_aft_jenkins_2d_normal_sampled(a, k->kt, k->mu, k->n0, k->kn, NC,
                                                               k->u, k->g, f, nf, NULL),
                         FRICREG_OK);
        time_domain(k, ft, nft);
        for (int i = 0; i < 2 * NC; i++)
            ck_assert_msg(fabs(f[i] - ft[i]) <= 1e-10 * scale, "%s: f[%d] = %.15g, marched %.15g",
                          k->what, i, f[i], ft[i]);
        for (int i = 0; i < NC; i++)
            ck_assert_msg(fabs(nf[i] - nft[i]) <= 1e-10 * (scale + 1.0),
                          "%s: nf[%d] = %.15g, marched %.15g", k->what, i, nf[i], nft[i]);
    }
    fricreg_aft_free(a);
}
END_TEST

START_TEST(jacobian_against_differences)
{
    fricreg_aft *a = make(H, NS);
    const double h = 1e-6;
    for (size_t c = 0; c < sizeof marched / sizeof *marched; c++) {
        const struct contact *k = &marched[c];
        double x[3 * NC], f[2 * NC], nf[NC], jac[9 * NC * NC], scale = k->kt + k->kn;
        memcpy(x, k->u, 2 * NC * sizeof *x);
        memcpy(x + 2 * NC, k->g, NC * sizeof *x);
        ck_assert_int_eq(fricreg_aft_jenkins_2d_normal_sampled(a, k->kt, k->mu, k->n0, k->kn, NC, x,
                                                               x + 2 * NC, f, nf, jac),
                         FRICREG_OK);
        for (int j = 0; j < 3 * NC; j++) {
            double xp[3 * NC], xm[3 * NC], fp[3 * NC], fm[3 * NC];
            memcpy(xp, x, sizeof xp);
            memcpy(xm, x, sizeof xm);
            xp[j] += h;
            xm[j] -= h;
            QUIET_OK(fricreg_aft_jenkins_2d_normal_sampled(a, k->kt, k->mu, k->n0, k->kn, NC, xp,
                                                           xp + 2 * NC, fp, fp + 2 * NC, NULL));
            QUIET_OK(fricreg_aft_jenkins_2d_normal_sampled(a, k->kt, k->mu, k->n0, k->kn, NC, xm,
                                                           xm + 2 * NC, fm, fm + 2 * NC, NULL));
            for (int i = 0; i < 3 * NC; i++) {
                double d = (fp[i] - fm[i]) / (2 * h);
                ck_assert_msg(fabs(d - jac[3 * NC * i + j]) <= 1e-6 * scale,
                              "%s: d out[%d]/d in[%d] = %.12g, differences %.12g", k->what, i, j,
                              jac[3 * NC * i + j], d);
            }
        }
    }
    fricreg_aft_free(a);
}
END_TEST

/* A slip along a line, barely past the bound (by 1e-12 of r_b = mu N0/kt), beside the line's
 * direction (uy's mean only): across the line the slider is all but neutral over a period (its
 * deviation shrinks by r_b/|u - w| at each sliding sample, 1 - 3e-13 over the period here),
 * so that I - Psi is singular to 1e-9 and the periodic slider's derivatives take the
 * pseudo-inverse (aft_2d.c, solve_periodic), whose output must stay finite: a NaN there is
 * what fuzz_aft once found. Closed form: under a constant N the element is
 * translation-invariant, so the columns of u's two means vanish, and the forces are the
 * stuck element's, kt (u - mean u) along x and 0 along y, to the slip's 1e-12. */
START_TEST(slip_along_a_line_is_neutral_across_it)
{
    const double kt = 40.0, mu = 0.3, n0 = 5.0, rb = mu * n0 / kt;
    double u[2 * NC] = {0.01, rb * (1.0 + 1e-12)}, g[NC] = {0.0};
    u[NC] = 0.02;
    double f[2 * NC], nf[NC], jac[9 * NC * NC];
    fricreg_aft *a = make(H, NS);
    ck_assert_int_eq(fricreg_aft_jenkins_2d_normal_sampled(a, kt, mu, n0, 0.0, NC, u, g, f, nf,
                                                           jac),
                     FRICREG_OK);
    for (int i = 0; i < 2 * NC; i++) {
        double stuck = i == 1 ? kt * u[1] : 0.0;
        ck_assert_msg(fabs(f[i] - stuck) <= 1e-9 * mu * n0, "f[%d] = %.15g, stuck %.15g", i, f[i],
                      stuck);
    }
    for (int i = 0; i < 3 * NC; i++)
        for (int j = 0; j < 3 * NC; j++) {
            double d = jac[3 * NC * i + j];
            ck_assert_msg(isfinite(d), "d out[%d]/d in[%d] = %g", i, j, d);
            if (i < 2 * NC && (j == 0 || j == NC)) /* u's means */
                ck_assert_msg(fabs(d) <= 1e-9 * kt, "d f[%d]/d u[%d] = %g, not a translation", i, j,
                              d);
        }
    fricreg_aft_free(a);
}
END_TEST

/* Smooth between the element's own events: a stuck orbit (ux = 0.01 cos + 0.004 sin,
 * uy = 0.006 sin; kt 20, mu 0.25, n0 4, kn 50) under g = -A cos, A from 0.0780 to 0.0840 in
 * steps of 2e-6: the continuous element starts to slip near A = 0.0791 where N dips, and opens
 * at A = 0.08; between those, and past them, its forces are smooth in A. The first harmonic of
 * fx, extrapolated as harmonic balance takes it (2 F(N) - F(N/2), N = 512), may change its
 * slope by a fifth at those events only: at most 4 such places. With the slider snapped to u
 * at the last open sample when the contact closes (1.9), the slope changed at 61 places, by up
 * to 0.6 of itself at every N (0.62 at N = 8192): each time the last open sample moved. */
START_TEST(smooth_between_events)
{
    fricreg_aft *a = make(H, 512), *b = make(H, 256);
    double prev[2] = {0.0, 0.0};
    int rough = 0;
    for (int k = 0; k <= 3000; k++) {
        double A = 0.078 + 2e-6 * k, u[2 * NC] = {0}, g[NC] = {0}, f[2][2 * NC], nf[NC];
        u[1] = 0.01;
        u[2] = 0.004;
        u[NC + 2] = 0.006;
        g[1] = -A;
        ck_assert_int_eq(fricreg_aft_jenkins_2d_normal_sampled(a, 20, 0.25, 4, 50, NC, u, g, f[0],
                                                               nf, NULL),
                         FRICREG_OK);
        ck_assert_int_eq(fricreg_aft_jenkins_2d_normal_sampled(b, 20, 0.25, 4, 50, NC, u, g, f[1],
                                                               nf, NULL),
                         FRICREG_OK);
        double fx1 = 2.0 * f[0][1] - f[1][1], d = fx1 - prev[1];
        /* where fx1 stands still (stuck: its steps are rounding), nothing to compare */
        double slope = fmax(fabs(d), fabs(prev[0]));
        if (k >= 2 && slope > 1e-9 * fabs(fx1) && fabs(d - prev[0]) > 0.2 * slope)
            rough++;
        prev[0] = k >= 1 ? d : 0.0;
        prev[1] = fx1;
    }
    ck_assert_msg(rough <= 4, "the slope of fx's first harmonic jumps at %d places", rough);
    fricreg_aft_free(a);
    fricreg_aft_free(b);
}
END_TEST

START_TEST(bad_input)
{
    const double u[2 * NC] = {0.3, 1.0, 0, 0, 0, 0, 0, 0.1, 0.0, 0.5}, g[NC] = {0.1, 0.2};
    double f[2 * NC], nf[NC], jac[9 * NC * NC], bad[2 * NC];
    for (int i = 0; i < 2 * NC; i++)
        f[i] = SENTINEL;
    for (int i = 0; i < NC; i++)
        nf[i] = SENTINEL;
    fricreg_aft *a = make(H, NS), *exact = make(H, 0);
    ck_assert_int_eq(fricreg_aft_jenkins_2d_normal_sampled(NULL, 1, 1, 1, 1, NC, u, g, f, nf, jac),
                     FRICREG_ENULL);
    ck_assert_int_eq(fricreg_aft_jenkins_2d_normal_sampled(a, 1, 1, 1, 1, NC, u, g, f, NULL, jac),
                     FRICREG_ENULL);
    ck_assert_int_eq(fricreg_aft_jenkins_2d_normal_sampled(a, 1, 1, 1, 1, NC, NULL, g, f, nf, jac),
                     FRICREG_ENULL);
    ck_assert_int_eq(fricreg_aft_jenkins_2d_normal_sampled(exact, 1, 1, 1, 1, NC, u, g, f, nf, jac),
                     FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_aft_errmsg(exact), "jenkins_2d_normal_sampled: the "
                                                            "workspace was created with no "
                                                            "samples"));
    ck_assert_int_eq(fricreg_aft_jenkins_2d_normal_sampled(a, 1, 1, 1, 1, NC - 2, u, g, f, nf, jac),
                     FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_aft_jenkins_2d_normal_sampled(a, 0, 1, 1, 1, NC, u, g, f, nf, jac),
                     FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_aft_jenkins_2d_normal_sampled(a, 1, 1, 1, -1, NC, u, g, f, nf, jac),
                     FRICREG_EINVAL);
    ck_assert_str_eq(fricreg_aft_errmsg(a), "jenkins_2d_normal_sampled: kn = -1 must be >= 0");
    memcpy(bad, u, sizeof bad);
    bad[NC + 1] = NAN; /* uy */
    ck_assert_int_eq(fricreg_aft_jenkins_2d_normal_sampled(a, 1, 1, 1, 1, NC, bad, g, f, nf, jac),
                     FRICREG_ENONFINITE);
    ck_assert_str_eq(fricreg_aft_errmsg(a), "jenkins_2d_normal_sampled: u[8] = nan");
    ck_assert_int_eq(fricreg_aft_jenkins_2d_normal_sampled(a, 1e-300, 1, 1e10, 1, NC, u, g, f, nf,
                                                           jac),
                     FRICREG_ENONFINITE);
    for (int i = 0; i < 2 * NC; i++)
        ck_assert_double_eq(f[i], SENTINEL);
    for (int i = 0; i < NC; i++)
        ck_assert_double_eq(nf[i], SENTINEL);
    fricreg_aft_free(a);
    fricreg_aft_free(exact);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("aft_2d");
    TCase *tc = tcase_create("core");
    tcase_add_test(tc, one_axis_is_the_1d_element);
    tcase_add_test(tc, circular_orbit_dissipation);
    tcase_add_test(tc, against_the_time_domain_element);
    tcase_add_test(tc, jacobian_against_differences);
    tcase_add_test(tc, slip_along_a_line_is_neutral_across_it);
    tcase_add_test(tc, smooth_between_events);
    tcase_add_test(tc, bad_input);
    suite_add_tcase(s, tc);
    SRunner *sr = srunner_create(s);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? 0 : 1;
}
