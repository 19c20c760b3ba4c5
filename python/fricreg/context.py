# SPDX-License-Identifier: GPL-3.0-or-later
"""Coupled 1-D contacts (``fricreg.h``'s context, ``fricreg_ctx``): the friction forces of m
contacts whose relative accelerations are zddot = a_free + W f, W the Delassus matrix, and the
contact step of one's own implicit integrator (``fricreg_structure.h``'s
``fricreg_ctx_solve_step_matrix``).

D. D. Quinn, *A New Regularization of Coulomb Friction*, J. Vib. Acoust. 126 (2004) 391-397:
the laws (1)-(4) and the f_eq partition of its Sec. 3.3; the consistent near-stick law beyond
the paper is ``docs/coupled.md``'s, the step ``docs/structural.md``'s ("Your own Newmark with
fricreg").
"""
import operator

import numpy as np

from ._record import record
from ._fricreg import ffi, lib
from ._arrays import as_doubles, as_integer, as_scalar, pointer
from .errors import raise_status, refused
from ._settings import assigned, fixed
from .laws import LAWS, _law_code
from ._matrices import MatrixArgs, is_sparse

__all__ = ["Context", "PARTITIONS", "StepResult"]

#: The partitions' names (``enum fricreg_partition``): the consistent near-stick law (the
#: default) and the paper's Sec. 3.3; the names of ``fricreg-sim --partition``.
PARTITIONS = ("consistent", "paper")
_PARTITION_CODES = {"consistent": lib.FRICREG_PARTITION_CONSISTENT,
                    "paper": lib.FRICREG_PARTITION_PAPER}
_STATS = ("evals", "feq_contacts", "factorizations", "solves", "qp_iterations", "factor_updates")

StepResult = record("StepResult", "f iterations converged", """\
The result of :meth:`Context.solve_step`.

f : ndarray of float64, shape (m,)
    The step's friction forces (force units); the best iterate when not converged.
iterations : int
    The Newton iterations made (``info[0]``).
converged : bool
    Whether max_i |G_i| <= tol (``info[1]``); a step that did not converge raises nothing.
""")


