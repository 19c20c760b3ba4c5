# SPDX-License-Identifier: GPL-3.0-or-later
"""What harmonic balance returns (harmonic_balance.py): a solution, a branch of the frequency
(or level) response with its stability and bifurcations, a nonlinear mode's backbone. Plain
arrays, so a result outlives the driver that computed it.

Fourier coefficients are laid out as fricreg_hb.h's: a periodic function of θ = Ω t is
x0 + Σ_{h=1..H} (a_h cos hθ + b_h sin hθ), stored as the 2H + 1 numbers
(x0, a_1, b_1, ..., a_H, b_H) along the last axis (tmdsimpy's and pyHarm's order per dof).
"""
from ._record import record

__all__ = ["Solution", "Response", "Bifurcation", "Backbone", "SpecialPoint"]

Solution = record("Solution", "omega q x stable mu_max multipliers", """\
A periodic steady state (:meth:`HarmonicBalance.solve`).

omega : float
    Excitation circular frequency Ω, rad/s.
q : ndarray, shape (nrows, 2H + 1)
    The elements' coordinates q = J x, one row per row of the elements' J, each its Fourier
    coefficients (displacement units).
x : ndarray, shape (ndof, 2H + 1)
    The displacements' Fourier coefficients, one row per dof.
stable : bool or None
    Every Floquet multiplier within the unit circle (|μ| <= 1 + 1e-6); None with stability off.
mu_max : float
    The largest |μ| (nan with stability off).
multipliers : ndarray of complex, shape (2 ndof,), or None
    The Floquet multipliers μ = exp(2π λ/Ω) by decreasing |μ| (``fricreg_hb_point_exponents``);
    None with stability off.
""")

Bifurcation = record("Bifurcation", "kind omega level point rms", """\
A bifurcation located along a branch (``fricreg_hb_bifurcation``).

kind : str
    ``"TP"`` turning point (a fold in the continued parameter), ``"BP"`` branch point,
    ``"PD"`` period doubling (a multiplier crosses -1), ``"NS"`` Neimark-Sacker (a complex
    pair crosses the unit circle); PD and NS need stability on.
omega : float
    Its excitation frequency, rad/s.
level : float
    Its excitation level λ (1 on a branch in Ω).
point : int
    The index of the stored point before it (it lies between point and point + 1).
rms : ndarray, shape (ndof,)
    Each dof's RMS there (displacement units).
""")

Response = record(
    "Response",
    "omega level rms x stable mu_max bifurcations solution multipliers",
    """\
A branch of the periodic response (:meth:`HarmonicBalance.frequency_response`,
:meth:`HarmonicBalance.level_response`), its points in the branch's order.

omega : ndarray, shape (npoints,)
    Excitation frequency of each point, rad/s (constant along a level branch).
level : ndarray, shape (npoints,)
    Excitation level λ of each point (1 along a frequency branch).
rms : ndarray, shape (npoints, ndof)
    Each dof's RMS over a period, sqrt(x0² + Σ_h (a_h² + b_h²)/2) (displacement units).
x : ndarray, shape (npoints, ndof, 2H + 1)
    The displacements' Fourier coefficients of each point (``fricreg_hb_point_displacement``:
    recomputed from the point's unknowns by (HB), one factorization of D_h per point).
stable : ndarray of bool, shape (npoints,), or None
    Each point's stability; None with stability off.
mu_max : ndarray, shape (npoints,), or None
    Each point's largest |Floquet multiplier|; None with stability off.
bifurcations : tuple of Bifurcation
    Located between the points, in the branch's order.
solution : Solution or None
    The branch's last point with its coefficients (None if the continuation stored none); its
    q is J x, equal to the solver's unknowns to Newton's tolerance: a guess to go on from.
multipliers : ndarray of complex, shape (npoints, 2 ndof), or None
    Each point's Floquet multipliers by decreasing |μ|; None with stability off.
""")

SpecialPoint = record("SpecialPoint", "kind amplitude omega zeta harmonic mode", """\
A special point of a backbone (``fricreg_hb_nma_special_point``), in the
branch's order among its folds and crossings.

kind : str
    ``"fold"``: the backbone's amplitude turns (an internal resonance; through_folds only);
    ``"crossing"``: a harmonic k ω of the backbone crosses another stuck linear mode's
    frequency ω_r, where an internal resonance can start.
amplitude : float
    The modal amplitude a there.
omega : float
    The backbone's natural frequency ω there, rad/s (a crossing: k ω = ω_r).
zeta : float
    Its damping ratio ζ there (a crossing: interpolated between the two points around it).
harmonic : int
    k, 2 <= k <= H for a crossing; 1 for a fold.
mode : int
    r, the stuck linear mode crossed (from 0, ascending); a fold's the backbone's own.
""")

Backbone = record("Backbone", "amplitude omega zeta harmonic_energy special_points x", """\
A nonlinear mode's backbone by the extended periodic motion concept (Krack,
Computers & Structures 154 (2015) 59-71): :meth:`HarmonicBalance.backbone`.

amplitude : ndarray, shape (npoints,)
    Modal amplitude a of each point (displacement times the square root of mass: φ^T M X_1,
    φ mass-normalized).
omega : ndarray, shape (npoints,)
    Natural frequency ω(a), rad/s.
zeta : ndarray, shape (npoints,)
    Damping ratio ζ(a), nondimensional.
harmonic_energy : ndarray, shape (npoints, H + 1)
    Each harmonic's share of the kinetic energy averaged over a period (row sums 1;
    ``fricreg_hb_nma_harmonic_energy``).
special_points : tuple of SpecialPoint
    Its folds and crossings in one list, in the branch's order (by arclength through_folds,
    by amplitude otherwise).
x : ndarray, shape (npoints, ndof, 2H + 1)
    The displacements' Fourier coefficients of each point's periodic motion.
""")
