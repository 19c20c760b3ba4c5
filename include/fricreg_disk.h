/* SPDX-License-Identifier: GPL-3.0-or-later */
/**
 * \file
 * fricreg_disk.h — friction laws for 2-D contacts (isotropic friction disk), beyond the paper:
 * the tangential velocity v and the forces f, f_eq of a contact are vectors of R^2.
 *
 * A header of its own, not a section of fricreg.h: the 2-D laws are a separate enum (their
 * vectors do not fit fricreg_law_eval's scalar signature), they are new in 1.2, and a caller of
 * the 1-D laws only is not made to read them. fricreg.h's conventions hold here unchanged
 * (units, status codes, nothing modified on failure, no printing, thread safety); in addition:
 *   - A vector is two doubles, (x, y) in any fixed orthonormal basis of the tangent plane; an
 *     array of m vectors is interleaved, v[2*i] and v[2*i + 1] the components of contact i
 *     (in Fortran: a (2, m) array, v(1, i) and v(2, i)).
 *   - |y| is the Euclidean norm; D is the unit disk; P_D the projection onto it.
 *   - The laws are isotropic: rotating v and f_eq rotates f (to rounding); and on a line (v and
 *     f_eq parallel) each is its 1-D counterpart of enum fricreg_law, to rounding.
 *   - Numbers must be finite and at most 1e250 in magnitude (components of v and f_eq, mun):
 *     beyond that the geometry would overflow; such inputs are refused (FRICREG_EINVAL).
 * The constructions and why each property holds: docs/laws2d.md. Since 1.2 (FRICREG_1.2).
 */
#ifndef FRICREG_DISK_H
#define FRICREG_DISK_H

#include "fricreg.h"

