/* SPDX-License-Identifier: GPL-3.0-or-later */
/* aft_roots.c — the switch points of the exact AFT of 1-D Jenkins sliders (aft_roots.h,
 * aft_internal.h): the real roots and sign changes of trigonometric polynomials, the velocity
 * reversals of u and the onsets of slip. Below the march (aft_exact.c) and the lift-off path
 * (aft_normal_exact.c).
 *
 * Roots. A real trigonometric polynomial g(θ) = c0 + sum_h (α_h cos hθ + β_h sin hθ) of
 * degree H is z^-H times a polynomial of degree 2H in z = e^{iθ}, whose roots on the unit
 * circle are g's real roots; its coefficients are complex, and GSL's gsl_poly_complex_solve
 * takes real ones. The half-angle substitution t = tan((θ − θs)/2) maps the same unit-circle
 * roots onto the real roots of a real polynomial of degree 2H,
 *
 *     P(t) = (1 + t^2)^H g(θs + φ) = c0 Q_0(t) + sum_h Re[(p_h − i q_h) Q_h(t)],
 *     Q_h(t) = (1 + i t)^(H+h) (1 − i t)^(H−h)          (since e^{iφ} = (1 + i t)^2/(1 + t^2))
 *
 * with (p_h, q_h) the coefficients of g rotated by θs. Its leading coefficient is g(θs + π),
 * so θs is taken where |g(θs + π)| is largest among 4H + 2 equidistant angles: P then has
 * degree 2H exactly, no root near t = ∞, and GSL never sees a zero leading term. The roots
 * are polished by Newton's method on g itself (at most three steps, each kept only if it
 * lowers |g|), which restores the digits the substitution costs.
 *
 * Reversals are the roots of u' where its sign changes (a double root, a flat inflection,
 * changes nothing and is dropped; so are duplicates); the sign of u' on each arc between
 * candidate roots is read at the arc's middle. They are isolated on a certified grid first
 * (isolate_roots, O(H^2)); the companion matrix above, O(H^3), only where the grid cannot
 * certify an interval. */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include "aft_internal.h"
#include "aft_roots.h"
#include "base/fr_math.h"

/* g(θ) and g'(θ) of the trigonometric polynomial with coefficients co[2H+1] in the layout of
 * fricreg_aft.h, from c1 = cos θ and s1 = sin θ; cos hθ, sin hθ by rotation. */
static double trig_eval_cs(int H, const double *co, double c1, double s1, double *dg)
{
    double c = 1.0, s = 0.0, g = co[0], d = 0.0;
    for (int h = 1; h <= H; h++) {
        double cn = c * c1 - s * s1;
        s = s * c1 + c * s1;
        c = cn;
        g += co[2 * h - 1] * c + co[2 * h] * s;
        d += h * (co[2 * h] * c - co[2 * h - 1] * s);
    }
    *dg = d;
    return g;
}

double fr_aft_trig_eval(int H, const double *co, double th, double *dg)
{
    return trig_eval_cs(H, co, cos(th), sin(th), dg);
}

static double trig_eval(int H, const double *co, double th, double *dg)
{
    return fr_aft_trig_eval(H, co, th, dg);
}

/* Newton on g from th, at most three steps, each kept if it stays in [lo, hi] and lowers |g|. */
static double polish(int H, const double *co, double th, double lo, double hi)
{
    for (int it = 0; it < 3; it++) {
        double d, g = trig_eval(H, co, th, &d);
        if (g == 0.0 || d == 0.0)
            break;
        double next = th - g / d, d2;
        if (!(next >= lo && next <= hi) || !(fabs(trig_eval(H, co, next, &d2)) < fabs(g)))
            break;
        th = next;
    }
    return th;
}

/* The roots of the trigonometric polynomial co (not zero, entries of order 1) as angles: real
 * parts into a->cand (in [0, 2pi)), sizes of the imaginary parts into a->cim, their count
 * (2D, D the degree kept) into *count. Harmonics below DBL_EPSILON times the largest
 * coefficient are left out of the algebraic polynomial (they move a simple real root by less
 * than the polish restores; kept, they would put multiple roots at t = +-i, which slow GSL's
 * QR). Returns FRICREG_OK, or FRICREG_EINTEGRATOR (message recorded) if GSL's QR did not
 * converge. */
