# SPDX-License-Identifier: GPL-3.0-or-later
"""fricreg.law_eval against the paper's equations (Quinn 2004, (1)-(4) and Sec. 2) written
in numpy, and against the C library's single-contact fricreg_law_eval bit for bit."""
import numpy as np
import pytest

import fricreg
from conftest import c_law_eval

EPS = 0.02


def sat(y):
    return np.clip(y, -1.0, 1.0)


def paper_law(law, v, f_eq, mun, eps):
    """The laws as the header and the paper state them, in numpy."""
    coulomb = -mun * np.sign(v)
    if law == "coulomb":
        return coulomb
    if law == "force-balance":
        return np.where(v == 0, mun * sat(f_eq / mun), coulomb)
    if law == "karnopp":
        return np.where(np.abs(v) < eps, mun * sat(f_eq / mun), coulomb)
    if law == "velocity-limited":
        return np.where(np.abs(v) < eps, -(mun / eps) * v, coulomb)
    if law == "tanh":
        return -mun * np.tanh(v / eps)
    xi = 0.5 * eps * sat(f_eq / mun)  # quinn, (4)
    return np.where(np.abs(v - xi) < 0.5 * eps, -(2 * mun / eps) * (v - xi),
                    -mun * np.sign(v - xi))


@pytest.fixture
def contacts():
    rng = np.random.default_rng(7)
    v = rng.uniform(-3 * EPS, 3 * EPS, 400)
    v[::7] = 0.0  # at rest: where (2) and (4) agree
    f_eq = rng.uniform(-1.5, 1.5, 400)
    mun = rng.uniform(0.2, 1.0, 400)
    return v, f_eq, mun


@pytest.mark.parametrize("law", fricreg.LAWS)
def test_each_law_is_the_papers(law, contacts):
    v, f_eq, mun = contacts
    f = fricreg.law_eval(law, v, f_eq, mun, EPS)
    np.testing.assert_allclose(f, paper_law(law, v, f_eq, mun, EPS), rtol=1e-14, atol=1e-15)
    assert np.all(np.abs(f) <= mun)


@pytest.mark.parametrize("law", fricreg.LAWS)
def test_each_law_equals_the_c_call(law, contacts):
    v, f_eq, mun = contacts
    code = fricreg.LAWS.index(law) + 1
    f = fricreg.law_eval(code, v, f_eq, mun, EPS)
    expected = [c_law_eval(code, *args, EPS) for args in zip(v, f_eq, mun)]
    assert all(status == 0 for status, _ in expected)
    assert f.tobytes() == np.array([x for _, x in expected]).tobytes()


def test_quinn_equals_force_balance_at_rest(contacts):
    _, f_eq, mun = contacts
    rest = np.zeros_like(f_eq)
    assert np.array_equal(fricreg.law_eval("quinn", rest, f_eq, mun, EPS),
                          fricreg.law_eval("force-balance", rest, f_eq, mun, EPS))


def test_broadcasting_and_shapes():
    v = np.linspace(-0.1, 0.1, 12).reshape(3, 4)
    f = fricreg.law_eval("quinn", v, 0.1, [0.5, 0.6, 0.7, 0.8], EPS)
    assert f.shape == (3, 4)
    assert f[1, 2] == fricreg.law_eval("quinn", v[1, 2], 0.1, 0.7, EPS)
    # a strided view and integers are converted, the inputs left as they were
    wide = np.linspace(-0.1, 0.1, 24)
    before = wide.copy()
    assert np.array_equal(fricreg.law_eval("tanh", wide[::2], None, 1, EPS),
                          fricreg.law_eval("tanh", wide[::2].copy(), None, 1.0, EPS))
    assert np.array_equal(wide, before)
    assert fricreg.law_eval("coulomb", [], None, [], EPS).shape == (0,)


def test_errors_name_the_argument():
    with pytest.raises(ValueError, match="law: 'stribeck' is not a law"):
        fricreg.law_eval("stribeck", 0.0, 0.0, 1.0, EPS)
    with pytest.raises(ValueError, match="law: 7"):
        fricreg.law_eval(7, 0.0, 0.0, 1.0, EPS)
    with pytest.raises(fricreg.InputError, match="quinn needs f_eq") as info:
        fricreg.law_eval("quinn", [0.0], None, [1.0], EPS)
    assert info.value.name == "FRICREG_ENULL"
    with pytest.raises(fricreg.InputError, match=r"mun\[1\] = -1 must be >= 0"):
        fricreg.law_eval("coulomb", [0.0, 1.0], None, [1.0, -1.0], EPS)
    with pytest.raises(fricreg.InputError, match="eps = 0 must be >= DBL_MIN"):
        fricreg.law_eval("tanh", 0.0, None, 1.0, 0.0)
    with pytest.raises(fricreg.InputError, match=r"v\[0\] = nan is not finite") as info:
        fricreg.law_eval("tanh", [np.nan], None, [1.0], EPS)
    assert info.value.status == 3 and isinstance(info.value, ValueError)
    with pytest.raises(ValueError, match="v: dtype complex128"):
        fricreg.law_eval("tanh", [1j], None, [1.0], EPS)
    with pytest.raises(ValueError, match="do not broadcast"):
        fricreg.law_eval("tanh", [0.0, 1.0, 2.0], None, [1.0, 2.0], EPS)
