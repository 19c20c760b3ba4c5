# SPDX-License-Identifier: GPL-3.0-or-later
"""fricreg.HarmonicBalance against the C library driven directly on the same inputs (bit for
bit), the closed forms of a Jenkins oscillator (its stuck linear response, its backbone's
describing function), and its Ctrl-C and thread promises."""
import signal
import subprocess
import sys
import threading
import _thread
import time

import numpy as np
import pytest

import fricreg
from fricreg._fricreg import ffi, lib

H = 7
NC = 2 * H + 1
# NLvib's 3-dof chain (bench/nlvib/chain_jenkins.m): unit masses and springs ground-1-2-3,
# dampers 0.02 K, force cos Ωt on dof 2, Jenkins kt = 20, mu N = 1 at dof 1 and between 1, 2.
M = np.eye(3)
K = np.array([[2.0, -1.0, 0.0], [-1.0, 2.0, -1.0], [0.0, -1.0, 2.0]])
C = 0.02 * K
J = np.array([[1.0, 0.0, 0.0], [-1.0, 1.0, 0.0]])
P = np.array([0.0, 1.0, 0.0])


def chain(**kwargs):
    hb = fricreg.HarmonicBalance(M, K, C, elements=[(fricreg.Element("jenkins", [20.0, 1.0]), J)],
                                 harmonics=H, excitation=(P, None), **kwargs)
    return hb


def c_chain():
    """The same chain through the C API alone."""
    out = ffi.new("fricreg_hb **")
    assert lib.fricreg_hb_create(3, 2, H, out) == 0
    hb = ffi.gc(out[0], lib.fricreg_hb_free)
    d = ffi.NULL
    for which, matrix in ((lib.FRICREG_MASS, M), (lib.FRICREG_STIFFNESS, K),
                          (lib.FRICREG_DAMPING, C)):
        values = ffi.new("double[]", matrix.ravel().tolist())
        assert lib.fricreg_hb_set_matrix(hb, which, 3, 3, lib.FRICREG_MATRIX_DENSE, d, d,
                                         values) == 0
    params = ffi.new("double[]", [20.0, 1.0, 20.0, 1.0])
    jenkins = lib.fricreg_element_lookup(b"jenkins")
    assert lib.fricreg_hb_add_elements(hb, jenkins, 2, 3, ffi.new("double[]", J.ravel().tolist()),
                                       params) == 0
    assert lib.fricreg_hb_set_excitation(hb, 3, ffi.new("double[]", P.tolist()),
                                         ffi.new("double[]", 3)) == 0
    return hb


def c_branch(hb, stability):
    """omega, rms, stable, mu_max and coefficients x of the C driver's stored branch."""
    n = lib.fricreg_hb_points(hb)
    omega, rms, stable, mu = np.empty(n), np.empty((n, 3)), np.empty(n, bool), np.empty(n)
    x = np.empty((n, 3, NC))
    w, s, m = ffi.new("double *"), ffi.new("int *"), ffi.new("double *")
    for k in range(n):
        r, xk = ffi.new("double[]", 3), ffi.new("double[]", 3 * NC)
        assert lib.fricreg_hb_point(hb, k, w, 3, r) == 0
        assert lib.fricreg_hb_point_displacement(hb, k, 3, NC, xk) == 0
        omega[k], rms[k], x[k] = w[0], list(r), np.reshape(list(xk), (3, NC))
        if stability:
            assert lib.fricreg_hb_point_stability(hb, k, s, m) == 0
            stable[k], mu[k] = s[0], m[0]
    return omega, rms, stable, mu, x


