# SPDX-License-Identifier: GPL-3.0-or-later
"""The friction laws of the paper on numpy arrays (``fricreg.h``'s ``fricreg_law_eval_batch``).

D. D. Quinn, *A New Regularization of Coulomb Friction*, J. Vib. Acoust. 126 (2004) 391-397:
Coulomb (1), force balance at rest (2), Karnopp, velocity-limited (3), tanh and Quinn (4).
"""
import numpy as np

from ._fricreg import ffi, lib
from ._arrays import as_doubles, as_scalar, pointer
from .errors import raise_status, refused

__all__ = ["LAWS", "law_eval"]

#: The laws' names, in the order of their codes 1, 2, ... (``enum fricreg_law``).
LAWS = tuple(
    ffi.string(lib.fricreg_law_name(code)).decode()
    for code in range(1, 64) if lib.fricreg_law_name(code) != ffi.NULL
)


def _law_code(law):
    """The code of a law given by name or code; ValueError naming the laws otherwise."""
    if isinstance(law, str):
        code = lib.fricreg_law_from_name(law.encode())
    elif isinstance(law, (int, np.integer)) and 1 <= law <= len(LAWS):
        code = int(law)
    else:
        code = 0
    if code == 0:
        raise refused("law: %r is not a law (one of %s, or its code 1..%d)"
                      % (law, ", ".join(LAWS), len(LAWS)))
    return code


def law_eval(law, v, f_eq, mun, eps):
    """The friction force of one law at many contacts.

    Parameters
    ----------
    law : str or int
        One of :data:`LAWS` (``"coulomb"``, ``"force-balance"``, ``"karnopp"``,
        ``"velocity-limited"``, ``"tanh"``, ``"quinn"``) or its code 1..6.
    v : array_like of float
        Relative contact velocities (velocity units), any shape.
    f_eq : array_like of float or None
        Equilibrium forces (force units): the force that keeps the contact at rest. ``None``
        for the laws that do not read it (coulomb, velocity-limited, tanh).
    mun : array_like of float
        Friction bounds mu N >= 0 (force units).
    eps : float
        The regularization, >= DBL_MIN (velocity units); validated though ignored by
        coulomb and force-balance.

    ``v``, ``f_eq`` and ``mun`` broadcast against one another.

    Returns
    -------
    f : ndarray of float64
        The friction forces, of the broadcast shape, ``|f| <= mun``.

    Raises
    ------
    fricreg.InputError
        (a ``ValueError``) ``law`` names no law, or an argument is not real numbers or does not
        broadcast. Refused by the library: ``f_eq`` is None for a law that needs it, a bound is
        negative, ``eps`` is below DBL_MIN, or an input is NaN or infinite.

    Notes
    -----
    Equations (1)-(4) of Quinn (2004) and its Sec. 2 for Karnopp's and the tanh law; Quinn's
    law (4): xi = (eps/2) sat(f_eq/mun); f = -(2 mun/eps)(v - xi) where |v - xi| < eps/2,
    else -mun sgn(v - xi). Calls ``fricreg_law_eval_batch`` once.
    """
    code = _law_code(law)
    eps = as_scalar(eps, "eps")
    arrays = [as_doubles(v, "v"), as_doubles(mun, "mun")]
    if f_eq is not None:
        arrays.append(as_doubles(f_eq, "f_eq"))
    try:
        broadcast = np.broadcast_arrays(*arrays)
    except ValueError as exc:
        raise refused("v, f_eq and mun do not broadcast: %s" % exc) from None
    v_b, mun_b = (np.ascontiguousarray(a) for a in broadcast[:2])
    f_eq_b = np.ascontiguousarray(broadcast[2]) if f_eq is not None else None
    f = np.empty(v_b.shape)
    status = lib.fricreg_law_eval_batch(
        code, float(eps), v_b.size, pointer(v_b),
        pointer(f_eq_b) if f_eq_b is not None else ffi.NULL, pointer(mun_b), pointer(f))
    if status != lib.FRICREG_OK:
        raise_status(status, "law_eval", _why(status, code, eps, v_b, f_eq_b, mun_b))
    return f


def _why(status, code, eps, v, f_eq, mun):
    """Which input fricreg_law_eval_batch refused (it returns the status alone)."""
    if status == lib.FRICREG_ENULL:
        return "the law %s needs f_eq" % LAWS[code - 1]
    if status == lib.FRICREG_EINVAL:
        if not eps >= np.finfo(float).tiny:
            return "eps = %g must be >= DBL_MIN (%g)" % (eps, np.finfo(float).tiny)
        bad = np.flatnonzero(mun < 0)
        if bad.size:
            return "mun[%d] = %g must be >= 0" % (bad[0], mun.flat[bad[0]])
    if status == lib.FRICREG_ENONFINITE:
        for name, array in (("v", v), ("f_eq", f_eq), ("mun", mun)):
            if array is not None and not np.all(np.isfinite(array)):
                bad = np.flatnonzero(~np.isfinite(array))[0]
                return "%s[%d] = %g is not finite" % (name, bad, array.flat[bad])
        return "eps = %g is not finite" % eps
    return ""
