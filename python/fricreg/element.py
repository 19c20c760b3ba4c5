# SPDX-License-Identifier: GPL-3.0-or-later
"""Friction elements on numpy arrays (``fricreg_element.h``): Jenkins, Iwan, 3-D contact with
lift-off and the linear spring, as pure functions of the parameters, the old state and the
displacement, many points in one C call (``fricreg_element_eval_batch``).

Each slider is a spring k in series with a Coulomb slider of bound b, returned from its old
position w (Simo & Hughes, *Computational Inelasticity*, 1998, Ch. 1 and 3): stick where
k |u_t - w| <= b (f = k (u_t - w)), else slip at |f| = b and w' = u_t - f/k. The header's
table lists every type's parameters and state.
"""

import numpy as np

from ._record import record
from ._fricreg import ffi, lib
from ._arrays import as_doubles, as_integer, as_scalar, pointer
from .errors import raise_status, refused
from ._settings import fixed

__all__ = ["ELEMENT_TYPES", "Element", "ElementResult", "segalman"]

#: The element types' names, in the order of their codes 1, 2, ... (``fricreg_element_at``).
ELEMENT_TYPES = tuple(
    ffi.string(lib.fricreg_element_name(lib.fricreg_element_at(i))).decode()
    for i in range(lib.fricreg_element_count())
)

ElementResult = record("ElementResult", "f dfdu dfdp state", """\
The result of :meth:`Element.eval`.

f : ndarray, shape (npoints, dim), or (dim,) for one point
    The element's force (the normal force N last for a normal type).
dfdu : ndarray, shape (npoints, dim, dim), or None
    The consistent tangent, ``dfdu[i, a, c]`` = df_a/du_c at point i.
dfdp : ndarray, shape (npoints, dim, nparams), or None
    The force's derivative in each parameter, ``dfdp[i, a, j]`` = df_a/dp_j.
state : ndarray, shape (npoints, nstate), or (nstate,) for one point
    The state at the end of the increment (the input state is never modified).
""")


def _type_for(name, nparams):
    """The C type called name whose parameter count is nparams (a family's slider count
    follows from it); ValueError naming the types or the counts otherwise."""
    if not isinstance(name, str):
        raise refused("name: %r is not a string (one of %s)" % (name, ", ".join(ELEMENT_TYPES)))
    first = lib.fricreg_element_lookup(name.encode())
    if first == ffi.NULL:
        raise refused("name: %r is not an element type (one of %s)"
                      % (name, ", ".join(ELEMENT_TYPES)))
    one = lib.fricreg_element_nparams(first)
    second = lib.fricreg_element_sliders(first, 2)
    if second == ffi.NULL:  # not a family: one count only
        if nparams != one:
            raise refused("params: %s takes %d parameters, not %d" % (name, one, nparams))
        return first
    per_slider = lib.fricreg_element_nparams(second) - one
    ns, rest = divmod(nparams - one, per_slider)
    typ = lib.fricreg_element_sliders(first, ns + 1) if rest == 0 and nparams >= one else ffi.NULL
    if typ == ffi.NULL:
        raise refused("params: %s takes %d + %d ns parameters for ns = 1..%d sliders, not %d"
                      % (name, one - per_slider, per_slider,
                         lib.FRICREG_ELEMENT_MAX_SLIDERS, nparams))
    return typ


