# SPDX-License-Identifier: GPL-3.0-or-later
"""Shared helpers of the binding's tests: the C library's own single-point calls, which every
batch of the binding must equal bit for bit, and the command line beside the package."""
import os

import numpy as np
import pytest

import fricreg
from fricreg._fricreg import ffi, lib

def pytest_configure(config):
    """The binding's own code and its tests read results by name and change settings by their
    set_* methods: a read by position or an assignment to a setting fails."""
    config.addinivalue_line("filterwarnings",
                            "error:.*reading a result by position:DeprecationWarning")
    config.addinivalue_line("filterwarnings",
                            "error:.*by assignment is deprecated:DeprecationWarning")


ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")


def c_doubles(values):
    """A C array holding the values (a copy)."""
    values = np.ascontiguousarray(values, dtype=np.float64).ravel()
    return ffi.new("double[]", values.tolist() or [0.0])


def c_element_eval(element, params, state, u):
    """fricreg_element_eval at one point: (status, f, dfdu, dfdp, state_out) as arrays."""
    dim, npar, nst = element.dim, element.nparams, element.nstate
    f, dfdu = ffi.new("double[]", dim), ffi.new("double[]", dim * dim)
    dfdp, w = ffi.new("double[]", dim * npar), ffi.new("double[]", max(nst, 1))
    status = lib.fricreg_element_eval(element._type, c_doubles(params), c_doubles(state),
                                      c_doubles(u), f, dfdu, dfdp, w)
    as_array = lambda buf, n: np.frombuffer(ffi.buffer(buf, 8 * n), dtype=np.float64).copy()
    return (status, as_array(f, dim), as_array(dfdu, dim * dim).reshape(dim, dim),
            as_array(dfdp, dim * npar).reshape(dim, npar), as_array(w, nst))


def c_law_eval(code, v, f_eq, mun, eps):
    """fricreg_law_eval at one contact: (status, f)."""
    f = ffi.new("double *")
    status = lib.fricreg_law_eval(code, v, f_eq, mun, eps, f)
    return status, f[0]


def fricreg_sim():
    """fricreg-sim: FRICREG_SIM (ctest sets it), beside the package (build/python/fricreg), or
    the source tree's build; the test is skipped where there is none."""
    package = os.path.dirname(os.path.abspath(fricreg.__file__))
    for path in (os.environ.get("FRICREG_SIM", ""),
                 os.path.join(package, "..", "..", "fricreg-sim"),
                 os.path.join(ROOT, "build", "fricreg-sim")):
        if path and os.access(path, os.X_OK):
            return path
    pytest.skip("fricreg-sim not found (set FRICREG_SIM)")
