# SPDX-License-Identifier: GPL-3.0-or-later
"""The result of :meth:`fricreg.Structure.run`: the time series its observer recorded, and what
the structure's getters report at the run's end (``fricreg_structure.h``): peaks, dissipation,
the energy balance, the counters, the error estimates with their kinds and the warnings."""
import threading

import numpy as np

from ._fricreg import ffi, lib
from ._record import record

__all__ = ["ErrorEstimate", "EstimateCompanions", "StructureResult"]

ErrorEstimate = record("ErrorEstimate", "error kind", """\
An error estimate against the Coulomb problem (eps -> 0), from the
companion runs of ``fricreg_structure_set_error_estimate`` (docs/structural.md, "Error
estimate").

error : ndarray of float64, shape (n,)
    The estimate of each quantity's error, in its units (>= 0; +inf where a companion failed).
kind : ndarray of str, shape (n,)
    Each estimate's kind (``enum fricreg_estimate_kind``): ``"asymptotic"`` (Richardson's with
    the observed order, expected 1 ... 3x the error), ``"bound"`` (a safe upper bound) or
    ``"assumed"`` (one companion, the order assumed).
""")

EstimateCompanions = record(
    "EstimateCompanions",
    "used cpu_seconds screen_peak_displacement_error screen_dissipation_error",
    """\
Which companions gave a structure's error estimate, what they cost, and
what the coarser screen had said where the finer confirmed it
(``fricreg_structure_set_error_companions``, ``fricreg_structure_get_value``).

used : str
    ``"coarser"`` or ``"finer"``: the companions whose estimate the result reports (with
    ``error_companions="auto"``: ``"coarser"`` where the screen was quiet, ``"finer"`` where
    it doubted or failed).
cpu_seconds : float
    The CPU seconds the companions took (``FRICREG_SVALUE_COMPANION_CPU``), the screen's and
    the finer ones' together; their share of the run is this over the run's own CPU time.
screen_peak_displacement_error, screen_dissipation_error : float
    Where ``"auto"``'s finer companions confirmed: the screen's estimate of the largest peak's
    error (m) and of the summed dissipations' error (J) when it doubted, inf where it failed;
    nan where no confirmation ran.
""")

StructureResult = record(
    "StructureResult",
    "times displacements velocities forces output_dofs t peak_displacement "
    "dissipation element_dissipation element_forces energy stats "
    "peak_displacement_error dissipation_error element_dissipation_error warnings "
    "estimate_companions",
    """\
The result of :meth:`fricreg.Structure.run`.

Rows of the time series are samples, in time order: the state at the run's start, then at
every ``output_every``-th step time k dt and at the run's end (``fricreg-sim structure
--output trajectory``'s rows, bit for bit).

times : ndarray of float64, shape (nsamples,)
    The samples' times (s).
displacements, velocities : ndarray of float64, shape (nsamples, len(output_dofs))
    u and u' at the output dofs, ``displacements[k, j]`` = u of dof ``output_dofs[j]`` at
    ``times[k]``.
forces : ndarray of float64, shape (nsamples, m)
    The friction contacts' forces f (m = 0 for a structure without contacts).
output_dofs : ndarray of int64, shape (nout,)
    The dofs of the columns, numbered from 0.
t : float
    The time reached.
peak_displacement : ndarray of float64, shape (ndof,)
    max |u_k| since the last reset, turning points inside steps included, every dof.
dissipation : ndarray of float64, shape (m,)
    The energy each contact dissipated since the last reset.
element_dissipation : ndarray of float64, shape (nelements,)
    The energy each joint element dissipated, in the order they were given.
element_forces : list of ndarray of float64, one per element set, shape (me, dim)
    The force each element exerts at the end (tangential components, then the normal force N
    of a type with a normal law; the structure receives -J^T f).
energy : dict of str to float
    The energy balance (``fricreg_structure_get_value``): ``initial``, ``input``,
    ``kinetic``, ``strain`` (the elements' springs included), ``viscous``, ``friction``,
    ``elements`` (the joint elements' dissipation, the CLI's ``jenkins``) and ``residual`` =
    initial + input - kinetic - strain - viscous - friction - elements.
stats : dict of str to int
    Counters since the last reset: ``steps``, ``newton_iterations``, ``newton_max``,
    ``newton_failures``, ``line_search_cuts``.
peak_displacement_error, dissipation_error, element_dissipation_error : ErrorEstimate or None
    The error estimates of ``peak_displacement`` (n = ndof), ``dissipation`` (m) and
    ``element_dissipation`` (nelements); None without an estimate.
warnings : list of (str, str)
    The library's warnings on the model and the run since the last reset, ``(name,
    message)``, name as ``fricreg_warning_name`` gives it (``"eps_large"``, ...).
estimate_companions : EstimateCompanions or None
    Which companions gave the error estimates and what the screen said; None without an
    estimate (new in 1.9, the last field: unpacking by position takes one more name).
""")

