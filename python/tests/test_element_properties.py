# SPDX-License-Identifier: GPL-3.0-or-later
"""Property tests of fricreg.Element with hypothesis (python3-hypothesis; skipped where it is
absent): the call is pure, its tangent matches centred differences away from the stick/slip
border, and the force stays within the sliders' bounds. Derandomized: the same examples at
every run, so that CI is reproducible."""
import math

import numpy as np
import pytest

hypothesis = pytest.importorskip(
    "hypothesis", reason="python3-hypothesis is not installed: the property tests are skipped")
from hypothesis import given, settings, strategies as st  # noqa: E402

import fricreg  # noqa: E402

finite = st.floats(-2.0, 2.0, allow_nan=False)
stiffness = st.floats(0.5, 5.0)
bound = st.floats(0.0, 2.0)


@settings(max_examples=200, deadline=None, database=None, derandomize=True)
@given(kt=stiffness, mun=bound, w=st.tuples(finite, finite), u=st.tuples(finite, finite))
def test_jenkins_2d_is_pure_and_bounded(kt, mun, w, u):
    element = fricreg.Element("jenkins_2d", [kt, mun])
    state = np.array([w])
    first = element.eval([u], state, derivatives=True)
    again = element.eval([u], state, derivatives=True)
    for field in first._fields:
        assert getattr(first, field).tobytes() == getattr(again, field).tobytes()
    # hypot, not the norm's sum of squares, which loses digits below 1e-154 (subnormal squares)
    assert math.hypot(*first.f[0]) <= mun * (1 + 1e-12) + 1e-300


@settings(max_examples=200, deadline=None, database=None, derandomize=True)
@given(kt=stiffness, mun=st.floats(0.1, 2.0), w=finite, u=finite)
def test_jenkins_tangent_matches_differences(kt, mun, w, u):
    element = fricreg.Element("jenkins", [kt, mun])
    h = 1e-7
    hypothesis.assume(abs(abs(kt * (u - w)) - mun) > 10 * kt * h)  # not at the border
    state = np.array([w])
    r = element.eval([u], state)
    fp = element.eval([u + h], state).f[0]
    fm = element.eval([u - h], state).f[0]
    assert abs((fp - fm) / (2 * h) - r.dfdu[0, 0]) <= 1e-6 * kt
