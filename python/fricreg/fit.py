# SPDX-License-Identifier: GPL-3.0-or-later
"""A joint's parameters from a test (``fricreg_fit.h``, docs/identification.md): the modal Iwan
model (Segalman's four-parameter Iwan joint, D. J. Segalman, J. Appl. Mech. 72 (2005) 752-760,
beside a linear modal stiffness K0 and damping ratio zeta0) fitted to a mode's measured natural
frequency and damping ratio at several response levels, by GSL's trust-region least squares
with the exact Jacobian; covariance, 95 % intervals, identifiability. The backbone is the
quasi-static modal analysis's (Lacayo and Allen, MSSP 118 (2019) 133-157)::

    k_sec = K0 + F(a)/a,   f = sqrt(k_sec)/(2 pi),   zeta = zeta0 + D(a)/(2 pi k_sec a^2)

F and D the joint's backbone force and Masing dissipation at the modal amplitude a.

Or any harmonic-balance model's nonlinear mode (``model=``, a :class:`HarmonicBalance`): its
EPMC backbone at the levels, the parameters its elements' values and Rayleigh's damping,
differentiated exactly through the backbone (``fricreg_fit_set_model_hb``).
"""
import numpy as np

from ._fricreg import ffi, lib
from ._arrays import as_doubles, as_integer, as_scalar, choice, pointer
from .errors import raise_status, refused

__all__ = ["FIT_PARAMS", "FitResult", "fit_backbone", "backbone"]

#: The modal Iwan model's parameters, in the order of every parameter array
#: (``enum fricreg_fit_param``): F_S (macroslip force, modal), K_T (the joint's stiffness,
#: 1/s^2), chi (> -1), beta (>= 0), zeta0 (linear damping ratio), K0 (linear modal stiffness
#: beside the joint, 1/s^2).
FIT_PARAMS = ("fs", "kt", "chi", "beta", "zeta0", "k0")
_NP = len(FIT_PARAMS)
_KINDS = {"displacement": lib.FRICREG_FIT_DISPLACEMENT, "velocity": lib.FRICREG_FIT_VELOCITY,
          "acceleration": lib.FRICREG_FIT_ACCELERATION}
_FLOORS = {"chi": -1.0}
_BACKBONES = {"epmc": 0, "qsma": 1}  # a driver's model: its nonlinear mode, or QSMA


class FitResult(dict):
    """The fit, in the conventions of ``scipy.optimize.OptimizeResult`` (a dict whose keys are
    also attributes).

    Attributes
    ----------
    x : ndarray, shape (np,)
        The parameters, in the order of :data:`FIT_PARAMS` (np = 6), or of ``params`` for a
        harmonic-balance model (the fixed ones as fixed).
    params : dict
        The same by name, or by description for a harmonic-balance model.
    cov : ndarray, shape (np, np)
        Their covariance (a fixed parameter's row and column 0).
    lower, upper : ndarray, shape (np,)
        The 95 % intervals (asymmetric for a log-scaled parameter, inside its bounds).
    free : ndarray of bool, shape (np,)
    sv : ndarray, shape (p,)
        The singular values of the Jacobian in the transformed free parameters (log-scaled:
        relative changes), largest first.
    vectors : ndarray, shape (p, np)
        Row k: the parameter combination sv[k] determines (0 on fixed parameters).
    residuals_freq, residuals_zeta : ndarray, shape (n,)
        The levels' weighted residuals (model - measured)/sd.
    cost : float
        r^T r (chi-square with deviations given).
    residual_variance, quantile, condition : float
    success : bool
        True (a failed fit raises :class:`fricreg.Error` instead: nothing is reported as a fit).
    message : str
    nfev, njev, nit : int
        Residual and Jacobian evaluations over every start; the iterations of the start that
        gave the fit.
    starts_converged, best_start : int
    """

    def __getattr__(self, name):
        try:
            return self[name]
        except KeyError:
            raise AttributeError(name) from None

    def curve(self, amplitude):
        """The fitted backbone at amplitudes of the levels' kind, with its standard deviations
        (the delta method): ``(freq_hz, zeta, sd_freq_hz, sd_zeta)``, arrays of amplitude's
        shape (1-D); the 95 % band is value +- ``quantile`` sd."""
        a = as_doubles(amplitude, "amplitude", ndim=1)
        out = [np.empty_like(a) for _ in range(4)]
        fit = self["_fit"]
        status = lib.fricreg_fit_curve(fit, a.size, pointer(a), *map(pointer, out))
        _check(fit, status, "FitResult.curve")
        return tuple(out)


