# SPDX-License-Identifier: GPL-3.0-or-later
"""fricreg.fit_backbone and fricreg.backbone against Segalman's closed forms written here in
the density's constants R and S (../shared/notes/identification.md), independently of the
library's x = a/phi_max form; recovery of known parameters; the C fit's numbers unchanged."""
import math

import numpy as np
import pytest

import fricreg

TRUTH = {"fs": 30.0, "kt": 3e5, "chi": 0.3, "beta": 0.5, "zeta0": 0.002, "k0": 8.4e5}
SENSOR = 0.37


def phi_max(p):
    c = p["beta"] + (p["chi"] + 1) / (p["chi"] + 2)
    return p["fs"] * (1 + p["beta"]) / (p["kt"] * c)


def reference(p, a):
    """(f in Hz, zeta) at the modal amplitude a, by the R, S form."""
    chi, beta, fs = p["chi"], p["beta"], p["fs"]
    c, pm = beta + (chi + 1) / (chi + 2), phi_max(p)
    R, S = fs * (chi + 1) / (pm ** (chi + 2) * c), fs / pm * beta / c
    if a < pm:
        F = R * a ** (chi + 2) / (chi + 2) + a * (R * (pm ** (chi + 1) - a ** (chi + 1)) / (chi + 1) + S)
        D = 4 * R * a ** (chi + 3) / ((chi + 2) * (chi + 3))
    else:
        F = fs
        D = 4 * R * (a * pm ** (chi + 2) / (chi + 2) - pm ** (chi + 3) / (chi + 3)) + 4 * S * pm * (a - pm)
    w2 = p["k0"] + F / a
    return math.sqrt(w2) / (2 * math.pi), p["zeta0"] + D / (2 * math.pi * w2 * a * a)


def levels():
    """8 accelerations from 3 % to 150 % of phi_max, and the truth's f, zeta there."""
    amp = SENSOR * phi_max(TRUTH) * 0.03 * 50.0 ** (np.arange(8) / 7) * (2 * math.pi * 165) ** 2
    f, z, _ = fricreg.backbone(TRUTH, amp, kind="acceleration", sensor=SENSOR)
    return amp, f, z


def test_backbone_is_the_closed_form():
    a = phi_max(TRUTH) * np.geomspace(0.01, 4.0, 9)
    f, z, modal = fricreg.backbone([TRUTH[k] for k in fricreg.FIT_PARAMS], a)
    np.testing.assert_allclose(modal, a, rtol=1e-15)
    for i, ai in enumerate(a):
        fr, zr = reference(TRUTH, ai)
        assert f[i] == pytest.approx(fr, rel=1e-12)
        assert z[i] == pytest.approx(zr, rel=1e-12)


def test_sensitivities_match_central_differences():
    amp, _, _ = levels()
    f, z, _, df, dz = fricreg.backbone(TRUTH, amp, kind="acceleration", sensor=SENSOR,
                                       sensitivities=True)
    assert df.shape == dz.shape == (8, 6)
    for j, name in enumerate(fricreg.FIT_PARAMS):
        h = 1e-5 * TRUTH[name]
        up, down = dict(TRUTH), dict(TRUTH)
        up[name] += h
        down[name] -= h
        fu, zu, _ = fricreg.backbone(up, amp, kind="acceleration", sensor=SENSOR)
        fd, zd, _ = fricreg.backbone(down, amp, kind="acceleration", sensor=SENSOR)
        assert np.max(np.abs((fu - fd) / (2 * h) - df[:, j])) <= 1e-6 * np.max(np.abs(df[:, j]))
        assert np.max(np.abs((zu - zd) / (2 * h) - dz[:, j])) <= 1e-6 * np.max(np.abs(dz[:, j]))


def test_fit_recovers_known_parameters_with_the_optimizeresult_fields():
    amp, f, z = levels()
    x0 = {k: v * (10.0 if k in ("fs", "beta", "k0") else 0.1) for k, v in TRUTH.items()}
    x0["chi"] = 10 * (TRUTH["chi"] + 1) - 1
    res = fricreg.fit_backbone(amp, f, z, sensor=SENSOR, sd_freq_hz=5e-4 * f, sd_zeta=0.01 * z,
                               x0=x0)
    assert res.success and res.x.shape == (6,) and res.cov.shape == (6, 6)
    for j, name in enumerate(fricreg.FIT_PARAMS):
        assert res.params[name] == pytest.approx(TRUTH[name], rel=1e-6)
        assert res.lower[j] < TRUTH[name] < res.upper[j]
    assert res.nfev > 0 and res.njev > 0 and res.quantile == pytest.approx(1.959964, rel=1e-6)
    assert res.sv.shape == (6,) and res.vectors.shape == (6, 6) and res.free.all()
    np.testing.assert_allclose(res.cov, res.cov.T, rtol=1e-12, atol=0)
    fc, zc, sf, sz = res.curve(amp)
    np.testing.assert_allclose(fc, f, rtol=1e-9)
    assert (sf > 0).all() and (sz > 0).all()


def test_fixed_parameters_and_relative_residuals():
    amp, f, z = levels()
    res = fricreg.fit_backbone(amp, f * (1 + 3e-4 * np.sin(np.arange(8))), z,
                               sensor=SENSOR, fixed={"beta": 0.5, "k0": 8.4e5})
    assert list(res.free) == [True, True, True, False, True, False]
    assert res.x[3] == 0.5 and res.cov[3, 3] == 0.0 and res.lower[5] == res.upper[5] == 8.4e5
    # t(0.975) at 2 * 8 - 4 = 12 degrees of freedom
    assert res.quantile == pytest.approx(2.178812829667228, rel=1e-12)