def test_chain_sweep_with_stability_equals_the_c_library():
    hb = chain()
    hb.set_stability(True)
    r = hb.frequency_response(0.5, 2.0)
    c = c_chain()
    assert lib.fricreg_hb_set_stability(c, 1) == 0
    assert lib.fricreg_hb_continue(c, 0.5, 2.0, 2 * NC, ffi.NULL) == 0
    omega, rms, stable, mu, x = c_branch(c, True)
    assert r.omega.tobytes() == omega.tobytes()
    assert r.rms.tobytes() == rms.tobytes()
    assert r.x.tobytes() == x.tobytes() and r.solution.x.tobytes() == x[-1].tobytes()
    # each point's coefficients give its RMS, sqrt(x0² + Σ (a_h² + b_h²)/2)
    weights = np.r_[1.0, np.full(NC - 1, 0.5)]
    np.testing.assert_allclose(np.sqrt((r.x ** 2) @ weights), r.rms, rtol=1e-14, atol=0)
    assert np.array_equal(r.stable, stable) and r.mu_max.tobytes() == mu.tobytes()
    assert np.all(r.level == 1.0)
    assert r.solution.omega == 2.0 and r.solution.x.shape == (3, NC)
    restart = hb.solve(2.0, guess=r.solution.q)  # the branch's end, a guess to go on from
    np.testing.assert_allclose(restart.x, r.solution.x, rtol=0, atol=1e-9 * np.abs(r.rms).max())
    # the peak lies between the slipped and stuck chains' first resonances
    peak_omega, peak_rms = hb.peak(1)
    assert 0.76 < peak_omega < 1.7 and peak_rms >= r.rms[:, 1].max()


def test_newton_solvers_agree_to_rounding():
    # "dense" is 1.9's solver and "auto" the same below 512 unknowns, bit for bit; the
    # capacitance agrees to rounding (tests/hb/test_hb_capacitance.c: 1e-10 on every element)
    hb = chain()
    hb.set_newton(solver="dense")
    dense = hb.solve(1.2)
    hb.set_newton(solver="auto")
    assert hb.solve(1.2).q.tobytes() == dense.q.tobytes()
    hb.set_newton(solver="capacitance")
    hb.set_newton(tol=1e-10)  # the tolerance alone leaves the solver chosen
    assert hb.solve(1.2).q.tobytes() != dense.q.tobytes()
    np.testing.assert_allclose(hb.solve(1.2).q, dense.q, rtol=0, atol=1e-10 * np.abs(dense.q).max())
    with pytest.raises(fricreg.InputError, match="solver"):
        hb.set_newton(solver="sparse")


def test_receptance_methods_agree_to_rounding():
    # Rayleigh damping: "lu" is 1.9's and "auto" the same below 200 dofs, bit for bit; the
    # modes agree to rounding (tests/hb/test_hb_receptance.c: 1e-10 on every harmonic)
    hb = fricreg.HarmonicBalance(M, K, elements=[(fricreg.Element("jenkins", [20.0, 1.0]), J)],
                                 harmonics=H, excitation=(P, None), rayleigh=(0.01, 0.002))
    hb.set_receptance("lu")
    lu = hb.solve(1.2)
    hb.set_receptance()
    assert hb.solve(1.2).q.tobytes() == lu.q.tobytes()
    hb.set_receptance("modes")
    modes = hb.solve(1.2)
    assert modes.q.tobytes() != lu.q.tobytes()
    np.testing.assert_allclose(modes.q, lu.q, rtol=0, atol=1e-10 * np.abs(lu.q).max())
    with pytest.raises(fricreg.InputError, match="method"):
        hb.set_receptance("klu")


def test_condensed_stability_is_the_c_librarys_by_name():
    # "condensed" names FRICREG_HB_STABILITY_CONDENSED; on the 3-dof chain (one dof no element
    # touches, kept below 50 Omega) its multipliers are the whole model's; the C library's
    # tests/floquet/test_hb_condensed.c checks larger models
    hb = chain()
    hb.set_stability(True, "condensed")
    out = ffi.new("int *")
    assert lib.fricreg_hb_get_stability_method(hb._hb, out) == 0
    assert out[0] == lib.FRICREG_HB_STABILITY_CONDENSED
    condensed = hb.solve(1.2)
    hb.set_stability(True, "monodromy")
    whole = hb.solve(1.2, guess=condensed.q)
    assert condensed.stable == whole.stable
    assert abs(condensed.mu_max - whole.mu_max) <= 1e-9