_KINDS = {lib.FRICREG_EST_KIND_ASYMPTOTIC: "asymptotic", lib.FRICREG_EST_KIND_BOUND: "bound",
          lib.FRICREG_EST_KIND_ASSUMED: "assumed"}
_ENERGY = (("initial", lib.FRICREG_SVALUE_INITIAL), ("input", lib.FRICREG_SVALUE_INPUT),
           ("kinetic", lib.FRICREG_SVALUE_KINETIC), ("strain", lib.FRICREG_SVALUE_STRAIN),
           ("viscous", lib.FRICREG_SVALUE_VISCOUS), ("friction", lib.FRICREG_SVALUE_FRICTION),
           ("elements", lib.FRICREG_SVALUE_JENKINS), ("residual", lib.FRICREG_SVALUE_RESIDUAL))
_STATS = (("steps", lib.FRICREG_SSTAT_STEPS),
          ("newton_iterations", lib.FRICREG_SSTAT_NEWTON_ITERATIONS),
          ("newton_max", lib.FRICREG_SSTAT_NEWTON_MAX),
          ("newton_failures", lib.FRICREG_SSTAT_NEWTON_FAILURES),
          ("line_search_cuts", lib.FRICREG_SSTAT_LINE_SEARCH_CUTS))

# The exception an observer call raised (Ctrl-C's KeyboardInterrupt), per thread: the callback
# returns 1, which stops the run, and Structure.run raises it once the C call has returned.
_pending = threading.local()


def _keep_exception(exc_type, exc_value, traceback):
    """cffi's onerror of the observer: keep the exception for Structure.run."""
    _pending.exception = exc_value


def take_pending():
    """The exception an observer raised during the last run on this thread, or None."""
    exception = getattr(_pending, "exception", None)
    _pending.exception = None
    return exception


@ffi.def_extern(error=1, onerror=_keep_exception)
def fricreg_py_rows_grow(handle):
    """The observer's rows are full: twice the room (a MemoryError stops the run)."""
    ffi.from_handle(handle).grow()
    return 0


@ffi.def_extern(error=1, onerror=_keep_exception)
def fricreg_py_rows_check(handle):
    """Python's turn during a run (Recorder.CHECK_INTERVAL): a KeyboardInterrupt raised here
    (Python runs its SIGINT handler as the callback starts) stops the run."""
    ffi.from_handle(handle).check()
    return 0


class Recorder:
    """The rows of a run: the first, the last and every K-th step time k dt (the CLI's
    ``row_due``), u and v at the output dofs, the first m forces, in arrays that double when
    full. fricreg_structure_run's observer is C (callbacks.c) copying into them, which calls
    back into Python at most once per CHECK_INTERVAL seconds of wall time."""

    CHECK_INTERVAL = 0.02  # s: Ctrl-C's latency, against the cost of taking the GIL back

    def __init__(self, dofs, ndof, m, t0, dt, t_end, every):
        self.dofs, self.ndof, self.m = dofs, ndof, m
        self._handle = ffi.new_handle(self)
        self._dofs = np.ascontiguousarray(dofs, dtype=np.int64)
        all_dofs = len(dofs) == ndof and bool(np.all(dofs == np.arange(ndof)))
        self.rows = ffi.new("struct fricreg_py_rows *", {
            "dt": dt, "t_end": t_end, "interval": self.CHECK_INTERVAL, "every": every,
            "nout": len(dofs), "m": m, "handle": self._handle,
            "dofs": ffi.NULL if all_dofs else ffi.from_buffer("int64_t[]", self._dofs)})
        self._arrays = ()
        rows = (t_end - t0) / dt / every + 3  # the run's rows, if it ends at t_end
        self._resize(int(min(rows, 1 << 16)))

    @property
    def count(self):
        return self.rows.count

    def _resize(self, capacity):
        """Room for capacity rows, the rows so far kept."""
        k, width = self.rows.count, len(self.dofs)
        arrays = (np.empty(capacity), np.empty((capacity, width)), np.empty((capacity, width)),
                  np.empty((capacity, self.m)))
        for new, old in zip(arrays, self._arrays):
            new[:k] = old[:k]
        self._arrays = arrays
        r = self.rows
        r.times, r.u, r.v, r.f = (ffi.from_buffer("double[]", a) for a in arrays)
        r.capacity = capacity

    def grow(self):
        self._resize(2 * self.rows.capacity)

    def check(self):
        """Python's turn during a run: its signal handlers run here."""

    def observer(self):
        """(fn, user) of fricreg_structure_set_observer."""
        return ffi.addressof(lib, "fricreg_py_rows_observer"), self.rows

    def observe_now(self, s, last=False):
        """A row of the structure's current state: at the start and after each run_ode call
        where one is due, or with last where the last row is not at the current time (a run
        stopped or failed between rows)."""
        t = ffi.new("double *")
        lib.fricreg_structure_get_value(s, lib.FRICREG_SVALUE_TIME, t)
        r = self.rows
        due = (self._arrays[0][r.count - 1] != t[0]) if last else lib.fricreg_py_rows_due(r, t[0])
        if not due:
            return
        u, v = ffi.new("double[]", self.ndof), ffi.new("double[]", self.ndof)
        f = ffi.new("double[]", max(self.m, 1))
        lib.fricreg_structure_get_state(s, self.ndof, u, v, ffi.NULL)
        lib.fricreg_structure_get_forces(s, max(self.m, 1), f)
        if r.count == r.capacity:
            self.grow()
        lib.fricreg_py_rows_append(r, t[0], u, v, f)

    def arrays(self):
        """times, u, v, f: the rows recorded (views: the recorder is done with them)."""
        k = self.rows.count
        return tuple(a[:k] for a in self._arrays)