def _check(fit, status, where):
    if status != lib.FRICREG_OK:
        raise_status(status, where, ffi.string(lib.fricreg_fit_errmsg(fit)).decode())


def _new_fit(sensor):
    out = ffi.new("fricreg_fit **")
    if lib.fricreg_fit_create(out) != lib.FRICREG_OK:
        raise_status(lib.FRICREG_ENOMEM, "fit")
    fit = ffi.gc(out[0], lib.fricreg_fit_free)
    _check(fit, lib.fricreg_fit_set_sensor(fit, as_scalar(sensor, "sensor")), "sensor")
    return fit


def _by_name(mapping, name):
    """mapping (dict by parameter name) checked: every key a parameter."""
    mapping = dict(mapping or {})
    unknown = sorted(set(mapping) - set(FIT_PARAMS))
    if unknown:
        raise refused("%s: unknown parameters %s; expected some of %s"
                      % (name, unknown, ", ".join(FIT_PARAMS)))
    return mapping


def _by_index(mapping, name, names):
    """mapping (dict by parameter description or index into params) as a dict by description."""
    out = {}
    for key, value in dict(mapping or {}).items():
        if isinstance(key, (int, np.integer)) and 0 <= key < len(names):
            key = names[key]
        if key not in names:
            raise refused("%s: %r is not one of params (nor an index into them)" % (name, key))
        out[key] = value
    return out


def _set_params(fit, x0, bounds, fixed, names=None):
    """Each parameter free (start, bounds) or fixed; names: an HB model's descriptions."""
    if names is not None:
        x0, bounds, fixed = (_by_index(m, n, names) for m, n in
                             ((x0, "x0"), (bounds, "bounds"), (fixed, "fixed")))
    else:
        x0, bounds = _by_name(x0, "x0"), _by_name(bounds, "bounds")
        fixed = _by_name(fixed, "fixed")
    for j, name in enumerate(names or FIT_PARAMS):
        if name in fixed:
            status = lib.fricreg_fit_set_fixed(fit, j, as_scalar(fixed[name], "fixed"))
            _check(fit, status, "fixed[%r]" % name)
            continue
        lo, hi = bounds.get(name, (_FLOORS.get(name, 0.0), np.inf))
        start = as_scalar(x0[name], "x0") if name in x0 else np.nan
        status = lib.fricreg_fit_set_free(fit, j, start, as_scalar(lo, "bounds"),
                                          as_scalar(hi, "bounds"))
        _check(fit, status, "parameter %r" % (name,))
    return np.array([name not in fixed for name in names or FIT_PARAMS])


