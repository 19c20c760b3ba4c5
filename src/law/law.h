/* SPDX-License-Identifier: GPL-3.0-or-later */
/* law.h — internal: the scalar friction laws, inlined into the batched and context loops. */
#ifndef FRICREG_LAW_INTERNAL_H
#define FRICREG_LAW_INTERNAL_H

#include <float.h>
#include <math.h>
#include <stdint.h>

#include "fricreg.h"
#include "law_table.h"

/* Every switch on a law lists every law by name, with no default, on (enum fricreg_law): the
 * compiler's -Wswitch names a switch that misses a law added later (an error under
 * FRICREG_WERROR), and FR_LAWS_LISTED(n) beside it, n the laws its author listed, stops the
 * build until each is read again for the new law. */
#define FR_LAWS_LISTED(n) ((void)sizeof(char[(n) == FR_LAW_COUNT ? 1 : -1]))

/* clamp(x, lo, hi) = min(max(x, lo), hi) for lo <= hi, written in the operand order of the
 * maxsd/minsd instructions and their packed forms, so the compiler emits selects, never
 * branches, and vectorizes the loops around it. A NaN x gives a bound (see fr_quinn_band). */
static inline double fr_clamp(double x, double lo, double hi)
{
    double y = x > lo ? x : lo;
    return y < hi ? y : hi;
}

/* mun sat(f_eq/mun), the force of (2) at rest, division-free: clamp(f_eq, -mun, mun). Equal
 * for mun > 0 up to the rounding of the division, and 0 for mun = 0 (f_eq finite). */
static inline double fr_hold(double f_eq, double mun)
{
    return fr_clamp(f_eq, -mun, mun);
}

/* (1) f = -mun sgn(v) with sgn(0) = 0, as the paper uses it: two selects, which the
 * vectorizer takes (it gives up on a sgn formed from bool-to-double conversions). */
static inline double fr_coulomb(double v, double mun)
{
    double s = v < 0.0 ? mun : 0.0;
    return v > 0.0 ? -mun : s;
}

/* (2) at v == 0: f = mun sat(f_eq/mun); else (1). */
static inline double fr_force_balance(double v, double f_eq, double mun)
{
    double hold = fr_hold(f_eq, mun), slip = fr_coulomb(v, mun); /* both: see fr_karnopp */
    return v == 0.0 ? hold : slip;
}

/* Karnopp's dead band |v| < eps: the force balance holds; outside it, (1). Both forces are
 * formed, then selected: the vectorizer will not hoist floating-point work out of one arm of
 * a select itself (it might trap). */
static inline double fr_karnopp(double v, double f_eq, double mun, double eps)
{
    double hold = fr_hold(f_eq, mun), slip = fr_coulomb(v, mun);
    return fabs(v) < eps ? hold : slip;
}

/* (3) f = -(mun/eps) v in |v| < eps, else (1): the same as -mun sat(v/eps), written as
 * clamp(-mun (v/eps), -mun, mun), which rounds identically and which GCC vectorizes (the
 * constant bounds of sat(y) it turns into branches). */
static inline double fr_velocity_limited(double v, double mun, double eps)
{
    return fr_clamp(-mun * (v / eps), -mun, mun);
}

static inline double fr_tanh(double v, double mun, double eps)
{
    return -mun * tanh(v / eps);
}

/* (4): xi = (eps/2) sat(f_eq/mun) (4b); in |v - xi| < eps/2, f = -(2 mun/eps)(v - xi), else
 * -mun sgn(v - xi) (4a). Both branches are -mun sat(2(v - xi)/eps) = -mun sat(c - s) with
 * c = 2v/eps, s = sat(f_eq/mun). For mun > 0, mun s = clamp(f_eq, -mun, mun) =: g, and
 * multiplying sat by -mun < 0 mirrors and scales its bounds: -mun sat(c - s) =
 * clamp(-mun (c - s), -mun, mun) = clamp(g - c mun, -mun, mun). So, with no division,
 *   f = clamp(clamp(f_eq, -mun, mun) - c mun, -mun, mun),
 * equal to the sat form within a few roundings of mun (tests/law/test_law.c); at v = 0, exactly
 * g, i.e. (2). For mun = 0 the sat form is 0; here c mun is 0 too, or NaN when c overflowed
 * to +-inf (v/eps > DBL_MAX/2), and fr_clamp maps a NaN to a bound, here +-0: f = 0 either
 * way. c = +-inf with mun > 0 gives -+mun, as the sat form. */
static inline double fr_quinn_band(double c, double f_eq, double mun)
{
    return fr_clamp(fr_hold(f_eq, mun) - c * mun, -mun, mun);
}

/* The scale k of c = k v: 2/eps, rounded up by one ulp where eps (2/eps) rounds below 2, so
 * that |v| >= eps always gives |c| >= 2 (rounding is monotone) and fr_quinn_band gives
 * exactly (1) outside the band, with no test: |c| mun >= 2 mun, so the inner difference is
 * past the bound. One ulp always suffices (tests/law/test_law.c); eps >= DBL_MIN keeps k finite. */
static inline double fr_band_scale(double eps)
{
    double k = 2.0 / eps;
    return eps * k >= 2.0 ? k : nextafter(k, INFINITY);
}

