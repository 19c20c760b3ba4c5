/* SPDX-License-Identifier: GPL-3.0-or-later */
/* disk_block.c — one 2-D contact's subproblem: projection onto a disk in the W_ii metric
 * (disk_block.h; docs/laws2d.md, "Coupled 2-D contacts in a context"). */
#include <float.h>
#include <math.h>

#include <gsl/gsl_errno.h>

#include "disk_block.h"

#define BRENT_MAX_ITER 200

void fr_disk_eig2(double a, double b, double d, struct fr_disk_eig *e)
{
    double t = 0.0, c = 1.0, s = 0.0;
    if (b != 0.0) {
        double tau = (d - a) / (2.0 * b);
        t = (tau >= 0.0 ? 1.0 : -1.0) / (fabs(tau) + hypot(1.0, tau));
        c = 1.0 / hypot(1.0, t);
        s = t * c;
    }
    /* J = [[c, s], [-s, c]], J^T A J = diag(a - t b, d + t b): columns e1 = (c, -s), e2. */
    e->d1 = a - t * b;
    e->d2 = d + t * b;
    e->c = c;
    e->s = -s;
}

/* The secular function |y(lam)| - radius, decreasing in lam >= 0. */
struct secular {
    double d1, d2, t1, t2, radius;
};

static double secular_eval(double lam, void *params)
{
    const struct secular *q = params;
    return hypot(q->d1 * q->t1 / (q->d1 + lam), q->d2 * q->t2 / (q->d2 + lam)) - q->radius;
}

/* lam of the anisotropic circle case, for d1, d2 scaled to max(d1, d2) = 1 (y is unchanged
 * when d and lam scale together); -1 when the bracket does not hold (rounding at the circle's
 * edge), where the caller falls back to the Euclidean projection, which then differs from the
 * answer by rounding. */
static double secular_root(struct secular *q, gsl_root_fsolver *brent)
{
    double nt = hypot(q->t1, q->t2);
    double hi = 2.0 * (nt / q->radius); /* finite: the caller checked nt/radius */
    if (!(secular_eval(0.0, q) > 0.0) || !(secular_eval(hi, q) < 0.0))
        return -1.0;
    gsl_function F = {secular_eval, q};
    gsl_root_fsolver_set(brent, &F, 0.0, hi); /* signs checked above: no GSL error */
    double epsabs = 2.0 * DBL_EPSILON * fmin(q->d1, q->d2);
    double lam = hi;
    for (int k = 0; k < BRENT_MAX_ITER; k++) {
        if (gsl_root_fsolver_iterate(brent) != GSL_SUCCESS)
            break;
        lam = gsl_root_fsolver_root(brent);
        double lo = gsl_root_fsolver_x_lower(brent), up = gsl_root_fsolver_x_upper(brent);
        if (gsl_root_test_interval(lo, up, epsabs, 2.0 * DBL_EPSILON) == GSL_SUCCESS)
            break;
    }
    return lam;
}

/* Whether |t| < radius is certain from the squares alone, with a margin for their rounding
 * (then hypot(t) <= radius too, and the answer is the one hypot would give); squares that
 * overflow, or a radius whose square is not a normal number, say no. Saves hypot, the
 * costliest call of a sweep, for the contacts inside their disks. */
static int inside_by_squares(double t1, double t2, double radius)
{
    double r2 = radius * radius;
    return r2 >= DBL_MIN && t1 * t1 + t2 * t2 < r2 * (1.0 - 8.0 * DBL_EPSILON);
}

int fr_disk_block_solve(const struct fr_disk_eig *e, const double g[2], const double p[2],
                        double radius, gsl_root_fsolver *brent, double f[2], double *lam)
{
    /* In the eigenbasis: t = h + p = -A^-1 g - p, the point relative to the centre -p. */
    double g1 = e->c * g[0] + e->s * g[1], g2 = -e->s * g[0] + e->c * g[1];
    double p1 = e->c * p[0] + e->s * p[1], p2 = -e->s * p[0] + e->c * p[1];
    double t1 = -g1 / e->d1 - p1, t2 = -g2 / e->d2 - p2;
    double y1 = t1, y2 = t2, l = 0.0;
    if (inside_by_squares(t1, t2, radius)) {
        f[0] = e->c * y1 - e->s * y2 - p[0];
        f[1] = e->s * y1 + e->c * y2 - p[1];
        *lam = 0.0;
        return 0;
    }
    double nt = hypot(t1, t2);
    int on_circle = nt > radius;
    double dmax = fmax(e->d1, e->d2), ratio = nt / radius;
    if (on_circle && e->d1 != e->d2 && !isfinite(ratio)) {
        /* A disk too small beside t for lam = |D t|/radius (about) to be a double: the limit
         * lam -> inf, y along D t (the direction of -g at rest), exact to rounding since
         * d/lam < 1e-296 (fuzz finding: the Euclidean projection's direction t was off by the
         * block's anisotropy). */
        double u1 = e->d1 / dmax * t1, u2 = e->d2 / dmax * t2, nu = hypot(u1, u2);
        y1 = radius * (u1 / nu);
        y2 = radius * (u2 / nu);
        l = dmax * ratio;
    } else if (on_circle) {
        struct secular q = {e->d1 / dmax, e->d2 / dmax, t1, t2, radius};
        double root = e->d1 == e->d2 ? -1.0 : secular_root(&q, brent);
        if (root < 0.0) { /* isotropic: the Euclidean projection, as fricreg_disk_eval; t/|t|
                           * first: radius/|t| may underflow. Anisotropic: t lies on the circle
                           * to rounding, where the multiplier is 0 to first order
                           * (|y(lam)| ~ |t| (1 - lam/d)): its estimate d (|t|/radius - 1) */
            double s = isfinite(nt) ? 1.0 : fmax(fabs(t1), fabs(t2)); /* |t| beyond DBL_MAX */
            double n1 = t1 / s, n2 = t2 / s, nn = s == 1.0 ? nt : hypot(n1, n2);
            y1 = radius * (n1 / nn); /* (fuzz finding: t/Inf put f at the centre) */
            y2 = radius * (n2 / nn);
            l = (e->d1 == e->d2 ? e->d1 : dmax) * (nt / radius - 1.0);
        } else {
            y1 = q.d1 * t1 / (q.d1 + root);
            y2 = q.d2 * t2 / (q.d2 + root);
            double ny = hypot(y1, y2); /* onto the circle to the last bit */
            y1 = radius * (y1 / ny);
            y2 = radius * (y2 / ny);
            l = root * dmax;
        }
    }
    /* back: f = Q y - p */
    double f0 = e->c * y1 - e->s * y2 - p[0], f1 = e->s * y1 + e->c * y2 - p[1];
    f[0] = f0;
    f[1] = f1;
    *lam = l;
    return on_circle;
}
