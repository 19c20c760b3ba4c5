# SPDX-License-Identifier: GPL-3.0-or-later
"""Arguments handed to the C library: arrays as float64, C-contiguous, of the shape a call
needs, anything else converted (a copy) or refused with a message that names the argument;
and names chosen from a fixed table (a method, a damping)."""
import numpy as np

from ._fricreg import ffi
from .errors import refused


def as_doubles(value, name, ndim=None):
    """value as a C-contiguous float64 array (a copy only where it is not one already).

    Raises ValueError naming ``name`` where value is not real numbers (complex, strings,
    objects) or has not ``ndim`` dimensions."""
    try:
        array = np.asarray(value)
    except Exception as exc:  # ragged lists and the like
        raise refused("%s: not an array of numbers (%s)" % (name, exc)) from None
    if array.dtype.kind not in "biuf":
        raise refused("%s: dtype %s is not real numbers" % (name, array.dtype))
    array = np.ascontiguousarray(array, dtype=np.float64)
    if ndim is not None and array.ndim != ndim:
        raise refused("%s: %d dimensions, shape %s; expected %d"
                      % (name, array.ndim, array.shape, ndim))
    return array


def as_scalar(value, name):
    """value as a Python float; ValueError naming the argument where it is not one real
    number (an array of another shape, a string, a complex)."""
    if isinstance(value, (str, bytes)):
        raise refused("%s: %r is not a real number" % (name, value))
    array = np.asarray(value)
    if array.shape != ():
        raise refused("%s: shape %s; expected a number" % (name, array.shape))
    if array.dtype.kind not in "biuf":
        raise refused("%s: %r is not a real number" % (name, value))
    return float(array)


def as_integer(value, name):
    """value as a Python int; InputError naming the argument where it is not an integer (a
    float, even 3.0, a string, a bool)."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, np.integer)):
        raise refused("%s: %r is not an integer" % (name, value))
    return int(value)


def pointer(array):
    """A ``double[]`` view of a C-contiguous float64 array for a C call (it keeps the array
    alive while the view is)."""
    return ffi.from_buffer("double[]", array)


def choice(table, value, name):
    """table[value] for an argument that names one of table's keys; ValueError naming the
    argument and the choices otherwise."""
    if value not in table:
        raise refused("%s: %r is not one of %s" % (name, value, ", ".join(map(repr, table))))
    return table[value]
