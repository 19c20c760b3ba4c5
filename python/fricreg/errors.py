# SPDX-License-Identifier: GPL-3.0-or-later
"""Errors and warnings: a nonzero status of the C library raised as an exception.

Every fricreg function returns a status (``enum fricreg_status`` of ``fricreg.h``); the
binding raises it as :class:`Error`, or as one of its subclasses that are also Python's own
``ValueError`` (bad input) and ``MemoryError`` (allocation failure), so that callers catch
them either way. The message is the library's, prefixed by the call that failed.
"""
from ._fricreg import ffi, lib

__all__ = ["Error", "InputError", "OutOfMemoryError", "AccuracyWarning", "Interrupted"]


class Error(Exception):
    """A fricreg call failed.

    Attributes
    ----------
    status : int
        The library's status code (``enum fricreg_status``: ``FRICREG_ESINGULAR`` = 8, ...).
    name : str
        The code's name, e.g. ``"FRICREG_ESINGULAR"``.
    result : object
        What a long call had computed when it failed, where the library keeps it (a
        continuation's points reached, a backbone's points), as the call would have returned
        it; None otherwise.
    """

    def __init__(self, status, message):
        super().__init__(message)
        self.status = status
        self.name = _STATUS_NAMES.get(status, "FRICREG_E%d" % status)
        self.result = None


class InputError(Error, ValueError):
    """An argument was refused: NULL, out of range, NaN or infinite, of the wrong size, or a
    coupling matrix not symmetric or not positive semidefinite (``FRICREG_ENULL``,
    ``EINVAL``, ``ENONFINITE``, ``ESIZE``, ``ENOTSYM``, ``ENOTPSD``); also a ``ValueError``.
    The binding's own refusals before any call (a shape, a dtype, an unknown name, a value
    out of range) are this class too, of status ``FRICREG_EINVAL``, their message naming the
    argument: ``except fricreg.Error`` catches every refusal."""


class OutOfMemoryError(Error, MemoryError):
    """The library could not allocate (``FRICREG_ENOMEM``); also a ``MemoryError``."""


class AccuracyWarning(UserWarning):
    """A run's result may be less accurate than asked: the library's warnings
    (``enum fricreg_warning``: a coarse step, an error estimate above its tolerance, ...)."""


#: Ctrl-C (SIGINT) stopped a long call through the library's own cancellation: Python's own
#: ``KeyboardInterrupt`` (since 1.9 the class itself, not a subclass: CPython exits with
#: status 130, as a shell expects of Ctrl-C, only for that exact class), raised with a
#: ``result`` attribute holding what the call had computed when it stopped (a continuation's
#: points so far, a backbone's points, a structure's run so far; None where it had nothing).
#: ``except fricreg.Interrupted`` and ``except KeyboardInterrupt`` catch it alike.
Interrupted = KeyboardInterrupt


def interrupted(result):
    """The KeyboardInterrupt of a call Ctrl-C stopped, its ``result`` what the call had
    computed."""
    error = KeyboardInterrupt("interrupted (Ctrl-C); the points computed so far are in .result")
    error.result = result
    return error


_STATUS_NAMES = dict(ffi.typeof("enum fricreg_status").elements)  # value: name
_INPUT = {lib.FRICREG_ENULL, lib.FRICREG_EINVAL, lib.FRICREG_ENONFINITE, lib.FRICREG_ESIZE,
          lib.FRICREG_ENOTSYM, lib.FRICREG_ENOTPSD}


def refused(message):
    """The binding's own refusal of an argument, before any C call: an :class:`InputError`
    (a ``ValueError`` too) of status ``FRICREG_EINVAL``; ``message`` begins with the
    argument's name."""
    return InputError(lib.FRICREG_EINVAL, message)


def raise_status(status, where, detail=""):
    """Raise the exception of a nonzero status of the call ``where``: the detail (the
    library's own message) followed by the status's name, or without one the library's text
    for the status."""
    text = ffi.string(lib.fricreg_strerror(status)).decode()
    name = _STATUS_NAMES.get(status, "FRICREG_E%d" % status)
    message = "%s: %s (%s)" % (where, detail, name) if detail else "%s: %s" % (where, text)
    if status in _INPUT:
        raise InputError(status, message)
    if status == lib.FRICREG_ENOMEM:
        raise OutOfMemoryError(status, message)
    raise Error(status, message)
