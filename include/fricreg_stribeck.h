/* SPDX-License-Identifier: GPL-3.0-or-later */
/**
 * \file
 * fricreg_stribeck.h — static friction above kinetic (Stribeck), with exact stick, for 1-D
 * and 2-D contacts, beyond the paper.
 *
 * The set-valued law: at v = 0 the contact holds any force |f| <= fs = mu_s N; sliding, the
 * force opposes v with the kinetic curve
 *     k(s) = fk + (fs - fk) exp(-(s/vs)^delta),   s = |v|,   fk = mu_k N <= fs,
 * which falls from fs at s = 0 to fk (fs = fk: constant Coulomb friction). The regularized law
 * here (docs/laws2d.md):
 *   |v| >= eps:  f = -k(|v|) sgn(v)  (2-D: -k(|v|) v/|v|), the kinetic curve itself;
 *   |v| <  eps:  law (4) (2-D: the default disk law FRICREG_DISK_QUINN) with the bound
 *                B = fs + (k(eps) - fs) |v|/eps in place of mu N,
 * so that at v = 0 it is the force balance with fs, f = fs sat(f_eq/fs) (2-D: fs P_D(f_eq/fs)):
 * exact stick while |f_eq| <= fs, break-away at |f_eq| = fs exactly; at |v| -> eps it is
 * -k(eps) sgn(v), so f is continuous (Lipschitz, for every delta > 0) in (v, f_eq); and as
 * eps -> 0 it converges pointwise to the set-valued law. With fs = fk it is law (4) (2-D:
 * FRICREG_DISK_QUINN) with mun = fk, bit for bit. The band's error relative to fs is of order
 * (fs - fk)/fs (eps/vs)^delta: with delta < 1 it falls slower than eps (docs/laws2d.md,
 * "Warnings: δ < 1"; fricreg-sim belt warns, FRICREG_WARN_STRIBECK_EPS).
 *
 * Conventions are fricreg.h's, and for 2-D fricreg_disk.h's (vectors of two doubles, arrays of
 * m vectors interleaved: contact i is (v[2*i], v[2*i + 1]); numbers at most 1e250). Since 1.2
 * (FRICREG_1.2).
 */
#ifndef FRICREG_STRIBECK_H
#define FRICREG_STRIBECK_H

#include "fricreg.h"
#include "fricreg_disk_ctx.h"

