# SPDX-License-Identifier: GPL-3.0-or-later
"""fricreg.Structure against its sources: `fricreg-sim structure` on the same Matrix Market
files and the C library called directly (bit for bit: the binding only forwards), the exact
solution of Newmark's average acceleration (a trapezoidal rotation), the paper's oscillator
sliding to rest, a stuck Jenkins element as a linear spring, checkpoints continuing a run bit
for bit, Ctrl-C stopping one, and every error path."""
import io
import json
import os
import signal
import subprocess
import sys
import warnings

import numpy as np
import pytest

import fricreg
from fricreg import _structure_result as structure_result
from fricreg._fricreg import ffi, lib
from conftest import fricreg_sim

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")



# ---- the ten-storey building of examples/building (building_model.h), in numpy ----------------

def building():
    """M, K, J, mun, the Rayleigh coefficients and the ground record (t0, dt_rec, a_g)."""
    n, mass, k, g = 10, 1e5, 1e8, 9.81
    K = 2 * k * np.eye(n) - k * np.eye(n, k=1) - k * np.eye(n, k=-1)
    K[-1, -1] = k
    t = 1e-3 * np.arange(10001)
    w0 = 2 * np.sqrt(k / mass)
    w1, w2 = (w0 * np.sin(j * np.pi / (2 * (2 * n + 1))) for j in (1, 3))
    return dict(M=mass * np.eye(n), K=K, J=np.eye(n) - np.eye(n, k=-1),
                mun=0.05 * g * mass * (n - np.arange(n)),
                rayleigh=(2 * 0.05 * w1 * w2 / (w1 + w2), 2 * 0.05 / (w1 + w2)),
                ground_accel=(0.0, 1e-3, 0.3 * g * np.sin(np.pi * t / 10) * np.sin(2 * np.pi * t)))


BUILDING = building()


def make_building(**settings):
    return fricreg.Structure(**{**BUILDING, "eps": 0.01, **settings})


def write_mtx(path, A):
    nonzero = np.argwhere(A != 0)
    with open(path, "w") as f:
        f.write("%%%%MatrixMarket matrix coordinate real general\n%d %d %d\n"
                % (A.shape[0], A.shape[1], len(nonzero)))
        f.writelines("%d %d %r\n" % (i + 1, j + 1, A[i, j]) for i, j in nonzero)


@pytest.fixture(scope="module")
def cli(tmp_path_factory):
    """`fricreg-sim structure` on the building's files, written from the arrays above (so the
    CLI reads the same doubles), with the options given."""
    d = tmp_path_factory.mktemp("building")
    for name in ("M", "K", "J"):
        write_mtx(d / (name + ".mtx"), BUILDING[name])
    np.savetxt(d / "mun.txt", BUILDING["mun"], fmt="%r")
    t0, dt_rec, ag = BUILDING["ground_accel"]
    np.savetxt(d / "ground.txt", np.column_stack([t0 + dt_rec * np.arange(ag.size), ag]),
               fmt="%r")
    a0, a1 = BUILDING["rayleigh"]
    base = [fricreg_sim(), "structure", "--mass", d / "M.mtx", "--stiffness", d / "K.mtx",
            "--rayleigh", "%r,%r" % (a0, a1), "--contacts", d / "J.mtx", "--mun", d / "mun.txt",
            "--ground-accel", d / "ground.txt"]

    def run(*options):
        out = subprocess.run([str(a) for a in base + list(options)], capture_output=True,
                             text=True, check=True)
        return out.stdout
    return run


def rows(result):
    """The CLI trajectory's columns: t, u, v, f."""
    return np.hstack([result.times[:, None], result.displacements, result.velocities,
                      result.forces])