def _estimate(s, getter, quantity, n):
    """An ErrorEstimate of n quantities from getter and their kinds, or None without one."""
    err, kind = np.empty(max(n, 1)), ffi.new("int[]", max(n, 1))
    if getter(s, n, ffi.from_buffer("double[]", err)) != lib.FRICREG_OK:
        return None
    if lib.fricreg_structure_get_error_kind(s, quantity, n, kind) != lib.FRICREG_OK:
        return None
    return ErrorEstimate(err[:n], np.array([_KINDS.get(kind[i], "unknown") for i in range(n)],
                                           dtype=str))


def _companions(s):
    """The EstimateCompanions of the estimate now, or None without one."""
    value = ffi.new("double *")
    lib.fricreg_structure_get_value(s, lib.FRICREG_SVALUE_COMPANIONS_USED, value)
    if value[0] < 0:
        return None
    used = "coarser" if value[0] == lib.FRICREG_COMPANIONS_COARSER else "finer"
    read = []
    for which in (lib.FRICREG_SVALUE_COMPANION_CPU, lib.FRICREG_SVALUE_SCREEN_PEAK_ERR,
                  lib.FRICREG_SVALUE_SCREEN_DISS_ERR):
        lib.fricreg_structure_get_value(s, which, value)
        read.append(value[0])
    return EstimateCompanions(used, *read)


def judge_warnings(s):
    """fricreg_structure_warning_count's list, judged now: [(name, message), ...]."""
    found = []
    code = ffi.new("int *")
    for k in range(lib.fricreg_structure_warning_count(s)):
        lib.fricreg_structure_get_warning(s, k, code, ffi.NULL, 0)
        found.append((ffi.string(lib.fricreg_warning_name(code[0])).decode(),
                      ffi.string(lib.fricreg_structure_warning_message(s, k)).decode()))
    return found


def read_result(s, recorder, ndof, m, sets, warnings):
    """The StructureResult of a run: the recorder's rows and the structure's getters now.
    m is the contacts' count (0: the library's one contact of bound 0 is not shown); sets are
    the element sets' (me, dim)."""
    mlib, me = max(m, 1), sum(n for n, _ in sets)
    value, count = ffi.new("double *"), ffi.new("int64_t *")
    peak, D = np.empty(ndof), np.empty(mlib)
    lib.fricreg_structure_get_peak_displacement(s, ndof, ffi.from_buffer("double[]", peak))
    lib.fricreg_structure_get_dissipation(s, mlib, ffi.from_buffer("double[]", D))
    De, fe = np.empty(max(me, 1)), np.empty(max(sum(n * dim for n, dim in sets), 1))
    if me:
        lib.fricreg_structure_get_elements(s, me, ffi.from_buffer("double[]", fe), ffi.NULL,
                                           ffi.from_buffer("double[]", De))
    forces, start = [], 0
    for n, dim in sets:
        forces.append(fe[start:start + n * dim].reshape(n, dim))
        start += n * dim
    energy = {}
    for name, which in _ENERGY:
        lib.fricreg_structure_get_value(s, which, value)
        energy[name] = value[0]
    stats = {}
    for name, which in _STATS:
        lib.fricreg_structure_get_stat(s, which, count)
        stats[name] = int(count[0])
    lib.fricreg_structure_get_value(s, lib.FRICREG_SVALUE_TIME, value)
    peak_err = _estimate(s, lib.fricreg_structure_get_peak_displacement_error,
                         lib.FRICREG_EST_PEAK_DISPLACEMENT, ndof)
    D_err = _estimate(s, lib.fricreg_structure_get_dissipation_error, lib.FRICREG_EST_DISSIPATION,
                      mlib)
    De_err = _estimate(s, lib.fricreg_structure_get_jenkins_dissipation_error,
                       lib.FRICREG_EST_ELEMENT_DISSIPATION, me)
    if D_err is not None:
        D_err = ErrorEstimate(D_err.error[:m], D_err.kind[:m])
    times, u, v, f = recorder.arrays()
    return StructureResult(times, u, v, f, np.array(recorder.dofs, dtype=np.int64), value[0],
                           peak, D[:m], De[:me], forces, energy, stats, peak_err, D_err, De_err,
                           warnings, _companions(s))
