# SPDX-License-Identifier: GPL-3.0-or-later
"""An import blocker: on PYTHONPATH, Python starts as on a machine that has only the README's
first command installed, without the optional modules below (Debian's python3-hypothesis,
python3-scipy, python3-matplotlib). Importing one of them, or anything inside it, raises
ModuleNotFoundError, as where the package is absent. .ci/run runs the binding's tests so, and
check_blocker.py checks that it blocks every optional module the tests and examples import."""
import importlib.abc
import sys

HIDDEN = ("hypothesis", "scipy", "matplotlib")


class _Hide(importlib.abc.MetaPathFinder):
    def find_spec(self, name, path=None, target=None):
        if name.split(".")[0] in HIDDEN:
            raise ModuleNotFoundError(f"No module named '{name}' (hidden by {__file__})",
                                      name=name)
        return None


sys.meta_path.insert(0, _Hide())
