# SPDX-License-Identifier: GPL-3.0-or-later
"""fricreg: dry (Coulomb) friction with stick-slip, from Python.

A binding (cffi, API mode) of the C library fricreg: D. D. Quinn's regularization of Coulomb
friction (J. Vib. Acoust. 126 (2004) 391-397) and the paper's comparison laws on numpy arrays,
the friction elements of joints (Jenkins, Iwan, 3-D contact with lift-off), many points in one
C call, the objects built on them, and a joint's parameters fitted to a test's levels. Every
call that fails raises :class:`fricreg.Error`
(bad input: :class:`fricreg.InputError`, also a ``ValueError``) with the library's message.
The guide is ``docs/python.md``.
"""
from . import aft, aft_layouts, context, element, errors, fit, harmonic_balance, laws, structure
from ._fricreg import ffi as _ffi, lib as _lib
from .aft import *  # noqa: F401,F403
from .aft_layouts import *  # noqa: F401,F403
from .context import *  # noqa: F401,F403
from .element import *  # noqa: F401,F403
from .errors import *  # noqa: F401,F403
from .fit import *  # noqa: F401,F403
from .harmonic_balance import *  # noqa: F401,F403
from .laws import *  # noqa: F401,F403
from .structure import *  # noqa: F401,F403

#: The C library's version, "MAJOR.MINOR.PATCH" (``fricreg_version()``).
__version__ = _ffi.string(_lib.fricreg_version()).decode()

_MODULES = (aft, aft_layouts, context, element, errors, fit, harmonic_balance, laws, structure)
__all__ = sorted(set(name for module in _MODULES for name in module.__all__)) + ["__version__"]
