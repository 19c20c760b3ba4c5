/*
 * fricreg_exact.h — the semi-analytical ("exact") solution of the 1-dof oscillator, Eq. (5),
 * under classical Coulomb friction (1) with force balance at rest (2).
 *
 *     x'' + x = f + a sin(omega t),   f_eq = x - a sin(omega t)
 *
 * On every interval of constant sliding direction s the motion is in closed form,
 * x = c + x_p(t) + A cos(t - t0) + B sin(t - t0) with c = -s mun and the forced response x_p
 * (a sin(wt)/(1 - w^2), or -(a/2) t cos t at resonance w = 1); at rest, x is constant while
 * |f_eq| <= mun. The switching times — slip to rest (x' = 0) and rest to slip (|f_eq| = mun) —
 * are roots of these closed forms, bracketed on a fine scan and refined with GSL's Brent
 * solver to the last bits (Quinn 2004, Sec. 3.1: "convergent to the 12th significant digit").
 * The dissipation per cycle is mun times the distance slid in that cycle, exactly.
 *
 * Conventions are those of fricreg.h: int results are fricreg_status codes, nothing is
 * printed, a failed call leaves the caller's arrays untouched, one object per thread.
 */
#ifndef FRICREG_EXACT_H
#define FRICREG_EXACT_H

#include "fricreg.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Opaque exact solution: its parameters and the phases (stick or slip) computed so far. */
typedef struct fricreg_exact fricreg_exact;

/** Solve Eq. (5) with (1)+(2) from (x, x')(0) = (x0, v0) over 0 <= t <= t_end.
 *
 *  a      forcing amplitude (finite; 0: unforced).
 *  omega  forcing frequency > 0; also sets the cycle 2 pi/omega of the dissipation.
 *         Resonance omega = 1 uses the secular solution; |1 - omega^2| below ~1e-6 loses
 *         digits in proportion to 1/|1 - omega^2|.
 *  mun    friction bound >= 0.  x0, v0  initial state (finite).
 *  t_end  end time > 0, at most 10^6 forcing cycles.
 *  out    out: the solution, released with fricreg_exact_free. Written only on success.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_ENONFINITE; FRICREG_EINVAL (omega <= 0,
 *  mun < 0, t_end <= 0 or too long); FRICREG_ENOMEM; FRICREG_EINTEGRATOR if a switching
 *  time cannot be bracketed (never seen; it would mean two switches closer than 1e-3). */
FRICREG_API int fricreg_exact_solve(double a, double omega, double mun, double x0, double v0,
                                    double t_end, fricreg_exact **out);

/** Release a solution. fricreg_exact_free(NULL) does nothing. */
FRICREG_API void fricreg_exact_free(fricreg_exact *ex);

/** The state at time t, 0 <= t <= t_end, in closed form (no integration error).
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_EINVAL if t is outside [0, t_end]. */
FRICREG_API int fricreg_exact_state(const fricreg_exact *ex, double t, double *x, double *v);

/** Number of switches (phase changes after t = 0) up to t_end; 0 if ex is NULL. */
FRICREG_API size_t fricreg_exact_nswitches(const fricreg_exact *ex);

/** Copy the switching times into times[n] (increasing), and into sticks[n] (may be NULL) 1
 *  where the phase that starts there is a stick, 0 where it is a slip.
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_ESIZE if n is not fricreg_exact_nswitches. */
FRICREG_API int fricreg_exact_switches(const fricreg_exact *ex, size_t n, double times[],
                                       int sticks[]);

/** Number of whole forcing cycles in [0, t_end]; 0 if ex is NULL. */
FRICREG_API size_t fricreg_exact_ncycles(const fricreg_exact *ex);

/** Dissipation of each whole cycle k, D_k = -∫ x' f dt over [kT, (k+1)T], T = 2 pi/omega,
 *  which is mun times the distance slid, into D[ncycles].
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_ESIZE if ncycles is not fricreg_exact_ncycles. */
FRICREG_API int fricreg_exact_dissipation(const fricreg_exact *ex, size_t ncycles, double D[]);

/** Fraction of time at rest within [t0, t1] (0 <= t0 < t1 <= t_end), into *fraction.
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_EINVAL for a bad interval. */
FRICREG_API int fricreg_exact_stick_fraction(const fricreg_exact *ex, double t0, double t1,
                                             double *fraction);

#ifdef __cplusplus
}
#endif

#endif /* FRICREG_EXACT_H */