def test_failures_raise_with_the_library_message():
    amp, f, z = levels()
    with pytest.raises(fricreg.InputError, match="5 levels for 6 free"):
        fricreg.fit_backbone(amp[:5], f[:5], z[:5], sensor=SENSOR)
    with pytest.raises(ValueError, match="unknown parameters"):
        fricreg.fit_backbone(amp, f, z, fixed={"mu": 0.3})
    with pytest.raises(ValueError, match="kind"):
        fricreg.fit_backbone(amp, f, z, kind="jerk")
    with pytest.raises(fricreg.InputError, match="amplitude"):
        fricreg.backbone(TRUTH, [1.0, -1.0])
    same = np.full(8, amp[4])
    fs, zs, _ = fricreg.backbone(TRUTH, same, kind="acceleration", sensor=SENSOR)
    with pytest.raises(fricreg.Error, match="do not determine") as info:
        fricreg.fit_backbone(same, fs, zs, sensor=SENSOR, sd_freq_hz=fs * 1e-4, sd_zeta=zs * 0.01,
                             fixed={"chi": 0.3, "beta": 0.5, "zeta0": 0.002})
    assert info.value.name == "FRICREG_ESINGULAR"


def describing_function(a, kt, mun):
    """ω² and ζ of x'' + x + f = 0 at x = a cos θ, f a Jenkins element, H = 1 (the
    oscillator's backbone in closed form; tests/nma/test_hb_nma.c derives it)."""
    delta = mun / kt
    beta = np.arccos(1 - 2 * delta / a)
    w2 = 1 + kt / np.pi * (beta - 0.5 * np.sin(2 * beta))
    return w2, 4 * mun * (a - delta) / (2 * np.pi * a * a * w2)


def test_a_qsma_fit_recovers_the_oscillators_closed_form():
    """QSMA's closed form of the Jenkins oscillator (unit mass and spring; slipping,
    ω² = 1 + mu N/a, ζ = 4 mu N (a − mu N/kt)/(2π (a + mu N) a)), fitted with
    backbone="qsma" from starts 2x off: kt and mu N back to the fit's tolerance; a dof
    refused (QSMA's levels are modal)."""
    kt, mun = 2.0, 3.0
    a = np.array([2.0, 3.0, 5.0, 9.0, 20.0])
    freq = np.sqrt(1 + mun / a) / (2 * np.pi)
    zeta = 4 * mun * (a - mun / kt) / (2 * np.pi * (a + mun) * a)
    hb = fricreg.HarmonicBalance([[1.0]], [[1.0]], elements=[("jenkins", [[1.0]], [[4.0, 1.5]])],
                                 harmonics=1)
    params = [("element", 0, 1, 0), ("element", 0, 1, 1)]
    res = fricreg.fit_backbone(a, freq, zeta, kind="displacement", model=hb, params=params,
                               backbone="qsma")
    np.testing.assert_allclose(res.x, [kt, mun], rtol=1e-7)
    with pytest.raises(fricreg.InputError, match="modal"):
        fricreg.fit_backbone(a, freq, zeta, kind="displacement", model=hb, params=params,
                             backbone="qsma", dof=0)
    with pytest.raises(fricreg.InputError, match="backbone"):
        fricreg.fit_backbone(a, freq, zeta, model=hb, params=params, backbone="shooting")


def test_a_harmonic_balance_models_fit_recovers_the_closed_forms_parameters():
    """Levels made by the describing function's closed form (kt = 2, mu N = 3), fitted on the
    HB model of the same oscillator from starts 2x off: the parameters back to the fit's
    tolerance, the driver left at them, and the fitted curve through the levels."""
    a = np.array([2.0, 3.0, 5.0, 9.0, 20.0])  # all slipping: mun/kt = 1.5
    w2, zeta = describing_function(a, 2.0, 3.0)
    hb = fricreg.HarmonicBalance([[1.0]], [[1.0]], elements=[("jenkins", [[1.0]], [[4.0, 1.5]])],
                                 harmonics=1)
    params = [("element", 0, 1, 0), ("element", 0, 1, 1)]
    res = fricreg.fit_backbone(a, np.sqrt(w2) / (2 * np.pi), zeta, kind="displacement",
                               model=hb, params=params)
    np.testing.assert_allclose(res.x, [2.0, 3.0], rtol=1e-7)
    assert res.params[params[1]] == res.x[1] and res.success and res.x.shape == (2,)
    assert (hb.element_param(0, 0), hb.element_param(0, 1)) == tuple(res.x)
    f, z, sf, sz = res.curve(a)
    np.testing.assert_allclose(f, np.sqrt(w2) / (2 * np.pi), rtol=1e-7)
    np.testing.assert_allclose(z, zeta, rtol=1e-6)
    with pytest.raises(fricreg.InputError, match="params"):
        fricreg.fit_backbone(a, np.sqrt(w2) / (2 * np.pi), zeta, model=hb,
                             params=[("amplitude",)])
    with pytest.raises(fricreg.InputError, match="model"):
        fricreg.fit_backbone(a, np.sqrt(w2) / (2 * np.pi), zeta, model="hb", params=params)
    with pytest.raises(fricreg.InputError, match="x0"):
        fricreg.fit_backbone(a, np.sqrt(w2) / (2 * np.pi), zeta, model=hb, params=params,
                             x0={("element", 0, 1, 2): 1.0})