class Element:
    """One friction element type with its parameters, evaluated at many points at once; its
    attributes are read-only, fixed at construction.

    Parameters
    ----------
    name : str
        One of :data:`ELEMENT_TYPES`: ``"jenkins"``, ``"jenkins_2d"``, ``"jenkins_3d"``,
        ``"jenkins_normal"``, ``"contact_3d"``, ``"iwan"``, ``"iwan_2d"``, ``"iwan_3d"``,
        ``"iwan_normal"``, ``"spring"``.
    params : array_like of float, shape (nparams,)
        The parameters in the order of ``fricreg_element.h``'s table, in the caller's units:
        jenkins* ``[kt, mun]``; jenkins_normal and contact_3d ``[kt, mu, kn, n0, gap]``;
        iwan, iwan_2d, iwan_3d ``[k_1..k_ns, phi_1..phi_ns]``; iwan_normal
        ``[k_1..k_ns, mu_1..mu_ns, kn, n0, gap]``; spring ``[k]``. An Iwan type's slider
        count ns follows from the length.

    Attributes
    ----------
    name : str
    dim : int
        Components of u and f (1, 2 or 3); a normal type's last is the normal one.
    nparams, nstate, nsliders : int
    params : ndarray, shape (nparams,)
        A read-only copy of the parameters.

    Raises
    ------
    fricreg.InputError
        (a ``ValueError``) ``name`` names no type, or ``params`` has a length no member of the
        type takes. Refused by the library: a parameter is NaN, infinite or out of its range (kt
        > 0, mun >= 0, ...); the message is ``fricreg_element_explain``'s.
    """

    # every attribute: assigning a misspelt setting raises instead of adding one
    __slots__ = ("_type", "_name", "_dim", "_nparams", "_nstate", "_nsliders", "_params",
                 "__weakref__")

    def __init__(self, name, params):
        params = as_doubles(params, "params", ndim=1)
        self._type = _type_for(name, params.size)
        self._name = name
        self._dim = lib.fricreg_element_dim(self._type)
        self._nparams = lib.fricreg_element_nparams(self._type)
        self._nstate = lib.fricreg_element_nstate(self._type)
        self._nsliders = lib.fricreg_element_nsliders(self._type)
        self._raise_if_refused(params, None, None, "Element")
        params = params.copy()
        params.setflags(write=False)
        self._params = params

    name = fixed("name", "str: the type's name, one of :data:`ELEMENT_TYPES`.")
    dim = fixed("dim", "int: components of u and f (1, 2 or 3).")
    nparams = fixed("nparams", "int: the parameters of one element.")
    nstate = fixed("nstate", "int: the state's entries of one element.")
    nsliders = fixed("nsliders", "int: the sliders of one element (an Iwan type's ns).")
    params = fixed("params", "ndarray, shape (nparams,): the parameters, read-only (an "
                   "element of other parameters is a new Element).")

    def __repr__(self):
        return "Element(%r, %r)" % (self.name, self.params.tolist())

    def _raise_if_refused(self, params, state, u, where, point=None):
        """Raise with fricreg_element_explain's message where these inputs fail."""
        msg = ffi.new("char[]", 256)
        status = lib.fricreg_element_explain(
            self._type, pointer(params), pointer(state) if state is not None else ffi.NULL,
            pointer(u) if u is not None else ffi.NULL, msg, 256)
        if status != lib.FRICREG_OK:
            text = ffi.string(msg).decode()
            raise_status(status, where, text if point is None else "point %d: %s" % (point, text))

    def init(self, npoints=None):
        """The state of elements at rest, every slider at w = 0.

        Parameters
        ----------
        npoints : int or None
            The number of points; None for one.

        Returns
        -------
        state : ndarray of float64, shape (npoints, nstate), or (nstate,) for None

        Raises
        ------
        fricreg.InputError
            (a ``ValueError``) npoints is not an integer, or is negative.
        """
        shape = (self.nstate,) if npoints is None else (as_integer(npoints, "npoints"), self.nstate)
        if npoints is not None and shape[0] < 0:
            raise refused("npoints: %d is negative" % npoints)
        return np.zeros(shape)

    def eval(self, u, state, params=None, tangent=True, derivatives=False):
        """The force, tangents and new state at the displacements u from the old state: the
        return mapping of ``fricreg_element.h`` at every point, in one C call.

        Parameters
        ----------
        u : array_like of float, shape (npoints, dim), or (dim,) for one point
            The relative displacement at the end of the increment (a normal type's last
            component the normal displacement g, positive pressing).
        state : array_like of float, shape (npoints, nstate), or (nstate,) for one point
            The state at the start of the increment (from :meth:`init` or an earlier eval).
        params : array_like of float, shape (nparams,) or (npoints, nparams), optional
            Parameters shared by every point or one row per point; the element's own when
            omitted.
        tangent : bool
            Compute ``dfdu`` (the consistent tangent).
        derivatives : bool
            Compute ``dfdp`` (the derivatives in the parameters).

        Returns
        -------
        ElementResult
            ``(f, dfdu, dfdp, state)``, shapes as its documentation says; each point's
            numbers equal ``fricreg_element_eval``'s bit for bit.

        Raises
        ------
        fricreg.InputError
            (a ``ValueError``) An argument's shape or dtype does not fit. Refused by the
            library: a point's u, state or parameter is NaN, infinite or out of its range: the
            message names the point and the value (``fricreg_element_explain``). Nothing is
            computed then.
        """
        u = as_doubles(u, "u")
        single = u.ndim == 1
        u2 = u.reshape(1, -1) if single else u
        if u2.ndim != 2 or u2.shape[1] != self.dim:
            raise refused("u: shape %s; %s expects (npoints, %d) or (%d,)"
                          % (u.shape, self.name, self.dim, self.dim))
        npoints = u2.shape[0]
        state = as_doubles(state, "state")
        if state.shape != ((self.nstate,) if single else (npoints, self.nstate)):
            raise refused("state: shape %s; expected %s" % (
                state.shape, (self.nstate,) if single else (npoints, self.nstate)))
        params, stride = self._params_for(params, npoints, single)
        f = np.empty((npoints, self.dim))
        dfdu = np.empty((npoints, self.dim, self.dim)) if tangent else None
        dfdp = np.empty((npoints, self.dim, self.nparams)) if derivatives else None
        state_out = np.empty((npoints, self.nstate))
        # a type without state (spring): the C call wants non-NULL state arrays and reads
        # none of them, so one double stands in
        state_in = state if state.size else np.zeros(1)
        state_out_c = state_out if state_out.size else np.zeros(1)
        bad = ffi.new("size_t *")
        status = lib.fricreg_element_eval_batch(
            self._type, npoints, pointer(params), stride, pointer(state_in), pointer(u2),
            pointer(f), pointer(dfdu) if tangent else ffi.NULL,
            pointer(dfdp) if derivatives else ffi.NULL, pointer(state_out_c), bad)
        if status != lib.FRICREG_OK:
            i = bad[0]
            p_i = params if stride == 0 else params[i]
            s_i = state_in.reshape(npoints, -1)[i] if state.size else state_in
            self._raise_if_refused(p_i, s_i, u2[i], "Element.eval", None if single else i)
            raise_status(status, "Element.eval")
        if single:
            return ElementResult(f[0], dfdu[0] if tangent else None,
                                 dfdp[0] if derivatives else None, state_out[0])
        return ElementResult(f, dfdu, dfdp, state_out)

    def _params_for(self, params, npoints, single):
        """The parameters of a call and their stride (0: shared)."""
        if params is None:
            return self.params, 0
        params = as_doubles(params, "params")
        if params.shape == (self.nparams,):
            return params, 0
        if not single and params.shape == (npoints, self.nparams):
            return params, self.nparams
        raise refused("params: shape %s; expected (%d,) or (npoints, %d) = (%d, %d)"
                      % (params.shape, self.nparams, self.nparams, npoints, self.nparams))


