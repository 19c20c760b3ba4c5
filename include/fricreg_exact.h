/* SPDX-License-Identifier: GPL-3.0-or-later */
/**
 * \file
 * fricreg_exact.h — the semi-analytical ("exact") solution of the 1-dof oscillator, Eq.\ (5),
 * under classical Coulomb friction (1) with force balance at rest (2).
 *
 *     x'' + x = f + a sin(omega t),   f_eq = x - a sin(omega t)
 *
 * On every interval of constant sliding direction s the motion is in closed form,
 * x = c + x_p(t) + A cos(t - t0) + B sin(t - t0) with c = -s mun and the forced response x_p
 * (a sin(wt)/(1 - w^2), or -(a/2) t cos t at resonance w = 1); at rest, x is constant while
 * |f_eq| <= mun. The switching times — slip to rest (x' = 0) and rest to slip (|f_eq| = mun) —
 * are roots of these closed forms, bracketed on a scan and refined with GSL's Brent solver to
 * the last bits (Quinn 2004, Sec. 3.1: "convergent to the 12th significant digit"). The scan
 * steps by what a bound on the second derivative allows (no root can lie within a step), never
 * below 1/1024 of the shortest period involved, so its work follows the number of switches.
 * Work limits of one run: at most 4194303 switches and 2^27 scan points, and a scan step above
 * 2^-32 t (beyond, the closed forms lose the time resolution); a run over them is refused
 * with FRICREG_EINVAL (a few seconds of work at most).
 * The dissipation per cycle is mun times the distance slid in that cycle, exactly.
 *
 * Conventions are those of fricreg.h: int results are fricreg_status codes, nothing is
 * printed, a failed call leaves the caller's arrays untouched, one object per thread. As for
 * contexts and simulations, an object keeps the status and a message of its last failed call
 * (fricreg_exact_errcode, fricreg_exact_errmsg, fricreg_exact_errmsg_copy).
 *
 * Use (since 1.1): fricreg_exact_create with the parameters, fricreg_exact_run (or _run_cycles),
 * then the getters below; fricreg_exact_free. fricreg_exact_solve (1.0) does create and run in
 * one call, with no message on failure.
 */
#ifndef FRICREG_EXACT_H
#define FRICREG_EXACT_H

#include "fricreg.h"

