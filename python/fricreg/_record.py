# SPDX-License-Identifier: GPL-3.0-or-later
"""The binding's result records: named tuples read by name, so that a later release can add a
field without breaking a caller. Reading one by position (unpacking, indexing, iterating) still
works in 1.9 but warns (``DeprecationWarning``): a field added later would shift it, as
``multipliers`` did to ``Solution`` and ``Response`` in 1.9.
"""
import sys
import warnings
from collections import namedtuple


def record(name, fields, doc):
    """A named-tuple class ``name`` of the space-separated ``fields`` and docstring ``doc``:
    its fields read by name as a namedtuple's; ``==``, ``len``, ``repr``, pickling and
    ``_asdict``/``_replace`` as a namedtuple's; iteration and ``[i]`` warn."""
    base = namedtuple(name, fields)

    def positional(self):
        warnings.warn("%s: reading a result by position is deprecated and will end in 2.0 (a "
                      "later release may add fields): read it by name (%s)"
                      % (name, ", ".join(self._fields)), DeprecationWarning, stacklevel=3)

    def __iter__(self):
        positional(self)
        return tuple.__iter__(self)

    def __getitem__(self, index):
        positional(self)
        return tuple.__getitem__(self, index)

    def _asdict(self):
        return {field: getattr(self, field) for field in self._fields}

    def _replace(self, **changes):
        values = {field: changes.pop(field, getattr(self, field)) for field in self._fields}
        if changes:
            raise ValueError("%s: no fields %s" % (name, ", ".join(changes)))
        return type(self)(**values)

    def __getnewargs__(self):
        return tuple(getattr(self, field) for field in self._fields)

    module = sys._getframe(1).f_globals.get("__name__", __name__)  # as namedtuple's, for pickle
    namespace = {"__slots__": (), "__doc__": doc, "__iter__": __iter__,
                 "__getitem__": __getitem__, "_asdict": _asdict, "_replace": _replace,
                 "__getnewargs__": __getnewargs__, "__module__": module}
    return type(name, (base,), namespace)