def test_stuck_multipliers_are_the_linear_oscillators():
    # one dof, m = 1, c = 0.1, k = 3 and a Jenkins element kt = 1 that sticks throughout: the
    # multipliers are exp(λ T) of λ² + c λ + k + kt = 0, by decreasing modulus (equal here),
    # on a solution and on each point of a branch
    hb = fricreg.HarmonicBalance([[1.0]], [[3.0]], [[0.1]],
                                 elements=[(fricreg.Element("jenkins", [1.0, 1.0]), [[1.0]])],
                                 harmonics=H, excitation=([0.1], None))
    hb.set_stability(True, "monodromy")
    lam = np.roots([1.0, 0.1, 4.0])
    s = hb.solve(1.0)
    expected = np.exp(2.0 * np.pi / 1.0 * lam)
    assert s.multipliers.shape == (2,) and s.stable
    np.testing.assert_allclose(np.sort_complex(s.multipliers), np.sort_complex(expected),
                               rtol=0, atol=1e-12)
    assert abs(np.abs(s.multipliers[0]) - s.mu_max) <= 1e-15
    r = hb.frequency_response(0.9, 1.1)
    assert r.multipliers.shape == (r.omega.size, 2)
    for omega, mu in zip(r.omega, r.multipliers):
        np.testing.assert_allclose(np.sort_complex(mu),
                                   np.sort_complex(np.exp(2.0 * np.pi / omega * lam)),
                                   rtol=0, atol=1e-12)
    hb.set_stability(False)
    assert hb.solve(1.0).multipliers is None


def test_stuck_response_is_linear():
    # one dof, m = 1, c = 0.1, k = 3 and a stuck Jenkins element kt = 1 (examples/hb_frf.c):
    # |X| = F / |k + kt - m Ω² + i c Ω| = 0.1 / |3 + 0.1 i| at Ω = 1
    hb = fricreg.HarmonicBalance([[1.0]], [[3.0]], [[0.1]],
                                 elements=[(fricreg.Element("jenkins", [1.0, 1.0]), [[1.0]])],
                                 harmonics=H, excitation=([0.1], None))
    s = hb.solve(1.0)
    assert abs(np.hypot(s.x[0, 1], s.x[0, 2]) - 0.1 / abs(3 + 0.1j)) <= 1e-13
    assert np.all(np.abs(s.x[0, 3:]) <= 1e-15) and s.stable is None and np.isnan(s.mu_max)
    again = hb.solve(1.0, guess=s.q)
    assert again.x.tobytes() == s.x.tobytes() or np.allclose(again.x, s.x, atol=1e-15)


def describing_function(a, kt=2.0, mun=3.0):
    """ω² and ζ of x'' + x + f = 0 at x = a cos θ, f a Jenkins element, H = 1
    (tests/nma/test_hb_nma.c derives them)."""
    delta = mun / kt
    if a <= delta:
        return 1 + kt, 0.0
    beta = np.arccos(1 - 2 * delta / a)
    w2 = 1 + kt / np.pi * (beta - 0.5 * np.sin(2 * beta))
    return w2, 4 * mun * (a - delta) / (2 * np.pi * a * a * w2)


def test_backbone_closed_form_and_c_library():
    hb = fricreg.HarmonicBalance([[1.0]], [[1.0]], elements=[("jenkins", [[1.0]], [[2.0, 3.0]])],
                                 harmonics=1)
    b = hb.backbone(0, 0.5, 1000.0, 16, through_folds=False)  # fricreg_hb_nma
    for a, w, z in zip(b.amplitude, b.omega, b.zeta):
        w2, zeta = describing_function(a)
        assert abs(w * w - w2) <= 1e-9 * w2 and abs(z - zeta) <= 1e-9 * max(zeta, 1e-3)
    np.testing.assert_allclose(b.harmonic_energy[:, 1], 1.0, rtol=1e-12)
    np.testing.assert_allclose(b.x[:, 0, 1], b.amplitude, rtol=1e-9)
    assert b.special_points == ()
    np.testing.assert_allclose(hb.modal_participation(3, 1), [1.0], rtol=1e-12)
    # the same through the C API
    out = ffi.new("fricreg_hb **")
    assert lib.fricreg_hb_create(1, 1, 1, out) == 0
    c = ffi.gc(out[0], lib.fricreg_hb_free)
    one, p = ffi.new("double[]", [1.0]), ffi.new("double[]", [2.0, 3.0])
    d = ffi.NULL
    assert lib.fricreg_hb_set_matrix(c, lib.FRICREG_MASS, 1, 1, 0, d, d, one) == 0
    assert lib.fricreg_hb_set_matrix(c, lib.FRICREG_STIFFNESS, 1, 1, 0, d, d, one) == 0
    assert lib.fricreg_hb_add_elements(c, lib.fricreg_element_lookup(b"jenkins"), 1, 1, one, p) == 0
    assert lib.fricreg_hb_nma(c, 0, 0, 0.5, 1000.0, 16) == 0
    a, w, z = ffi.new("double *"), ffi.new("double *"), ffi.new("double *")
    for i in range(16):
        assert lib.fricreg_hb_nma_point(c, i, a, w, z, 0, 0, ffi.NULL) == 0
        assert (a[0], w[0], z[0]) == (b.amplitude[i], b.omega[i], b.zeta[i])


