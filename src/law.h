/* law.h — internal: the scalar friction laws, inlined into the batched and context loops. */
#ifndef FRICREG_LAW_INTERNAL_H
#define FRICREG_LAW_INTERNAL_H

#include <math.h>

#include "fricreg.h"

/* sat(y) = max(-1, min(1, y)), in the operand order of the maxsd/minsd instructions, so the
 * compiler emits them instead of branches (inputs are validated finite). */
static inline double fr_sat(double y)
{
    double lo = y > -1.0 ? y : -1.0;
    return lo < 1.0 ? lo : 1.0;
}

/* sgn(y) with sgn(0) = 0, as the paper uses it in (1). */
static inline double fr_sgn(double y)
{
    return (double)(y > 0.0) - (double)(y < 0.0);
}

/* f_eq/mun, saturated; a zero bound gives 0 (its force is 0 whatever f_eq is). */
static inline double fr_sat_ratio(double f_eq, double mun)
{
    return mun > 0.0 ? fr_sat(f_eq / mun) : 0.0;
}

/* (1) f = -mun sgn(v). */
static inline double fr_coulomb(double v, double mun)
{
    return -mun * fr_sgn(v);
}

/* (2) at v == 0: f = mun sat(f_eq/mun); else (1). */
static inline double fr_force_balance(double v, double f_eq, double mun)
{
    return v == 0.0 ? mun * fr_sat_ratio(f_eq, mun) : fr_coulomb(v, mun);
}

/* Karnopp's dead band |v| < eps: the force balance holds; outside it, (1). */
static inline double fr_karnopp(double v, double f_eq, double mun, double eps)
{
    return fabs(v) < eps ? mun * fr_sat_ratio(f_eq, mun) : fr_coulomb(v, mun);
}

/* (3) f = -(mun/eps) v in |v| < eps, else (1): the same as -mun sat(v/eps). */
static inline double fr_velocity_limited(double v, double mun, double eps)
{
    return -mun * fr_sat(v / eps);
}

static inline double fr_tanh(double v, double mun, double eps)
{
    return -mun * tanh(v / eps);
}

/* (4): xi = (eps/2) sat(f_eq/mun) (4b); in |v - xi| < eps/2, f = -(2 mun/eps)(v - xi), else
 * -mun sgn(v - xi) (4a). Both branches are -mun sat(2(v - xi)/eps) = -mun sat(2v/eps - s)
 * with s = sat(f_eq/mun): one select-only formula, and at v = 0 exactly mun s, i.e. (2). */
static inline double fr_quinn(double v, double f_eq, double mun, double eps)
{
    return -mun * fr_sat(v * (2.0 / eps) - fr_sat_ratio(f_eq, mun)); /* 2/eps: hoisted */
}

/* Law (4) on the band |c| < 2, c = 2 v/eps, written division-free (docs/coupled.md):
 * f = clamp(clamp(f_eq, -mun, mun) - c mun, -mun, mun) = clamp(f_eq - c mun, lo, hi) with
 *   lo = -mun (1 - max(-c, 0)),   hi = mun (1 - max(c, 0)),
 * the box of the consistent law's QP. Karnopp and (2) are the same with c = 0. */
static inline void fr_box(double c, double mun, double *lo, double *hi)
{
    *lo = -mun * (1.0 - fmax(-c, 0.0));
    *hi = mun * (1.0 - fmax(c, 0.0));
}

/* d lo/dc and d hi/dc; at the kink c = 0, the side c > 0 (the tangent's convention). */
static inline void fr_box_slopes(double c, double mun, double *dlo, double *dhi)
{
    *dlo = c < 0.0 ? -mun : 0.0;
    *dhi = c >= 0.0 ? -mun : 0.0;
}

/* Whether the law reads f_eq at velocity v: the near-stick test of Sec. 3.3. */
static inline int fr_needs_feq(int law, double v, double eps)
{
    switch (law) {
    case FRICREG_LAW_FORCE_BALANCE: return v == 0.0;
    case FRICREG_LAW_KARNOPP:
    case FRICREG_LAW_QUINN: return fabs(v) < eps;
    default: return 0;
    }
}

/* Whether the law reads f_eq at all (for any v). */
static inline int fr_law_uses_feq(int law)
{
    return law == FRICREG_LAW_FORCE_BALANCE || law == FRICREG_LAW_KARNOPP ||
           law == FRICREG_LAW_QUINN;
}

static inline int fr_law_known(int law)
{
    return law >= FRICREG_LAW_COULOMB && law <= FRICREG_LAW_QUINN;
}

/* One evaluation; law must be known (checked by the caller). */
static inline double fr_law(int law, double v, double f_eq, double mun, double eps)
{
    switch (law) {
    case FRICREG_LAW_COULOMB: return fr_coulomb(v, mun);
    case FRICREG_LAW_FORCE_BALANCE: return fr_force_balance(v, f_eq, mun);
    case FRICREG_LAW_KARNOPP: return fr_karnopp(v, f_eq, mun, eps);
    case FRICREG_LAW_VELOCITY_LIMITED: return fr_velocity_limited(v, mun, eps);
    case FRICREG_LAW_TANH: return fr_tanh(v, mun, eps);
    default: return fr_quinn(v, f_eq, mun, eps);
    }
}

#endif
