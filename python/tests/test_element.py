# SPDX-License-Identifier: GPL-3.0-or-later
"""fricreg.Element against the C library's single-point fricreg_element_eval bit for bit, the
closed-form hysteresis loops of Jenkins and Iwan elements, and centred differences."""
import numpy as np
import pytest

import fricreg
from conftest import c_element_eval


def params_of(name, rng, ns=3):
    """In-range parameters: stiffnesses near 2, bounds near 0.7, a preload near 1."""
    if name == "spring":
        return [rng.uniform(1, 3)]
    slide = rng.uniform(1, 3, ns if name.startswith("iwan") else 1).tolist()
    bounds = rng.uniform(0.3, 1.0, len(slide)).tolist()
    normal = [rng.uniform(2, 4), rng.uniform(0.5, 1.5), 0.0] if "normal" in name \
        or name == "contact_3d" else []
    return slide + bounds + normal


@pytest.mark.parametrize("name", fricreg.ELEMENT_TYPES)
@pytest.mark.parametrize("shared", [True, False])
def test_each_type_equals_the_c_call(name, shared):
    rng = np.random.default_rng(3)
    element = fricreg.Element(name, params_of(name, rng))
    npoints = 9
    params = element.params if shared else np.array(
        [params_of(name, rng) for _ in range(npoints)])
    state = rng.uniform(-0.5, 0.5, (npoints, element.nstate))
    u = rng.uniform(-1, 1, (npoints, element.dim))
    state_before = state.copy()
    r = element.eval(u, state, params=None if shared else params, derivatives=True)
    assert np.array_equal(state, state_before)  # the input state is left as it was
    assert r.f.shape == (npoints, element.dim)
    assert r.dfdu.shape == (npoints, element.dim, element.dim)
    assert r.dfdp.shape == (npoints, element.dim, element.nparams)
    assert r.state.shape == (npoints, element.nstate)
    for i in range(npoints):
        status, f, dfdu, dfdp, w = c_element_eval(
            element, params if shared else params[i], state[i], u[i])
        assert status == 0
        assert r.f[i].tobytes() == f.tobytes()
        assert r.dfdu[i].tobytes() == dfdu.tobytes()
        assert r.dfdp[i].tobytes() == dfdp.tobytes()
        assert r.state[i].tobytes() == w.tobytes()
    one = element.eval(u[4], state[4], params=None if shared else params[4])
    assert one.f.tobytes() == r.f[4].tobytes() and one.dfdp is None


