/* SPDX-License-Identifier: GPL-3.0-or-later */
/* law_stribeck.h — internal: the Stribeck kinetic curve and the band's bound
 * (fricreg_stribeck.h), shared by the scalar laws (law_stribeck.c) and the context
 * (ctx_stribeck.c), so that both give the same bits. */
#ifndef FRICREG_LAW_STRIBECK_INTERNAL_H
#define FRICREG_LAW_STRIBECK_INTERNAL_H

#include <math.h>
#include <stddef.h>

/* One contact's parameters: static bound fs, kinetic fk <= fs, Stribeck velocity vs > 0,
 * exponent delta > 0. */
struct fr_stribeck {
    double fs, fk, vs, delta;
};

/* The kinetic curve k(s) = fk + (fs - fk) exp(-(s/vs)^delta), s >= 0. With fs == fk the
 * difference is 0 and k is fk exactly. */
static inline double fr_stribeck_kinetic(const struct fr_stribeck *p, double s)
{
    return p->fk + (p->fs - p->fk) * exp(-pow(s / p->vs, p->delta));
}

/* k'(s) = -(fs - fk) (delta/vs) (s/vs)^(delta-1) exp(-(s/vs)^delta), for s > 0 (the kinetic
 * curve's slope, <= 0; used outside the band, s >= eps > 0, where it is finite). Written as
 * -(fs - fk) (delta/s) y exp(-y), y = (s/vs)^delta, whose last factor is at most 1/e: the
 * direct form overflows to Inf * 0 = NaN for tiny vs (delta/vs, (s/vs)^(delta-1) beyond
 * DBL_MAX where exp(-y) is 0). 0 where exp(-y) underflows, and for fs == fk. */
static inline double fr_stribeck_kinetic_slope(const struct fr_stribeck *p, double s)
{
    double y = pow(s / p->vs, p->delta);
    double y_exp = y < 746.0 ? y * exp(-y) : 0.0; /* exp(-746) is 0 in double */
    if (y_exp == 0.0 || p->fs == p->fk)
        return 0.0;
    return -(p->fs - p->fk) * (p->delta / s) * y_exp;
}

/* The band's bound at rho = |v|/eps in [0, 1], given k_eps = k(eps): fs at rho = 0 (exactly:
 * the product is 0), k(eps) at rho = 1. Linear, not k(|v|) itself: k has an infinite slope at
 * 0 for delta < 1, which would make the force non-Lipschitz where it saturates; the line's
 * slope is bounded, (fs - k(eps))/eps, for every delta. */
static inline double fr_stribeck_band_bound(const struct fr_stribeck *p, double k_eps, double rho)
{
    return p->fs + (k_eps - p->fs) * rho;
}

/* The contexts' check of per-contact parameters (fricreg_ctx_set_stribeck,
 * fricreg_disk_ctx_set_stribeck), in fricreg_stribeck_eval's order: FRICREG_ENULL if an array
 * is NULL, then FRICREG_ENONFINITE if any number is NaN or infinite, then FRICREG_EINVAL for
 * the first contact outside 0 <= fk <= fs <= fs_max, vs > 0, delta > 0; FRICREG_OK otherwise.
 * On failure why[len] says which array or contact, for the context's message. */
int fr_stribeck_check(size_t m, const double fs[], const double fk[], const double vs[],
                      const double delta[], double fs_max, char why[], size_t len);

#endif