static int trig_roots(fricreg_aft *a, const char *fn, const double *co, int *count)
{
    int H = a->H, D = 1;
    double big = fabs(co[0]), d;
    for (size_t j = 1; j < a->nc; j++)
        big = fmax(big, fabs(co[j]));
    for (int h = 1; h <= H; h++)
        if (fmax(fabs(co[2 * h - 1]), fabs(co[2 * h])) > DBL_EPSILON * big)
            D = h;
    if (a->table_H != D)
        fr_aft_half_angle_table(a, D);
    size_t w = (size_t)(2 * D + 1), probes = 4 * (size_t)D + 2;
    double best = -1.0, ths = 0.0;
    for (size_t j = 0; j < probes; j++) {
        double th = FR_TWO_PI * (double)j / (double)probes, g = fabs(trig_eval(H, co, th, &d));
        if (g > best) {
            best = g;
            ths = th - 0.5 * FR_TWO_PI;
        }
    }
    for (size_t k = 0; k < w; k++)
        a->poly[k] = co[0] * a->qre[k];
    for (int h = 1; h <= D; h++) {
        double ch = cos(h * ths), sh = sin(h * ths), al = co[2 * h - 1], be = co[2 * h];
        double p = al * ch + be * sh, q = be * ch - al * sh;
        const double *re = &a->qre[w * (size_t)h], *im = &a->qim[w * (size_t)h];
        for (size_t k = 0; k < w; k++)
            a->poly[k] += p * re[k] + q * im[k];
    }
    double scale = 0.0;
    for (size_t k = 0; k < w; k++)
        scale = fmax(scale, fabs(a->poly[k]));
    if (!(scale > 0.0) || a->poly[w - 1] == 0.0) /* g = 0 at every probe: ruled out by callers */
        return fr_fail(a, FRICREG_EINTEGRATOR, "%s: a trigonometric polynomial vanished", fn);
    for (size_t k = 0; k < w; k++)
        a->poly[k] /= scale;
    /* inputs finite, leading term non-zero, workspace of the right size: GSL's only remaining
     * failure is QR's non-convergence */
    a->ws.nc = w - 1;
    if (gsl_poly_complex_solve(a->poly, w, &a->ws, a->roots) != GSL_SUCCESS)
        return fr_fail(a, FRICREG_EINTEGRATOR, "%s: GSL's polynomial root solver did not converge",
                       fn);
    for (int k = 0; k < 2 * D; k++) {
        double x = a->roots[2 * k], y = a->roots[2 * k + 1];
        double th = fmod(ths + 2.0 * atan(x), FR_TWO_PI);
        a->cand[k] = th < 0.0 ? th + FR_TWO_PI : th;
        a->cim[k] = 2.0 * fabs(y) / (1.0 + x * x); /* d theta/dt = 2/(1 + t^2) */
    }
    *count = 2 * D;
    return FRICREG_OK;
}

/* u(theta) - target for GSL's Brent. */
struct onset_probe {
    int H;
    const double *u;
    double target;
};

static double onset_gap(double th, void *params)
{
    const struct onset_probe *p = params;
    double d;
    return trig_eval(p->H, p->u, th, &d) - p->target;
}

/* GSL's Brent for the root of co(θ) − target in the bracket [*lo, *hi] (a sign change), to a
 * width of 4 DBL_EPSILON |θ| (at most 100 iterations: Brent's guarantee is about
 * 4 log2(2 pi/eps) evaluations); the final bracket into *lo, *hi. The function is finite
 * (inputs checked) and the bracket is checked to straddle 0 with this very function, so GSL
 * has nothing to report to its error handler. */
