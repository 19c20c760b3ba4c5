/* SPDX-License-Identifier: GPL-3.0-or-later */
/* companion_estimate.c — the estimate of q's error against eps -> 0 from q2 = q(eps/2) and
 * q4 = q(eps/4) (companion_estimate.h).
 *
 * Law (4)'s error is c eps^p with p = 1 or 2, and along dt / eps fixed a fixed step's error
 * follows eps (fricreg_sim_run_extrapolated), so in the asymptotic range d1 = q - q2 and
 * d2 = q2 - q4 have one sign and d1 / d2 = 2^p with p in [1, 2]; then
 * q - q(0) = d1 2^p / (2^p - 1), Richardson's correction with the observed order. The range
 * test: d1 / d2 at least 2^(P_LO - BAND); there the estimate is SAFETY d1 2^p / (2^p - 1).
 * That holds above the law's orders too (d2 far below d1: the companions converged faster, a
 * slip's end inside a step, or q2 and q4 at a solver's tolerance): q2 is then much nearer the
 * limit than q, and the estimate tends to SAFETY |d1|. Below the range (a stall: q and q2
 * agree on a wrong value; or differences that grow or change sign) no order can be trusted:
 * the bound OUT_FACTOR (|d1| + |d2|), what a geometric tail of the slowest accepted order
 * would add to the two differences seen, of kind BOUND; but of opposite signs with d2 at
 * most an eighth of d1, SAFETY (|d1| + 2 |d2|) (OPPOSITE_RATIO below), of kind BOUND too.
 * Differences both below NOISE of the quantity are a solver's tolerance, not an order: no
 * order is read from them, but the safety factor and the tail of the law's lower order still
 * apply, NOISE_FACTOR (|d1| + |d2|) (their bare sum was 0.997x the error on the disk of
 * bench/estimate_unseen.sh), of kind BOUND too.
 * One companion (1.6's estimator): FACTOR_ONE |d1|, of kind ASSUMED. */
#include "companion_estimate.h"

#include <math.h>

/* One companion: 2 at p = 1 (D(eps) - D(0) = 2 (D(eps) - D(eps/2))) with the margin the
 * calibration of bench/error_estimate.c asked for (docs/integrators.md, "Error estimate"). */
#define FACTOR_ONE 3.0
#define P_LO 1.0 /* law (4)'s lower order in eps along dt / eps fixed */
#define BAND 0.5 /* the observed order accepted from P_LO - BAND on */
/* On the observed order's Richardson correction: at 2 the frame of bench/frame_estimate.c is
 * bounded at every dt and scheme, the oscillator of tests/structure/test_structure_error.c within 10x.
 * The warning reads the estimate without it (FR_ESTIMATE_CENTRAL). */
#define SAFETY (1.0 / FR_ESTIMATE_CENTRAL)
/* Below the range: SAFETY 2^p / (2^p - 1) at the band's lowest order p = 0.5, 6.83. */
#define OUT_FACTOR (SAFETY * 3.414213562373095)
#define NOISE 1e-9 /* relative differences below this are a solver's tolerance (Newton: 1e-10) */
/* The noise branch: SAFETY times p = P_LO's Richardson tail 2^P_LO / (2^P_LO - 1) = 2. */
#define NOISE_FACTOR (SAFETY * 2.0)
/* Differences of opposite signs with |d2| <= |d1| / OPPOSITE_RATIO: q2 and q4 much nearer each
 * other than q and q2, as where r is above the law's orders. Law (4)'s two orders,
 * q = q0 + a eps + b eps^2, give the error exactly as q - q0 = (2/3) d1 + (8/3) d2 (both
 * orders eliminated), at most |d1| + 2 |d2| wherever |d2| <= |d1| / 2: the estimate is
 * SAFETY (|d1| + 2 |d2|), of kind BOUND (no order seen). Below the ratio, opposite signs are
 * left to OUT_FACTOR: a stall that changes sign looks the same. On the frame of
 * bench/frame_estimate.c at 5 ms (storey 2's peak, r = -17) OUT_FACTOR's bound was 8.7x the
 * error, this one 2.7x. Over that bench's seven --companions sets (285 estimates, 195 on
 * problems the rule was not derived on) and bench/estimate_unseen.sh's 41, all still bound. */
#define OPPOSITE_RATIO 8.0

static double two_companions(double q, double q2, double q4, int *kind)
{
    double d1 = q - q2, d2 = q2 - q4;
    double floor = NOISE * fmax(fabs(q), fmax(fabs(q2), fabs(q4)));
    *kind = FRICREG_EST_KIND_BOUND;
    if (fabs(d1) <= floor && fabs(d2) <= floor) /* no order can be read from noise */
        return NOISE_FACTOR * (fabs(d1) + fabs(d2));
    if (fabs(d2) <= floor) { /* q2 and q4 agree to a solver's tolerance: Richardson's limit */
        *kind = FRICREG_EST_KIND_ASYMPTOTIC;
        return SAFETY * fabs(d1) + fabs(d2);
    }
    double r = d1 / d2;
    if (r >= exp2(P_LO - BAND)) {
        *kind = FRICREG_EST_KIND_ASYMPTOTIC;
        return SAFETY * fabs(d1) * r / (r - 1.0);
    }
    if (r <= -OPPOSITE_RATIO)
        return SAFETY * (fabs(d1) + 2.0 * fabs(d2));
    return OUT_FACTOR * (fabs(d1) + fabs(d2));
}

