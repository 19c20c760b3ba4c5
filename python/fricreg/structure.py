# SPDX-License-Identifier: GPL-3.0-or-later
"""A linear structure with friction contacts and joint elements, stepped in time
(``fricreg_structure.h``)::

    M u'' + C u' + K u = p g(t) - M r a_g(t) + J^T f - J_e^T f_e,      zdot = J u'

f the contacts' friction forces from a law of Quinn's paper (D. D. Quinn, *A New
Regularization of Coulomb Friction*, J. Vib. Acoust. 126 (2004) 391-397; law (4) by default),
f_e the joint elements' (``fricreg_element.h``: Jenkins, Iwan, 3-D contact with lift-off),
stepped by average-acceleration Newmark, HHT-alpha (Hilber, Hughes and Taylor 1977) or central
differences, or by one of GSL's steppers; the energy balance, each contact's dissipation, the
error estimates against eps -> 0 and the library's warnings come with every run
(docs/structural.md).
"""
import warnings

import numpy as np

from . import _structure_result as structure_result
from ._fricreg import ffi, lib
from ._arrays import as_doubles, as_scalar, choice, pointer
from .element import Element, _type_for
from .errors import AccuracyWarning, Error, interrupted, raise_status, refused
from ._settings import assigned, fixed
from .laws import _law_code
from ._matrices import MatrixArgs, is_sparse
from ._structure_result import ErrorEstimate, EstimateCompanions, StructureResult

__all__ = ["INTEGRATORS", "Structure", "StructureResult", "ErrorEstimate", "EstimateCompanions"]

_SCHEMES = ("newmark", "hht", "central")
#: The integrators of :meth:`Structure.run`: the structure's own schemes, then GSL's steppers
#: (``fricreg_integrator_name``, but fricreg_sim's central differences).
INTEGRATORS = _SCHEMES + tuple(
    ffi.string(lib.fricreg_integrator_name(k)).decode()
    for k in range(1, 64) if lib.fricreg_integrator_name(k) != ffi.NULL
    and not ffi.string(lib.fricreg_integrator_name(k)).startswith(b"central"))
_ESTIMATES = {"off": lib.FRICREG_ESTIMATE_OFF, "on": lib.FRICREG_ESTIMATE_TWO_COMPANIONS,
              "one": lib.FRICREG_ESTIMATE_ONE_COMPANION}
_COMPANIONS = {"auto": lib.FRICREG_COMPANIONS_AUTO, "finer": lib.FRICREG_COMPANIONS_FINER,
               "coarser": lib.FRICREG_COMPANIONS_COARSER}
_SOLVERS = {"auto": lib.FRICREG_CONTACT_SOLVER_AUTO, "dense": lib.FRICREG_CONTACT_SOLVER_DENSE,
            "sparse": lib.FRICREG_CONTACT_SOLVER_SPARSE}


def _vector(a, name, n):
    """a as float64 of shape (n,); ValueError naming it otherwise."""
    a = as_doubles(a, name, ndim=1)
    if a.shape != (n,):
        raise refused("%s: shape %s; expected (%d,)" % (name, a.shape, n))
    return a


def _shape(a):
    """The shape of an array_like or a scipy.sparse matrix."""
    return a.shape if is_sparse(a) else np.shape(a)


def _record(record, name):
    """(t0, dt_rec, samples) of a ground or load record, checked."""
    try:
        t0, dt_rec, samples = record
    except (TypeError, ValueError):
        raise refused("%s: expected (t0, dt_rec, samples)" % name) from None
    samples = as_doubles(samples, name + " samples", ndim=1)
    if samples.size < 2:
        raise refused("%s: %d samples; a record needs at least 2" % (name, samples.size))
    return float(t0), float(dt_rec), samples


