# SPDX-License-Identifier: GPL-3.0-or-later
"""The result records (fricreg/_record.py): read by name, a field added later breaks no caller
that reads names, and a read by position still works in 1.9 but warns."""
import pickle
import warnings

import numpy as np
import pytest

import fricreg
from fricreg._record import record

RESULTS = [fricreg.Solution, fricreg.Response, fricreg.Bifurcation, fricreg.Backbone,
           fricreg.SpecialPoint, fricreg.ElementResult, fricreg.AFTResult,
           fricreg.AFTNormalResult, fricreg.StepResult, fricreg.StructureResult,
           fricreg.ErrorEstimate, fricreg.EstimateCompanions]


def a_caller_by_name(result):
    """What a caller of 1.8's Solution reads."""
    return result.omega, result.x, result.stable


def test_a_field_added_breaks_no_caller_that_reads_names():
    old = record("Solution", "omega q x stable mu_max", "1.8's fields")
    new = record("Solution", "omega q x stable mu_max multipliers extra", "later fields")
    before = old(1.0, np.zeros(2), np.ones(2), True, 0.5)
    after = new(1.0, np.zeros(2), np.ones(2), True, 0.5, None, "added")
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # reading by name never warns
        assert a_caller_by_name(before)[0] == a_caller_by_name(after)[0] == 1.0
        assert a_caller_by_name(after)[2] is True
        assert after._asdict()["extra"] == "added" and after._replace(extra=1).extra == 1
        assert pickle.loads(pickle.dumps(fricreg.ErrorEstimate(1.0, "bound"))).kind == "bound"
        assert "omega=1.0" in repr(before) and len(after) == 7


@pytest.mark.parametrize("cls", RESULTS, ids=[c.__name__ for c in RESULTS])
def test_reading_by_position_warns(cls):
    result = cls(*range(len(cls._fields)))
    assert isinstance(result, tuple) and cls.__doc__ and len(cls.__doc__) > 40
    with pytest.warns(DeprecationWarning, match="read it by name"):
        first, *rest = result
    assert first == 0 and rest == list(range(1, len(cls._fields)))
    with pytest.warns(DeprecationWarning, match=cls.__name__):
        assert result[1] == 1
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert getattr(result, cls._fields[-1]) == len(cls._fields) - 1