def fit_backbone(amplitude, freq_hz, zeta, *, kind="acceleration", sensor=1.0,
                 sd_freq_hz=None, sd_zeta=None, x0=None, bounds=None, fixed=None, starts=None,
                 model=None, params=None, mode=0, damping="matrix", dof=None,
                 backbone="epmc"):
    """Fit the modal Iwan model, or a harmonic-balance model's nonlinear mode, to measured
    levels (``fricreg_fit_run``).

    Parameters
    ----------
    amplitude : array_like, shape (n,)
        The levels' response amplitudes at the sensor, > 0 (m, m/s or m/s^2 by ``kind``).
    freq_hz : array_like, shape (n,)
        The measured natural frequencies (Hz), > 0.
    zeta : array_like, shape (n,)
        The measured damping ratios, > 0.
    kind : {"acceleration", "velocity", "displacement"}
        What amplitude is: |s| omega^k a for k = 2, 1, 0 (a the modal amplitude).
    sensor : float
        The mass-normalized mode shape's value s at the sensor (1: amplitudes are modal).
    sd_freq_hz, sd_zeta : array_like, shape (n,), optional (both or neither)
        The levels' standard deviations (absolute): residuals weighted by them, the covariance
        not rescaled. Without: relative residuals, the covariance scaled by the residual
        variance, Student's t intervals.
    x0 : dict, optional
        Starts by name (:data:`FIT_PARAMS`); a parameter without one takes the levels'
        (docs/identification.md, "Starts"). With ``model``: by description or index into
        ``params``; default the driver's value.
    bounds : dict of (lower, upper), optional
        Bounds by name, not below the parameter's own (0; -1 for chi); default (own, inf).
    fixed : dict, optional
        Parameters fixed at values (``{"beta": 0.0}``: the model without the delta).
    starts : int, optional
        How many starts, 1 ... 1000: default 32 for the modal Iwan model, 1 with ``model``
        (each start marches backbones).
    model : HarmonicBalance, optional
        Fit this driver's nonlinear mode instead (EPMC, ``fricreg_fit_set_model_hb``): its
        element values and Rayleigh's coefficients that ``params`` names, set in the driver
        at each evaluation; after the fit the driver holds the fitted values.
    params : sequence, with ``model``
        The parameters, as :meth:`HarmonicBalance.backbone_sensitivities` describes them:
        ``("element", first, count, index)`` (one value shared by elements first ..
        first + count - 1) or ``("damping", 1)`` / ``("damping", 2)`` (Rayleigh's a0, a1).
    mode, damping : with ``model``
        The mode (from 0) and its linear damping, as :meth:`HarmonicBalance.backbone`'s.
    dof : int, optional, with ``model``
        The levels' amplitudes are the first harmonic's at this dof (``kind`` displacement,
        velocity or acceleration); without it, modal amplitudes times ``sensor``.
    backbone : {"epmc", "qsma"}, with ``model``
        The model's backbone: its nonlinear mode (EPMC), or its quasi-static modal analysis
        (``fricreg_fit_set_model_qsma``: the cheap route where QSMA holds, docs/
        identification.md; ``damping`` is then QSMA's own, φᵀCφ/(2ω_k), and ``dof`` refused).

    Returns
    -------
    FitResult

    Raises
    ------
    fricreg.InputError
        Bad input, fewer levels than free parameters, a parameter ended at its bound (the
        message names it), a level beyond the backbone's reach.
    fricreg.Error
        ``FRICREG_ESINGULAR``: the levels do not determine the parameters (the message names
        the combination); ``FRICREG_EWORK``: no start converged.
    """
    a = as_doubles(amplitude, "amplitude", ndim=1)
    f = as_doubles(freq_hz, "freq_hz", ndim=1)
    z = as_doubles(zeta, "zeta", ndim=1)
    if not a.shape == f.shape == z.shape:
        raise refused("amplitude, freq_hz, zeta: shapes %s, %s, %s differ"
                      % (a.shape, f.shape, z.shape))
    fit = _new_fit(sensor)
    status = lib.fricreg_fit_set_levels(fit, a.size, choice(_KINDS, kind, "kind"), pointer(a),
                                        pointer(f), pointer(z))
    _check(fit, status, "levels")
    if (sd_freq_hz is None) != (sd_zeta is None):
        raise refused("sd_freq_hz, sd_zeta: give both or neither")
    if sd_freq_hz is not None:
        sf = as_doubles(sd_freq_hz, "sd_freq_hz", ndim=1)
        sz = as_doubles(sd_zeta, "sd_zeta", ndim=1)
        if sf.shape != a.shape or sz.shape != a.shape:
            raise refused("sd_freq_hz, sd_zeta: shapes %s, %s; expected %s"
                          % (sf.shape, sz.shape, a.shape))
        _check(fit, lib.fricreg_fit_set_deviations(fit, a.size, pointer(sf), pointer(sz)),
               "deviations")
    names = None
    if model is not None:
        names = _set_model(fit, model, params, mode, damping, dof, backbone)
    elif params is not None or dof is not None:
        raise refused("params, dof: only with model (a HarmonicBalance)")
    free = _set_params(fit, x0, bounds, fixed, names)
    if starts is not None:
        _check(fit, lib.fricreg_fit_set_starts(fit, as_integer(starts, "starts")), "starts")
    _check(fit, lib.fricreg_fit_run(fit), "fit_backbone")
    result = _result(fit, a.size, free, names)
    result["_model"] = model  # the driver a curve marches, kept alive with the result
    return result


def _set_model(fit, model, params, mode, damping, dof, backbone):
    """An HB model's nonlinear mode (or QSMA) as the fit's model; the parameters'
    descriptions."""
    from .harmonic_balance import HarmonicBalance, _DAMPING, model_params
    if not isinstance(model, HarmonicBalance):
        raise refused("model: %r is not a fricreg.HarmonicBalance" % (model,))
    if params is None or len(params) == 0:
        raise refused("params: the model's parameters to fit are missing")
    rows = model_params(params)
    columns = [ffi.new("int[]", [r[0] for r in rows])] + [
        ffi.new("size_t[]", [r[j] for r in rows]) for j in (1, 2, 3)]
    if choice(_BACKBONES, backbone, "backbone"):
        _check(fit, lib.fricreg_fit_set_model_qsma(fit, model._hb, as_integer(mode, "mode"),
                                                    len(rows), *columns), "model")
    else:
        _check(fit, lib.fricreg_fit_set_model_hb(fit, model._hb, as_integer(mode, "mode"),
                                                  choice(_DAMPING, damping, "damping"),
                                                  len(rows), *columns), "model")
    if dof is not None:
        _check(fit, lib.fricreg_fit_set_sensor_dof(fit, model.ndof, model.harmonics,
                                                    as_integer(dof, "dof")), "dof")
    return [tuple(p) for p in params]