def test_backbone_sensitivities_against_the_closed_form():
    """dω/dp, dζ/dp of the describing function's closed form (differentiated here by central
    differences of the formula itself, step 1e-6), for kt, mun, the amplitude; and a
    parameter of a single element shared (count 1) is the same as per element."""
    hb = fricreg.HarmonicBalance([[1.0]], [[1.0]], elements=[("jenkins", [[1.0]], [[2.0, 3.0]])],
                                 harmonics=1)
    b = hb.backbone(0, 0.5, 1000.0, 16)
    i = 8
    a = b.amplitude[i]
    assert a > 1.5  # slipping: mun/kt = 1.5
    dw, dz, damp = hb.backbone_sensitivities(
        i, [("element", 0, 1, 0), ("element", 0, 1, 1), ("amplitude",)], amplitudes=True)

    def closed(kt=2.0, mun=3.0, amp=a):
        w2, zeta = describing_function(amp, kt, mun)
        return np.sqrt(w2), zeta

    steps = [("kt", 2.0), ("mun", 3.0), ("amp", a)]
    for k, (name, value) in enumerate(steps):
        h = 1e-6 * value
        up, down = closed(**{name: value + h}), closed(**{name: value - h})
        assert dw[k] == pytest.approx((up[0] - down[0]) / (2 * h), rel=1e-7, abs=1e-12)
        assert dz[k] == pytest.approx((up[1] - down[1]) / (2 * h), rel=1e-7, abs=1e-12)
    assert damp.shape == (3, 1) and damp[2, 0] == pytest.approx(1.0, rel=1e-9)  # |X_1| = a
    at = hb.backbone_at(0, [0.7, 2.385, 41.7])  # a test's levels, off the grid
    for a_i, w, z in zip(at.amplitude, at.omega, at.zeta):
        w2, zeta = describing_function(a_i)
        assert abs(w * w - w2) <= 1e-9 * w2 and abs(z - zeta) <= 1e-9 * max(zeta, 1e-3)
    np.testing.assert_allclose(at.amplitude, [0.7, 2.385, 41.7], rtol=1e-15)
    with pytest.raises(fricreg.InputError, match="increase"):
        hb.backbone_at(0, [2.0, 1.0])
    with pytest.raises(ValueError, match="params"):
        hb.backbone_sensitivities(i, [("stiffness", 0)])
    with pytest.raises(fricreg.InputError):
        hb.backbone_sensitivities(i, [("element", 0, 2, 0)])  # one element only


def test_element_param_set_in_place_is_the_model_built_so():
    """A parameter moved in place gives the backbone of the oscillator built with it (bit for
    bit), and that backbone is the describing function's at the new mun."""
    hb = fricreg.HarmonicBalance([[1.0]], [[1.0]], elements=[("jenkins", [[1.0]], [[2.0, 3.0]])],
                                 harmonics=1)
    hb.set_element_param(0, 1, 1, 4.5)
    assert (hb.element_param(0, 0), hb.element_param(0, 1)) == (2.0, 4.5)
    built = fricreg.HarmonicBalance([[1.0]], [[1.0]],
                                    elements=[("jenkins", [[1.0]], [[2.0, 4.5]])], harmonics=1)
    moved, fresh = hb.backbone(0, 0.5, 1000.0, 16), built.backbone(0, 0.5, 1000.0, 16)
    assert (moved.omega == fresh.omega).all() and (moved.zeta == fresh.zeta).all()
    for a, w in zip(moved.amplitude, moved.omega):
        w2, _ = describing_function(a, 2.0, 4.5)
        assert abs(w * w - w2) <= 1e-9 * w2
    with pytest.raises(fricreg.InputError, match="must be > 0"):
        hb.set_element_param(0, 1, 0, -1.0)
    with pytest.raises(fricreg.InputError, match="parameters"):
        hb.element_param(0, 2)
    assert hb.element_param(0, 0) == 2.0