class Context:
    """The friction forces of m coupled 1-D contacts, zddot = a_free + W f (``fricreg_ctx``).

    Parameters
    ----------
    m : int, optional
        The number of contacts, 1 <= m <= 2^26; taken from ``W`` or ``mun`` when omitted.
    W : array_like or scipy.sparse matrix, optional
        The Delassus matrix W = J M^-1 J^T (acceleration per force: an inverse mass),
        symmetric positive semidefinite: shape (m,) for a diagonal W (every entry > 0), (m, m)
        dense (``W[i, j]`` = W_ij, row-major), or any scipy.sparse matrix of shape (m, m)
        (CSR and CSC passed as they are, other formats converted to CSR; given whole, not by a
        triangle). The identity when omitted (uncoupled contacts of unit effective mass).
    mun : array_like of float, shape (m,) or scalar, optional
        The friction bounds mu_i N_i >= 0 (force units); 1 when omitted.
    law : str or int
        One of :data:`fricreg.LAWS` or its code (default ``"quinn"``, law (4)).
    eps : float
        The regularization >= DBL_MIN (velocity units); default 1e-3.
    partition : str
        One of :data:`PARTITIONS`: ``"consistent"`` (default) or ``"paper"``.

    Attributes
    ----------
    m : int
        The number of contacts (read-only).
    law, eps, mun, W, partition, keep_tangent
        Read-only properties: a copy of what was set. Each is set by a method
        (:meth:`set_law` for law and eps, :meth:`set_bounds`, :meth:`set_coupling`,
        :meth:`set_partition`, :meth:`set_keep_tangent`), which discards the tangent of the
        last evaluation. Assigning one (``ctx.mun = ...``) still calls its method but warns
        (``DeprecationWarning``) and ends in 2.0.

    Raises
    ------
    fricreg.InputError
        (a ``ValueError``) ``m`` is missing and cannot be inferred, an argument has the wrong
        shape or dtype, or ``law`` or ``partition`` names none. Refused by the library: the C
        library refused a value (m out of range, a bound < 0, eps below DBL_MIN, W not
        symmetric, not semidefinite, NaN, ...); the message names the argument and is the
        context's own (``fricreg_ctx_errmsg``).
    fricreg.OutOfMemoryError
        The context or W's factor could not be allocated.

    Notes
    -----
    Calls ``fricreg_ctx_create`` and the setters ``fricreg_ctx_set_law``,
    ``fricreg_ctx_set_partition``, ``fricreg_ctx_set_coupling_diagonal`` / ``_dense`` /
    ``_csr`` / ``_csc`` and ``fricreg_ctx_set_bounds``; the context is freed
    (``fricreg_ctx_free``) when the object is collected. One context must not be used from two
    threads at once; separate contexts may.
    """

    # every attribute: assigning a misspelt setting raises instead of adding one
    __slots__ = ("_ctx", "_m", "_law", "_eps", "_keep", "_partition", "_W", "_mun", "__weakref__")

    def __init__(self, m=None, *, W=None, mun=None, law="quinn", eps=1e-3,
                 partition="consistent"):
        m = self._size_from(m, W, mun)
        out = ffi.new("fricreg_ctx **")
        status = lib.fricreg_ctx_create(m, out)
        if status != lib.FRICREG_OK:
            raise_status(status, "Context", "m = %d: not 1 <= m <= 2^26" % m
                         if status == lib.FRICREG_EINVAL else "")
        self._ctx = ffi.gc(out[0], lib.fricreg_ctx_free)
        self._m = m
        self._law, self._eps, self._keep = "quinn", 1e-3, True
        self._partition, self._W, self._mun = "consistent", np.ones(m), np.ones(m)
        self.set_law(law, eps)
        self.set_partition(partition)
        if W is not None:
            self.set_coupling(W)
        if mun is not None:
            self.set_bounds(mun)

    m = fixed("m", "int: the number of contacts, fixed at construction.")

    @staticmethod
    def _size_from(m, W, mun):
        """m, or W's or mun's length; ValueError naming m otherwise."""
        if m is None:
            if W is not None:
                m = W.shape[0] if is_sparse(W) else len(np.atleast_1d(np.asarray(W)))
            elif mun is not None and np.ndim(mun) == 1:
                m = len(mun)
            else:
                raise refused("m: not given, and neither W nor an array mun gives it")
        m = as_integer(m, "m")
        if m < 1:
            raise_status(lib.FRICREG_EINVAL, "Context", "m = %d: not 1 <= m <= 2^26" % m)
        return m

    def __repr__(self):
        kind = "sparse" if is_sparse(self._W) else "diagonal" if self._W.ndim == 1 else "dense"
        return "Context(m=%d, law=%r, eps=%r, partition=%r, W=<%s>)" % (
            self.m, self._law, self._eps, self._partition, kind)

    def _check(self, status, where):
        """Raise the context's own message (fricreg_ctx_errmsg) for a failed call."""
        if status != lib.FRICREG_OK:
            raise_status(status, where, ffi.string(lib.fricreg_ctx_errmsg(self._ctx)).decode())

    def _vector(self, value, name):
        """value as a float64 array of shape (m,); ValueError naming it otherwise."""
        array = as_doubles(value, name)
        if array.shape != (self.m,):
            raise refused("%s: shape %s; expected (%d,)" % (name, array.shape, self.m))
        return array

    # ---- settings: set_* methods, read-only properties (docs/python.md, "Settings") -----

    def set_law(self, law, eps=None):
        """Select the friction law and its regularization (``fricreg_ctx_set_law``).

        Parameters
        ----------
        law : str or int
            One of :data:`fricreg.LAWS` or its code 1..6.
        eps : float, optional
            The regularization >= DBL_MIN (velocity units; Karnopp's dead band); the current
            one when omitted. Validated though ignored by coulomb and force-balance.

        Raises
        ------
        fricreg.InputError
            (a ``ValueError``) ``law`` names no law, or ``eps`` is not one real number.
            Refused by the library: ``eps`` below DBL_MIN, NaN or infinite. The law and eps
            stay as they were.
        """
        code = _law_code(law)
        eps = self._eps if eps is None else as_scalar(eps, "eps")
        self._check(lib.fricreg_ctx_set_law(self._ctx, code, eps), "Context.set_law: eps")
        self._law, self._eps = LAWS[code - 1], eps

    def set_bounds(self, mun):
        """Set the friction bounds mu_i N_i (``fricreg_ctx_set_bounds``): cheap, O(m), may
        change before every :meth:`eval` (normal forces vary).

        Parameters
        ----------
        mun : array_like of float, shape (m,), or float
            The bounds >= 0 (force units); one number sets every contact's.

        Raises
        ------
        fricreg.InputError
            (a ``ValueError``) ``mun`` is not real numbers or not of shape (m,). Refused by
            the library: a bound < 0, NaN or infinite. The bounds stay as they were.
        """
        mun = np.full(self.m, as_scalar(mun, "mun")) if np.ndim(mun) == 0 \
            else self._vector(mun, "mun")
        self._check(lib.fricreg_ctx_set_bounds(self._ctx, self.m, pointer(mun)),
                    "Context.set_bounds: mun")
        self._mun = mun.copy()

    def set_coupling(self, W):
        """Set the Delassus matrix W = J M^-1 J^T (``fricreg_ctx_set_coupling_diagonal``,
        ``_dense``, ``_csr``, ``_csc``, by W's storage).

        Parameters
        ----------
        W : array_like or scipy.sparse matrix
            Symmetric positive semidefinite (acceleration per force): shape (m,) for a
            diagonal W (every entry > 0), (m, m) dense (``W[i, j]`` = W_ij, row-major), or a
            scipy.sparse matrix of shape (m, m) (CSR and CSC as they are, other formats
            converted to CSR; given whole, not by a triangle). Copied.

        Raises
        ------
        fricreg.InputError
            (a ``ValueError``) ``W`` is not real numbers or of another shape. Refused by the
            library: a diagonal entry <= 0, W not symmetric (``FRICREG_ENOTSYM``) or not
            semidefinite (``FRICREG_ENOTPSD``), NaN or infinite. The coupling stays as it
            was.
        fricreg.OutOfMemoryError
            W's factor could not be allocated.
        """
        if is_sparse(W):
            args = self._square(W, "W")
            setter = (lib.fricreg_ctx_set_coupling_csc if args.format == lib.FRICREG_MATRIX_CSC
                      else lib.fricreg_ctx_set_coupling_csr)
            status = setter(self._ctx, self.m, lib.FRICREG_SPARSE_ZERO_BASED, args.ptr, args.ind,
                            args.values)
            stored = args.matrix.astype(float)
        else:
            stored = as_doubles(W, "W").copy()
            if stored.shape == (self.m,):
                status = lib.fricreg_ctx_set_coupling_diagonal(self._ctx, self.m, pointer(stored))
            elif stored.shape == (self.m, self.m):
                status = lib.fricreg_ctx_set_coupling_dense(self._ctx, self.m, pointer(stored))
            else:
                raise refused("W: shape %s; expected (%d,) (diagonal) or (%d, %d)"
                              % (stored.shape, self.m, self.m, self.m))
        self._check(status, "Context.set_coupling: W")
        self._W = stored

    def set_partition(self, partition):
        """Select the near-stick partition (``fricreg_ctx_set_partition``).

        Parameters
        ----------
        partition : str
            One of :data:`PARTITIONS`: ``"consistent"`` (the consistent near-stick law of
            ``docs/coupled.md``) or ``"paper"`` (Quinn's Sec. 3.3).

        Raises
        ------
        fricreg.InputError
            (a ``ValueError``) ``partition`` names none. The partition stays as it was.
        """
        if not isinstance(partition, str) or partition not in _PARTITION_CODES:
            raise refused("partition: %r is not a partition (one of %s)"
                          % (partition, ", ".join(PARTITIONS)))
        self._check(lib.fricreg_ctx_set_partition(self._ctx, _PARTITION_CODES[partition]),
                    "Context.set_partition: partition")
        self._partition = partition

    def set_keep_tangent(self, keep):
        """Whether :meth:`eval` keeps what :meth:`tangent` needs
        (``fricreg_ctx_set_keep_tangent``); on by default, an explicit integrator that never
        asks for the tangent may turn it off.

        Parameters
        ----------
        keep : bool
            True or False (a numpy bool, 0 or 1 too).

        Raises
        ------
        fricreg.InputError
            (a ``ValueError``) ``keep`` is not a bool (a string such as ``"no"`` would read
            as true). The setting stays as it was.
        """
        if not isinstance(keep, (bool, np.bool_)) and not (
                isinstance(keep, (int, np.integer)) and keep in (0, 1)):
            raise refused("keep: %r is not a bool" % (keep,))
        keep = bool(keep)
        self._check(lib.fricreg_ctx_set_keep_tangent(self._ctx, int(keep)),
                    "Context.set_keep_tangent: keep")
        self._keep = keep

    @property
    def law(self):
        """str: the law's name (:data:`fricreg.LAWS`); set by :meth:`set_law`."""
        return self._law

    @law.setter
    def law(self, law):
        assigned("Context", "law", "set_law")
        self.set_law(law)

    @property
    def eps(self):
        """float: the regularization eps (velocity units); set by :meth:`set_law`."""
        return self._eps

    @eps.setter
    def eps(self, eps):
        assigned("Context", "eps", "set_law")
        self.set_law(self._law, eps)

    @property
    def mun(self):
        """ndarray of float64, shape (m,): the bounds mu_i N_i (force units), a copy; set by
        :meth:`set_bounds`."""
        return self._mun.copy()

    @mun.setter
    def mun(self, mun):
        assigned("Context", "mun", "set_bounds")
        self.set_bounds(mun)

    @property
    def W(self):
        """The coupling, a copy of what was set: ndarray of shape (m,) (diagonal) or (m, m)
        (dense), or a scipy.sparse CSR or CSC matrix; set by :meth:`set_coupling`."""
        return self._W.copy()

    @W.setter
    def W(self, W):
        assigned("Context", "W", "set_coupling")
        self.set_coupling(W)

    @property
    def partition(self):
        """str: the near-stick partition, one of :data:`PARTITIONS`; set by
        :meth:`set_partition`."""
        return self._partition

    @partition.setter
    def partition(self, partition):
        assigned("Context", "partition", "set_partition")
        self.set_partition(partition)

    @property
    def keep_tangent(self):
        """bool: whether :meth:`eval` keeps what :meth:`tangent` needs (default True); set by
        :meth:`set_keep_tangent`."""
        return self._keep

    @keep_tangent.setter
    def keep_tangent(self, keep):
        assigned("Context", "keep_tangent", "set_keep_tangent")
        self.set_keep_tangent(bool(keep))

    # ---- evaluation ----------------------------------------------------------------------

    def eval(self, zdot, a_free):
        """The friction forces of the m contacts (``fricreg_ctx_eval``).

        Parameters
        ----------
        zdot : array_like of float, shape (m,)
            Relative contact velocities (velocity units).
        a_free : array_like of float, shape (m,)
            Free relative accelerations, those with f = 0 (acceleration units).

        Returns
        -------
        f : ndarray of float64, shape (m,)
            The friction forces (force units), |f_i| <= mun_i.
        f_eq : ndarray of float64, shape (m,)
            f_eq,i on the near-stick set S (the force that zeroes contact i's acceleration;
            under the consistent law -(a_free,i + sum_{j != i} W_ij f_j)/W_ii), NaN for
            contacts not in S, where the law does not read it.

        Raises
        ------
        fricreg.InputError
            (a ``ValueError``) An argument's shape or dtype does not fit. Refused by the
            library: A NaN or infinite input, or (dense W) a near-stick contact beyond the
            solve's range, ~1e280: the context's message names the argument and the contact.
        fricreg.Error
            ``FRICREG_ESINGULAR``: the near-stick block of W is singular (redundant contacts,
            whose forces are not unique).

        Notes
        -----
        Quinn (2004), Sec. 3.3: the slip set gets f_L = -mun_L sgn(zdot_L); the near-stick set
        S (|zdot_i| < eps for law (4) and Karnopp, zdot_i == 0 for (2)) gets f_eq from W and
        the law at (zdot_i, f_eq,i); under the consistent partition the near-stick forces solve
        the box-constrained QP of ``docs/coupled.md``. Dense and sparse W give the same forces
        to rounding; a diagonal W divides, contact by contact.
        """
        zdot, a_free = self._vector(zdot, "zdot"), self._vector(a_free, "a_free")
        f, f_eq = np.empty(self.m), np.empty(self.m)
        self._check(lib.fricreg_ctx_eval(self._ctx, self.m, pointer(zdot), pointer(a_free),
                                         pointer(f), pointer(f_eq)), "Context.eval")
        return f, f_eq

    def tangent(self):
        """The Jacobian of the last successful :meth:`eval`'s forces (``fricreg_ctx_tangent``).

        Returns
        -------
        df_dzdot : ndarray of float64, shape (m, m)
            ``df_dzdot[i, j]`` = d f_i / d zdot_j (force per velocity), row-major.
        df_dafree : ndarray of float64, shape (m, m)
            ``df_dafree[i, j]`` = d f_i / d a_free_j (force per acceleration: a mass).

        Raises
        ------
        fricreg.InputError
            ``FRICREG_EINVAL``: no successful eval since the context was created or a setter
            was called, or :attr:`keep_tangent` is off.
        fricreg.Error
            ``FRICREG_ESINGULAR`` if the block to refactorize has become singular.

        Notes
        -----
        Exact where the force is differentiable; on a kink the Jacobian of one adjacent piece
        (``fricreg.h``, ``docs/coupled.md``, "The tangent"). Entries beyond a double's range
        are +-inf. For a large m use :meth:`tangent_apply`: this is 2 m^2 doubles.
        """
        df_dzdot, df_dafree = np.empty((self.m, self.m)), np.empty((self.m, self.m))
        self._check(lib.fricreg_ctx_tangent(self._ctx, self.m, pointer(df_dzdot),
                                            pointer(df_dafree)), "Context.tangent")
        return df_dzdot, df_dafree

    def tangent_apply(self, dzdot=None, dafree=None):
        """The tangent of the last successful :meth:`eval` times a direction
        (``fricreg_ctx_tangent_apply``): df = (df/dzdot) dzdot + (df/da_free) dafree.

        Parameters
        ----------
        dzdot : array_like of float, shape (m,), optional
            The velocity direction (zdot's units); zero when omitted.
        dafree : array_like of float, shape (m,), optional
            The free-acceleration direction (a_free's units); zero when omitted.

        Returns
        -------
        df : ndarray of float64, shape (m,)
            The forces' change (force units), the same Jacobian as :meth:`tangent`'s.

        Raises
        ------
        fricreg.InputError
            (a ``ValueError``) An argument's shape or dtype does not fit. Refused by the
            library: A NaN or infinite direction or result, or ``FRICREG_EINVAL`` as
            :meth:`tangent`.
        fricreg.Error
            ``FRICREG_ESINGULAR`` as :meth:`tangent`.

        Notes
        -----
        One or two solves with the evaluation's factor, no m x m array: for Newton-Krylov
        callers and a large sparse W.
        """
        arrays = [None if d is None else self._vector(d, name)
                  for d, name in ((dzdot, "dzdot"), (dafree, "dafree"))]
        df = np.empty(self.m)
        self._check(lib.fricreg_ctx_tangent_apply(
            self._ctx, self.m, *[ffi.NULL if a is None else pointer(a) for a in arrays],
            pointer(df)), "Context.tangent_apply")
        return df

    def switching(self, zdot, a_free, f):
        """The switching functions of the contacts at a state, for event location
        (``fricreg_ctx_switching``): signed distances to the kinks of their laws.

        Parameters
        ----------
        zdot, a_free : array_like of float, shape (m,)
            As for :meth:`eval`.
        f : array_like of float, shape (m,)
            The forces :meth:`eval` gave at (zdot, a_free) (force units).

        Returns
        -------
        g : ndarray of float64, shape (m, 7)
            ``g[i, k]``: component k (``enum fricreg_switch``: 0 zdot - eps, 1 zdot + eps,
            2 zdot, 3 and 4 the edges of law (4)'s linear zone, 5 and 6 the saturations
            f_eq = +-mun) of contact i; +1 where inert for the law.

        Raises
        ------
        fricreg.InputError
            (a ``ValueError``) An argument's shape or dtype does not fit. Refused by the
            library: A NaN or infinite input.

        Notes
        -----
        A pure function of its inputs: the context's tangent, warm start and counters are
        left as they are (``docs/integrators.md``, "Switching functions").
        """
        zdot, a_free = self._vector(zdot, "zdot"), self._vector(a_free, "a_free")
        f = self._vector(f, "f")
        ng = lib.fricreg_ctx_switching_count(self._ctx)
        g = np.empty(ng)
        self._check(lib.fricreg_ctx_switching(self._ctx, self.m, pointer(zdot), pointer(a_free),
                                              pointer(f), pointer(g), ng), "Context.switching")
        return g.reshape(self.m, -1)

    def stick_stiffness(self):
        """An upper bound lambda of the stick zone's decay rates (``fricreg_ctx_stick_stiffness``).

        Returns
        -------
        lam : float
            lambda >= 0 (1/time units of zdot/eps), +inf where it overflows: a fixed explicit
            step dt is stable in the stick zone when dt lambda is within the stepper's bound
            (RK4: 2.785).

        Raises
        ------
        fricreg.OutOfMemoryError
            The eigenvalue problem of a dense W could not be allocated.

        Notes
        -----
        max_i W_ii s_i with s_i the law's slope at rest (2 mun_i/eps for (4)) for a diagonal
        W or (4) under the consistent partition; the largest eigenvalue of D^1/2 W D^1/2
        (dense) or Gershgorin's bound of it (sparse) otherwise (``docs/coupled.md``).
        """
        lam = ffi.new("double *")
        self._check(lib.fricreg_ctx_stick_stiffness(self._ctx, lam), "Context.stick_stiffness")
        return lam[0]

    def stats(self, reset=False):
        """The context's counters since creation or the last reset (``fricreg_ctx_get_stat``).

        Parameters
        ----------
        reset : bool
            Set every counter to zero after reading (``fricreg_ctx_reset_stats``).

        Returns
        -------
        dict of str to int
            ``evals``, ``feq_contacts``, ``factorizations``, ``solves``, ``qp_iterations``,
            ``factor_updates`` (``enum fricreg_stat``).
        """
        value = ffi.new("int64_t *")
        counts = {}
        for which, name in enumerate(_STATS):
            self._check(lib.fricreg_ctx_get_stat(self._ctx, which, value), "Context.stats")
            counts[name] = int(value[0])
        if reset:
            lib.fricreg_ctx_reset_stats(self._ctx)
        return counts

    # ---- the step of one's own integrator ------------------------------------------------

    def solve_step(self, zdot_start, zdot_pred, a_pred, W_eff, c, tol, f=None, max_iter=50,
                   plain=False):
        """The friction forces of one implicit step of one's own integrator (Newmark, HHT-alpha,
        a BDF): ``fricreg_ctx_solve_step_matrix``, with the context's W.

        Solves G(f) = f - F(zdot_pred + c W_eff f, a_pred - (W - W_eff) f) = 0, F this
        context's law (:meth:`eval`), by Newton with fricreg_structure's safeguards.

        Parameters
        ----------
        zdot_start : array_like of float, shape (m,)
            The contacts' velocities at the step's start, J v (velocity units).
        zdot_pred : array_like of float, shape (m,)
            The end's velocities with no friction change, J v_pred + c J K_eff^-1 b.
        a_pred : array_like of float, shape (m,)
            J K_eff^-1 b (acceleration units): a_free(f) = a_pred - (W - W_eff) f.
        W_eff : array_like of float, shape (m, m), or scipy.sparse matrix
            W_eff = J K_eff^-1 J^T, symmetric positive definite (acceleration per force),
            dense row-major or sparse (CSR or CSC as they are, other formats as CSR). The
            context's W is passed in the same storage (a dense one's exact zeros dropped
            for sparse); keep W_eff's zeros exact so that the kept solver's pattern holds.
        c : float
            > 0, d zdot / d(J x): gamma dt for Newmark (time units).
        tol : float
            > 0 (force units): converged when max_i |G_i| <= tol; e.g. 1e-10 of the largest
            bound.
        f : array_like of float, shape (m,), optional
            The guess, usually the previous step's forces; zeros when omitted. Not modified.
        max_iter : int
            >= 1, the step's Newton iterations.
        plain : bool
            Plain Newton (``FRICREG_STEP_PLAIN``): no stick guess, no stop at zdot = 0, no
            line search; for comparison only.

        Returns
        -------
        StepResult
            ``(f, iterations, converged)``; the context's last evaluation is at f.

        Raises
        ------
        fricreg.InputError
            (a ``ValueError``) An argument's shape or dtype does not fit. Refused by the
            library: c, tol or an entry NaN or infinite, c <= 0, tol <= 0, max_iter < 1, W_eff
            not symmetric (``FRICREG_ENOTSYM``) or a diagonal entry below DBL_MIN
            (``FRICREG_ENOTPSD``); the context's message.
        fricreg.Error
            ``FRICREG_EDIVERGED`` if the residual became NaN or infinite, ``FRICREG_ESINGULAR``
            for redundant contacts.
        fricreg.OutOfMemoryError
            The step's solver could not be allocated.

        Notes
        -----
        ``docs/structural.md``, "Your own Newmark with fricreg": with M x + C v1 + K u1 =
        p1 + J^T f and Newmark's affine end state, K_eff = M + gamma dt C + beta dt^2 K and
        b = p1 - C v_pred - K u_pred; then x = K_eff^-1 (b + J^T f) gives the structure's
        update. Newton on the exact tangent T = I - c F_z W_eff + F_a (W - W_eff), with a
        stick guess, a stop at zdot_i = 0 and a backtracking line search on sqrt(G^T W G).
        """
        vectors = [self._vector(v, name) for v, name in (
            (zdot_start, "zdot_start"), (zdot_pred, "zdot_pred"), (a_pred, "a_pred"))]
        f = np.zeros(self.m) if f is None else self._vector(f, "f").copy()
        w, weff = self._step_matrices(W_eff)
        info = ffi.new("int[2]")
        self._check(lib.fricreg_ctx_solve_step_matrix(
            self._ctx, self.m, *[pointer(v) for v in vectors], weff.format, w.ptr, w.ind,
            w.values, weff.ptr, weff.ind, weff.values, as_scalar(c, "c"), as_scalar(tol, "tol"),
            operator.index(max_iter),
            lib.FRICREG_STEP_PLAIN if plain else 0, pointer(f), info), "Context.solve_step")
        return StepResult(f, int(info[0]), bool(info[1]))

    def _square(self, matrix, name, form=None):
        """MatrixArgs of an (m, m) matrix; ValueError naming it for another shape."""
        args = MatrixArgs(matrix, name, form)
        if args.shape != (self.m, self.m):
            raise refused("%s: shape %s; expected (%d, %d)"
                          % (name, args.shape, self.m, self.m))
        return args

    def _step_matrices(self, W_eff):
        """MatrixArgs of the context's W and of W_eff, both in W_eff's storage, for
        fricreg_ctx_solve_step_matrix."""
        W = self._W
        if is_sparse(W_eff):
            weff = self._square(W_eff, "W_eff")
            if not is_sparse(W):
                import scipy.sparse  # W_eff is sparse: scipy is there
                W = scipy.sparse.diags(W) if W.ndim == 1 else scipy.sparse.csr_matrix(W)
            return self._square(W, "W", weff.matrix.format), weff
        w = W.toarray() if is_sparse(W) else np.diag(W) if W.ndim == 1 else W
        return self._square(w, "W"), self._square(W_eff, "W_eff")
