# SPDX-License-Identifier: GPL-3.0-or-later
"""Checks the import blocker beside this file: run with its folder on PYTHONPATH, every module
the binding's tests and examples take as optional (pytest.importorskip, or an import inside
try/except ImportError) fails to import, while the required ones (cffi, numpy, pytest) and
fricreg import. Usage: PYTHONPATH=BLOCKER:PACKAGE python3 check_blocker.py SOURCE_ROOT"""
import ast
import importlib
import os
import sys


def optional_imports(path):
    """The top-level names a file imports only as optional: importorskip's first argument, and
    imports in a try whose handler catches ImportError (or ModuleNotFoundError)."""
    with open(path, encoding="utf-8") as f:
        tree = ast.parse(f.read(), path)
    names = set()
    for node in ast.walk(tree):
        if (isinstance(node, ast.Call) and getattr(node.func, "attr", "") == "importorskip"
                and node.args and isinstance(node.args[0], ast.Constant)):
            names.add(node.args[0].value.split(".")[0])
        if isinstance(node, ast.Try) and any(
                getattr(h.type, "id", "") in ("ImportError", "ModuleNotFoundError")
                for h in node.handlers):
            for inner in node.body:
                if isinstance(inner, ast.Import):
                    names.update(a.name.split(".")[0] for a in inner.names)
                elif isinstance(inner, ast.ImportFrom) and inner.module:
                    names.add(inner.module.split(".")[0])
    return names


def main(root):
    results = []  # (passed, what failed)

    def check(ok, failure):
        results.append((ok, failure))

    check(any(type(f).__name__ == "_Hide" for f in sys.meta_path),
          "the blocker is not on sys.meta_path: was its folder on PYTHONPATH?")
    files = [os.path.join(folder, name)
             for sub in ("python/tests", "python/fricreg", "examples/python")
             for folder, _, names in os.walk(os.path.join(root, sub))
             for name in names if name.endswith(".py")]
    optional = set().union(*(optional_imports(p) for p in files)) - {"fricreg"}
    check({"hypothesis", "scipy", "matplotlib"} <= optional,
          f"the scan found too few optional modules: {sorted(optional)}")
    for name in sorted(optional) + ["scipy.sparse", "matplotlib.pyplot"]:
        check(not importable(name), f"{name} imported: the blocker does not hide it")
    for name in ("cffi", "numpy", "pytest", "fricreg"):
        check(importable(name), f"{name} is required but did not import")
    for ok, failure in results:
        if not ok:
            print("FAIL:", failure)
    failed = sum(not ok for ok, _ in results)
    print(f"{len(results) - failed} passed, {failed} failed")
    return 1 if failed else 0


def importable(name):
    try:
        importlib.import_module(name)
        return True
    except ModuleNotFoundError:
        return False


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
