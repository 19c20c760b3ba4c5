# SPDX-License-Identifier: GPL-3.0-or-later
"""fricreg.AFT against the C functions of fricreg_aft.h called directly, bit for bit; the
closed forms of tests/joint/test_aft.c (Caughey's describing function of the Jenkins element, the
square wave of full slip, the centred stick); the time-domain element marched to its
periodic state; the sampled path converging on the exact one at O(N^-2); Jacobians against
centred differences; the tmdsimpy and pyHarm orders against those packages' own formulas;
every error path."""
import numpy as np
import pytest

import fricreg
from fricreg._fricreg import ffi, lib

U3 = np.array([0.3, 1.0, 0.0, 0.0, 0.2, 0.9, -0.1])  # six reversals a period (test_aft.c)
G3 = np.array([0.4, -0.8, 0.3, 0.1, 0.0, 0.05, 0.2])  # a normal displacement with openings


def c_array(values):
    """A C array holding the values (a copy)."""
    values = np.ascontiguousarray(values, dtype=np.float64).ravel()
    return ffi.new("double[]", values.tolist() or [0.0])


def as_array(buf, shape):
    return np.frombuffer(ffi.buffer(buf, 8 * int(np.prod(shape))), dtype=np.float64).reshape(
        shape).copy()


def c_workspace(H, N):
    out = ffi.new("fricreg_aft **")
    assert lib.fricreg_aft_create(H, N, out) == lib.FRICREG_OK
    return ffi.gc(out[0], lib.fricreg_aft_free)


def c_call(name, H, N, scalars, inputs, outputs, jac_size):
    """fricreg_aft_<name>(aft, *scalars, n, *inputs, *outputs, jac) on a fresh workspace:
    the outputs (their sizes given) and the Jacobian as arrays."""
    n = 2 * H + 1
    ws = c_workspace(H, N)
    outs = [ffi.new("double[]", size) for size in outputs]
    jac = ffi.new("double[]", jac_size * jac_size)
    args = list(scalars) + [n] + [c_array(x) for x in inputs] + outs + [jac]
    if name.startswith("iwan"):  # ns, k, phi before n
        k, phi = scalars
        args = [len(k), c_array(k), c_array(phi), n] + [c_array(x) for x in inputs] + outs + [jac]
    assert getattr(lib, "fricreg_aft_" + name)(ws, *args) == lib.FRICREG_OK
    return [as_array(o, (s,)) for o, s in zip(outs, outputs)] + [
        as_array(jac, (jac_size, jac_size))]


def same(a, b):
    return a.shape == b.shape and a.tobytes() == b.tobytes()


@pytest.mark.parametrize("exact", [True, False])
def test_methods_equal_the_c_calls(exact):
    H, N, n = 3, 256, 7
    aft = fricreg.AFT(H, N)
    path = "exact" if exact else "sampled"
    u, g = U3.copy(), G3.copy()
    r = aft.jenkins(2.385, 0.7, u, exact=exact)
    f, jac = c_call("jenkins_" + path, H, N, (2.385, 0.7), [u], [n], n)
    assert same(r.f, f) and same(r.jac, jac)
    assert aft.jenkins(2.385, 0.7, u, exact=exact, jacobian=False).jac is None
    k, phi = [2.385, 1.0, 0.5], [0.7, 0.25, 3.0]
    r = aft.iwan(k, phi, u, exact=exact)
    f, jac = c_call("iwan_" + path, H, N, (k, phi), [u], [n], n)
    assert same(r.f, f) and same(r.jac, jac)
    r = aft.jenkins_normal(2.385, 0.3, 0.5, 1.7, u, g, exact=exact)
    f, nf, jac = c_call("jenkins_normal_" + path, H, N, (2.385, 0.3, 0.5, 1.7), [u, g], [n, n],
                        2 * n)
    assert same(r.f, f) and same(r.nf, nf) and same(r.jac, jac)
    assert np.array_equal(u, U3) and np.array_equal(g, G3)  # inputs left as they were


def test_2d_normal_equals_the_c_call():
    H, N, n = 3, 256, 7
    u = np.array([U3, 0.5 * np.roll(U3, 2)])
    u_before = u.copy()
    r = fricreg.AFT(H, N).jenkins_2d_normal(2.385, 0.3, 0.5, 1.7, u, G3)
    f, nf, jac = c_call("jenkins_2d_normal_sampled", H, N, (2.385, 0.3, 0.5, 1.7), [u, G3],
                        [2 * n, n], 3 * n)
    assert same(r.f, f.reshape(2, n)) and same(r.nf, nf) and same(r.jac, jac)
    assert np.array_equal(u, u_before)