def segalman(ns, fs, kt, chi, beta, resolution):
    """The sliders of an Iwan element from Segalman's four-parameter model.

    D. J. Segalman, *A four-parameter Iwan model for lap-type joints*, J. Appl. Mech. 72 (2005)
    752-760, discretized by ``fricreg_element_segalman`` (the rule of
    ``fricreg_iwan_set_segalman``, bit for bit).

    Parameters
    ----------
    ns : int
        Sliders, 1..1024 (``FRICREG_ELEMENT_MAX_SLIDERS``).
    fs : float
        Macroslip force (> 0, force units).
    kt : float
        Joint stiffness (> 0, force per length).
    chi : float
        Exponent of the slip forces' density, -1 < chi <= 1.
    beta : float
        Weight of the density's delta at phi_max (>= 0; 0 when ns = 1).
    resolution : float
        The smallest breakpoint as a fraction of phi_max, in (0, 1).

    Returns
    -------
    params : ndarray of float64, shape (2 ns,)
        ``[k_1..k_ns, phi_1..phi_ns]``: the parameters of ``Element("iwan", params)`` (or of
        iwan_2d and iwan_3d).

    Raises
    ------
    fricreg.InputError
        (a ``ValueError``) a parameter out of the ranges above, NaN or infinite.
    """
    ns = as_integer(ns, "ns")
    if ns <= 0:
        raise_status(lib.FRICREG_EINVAL, "segalman", "ns = %d must be >= 1" % ns)
    fs, kt, chi = as_scalar(fs, "fs"), as_scalar(kt, "kt"), as_scalar(chi, "chi")
    beta, resolution = as_scalar(beta, "beta"), as_scalar(resolution, "resolution")
    params = np.empty(2 * ns)
    status = lib.fricreg_element_segalman(ns, fs, kt, chi, beta, resolution,
                                          pointer(params[:ns]), pointer(params[ns:]))
    if status != lib.FRICREG_OK:
        raise_status(status, "segalman", "fs = %g, kt = %g, chi = %g, beta = %g, resolution = %g,"
                     " ns = %d: out of range (fricreg_element_segalman)"
                     % (fs, kt, chi, beta, resolution, ns))
    return params