/* x and y of opposite signs, by their signs: x y < 0 underflows to -0 for values near DBL_MIN
 * (a margin of 1e-303 against 1e-304 at kt, mu of 1e-304) and took a bracket for none. */
static int opposite_signs(double x, double y)
{
    return (x < 0.0 && y > 0.0) || (x > 0.0 && y < 0.0);
}

static double brent_root(fricreg_aft *a, const double *co, double target, double *lo, double *hi)
{
    struct onset_probe p = {a->H, co, target};
    gsl_function F = {onset_gap, &p};
    double th = 0.5 * (*lo + *hi), flo = onset_gap(*lo, &p), fhi = onset_gap(*hi, &p);
    /* a bracket decided by values computed another way (the grid's rotated angles) may not
     * straddle 0 here by rounding: an end is then a root to rounding, and GSL, which would
     * call its error handler, is not asked */
    if (!opposite_signs(flo, fhi))
        return fabs(flo) <= fabs(fhi) ? *lo : *hi;
    if (gsl_root_fsolver_set(a->brent, &F, *lo, *hi) == GSL_SUCCESS)
        for (int it = 0; it < 100; it++) {
            if (gsl_root_fsolver_iterate(a->brent) != GSL_SUCCESS)
                break;
            th = gsl_root_fsolver_root(a->brent);
            *lo = gsl_root_fsolver_x_lower(a->brent);
            *hi = gsl_root_fsolver_x_upper(a->brent);
            if (gsl_root_test_interval(*lo, *hi, 0.0, 4.0 * DBL_EPSILON) == GSL_SUCCESS)
                break;
        }
    return th;
}

double fr_aft_root_in(fricreg_aft *a, const double *co, double lo, double hi)
{
    double th = brent_root(a, co, 0.0, &lo, &hi);
    return polish(a->H, co, th, lo, hi);
}

/* Isolation of the sign changes of g = co (entries of order 1) on a grid, certified by bounds
 * on its derivatives, B1 >= |g'|, B2 >= |g''|, B3 >= |g'''| (sums of h |c_h|, h^2 |c_h|,
 * h^3 |c_h|). On an interval [a, b] of width δ whose ends have one sign σ, g cannot vanish if
 * |g(a)| + |g(b)| > B1 δ (two cones), or if σ (g(a) + g'(a) δ) − B2 δ²/2 > 0 (the Taylor bound
 * from a, concave: positive at both ends, so throughout), or the same from b. Where the signs
 * differ, g has exactly one root if g' keeps one sign, which the same tests on g' (with g'',
 * B2, B3) certify. An interval certified neither way is halved, up to ISOLATE_DEPTH times.
 * Each root is bracketed for Brent. The companion matrix finds every root but costs O(H^3),
 * 70 % of an exact AFT at H = 7; the grid costs O(H^2) and is certain where it certifies.
 * isolate_roots returns the number of roots, in a->cand, or -1 where some interval could not
 * be certified (the caller then takes the companion matrix). */
#define ISOLATE_GRID 8  /* grid intervals per harmonic of the degree */
#define ISOLATE_DEPTH 8 /* halvings of an interval before giving up (at most 2^8 leaves) */
struct isolation {
    fricreg_aft *a;
    const double *co;
    double B1, B2, B3;
    int count;
};

/* g and its first two derivatives at one angle t, from cos t and sin t. */
struct sample {
    double t, g, d, dd;
};

static struct sample sample_at(const struct isolation *iso, double t, double c1, double s1)
{
    const double *co = iso->co;
    double c = 1.0, s = 0.0;
    struct sample p = {t, co[0], 0.0, 0.0};
    for (int h = 1; h <= iso->a->H; h++) {
        double cn = c * c1 - s * s1, al = co[2 * h - 1], be = co[2 * h];
        s = s * c1 + c * s1;
        c = cn;
        p.g += al * c + be * s;
        p.d += h * (be * c - al * s);
        p.dd -= (double)h * h * (al * c + be * s);
    }
    return p;
}