def dissipation(u, f):
    """The energy dissipated per period, pi sum_h h (b_h fa_h - a_h fb_h) (fricreg_aft.h)."""
    h = np.arange(1, len(u) // 2 + 1)
    return np.pi * np.sum(h * (u[2::2] * f[1::2] - u[1::2] * f[2::2]))


def test_single_harmonic_closed_form():
    # u = A cos(theta - psi) + u0, kt = 2, mun = 3, A = 5 (test_aft.c, Caughey 1960):
    # fa_1 = (kt A/pi)(t - sin t cos t), cos t = 1 - 2 mun/(kt A), fb_1 = -(4 mun/pi)(1 - r/A);
    # a phase rotates (fa, fb) by psi, an offset changes nothing; dissipation 4 mun (A - r) = 42
    kt, mun, A = 2.0, 3.0, 5.0
    r = mun / kt
    t = np.arccos(1 - 2 * r / A)
    fa, fb = kt * A / np.pi * (t - np.sin(t) * np.cos(t)), -4 * mun / np.pi * (1 - r / A)
    assert abs(fa - 2.523157877343) < 1e-12 and abs(fb + 2.673803043944) < 1e-12
    aft = fricreg.AFT(3)
    for psi, u0 in [(0.0, 0.0), (0.3, 0.7), (-2.1, -12.5)]:
        u = np.array([u0, A * np.cos(psi), A * np.sin(psi), 0, 0, 0, 0])
        f = aft.jenkins(kt, mun, u, jacobian=False).f
        expected = [0.0, fa * np.cos(psi) - fb * np.sin(psi), fa * np.sin(psi) + fb * np.cos(psi)]
        np.testing.assert_allclose(f[:3], expected, rtol=0, atol=1e-13 * fa)
        np.testing.assert_allclose(f[3:5], 0.0, atol=1e-13 * mun)  # half-wave symmetry
        assert abs(dissipation(u, f) - 4 * mun * (A - r)) < 1e-13 * 42


def test_full_slip_is_a_square_wave_and_full_stick_is_linear():
    aft = fricreg.AFT(3, 64)
    f = aft.jenkins(1e9, 3.0, [0, 5.0, 0, 0, 0, 0, 0]).f  # r/A = 6e-10: f = -mun sgn(sin)
    assert abs(f[2] + 4 * 3.0 / np.pi) < 1e-8 * 3 and abs(f[6] + 4 * 3.0 / (3 * np.pi)) < 1e-8 * 3
    kt, u = 2.385, np.array([0.7, 2.5, 0.0, 0.0, -0.4, 0.0, 0.0])  # range < 2 mun/kt
    for exact in (True, False):
        r = aft.jenkins(kt, 7.0, u, exact=exact)
        np.testing.assert_allclose(r.f[1:], kt * u[1:], rtol=0, atol=1e-14 * kt)
        np.testing.assert_allclose(r.jac[1:, 1:], kt * np.eye(6), rtol=0, atol=1e-14 * kt)


def test_exact_equals_the_time_domain_element_marched():
    # fricreg.Element's return mapping (fricreg_element.h) marched two periods at 2^14 points
    # from rest, the second period's force integrated against cos, sin by the trapezoid rule:
    # the periodic response, within the sampling error O(N^-2) of the kinks
    kt, mun, steps = 2.385, 0.7125, 1 << 14
    theta = 2 * np.pi * np.arange(steps) / steps
    u = U3[0] + sum(U3[2 * h - 1] * np.cos(h * theta) + U3[2 * h] * np.sin(h * theta)
                    for h in (1, 2, 3))
    jenkins = fricreg.Element("jenkins", [kt, mun])
    path = np.concatenate([u, u])[:, None, None]
    state, force = jenkins.init(1), np.empty(steps)
    for s in range(2 * steps):
        r = jenkins.eval(path[s], state, tangent=False)
        state = r.state
        if s >= steps:
            force[s - steps] = r.f[0, 0]
    basis = np.vstack([np.ones(steps)] + [f(h * theta) for h in (1, 2, 3)
                                          for f in (np.cos, np.sin)])
    timed = basis @ force / steps * np.r_[1, 2 * np.ones(6)]
    exact = fricreg.AFT(3).jenkins(kt, mun, U3).f
    np.testing.assert_allclose(timed, exact, rtol=0, atol=5e-7 * mun)  # measured 8e-8
    assert dissipation(U3, exact) > 0


def test_sampled_converges_at_second_order():
    # test_aft.c: the envelope over eight phases of u, N^2 e < 20 mun, order 1.8 ... 2.2
    kt, mun = 2.385, 0.7125
    sizes, errors = 2 ** np.arange(6, 13), []
    for N in sizes:
        aft, e = fricreg.AFT(2, int(N)), 0.0
        for c in range(8):
            psi = 0.3 + 0.61 * c
            u = [0.1, 1.3 * np.cos(psi), 1.3 * np.sin(psi), 0.0, 0.0]
            exact = aft.jenkins(kt, mun, u, jacobian=False).f
            sampled = aft.jenkins(kt, mun, u, exact=False, jacobian=False).f
            e = max(e, np.max(np.abs(sampled - exact)))
        assert e * N * N < 20 * mun
        errors.append(e)
    order = -np.polyfit(np.log(sizes), np.log(errors), 1)[0]
    assert 1.8 < order < 2.2


def centred_jacobian(evaluate, x, step=1e-6):
    """Centred differences of evaluate (an array of shape (m,)) in each entry of x."""
    columns = []
    for j in range(x.size):
        up, down = x.copy(), x.copy()
        up.flat[j] += step
        down.flat[j] -= step
        columns.append((evaluate(up) - evaluate(down)) / (2 * step))
    return np.array(columns).T


@pytest.mark.parametrize("exact", [True, False])
def test_jacobians_against_centred_differences(exact):
    aft, kt = fricreg.AFT(3, 1024), 2.385
    for mun in (0.7, 0.15, 3.0):  # minor loops stuck, all slipping, all stuck
        r = aft.jenkins(kt, mun, U3, exact=exact)
        fd = centred_jacobian(lambda u: aft.jenkins(kt, mun, u, exact, False).f, U3)
        np.testing.assert_allclose(r.jac, fd, rtol=0, atol=1e-6 * kt)
    k, phi = [2.385, 1.0, 0.5], [0.7, 0.25, 3.0]
    r = aft.iwan(k, phi, U3, exact=exact)
    fd = centred_jacobian(lambda u: aft.iwan(k, phi, u, exact, False).f, U3)
    np.testing.assert_allclose(r.jac, fd, rtol=0, atol=1e-6 * sum(k))
    # lift-off: rows (f, N), columns (u, g)
    ug = np.concatenate([U3, G3])
    r = aft.jenkins_normal(kt, 0.3, 0.5, 1.7, U3, G3, exact=exact)
    fd = centred_jacobian(
        lambda x: np.concatenate(_f_nf(aft.jenkins_normal(kt, 0.3, 0.5, 1.7, x[:7], x[7:], exact,
                                                          False))), ug)
    np.testing.assert_allclose(r.jac, fd, rtol=0, atol=1e-6 * kt)
    assert np.all(r.jac[7:, :7] == 0.0)  # dN/du = 0


def test_2d_jacobian_against_centred_differences():
    aft = fricreg.AFT(2, 256)
    u = np.array([[0.1, 1.2, 0.3, 0.0, 0.1], [-0.2, 0.2, 0.9, 0.1, 0.0]])
    g = np.array([0.3, 0.2, -0.1, 0.0, 0.05])
    r = aft.jenkins_2d_normal(2.385, 0.3, 1.0, 1.5, u, g)

    def forces(x):  # (fx, fy, N) at x = (ux, uy, g)
        r = aft.jenkins_2d_normal(2.385, 0.3, 1.0, 1.5, x[:10].reshape(2, 5), x[10:], False)
        return np.concatenate([r.f.ravel(), r.nf])

    fd = centred_jacobian(forces, np.concatenate([u.ravel(), g]))
    np.testing.assert_allclose(r.jac, fd, rtol=0, atol=1e-6 * 2.385)


def test_iwan_is_the_sum_and_a_constant_normal_force_is_jenkins():
    aft = fricreg.AFT(3, 256)
    k, phi = np.array([2.385, 1.0, 0.5]), np.array([0.7, 0.25, 3.0])
    for exact in (True, False):
        parts = [aft.jenkins(k[s], phi[s], U3, exact) for s in range(3)]
        r = aft.iwan(k, phi, U3, exact)
        np.testing.assert_allclose(r.f, sum(p.f for p in parts), rtol=0, atol=4e-14)
        np.testing.assert_allclose(r.jac, sum(p.jac for p in parts), rtol=0, atol=4e-13)
    # kn = 0, N0 >= 0: the sampled path is jenkins_sampled at mun = mu N0 to the bit
    normal = aft.jenkins_normal(2.385, 0.35, 2.0, 0.0, U3, G3, exact=False)
    plain = aft.jenkins(2.385, 0.35 * 2.0, U3, exact=False)
    assert same(normal.f, plain.f) and same(normal.jac[:7, :7], plain.jac)
    np.testing.assert_array_equal(normal.nf, [2.0, 0, 0, 0, 0, 0, 0])


def _f_nf(r):
    return r.f, r.nf


def test_element_dispatch_equals_the_methods():
    aft = fricreg.AFT(3, 256)
    r = aft.element(fricreg.Element("jenkins", [2.385, 0.7]), U3)
    assert same(r.f, aft.jenkins(2.385, 0.7, U3).f) and r.jac.shape == (7, 7)
    assert aft.element(fricreg.Element("jenkins", [2.385, 0.7]), U3[None, :]).f.shape == (1, 7)
    params = fricreg.segalman(5, 1.0, 10.0, -0.5, 0.1, 0.01)
    r = aft.element(fricreg.Element("iwan", params), U3, exact=False)
    m = aft.iwan(params[:5], params[5:], U3, exact=False)
    assert same(r.f, m.f) and same(r.jac, m.jac)
    ug = np.array([U3, G3])
    r = aft.element(fricreg.Element("jenkins_normal", [2.385, 0.3, 1.7, 0.5, 0.0]), ug)
    m = aft.jenkins_normal(2.385, 0.3, 0.5, 1.7, U3, G3)
    assert same(r.f, np.array([m.f, m.nf])) and same(r.jac, m.jac)
    # a gap instead of a preload: N = max(0, kn (g - gap)) is the preload N0 = -kn gap
    r = aft.element(fricreg.Element("jenkins_normal", [2.385, 0.3, 1.7, 0.0, 0.25]), ug)
    preloaded = aft.jenkins_normal(2.385, 0.3, -1.7 * 0.25, 1.7, U3, G3)
    assert same(r.f, np.array([preloaded.f, preloaded.nf]))
    shifted = aft.jenkins_normal(2.385, 0.3, 0.0, 1.7, U3, G3 - [0.25, 0, 0, 0, 0, 0, 0])
    np.testing.assert_allclose(r.f, [shifted.f, shifted.nf], rtol=0, atol=1e-14)
    u3 = np.array([U3, 0.5 * np.roll(U3, 2), G3])
    r = aft.element(fricreg.Element("contact_3d", [2.385, 0.3, 1.7, 0.5, 0.0]), u3, exact=False)
    m = aft.jenkins_2d_normal(2.385, 0.3, 0.5, 1.7, u3[:2], G3)
    assert same(r.f, np.vstack([m.f, m.nf])) and same(r.jac, m.jac) and r.f.shape == (3, 7)


def tmdsimpy_coefficients(x_t, h):
    """tmdsimpy's get_fourier_coeff (tmdsimpy/harmonic_utils.py), as written there: the
    coefficients (Nhc, nd) of the harmonics h of time series x_t (Nt, nd)."""
    Nt, nd = x_t.shape
    xf = np.fft.fft(x_t, axis=0)
    v, zi = [], 0
    if h[0] == 0:
        v.append(np.real(xf[0, :]) / Nt)
        zi = 1
    for hi in h[zi:]:
        v += [np.real(xf[hi, :]) / (Nt / 2), -np.imag(xf[hi, :]) / (Nt / 2)]
    return np.array(v)


def pyharm_dft(nti, nh):
    """pyHarm's compute_DFT (src/pyHarm/DynamicOperator.py): D["ft"], D["tf"]."""
    k, t = np.arange(1, nh + 1)[:, None], np.arange(nti)[None, :]
    ft = np.vstack([np.ones(nti)] + [row for pair in zip(np.cos(k * t * 2 * np.pi / nti),
                                                        np.sin(k * t * 2 * np.pi / nti))
                                     for row in pair])
    tf = ft.T * np.r_[1.0, 2.0 * np.ones(2 * nh)] / nti
    return ft, tf


def test_the_orders_are_those_of_tmdsimpy_and_pyharm():
    rng = np.random.default_rng(7)
    c = rng.uniform(-1, 1, (3, 9))  # fricreg's coefficients of three dofs, H = 4
    theta = 2 * np.pi * np.arange(64) / 64
    x_t = np.array([row[0] + sum(row[2 * h - 1] * np.cos(h * theta) + row[2 * h]
                                 * np.sin(h * theta) for h in range(1, 5)) for row in c]).T
    for h in ([0, 1, 2, 3, 4], [1, 3], [0, 2, 4]):
        U = fricreg.to_tmdsimpy(c, h)
        # tmdsimpy's coefficients of the same time series, laid out as its U: k * nd + d
        np.testing.assert_allclose(U, tmdsimpy_coefficients(x_t, np.array(h)).ravel(), atol=1e-14)
        back = fricreg.from_tmdsimpy(U, h, ndof=3)
        kept = fricreg.to_tmdsimpy(back, h)
        assert same(kept, U) and back.shape == (3, 2 * max(h) + 1)
    assert same(fricreg.from_tmdsimpy(fricreg.to_tmdsimpy(c, range(5)), range(5), 3), c)
    # pyHarm: per dof x_time = x @ D["ft"] and back with D["tf"]; a node harmonic-major
    ft, tf = pyharm_dft(64, 4)
    np.testing.assert_allclose(c @ ft, x_t.T, atol=1e-13)
    x = fricreg.to_pyharm(c)
    for d in range(3):
        direction = np.eye(3)[d]
        np.testing.assert_allclose(np.kron(np.eye(9), direction) @ x @ ft @ tf, c[d], atol=1e-14)
    assert same(fricreg.from_pyharm(x, 3), c) and same(fricreg.to_pyharm(c[0]), c[0])
    jac = rng.uniform(-1, 1, (27, 27))
    assert same(fricreg.jacobian_to_pyharm(jac, 3),
                fricreg.jacobian_to_tmdsimpy(jac, range(5), 3))
    assert same(fricreg.jacobian_to_pyharm(jac[:9, :9]), jac[:9, :9])


def test_tmdsimpy_force_is_the_permuted_fricreg_result():
    jenkins = fricreg.Element("jenkins", [2.385, 0.7])
    h = np.array([1, 2, 3])  # no zeroth harmonic: U0 = 0
    U = fricreg.to_tmdsimpy(U3, h)
    U_before = U.copy()
    Fnl, dFnldU, dFnldw = fricreg.TmdsimpyForce(jenkins).aft(U, 2.0, h)
    u = fricreg.from_tmdsimpy(U, h)[0]
    r = fricreg.AFT(3).jenkins(2.385, 0.7, u)
    assert same(Fnl, fricreg.to_tmdsimpy(r.f, h))
    assert same(dFnldU, fricreg.jacobian_to_tmdsimpy(r.jac, h))
    assert np.array_equal(U, U_before)
    # rate-independent: dFnldw = 0, and another w changes nothing
    assert same(dFnldw, np.zeros(6))
    assert same(fricreg.TmdsimpyForce(jenkins).aft(U, 37.0, h)[0], Fnl)
    sampled = fricreg.TmdsimpyForce(jenkins, exact=False)
    (F256,) = sampled.aft(U, 2.0, h, Nt=256, calc_grad=False)
    assert same(F256, fricreg.to_tmdsimpy(
        fricreg.AFT(3, 256).jenkins(2.385, 0.7, u, exact=False).f, h))


def test_tmdsimpy_force_with_q_and_t():
    # two dofs, two Jenkins elements: one between dof 0 and ground, one between the dofs;
    # against tmdsimpy's own assembly, kron(I, T) J kron(I, Q); T not Q's transpose, so that
    # a swap of the global rows and columns shows
    Q = np.array([[1.0, 0.0], [-1.0, 1.0]])
    T = np.array([[1.0, -1.0], [0.5, 1.0]])
    h = np.array([0, 1, 3])
    rng = np.random.default_rng(5)
    U = rng.uniform(-1, 1, 10)
    jenkins = fricreg.Element("jenkins", [2.385, 0.4])
    Fnl, dFnldU, dFnldw = fricreg.TmdsimpyForce(jenkins, Q, T).aft(U, 1.0, h)
    local = (U.reshape(5, 2) @ Q.T).ravel()
    u = fricreg.from_tmdsimpy(local, h, ndof=2)
    aft = fricreg.AFT(3)
    r = [aft.jenkins(2.385, 0.4, u[e]) for e in range(2)]
    F = fricreg.to_tmdsimpy(np.array([r[0].f, r[1].f]), h)
    J = np.zeros((14, 14))
    J[:7, :7], J[7:, 7:] = r[0].jac, r[1].jac
    J = fricreg.jacobian_to_tmdsimpy(J, h, ndof=2)
    np.testing.assert_allclose(Fnl, (F.reshape(5, 2) @ T.T).ravel(), rtol=0, atol=1e-15)
    np.testing.assert_allclose(dFnldU, np.kron(np.eye(5), T) @ J @ np.kron(np.eye(5), Q),
                               rtol=0, atol=1e-14)
    fd = centred_jacobian(lambda x: fricreg.TmdsimpyForce(jenkins, Q, T).aft(x, 1.0, h)[0], U)
    np.testing.assert_allclose(dFnldU, fd, rtol=0, atol=1e-6 * 2.385)
    assert same(dFnldw, np.zeros(10))


def test_errors_name_the_argument():
    with pytest.raises(ValueError, match="harmonics: 1.5 is not an integer"):
        fricreg.AFT(1.5)
    with pytest.raises(ValueError, match="samples: -1 is negative"):
        fricreg.AFT(3, -1)
    for H, N in [(0, 0), (41, 0), (3, 48), (3, 4), (1, 2 ** 25)]:
        with pytest.raises(fricreg.InputError, match="harmonics = %d, samples = %d" % (H, N)):
            fricreg.AFT(H, N)
    exact, sampled = fricreg.AFT(1), fricreg.AFT(1, 8)
    u = [0.1, 1.0, 0.2]
    cases = [
        (lambda: exact.jenkins(1, 1, [0.1, 1.0]), ValueError, r"u: shape \(2,\); expected \(3,\)"),
        (lambda: exact.jenkins("1", 1, u), ValueError, "kt: '1' is not a real number"),
        (lambda: exact.jenkins(1, [1, 2], u), ValueError, r"mun: shape \(2,\); expected a number"),
        (lambda: exact.jenkins(0.0, 1, u), fricreg.InputError, "kt = 0 must be > 0"),
        (lambda: exact.jenkins(1, -0.5, u), fricreg.InputError, "mun = -0.5"),
        (lambda: exact.jenkins(np.nan, 1, u), fricreg.InputError, "kt = nan"),
        (lambda: exact.jenkins(1, 1, [0, np.nan, 0]), fricreg.InputError, r"u\[1\] = nan"),
        (lambda: exact.jenkins(1e300, 1, [1e300, 1e10, 0]), fricreg.InputError, "overflows"),
        (lambda: exact.jenkins(1, 1, u, exact=False), fricreg.InputError, "no samples"),
        (lambda: exact.jenkins(1, 1, ["a", "b", "c"]), ValueError, "u: dtype"),
        (lambda: exact.iwan([1, 2], [0.5], u), ValueError, "phi: shape"),
        (lambda: exact.iwan([[1, 2]], [[0.5, 0.5]], u), ValueError, "k: 2 dimensions"),
        (lambda: exact.iwan([], [], u), fricreg.InputError, "ns = 0"),
        (lambda: sampled.iwan([1, np.nan], [0.5, 0.5], u, False), fricreg.InputError, "nan"),
        (lambda: exact.jenkins_normal(1, 0.3, 1, -1, u, u), fricreg.InputError, "kn = -1"),
        (lambda: exact.jenkins_normal(1, 0.3, 1, 1, u, u[:2]), ValueError, "g: shape"),
        (lambda: exact.jenkins_normal(1, 0.3, np.inf, 1, u, u), fricreg.InputError, "inf"),
        (lambda: exact.jenkins_2d_normal(1, 0.3, 1, 1, [u, u], u), fricreg.InputError,
         "no samples"),
        (lambda: sampled.jenkins_2d_normal(1, 0.3, 1, 1, u, u), ValueError,
         r"u: shape \(3,\); expected \(2, 3\)"),
        (lambda: sampled.jenkins_2d_normal(1, -0.3, 1, 1, [u, u], u), fricreg.InputError,
         "mu = -0.3"),
        (lambda: exact.element("jenkins", u), ValueError, "element: 'jenkins' is not a fricreg"),
        (lambda: exact.element(fricreg.Element("jenkins_2d", [1, 1]), u), ValueError,
         "element: jenkins_2d has no AFT"),
        (lambda: sampled.element(fricreg.Element("contact_3d", [1, 0.3, 1, 1, 0]), [u, u, u]),
         ValueError, "exact: contact_3d has only the sampled AFT"),
        (lambda: exact.element(fricreg.Element("jenkins_normal", [1, 0.3, 1, 1, 0]), u),
         ValueError, r"coefficients: shape \(3,\); jenkins_normal expects \(2, 3\)"),
    ]
    for call, kind, pattern in cases:
        with pytest.raises(kind, match=pattern):
            call()
    with pytest.raises(fricreg.InputError) as error:
        exact.jenkins(1, 1, [0, np.inf, 0])
    assert error.value.status == lib.FRICREG_ENONFINITE


def test_adapter_errors_name_the_argument():
    c = np.zeros((2, 7))
    jenkins = fricreg.Element("jenkins", [1, 1])
    cases = [
        (lambda: fricreg.to_tmdsimpy(c, [2, 1]), "h: .* not sorted"),
        (lambda: fricreg.to_tmdsimpy(c, [0.0, 1.0]), "h: .* integer harmonics"),
        (lambda: fricreg.to_tmdsimpy(c, [-1, 1]), "h: .* >= 0"),
        (lambda: fricreg.to_tmdsimpy(c, [1, 4]), "h: harmonic 4 above the coefficients' H = 3"),
        (lambda: fricreg.to_tmdsimpy(np.zeros((2, 6)), [1]), r"coefficients: shape \(2, 6\)"),
        (lambda: fricreg.from_tmdsimpy(np.zeros(5), [0, 1], ndof=2), r"U: shape \(5,\)"),
        (lambda: fricreg.from_tmdsimpy(np.zeros(3), [0, 1], ndof=0), "ndof: 0"),
        (lambda: fricreg.jacobian_to_tmdsimpy(np.zeros((7, 6)), [1]), "jacobian: shape"),
        (lambda: fricreg.jacobian_to_tmdsimpy(np.zeros((7, 7)), [4]), "h: harmonic 4 above"),
        (lambda: fricreg.from_pyharm(np.zeros(8), ndof=2), "x: 8 entries"),
        (lambda: fricreg.jacobian_to_pyharm(np.zeros((6, 6))), "jacobian: 6 entries"),
        (lambda: fricreg.TmdsimpyForce(jenkins, Q=np.eye(2)), "Q, T: give both or neither"),
        (lambda: fricreg.TmdsimpyForce(jenkins, np.eye(2), np.eye(3)), "T: shape"),
        (lambda: fricreg.TmdsimpyForce(fricreg.Element("jenkins_normal", [1, 0.3, 1, 1, 0]),
                                       np.eye(3), np.eye(3)), "Q: 3 local dofs"),
        (lambda: fricreg.TmdsimpyForce(fricreg.Element("spring", [1])), "element: spring"),
        (lambda: fricreg.TmdsimpyForce(jenkins).aft(np.zeros(4), 1.0, [0, 1]), r"U: shape \(4,\)"),
        (lambda: fricreg.TmdsimpyForce(jenkins, exact=False).aft(np.zeros(3), 1.0, [0, 1],
                                                                 Nt=64.0), "Nt: 64.0"),
        (lambda: fricreg.TmdsimpyForce(jenkins, exact=False).aft(np.zeros(3), 1.0, [0, 1],
                                                                 Nt=100), "samples = 100"),
        (lambda: fricreg.TmdsimpyForce(jenkins).aft(np.zeros(83), 1.0, range(42)),
         "harmonics = 41"),
    ]
    for call, pattern in cases:
        with pytest.raises(ValueError, match=pattern):
            call()


def test_workspace_reports_its_sizes():
    aft = fricreg.AFT(np.int64(5), 64)
    assert (aft.harmonics, aft.samples, aft.n) == (5, 64, 11)
    assert repr(aft) == "AFT(harmonics=5, samples=64)"
    assert "AFT" in fricreg.__all__ and "TmdsimpyForce" in fricreg.__all__