#ifdef __cplusplus
extern "C" {
#endif

/** \defgroup exact Exact solver: the oscillator in closed form (fricreg_exact)
 *  An opaque object holding the semi-analytical solution of the paper's 1-dof oscillator under
 *  Coulomb friction with force balance at rest, switching times to the last bits. The reference
 *  the regularized runs are measured against: its state at any time, its switches and its
 *  dissipation per cycle, in closed form.
 *  \{ */

/** Opaque exact solution: its parameters and the phases (stick or slip) computed so far. */
typedef struct fricreg_exact fricreg_exact;

/** Solve Eq.\ (5) with (1)+(2) from (x, x')(0) = (x0, v0) over 0 <= t <= t_end.
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
 *  mun < 0, t_end <= 0 or too long, or over the work limits at the top of this header);
 *  FRICREG_EDIVERGED if the closed form overflows; FRICREG_ENOMEM; FRICREG_EINTEGRATOR if a switching
 *  time cannot be bracketed (never seen; it would mean two switches closer than 1e-3).
 *  The same as fricreg_exact_create then fricreg_exact_run, keeping the object only if both
 *  succeed: with no object on failure there is no message; use those two to get one. */
FRICREG_API int fricreg_exact_solve(double a, double omega, double mun, double x0, double v0,
                                    double t_end, fricreg_exact **out);

/** Create an exact solution of Eq.\ (5) with (1)+(2) from (x, x')(0) = (x0, v0). Nothing is
 *  solved yet: fricreg_exact_run or fricreg_exact_run_cycles does that. The Brent root solver
 *  is allocated here, so a run allocates only the list of phases.
 *
 *  a      forcing amplitude (finite; 0: unforced).
 *  omega  forcing frequency > 0; sets the forcing period 2 pi/omega of the cycles
 *         (fricreg_exact_get_value). Resonance omega = 1 as for fricreg_exact_solve.
 *  mun    friction bound >= 0 (finite).
 *  x0, v0 initial position and velocity (finite).
 *  out    out: the new object, released with fricreg_exact_free. Written only on success.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if out is NULL; FRICREG_ENONFINITE if a number is NaN or
 *  infinite; FRICREG_EINVAL if omega <= 0 or mun < 0; FRICREG_ENOMEM. With no object to keep
 *  it, a failure has no message beyond its status, as for fricreg_ctx_create. Since 1.1. */
FRICREG_API int fricreg_exact_create(double a, double omega, double mun, double x0, double v0,
                                     fricreg_exact **out);

/** Solve over 0 <= t <= t_end, replacing the solution held (if any); the getters below then
 *  describe this one. Switching times to the last bits (Brent), see the top of this header.
 *
 *  t_end  end time > 0 (finite), at most 10^6 forcing cycles (t_end omega/(2 pi) <= 10^6).
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if ex is NULL; FRICREG_ENONFINITE if t_end is NaN or
 *  infinite; FRICREG_EINVAL if t_end <= 0 or too long, or if the solution needs more work than
 *  the limits at the top of this header (the message says which limit, and the time reached);
 *  FRICREG_EDIVERGED if the closed form overflows (values near 1e308); FRICREG_ENOMEM;
 *  FRICREG_EINTEGRATOR if
 *  a switching time cannot be found (never seen; it would mean two switches closer than 1e-3).
 *  On failure fricreg_exact_errmsg names the value, or the time where the solution stopped,
 *  and the solution held before the call is kept unchanged. Since 1.1. */
FRICREG_API int fricreg_exact_run(fricreg_exact *ex, double t_end);

/** fricreg_exact_run over `cycles` whole forcing cycles: t_end = cycles 2 pi/omega, so
 *  fricreg_exact_ncycles is then `cycles`. 1 <= cycles <= 10^6.
 *  Returns FRICREG_OK or the codes of fricreg_exact_run; FRICREG_EINVAL also for cycles out
 *  of range. Since 1.1. */
FRICREG_API int fricreg_exact_run_cycles(fricreg_exact *ex, int cycles);

/** Status of the last failed call on ex. Returns that code, or FRICREG_OK if none (or ex
 *  NULL). A successful call does not clear it. The getters, which take a const object, return their status without
 *  recording it. Since 1.1. */
FRICREG_API int fricreg_exact_errcode(const fricreg_exact *ex);

/** Message of the last failed call on ex: names the argument and its value, or the time.
 *  "" if none; "NULL exact solution" if ex is NULL. Owned by ex, valid until its next call.
 *  Since 1.1. */
FRICREG_API const char *fricreg_exact_errmsg(const fricreg_exact *ex);

/** Copy the last error message into buf[len], NUL-terminated and truncated to fit (for
 *  Fortran). Returns the full message length (excluding the NUL), as snprintf does; 0 and
 *  nothing written if buf is NULL or len is 0. Since 1.1. */
FRICREG_API size_t fricreg_exact_errmsg_copy(const fricreg_exact *ex, char *buf, size_t len);

/** Quantities of an exact solution, for fricreg_exact_get_value. Values are fixed forever. */
enum fricreg_exact_value {
    FRICREG_EXACT_VALUE_TIME = 0,  /**< end time t_end of the solution held; 0 before a run */
    FRICREG_EXACT_VALUE_PERIOD = 1 /**< forcing period 2 pi/omega, the length of a cycle */
};

/** Read one quantity (enum fricreg_exact_value) into *value.
 *  Returns FRICREG_OK; FRICREG_ENULL if ex or value is NULL; FRICREG_EINVAL for an unknown
 *  quantity (*value untouched). Since 1.1. */
FRICREG_API int fricreg_exact_get_value(const fricreg_exact *ex, int which, double *value);

/** Work counters of the solution held (zero before a run), for fricreg_exact_get_stat.
 *  Values are fixed forever. The scan steps at least 1/1024 of the shortest period and mostly
 *  far more, so a run costs at most t_end/h scan points with h = 2 pi/max(1, omega)/1024, and
 *  typically 5 to 16 per phase (a stick that cannot end, |x| + |a| <= mun, costs none). */
enum fricreg_exact_stat {
    FRICREG_EXACT_STAT_SCAN_POINTS = 0, /**< closed-form tests "the phase still holds" on the
                                                scan grid, including the halved first steps */
    FRICREG_EXACT_STAT_ROOTS = 1,       /**< phase ends bracketed and refined: one per
                                                switch, plus any phase of zero length */
    FRICREG_EXACT_STAT_ROOT_ITERS = 2   /**< Brent iterations, summed over the roots */
};

/** Read one counter (enum fricreg_exact_stat) into *value.
 *  Returns FRICREG_OK; FRICREG_ENULL if ex or value is NULL; FRICREG_EINVAL for an unknown
 *  counter (*value untouched). Since 1.1. */
FRICREG_API int fricreg_exact_get_stat(const fricreg_exact *ex, int which, int64_t *value);

/** Release a solution. fricreg_exact_free(NULL) does nothing. */
FRICREG_API void fricreg_exact_free(fricreg_exact *ex);

/** The state at time t, 0 <= t <= t_end, in closed form (no integration error).
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_EINVAL if t is outside [0, t_end], or if ex
 *  holds no solution yet (created, never run successfully). */
FRICREG_API int fricreg_exact_state(const fricreg_exact *ex, double t, double *x, double *v);

/** Number of switches (phase changes after t = 0) up to t_end; 0 if ex is NULL or holds no
 *  solution yet. */
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

/** \} */

#ifdef __cplusplus
}
#endif

#endif /* FRICREG_EXACT_H */