static inline double fr_quinn(double v, double f_eq, double mun, double eps)
{
    return fr_quinn_band(v * fr_band_scale(eps), f_eq, mun); /* the scale: hoisted from loops */
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

/* The piece of clamp(f_eq - c mun, lo, hi) (fr_box) a contact's force lies on: 1 held at hi,
 * -1 held at lo, 0 free; a value exactly on a bound is held there (the tangent's rule). Made
 * of selects between values computed unconditionally, and a double, not an int, so that the
 * diagonal pass vectorizes with it (partition.c; GCC does not if-convert arithmetic under a
 * condition, which may trap). */
static inline double fr_box_piece(double c, double f_eq, double mun)
{
    /* fr_box's lo and hi as min/max of the shifted bounds (mun >= 0): the same values */
    double shifted_hi = mun * (1.0 - c), shifted_lo = -mun * (1.0 + c);
    double hi = shifted_hi < mun ? shifted_hi : mun, lo = shifted_lo > -mun ? shifted_lo : -mun;
    double y = f_eq - c * mun, held_lo = y <= lo ? -1.0 : 0.0;
    return y >= hi ? 1.0 : held_lo;
}

/* The diagonal tangent of a near-stick contact with a constant bound, as one number the
 * diagonal pass keeps in place of the evaluation's inputs (fricreg_ctx_tangent, tangent.c):
 * 1 when d f/d zdot = -mun dc (dc = 2/eps for (4), else 0), plus 2 when d f/d f_eq = 1
 * (free). On a bound the slope is d hi/dc or d lo/dc (fr_box_slopes): -mun for c >= 0 at hi,
 * for c < 0 at lo. A sliding contact of (2), (4) or Karnopp has slope 0: its code is 0, which
 * the pass selects (partition.c). */
static inline double fr_near_tangent_code(double c, double f_eq, double mun)
{
    double piece = fr_box_piece(c, f_eq, mun);
    double at_hi_slope = c >= 0.0 ? 1.0 : 0.0, at_lo_slope = c < 0.0 ? 1.0 : 0.0;
    double held_slope = piece > 0.0 ? at_hi_slope : at_lo_slope;
    double slope_on = piece == 0.0 ? 1.0 : held_slope;
    return slope_on + (piece == 0.0 ? 2.0 : 0.0);
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
    FR_LAWS_LISTED(6);
    switch ((enum fricreg_law)law) {
    case FRICREG_LAW_FORCE_BALANCE: return v == 0.0;
    case FRICREG_LAW_KARNOPP:
    case FRICREG_LAW_QUINN: return fabs(v) < eps;
    case FRICREG_LAW_COULOMB:
    case FRICREG_LAW_VELOCITY_LIMITED:
    case FRICREG_LAW_TANH: return 0;
    }
    return 0; /* not a law */
}

/* Whether the law's force jumps (law_table.c); law must be known. */
static inline int fr_law_jumps(int law)
{
    return fr_law_table[law].jumps;
}

/* The default bound on a run's adaptive steps (one forcing cycle of a simulation, one
 * run_ode call of a structure): an adaptive stepper meets a law that jumps at a stick and
 * chases the jump in ever smaller steps, at the pace of its own cost per step (10^4 steps of
 * bsimp on the chain of 32 blocks take 7 s, of rkf45 on the oscillator 2.4 ms); the other laws
 * need up to a few 10^5 steps a cycle at tight tolerances (rk8pd on the chain of 1000 blocks,
 * eps = the paper's, rtol 1e-10: 4.3e5). */
static inline int64_t fr_law_max_adaptive_steps(int law)
{
    return fr_law_jumps(law) ? 10000 : 1000000;
}

/* Whether the law reads f_eq at all (for any v); law must be known. */
static inline int fr_law_uses_feq(int law)
{
    return fr_law_table[law].reads_feq;
}

/* eps must be a normal positive number: below DBL_MIN, 2/eps overflows and (4) would give
 * +mun at v = 0 whatever f_eq is. */
static inline int fr_eps_valid(double eps)
{
    return eps >= DBL_MIN;
}

/* One evaluation; law must be known (checked by the caller). */
static inline double fr_law(int law, double v, double f_eq, double mun, double eps)
{
    FR_LAWS_LISTED(6);
    switch ((enum fricreg_law)law) {
    case FRICREG_LAW_COULOMB: return fr_coulomb(v, mun);
    case FRICREG_LAW_FORCE_BALANCE: return fr_force_balance(v, f_eq, mun);
    case FRICREG_LAW_KARNOPP: return fr_karnopp(v, f_eq, mun, eps);
    case FRICREG_LAW_VELOCITY_LIMITED: return fr_velocity_limited(v, mun, eps);
    case FRICREG_LAW_TANH: return fr_tanh(v, mun, eps);
    case FRICREG_LAW_QUINN: break;
    }
    return fr_quinn(v, f_eq, mun, eps);
}

/* Sums over many terms (box_qp.c, partition_paper.c) are added in FR_LANES explicit partial
 * sums: the vectorizer packs the lanes into vectors, where one floating-point sum it may not
 * reorder, so would add serially. */
enum { FR_LANES = 4 };

/* Law `law` (known) on m contacts whose inputs are validated: f[i] from v[i], f_eq[i] (NULL
 * for the laws that do not read it) and mun[i] (law.c). */
void fr_law_batch(int law, double eps, size_t m, const double v[], const double f_eq[],
                  const double mun[], double f[]);

#endif
