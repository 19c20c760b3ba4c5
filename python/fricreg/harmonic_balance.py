# SPDX-License-Identifier: GPL-3.0-or-later
"""Harmonic balance of a linear structure with friction elements (``fricreg_hb.h``): the
periodic response at one frequency, branches in the frequency or the excitation level with
Floquet stability and bifurcations, and nonlinear modes' backbones.

M. Krack and J. Gross, *Harmonic Balance for Nonlinear Vibration Problems*, Springer 2019:
the model M x'' + C x' + K x + J^T f(J x) = p_c cos Ωt + p_s sin Ωt, solved for H harmonics,
condensed on the elements' coordinates q = J x (Ch. 4), continued by pseudo-arclength (Ch. 5).
"""
import threading

import numpy as np

from ._fricreg import ffi, lib
from ._arrays import as_doubles, as_integer, as_scalar, choice, pointer
from .element import Element
from .errors import Error, InputError, interrupted, raise_status, refused
from ._settings import fixed
from ._hb_results import Backbone, Bifurcation, Response, Solution, SpecialPoint
from ._matrices import MatrixArgs

__all__ = ["HarmonicBalance", "Solution", "Response", "Bifurcation", "Backbone",
           "SpecialPoint"]

_STABILITY_METHODS = {"auto": lib.FRICREG_HB_STABILITY_AUTO,
                      "hill": lib.FRICREG_HB_STABILITY_HILL,
                      "monodromy": lib.FRICREG_HB_STABILITY_MONODROMY,
                      "condensed": lib.FRICREG_HB_STABILITY_CONDENSED}
_NEWTON_SOLVERS = {"auto": lib.FRICREG_HB_NEWTON_AUTO, "dense": lib.FRICREG_HB_NEWTON_DENSE,
                   "capacitance": lib.FRICREG_HB_NEWTON_CAPACITANCE}
_RECEPTANCES = {"auto": lib.FRICREG_HB_RECEPTANCE_AUTO, "lu": lib.FRICREG_HB_RECEPTANCE_LU,
                "modes": lib.FRICREG_HB_RECEPTANCE_MODES}
_DAMPING = {"matrix": lib.FRICREG_HB_NMA_DAMPING_MATRIX,
            "modal": lib.FRICREG_HB_NMA_DAMPING_MODAL}
_BIFURCATIONS = {lib.FRICREG_HB_TP: "TP", lib.FRICREG_HB_BP: "BP", lib.FRICREG_HB_PD: "PD",
                 lib.FRICREG_HB_NS: "NS"}
_SPECIAL_POINTS = {lib.FRICREG_HB_NMA_FOLD: "fold", lib.FRICREG_HB_NMA_CROSSING: "crossing"}

# FRICREG_HB_SOLUTION, ((size_t)-1): the index of the last solution (a cast, which cffi's
# cdef cannot declare as a constant).
_SOLUTION = ffi.cast("size_t", -1)

# Seconds of wall time between two calls of the monitor into Python (Ctrl-C's latency): each
# takes the GIL back, at a cost near a small model's Newton step.
WATCH_INTERVAL = 0.02

# The call in progress on each thread: where the monitor leaves an exception (Ctrl-C).
_calls = threading.local()


def model_params(params, amplitude=False):
    """The rows (kind, first, count, index) of parameter descriptions: ``("element", first,
    count, index)``, ``("damping", index)`` and, where allowed, ``("amplitude",)``."""
    kinds = {"element": lib.FRICREG_HB_NMA_PARAM_ELEMENT,
             "damping": lib.FRICREG_HB_NMA_PARAM_DAMPING,
             "amplitude": lib.FRICREG_HB_NMA_PARAM_AMPLITUDE}
    forms = "('element', first, count, index), ('damping', index)" + (
        " or ('amplitude',)" if amplitude else "")
    rows = []
    for p in params:
        p = tuple(p)
        if not p or p[0] not in kinds or (p[0] == "amplitude" and not amplitude):
            raise refused("params: %r is not %s" % (p, forms))
        if p[0] == "element" and len(p) == 4:
            rows.append((kinds["element"], as_integer(p[1], "params first"),
                         as_integer(p[2], "params count"), as_integer(p[3], "params index")))
        elif p[0] == "damping" and len(p) == 2:
            rows.append((kinds["damping"], 0, 0, as_integer(p[1], "params index")))
        elif p[0] == "amplitude" and len(p) == 1:
            rows.append((kinds["amplitude"], 0, 0, 0))
        else:
            raise refused("params: %r has the wrong number of entries" % (p,))
    return rows


def _check_mass(args):
    """A negative mass refused: a diagonal entry of M below 0 (the C driver takes any symmetric
    M, and only the backbone's linear mode would find it)."""
    diagonal = np.asarray(args.matrix.diagonal())
    if diagonal.size and diagonal.min() < 0:
        i = int(np.argmin(diagonal))
        raise refused("M: M[%d, %d] = %g; a mass is >= 0" % (i, i, diagonal[i]))


def _pair(value, name):
    """value as the two numbers (a, b)."""
    pair = as_doubles(value, name, ndim=1)
    if pair.shape != (2,):
        raise refused("%s: shape %s; expected 2 numbers" % (name, pair.shape))
    return float(pair[0]), float(pair[1])