def test_summary_equals_the_cli_bit_for_bit(cli):
    summary = json.loads(cli("--eps", "0.01", "--integrator", "newmark", "--dt", "0.01",
                             "--t-end", "15"))
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # the building in SI units raises no warning
        r = make_building(error_estimate="on").run("newmark", dt=0.01, t_end=15.0)
    u, v = r.displacements[-1], r.velocities[-1]
    assert u.tolist() == summary["x"] and v.tolist() == summary["v"]
    assert r.t == summary["t"] == 15.0 and r.stats["steps"] == summary["steps"] == 1500
    assert r.peak_displacement.tolist() == summary["peak_displacement"]
    assert r.dissipation.tolist() == summary["dissipation_per_contact"]
    assert r.peak_displacement_error.error.tolist() == summary["peak_displacement_error_estimate"]
    assert r.peak_displacement_error.kind.tolist() == summary["peak_displacement_error_kind"]
    assert r.dissipation_error.error.tolist() == summary["dissipation_per_contact_error_estimate"]
    assert r.dissipation_error.kind.tolist() == summary["dissipation_per_contact_error_kind"]
    for name, value in summary["energy_balance"].items():
        assert r.energy[name] == value, name
    assert r.stats["newton_iterations"] / r.stats["steps"] == summary["newton_iterations"]["mean"]
    assert r.stats["newton_max"] == summary["newton_iterations"]["max"]
    assert r.stats["newton_failures"] == summary["newton_failures"] == 0
    assert r.warnings == summary["warnings"] == []
    assert r.element_dissipation.shape == (0,) and r.element_dissipation_error.error.shape == (0,)
    # the screen (coarser) doubted the building and the finer confirmed it, as the CLI says
    used = r.estimate_companions
    assert used.used == summary["estimate_companions"] == "finer"
    assert used.screen_peak_displacement_error == summary["screen"]["peak_displacement_error"]
    assert used.screen_dissipation_error == summary["screen"]["dissipation_error"]
    assert 0 < used.cpu_seconds and summary["error_companions"] == "auto"
    # docs/structural.md's table: 0.2224 m and 1.542 MJ (its record from libm's sin)
    assert abs(r.peak_displacement[-1] - 0.2223898) < 1e-6
    assert abs(r.energy["friction"] - 1.542442e6) < 2.0


def test_the_default_eps_is_the_clis(cli):
    # 1 % of the record's peak ground velocity (docs/structural.md: 0.0047 m/s)
    summary = json.loads(cli("--integrator", "newmark", "--dt", "0.05", "--t-end", "0.1",
                             "--error-estimate", "off"))
    s = fricreg.Structure(**BUILDING)
    assert s.eps == summary["eps"] and round(s.eps, 4) == 0.0047 and s.law == "quinn"
    assert fricreg.Structure([[1.0]], [[1.0]], J=[[1.0]], mun=[1.0], law=5).eps == 1e-3
    assert fricreg.Structure([[1.0]], [[1.0]]).law is None


@pytest.mark.parametrize("integrator, options, settings, dt", [
    ("hht", ["--alpha", "-0.1"], dict(alpha=-0.1), 0.01),
    ("central", [], {}, 2e-4),
    ("rk4", [], {}, 5e-4),
    ("rkf45", ["--rtol", "1e-6"], dict(rtol=1e-6), 0.01),
])
def test_trajectory_equals_the_cli_bit_for_bit(cli, integrator, options, settings, dt):
    text = cli("--eps", "0.01", "--integrator", integrator, *options, "--dt", repr(dt),
               "--t-end", "4", "--output", "trajectory", "--output-dofs", "1,10",
               "--output-every", "7")
    expected = np.loadtxt(io.StringIO(text), delimiter=",", skiprows=1)
    r = make_building().run(integrator, dt=dt, t_end=4.0, output_dofs=[0, 9], output_every=7,
                            **settings)
    assert r.displacements.shape == (len(expected), 2) and r.forces.shape == (len(expected), 10)
    assert rows(r).tobytes() == expected.tobytes()
    assert r.times[0] == 0.0 and r.times[-1] == 4.0 and r.output_dofs.tolist() == [0, 9]
    assert r.warnings == []  # the dampers slide: eps_speed is not raised


# ---- the C library called directly ----------------------------------------------------------

def c_doubles(a):
    return ffi.new("double[]", np.ravel(a).tolist())