def test_backbone_special_points_in_the_branchs_order():
    """tests/nma/test_hb_nma_energy.c's two masses with kt = 11 (H = 3): the folds of its S (a =
    4.49) and then, the last special point, 3 ω crossing the stuck structure's second mode,
    ω_1² = 6.35 + sqrt(5.1² + 0.25²) (the 2x2 closed form), at a = 5.04; every fold harmonic 1
    of the backbone's mode 0."""
    K = [[1.25, -0.25], [-0.25, 0.45]]
    hb = fricreg.HarmonicBalance(np.eye(2), K, elements=[("jenkins", [[0.0, 1.0]], [[11.0, 1.0]])],
                                 harmonics=3)
    b = hb.backbone(0, 0.05, 1e3, 100, through_folds=True)
    *folds, last = b.special_points
    w1 = np.sqrt(6.35 + np.hypot(5.1, 0.25))
    assert last.kind == "crossing" and (last.harmonic, last.mode) == (3, 1)
    assert abs(3 * last.omega - w1) <= 1e-12 * w1 and abs(last.amplitude - 5.04) <= 0.01 * 5.04
    assert min(b.zeta) <= last.zeta <= max(b.zeta)
    assert len(folds) >= 2
    for fold in folds:
        assert fold.kind == "fold" and (fold.harmonic, fold.mode) == (1, 0)
        assert fold.amplitude < last.amplitude
    assert abs(folds[-2].amplitude - 4.4942) <= 0.01 * 4.4942


def test_level_response_and_bifurcation_fields():
    hb = chain()
    r = hb.level_response(1.2, 0.1, 2.0)
    assert np.all(r.omega == 1.2) and r.level[0] == 0.1 and r.level[-1] == 2.0
    assert r.stable is None and r.mu_max is None
    for bif in r.bifurcations:
        assert bif.kind in ("TP", "BP", "PD", "NS") and bif.rms.shape == (3,)


def test_errors_name_the_argument():
    element = fricreg.Element("jenkins", [20.0, 1.0])
    with pytest.raises(ValueError, match=r"K: shape \(2, 2\); expected \(3, 3\)"):
        fricreg.HarmonicBalance(M, np.eye(2), elements=[(element, J)], harmonics=3)
    with pytest.raises(ValueError, match=r"elements\[0\] J: shape \(2, 2\)"):
        fricreg.HarmonicBalance(M, K, elements=[(element, np.eye(2))], harmonics=3)
    with pytest.raises(fricreg.InputError, match="harmonics = 41"):
        fricreg.HarmonicBalance(M, K, elements=[(element, J)], harmonics=41)
    with pytest.raises(fricreg.InputError, match=r"set_matrix: .*\(FRICREG_ENOTSYM\)") as info:
        fricreg.HarmonicBalance(M, K + np.triu(np.ones((3, 3)), 1), elements=[(element, J)],
                                harmonics=3)
    assert info.value.name == "FRICREG_ENOTSYM"
    hb = chain()
    with pytest.raises(fricreg.InputError, match="solve"):
        hb.solve(-1.0)
    with pytest.raises(ValueError, match=r"guess: shape \(2, 3\); expected \(2, 15\)"):
        hb.solve(1.0, guess=np.zeros((2, 3)))
    with pytest.raises(ValueError, match="method: 'floquet' is not one of"):
        hb.set_stability(True, method="floquet")
    with pytest.raises(ValueError, match="damping: 'viscous'"):
        hb.backbone(0, 0.1, 1.0, damping="viscous")
    with pytest.raises(fricreg.InputError, match="peak"):
        hb.peak(0)  # no branch yet
    with pytest.raises(ValueError, match=r"pc: shape \(2,\)"):
        hb.set_excitation([1.0, 2.0])


def test_sparse_model_equals_dense():
    sparse = pytest.importorskip("scipy.sparse", reason="python3-scipy is not installed")
    dense_hb = chain()
    dense = dense_hb.frequency_response(0.5, 2.0)
    hb = fricreg.HarmonicBalance(sparse.csr_matrix(M), sparse.csc_matrix(K), sparse.coo_matrix(C),
                                 elements=[(fricreg.Element("jenkins", [20.0, 1.0]), J)],
                                 harmonics=H, excitation=(P, None))
    r = hb.frequency_response(0.5, 2.0)
    # KLU's pivots differ from the dense LU's: the same branch to Newton's tolerance, its peak
    # located between the points (Brent) on both
    assert len(r.omega) > 100 and len(dense.omega) > 100
    peak_sparse, peak_dense = np.array(hb.peak(1)), np.array(dense_hb.peak(1))
    np.testing.assert_allclose(peak_sparse, peak_dense, rtol=1e-8)