def _value(fit, which):
    out = ffi.new("double *")
    _check(fit, lib.fricreg_fit_get_value(fit, which, out), "fit_backbone")
    return out[0]


def _result(fit, n, free, names=None):
    names = names or FIT_PARAMS
    npar = len(names)
    x, lower, upper, sv = (np.empty(npar) for _ in range(4))
    cov, vectors = np.empty((npar, npar)), np.empty((npar, npar))
    rf, rz = np.empty(n), np.empty(n)
    _check(fit, lib.fricreg_fit_get_params(fit, npar, pointer(x)), "fit_backbone")
    _check(fit, lib.fricreg_fit_get_covariance(fit, npar, pointer(cov), pointer(lower),
                                               pointer(upper)), "fit_backbone")
    _check(fit, lib.fricreg_fit_get_identifiability(fit, npar, pointer(sv), pointer(vectors)),
           "fit_backbone")
    _check(fit, lib.fricreg_fit_get_residuals(fit, n, pointer(rf), pointer(rz)), "fit_backbone")
    q = ffi.new("double *")
    _check(fit, lib.fricreg_fit_get_quantile(fit, q), "fit_backbone")
    p = int(_value(fit, lib.FRICREG_FIT_NFREE))
    return FitResult(
        x=x, params=dict(zip(names, x.tolist())), cov=cov, lower=lower, upper=upper,
        free=free, sv=sv[:p].copy(), vectors=vectors[:p].copy(),
        residuals_freq=rf, residuals_zeta=rz, cost=_value(fit, lib.FRICREG_FIT_COST),
        residual_variance=_value(fit, lib.FRICREG_FIT_RESIDUAL_VARIANCE), quantile=q[0],
        condition=_value(fit, lib.FRICREG_FIT_CONDITION), success=True,
        message="converged from %d of the starts" % _value(fit, lib.FRICREG_FIT_STARTS_CONVERGED),
        nfev=int(_value(fit, lib.FRICREG_FIT_NFEV)), njev=int(_value(fit, lib.FRICREG_FIT_NJEV)),
        nit=int(_value(fit, lib.FRICREG_FIT_ITERATIONS)),
        starts_converged=int(_value(fit, lib.FRICREG_FIT_STARTS_CONVERGED)),
        best_start=int(_value(fit, lib.FRICREG_FIT_BEST_START)), _fit=fit)


def backbone(params, amplitude, *, kind="displacement", sensor=1.0, sensitivities=False):
    """The modal Iwan model's backbone at amplitudes of a kind (``fricreg_fit_eval``).

    Parameters
    ----------
    params : array_like, shape (6,), or dict
        The parameters, in the order of :data:`FIT_PARAMS` or by name (all six).
    amplitude : array_like, shape (n,)
        Amplitudes at the sensor, > 0, of ``kind`` (as :func:`fit_backbone`).
    kind, sensor
        As :func:`fit_backbone`; default displacement at s = 1 (modal amplitudes).
    sensitivities : bool
        Also return the exact derivatives in the parameters, the amplitude held.

    Returns
    -------
    freq_hz, zeta, modal : ndarray, shape (n,)
        The natural frequencies (Hz), damping ratios and modal amplitudes.
    dfreq_dp, dzeta_dp : ndarray, shape (n, 6)
        Only with ``sensitivities``: d/dp in the order of :data:`FIT_PARAMS`.
    """
    if isinstance(params, dict):
        names = _by_name(params, "params")
        missing = [name for name in FIT_PARAMS if name not in names]
        if missing:
            raise refused("params: missing %s" % ", ".join(missing))
        params = [names[name] for name in FIT_PARAMS]
    p = as_doubles(params, "params", ndim=1)
    if p.shape != (_NP,):
        raise refused("params: shape %s; expected (%d,)" % (p.shape, _NP))
    a = as_doubles(amplitude, "amplitude", ndim=1)
    fit = _new_fit(sensor)
    f, z, modal = np.empty_like(a), np.empty_like(a), np.empty_like(a)
    df, dz = np.empty((a.size, _NP)), np.empty((a.size, _NP))
    status = lib.fricreg_fit_eval(fit, pointer(p), choice(_KINDS, kind, "kind"), a.size,
                                  pointer(a), pointer(f), pointer(z), pointer(modal),
                                  pointer(df), pointer(dz))
    _check(fit, status, "backbone")
    return (f, z, modal, df, dz) if sensitivities else (f, z, modal)