/* Whether f, with f(a) = f0, f'(a) = f0p, f(b) = f1, f'(b) = f1p, |f'| <= b1 and |f''| <= b2
 * on [a, b] of width w, keeps one sign there (the tests above). */
static int keeps_sign(double f0, double f0p, double f1, double f1p, double b1, double b2, double w)
{
    if (!(f0 * f1 > 0.0))
        return 0;
    double sg = f0 > 0.0 ? 1.0 : -1.0, curve = 0.5 * b2 * w * w;
    return fabs(f0) + fabs(f1) > b1 * w || sg * (f0 + f0p * w) - curve > 0.0 ||
           sg * (f1 - f1p * w) - curve > 0.0;
}

static int isolate_interval(struct isolation *iso, struct sample p, struct sample q, int depth)
{
    double w = q.t - p.t;
    if (keeps_sign(p.g, p.d, q.g, q.d, iso->B1, iso->B2, w))
        return 0;
    if (opposite_signs(p.g, q.g) && keeps_sign(p.d, p.dd, q.d, q.dd, iso->B2, iso->B3, w)) {
        if (iso->count >= 2 * iso->a->H)
            return -1; /* more sign changes than the degree allows: rounding, not roots */
        double lo = p.t, hi = q.t, th = brent_root(iso->a, iso->co, 0.0, &lo, &hi);
        iso->a->cand[iso->count++] = polish(iso->a->H, iso->co, th, lo, hi);
        return 0;
    }
    if (depth == 0)
        return -1;
    double tm = 0.5 * (p.t + q.t);
    struct sample m = sample_at(iso, tm, cos(tm), sin(tm));
    if (isolate_interval(iso, p, m, depth - 1) != 0)
        return -1;
    return isolate_interval(iso, m, q, depth - 1);
}

static int isolate_roots(fricreg_aft *a, const double *co)
{
    int H = a->H, n = ISOLATE_GRID * H;
    struct isolation iso = {a, co, 0.0, 0.0, 0.0, 0};
    for (int h = 1; h <= H; h++) {
        double c = fabs(co[2 * h - 1]) + fabs(co[2 * h]);
        iso.B1 += h * c;
        iso.B2 += (double)h * h * c;
        iso.B3 += (double)h * h * h * c;
    }
    /* a margin for the rounding of the values and of the grid's angles, which are rotated
     * step by step (one sincos for the grid) */
    iso.B1 *= 1.0 + 1e-9;
    iso.B2 *= 1.0 + 1e-9;
    iso.B3 *= 1.0 + 1e-9;
    double cd = cos(FR_TWO_PI / n), sd = sin(FR_TWO_PI / n), c1 = 1.0, s1 = 0.0;
    struct sample first = sample_at(&iso, 0.0, 1.0, 0.0), p = first;
    for (int i = 1; i <= n; i++) { /* the last interval closes the period on the first point */
        double cn = c1 * cd - s1 * sd;
        s1 = s1 * cd + c1 * sd;
        c1 = cn;
        struct sample q = first;
        q.t = FR_TWO_PI * (double)i / (double)n;
        if (i < n)
            q = sample_at(&iso, q.t, c1, s1);
        if (isolate_interval(&iso, p, q, ISOLATE_DEPTH) != 0)
            return -1;
        p = q;
    }
    return iso.count;
}

static int cmp_double(const void *x, const void *y)
{
    double p = *(const double *)x, q = *(const double *)y;
    return (p > q) - (p < q);
}

static int sign_of(double x)
{
    return (x > 0.0) - (x < 0.0);
}

