# SPDX-License-Identifier: GPL-3.0-or-later
"""The binding's one settings style (docs/python.md, "Settings"): a setting is changed by a
``set_*`` method and read by a read-only property of the same name; a value fixed at
construction (a size, a type) is a read-only property that nothing changes. A property that
1.8 let one assign still takes the assignment in 1.9, through its method, but warns
(``DeprecationWarning``) and ends in 2.0.
"""
import warnings


def assigned(owner, name, method):
    """Warn that ``owner.name = value`` is deprecated in favour of ``owner.method(...)``; called
    by the property's setter, so the warning points at the caller's assignment."""
    warnings.warn("%s: setting %s by assignment is deprecated and will end in 2.0 (settings "
                  "are set_* methods): call %s(...)" % (owner, name, method),
                  DeprecationWarning, stacklevel=3)


def fixed(name, doc):
    """A read-only property reading ``self._name``: a value fixed at construction (a size, a
    type), which no method changes; assigning it raises ``AttributeError``."""
    attribute = "_" + name
    return property(lambda self: getattr(self, attribute), doc=doc)