@ffi.def_extern(onerror=lambda exception, value, traceback: _stop(value))
def fricreg_py_hb_monitor(user, iterations, parameter, residual):
    """Before a Newton step, once per WATCH_INTERVAL (callbacks.c): 0 goes on. A
    KeyboardInterrupt raised here (Python runs its SIGINT handler when the callback starts)
    goes to _stop, which stops the call."""
    return 0


def _stop(exception):
    """Keep the exception for the caller and stop the solve (the monitor's nonzero return)."""
    _calls.exception = exception
    return 1


class HarmonicBalance:
    """The periodic steady state of a linear structure with friction elements, by harmonic
    balance (``fricreg_hb``).

    Parameters
    ----------
    M, K : array_like, shape (ndof, ndof), or scipy.sparse matrix
        Mass (e.g. kg) and stiffness (N/m), symmetric; K nonsingular. Dense arrays are
        row-major; a sparse matrix (CSR or CSC kept, other formats converted to CSR) makes the
        model sparse (KLU).
    C : array_like or scipy.sparse matrix, shape (ndof, ndof), optional
        Damping (N s/m), symmetric. Give C or ``rayleigh``; a model without damping has no
        finite response at its linear resonances.
    elements : sequence
        The friction elements, in the order of their rows of q: each entry ``(element, J)``
        with ``element`` a :class:`fricreg.Element` (its parameters shared by the block) and
        ``J`` of shape (me * dim, ndof), me elements of dim rows each (tangential components,
        then the normal displacement); or ``(name, J, params)`` with params of shape
        (me, nparams), one row per element. Any number of elements: memory is the limit.
    harmonics : int
        H, 1..40.
    rayleigh : (float, float), optional
        Rayleigh damping C = a0 M + a1 K (a0 in 1/s, a1 in s), in place of C.
    excitation : (array_like, array_like), optional
        (p_c, p_s), each of shape (ndof,): the force p_c cos Ωt + p_s sin Ωt (N).

    Attributes
    ----------
    ndof, harmonics, nelements, nrows : int
        Read-only, fixed with the model: the dofs, H, the elements and q's rows. The settings
        that may change are methods: :meth:`set_excitation`, :meth:`set_newton`,
        :meth:`set_continuation`, :meth:`set_stability`, :meth:`set_element_param`.

    Raises
    ------
    fricreg.InputError
        (a ``ValueError``) A shape does not fit, or ``elements`` is not as described. Refused by
        the library: a matrix is not symmetric, an entry is NaN, a parameter is out of range
        (the library's message names it).
    fricreg.OutOfMemoryError

    Notes
    -----
    The driver is ``fricreg_hb`` (``fricreg_hb_create``, ``fricreg_hb_set_matrix``,
    ``fricreg_hb_add_elements``, ``fricreg_hb_set_excitation``); every result equals the C
    library's on the same inputs bit for bit. The C calls release the GIL; one driver serves one
    thread at a time. Ctrl-C during a solve stops it through the library's monitor
    (``fricreg_hb_set_monitor``) and raises :class:`fricreg.Interrupted` with what was computed.
    """

    # every attribute: assigning a misspelt setting raises instead of adding one
    __slots__ = ("_hb", "_ndof", "_harmonics", "_nelements", "_J", "_nrows", "_watch", "_stability",
                 "__weakref__")

    def __init__(self, M, K, C=None, *, elements, harmonics, rayleigh=None, excitation=None):
        matrices = [(lib.FRICREG_MASS, MatrixArgs(M, "M")),
                    (lib.FRICREG_STIFFNESS, MatrixArgs(K, "K"))]
        if C is not None:
            matrices.append((lib.FRICREG_DAMPING, MatrixArgs(C, "C")))
        ndof = matrices[0][1].shape[0]
        for which, args in matrices:
            if args.shape != (ndof, ndof):
                raise refused("%s: shape %s; expected (%d, %d) as M"
                              % ("MKC"[which - 1], args.shape, ndof, ndof))
        _check_mass(matrices[0][1])
        if C is not None and rayleigh is not None:
            raise refused("C, rayleigh: give one damping, the matrix C or Rayleigh's (a0, a1)")
        if len(elements) == 0:
            raise refused("elements: none given; harmonic balance needs at least one element")
        blocks = [self._block(entry, ndof, i) for i, entry in enumerate(elements)]
        count = sum(block[1] for block in blocks)
        self._ndof, self._harmonics = ndof, as_integer(harmonics, "harmonics")
        self._nelements = count
        self._J = np.vstack([block[2] for block in blocks])
        self._nrows = self._J.shape[0]
        out = ffi.new("fricreg_hb **")
        status = lib.fricreg_hb_create(ndof, count, self.harmonics, out)
        if status != lib.FRICREG_OK:
            raise_status(status, "HarmonicBalance", "ndof = %d, %d elements, harmonics = %d: "
                         "ndof 1..2^24, at least one element, harmonics 1..40" %
                         (ndof, count, self.harmonics))
        self._hb = ffi.gc(out[0], lib.fricreg_hb_free)
        for which, args in matrices:
            self._check(lib.fricreg_hb_set_matrix(self._hb, which, ndof, ndof, args.format,
                                                  args.ptr, args.ind, args.values),
                        "HarmonicBalance " + "MKC"[which - 1])
        if rayleigh is not None:
            a0, a1 = _pair(rayleigh, "rayleigh")
            self._check(lib.fricreg_hb_set_rayleigh(self._hb, a0, a1), "HarmonicBalance rayleigh")
        for typ, me, J, params in blocks:
            self._check(lib.fricreg_hb_add_elements(self._hb, typ, me, ndof, pointer(J),
                                                    pointer(params)), "HarmonicBalance")
        # the monitor is C (callbacks.c), asking Python about Ctrl-C once per WATCH_INTERVAL
        self._watch = ffi.new("struct fricreg_py_watch *", {"interval": WATCH_INTERVAL})
        self._check(lib.fricreg_hb_set_monitor(self._hb, ffi.addressof(lib, "fricreg_py_hb_watch"),
                                               self._watch), "HarmonicBalance")
        self._stability = False
        if excitation is not None:
            self.set_excitation(*excitation)

    @staticmethod
    def _block(entry, ndof, i):
        """(type, me, J, params) of one entry of ``elements``."""
        if len(entry) == 2 and isinstance(entry[0], Element):
            element, J = entry
            params = None
        elif len(entry) == 3:
            name, J, params = entry
            try:
                element = Element(name, as_doubles(params, "elements[%d] params" % i, ndim=2)[0])
            except InputError as error:
                raise refused("elements[%d]: %s" % (i, error)) from None
        else:
            raise refused("elements[%d]: expected (Element, J) or (name, J, params)" % i)
        J = as_doubles(J, "elements[%d] J" % i, ndim=2)
        if J.shape[1] != ndof or J.shape[0] % element.dim or J.shape[0] == 0:
            raise refused("elements[%d] J: shape %s; expected (me * %d, %d) for %s"
                          % (i, J.shape, element.dim, ndof, element.name))
        me = J.shape[0] // element.dim
        if params is None:
            params = np.tile(element.params, (me, 1))
        params = as_doubles(params, "elements[%d] params" % i, ndim=2)
        if params.shape != (me, element.nparams):
            raise refused("elements[%d] params: shape %s; expected (%d, %d)"
                          % (i, params.shape, me, element.nparams))
        return element._type, me, J, params

    def _check(self, status, where):
        """Raise with the driver's message where status is not FRICREG_OK."""
        if status != lib.FRICREG_OK:
            raise_status(status, where, ffi.string(lib.fricreg_hb_errmsg(self._hb)).decode())

    def _run(self, where, call, partial):
        """A solving call with Ctrl-C armed: Interrupted raised with partial() if the monitor
        stopped it, and a failure's Error carrying partial() as its result."""
        _calls.exception = None
        status = call()
        exception, _calls.exception = _calls.exception, None
        if isinstance(exception, KeyboardInterrupt):
            raise interrupted(partial()) from None
        if exception is not None:
            raise exception
        if status != lib.FRICREG_OK:
            try:
                self._check(status, where)
            except Error as error:
                error.result = partial()
                raise

    # ---- settings: set_* methods (docs/python.md, "Settings") ---------------------------

    ndof = fixed("ndof", "int: the model's degrees of freedom, fixed at construction.")
    harmonics = fixed("harmonics", "int: H, the harmonics, fixed at construction.")
    nelements = fixed("nelements", "int: the friction elements of every block, fixed at "
                      "construction.")
    nrows = fixed("nrows", "int: the rows of q = J x, every element's dim rows, fixed at "
                  "construction.")

    def set_excitation(self, pc, ps=None):
        """The force p_c cos Ωt + p_s sin Ωt.

        Parameters
        ----------
        pc, ps : array_like, shape (ndof,)
            Cosine and sine amplitudes (N); ps zero when omitted.

        Raises
        ------
        fricreg.InputError
            (a ``ValueError``) A shape is not (ndof,). Refused by the library: An entry is NaN
            or infinite (``fricreg_hb_set_excitation``).
        """
        pc = as_doubles(pc, "pc", ndim=1)
        ps = np.zeros(self.ndof) if ps is None else as_doubles(ps, "ps", ndim=1)
        for name, array in (("pc", pc), ("ps", ps)):
            if array.shape != (self.ndof,):
                raise refused("%s: shape %s; expected (%d,)" % (name, array.shape, self.ndof))
        self._check(lib.fricreg_hb_set_excitation(self._hb, self.ndof, pointer(pc), pointer(ps)),
                    "set_excitation")

    def set_element_param(self, first, count, index, value):
        """Move one parameter of the elements first .. first + count - 1 (in the order given
        to the constructor) to one value, in place (``fricreg_hb_set_element_param``): a
        parameter study or a fit without building the model again. ``index`` is in
        fricreg_element.h's layout of each element's type (jenkins 0 kt, 1 mun; iwan k[ns] then
        phi[ns]; jenkins_normal and contact_3d 0 kt, 1 mu, 2 kn, 3 n0; a marched type its own),
        as ``backbone_sensitivities``'s ``("element", first, count, index)``. A model change:
        the last solution, branch and backbone are forgotten.

        Raises
        ------
        fricreg.InputError
            An empty range or one beyond the elements, an index beyond an element's parameters,
            a value out of its range (a stiffness <= 0, a slip force or mu < 0; a gap other
            than 0), NaN or infinite. No element changes.
        """
        self._check(lib.fricreg_hb_set_element_param(
            self._hb, as_integer(first, "first"), as_integer(count, "count"),
            as_integer(index, "index"), as_scalar(value, "value")), "set_element_param")

    def element_param(self, element, index):
        """Parameter ``index`` of element ``element`` (``fricreg_hb_get_element_param``; the
        layout of ``set_element_param``; a gap reads 0).

        Raises
        ------
        fricreg.InputError
            element or index out of range.
        """
        value = ffi.new("double *")
        self._check(lib.fricreg_hb_get_element_param(self._hb, as_integer(element, "element"),
                                                     as_integer(index, "index"), value),
                    "element_param")
        return value[0]

    def set_newton(self, tol=1e-10, max_iter=50, solver=None):
        """Newton's stopping rule (``fricreg_hb_set_newton``): the largest residual entry at
        most tol times the displacement scale, after at most max_iter iterations a solve. A
        continuation's corrector also stops where it stalls at the solves' rounding, DBL_EPSILON
        times D_h's condition number of that scale (the C function's documentation).

        solver : {None, "auto", "dense", "capacitance"}
            How Newton's matrix is solved (``fricreg_hb_set_newton_solver``; None: as before,
            ``"auto"`` at first): ``"dense"``,
            LAPACK's LU of the whole (1.9's); ``"capacitance"``, Woodbury's identity on the rows
            of the elements' Jacobian off its diagonal; ``"auto"``, the capacitance from 512
            unknowns where those rows are at most 0.8 of them, else dense, from 1024 unknowns
            first by refinement on the last matrix's LU. The results agree to rounding.

        Raises
        ------
        fricreg.InputError
            Not 0 < tol < 1, max_iter outside 1..1000, or an unknown solver.
        MemoryError
            No room for the capacitance.
        """
        code = None if solver is None else choice(_NEWTON_SOLVERS, solver, "solver")
        self._check(lib.fricreg_hb_set_newton(self._hb, as_scalar(tol, "tol"),
                                              as_integer(max_iter, "max_iter")), "set_newton")
        if code is not None:
            self._check(lib.fricreg_hb_set_newton_solver(self._hb, code), "set_newton")

    def set_receptance(self, method="auto"):
        """How the dynamic stiffnesses D_h = K - (h omega)^2 M + i h omega C are solved at each
        frequency (``fricreg_hb_set_receptance``).

        method : {"auto", "lu", "modes"}
            ``"lu"``, LAPACK's LU of each D_h (1.9's); ``"modes"``, through the modes of
            K phi = lambda M phi, which make every D_h diagonal where the damping is Rayleigh's
            (or none): one product with the modes a harmonic, several times faster from a few
            hundred dofs; ``"auto"`` (the default), the modes from 200 dofs. The modes serve
            only where M's reciprocal condition number is at least 1e-6, and never with a
            nonzero damping matrix or a sparse model (the LU then serves). The results agree to
            rounding.

        Raises
        ------
        fricreg.InputError
            An unknown method.
        """
        code = choice(_RECEPTANCES, method, "method")
        self._check(lib.fricreg_hb_set_receptance(self._hb, code), "set_receptance")

    def set_continuation(self, ds=0.02, ds_min=1e-6, ds_max=0.1, max_points=2000):
        """The continuation's step control in the scaled arclength
        (``fricreg_hb_set_continuation``, whose defaults these are).

        Parameters
        ----------
        ds : float
            The first step, ds_min <= ds <= ds_max, in the arclength of the scaled unknowns
            (q by its largest entry so far, Ω by |omega1 - omega0|: ds = 0.01 is about a
            hundredth of the interval on a flat branch); nondimensional.
        ds_min, ds_max : float
            The smallest step, > 0 (a rejected step is halved down to it; below it the
            continuation stops with FRICREG_EINTEGRATOR) and the largest, <= 1 (the step
            follows the corrector's convergence and the branch's curvature up to it).
        max_points : int
            The most points a branch stores, >= 2; a continuation that would store more stops
            with FRICREG_EWORK, the points reached kept.

        Raises
        ------
        fricreg.InputError
            Not ds_min <= ds <= ds_max <= 1, ds_min <= 0, or max_points < 2.
        """
        self._check(lib.fricreg_hb_set_continuation(
            self._hb, as_scalar(ds, "ds"), as_scalar(ds_min, "ds_min"), as_scalar(ds_max, "ds_max"),
            as_integer(max_points, "max_points")), "set_continuation")

    def set_stability(self, enable=True, method="auto"):
        """Floquet stability of every later solution (``fricreg_hb_set_stability``).

        Parameters
        ----------
        enable : bool
        method : {"auto", "hill", "monodromy", "condensed"}
            ``"monodromy"``: the orbit's exact monodromy (1-D Jenkins and Iwan elements, with or
            without lift-off); ``"condensed"``: the same on the model condensed onto the dofs
            the elements touch (Craig-Bampton, the interior modes in band); ``"hill"``: Hill's
            method, any element, its verdict only; ``"auto"``: the condensed monodromy where
            the elements touch at most a quarter of 32 to 1024 dofs, else the monodromy up to
            order 512, else the condensed one up to 4096 dofs, else Hill's.

        Raises
        ------
        fricreg.InputError
            (a ``ValueError``) An unknown method. Refused by the library: Hill's method on a
            model beyond ndof (2H + 1) = 1024.
        """
        code = choice(_STABILITY_METHODS, method, "method")
        self._check(lib.fricreg_hb_set_stability_method(self._hb, code), "set_stability")
        self._check(lib.fricreg_hb_set_stability(self._hb, int(bool(enable))), "set_stability")
        self._stability = bool(enable)

    # ---- solves -----------------------------------------------------------------------

    def _guess(self, guess):
        """The C guess pointer (NULL for None), the array kept alive by the caller."""
        if guess is None:
            return None, ffi.NULL
        q0 = as_doubles(guess, "guess")
        if q0.shape != (self.nrows, 2 * self.harmonics + 1):
            raise refused("guess: shape %s; expected (%d, %d)"
                          % (q0.shape, self.nrows, 2 * self.harmonics + 1))
        return q0, pointer(q0)

    def _stability_of(self, k, omega):
        """(stable, mu_max, multipliers by decreasing modulus) of stored point k or of the
        solution, at its frequency omega (None, nan, None with stability off)."""
        if not self._stability:
            return None, float("nan"), None
        stable, mu = ffi.new("int *"), ffi.new("double *")
        self._check(lib.fricreg_hb_point_stability(self._hb, k, stable, mu), "stability")
        exponents = np.empty((2 * self.ndof, 2))
        self._check(lib.fricreg_hb_point_exponents(self._hb, k, exponents.shape[0],
                                                   pointer(exponents)), "stability")
        multipliers = np.exp(2.0 * np.pi / omega * (exponents[:, 0] + 1j * exponents[:, 1]))
        return bool(stable[0]), mu[0], multipliers[np.argsort(-np.abs(multipliers),
                                                              kind="stable")]

    def _solution(self, omega, q, x=None):
        """The driver's last solution as a Solution (x: its coefficients if known); without q
        (a branch's last point, whose unknowns the C API does not give), q = J x, the
        solver's own to Newton's tolerance."""
        if x is None:
            x = np.empty((self.ndof, 2 * self.harmonics + 1))
            self._check(lib.fricreg_hb_displacement(self._hb, self.ndof, x.shape[1],
                                                    pointer(x)), "displacement")
        if q is None:
            q = self._J @ x
        stable, mu, multipliers = self._stability_of(_SOLUTION, omega)
        return Solution(omega, q, x, stable, mu, multipliers)

    def solve(self, omega, guess=None):
        """The periodic response at the excitation frequency omega (``fricreg_hb_solve``).

        Parameters
        ----------
        omega : float
            Excitation circular frequency Ω > 0, rad/s.
        guess : array_like, shape (nrows, 2H + 1), optional
            The elements' coordinates to start from; without one the solution reached
            continuously from the linear regime along the excitation level.

        Returns
        -------
        Solution

        Raises
        ------
        fricreg.InputError
            (a ``ValueError``) guess has the wrong shape. Refused by the library: omega <= 0 or
            not finite, a NaN in guess.
        fricreg.Error
            FRICREG_ESINGULAR (K or some D_h singular), FRICREG_EWORK (Newton did not
            converge), FRICREG_EINTEGRATOR; the message is the driver's.
        fricreg.Interrupted
            Ctrl-C (its result is None: nothing is written).
        """
        omega = as_scalar(omega, "omega")
        q0, q0_ptr = self._guess(guess)
        q = np.empty((self.nrows, 2 * self.harmonics + 1))
        self._run("solve", lambda: lib.fricreg_hb_solve(self._hb, omega, q.size, q0_ptr,
                                                         pointer(q)), lambda: None)
        return self._solution(omega, q)

    def _response(self):
        """The stored branch as a Response."""
        n = lib.fricreg_hb_points(self._hb)
        omega, level = np.empty(n), np.empty(n)
        rms = np.empty((n, self.ndof))
        x = np.empty((n, self.ndof, 2 * self.harmonics + 1))
        stable = np.empty(n, dtype=bool) if self._stability else None
        mu_max = np.empty(n) if self._stability else None
        multipliers = np.empty((n, 2 * self.ndof), complex) if self._stability else None
        w, lv = ffi.new("double *"), ffi.new("double *")
        for k in range(n):
            self._check(lib.fricreg_hb_point(self._hb, k, w, self.ndof, pointer(rms[k])), "point")
            self._check(lib.fricreg_hb_point_level(self._hb, k, lv), "point")
            self._check(lib.fricreg_hb_point_displacement(self._hb, k, self.ndof, x.shape[2],
                                                          pointer(x[k])), "point")
            omega[k], level[k] = w[0], lv[0]
            if self._stability:
                stable[k], mu_max[k], multipliers[k] = self._stability_of(k, omega[k])
        solution = self._solution(omega[-1], None, x[-1].copy()) if n else None  # its q: J x
        return Response(omega, level, rms, x, stable, mu_max, self._bifurcations(), solution,
                        multipliers)

    def _bifurcations(self):
        """The located bifurcations of the stored branch."""
        found = []
        kind, w, level = ffi.new("int *"), ffi.new("double *"), ffi.new("double *")
        point = ffi.new("size_t *")
        for i in range(lib.fricreg_hb_bifurcations(self._hb)):
            rms = np.empty(self.ndof)
            self._check(lib.fricreg_hb_bifurcation(self._hb, i, kind, w, point, self.ndof,
                                                   pointer(rms)), "bifurcation")
            self._check(lib.fricreg_hb_bifurcation_level(self._hb, i, level), "bifurcation")
            found.append(Bifurcation(_BIFURCATIONS[kind[0]], w[0], level[0], point[0], rms))
        return tuple(found)

    def frequency_response(self, omega0, omega1, guess=None):
        """The periodic response from omega0 to omega1 by pseudo-arclength continuation in Ω
        (``fricreg_hb_continue``), through turning points; with stability on, each point's
        Floquet stability and the bifurcations between them.

        Parameters
        ----------
        omega0, omega1 : float
            The interval's ends, > 0, different (either order), rad/s.
        guess : array_like, shape (nrows, 2H + 1), optional
            The elements' coordinates at omega0, as for :meth:`solve`.

        Returns
        -------
        Response
            The branch's points; ``solution`` is its last, at omega1 (short of it where the
            branch is a closed loop, which the C library returns as such).

        Raises
        ------
        ValueError, fricreg.InputError
            As :meth:`solve`, and omega0 == omega1.
        fricreg.Error
            As :meth:`solve`; FRICREG_EINTEGRATOR if the step fell below ds_min, FRICREG_EWORK
            if max_points were stored before omega1. Its ``result`` is the Response of the
            points reached (None if the solve at omega0 failed).
        fricreg.Interrupted
            Ctrl-C; its result is the Response of the points computed so far (the first points
            of the uninterrupted branch, bit for bit).
        """
        omega0, omega1 = as_scalar(omega0, "omega0"), as_scalar(omega1, "omega1")
        q0, q0_ptr = self._guess(guess)
        nq = self.nrows * (2 * self.harmonics + 1)
        self._run("frequency_response",
                  lambda: lib.fricreg_hb_continue(self._hb, omega0, omega1, nq, q0_ptr),
                  self._partial_response)
        return self._response()

    def level_response(self, omega, level0, level1, guess=None):
        """The periodic response at the fixed frequency omega from the excitation level
        λ = level0 to level1, the force λ (p_c, p_s) (``fricreg_hb_continue_level``): the
        S-curve of the amplitude against the level.

        Parameters
        ----------
        omega : float
            Ω > 0, rad/s.
        level0, level1 : float
            The levels' ends, >= 0, different, nondimensional.
        guess : array_like, shape (nrows, 2H + 1), optional
            The elements' coordinates at level0.

        Returns
        -------
        Response
            ``level`` holds each point's λ; ``TP`` bifurcations are folds in λ.

        Raises
        ------
        As :meth:`frequency_response`.
        """
        omega = as_scalar(omega, "omega")
        level0, level1 = as_scalar(level0, "level0"), as_scalar(level1, "level1")
        q0, q0_ptr = self._guess(guess)
        nq = self.nrows * (2 * self.harmonics + 1)
        self._run("level_response",
                  lambda: lib.fricreg_hb_continue_level(self._hb, omega, level0, level1, nq,
                                                        q0_ptr),
                  self._partial_response)
        return self._response()

    def _partial_response(self):
        """The points a stopped continuation kept (no bifurcations are located then)."""
        return self._response() if lib.fricreg_hb_points(self._hb) else None

    def peak(self, dof):
        """The largest RMS of one dof along the last frequency response, located between its
        points (``fricreg_hb_peak``: Brent's method on the branch).

        Parameters
        ----------
        dof : int
            0 <= dof < ndof.

        Returns
        -------
        omega, rms : float
            The frequency (rad/s) and RMS (displacement units) of the peak.

        Raises
        ------
        fricreg.InputError
            dof out of range, or no frequency response computed (or a level response).
        fricreg.Error
            FRICREG_EWORK if a corrector did not converge.
        fricreg.Interrupted
            Ctrl-C (result None).
        """
        omega, rms = ffi.new("double *"), ffi.new("double *")
        dof = as_integer(dof, "dof")
        self._run("peak", lambda: lib.fricreg_hb_peak(self._hb, dof, omega, rms),
                  lambda: None)
        return omega[0], rms[0]

    # ---- nonlinear modes --------------------------------------------------------------

    def backbone(self, mode, a0, a1, npoints=50, damping="matrix", through_folds=True):
        """A nonlinear mode's backbone ω(a), ζ(a) by the extended periodic motion concept
        (``fricreg_hb_nma``, or ``fricreg_hb_nma_continue`` with through_folds): Krack,
        Computers & Structures 154 (2015) 59-71.

        Parameters
        ----------
        mode : int
            k, 0 <= k < ndof, in ascending order of the stuck structure's natural frequencies.
        a0, a1 : float
            Modal amplitudes, 0 < a0 < a1 (displacement times sqrt(mass)).
        npoints : int
            Points stored: geometric in a (through_folds False), or at equal arclength.
        damping : {"matrix", "modal"}
            The linear damping as set, or the mode's own modal damping.
        through_folds : bool
            Continue by pseudo-arclength through the folds in a (internal resonances), the
            default since 1.9 as ``fricreg-sim nma``'s; False: the natural-parameter march in
            log a, which stops at a fold (1.8's default).

        Returns
        -------
        Backbone

        Raises
        ------
        fricreg.InputError
            (a ``ValueError``) An unknown damping. Refused by the library: mode out of range,
            not 0 < a0 < a1, npoints out of 2..max_points.
        fricreg.Error
            FRICREG_ESINGULAR, FRICREG_EWORK (Newton did not converge, or the march met a
            fold: try through_folds), FRICREG_EINTEGRATOR. Its ``result`` is the Backbone of
            the points reached.
        fricreg.Interrupted
            Ctrl-C; its result is the Backbone of the points reached.
        """
        code = choice(_DAMPING, damping, "damping")
        solve = lib.fricreg_hb_nma_continue if through_folds else lib.fricreg_hb_nma
        mode, npoints = as_integer(mode, "mode"), as_integer(npoints, "npoints")
        a0, a1 = as_scalar(a0, "a0"), as_scalar(a1, "a1")
        self._run("backbone", lambda: solve(self._hb, mode, code, a0, a1, npoints),
                  self._backbone)
        return self._backbone()

    def backbone_at(self, mode, amplitudes, damping="matrix"):
        """The backbone at the caller's modal amplitudes (``fricreg_hb_nma_at``): the march of
        :meth:`backbone` through them, a point at each (a test's levels, which a geometric
        grid does not hold).

        Parameters
        ----------
        mode : int
            As :meth:`backbone`.
        amplitudes : array_like, shape (n,)
            Modal amplitudes, > 0 and strictly increasing.
        damping : {"matrix", "modal"}
            As :meth:`backbone`.

        Returns
        -------
        Backbone

        Raises
        ------
        fricreg.InputError
            Amplitudes not > 0 and increasing, n out of 1..max_points, mode out of range.
        fricreg.Error
            As :meth:`backbone` (its ``result`` the points reached).
        """
        code = choice(_DAMPING, damping, "damping")
        a = as_doubles(amplitudes, "amplitudes", ndim=1)
        self._run("backbone_at",
                  lambda: lib.fricreg_hb_nma_at(self._hb, as_integer(mode, "mode"), code, a.size,
                                                pointer(a)),
                  self._backbone)
        return self._backbone()

    def _backbone(self):
        """The stored backbone as a Backbone."""
        n, nc = lib.fricreg_hb_nma_points(self._hb), 2 * self.harmonics + 1
        a, w, z = np.empty(n), np.empty(n), np.empty(n)
        energy = np.empty((n, self.harmonics + 1))
        x = np.empty((n, self.ndof, nc))
        pa, pw, pz = ffi.new("double *"), ffi.new("double *"), ffi.new("double *")
        for i in range(n):
            self._check(lib.fricreg_hb_nma_point(self._hb, i, pa, pw, pz, self.ndof, nc,
                                                 pointer(x[i])), "backbone")
            a[i], w[i], z[i] = pa[0], pw[0], pz[0]
            self._check(lib.fricreg_hb_nma_harmonic_energy(self._hb, i, self.harmonics + 1,
                                                           pointer(energy[i])), "backbone")
        special = []
        kind, k, r = ffi.new("int *"), ffi.new("int *"), ffi.new("size_t *")
        for i in range(lib.fricreg_hb_nma_special_points(self._hb)):
            self._check(lib.fricreg_hb_nma_special_point(self._hb, i, kind, pa, pw, pz, k, r),
                        "backbone")
            special.append(SpecialPoint(_SPECIAL_POINTS[kind[0]], pa[0], pw[0], pz[0], k[0], r[0]))
        return Backbone(a, w, z, energy, tuple(special), x)

    def backbone_sensitivities(self, point, params, amplitudes=False):
        """Exact derivatives of a point of the last backbone in model parameters
        (``fricreg_hb_nma_point_sensitivities``): by the implicit function theorem on the
        point's converged residual, one solve for all the parameters (docs/nonlinear_modes.md,
        "Sensitivities").

        Parameters
        ----------
        point : int
            The backbone point, 0 <= point < npoints.
        params : sequence
            Each parameter one of ``("element", first, count, index)`` (elements first ..
            first + count - 1 in the order added, sharing one value of their type's parameter
            ``index`` of fricreg_element.h's layout: jenkins 0 kt, 1 mun; contact_3d 0 kt, 1 mu,
            2 kn, 3 n0; ...), ``("damping", index)`` (0 the mode's modal damping ratio with
            damping="modal", 1 and 2 Rayleigh's a0 and a1) or ``("amplitude",)`` (along the
            backbone).
        amplitudes : bool
            Also each dof's first-harmonic amplitude's derivatives.

        Returns
        -------
        domega, dzeta : ndarray, shape (np,)
            dω/dp (rad/s per unit) and dζ/dp.
        damp : ndarray, shape (np, ndof)
            Only with ``amplitudes``: d|X_1,j|/dp.

        Raises
        ------
        fricreg.InputError
            (a ``ValueError``) A parameter not of those forms. Refused by the library: point out
            of range, a kind, range or index the library refuses (the message says which: a
            parameter whose identity divides by 0, a stiffness on a model of more than 256 dofs,
            ...).
        fricreg.Error
            FRICREG_ESINGULAR at a fold or a repeated stuck mode.
        """
        rows = model_params(params, amplitude=True)
        n = len(rows)
        kind = ffi.new("int[]", [r[0] for r in rows] or [0])
        first, count, index = (ffi.new("size_t[]", [r[j] for r in rows] or [0])
                               for j in (1, 2, 3))
        domega, dzeta = np.empty(n), np.empty(n)
        damp = np.empty((n, self.ndof)) if amplitudes else None
        self._check(lib.fricreg_hb_nma_point_sensitivities(
            self._hb, as_integer(point, "point"), n, kind, first, count, index, pointer(domega),
            pointer(dzeta),
            self.ndof, pointer(damp) if amplitudes else ffi.NULL), "backbone_sensitivities")
        return (domega, dzeta, damp) if amplitudes else (domega, dzeta)

    def qsma(self, mode, amplitudes, params=None):
        """A mode's frequency and damping ratio by quasi-static modal analysis
        (``fricreg_hb_qsma_at``; Lacayo and Allen, MSSP 118 (2019) 133-157): the static
        loading path along M φ_k with the elements' hysteresis, exact for Jenkins and Iwan
        elements, marched in 256 to 512 steps where contact_3d or jenkins_normal elements are,
        and Masing's rule
        for the loop; the cheap route beside :meth:`backbone` (EPMC) for one mode with Masing
        behaviour (docs/identification.md, "QSMA").

        Parameters
        ----------
        mode : int
            k, 0 <= k < ndof, as :meth:`backbone`'s.
        amplitudes : array_like, shape (n,)
            Modal amplitudes φ_k^T M x, > 0, increasing.
        params : sequence, optional
            Also the exact derivatives in these parameters, described as
            :meth:`backbone_sensitivities` describes them.

        Returns
        -------
        omega, zeta : ndarray, shape (n,)
            ω = sqrt(λ/a) (rad/s) and ζ = ζ_k + D/(2π λ a).
        domega, dzeta : ndarray, shape (n, np)
            Only with ``params``: d/dp at each amplitude.

        Raises
        ------
        fricreg.InputError
            Bad amplitudes, a mode out of range, an element type QSMA does not take
            (iwan_normal, marched types: the message names it), contacts whose preloads at rest open one
            another, a parameter it refuses.
        fricreg.Error
            ``FRICREG_ESINGULAR``: macroslip below an amplitude (the message gives it), or a
            repeated stuck mode; ``FRICREG_EWORK``: with normal-law elements, a static
            equilibrium Newton's method does not find (the message gives the amplitude).
        """
        mode = as_integer(mode, "mode")
        a = as_doubles(amplitudes, "amplitudes", ndim=1)
        omega, zeta = np.empty_like(a), np.empty_like(a)
        self._check(lib.fricreg_hb_qsma_at(self._hb, mode, a.size, pointer(a), pointer(omega),
                                           pointer(zeta)), "qsma")
        if params is None:
            return omega, zeta
        rows = model_params(params, amplitude=True)
        n = len(rows)
        kind = ffi.new("int[]", [r[0] for r in rows] or [0])
        first, count, index = (ffi.new("size_t[]", [r[j] for r in rows] or [0])
                               for j in (1, 2, 3))
        domega, dzeta = np.empty((a.size, n)), np.empty((a.size, n))
        self._check(lib.fricreg_hb_qsma_sensitivities(
            self._hb, mode, a.size, pointer(a), n, kind, first, count, index, pointer(domega),
            pointer(dzeta)), "qsma")
        return omega, zeta, domega, dzeta

    def modal_participation(self, point, harmonic):
        """Each stuck linear mode's share in one harmonic of a point of the last backbone
        (``fricreg_hb_nma_modal_participation``): which mode a harmonic excites.

        Parameters
        ----------
        point : int
            The backbone point, 0 <= point < npoints.
        harmonic : int
            h, 0 <= h <= H.

        Returns
        -------
        fraction : ndarray, shape (ndof,)
            fraction[r], the share of mode r (from the lowest), summing to 1.

        Raises
        ------
        fricreg.InputError
            point or harmonic out of range, no backbone, a sparse model of more than 256 dofs.
        """
        fraction = np.empty(self.ndof)
        self._check(lib.fricreg_hb_nma_modal_participation(self._hb, as_integer(point, "point"),
                                                           as_integer(harmonic, "harmonic"),
                                                           self.ndof, pointer(fraction)),
                    "modal_participation")
        return fraction