int fr_aft_sign_changes(fricreg_aft *a, const char *fn, const double *co, double *roots, int *dir,
                        int *m)
{
    int H = a->H;
    double d;
    *m = 0;
    int K = isolate_roots(a, co);
    if (K < 0) { /* not certified on the grid: every root, by the companion matrix */
        int nroots = 0, status = trig_roots(a, fn, co, &nroots);
        if (status != FRICREG_OK)
            return status;
        K = 0;
        for (int k = 0; k < nroots; k++) /* real to first order: |Im theta| below 1e-6 */
            if (a->cim[k] <= 1e-6)
                a->cand[K++] = polish(H, co, a->cand[k], a->cand[k] - 0.1, a->cand[k] + 0.1);
    }
    for (int k = 0; k < K; k++) { /* back into [0, 2pi) after the polish */
        a->cand[k] = fmod(a->cand[k], FR_TWO_PI);
        if (a->cand[k] < 0.0)
            a->cand[k] += FR_TWO_PI;
    }
    qsort(a->cand, (size_t)K, sizeof *a->cand, cmp_double);
    int kept = 0;
    for (int k = 0; k < K; k++) /* duplicates (a double root found twice) */
        if (kept == 0 || a->cand[k] - a->cand[kept - 1] > 1e-10)
            a->cand[kept++] = a->cand[k];
    if (kept > 1 && a->cand[0] + FR_TWO_PI - a->cand[kept - 1] <= 1e-10)
        kept--;
    /* sign of co on arc k (from cand[k] to the next); a zero takes the previous arc's */
    for (int k = 0; k < kept; k++) {
        double lo = a->cand[k], hi = k + 1 < kept ? a->cand[k + 1] : a->cand[0] + FR_TWO_PI;
        dir[k] = sign_of(trig_eval(H, co, 0.5 * (lo + hi), &d));
    }
    for (int pass = 0; pass < 2; pass++)
        for (int k = 0; k < kept; k++)
            if (dir[k] == 0)
                dir[k] = dir[(k + kept - 1) % kept];
    for (int k = 0; k < kept; k++)
        if (dir[k] != 0 && dir[k] != dir[(k + kept - 1) % kept]) {
            roots[*m] = a->cand[k];
            dir[*m] = dir[k]; /* *m <= k: dir is written behind its reads */
            (*m)++;
        }
    return FRICREG_OK;
}

int fr_aft_reversals(fricreg_aft *a, const char *fn, const double *u, int *m)
{
    int H = a->H;
    double *du = a->dcoef, big = 0.0;
    du[0] = 0.0;
    for (int h = 1; h <= H; h++) {
        du[2 * h - 1] = h * u[2 * h];
        du[2 * h] = -h * u[2 * h - 1];
        big = fmax(big, fmax(fabs(du[2 * h - 1]), fabs(du[2 * h])));
    }
    *m = 0;
    if (big == 0.0)
        return FRICREG_OK;
    for (int j = 1; j < (int)a->nc; j++)
        du[j] /= big;
    int status = fr_aft_sign_changes(a, fn, du, a->rev, a->rdir, m);
    if (status != FRICREG_OK)
        return status;
    if (*m < 2)
        return fr_fail(a, FRICREG_EINTEGRATOR,
                       "%s: fewer than two velocity reversals found for a non-constant u", fn);
    return FRICREG_OK;
}

int fr_aft_extremes(fricreg_aft *a, const char *fn, const double *u, double *thmax, double *thmin)
{
    int m, status = fr_aft_reversals(a, fn, u, &m);
    *thmax = *thmin = 0.0;
    if (status != FRICREG_OK || m == 0)
        return status;
    double d, umax = -INFINITY, umin = INFINITY;
    for (int i = 0; i < m; i++) {
        double v = trig_eval(a->H, u, a->rev[i], &d);
        if (v > umax) {
            umax = v;
            *thmax = a->rev[i];
        }
        if (v < umin) {
            umin = v;
            *thmin = a->rev[i];
        }
    }
    return FRICREG_OK;
}

double fr_aft_slip_onset(fricreg_aft *a, const double *u, double target, int dir, double al,
                         double be)
{
    struct onset_probe p = {a->H, u, target};
    if (dir * onset_gap(al, &p) >= 0.0)
        return al;
    double lo = al, hi = be, th = brent_root(a, u, target, &lo, &hi);
    double *co = a->dcoef; /* u - target as coefficients, for the Newton step */
    memcpy(co, u, a->nc * sizeof *co);
    co[0] -= target;
    return polish(a->H, co, th, lo, hi);
}