def c_structure(M, K, J, mun, eps, rayleigh=None, ground=None, element_sets=()):
    """The same model through fricreg_structure.h's calls, dense."""
    n, m = len(M), len(J)
    out = ffi.new("fricreg_structure **")
    assert lib.fricreg_structure_create(n, m, out) == 0
    s = ffi.gc(out[0], lib.fricreg_structure_free)
    assert lib.fricreg_structure_set_mass(s, n, c_doubles(M)) == 0
    assert lib.fricreg_structure_set_stiffness(s, n, c_doubles(K)) == 0
    if rayleigh is not None:
        assert lib.fricreg_structure_set_rayleigh(s, *rayleigh) == 0
    assert lib.fricreg_structure_set_contacts(s, m, n, c_doubles(J)) == 0
    assert lib.fricreg_structure_set_bounds(s, m, c_doubles(mun)) == 0
    if ground is not None:
        assert lib.fricreg_structure_set_ground_accel(s, ground[0], ground[1], len(ground[2]),
                                                      c_doubles(ground[2])) == 0
    for typ, Je, params in element_sets:
        assert lib.fricreg_structure_add_elements(s, typ, len(params), n, c_doubles(Je),
                                                  c_doubles(params)) == 0
    assert lib.fricreg_structure_set_law(s, lib.fricreg_law_from_name(b"quinn"), eps) == 0
    return s


def c_get(s, getter, n):
    a = ffi.new("double[]", n)
    assert getter(s, n, a) == 0
    return np.frombuffer(ffi.buffer(a), dtype=np.float64).copy()


def c_value(s, which):
    value = ffi.new("double *")
    lib.fricreg_structure_get_value(s, which, value)
    return value[0]


def test_equals_the_c_library_with_elements_of_two_types():
    b, n = BUILDING, 10
    jenkins = fricreg.Element("jenkins_2d", [3e7, 2e5])
    iwan = fricreg.Element("iwan", fricreg.segalman(6, 1.5e5, 4e7, -0.5, 0.1, 0.01))
    drifts = b["J"]  # two 2-D elements on the drifts of storeys (1, 2) and (3, 4)
    J1, J2 = drifts[:4], drifts[5:6]
    params1 = np.array([[3e7, 2e5], [2e7, 1e5]])
    s = c_structure(b["M"], b["K"], b["J"], b["mun"], 0.01, b["rayleigh"], b["ground_accel"],
                    [(jenkins._type, J1, params1), (iwan._type, J2, iwan.params[None, :])])
    assert lib.fricreg_structure_run(s, 0.01, 3.0) == 0
    r = make_building(elements=[("jenkins_2d", J1, params1), (iwan, J2)]).run(dt=0.01, t_end=3.0)
    u = c_get(s, lambda s, n, a: lib.fricreg_structure_get_state(s, n, a, ffi.NULL, ffi.NULL), n)
    assert r.displacements[-1].tobytes() == u.tobytes()
    assert r.forces[-1].tobytes() == c_get(s, lib.fricreg_structure_get_forces, n).tobytes()
    assert r.dissipation.tobytes() == c_get(s, lib.fricreg_structure_get_dissipation, n).tobytes()
    peak = c_get(s, lib.fricreg_structure_get_peak_displacement, n)
    assert r.peak_displacement.tobytes() == peak.tobytes()
    f, D = ffi.new("double[]", 5), ffi.new("double[]", 3)
    assert lib.fricreg_structure_get_elements(s, 3, f, ffi.NULL, D) == 0
    assert r.element_dissipation.tolist() == list(D) and r.energy["elements"] > 0
    assert [a.shape for a in r.element_forces] == [(2, 2), (1, 1)]
    assert np.concatenate([a.ravel() for a in r.element_forces]).tolist() == list(f)
    assert r.energy["residual"] == c_value(s, lib.FRICREG_SVALUE_RESIDUAL)
    assert abs(r.energy["residual"]) < 1e-6 * r.energy["input"]  # Newmark's balance is exact