double fr_companion_estimate(int estimator, double q, double q2, double q4, int *kind)
{
    if (estimator == FRICREG_ESTIMATE_ONE_COMPANION) {
        *kind = FRICREG_EST_KIND_ASSUMED;
        return FACTOR_ONE * fabs(q - q2);
    }
    double err = two_companions(q, q2, q4, kind);
    if (!(err < INFINITY)) /* a difference overflowed or was NaN: no order was seen */
        *kind = FRICREG_EST_KIND_BOUND;
    return err;
}

/* Coarser companions: q2 = q(2 eps), q4 = q(4 eps) along 2 dt, 4 dt. In the asymptotic range
 * d1 = q - q2 = -c eps^p (2^p - 1) and d2 = q2 - q4 = 2^p d1, so r = d2 / d1 = 2^p and the
 * run's own error is Richardson's from the coarser levels, |d1| / (r - 1).
 *
 * The accepted range of r is what makes SAFETY enough. Law (4)'s error is the sum of its two
 * orders, e = A eps + B eps^2 (P_LO, P_HI). With a = A eps, b = 3 B eps^2: d1 = -(a + b),
 * d2 = -(2 a + 4 b), so r = 4 - 2 w with w = a / (a + b), and e / (|d1| / (r - 1)) =
 * (3 - 2 w)(w + (1 - w) / 3). Where A and B have one sign (w in [0, 1], r in [2, 4]) its
 * largest value is at w = 1/2 (r = 3): (rho1 + rho2 - 2)^2 / (4 (rho1 - 1)(rho2 - 1)) = 4/3
 * for the ratios rho1 = 2, rho2 = 4, so SAFETY = 2 bounds it with a margin of 1.5. Of opposite
 * signs (w > 1, r < 2) it is below 1: the band's r >= 2^0.5 is safe too. But r above 4 is
 * w < 0, opposite signs the other way, where the quotient grows without bound as the two
 * terms cancel in d1: 7 at r = 8 (w = -2; the error |d1| against Richardson's |d1| / 7). So
 * the range ends at the law's higher order, 2^P_HI: above it, no factor on Richardson's is safe,
 * and the estimate is the bound (as where a stall makes d1 small against d2). */
#define P_HI 2.0 /* law (4)'s higher order: r accepted up to 2^P_HI */
#define OUT_COARSER (SAFETY * 2.414213562373095) /* SAFETY / (2^0.5 - 1): the band's lowest p */

static double two_coarser(double q, double q2, double q4, int *kind)
{
    double d1 = q - q2, d2 = q2 - q4;
    double floor = NOISE * fmax(fabs(q), fmax(fabs(q2), fabs(q4)));
    *kind = FRICREG_EST_KIND_BOUND;
    if (fabs(d1) <= floor && fabs(d2) <= floor) /* no order can be read from noise */
        return NOISE_FACTOR * (fabs(d1) + fabs(d2));
    if (fabs(d1) > floor) {
        double r = d2 / d1;
        if (r >= exp2(P_LO - BAND) && r <= exp2(P_HI)) {
            *kind = FRICREG_EST_KIND_ASYMPTOTIC;
            return SAFETY * fabs(d1) / (r - 1.0);
        }
    }
    return OUT_COARSER * (fabs(d1) + fabs(d2)); /* d1 at noise, d2 not: a stall, or no order */
}

double fr_companion_estimate_coarser(int estimator, double q, double q2, double q4, int *kind)
{
    if (estimator == FRICREG_ESTIMATE_ONE_COMPANION) { /* p = 1's error is |d1|: margin 3 */
        *kind = FRICREG_EST_KIND_ASSUMED;
        return FACTOR_ONE * fabs(q - q2);
    }
    double err = two_coarser(q, q2, q4, kind);
    if (!(err < INFINITY))
        *kind = FRICREG_EST_KIND_BOUND;
    return err;
}

int fr_estimate_exceeds(double err, double q, double answer_rtol, double scale)
{
    return FR_ESTIMATE_CENTRAL * err > answer_rtol * fabs(q) && err > FR_ESTIMATE_ROUNDOFF * scale;
}

const char *fr_estimate_kind_name(int kind)
{
    switch (kind) {
    case FRICREG_EST_KIND_ASYMPTOTIC: return "asymptotic";
    case FRICREG_EST_KIND_BOUND: return "bound";
    case FRICREG_EST_KIND_ASSUMED: return "assumed";
    default: return "unknown";
    }
}
