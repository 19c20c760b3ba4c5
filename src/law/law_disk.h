/* SPDX-License-Identifier: GPL-3.0-or-later */
/* law_disk.h — internal: the 2-D (isotropic friction disk) laws of fricreg_disk.h as inline
 * kernels on one contact, shared by the disk and Stribeck entry points (docs/laws2d.md).
 *
 * Vectors are double[2]; m >= 0 is the bound (mu N, or the Stribeck bound of the moment), in
 * force units. Inputs are finite and at most FR_DISK_MAX in magnitude (checked by the callers):
 * then no hypot, product or sum below overflows. Outputs are computed into locals first, so f
 * may alias v or g. */
#ifndef FRICREG_LAW_DISK_INTERNAL_H
#define FRICREG_LAW_DISK_INTERNAL_H

#include <float.h>
#include <math.h>

#include "fricreg_disk.h"

/* The largest input magnitude the 2-D kernels take (documented in fricreg_disk.h). */
#define FR_DISK_MAX 1e250

static inline int fr_disk_law_known(int law)
{
    return law >= FRICREG_DISK_COULOMB && law <= FRICREG_DISK_QUINN_NESTED;
}

/* Whether the 2-D law reads f_eq. */
static inline int fr_disk_law_uses_feq(int law)
{
    return law != FRICREG_DISK_COULOMB;
}

/* The unit vector u = v/|v| of v != 0 (v/|v| first, so that m u never meets m/|v|, which a
 * subnormal v makes overflow). A v whose components are both below 2^-900 is scaled by 2^600
 * first, exactly: on the subnormal grid |v| rounds by up to half its own size, and
 * v = (4.9e-324, 4.9e-324) gave u = (1, 1), a sliding force of sqrt 2 mun. Normal v: the same
 * bits as v/hypot(v). */
static inline void fr_disk_direction(const double v[2], double u[2])
{
    double s0 = v[0], s1 = v[1];
    if (fabs(s0) < 0x1p-900 && fabs(s1) < 0x1p-900) {
        s0 *= 0x1p600;
        s1 *= 0x1p600;
    }
    double r = hypot(s0, s1);
    u[0] = s0 / r;
    u[1] = s1 / r;
}

/* The 2-D (2) at rest: the projection of g onto the disk of radius m, g if |g| <= m (the same
 * bits), else m g/|g| (the direction first: m/|g| may underflow, m = 1e-100 beside
 * |g| = 1e250 gave f = 0). m = 0 gives 0. */
static inline void fr_disk_hold(const double g[2], double m, double f[2])
{
    double u[2] = {0.0, 0.0};
    int out = hypot(g[0], g[1]) > m;
    if (out)
        fr_disk_direction(g, u);
    double f0 = out ? m * u[0] : g[0], f1 = out ? m * u[1] : g[1];
    f[0] = f0;
    f[1] = f1;
}

/* The 2-D (1): f = -m v/|v| (0 at v = 0). */
static inline void fr_disk_slide(const double v[2], double m, double f[2])
{
    if (v[0] == 0.0 && v[1] == 0.0) {
        f[0] = f[1] = 0.0;
        return;
    }
    double u[2];
    fr_disk_direction(v, u);
    f[0] = -m * u[0];
    f[1] = -m * u[1];
}

/* The lens law in the band 0 < |v| < eps, with rho = |v|/eps in (0, 1] and u = v/|v|:
 *   f = P_K(g - w),  K = disk(0, m) ∩ disk(-w, m),  w = 2 a u,  a = m rho
 * (docs/laws2d.md). In the frame of the lens's centre -a u, with axes u and n = u rotated by
 * +90 degrees, the lens is {(|x| + a)^2 + y^2 <= m^2}: symmetric in x and in y, so the closed
 * form is worked out for (|x|, |y|), where the far disk (centre (-a, 0)) is the one that binds:
 *   inside  when (|x| + a)^2 + |y|^2 <= m^2:  f = g - w, no rounding beyond that difference;
 *   on that disk's arc when the projection onto it keeps x >= 0, i.e. m (|x| + a) >= a d with
 *     d = |(|x| + a, |y|)|: p = m (|x| + a, |y|)/d - (a, 0);
 *   else the corner (0, h), h = sqrt(m^2 - a^2);
 * then the signs of x and y come back. The arc condition compares a cosine with a/m, never a
 * computed point with a circle, so a tiny a (v near 0) cannot send a point to a corner by a
 * rounding: at a -> 0 the condition always holds and the arc is the whole circle. The three
 * pieces meet continuously: at the arc's end p = (0, h) exactly in exact arithmetic. */
static inline void fr_disk_lens(const double v[2], const double g[2], double m, double rho,
                                double f[2])
{
    double u[2];
    fr_disk_direction(v, u);
    double u0 = u[0], u1 = u[1];
    double a = m * rho;
    double x = (g[0] * u0 + g[1] * u1) - a, y = g[1] * u0 - g[0] * u1;
    double X = fabs(x) + a, Y = fabs(y);
    double d = hypot(X, Y);
    if (d <= m) {
        double f0 = g[0] - 2.0 * a * u0, f1 = g[1] - 2.0 * a * u1;
        f[0] = f0;
        f[1] = f1;
        return;
    }
    double px, py;
    if (m * X >= a * d) {
        px = m * (X / d) - a;
        py = m * (Y / d);
    } else {
        px = 0.0;
        py = sqrt((m - a) * (m + a));
    }
    px = copysign(px, x) - a; /* back to the frame of the origin, along u */
    py = copysign(py, y);
    double f0 = px * u0 - py * u1, f1 = px * u1 + py * u0;
    f[0] = f0;
    f[1] = f1;
}