def cycle_dissipation(element, amplitudes, steps=4000):
    """The dissipation per cycle of elements under u = A sin t, one point per amplitude: the
    sum of f dw over a cycle after the first quarter (samples on the turns)."""
    amplitudes = np.asarray(amplitudes, dtype=float)
    state = element.init(amplitudes.size)
    dissipation = np.zeros(amplitudes.size)
    for s in range(1, steps + steps // 4 + 1):
        u = (amplitudes * np.sin(2 * np.pi * s / steps))[:, None]
        r = element.eval(u, state, tangent=False)
        nst = element.nsliders
        k, phi = element.params[:nst], element.params[nst:]
        forces = np.clip(k * (u - state), -phi, phi)  # each slider's force, |f_s| <= phi_s
        dissipation += np.sum(forces * (r.state - state), axis=1)
        state = r.state
        if s == steps // 4:
            dissipation[:] = 0.0
    return dissipation


def test_jenkins_loop_closed_form():
    kt, mun = 2.0, 0.5
    amplitudes = [0.3, 0.6, 1.2]
    d = cycle_dissipation(fricreg.Element("jenkins", [kt, mun]), amplitudes)
    exact = 4 * mun * (np.array(amplitudes) - mun / kt)  # 4 mun (A - mun/kt)
    np.testing.assert_allclose(d, exact, rtol=1e-12)


def test_iwan_loop_closed_form():
    # sum over the slipping sliders of 4 phi_s (A - phi_s/k_s); stuck ones dissipate nothing
    params = fricreg.segalman(8, 1.0, 10.0, -0.5, 0.1, 0.01)
    element = fricreg.Element("iwan", params)
    k, phi = params[:8], params[8:]
    amplitudes = np.array([0.002, 0.02, 0.2])
    slipping = amplitudes[:, None] > phi / k
    exact = np.sum(np.where(slipping, 4 * phi * (amplitudes[:, None] - phi / k), 0), axis=1)
    assert 0 < slipping.sum() < slipping.size  # some stuck, some slipping
    np.testing.assert_allclose(cycle_dissipation(element, amplitudes), exact, rtol=1e-12)


@pytest.mark.parametrize("name", ["jenkins_2d", "jenkins_3d", "contact_3d", "iwan_normal"])
def test_tangent_against_differences(name):
    rng = np.random.default_rng(11)
    element = fricreg.Element(name, params_of(name, rng))
    state = rng.uniform(-0.3, 0.3, (20, element.nstate))
    u = rng.uniform(-1, 1, (20, element.dim))
    if element.dim > 1 and (name == "contact_3d" or "normal" in name):
        u[:, -1] = rng.uniform(0.1, 0.5, 20)  # closed, away from lift-off
    r = element.eval(u, state)
    h = 1e-7
    for c in range(element.dim):
        du = np.zeros(element.dim)
        du[c] = h
        fp = element.eval(u + du, state, tangent=False).f
        fm = element.eval(u - du, state, tangent=False).f
        np.testing.assert_allclose((fp - fm) / (2 * h), r.dfdu[:, :, c], atol=2e-6)


def test_type_from_params_and_sizes():
    iwan = fricreg.Element("iwan_normal", [1.0, 2.0, 0.3, 0.4, 3.0, 1.0, 0.0])
    assert (iwan.nsliders, iwan.dim, iwan.nparams, iwan.nstate) == (2, 2, 7, 2)
    assert fricreg.Element("jenkins_3d", [1, 1]).nstate == 3
    assert fricreg.Element("spring", [2.0]).init(4).shape == (4, 0)
    assert repr(fricreg.Element("jenkins", [2, 0.5])) == "Element('jenkins', [2.0, 0.5])"
    with pytest.raises(ValueError):
        fricreg.Element("jenkins", [2, 0.5]).params[0] = 3.0  # read-only


def test_errors_name_the_argument():
    with pytest.raises(ValueError, match="'lugre' is not an element type"):
        fricreg.Element("lugre", [1.0])
    with pytest.raises(ValueError, match="jenkins takes 2 parameters, not 3"):
        fricreg.Element("jenkins", [1.0, 2.0, 3.0])
    with pytest.raises(ValueError, match=r"iwan takes 0 \+ 2 ns parameters"):
        fricreg.Element("iwan", [1.0, 2.0, 3.0])
    with pytest.raises(fricreg.InputError, match="kt = -1 must be > 0") as info:
        fricreg.Element("jenkins", [-1.0, 0.5])
    assert info.value.name == "FRICREG_EINVAL"
    jenkins = fricreg.Element("jenkins", [2.0, 0.5])
    state = jenkins.init(3)
    with pytest.raises(ValueError, match=r"u: shape \(3, 2\); jenkins expects \(npoints, 1\)"):
        jenkins.eval(np.zeros((3, 2)), state)
    with pytest.raises(ValueError, match=r"state: shape \(2, 1\); expected \(3, 1\)"):
        jenkins.eval(np.zeros((3, 1)), jenkins.init(2))
    with pytest.raises(ValueError, match=r"params: shape \(2, 2\)"):
        jenkins.eval(np.zeros((3, 1)), state, params=np.ones((2, 2)))
    u = np.zeros((3, 1))
    u[2, 0] = np.inf
    with pytest.raises(fricreg.InputError, match=r"point 2: jenkins: u\[0\] = inf"):
        jenkins.eval(u, state)
    per_point = np.array([[2.0, 0.5], [2.0, -0.5], [2.0, 0.5]])
    with pytest.raises(fricreg.InputError, match="point 1: .*mun = -0.5"):
        jenkins.eval(np.zeros((3, 1)), state, params=per_point)
    with pytest.raises(fricreg.InputError, match="ns = 0 must be >= 1"):
        fricreg.segalman(0, 1.0, 10.0, -0.5, 0.1, 0.01)
    with pytest.raises(fricreg.InputError, match="out of range"):
        fricreg.segalman(4, -1.0, 10.0, -0.5, 0.1, 0.01)