def test_ctrl_c_keeps_the_points_computed():
    hb = chain()
    hb.set_continuation(ds=5e-4, ds_max=5e-4, max_points=100000)
    timer = threading.Timer(0.2, _thread.interrupt_main)
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt) as info:
            hb.frequency_response(0.5, 2.0)
            time.sleep(5)  # the sweep ended before the timer: the test cannot tell
    finally:
        timer.cancel()
    assert isinstance(info.value, fricreg.Interrupted)
    partial = info.value.result
    n = len(partial.omega)
    assert n > 1 and partial.bifurcations == ()
    # the same sweep bounded at n points: its points are the first n of the whole sweep
    bounded = chain()
    bounded.set_continuation(ds=5e-4, ds_max=5e-4, max_points=n)
    with pytest.raises(fricreg.Error, match="FRICREG_EWORK") as failed:
        bounded.frequency_response(0.5, 2.0)
    assert failed.value.result.omega.tobytes() == partial.omega.tobytes()
    assert failed.value.result.rms.tobytes() == partial.rms.tobytes()


def test_uncaught_ctrl_c_exits_as_sigint():
    """A script a Ctrl-C stops inside a sweep, uncaught, ends as Python ends on Ctrl-C: killed
    by SIGINT (a shell's status 130), not exit status 1 (CPython does so for the exact class
    KeyboardInterrupt only)."""
    script = (
        "import _thread, threading, numpy as np, fricreg\n"
        "K = np.array([[2.0, -1.0, 0.0], [-1.0, 2.0, -1.0], [0.0, -1.0, 2.0]])\n"
        "J = np.array([[1.0, 0.0, 0.0], [-1.0, 1.0, 0.0]])\n"
        "hb = fricreg.HarmonicBalance(np.eye(3), K, 0.02 * K, harmonics=7,\n"
        "    elements=[(fricreg.Element('jenkins', [20.0, 1.0]), J)],\n"
        "    excitation=([0.0, 1.0, 0.0], None))\n"
        "hb.set_continuation(ds=5e-4, ds_max=5e-4, max_points=100000)\n"
        "threading.Timer(0.2, _thread.interrupt_main).start()\n"
        "hb.frequency_response(0.5, 2.0)\n"
        "import time; time.sleep(5)\n")
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, timeout=60)
    assert done.returncode in (-signal.SIGINT, 128 + signal.SIGINT), done.stderr.decode()
    assert b"KeyboardInterrupt" in done.stderr


def test_four_threads_give_the_serial_answers():
    serial = [chain().frequency_response(0.5, 2.0 + 0.1 * i) for i in range(4)]
    results = [None] * 4

    def work(i):
        results[i] = chain().frequency_response(0.5, 2.0 + 0.1 * i)

    threads = [threading.Thread(target=work, args=(i,)) for i in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for a, b in zip(serial, results):
        assert a.omega.tobytes() == b.omega.tobytes() and a.rms.tobytes() == b.rms.tobytes()


def test_qsma_of_the_jenkins_oscillator_is_its_closed_form():
    """The Jenkins oscillator's static loading path (m = k = 1, kt = 2, mu N = 3): lambda(a) =
    a + mun past the slip at a = mun/kt, so omega^2 = 1 + mun/a and zeta = D/(2 pi lambda a),
    D = 4 mun (a - mun/kt) (the Jenkins loop); d omega/d mun by the formula's own derivative."""
    hb = fricreg.HarmonicBalance([[1.0]], [[1.0]], elements=[("jenkins", [[1.0]], [[2.0, 3.0]])],
                                 harmonics=1)
    a = np.array([2.0, 3.0, 10.0])
    omega, zeta, dw, dz = hb.qsma(0, a, params=[("element", 0, 1, 1)])
    np.testing.assert_allclose(omega, np.sqrt(1 + 3.0 / a), rtol=1e-12)
    np.testing.assert_allclose(zeta, 4 * 3.0 * (a - 1.5) / (2 * np.pi * (a + 3.0) * a), rtol=1e-12)
    np.testing.assert_allclose(dw[:, 0], 0.5 / np.sqrt(1 + 3.0 / a) / a, rtol=1e-10)
    assert dz.shape == (3, 1)
    with pytest.raises(fricreg.InputError, match="amplitude"):
        hb.qsma(0, [2.0, 1.0])