#ifdef __cplusplus
extern "C" {
#endif

/** \defgroup law_disk 2-D friction laws (the friction disk)
 *  \ingroup law
 *  The friction laws of 2-D contacts, whose velocity and forces are vectors of the tangent plane
 *  and whose bound is the disk |f| <= mun. Beyond the paper; the constructions are in
 *  docs/laws2d.md, and coupled 2-D contacts in a context are fricreg_disk_ctx.h's.
 *  \{ */

/** 2-D friction laws (the disk |f| <= mun). Values are fixed forever. c = 2 v/eps. */
enum fricreg_disk_law {
    /** The 2-D (1), sliding: f = -mun v/|v|; f = 0 at v = 0. Ignores f_eq and eps. */
    FRICREG_DISK_COULOMB = 1,
    /** The 2-D (2), force balance at rest: v == 0 (both components): f = mun P_D(f_eq/mun),
     *  i.e.\ f_eq if |f_eq| <= mun, else mun f_eq/|f_eq|; otherwise the 2-D (1). Ignores eps. */
    FRICREG_DISK_FORCE_BALANCE = 2,
    /** The 2-D (4), the default: for 0 < |v| < eps, with u = v/|v| and a = mun |v|/eps,
     *  f = P_K(f_eq - 2 a u) onto the disk K of centre -a u and radius mun - a (the largest
     *  disk inside the lens of FRICREG_DISK_QUINN_LENS, tangent to both of its circles);
     *  f = -mun v/|v| for |v| >= eps; the force balance (2) at v = 0, bit for bit (exact
     *  isotropic stick: no creep, no anisotropy). K shrinks linearly from the bound's disk at
     *  v = 0 to the point -mun u at |v| = eps, so f is Lipschitz in (v, f_eq) (constants 1 in
     *  f_eq, 5 mun/eps in v) and the sliding law holds exactly outside the band; on a line it
     *  is law (4). Chosen over the spec's two candidates (docs/laws2d.md): the lens has an
     *  error per cycle 1.3 to 1.9 times larger and corners that move as sqrt(eps - |v|) near
     *  the band's edge (not Lipschitz there); the nested form is not the sliding law outside
     *  the band and its error per cycle is 35 to 1700 times larger on the rotating-forcing
     *  oscillator. */
    FRICREG_DISK_QUINN = 3,
    /** The spec's lens: for |v| < eps, f = P_K(f_eq - c mun) onto K = mun (D ∩ (D - c)), the
     *  intersection of the bound's disk with it shifted by -c mun; -mun v/|v| for |v| >= eps;
     *  (2) at v = 0. Continuous, but only Hoelder-1/2 at |v| -> eps, where the lens's corners
     *  close as sqrt(eps - |v|). Kept to reproduce the comparison of docs/laws2d.md
     *  (fricreg-bench-disk) and as the set of a future coupled 2-D law; prefer
     *  FRICREG_DISK_QUINN. */
    FRICREG_DISK_QUINN_LENS = 4,
    /** The direct transcription of (4): f = mun P_D(P_D(f_eq/mun) - c) for every v. Lipschitz,
     *  exactly (2) at v = 0, but its force turns away from -v/|v| by up to asin(1/|c|) at any
     *  |v| (30 degrees at |v| = eps): not the sliding law outside
     *  the band, and first order in eps where the others are not. Kept only to reproduce the
     *  comparison of docs/laws2d.md. */
    FRICREG_DISK_QUINN_NESTED = 5
};

/** Name of a 2-D friction law (enum fricreg_disk_law): "coulomb", "force-balance", "quinn",
 *  "quinn-lens" or "quinn-nested".
 *
 *  law  one of enum fricreg_disk_law.
 *
 *  Returns the name, lowercase, in static storage owned by the library (never free it); NULL
 *  for an unknown law. Laws are numbered 1, 2, … without gaps, so a loop from 1 until NULL
 *  visits every law. Since 1.2. Pure function; thread safe. */
FRICREG_API const char *fricreg_disk_law_name(int law);

/** The 2-D friction law (enum fricreg_disk_law) whose fricreg_disk_law_name is `name`.
 *
 *  name  in: NUL-terminated name, compared exactly (case-sensitive); may be NULL.
 *
 *  Returns the law's value (>= 1), not a status; 0 if name is NULL or names no law. Since 1.2.
 *  Pure function; thread safe. */
FRICREG_API int fricreg_disk_law_from_name(const char *name);

/** Evaluate one 2-D friction law at one contact.
 *
 *  law   one of enum fricreg_disk_law.
 *  v     in: v[2], the tangential relative velocity (velocity units).
 *  f_eq  in: f_eq[2], the tangential force that would make the contact's relative acceleration
 *        zero (force units); ignored (may be NULL) for FRICREG_DISK_COULOMB.
 *  mun   the friction bound mu*N >= 0 (force units): |f| <= mun. mun = 0 gives f = 0.
 *  eps   regularization parameter >= DBL_MIN (velocity units: the band |v| < eps); ignored by
 *        FRICREG_DISK_COULOMB and FRICREG_DISK_FORCE_BALANCE but validated.
 *  f     out: f[2], the friction force (may be the same array as v or f_eq). Written only on
 *        success.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if v or f, or f_eq for a law that reads it, is NULL;
 *  FRICREG_EINVAL for an unknown law, mun < 0, eps < DBL_MIN, or an input beyond 1e250 in
 *  magnitude; FRICREG_ENONFINITE if a number is NaN or infinite.
 *  Implements the 2-D (1), (2) and (4) of docs/laws2d.md. Since 1.2. Pure function; thread
 *  safe. */
FRICREG_API int fricreg_disk_eval(int law, const double v[], const double f_eq[], double mun,
                                  double eps, double f[]);

/** Evaluate one 2-D friction law over m contacts (one eps for all).
 *
 *  law   one of enum fricreg_disk_law.
 *  eps   as for fricreg_disk_eval.
 *  m     number of contacts; m = 0 is valid and does nothing.
 *  v     in: v[2*m], interleaved: contact i's velocity is (v[2*i], v[2*i + 1]).
 *  f_eq  in: f_eq[2*m], interleaved likewise; NULL for FRICREG_DISK_COULOMB, which does not
 *        read it (if given, it is validated all the same).
 *  mun   in: mun[m], the bounds >= 0.
 *  f     out: f[2*m], interleaved; may be the same array as v or f_eq. Inputs are validated
 *        before any output is written.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if v, mun, f, or f_eq for a law that reads it, is NULL
 *  (when m > 0); FRICREG_EINVAL for an unknown law, eps < DBL_MIN, some mun[i] < 0 or an input
 *  beyond 1e250 in magnitude; FRICREG_ENONFINITE if any input is NaN or infinite (checked
 *  before the ranges). The same numbers as fricreg_disk_eval contact by contact. Since 1.2.
 *  Thread safe. */
FRICREG_API int fricreg_disk_eval_batch(int law, double eps, size_t m, const double v[],
                                        const double f_eq[], const double mun[], double f[]);

/** \} */

#ifdef __cplusplus
}
#endif

#endif /* FRICREG_DISK_H */
