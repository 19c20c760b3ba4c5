/* SPDX-License-Identifier: GPL-3.0-or-later */
/**
 * \file
 * fricreg_hb_stability.h — the stability of harmonic balance's solutions: Floquet multipliers and
 * exponents by Hill's method or the exact monodromy, on or off, and the method's choice.
 *
 * Part of fricreg_hb.h, which includes it (so does every header of the driver: include
 * either), split out by object since 1.9; the driver, its model and the conventions are
 * fricreg_hb.h's. Since 1.6 unless a function says otherwise.
 */
#ifndef FRICREG_HB_STABILITY_H
#define FRICREG_HB_STABILITY_H

#include "fricreg_hb.h"

#ifdef __cplusplus
extern "C" {
#endif

/** \defgroup hb_stability Joints: harmonic balance, stability (fricreg_hb_stability.h)
 *  \{ */

/** Largest number of Fourier coefficients ndof (2H + 1) of Hill's method
 *  (fricreg_hb_set_stability): its companion matrix, of order 2 ndof (2H + 1), is dense. */
#define FRICREG_HB_MAX_HILL 1024

/** The index of fricreg_hb_point_stability that names the driver's last solution (that of
 *  fricreg_hb_solve, or the last point of fricreg_hb_continue) rather than a stored point. */
#define FRICREG_HB_SOLUTION ((size_t)-1)

/** Compute the stability of every solution from now on (enable = 1), or stop (0, the default),
 *  by the method of fricreg_hb_set_stability_method: the exact monodromy of the orbit where
 *  every element is piecewise linear, Hill's method otherwise. Since 1.7 (FRICREG_1.7).
 *
 *  Hill's method (the only one before 1.8). A perturbation y(t) = e^{λt} p(t), p periodic, of
 *  a solution solves the quadratic eigenproblem (λ² M⊗I + λ (C⊗I + 2 M⊗∇) + S) P = 0 in the
 *  Fourier coefficients P of p (the full ndof (2H + 1) of them, not the condensed q), S the
 *  Jacobian of the HB equations (HB), K − (hΩ)² M ± hΩ C per harmonic plus J^T (∂F/∂q) J from
 *  the elements' exact AFT Jacobians, ∇ the derivative on one period's coefficients (Krack &
 *  Gross Sec. 5.3; G. W. Hill 1886). Solved as the eigenproblem of its companion matrix of
 *  order 2 ndof (2H + 1) by LAPACK's dgeev (since 1.8; GSL's gsl_eigen_nonsymm before); of
 *  its eigenvalues, each Floquet exponent repeated at λ + i k Ω, the 2 ndof of least |Im λ|
 *  (within ±Ω/2) are the Floquet exponents, μ = exp(2π λ/Ω) the multipliers. The elements'
 *  sliders enter through their stabilized hysteresis's Jacobian: their offsets, forgotten once
 *  they slip, are no state of their own, so beyond the verdict its multipliers are not the
 *  orbit's (on a Jenkins pair the largest is off by up to 0.44). A real negative multiplier
 *  appears as the pair Re λ ± iΩ/2; those of Im λ > 0 are selected before their conjugates, so
 *  each is counted once (two of them, as after a pair's collision on the negative real axis,
 *  give four exponents of one |Im λ|, of which |Im λ| alone could take the smaller twice);
 *  only a lone one is completed by its conjugate, counted twice. Cost per solution: about
 *  10 (2 ndof (2H + 1))³ flops, with ndof (2H + 1) <= FRICREG_HB_MAX_HILL; its matrices, 4
 *  (ndof (2H + 1))² + O(ndof (2H + 1)) doubles.
 *
 *  The exact monodromy (since 1.8), for 1-D Jenkins and Iwan elements, with or without lift-off
 *  (not the 3-D contact element): between the switches, which the exact AFT locates on the
 *  solution (slip onsets, stops, openings, touchdowns), the equations of motion linearized on
 *  the state (x, x', the offsets of the sliders that switch) are linear and time-invariant, so
 *  the monodromy matrix is the product Φ = e^{A_K Δt_K} S_K ⋯ S_1 e^{A_1 Δt_1} of the pieces'
 *  exponentials (Padé, scaling and squaring) and the saltation matrices S_k of the onsets and
 *  touchdowns, where a slider's offset starts following its element's displacement (R. I.
 *  Leine, H. Nijmeijer 2004, Ch. 7). A slider stuck over the whole period
 *  has a neutral multiplier 1, which is left out (like HB's offset ambiguity); one that slips
 *  once adds a 0, dropped. The 2 ndof left are the multipliers μ, λ = log μ Ω/2π the exponents
 *  (Im λ in (−Ω/2, Ω/2]). They are the HB orbit's own multipliers, which converge to an
 *  event-driven shooting's as H grows (8.6e-6 off at H = 40 on a Jenkins pair, where Hill's
 *  stays 0.44 away: tests/floquet/test_hb_monodromy.c). With lift-off (Jenkins elements, up to 32
 *  dofs; since 1.9) the switch instants are moved from the HB orbit's onto the exact orbit's,
 *  whose multipliers they then are: a stiff contact's product is too sensitive to the HB's
 *  truncated instants (docs/stability.md, "A stiff unilateral spring"). Cost per solution: a few (2 ndof +
 *  sliders)³ flops per switch, M^-1 applied once; no size limit but memory, 14 (2 ndof +
 *  sliders)² doubles (measured with the reference BLAS on a chain with 10 Jenkins elements at
 *  H = 3: 0.13 s a solution at 60 dofs, 35 s at 300, against 0.7 ms and 0.1 s for a
 *  solution's Newton from a near guess; OpenBLAS: 0.045 s and 6.1 s).
 *
 *  The condensed monodromy (since 1.9): the same on the model condensed onto the dofs B some row
 *  of J touches (R. R. Craig, M. C. C. Bampton 1968): x_I = Ψ x_B + Φ_k η, Ψ = −K_II^-1 K_IB,
 *  Φ_k the fixed-interface modes below 50 Ω (not H's: the orbit's monodromy does not depend on
 *  it; the error is about (Ω/ω_r)^4 of the first mode left out); the modes left out keep the
 *  multipliers of the structure's highest modes (from ω² and φ^T C φ), so all 2 ndof are
 *  reported. Its modes are computed once per model (LAPACK's dsygvd, O(ndof³)), its workspace
 *  made and grown by the solves (its order depends on Ω). K_II must be positive definite
 *  (FRICREG_ESINGULAR from the solve otherwise) and the model at most 4096 dofs
 *  (FRICREG_EINVAL; dense: about 9 ndof² doubles, 290 MB and 1.4 s of modes at 1500 dofs).
 *  Along continuations on chains of 60 and 300 dofs with 10 Jenkins elements, and on a gap
 *  chain with folds and Neimark–Sacker points, every point's count of unstable multipliers is
 *  the whole model's and the largest within 3e-4 of it, at 1.7-2.8x a point's cost without
 *  stability at 60 dofs and 1.3-1.9x at 300 and 1000 dofs, where the whole model's takes
 *  3.9-9.8x (60 dofs) and 190-410x (300 dofs) (bench/hb_stability_size.c, docs/stability.md).
 *
 *  Either way a solution is stable when every multiplier has |μ| <= 1 + 1e-6 (Re λ 2π/Ω <=
 *  1e-6), and each stored point then keeps 4 + 4 ndof numbers. The workspace of the method in
 *  force is allocated here, so the solves allocate nothing; elements set later that change the
 *  automatic choice have the other's made at the next solution. M must be nonsingular (checked
 *  at each solution: FRICREG_ESINGULAR from the solve). Enabling or disabling drops the stored
 *  points and the last solution (they have no stability). LAPACK reports a QR iteration that
 *  does not converge by a status, which the solve or continuation returns as
 *  FRICREG_EINTEGRATOR with a message naming Ω, the kept solution and points untouched.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if hb is NULL; FRICREG_EINVAL if enable is not 0 or 1, or
 *  the method in force is Hill's and ndof (2H + 1) > FRICREG_HB_MAX_HILL (the same from a
 *  solve where the elements changed since); FRICREG_ENOMEM (nothing changed). */
FRICREG_API int fricreg_hb_set_stability(fricreg_hb *hb, int enable);

/** The stability of a stored continuation point, or of the last solution.
 *
 *  k        the point's index, 0 <= k < fricreg_hb_points(hb), or FRICREG_HB_SOLUTION for the
 *           last solution (fricreg_hb_solve's, or the last point of fricreg_hb_continue).
 *  stable   out: 1 if every Floquet exponent has Re λ 2π/Ω <= 1e-6, else 0
 *           (fricreg_hb_set_stability).
 *  mu_max   out: the largest |Floquet multiplier|, exp(2π max Re λ/Ω), nondimensional.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if hb, stable or mu_max is NULL; FRICREG_EINVAL if
 *  stability is off, k is out of range, or (FRICREG_HB_SOLUTION) there is no solution (none
 *  since stability was turned on, or the model changed since). Since 1.7 (FRICREG_1.7). */
FRICREG_API int fricreg_hb_point_stability(fricreg_hb *hb, size_t k, int *stable, double *mu_max);

/** The Floquet exponents of a stored continuation point, or of the last solution, as the
 *  method in force computed them (fricreg_hb_set_stability_method; see fricreg_hb_set_stability).
 *
 *  k          the point's index, 0 <= k < fricreg_hb_points(hb), or FRICREG_HB_SOLUTION.
 *  nexp       must equal 2 ndof, the number of exponents.
 *  exponents  out: [nexp][2] row-major, (Re λ, Im λ) per exponent, rad/s, |Im λ| <= Ω/2,
 *             in no particular order; the multipliers are μ = exp(2π λ/Ω), and a solution is
 *             unstable by as many as have Re λ 2π/Ω > 1e-6.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if hb or exponents is NULL; FRICREG_ESIZE if nexp is not
 *  2 ndof; FRICREG_EINVAL as fricreg_hb_point_stability (stability off, k out of range, no
 *  solution); exponents is untouched on failure. Since 1.9 (FRICREG_1.9). */
FRICREG_API int fricreg_hb_point_exponents(fricreg_hb *hb, size_t k, size_t nexp,
                                           double exponents[]);

/** Largest order 2 ndof + sliders of the exact monodromy that FRICREG_HB_STABILITY_AUTO takes
 *  (fricreg_hb_set_stability_method): its matrices are dense, each switch costing a few times
 *  that order cubed (past it a solution takes seconds to minutes, a continuation of hundreds
 *  of points hours: chosen, not taken by default). */
#define FRICREG_HB_MAX_MONODROMY 512

/** How fricreg_hb_set_stability computes a solution's stability. */
enum fricreg_hb_stability_method {
    FRICREG_HB_STABILITY_AUTO = 0,      /**< where every element is piecewise linear (1-D
                                             Jenkins and Iwan elements, with or without
                                             lift-off): the condensed monodromy where
                                             32 <= ndof <= 1024 and the elements touch at most
                                             ndof/4 dofs (since 1.9), else the exact monodromy
                                             where its order 2 ndof + sliders is at most
                                             FRICREG_HB_MAX_MONODROMY, else the condensed one
                                             up to 4096 dofs (since 1.9); Hill's method
                                             otherwise (the default) */
    FRICREG_HB_STABILITY_HILL = 1,      /**< Hill's method, for any element */
    FRICREG_HB_STABILITY_MONODROMY = 2, /**< the exact monodromy of the orbit, at any order */
    FRICREG_HB_STABILITY_CONDENSED = 3  /**< the exact monodromy of the model condensed onto
                                             the dofs the elements touch (since 1.9) */
};

/** Choose how the stability of the next solutions is computed (fricreg_hb_set_stability);
 *  points already stored keep theirs. The default, FRICREG_HB_STABILITY_AUTO, takes the exact
 *  monodromy where the elements allow it (condensed where they touch few dofs: since 1.9;
 *  FRICREG_HB_STABILITY_MONODROMY gives 1.8's), which differs from 1.7's Hill's method beyond
 *  the verdict (the multipliers are the orbit's own); FRICREG_HB_STABILITY_HILL gives 1.7's
 *  results. Since 1.8 (FRICREG_1.8).
 *
 *  method   enum fricreg_hb_stability_method.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if hb is NULL; FRICREG_EINVAL if method is none of the
 *  enum, or when called from the monitor during a solve. A solve with
 *  FRICREG_HB_STABILITY_MONODROMY or _CONDENSED on elements that are not piecewise linear (the
 *  3-D contact element) returns FRICREG_EINVAL with a message. */
FRICREG_API int fricreg_hb_set_stability_method(fricreg_hb *hb, int method);

/** The method that computes the next solution's stability: FRICREG_HB_STABILITY_HILL,
 *  FRICREG_HB_STABILITY_MONODROMY or FRICREG_HB_STABILITY_CONDENSED, the automatic choice made
 *  for the elements set now (whether stability is on or not). Since 1.8 (FRICREG_1.8).
 *
 *  method   out: enum fricreg_hb_stability_method, never FRICREG_HB_STABILITY_AUTO.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if hb or method is NULL. */
FRICREG_API int fricreg_hb_get_stability_method(fricreg_hb *hb, int *method);

/** \} */

#ifdef __cplusplus
}
#endif

#endif /* FRICREG_HB_STABILITY_H */