def test_sparse_matrices_give_the_dense_results():
    sparse = pytest.importorskip("scipy.sparse")
    b = BUILDING
    Je, params = np.eye(10)[3:5], [3e7, 2e5]
    dense = make_building(elements=[("jenkins", Je, params)]).run(dt=0.02, t_end=4.0)
    r = make_building(M=sparse.diags(np.diag(b["M"])), K=sparse.csr_matrix(b["K"]),
                      J=sparse.coo_matrix(b["J"]),
                      elements=[("jenkins", sparse.csc_matrix(Je), params)]).run(dt=0.02,
                                                                                  t_end=4.0)
    assert rows(r).tobytes() == rows(dense).tobytes()
    assert r.dissipation.tobytes() == dense.dissipation.tobytes()
    assert r.element_dissipation.tobytes() == dense.element_dissipation.tobytes()


def test_scipy_is_imported_only_for_a_sparse_matrix():
    code = ("import sys, fricreg; s = fricreg.Structure([[2.0]], [[3.0]]); "
            "s.run(dt=0.1, t_end=1.0); print('scipy' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "False"


# ---- closed forms -----------------------------------------------------------------------------

def test_newmark_is_the_trapezoidal_rotation():
    # tests/structure/test_structure.c: average acceleration on m u'' + k u = 0 from (u0, 0) is the
    # Cayley transform of [[0, 1], [-w^2, 0]]: u_n = u0 cos(wb t_n), tan(wb dt/2) = w dt/2.
    mass, w, u0, dt = 2.385, 1.7, 0.0371, 0.137
    s = fricreg.Structure([[mass]], [[mass * w * w]], u0=[u0])
    r = s.run(dt=dt, t_end=400 * dt)
    wb = 2 * np.arctan(w * dt / 2) / dt
    np.testing.assert_allclose(r.displacements[:, 0], u0 * np.cos(wb * r.times), rtol=0,
                               atol=1e-12 * u0)
    np.testing.assert_allclose(r.velocities[:, 0], -u0 * w * np.sin(wb * r.times), rtol=0,
                               atol=1e-12 * u0 * w)
    assert r.times.shape == (401,) and r.forces.shape == (401, 0) and r.dissipation.shape == (0,)
    e0 = 0.5 * mass * w * w * u0 * u0
    assert r.energy["initial"] == pytest.approx(e0, rel=1e-15)
    assert abs(r.energy["residual"]) < 1e-12 * e0 and r.stats["newton_max"] <= 1


def test_the_paper_oscillator_slides_to_rest():
    # tests/structure/test_structure.c: M = K = J = 1, mun = 1, from x0 = 2.75 the exact motion
    # slides to -0.75 at t = pi and sticks, dissipating mun * 3.5; law (4) within eps^2/2 (eps = 2 dt).
    dt = 1e-3
    s = fricreg.Structure([[1.0]], [[1.0]], J=[[1.0]], mun=[1.0], eps=2 * dt, u0=[2.75])
    r = s.run(dt=dt, t_end=8.0, output_every=1000)
    tol = 0.5 * (2 * dt) ** 2
    assert r.times.tolist() == [float(k) for k in range(9)]
    assert r.displacements[-1, 0] == pytest.approx(-0.75, abs=tol)
    assert r.dissipation[0] == pytest.approx(3.5, abs=tol)
    assert r.forces[-1, 0] == pytest.approx(r.displacements[-1, 0], abs=1e-10)  # f holds k u
    later = s.run(dt=dt, t_end=12.0)
    assert later.displacements[-1, 0] == r.displacements[-1, 0]  # stuck: not one ulp of creep


def test_a_stuck_jenkins_element_is_a_spring():
    # a Jenkins element whose bound is never reached adds kt to k: the trapezoidal rotation of
    # w^2 = (k + kt)/m, elements only (no contacts).
    mass, k, kt, u0, dt = 2.385, 3.1, 4.7, 0.0371, 0.05
    s = fricreg.Structure([[mass]], [[k]], elements=[(fricreg.Element("jenkins", [kt, 1e3]),
                                                      [[1.0]])], u0=[u0])
    r = s.run(dt=dt, t_end=200 * dt)
    w = np.sqrt((k + kt) / mass)
    wb = 2 * np.arctan(w * dt / 2) / dt
    np.testing.assert_allclose(r.displacements[:, 0], u0 * np.cos(wb * r.times), rtol=0,
                               atol=1e-12 * u0)
    assert r.element_forces[0][0, 0] == pytest.approx(kt * r.displacements[-1, 0], abs=1e-12)
    assert r.element_dissipation.tolist() == [0.0] and s.nelements == 1


# ---- checkpoints, Ctrl-C, warnings ----------------------------------------------------------

def test_a_checkpoint_continues_the_run_bit_for_bit():
    whole = make_building(error_estimate="on").run("hht", dt=0.01, t_end=4.0, alpha=-0.1)
    first = make_building(error_estimate="on")
    with pytest.warns(fricreg.AccuracyWarning, match="eps_speed"):  # the dampers hold till 2.78 s
        first.run("hht", dt=0.01, t_end=2.0, alpha=-0.1)
    data = first.save()
    second = make_building(error_estimate="on")
    second.restore(data, integrator="hht", alpha=-0.1)
    assert second.t == 2.0
    rest = second.run("hht", dt=0.01, t_end=4.0, alpha=-0.1)
    assert rows(rest).tobytes() == rows(whole)[200:].tobytes()
    for name in ("peak_displacement", "dissipation"):
        assert getattr(rest, name).tobytes() == getattr(whole, name).tobytes()
    assert rest.dissipation_error.error.tobytes() == whole.dissipation_error.error.tobytes()
    assert rest.energy == whole.energy and rest.stats == whole.stats
    with pytest.raises(fricreg.InputError, match="Structure.restore: data: .*eps"):
        make_building(eps=0.02, error_estimate="on").restore(data, integrator="hht", alpha=-0.1)
    with pytest.raises(fricreg.InputError, match="Structure.restore: data: "):
        make_building().restore(data[:-7])
    with pytest.raises(fricreg.InputError, match="data: a str is not bytes-like"):
        make_building().restore("checkpoint")
    with pytest.raises(ValueError, match="integrator: 'rk4' is not one of newmark, hht, central"):
        make_building().restore(data, integrator="rk4")


def test_ctrl_c_stops_the_run_where_it_is(monkeypatch):
    whole = make_building().run(dt=0.01, t_end=4.0)

    def interrupted(self):  # Ctrl-C pressed during the 300th step
        if self.count == 301:
            signal.raise_signal(signal.SIGINT)
    monkeypatch.setattr(structure_result.Recorder, "CHECK_INTERVAL", 0.0)  # a check each step
    monkeypatch.setattr(structure_result.Recorder, "check", interrupted)
    s = make_building()
    with pytest.raises(KeyboardInterrupt) as info:
        s.run(dt=0.01, t_end=4.0)
    monkeypatch.undo()
    stopped = info.value.result
    # the step during which it was pressed completes, and its state ends the result
    assert s.t == stopped.t == stopped.times[-1] == whole.times[300]
    assert rows(stopped).tobytes() == rows(whole)[:301].tobytes()
    rest = s.run(dt=0.01, t_end=4.0)  # the structure is consistent: it continues the run
    assert rows(rest).tobytes() == rows(whole)[300:].tobytes()
    assert rest.dissipation.tobytes() == whole.dissipation.tobytes()


def test_warnings_of_units_are_raised_once():
    # docs/structural.md, "Warnings": eps typed in mm/s (2.354 for 0.002354 m/s)
    s = make_building(eps=2.354)
    with pytest.warns(fricreg.AccuracyWarning) as caught:
        r = s.run(dt=0.01, t_end=15.0)
    names = [name for name, _ in r.warnings]
    assert names == ["eps_large", "eps_speed"]
    assert [str(w.message).split(":")[0] for w in caught] == names
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        again = s.run(dt=0.01, t_end=16.0)  # listed again, not warned again
    assert [name for name, _ in again.warnings] == names
    s.reset()
    with pytest.warns(fricreg.AccuracyWarning, match="eps_large"):
        s.run(dt=0.01, t_end=1.0)


def test_inputs_are_never_modified():
    arrays = {name: (value.copy() if isinstance(value, np.ndarray) else value)
              for name, value in BUILDING.items()}
    J1, params, u0 = np.eye(10)[:1], np.array([[3e7, 2e5]]), np.full(10, 1e-3)
    J1_copy, params_copy, u0_copy = J1.copy(), params.copy(), u0.copy()
    make_building(elements=[("jenkins", J1, params)], u0=u0).run(dt=0.05, t_end=0.5)
    for name, value in BUILDING.items():
        if isinstance(value, np.ndarray):
            assert value.tobytes() == arrays[name].tobytes(), name
    assert BUILDING["ground_accel"][2].tobytes() == building()["ground_accel"][2].tobytes()
    assert J1.tobytes() == J1_copy.tobytes() and params.tobytes() == params_copy.tobytes()
    assert u0.tobytes() == u0_copy.tobytes()


# ---- every error path -----------------------------------------------------------------------

@pytest.mark.parametrize("settings, error, match", [
    (dict(M=np.ones((2, 3))), ValueError, r"M: shape \(2, 3\); expected \(ndof, ndof\)"),
    (dict(M=-np.eye(10)), fricreg.InputError, "Structure: M: set_matrix: .*not positive definite"),
    (dict(M=np.eye(10).astype(complex)), ValueError, "M: dtype complex128"),
    (dict(K=np.eye(3)), ValueError, r"K: shape \(3, 3\); expected \(10, 10\)"),
    (dict(K=np.triu(np.ones((10, 10)))), fricreg.InputError, "K: set_matrix: .*not symmetric"),
    (dict(damping=np.eye(10)), ValueError, "rayleigh: give damping or rayleigh, not both"),
    (dict(rayleigh=(-1.0, 0.0)), fricreg.InputError, "rayleigh: set_rayleigh"),
    (dict(rayleigh=(1.0,)), ValueError, r"rayleigh: shape \(1,\); expected \(2,\)"),
    (dict(mun=None), ValueError, "mun: J and mun come together"),
    (dict(mun=-BUILDING["mun"]), fricreg.InputError, r"mun: set_bounds: mun\[0\] = -49050"),
    (dict(mun=[1.0]), ValueError, r"mun: shape \(1,\); expected \(10,\)"),
    (dict(J=np.zeros((10, 10))), fricreg.InputError, "J: set_matrix: row 0 of J is zero"),
    (dict(J=np.eye(10)[:, :3]), ValueError, r"J: shape \(10, 3\); expected \(10, 10\)"),
    (dict(law="stribeck"), ValueError, "law: 'stribeck' is not a law"),
    (dict(eps=-1.0), fricreg.InputError, "eps: set_law: eps = -1"),
    (dict(eps=float("nan")), fricreg.InputError, "eps: set_law"),
    (dict(influence=np.ones(3)), ValueError, r"influence: shape \(3,\)"),
    (dict(ground_accel=[1.0, 2.0]), ValueError, r"ground_accel: expected \(t0, dt_rec, samples\)"),
    (dict(ground_accel=(0.0, 0.01, [1.0])), ValueError, "ground_accel: 1 samples"),
    (dict(ground_accel=(0.0, -0.01, [1.0, 2.0])), fricreg.InputError, "ground_accel: "),
    (dict(ground_accel=(0.0, 0.01, [1.0, np.inf])), fricreg.InputError, "ground_accel: "),
    (dict(load=np.ones(3)), ValueError, r"load: shape \(3,\); expected \(10,\)"),
    (dict(load_history=(0.0, 1.0, [1.0, 1.0])), ValueError, "load_history: the time function"),
    (dict(load=np.ones(10), load_history=(0.0, 0.0, [1.0, 1.0])), fricreg.InputError,
     "load_history: set_load"),
    (dict(elements=[("jenkins",)]), ValueError, r"elements\[0\]: expected \(element, J\)"),
    (dict(elements=[(3, np.eye(10))]), ValueError, r"elements\[0\]: 3 is neither an Element"),
    (dict(elements=[("jenkins", np.eye(10))]), ValueError,
     r"elements\[0\]: the parameters of jenkins elements are missing"),
    (dict(elements=[("slider", np.eye(10), [1.0, 1.0])]), ValueError,
     r"elements\[0\]: name: 'slider' is not an element type"),
    (dict(elements=[("jenkins", np.eye(10), [1.0, 2.0, 3.0])]), ValueError,
     r"elements\[0\]: params: jenkins takes 2 parameters, not 3"),
    (dict(elements=[("jenkins_2d", np.eye(10)[:3], [1.0, 2.0])]), ValueError,
     r"elements\[0\] J: shape \(3, 10\); expected \(me \* 2, 10\)"),
    (dict(elements=[("jenkins", np.eye(10)[:2], np.ones((3, 2)))]), ValueError,
     r"elements\[0\] params: shape \(3, 2\); expected \(2, 2\)"),
    (dict(elements=[("jenkins", np.eye(10)[:1], [-1.0, 2.0])]), fricreg.InputError,
     r"elements\[0\]: add_elements"),
    (dict(u0=np.ones(3)), ValueError, r"u0: shape \(3,\)"),
    (dict(v0=np.full(10, np.nan)), fricreg.InputError, "u0, v0: set_initial"),
    (dict(newton_tol=2.0), fricreg.InputError, "newton_tol: set_newton"),
    (dict(contact_solver="lu"), ValueError, "contact_solver: 'lu' is not one of 'auto', 'dense'"),
    (dict(error_estimate=True), ValueError, "error_estimate: True is not one of 'off', 'on', 'one'"),
    (dict(error_companions="both"), ValueError, "error_companions: 'both' is not one of"),
    (dict(answer_rtol=0.0), fricreg.InputError, "answer_rtol: set_answer_rtol"),
])
def test_bad_settings_are_refused_naming_them(settings, error, match):
    with pytest.raises(error, match=match):
        make_building(**settings)


def test_no_contacts_means_no_law():
    with pytest.raises(ValueError, match="eps: the contacts' friction law: without J"):
        fricreg.Structure([[1.0]], [[1.0]], eps=0.1)
    with pytest.raises(ValueError, match="J: J and mun come together"):
        fricreg.Structure([[1.0]], [[1.0]], mun=[1.0])


def oscillator(**settings):
    """One mass on a spring with a contact, pushed off at 0.37 m/s."""
    return fricreg.Structure([[1.0]], [[2.385]], J=[[1.0]], mun=settings.pop("mun", [0.3]),
                             v0=[0.37], **settings)


def test_set_methods_change_the_contacts_between_runs():
    # set_law and set_bounds then reset: the run is a fresh structure's with those settings
    s = oscillator(law="quinn", eps=1e-3)
    s.run(dt=1e-3, t_end=0.05)
    s.set_law("tanh", 2.5e-3)
    s.set_bounds(0.21)  # a scalar for every contact
    s.reset(v0=[0.37])
    assert (s.law, s.eps, s.mun.tolist()) == ("tanh", 2.5e-3, [0.21])
    fresh = oscillator(law="tanh", eps=2.5e-3, mun=[0.21])
    a, b = s.run(dt=1e-3, t_end=0.3), fresh.run(dt=1e-3, t_end=0.3)
    assert a.displacements.tobytes() == b.displacements.tobytes()
    assert a.forces.tobytes() == b.forces.tobytes() and a.forces.any()
    s.set_law("quinn")  # eps kept
    assert (s.law, s.eps) == ("quinn", 2.5e-3)
    mun = s.mun
    mun[0] = 9.0  # a copy
    assert s.mun.tolist() == [0.21]


def test_set_methods_refuse_and_keep_the_settings():
    s = oscillator(law="karnopp", eps=1e-3)
    for call, argument in ((lambda: s.set_law("dahl"), "law"),
                           (lambda: s.set_law("tanh", 0.0), "eps"),
                           (lambda: s.set_law("tanh", "small"), "eps"),
                           (lambda: s.set_bounds([-0.3]), "mun"),
                           (lambda: s.set_bounds([0.3, 0.4]), "mun")):
        with pytest.raises(fricreg.InputError, match=r"(^|: )%s: " % argument):
            call()
    assert (s.law, s.eps, s.mun.tolist()) == ("karnopp", 1e-3, [0.3])
    kept = s.run(dt=1e-3, t_end=0.2)
    assert kept.displacements.tobytes() == oscillator(law="karnopp", eps=1e-3).run(
        dt=1e-3, t_end=0.2).displacements.tobytes()
    bare = fricreg.Structure([[1.0]], [[1.0]])
    for call, argument in ((lambda: bare.set_law("quinn", 1e-3), "law"),
                           (lambda: bare.set_bounds([0.3]), "mun")):
        with pytest.raises(fricreg.InputError, match="%s: the structure has no friction "
                           "contacts" % argument):
            call()
    for name in ("ndof", "ncontacts", "nelements", "mun"):
        with pytest.raises(AttributeError):
            setattr(s, name, 2)  # fixed at construction, or set by a method


@pytest.mark.parametrize("name, value", [("law", "tanh"), ("eps", 2.5e-3)])
def test_assigning_the_law_warns_and_sets_it(name, value):
    s = oscillator()
    with pytest.warns(DeprecationWarning, match=r"Structure: setting %s by assignment is "
                      r"deprecated and will end in 2.0 .*: call set_law\(" % name) as record:
        setattr(s, name, value)
    assert record[0].filename == __file__ and getattr(s, name) == value
    with pytest.warns(DeprecationWarning), pytest.raises(fricreg.InputError):
        setattr(s, name, "bad")
    assert getattr(s, name) == value


@pytest.mark.parametrize("arguments, error, match", [
    (dict(integrator="euler"), ValueError, "integrator: 'euler' is not one of newmark, hht"),
    (dict(integrator="central-imex"), ValueError, "integrator: 'central-imex' is not one of"),
    (dict(alpha=-0.1), ValueError, "alpha: only integrator 'hht' has alpha"),
    (dict(integrator="hht", alpha=-0.5), fricreg.InputError, "alpha: set_hht"),
    (dict(rtol=1e-6), ValueError, "rtol: only GSL's steppers are adaptive"),
    (dict(atol=1e-6), ValueError, "atol: only GSL's steppers are adaptive"),
    (dict(dt=0.0), ValueError, "dt: 0.0 must be finite and > 0"),
    (dict(dt=np.nan), ValueError, "dt: nan must be finite and > 0"),
    (dict(t_end=0.0), ValueError, "t_end: 0.0 must be finite and after the structure's time 0.0"),
    (dict(output_dofs=[0, 10]), ValueError, r"output_dofs: dof 10 is not in 0 .. 9"),
    (dict(output_dofs=[0.5]), ValueError, "output_dofs: expected a sequence of dof numbers"),
    (dict(output_every=0), ValueError, "output_every: 0 must be a whole number >= 1"),
    (dict(integrator="msbdf", rtol=1e-6, atol=0.0), fricreg.InputError, "Structure.run: "),
])
def test_bad_run_arguments_are_refused_naming_them(arguments, error, match):
    s = make_building()
    with pytest.raises(error, match=match):
        s.run(**{"dt": 0.01, "t_end": 0.1, **arguments})
    assert s.t == 0.0


def test_a_failed_run_keeps_its_result():
    # central differences beyond their stability bound: FRICREG_ESTEP at the first step
    s = make_building()
    with pytest.raises(fricreg.Error, match="Structure.run: after t = 0: .*") as info:
        s.run("central", dt=0.01, t_end=1.0)
    assert info.value.name == "FRICREG_ESTEP" and info.value.result.times.tolist() == [0.0]
    with pytest.raises(fricreg.InputError, match="Structure.run: "):
        make_building(elements=[("jenkins", np.eye(10)[:1], [1e7, 1e5])]).run(
            "rk4", dt=1e-3, t_end=0.01)