#ifdef __cplusplus
extern "C" {
#endif

/** \defgroup law_stribeck Stribeck friction (static above kinetic)
 *  \ingroup law
 *  The Stribeck law, static friction above kinetic with exact stick, at 1-D and 2-D contacts,
 *  one contact or an array at a time. Beyond the paper; the law is at the top of
 *  fricreg_stribeck.h. In a context it is set by fricreg_ctx_set_stribeck (1-D) and
 *  fricreg_disk_ctx_set_stribeck (2-D), which belong to their contexts' groups.
 *  \{ */

/** Evaluate the Stribeck law at one 1-D contact (see the top of this header).
 *
 *  v      relative contact velocity (velocity units).
 *  f_eq   equilibrium force (force units), as for fricreg_law_eval.
 *  fs     static bound mu_s N, the holding force (force units), fs >= fk.
 *  fk     kinetic force mu_k N >= 0, the limit of k(|v|) for |v| -> infinity; fk <= fs.
 *  vs     Stribeck velocity > 0 (velocity units): k(vs) = fk + (fs - fk)/e.
 *  delta  Stribeck exponent > 0 (1: exponential, 2: Gaussian decay).
 *  eps    regularization parameter >= DBL_MIN (velocity units), the band |v| < eps.
 *  f      out: the friction force; |f| <= fs. Written only on success.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if f is NULL; FRICREG_ENONFINITE if a number is NaN or
 *  infinite; FRICREG_EINVAL if fk < 0, fk > fs (kinetic above static), vs <= 0, delta <= 0 or
 *  eps < DBL_MIN. Pure function; thread safe. */
FRICREG_API int fricreg_stribeck_eval(double v, double f_eq, double fs, double fk, double vs,
                                      double delta, double eps, double *f);

/** Evaluate the Stribeck law over m 1-D contacts, each with its own parameters (one eps).
 *
 *  eps       as for fricreg_stribeck_eval.
 *  m         number of contacts; m = 0 is valid and does nothing.
 *  v[m], f_eq[m]                in: velocities and equilibrium forces.
 *  fs[m], fk[m], vs[m], delta[m]  in: each contact's parameters, as for fricreg_stribeck_eval.
 *  f[m]      out: the forces; may be the same array as v or f_eq. Inputs are validated before
 *            any output is written.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if an array is NULL (when m > 0); FRICREG_ENONFINITE if a
 *  number is NaN or infinite (anywhere, checked first); FRICREG_EINVAL if eps < DBL_MIN or
 *  some contact has fk < 0, fk > fs, vs <= 0 or delta <= 0. The same numbers as
 *  fricreg_stribeck_eval contact by contact. Thread safe. */
FRICREG_API int fricreg_stribeck_eval_batch(double eps, size_t m, const double v[],
                                            const double f_eq[], const double fs[],
                                            const double fk[], const double vs[],
                                            const double delta[], double f[]);

/** Evaluate the 2-D Stribeck law at one contact (see the top of this header): the default law of
 *  FRICREG_DISK_QUINN with the bound B in the band, the kinetic curve -k(|v|) v/|v| outside.
 *
 *  v      in: v[2], the tangential velocity.  f_eq  in: f_eq[2], the equilibrium force.
 *  fs, fk, vs, delta, eps  as for fricreg_stribeck_eval (fs and fk at most 1e250).
 *  f      out: f[2], the force, |f| <= fs; may be the same array as v or f_eq. Written only on
 *         success.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if v, f_eq or f is NULL; FRICREG_ENONFINITE if a number
 *  is NaN or infinite; FRICREG_EINVAL if fk < 0, fk > fs, vs <= 0, delta <= 0, eps < DBL_MIN or
 *  a component of v or f_eq, or fs, exceeds 1e250 in magnitude. Pure function; thread safe. */
FRICREG_API int fricreg_stribeck_disk_eval(const double v[], const double f_eq[], double fs,
                                           double fk, double vs, double delta, double eps,
                                           double f[]);

/** Evaluate the 2-D Stribeck law over m contacts, each with its own parameters (one eps).
 *
 *  v[2*m], f_eq[2*m]  in: interleaved vectors (contact i: v[2*i], v[2*i + 1]).
 *  fs[m], fk[m], vs[m], delta[m]  in: each contact's parameters.
 *  f[2*m]  out: interleaved forces; may be the same array as v or f_eq. Inputs are validated
 *          before any output is written. m = 0 is valid and does nothing.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if an array is NULL (when m > 0); FRICREG_ENONFINITE if a
 *  number is NaN or infinite (anywhere, checked first); FRICREG_EINVAL if eps < DBL_MIN or some
 *  contact's numbers are out of range as for fricreg_stribeck_disk_eval. The same numbers as
 *  fricreg_stribeck_disk_eval contact by contact. Thread safe. */
FRICREG_API int fricreg_stribeck_disk_eval_batch(double eps, size_t m, const double v[],
                                                 const double f_eq[], const double fs[],
                                                 const double fk[], const double vs[],
                                                 const double delta[], double f[]);

/** \} */

/** \addtogroup ctx
 *  \{ */

/** Static > kinetic (Stribeck) friction for the m contacts of a 1-D context (fricreg.h,
 *  fricreg_ctx_eval), each with its own parameters: the law at the top of this header, with the
 *  context's eps, under every coupling and partition the context offers. Since 1.3
 *  (FRICREG_1.3).
 *
 *  What fricreg_ctx_eval then computes: law (4) with a bound that depends on the contact's own
 *  |zdot_i|, B_i = fs_i + (k_i(eps) - fs_i) |zdot_i|/eps in the band |zdot_i| < eps, and the
 *  slip force -k_i(|zdot_i|) sgn(zdot_i) outside it. With a diagonal W that is
 *  fricreg_stribeck_eval at (zdot_i, f_eq,i = -a_free,i/W_ii), bit for bit; with a dense W the
 *  consistent law's box QP (docs/coupled.md) has the bounds lo_i = -B_i (1 - max(-c_i, 0)),
 *  hi_i = B_i (1 - max(c_i, 0)), c_i = 2 zdot_i/eps, and b_i = a_free,i + W_ii c_i B_i
 *  + (W_SL f_L)_i; the paper's partition applies the law at (zdot_i, f_eq,i). So at rest
 *  (zdot_S = 0) the consistent law is Coulomb's stick problem with the static bounds fs: a
 *  contact whose f_eq,i stays within fs_i holds, at zero acceleration (to rounding), and it
 *  breaks away when |f_eq,i| reaches fs_i; f is continuous in (zdot, a_free), across
 *  |zdot_j| = eps too. With fs = fk the numbers (f, f_eq, tangent) are those of
 *  fricreg_ctx_set_bounds with mun = fk, bit for bit. fricreg_ctx_tangent includes the bound's
 *  motion with |zdot_i|, (k(eps) - fs)/eps sgn(zdot_i) in the band, the slip slope
 *  -k'(|zdot_i|) outside it, and through W_SL f_L the near-stick forces' dependence on a
 *  sliding contact's zdot; fricreg_ctx_stick_stiffness uses fs (the band's largest slope at
 *  rest is 2 fs/eps). Each evaluation costs one pow and exp more per sliding contact.
 *
 *  How it combines with the other setters (each discards the tangent, as every setter does):
 *   - this call selects law (4) (FRICREG_LAW_QUINN) and keeps the context's eps;
 *   - fricreg_ctx_set_law with FRICREG_LAW_QUINN changes eps and keeps Stribeck friction;
 *     with any other law it switches Stribeck friction off;
 *   - fricreg_ctx_set_bounds switches it off: the last of set_bounds and set_stribeck decides
 *     the bounds. The bounds mun are kept, not changed, while Stribeck friction is on;
 *   - m = 0 switches it off (the arrays are not read and may be NULL): law (4) with the
 *     bounds mun of the last fricreg_ctx_set_bounds (or the defaults, 1).
 *  It may be called before every evaluation (normal forces vary): O(m), plus m exp and pow
 *  calls; the first call allocates 6 m doubles, kept until fricreg_ctx_free.
 *
 *  ctx       the context.
 *  m         the context's contact count, or 0 to switch Stribeck friction off.
 *  fs[m]     static bounds mu_s,i N_i (force units), the holding forces; fs[i] >= fk[i].
 *  fk[m]     kinetic forces mu_k,i N_i >= 0 (force units), the limits of k_i for |v| -> inf.
 *  vs[m]     Stribeck velocities > 0 (velocity units).
 *  delta[m]  Stribeck exponents > 0 (1: exponential, 2: Gaussian decay).
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if ctx is NULL or (m > 0) an array is NULL; FRICREG_ESIZE
 *  if m is neither 0 nor the context's count; FRICREG_ENONFINITE if a number is NaN or
 *  infinite (anywhere, checked first); FRICREG_EINVAL if some contact has fk < 0, fk > fs
 *  (kinetic above static), vs <= 0 or delta <= 0; FRICREG_ENOMEM. On failure the context is
 *  unchanged (its law, eps, bounds and Stribeck parameters), and the error is recorded in it. */
FRICREG_API int fricreg_ctx_set_stribeck(fricreg_ctx *ctx, size_t m, const double fs[],
                                         const double fk[], const double vs[],
                                         const double delta[]);

/** \} */

/** \addtogroup disk_ctx
 *  \{ */

/** Static > kinetic (Stribeck) friction for the m contacts of a 2-D context
 *  (fricreg_disk_ctx.h, fricreg_disk_ctx_eval), each with its own parameters: the 2-D law at
 *  the top of this header, with the context's eps, under its coupling. Since 1.3
 *  (FRICREG_1.3). Declared here with the other Stribeck entry points, so that this header is
 *  where Stribeck friction is defined and offered; fricreg_disk_ctx.h keeps the Coulomb bounds.
 *
 *  What fricreg_disk_ctx_eval then computes: the law of fricreg_disk_ctx.h (FRICREG_DISK_QUINN)
 *  with a bound that depends on the contact's own r_i = |zdot_i|, B_i = fs_i + (k_i(eps) -
 *  fs_i) r_i/eps in the band r_i < eps, in place of mun_i: K_i is the disk of centre -a_i u_i
 *  and radius B_i - a_i, a_i = B_i r_i/eps, b_i = a_free,i + W_ii c_i B_i (c_i = 2 zdot_i/eps),
 *  the whole disk fs_i D at rest; outside the band the slip force -k_i(r_i) u_i, entering the
 *  others' b through W. With isotropic blocks W_ii = w_i I (block-diagonal W) that is
 *  fricreg_stribeck_disk_eval at (zdot_i, f_eq,i = -a_free,i/w_i) contact by contact, to
 *  rounding; with a dense W the coupled QP on these disks (fricreg_disk_ctx.h), whose bounds
 *  do not depend on f. So at rest (zdot = 0) it is Coulomb's coupled stick problem with the
 *  static bounds fs: a contact whose f_eq,i stays within fs_i holds, at zero acceleration (to
 *  the solver's tolerance), and breaks away when |f_eq,i| passes fs_i; f is continuous in
 *  (zdot, a_free), across |zdot_j| = eps too. With fs = fk the numbers (f and tangent) are those
 *  of fricreg_disk_ctx_set_bounds with mun = fk, bit for bit. fricreg_disk_ctx_tangent
 *  includes the bound's motion with r_i: dB/dr = (k(eps) - fs)/eps in the band (at rest taken
 *  along the direction the contact will slide, -f_i/|f_i|, as for the radius), the slip slope
 *  -k'(r_i) u_i u_i^T outside it, and through W the near-stick forces' dependence on a sliding
 *  contact's zdot. Each evaluation costs one pow and exp more per sliding contact.
 *
 *  How it combines with the other setters (each discards the tangent, as every setter does):
 *   - this call selects FRICREG_DISK_QUINN and keeps the context's eps;
 *   - fricreg_disk_ctx_set_law with FRICREG_DISK_QUINN changes eps and keeps Stribeck
 *     friction; with FRICREG_DISK_FORCE_BALANCE it switches Stribeck friction off;
 *   - fricreg_disk_ctx_set_bounds switches it off: the last of set_bounds and set_stribeck
 *     decides the bounds. The bounds mun are kept, not changed, while Stribeck friction is on;
 *   - m = 0 switches it off (the arrays are not read and may be NULL): the bounds mun of the
 *     last fricreg_disk_ctx_set_bounds (or the defaults, 1).
 *  It may be called before every evaluation (normal forces vary): O(m), plus m exp and pow
 *  calls; the first call allocates 5 m doubles, kept until fricreg_disk_ctx_free.
 *
 *  ctx       the 2-D context.
 *  m         the context's contact count, or 0 to switch Stribeck friction off.
 *  fs[m]     static bounds mu_s,i N_i (force units), the holding forces; fk[i] <= fs[i] <= 1e250.
 *  fk[m]     kinetic forces mu_k,i N_i >= 0 (force units), the limits of k_i for |v| -> inf.
 *  vs[m]     Stribeck velocities > 0 (velocity units).
 *  delta[m]  Stribeck exponents > 0 (1: exponential, 2: Gaussian decay).
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if ctx is NULL or (m > 0) an array is NULL; FRICREG_ESIZE
 *  if m is neither 0 nor the context's count; FRICREG_ENONFINITE if a number is NaN or
 *  infinite (anywhere, checked first); FRICREG_EINVAL if some contact has fk < 0, fk > fs
 *  (kinetic above static), fs > 1e250, vs <= 0 or delta <= 0; FRICREG_ENOMEM. On failure the
 *  context is unchanged (its law, eps, bounds and Stribeck parameters), and the error is
 *  recorded in it. */
FRICREG_API int fricreg_disk_ctx_set_stribeck(fricreg_disk_ctx *ctx, size_t m, const double fs[],
                                              const double fk[], const double vs[],
                                              const double delta[]);

/** \} */

#ifdef __cplusplus
}
#endif

#endif /* FRICREG_STRIBECK_H */