class Structure:
    """A linear structure with friction contacts and joint elements, ``fricreg_structure``.

    Parameters
    ----------
    M : array_like or scipy.sparse matrix, shape (ndof, ndof)
        Mass matrix (kg), symmetric positive definite. Dense arrays are row-major
        (``M[i, j]``); a scipy.sparse matrix stays sparse (scipy is imported only then).
    K : array_like or scipy.sparse matrix, shape (ndof, ndof)
        Stiffness matrix (N/m), symmetric; may be singular (rigid-body modes).
    damping : array_like or scipy.sparse matrix, shape (ndof, ndof), optional
        Damping matrix C (N s/m), symmetric. Not with ``rayleigh``.
    rayleigh : (float, float), optional
        Rayleigh damping C = a0 M + a1 K (a0 in 1/s, a1 in s, both >= 0).
    J : array_like or scipy.sparse matrix, shape (m, ndof), optional
        The friction contacts: contact i slides with zdot_i = (J u')_i (row i nonzero). With
        ``mun``; without both the structure has no contacts (m = 0).
    mun : array_like, shape (m,), optional
        The contacts' bounds mu N_i >= 0 (N).
    law : str or int, optional
        The contacts' friction law, one of :data:`fricreg.LAWS`; default ``"quinn"`` (4).
    eps : float, optional
        The law's regularization (m/s), > 0; default 1 % of the ground record's peak velocity
        max |integral of a_g dt|, or 1e-3 without a record (``fricreg-sim structure``'s).
    influence : array_like, shape (ndof,), optional
        The ground motion's influence vector r; default 1 at every dof.
    ground_accel : (t0, dt_rec, samples), optional
        Ground acceleration a_g (m/s^2): samples of shape (n,), n >= 2, at t0 + k dt_rec (s),
        linear between them and 0 outside.
    load : array_like, shape (ndof,), optional
        The load pattern p (N) of the external load p g(t).
    load_history : (t0, dt_rec, samples), optional
        Its time function g (dimensionless), as ``ground_accel``; default g = 1 (a constant
        load).
    elements : sequence of (element, J) or (element, J, params), optional
        Joint element sets, each ``fricreg_structure_add_elements``'s: ``element`` a
        :class:`fricreg.Element` or a type name of :data:`fricreg.ELEMENT_TYPES`; ``J`` of shape
        (me dim, ndof), dense or sparse, element i's dim rows consecutive (tangential, then
        normal); ``params`` of shape (me, nparams) or (nparams,) shared, in the type's layout
        (default: the Element's own parameters, for every element).
    u0, v0 : array_like, shape (ndof,), optional
        The initial displacements (m) and velocities (m/s) at t = 0; default 0.
    newton_tol : float, optional
        Newton's relative tolerance, 0 < tol < 1 (default 1e-10).
    newton_max_iter : int, optional
        Newton's iterations per step, 1 ... 1000 (default 50).
    contact_solver : {"auto", "dense", "sparse"}
        Newmark's and HHT's near-stick block solver (``fricreg_structure_set_contact_solver``).
    error_estimate : {"off", "on", "one"}
        The error estimate against eps -> 0: two companion runs at (eps/2, dt/2) and
        (eps/4, dt/4) (``"on"``, about 7x a run's cost), 1.6's one companion (``"one"``), or
        none (default).
    error_companions : {"auto", "finer", "coarser"}
        Where the companions sit: ``"auto"`` (default) screens with the coarser ones and,
        where their estimate would warn or fails, runs the finer ones from the start and
        reports theirs (``fricreg_structure_set_error_companions``; the result's
        ``estimate_companions`` says which gave it); ``"finer"`` at (eps/2, dt/2),
        (eps/4, dt/4), about 7x a run's cost (1.8's default); ``"coarser"`` at (2 eps, 2 dt),
        (4 eps, 4 dt), about 0.7x, warning on many runs within the tolerance.
    answer_rtol : float, optional
        The relative error above which the estimate raises the warning ``error_estimate``
        (default 1e-2): half the estimate, its central value, is compared with it.

    Attributes
    ----------
    ndof, ncontacts, nelements : int
        Read-only, fixed at construction.
    law : str or None
        The contacts' law (None without contacts); read-only, set by :meth:`set_law`.
    eps : float or None
        The regularization in force (m/s); read-only, set by :meth:`set_law`.
    mun : ndarray of float64, shape (ncontacts,)
        A copy of the contacts' bounds (N); read-only, set by :meth:`set_bounds`.

    Raises
    ------
    fricreg.InputError
        (a ``ValueError``) An argument's shape, dtype or choice does not fit; the message names
        it. Refused by the library: the library refused an argument: not symmetric, M not
        positive definite, a zero row of J, a negative bound, a parameter out of range, NaN or
        infinite; the message names the argument and the library's reason.
    fricreg.OutOfMemoryError

    Notes
    -----
    The model is copied into the C object (``fricreg_structure_create`` and its setters); the
    arrays passed are never modified. Without contacts the library's structure holds one
    contact of bound 0 on dof 0, whose force is exactly 0 (``fricreg_structure_create``), as
    ``fricreg-sim structure`` without ``--contacts``; it is not shown. One structure must not
    be used from two threads at once; separate ones may run side by side (cffi releases the
    GIL during the C calls; a run's observer, in C, takes it back once per 20 ms of wall time,
    for Ctrl-C).
    """

    # every attribute: assigning a misspelt setting raises instead of adding one
    __slots__ = ("_s", "_ndof", "_ncontacts", "_mun", "_sets", "_nelements", "_law", "_eps",
                 "_scheme", "_warned", "__weakref__")

    def __init__(self, M, K, *, damping=None, rayleigh=None, J=None, mun=None, law=None,
                 eps=None, influence=None, ground_accel=None, load=None, load_history=None,
                 elements=(), u0=None, v0=None, newton_tol=None, newton_max_iter=None,
                 contact_solver="auto", error_estimate="off", error_companions="auto",
                 answer_rtol=None):
        shape = _shape(M)
        if len(shape) != 2 or shape[0] != shape[1] or shape[0] < 1:
            raise refused("M: shape %s; expected (ndof, ndof), ndof >= 1" % (shape,))
        n = self._ndof = shape[0]
        if (J is None) != (mun is None):
            raise refused("%s: J and mun come together (neither: no friction contacts)"
                          % ("mun" if mun is None else "J"))
        if J is None and (law is not None or eps is not None):
            raise refused("%s: the contacts' friction law: without J there is none"
                          % ("eps" if eps is not None else "law"))
        if damping is not None and rayleigh is not None:
            raise refused("rayleigh: give damping or rayleigh, not both")
        m = self._ncontacts = 0 if J is None else (_shape(J) + (0,))[0]
        out = ffi.new("fricreg_structure **")
        self._check(lib.fricreg_structure_create(n, max(m, 1), out), "ndof")
        self._s = ffi.gc(out[0], lib.fricreg_structure_free)
        self._set_matrix(M, "M", lib.FRICREG_MASS, (n, n))
        self._set_matrix(K, "K", lib.FRICREG_STIFFNESS, (n, n))
        if damping is not None:
            self._set_matrix(damping, "damping", lib.FRICREG_DAMPING, (n, n))
        if rayleigh is not None:
            a0, a1 = _vector(rayleigh, "rayleigh", 2)
            self._check(lib.fricreg_structure_set_rayleigh(self._s, a0, a1), "rayleigh")
        self._set_contacts(J, mun, m)
        if influence is not None:
            r = _vector(influence, "influence", n)
            self._check(lib.fricreg_structure_set_influence(self._s, n, pointer(r)), "influence")
        if ground_accel is not None:
            t0, dt_rec, ag = _record(ground_accel, "ground_accel")
            self._check(lib.fricreg_structure_set_ground_accel(self._s, t0, dt_rec, ag.size,
                                                               pointer(ag)), "ground_accel")
        self._set_load(load, load_history)
        self._sets = []
        for k, element_set in enumerate(elements):
            self._add_elements(element_set, "elements[%d]" % k)
        self._nelements = sum(me for me, _ in self._sets)
        self._law = self._eps = None
        if m:
            self.set_law("quinn" if law is None else law, self._default_eps() if eps is None
                         else eps)
        if u0 is not None or v0 is not None:
            self.reset(u0, v0)
        if newton_tol is not None or newton_max_iter is not None:
            self._check(lib.fricreg_structure_set_newton(
                self._s, 1e-10 if newton_tol is None else float(newton_tol),
                50 if newton_max_iter is None else int(newton_max_iter)), "newton_tol")
        self._check(lib.fricreg_structure_set_contact_solver(
            self._s, choice(_SOLVERS, contact_solver, "contact_solver")), "contact_solver")
        self._check(lib.fricreg_structure_set_error_estimate(
            self._s, choice(_ESTIMATES, error_estimate, "error_estimate")), "error_estimate")
        self._check(lib.fricreg_structure_set_error_companions(
            self._s, choice(_COMPANIONS, error_companions, "error_companions")),
            "error_companions")
        if answer_rtol is not None:
            self._check(lib.fricreg_structure_set_answer_rtol(self._s, float(answer_rtol)),
                        "answer_rtol")
        self._scheme = ("newmark",)
        self._warned = set()

    def __repr__(self):
        return "Structure(ndof=%d, ncontacts=%d, nelements=%d, t=%r)" % (
            self.ndof, self.ncontacts, self.nelements, self.t)

    # ---- set-up ------------------------------------------------------------------------------

    def _check(self, status, argument, where="Structure"):
        """Raise a nonzero status, the message naming the argument and the library's reason."""
        if status != lib.FRICREG_OK:
            s = getattr(self, "_s", ffi.NULL)
            detail = ffi.string(lib.fricreg_structure_errmsg(s)).decode() if s != ffi.NULL else ""
            raise_status(status, where, "%s: %s" % (argument, detail) if argument else detail)

    def _set_matrix(self, a, name, which, shape):
        """M, K, C or J (which: enum fricreg_model_matrix), dense or sparse, as it is."""
        args = MatrixArgs(a, name)
        if args.shape != shape:
            raise refused("%s: shape %s; expected %s as M's" % (name, args.shape, shape))
        self._check(lib.fricreg_structure_set_matrix(self._s, which, shape[0], shape[1],
                                                     args.format, args.ptr, args.ind,
                                                     args.values), name)

    def _set_contacts(self, J, mun, m):
        """J and mun, or the library's one contact of bound 0 on dof 0 (no contacts), as
        fricreg-sim structure without --contacts."""
        self._mun = np.zeros(0)
        if m == 0:
            if J is not None:
                _vector(mun, "mun", 0)
            self._check(lib.fricreg_structure_set_matrix(
                self._s, lib.FRICREG_CONTACTS, 1, self.ndof, lib.FRICREG_MATRIX_CSR,
                ffi.new("int64_t[]", [0, 1]), ffi.new("int64_t[]", [0]),
                ffi.new("double[]", [1.0])), "J")
            self._check(lib.fricreg_structure_set_bounds(self._s, 1, ffi.new("double[]", [0.0])),
                        "mun")
            return
        self._set_matrix(J, "J", lib.FRICREG_CONTACTS, (m, self.ndof))
        self.set_bounds(mun)

    def _set_load(self, load, load_history):
        if load is None:
            if load_history is not None:
                raise refused("load_history: the time function of load: give both")
            return
        p = _vector(load, "load", self.ndof)
        t0, dt_rec, g = (0.0, 0.0, None) if load_history is None else \
            _record(load_history, "load_history")
        self._check(lib.fricreg_structure_set_load(
            self._s, self.ndof, pointer(p), t0, dt_rec, 0 if g is None else g.size,
            ffi.NULL if g is None else pointer(g)),
            "load" if load_history is None else "load_history")

    def _add_elements(self, element_set, name):
        """One element set, fricreg_structure_add_elements."""
        if not isinstance(element_set, (tuple, list)) or len(element_set) not in (2, 3):
            raise refused("%s: expected (element, J) or (element, J, params)" % name)
        element, J = element_set[:2]
        params = element_set[2] if len(element_set) == 3 else None
        if isinstance(element, Element):
            type_name, own = element.name, element.params
        elif isinstance(element, str):
            type_name, own = element, None
        else:
            raise refused("%s: %r is neither an Element nor a type name" % (name, element))
        if params is None and own is None:
            raise refused("%s: the parameters of %s elements are missing" % (name, type_name))
        params = as_doubles(own if params is None else params, name + " params")
        if params.ndim not in (1, 2):
            raise refused("%s params: shape %s; expected (me, nparams) or (nparams,)"
                          % (name, params.shape))
        try:
            typ = _type_for(type_name, params.shape[-1])
        except ValueError as exc:
            raise refused("%s: %s" % (name, exc)) from None
        dim = lib.fricreg_element_dim(typ)
        J = as_doubles(J.toarray() if is_sparse(J) else J, name + " J", ndim=2)
        if J.shape[0] == 0 or J.shape[0] % dim or J.shape[1] != self.ndof:
            raise refused("%s J: shape %s; expected (me * %d, %d), %s's %d rows per element"
                          % (name, J.shape, dim, self.ndof, type_name, dim))
        me = J.shape[0] // dim
        if params.ndim == 1:
            params = np.tile(params, (me, 1))
        if params.shape[0] != me:
            raise refused("%s params: shape %s; expected (%d, %d) or (%d,)" % (
                name, params.shape, me, params.shape[1], params.shape[1]))
        self._check(lib.fricreg_structure_add_elements(self._s, typ, me, self.ndof, pointer(J),
                                                       pointer(params)), name)
        self._sets.append((me, dim))

    def _default_eps(self):
        """fricreg-sim's eps: 1 % of the ground record's peak velocity, or 1e-3."""
        pgv = ffi.new("double *")
        lib.fricreg_structure_get_value(self._s, lib.FRICREG_SVALUE_GROUND_PGV, pgv)
        return 0.01 * pgv[0] if pgv[0] > 0.0 else 1e-3

    # ---- settings: set_* methods, read-only properties (docs/python.md, "Settings") ------

    ndof = fixed("ndof", "int: the degrees of freedom, fixed at construction.")
    ncontacts = fixed("ncontacts", "int: the friction contacts (J's rows, 0 without J), "
                      "fixed at construction.")
    nelements = fixed("nelements", "int: the joint elements of every set, fixed at "
                      "construction.")

    def _has_contacts(self, argument):
        """Refuse a contacts' setting of a structure built without J."""
        if not self.ncontacts:
            raise refused("%s: the structure has no friction contacts (it was built without J "
                          "and mun)" % argument)

    def set_law(self, law, eps=None):
        """Select the contacts' friction law and its regularization
        (``fricreg_structure_set_law``), between runs: the next step starts from the
        equilibrium acceleration under the new law (an error estimate's companions follow).

        Parameters
        ----------
        law : str or int
            One of :data:`fricreg.LAWS` or its code 1..6.
        eps : float, optional
            The regularization > 0 (m/s); the current one when omitted.

        Raises
        ------
        fricreg.InputError
            (a ``ValueError``) The structure has no contacts, ``law`` names no law, or
            ``eps`` is not one real number. Refused by the library: ``eps`` <= 0, NaN or
            infinite. The law and eps stay as they were.
        """
        self._has_contacts("law")
        code = _law_code(law)
        eps = self._eps if eps is None else as_scalar(eps, "eps")
        self._check(lib.fricreg_structure_set_law(self._s, code, eps), "eps", "Structure.set_law")
        self._law, self._eps = ffi.string(lib.fricreg_law_name(code)).decode(), eps

    def set_bounds(self, mun):
        """Set the contacts' friction bounds mu N_i (``fricreg_structure_set_bounds``), between
        runs (normal forces vary): the next step starts from the equilibrium acceleration with
        the new bounds.

        Parameters
        ----------
        mun : array_like of float, shape (ncontacts,), or float
            The bounds >= 0 (N); one number sets every contact's.

        Raises
        ------
        fricreg.InputError
            (a ``ValueError``) The structure has no contacts, or ``mun`` is not real numbers
            or not of shape (ncontacts,). Refused by the library: a bound < 0, NaN or
            infinite. The bounds stay as they were.
        """
        self._has_contacts("mun")
        mun = np.full(self.ncontacts, as_scalar(mun, "mun")) if np.ndim(mun) == 0 \
            else _vector(mun, "mun", self.ncontacts)
        self._check(lib.fricreg_structure_set_bounds(self._s, self.ncontacts, pointer(mun)),
                    "mun", "Structure.set_bounds")
        self._mun = mun.copy()

    @property
    def law(self):
        """str or None: the contacts' law (:data:`fricreg.LAWS`; None without contacts); set by
        :meth:`set_law`."""
        return self._law

    @law.setter
    def law(self, law):
        assigned("Structure", "law", "set_law")
        self.set_law(law)

    @property
    def eps(self):
        """float or None: the regularization in force (m/s; None without contacts); set by
        :meth:`set_law`."""
        return self._eps

    @eps.setter
    def eps(self, eps):
        assigned("Structure", "eps", "set_law")
        self.set_law(self._law, eps)

    @property
    def mun(self):
        """ndarray of float64, shape (ncontacts,): a copy of the contacts' bounds (N); set by
        :meth:`set_bounds`."""
        return self._mun.copy()

    # ---- state -------------------------------------------------------------------------------

    @property
    def t(self):
        """The time reached (s)."""
        t = ffi.new("double *")
        lib.fricreg_structure_get_value(self._s, lib.FRICREG_SVALUE_TIME, t)
        return t[0]

    def state(self):
        """The state at the current time.

        Returns
        -------
        u, v, a : ndarray of float64, shape (ndof,)
            Displacements (m), velocities (m/s) and accelerations (m/s^2)
            (``fricreg_structure_get_state``).
        """
        u, v, a = np.empty(self.ndof), np.empty(self.ndof), np.empty(self.ndof)
        lib.fricreg_structure_get_state(self._s, self.ndof, pointer(u), pointer(v), pointer(a))
        return u, v, a

    def reset(self, u0=None, v0=None):
        """Restart at t = 0 from u0 and v0 (``fricreg_structure_set_initial``): the energy
        balance, the dissipation, the counters, the peaks, the warnings and the error estimate
        start anew, the elements' sliders at 0.

        Parameters
        ----------
        u0, v0 : array_like, shape (ndof,), optional
            Displacements (m) and velocities (m/s); default 0.

        Raises
        ------
        fricreg.InputError
            (a ``ValueError``) A shape does not fit. Refused by the library: NaN or infinite
            entries.
        """
        u0 = np.zeros(self.ndof) if u0 is None else _vector(u0, "u0", self.ndof)
        v0 = np.zeros(self.ndof) if v0 is None else _vector(v0, "v0", self.ndof)
        self._check(lib.fricreg_structure_set_initial(self._s, self.ndof, pointer(u0),
                                                      pointer(v0)), "u0, v0")
        self._warned = set()

    # ---- running -----------------------------------------------------------------------------

    def _set_scheme(self, integrator, alpha):
        """Select the structure's own scheme where it changes (a change ends an estimate)."""
        scheme = ("hht", -0.05 if alpha is None else float(alpha)) if integrator == "hht" else \
            (integrator,)
        if scheme == self._scheme:
            return
        if integrator == "newmark":
            status = lib.fricreg_structure_set_newmark(self._s, 0.25, 0.5)
        elif integrator == "hht":
            status = lib.fricreg_structure_set_hht(self._s, scheme[1])
        else:
            status = lib.fricreg_structure_set_central_difference(self._s)
        self._check(status, "alpha" if integrator == "hht" else "integrator")
        self._scheme = scheme

    def _integrator(self, integrator, alpha, rtol, atol):
        """The GSL stepper's code, or 0 for the structure's own schemes (selected here)."""
        if integrator not in INTEGRATORS:
            raise refused("integrator: %r is not one of %s" % (integrator,
                                                               ", ".join(INTEGRATORS)))
        if alpha is not None and integrator != "hht":
            raise refused("alpha: only integrator 'hht' has alpha")
        if integrator in _SCHEMES:
            if rtol != 0.0 or atol is not None:
                raise refused("%s: only GSL's steppers are adaptive"
                              % ("rtol" if rtol != 0.0 else "atol"))
            self._set_scheme(integrator, alpha)
            return 0
        return lib.fricreg_integrator_from_name(integrator.encode())

    def _output_dofs(self, output_dofs):
        if output_dofs is None:
            return np.arange(self.ndof)
        dofs = np.asarray(output_dofs)
        if dofs.ndim != 1 or dofs.dtype.kind not in "iu":
            raise refused("output_dofs: expected a sequence of dof numbers from 0, not %r"
                          % (output_dofs,))
        bad = dofs[(dofs < 0) | (dofs >= self.ndof)]
        if bad.size:
            raise refused("output_dofs: dof %d is not in 0 .. %d" % (bad[0], self.ndof - 1))
        return dofs.astype(np.int64)

    def run(self, integrator="newmark", *, dt, t_end, output_dofs=None, output_every=1,
            alpha=None, rtol=0.0, atol=None):
        """Step from the current time to t_end and return the time series and the run's
        summary.

        Parameters
        ----------
        integrator : str
            One of :data:`INTEGRATORS`: ``"newmark"`` (average acceleration), ``"hht"``
            (HHT-alpha), ``"central"`` (explicit central differences) or a GSL stepper
            (``"rk4"``, ``"rkf45"``, ``"msbdf"``, ...; no joint elements).
        dt : float
            The step (s), > 0; the last one shortened to land on t_end. With ``rtol`` a GSL
            stepper's output interval and first step.
        t_end : float
            The end time (s), after the current time.
        output_dofs : sequence of int, optional
            The dofs (numbered from 0) whose u and u' the time series holds; default all.
        output_every : int
            A row every K-th step time k dt (K >= 1), and always the first and the last.
        alpha : float, optional
            HHT's alpha in [-1/3, 0]; default -0.05 (hht only).
        rtol : float
            GSL steppers: the relative tolerance of adaptive steps; 0 (default): fixed steps.
        atol : float, optional
            GSL steppers: the absolute tolerance; with rtol > 0 and no atol, each velocity a
            contact reads is held to 1e-3 eps (``FRICREG_ATOL_FROM_EPS``).

        Returns
        -------
        StructureResult
            Times (nsamples,), displacements and velocities (nsamples, len(output_dofs)),
            contact forces (nsamples, m), and the summary: see :class:`StructureResult`.

        Raises
        ------
        fricreg.InputError
            (a ``ValueError``) An argument out of its range or choice; the message names it.
            Refused by the library: the library refused an argument (hht's alpha out of range, a
            step too long for the model's numbers, elements with a GSL stepper, ...).
        fricreg.Error
            The run failed (``FRICREG_ESTEP``: a central or explicit fixed step beyond its
            stability bound; ``EDIVERGED``, ``ESINGULAR``, ``EWORK``, ``EINTEGRATOR``). The
            structure stays at its last successful step; the exception's ``result`` holds the
            run up to there.
        fricreg.Interrupted
            (a ``KeyboardInterrupt``) Ctrl-C: the run stops at the step it reached (the
            structure consistent there, a later run continues it), the exception's ``result``
            holding the run so far.

        Warns
        -----
        fricreg.AccuracyWarning
            Each warning of the library's checks (``fricreg_structure_warning_count``, e.g.
            ``eps_large: ...``), once per code until the next reset; all are in
            ``result.warnings``.

        Notes
        -----
        Newmark and HHT-alpha solve the friction forces implicitly, Newton on the exact
        tangent of the law (``fricreg_structure_step``), in one ``fricreg_structure_run``
        call whose observer records the rows; the GSL steppers run one
        ``fricreg_structure_run_ode`` call per sample k dt, as ``fricreg-sim structure``
        does, so that the rows equal its trajectory's bit for bit. A run continues the
        structure's state: two runs to T1 and T2 take the steps of one run to T2.
        """
        code = self._integrator(integrator, alpha, rtol, atol)
        dt, t_end, t = as_scalar(dt, "dt"), as_scalar(t_end, "t_end"), self.t
        if not 0.0 < dt < np.inf:
            raise refused("dt: %r must be finite and > 0" % dt)
        if not t < t_end < np.inf:
            raise refused("t_end: %r must be finite and after the structure's time %r"
                          % (t_end, t))
        every = int(output_every)
        if every < 1 or every != output_every:
            raise refused("output_every: %r must be a whole number >= 1" % (output_every,))
        recorder = structure_result.Recorder(self._output_dofs(output_dofs), self.ndof,
                                             self.ncontacts, t, dt, t_end, every)
        recorder.observe_now(self._s)
        structure_result.take_pending()
        interrupt = None
        if code == 0:
            lib.fricreg_structure_set_observer(self._s, *recorder.observer())
            try:
                status = lib.fricreg_structure_run(self._s, dt, t_end)
            finally:
                lib.fricreg_structure_set_observer(self._s, ffi.NULL, ffi.NULL)
            interrupt = structure_result.take_pending()
        else:
            try:
                status = self._run_ode(code, dt, t_end, rtol, atol, recorder)
            except KeyboardInterrupt as exc:
                status, interrupt = lib.FRICREG_OK, exc
        message = ffi.string(lib.fricreg_structure_errmsg(self._s)).decode()
        recorder.observe_now(self._s, last=True)
        result = structure_result.read_result(self._s, recorder, self.ndof, self.ncontacts,
                                              self._sets, self._warn())
        if status != lib.FRICREG_OK:
            try:
                raise_status(status, "Structure.run", "after t = %.17g: %s" % (result.t, message))
            except Error as exc:
                exc.result = result
                raise
        if isinstance(interrupt, KeyboardInterrupt):
            raise interrupted(result) from None
        if interrupt is not None:  # an error of the recording itself
            raise interrupt
        return result

    def _run_ode(self, code, dt, t_end, rtol, atol, recorder):
        """fricreg_structure_run_ode from sample to sample k dt, as fricreg-sim's advance()."""
        rtol = float(rtol)
        if atol is None:
            atol = (lib.FRICREG_ATOL_FROM_EPS if self.ncontacts else rtol) if rtol > 0.0 else 0.0
        atol = float(atol)
        steps = np.ceil(t_end / dt * (1.0 - 1e-12))
        nsteps, t = (1 if steps < 1.0 else int(steps)), self.t
        first = int(t / dt) if t > dt else 1
        while first > 1 and (first - 1) * dt > t:
            first -= 1
        while first < nsteps and not first * dt > t:
            first += 1
        for k in range(first, nsteps + 1):
            t1 = t_end if k == nsteps else k * dt
            status = lib.fricreg_structure_run_ode(self._s, code, t1 - t, rtol, atol, t1)
            if status != lib.FRICREG_OK:
                return status
            t = t1
            recorder.observe_now(self._s)
        return lib.FRICREG_OK

    def _warn(self):
        """The library's warnings now; each code not yet warned of since the last reset is
        also emitted as an AccuracyWarning."""
        found = structure_result.judge_warnings(self._s)
        for name, message in found:
            if name not in self._warned:
                self._warned.add(name)
                warnings.warn("%s: %s" % (name, message), AccuracyWarning, stacklevel=3)
        return found

    # ---- checkpoints -------------------------------------------------------------------------

    def save(self):
        """The structure's state as a checkpoint (``fricreg_structure_save``).

        Returns
        -------
        bytes
            Everything a step carries to the next (time and grid, u, v, a, forces, energies,
            dissipation, counters, peaks, warnings, elements' sliders, the error estimate's
            companions); not the model, which :meth:`restore` checks. For the same build on the
            same machine.

        Raises
        ------
        fricreg.InputError
            More than 64 coupled contacts (a sparse W: not supported; the message says so).
        """
        size = ffi.new("size_t *")
        self._check(lib.fricreg_structure_save(self._s, ffi.NULL, size), "", "Structure.save")
        buf = ffi.new("char[]", size[0])
        self._check(lib.fricreg_structure_save(self._s, buf, size), "", "Structure.save")
        return ffi.buffer(buf, size[0])[:]

    def restore(self, data, integrator=None, alpha=None):
        """Continue from a checkpoint of :meth:`save` (``fricreg_structure_restore``).

        The structure must be set up as the saved one was: the same model, records, law and
        eps, elements, error estimate and scheme. A run from here then gives, bit for bit,
        what the saved structure would have given.

        Parameters
        ----------
        data : bytes-like
            The checkpoint.
        integrator : {"newmark", "hht", "central"}, optional
            The scheme the saved structure stepped with last, selected before restoring
            (default: the scheme in force).
        alpha : float, optional
            HHT's alpha (default -0.05).

        Raises
        ------
        fricreg.InputError
            (a ``ValueError``) ``data`` is not bytes-like (a ``TypeError`` before 1.9), or
            ``integrator`` is not one of the structure's own schemes. Refused
            by the library: Not a checkpoint, truncated or corrupted, of another build, or of a
            structure set up otherwise (the message names the first difference). The state is
            unchanged.
        """
        try:
            buf = ffi.from_buffer(data)
        except TypeError:
            raise refused("data: a %s is not bytes-like" % type(data).__name__) from None
        if integrator is not None:
            if integrator not in _SCHEMES:
                raise refused("integrator: %r is not one of %s"
                              % (integrator, ", ".join(_SCHEMES)))
            self._set_scheme(integrator, alpha)
        self._check(lib.fricreg_structure_restore(self._s, buf, len(buf)), "data",
                    "Structure.restore")