/* The inscribed-disk law in the band 0 < |v| < eps, rho = |v|/eps, u = v/|v|, a = m rho:
 *   f = P_K(g - w),  K = disk(-a u, m - a),  w = 2 a u,
 * the largest disk inside the lens, tangent to both of its disks on the axis. At rho = 0 it is
 * the disk of radius m (the force balance), at rho = 1 the point -m u; on the axis it is the
 * lens's interval, so on a line it is law (4). One projection onto a disk whose centre and
 * radius move linearly with v: Lipschitz in (v, g). */
static inline void fr_disk_inscribed(const double v[2], const double g[2], double m, double rho,
                                     double f[2])
{
    double u[2];
    fr_disk_direction(v, u);
    double u0 = u[0], u1 = u[1];
    double a = m * rho, radius = m * (1.0 - rho);
    double d0 = g[0] - a * u0, d1 = g[1] - a * u1; /* g - w relative to the centre -a u */
    double d = hypot(d0, d1);
    int out = d > radius; /* d/|d| first, as fr_disk_hold */
    double f0 = (out ? radius * (d0 / d) : d0) - a * u0,
           f1 = (out ? radius * (d1 / d) : d1) - a * u1;
    f[0] = f0;
    f[1] = f1;
}

/* The regularized 2-D law with the lens (FRICREG_DISK_QUINN_LENS): as fr_disk_quinn, with the
 * lens in the band. */
static inline void fr_disk_quinn_lens(const double v[2], const double g[2], double m, double eps,
                                      double f[2])
{
    double r = hypot(v[0], v[1]);
    if (r == 0.0)
        fr_disk_hold(g, m, f);
    else if (r >= eps)
        fr_disk_slide(v, m, f);
    else
        fr_disk_lens(v, g, m, r / eps, f);
}

/* The regularized 2-D law, the default (FRICREG_DISK_QUINN): (2) at v == 0 (the same bits as
 * fr_disk_hold), the inscribed disk in 0 < |v| < eps, the 2-D (1) outside. */
static inline void fr_disk_quinn(const double v[2], const double g[2], double m, double eps,
                                 double f[2])
{
    double r = hypot(v[0], v[1]);
    if (r == 0.0)
        fr_disk_hold(g, m, f);
    else if (r >= eps)
        fr_disk_slide(v, m, f);
    else
        fr_disk_inscribed(v, g, m, r / eps, f);
}

/* The direct transcription of (4): f = m P_D(P_D(g/m) - c), c = 2 v/eps, written as the
 * projection of P(g) - w onto the disk of radius m, w = m c, for every v (it reaches the
 * sliding force only as |v|/eps -> infinity). Past |c| = 2^54 the inner point is -w to the
 * last bit of its direction (|P(g)|/|w| <= 1/|c|) and the projection is the sliding force;
 * the cut also keeps w finite (|w| <= 2^54 FR_DISK_MAX). */
static inline void fr_disk_quinn_nested(const double v[2], const double g[2], double m, double eps,
                                        double f[2])
{
    double r = hypot(v[0], v[1]);
    if (r == 0.0) {
        fr_disk_hold(g, m, f);
        return;
    }
    double t = 2.0 * (r / eps);
    if (t > 0x1p54) {
        fr_disk_slide(v, m, f);
        return;
    }
    double p[2], u[2];
    fr_disk_hold(g, m, p);
    fr_disk_direction(v, u);
    p[0] -= t * (m * u[0]); /* w = m c = t m u */
    p[1] -= t * (m * u[1]);
    fr_disk_hold(p, m, f);
}

/* Law `law` (known) at one contact with validated inputs; g unused by the 2-D (1). */
static inline void fr_disk_law(int law, const double v[2], const double g[2], double m, double eps,
                               double f[2])
{
    switch (law) {
    case FRICREG_DISK_COULOMB: fr_disk_slide(v, m, f); break;
    case FRICREG_DISK_FORCE_BALANCE:
        if (v[0] == 0.0 && v[1] == 0.0)
            fr_disk_hold(g, m, f);
        else
            fr_disk_slide(v, m, f);
        break;
    case FRICREG_DISK_QUINN: fr_disk_quinn(v, g, m, eps, f); break;
    case FRICREG_DISK_QUINN_LENS: fr_disk_quinn_lens(v, g, m, eps, f); break;
    default: fr_disk_quinn_nested(v, g, m, eps, f); break;
    }
}

/* Whether x is a number the 2-D kernels take: finite (checked first, for the status) and at
 * most FR_DISK_MAX in magnitude. */
static inline int fr_disk_in_range(double x)
{
    return fabs(x) <= FR_DISK_MAX;
}

#endif
