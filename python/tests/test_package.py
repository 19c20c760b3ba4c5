# SPDX-License-Identifier: GPL-3.0-or-later
"""The package as a whole: its version is the library's, its errors are Python's own kinds,
every public name has a docstring with its shapes and sources, and the guide's examples
(docs/python.md) run as printed."""
import os
import re
import warnings

import pytest

import fricreg

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")


def test_version_is_the_librarys():
    # FRICREG_VERSION: CMake's project version, set in the test's environment
    assert fricreg.__version__ == os.environ.get("FRICREG_VERSION", fricreg.__version__)
    assert re.fullmatch(r"\d+\.\d+\.\d+", fricreg.__version__)


def test_errors_are_pythons_kinds():
    assert issubclass(fricreg.InputError, fricreg.Error)
    assert issubclass(fricreg.InputError, ValueError)
    assert issubclass(fricreg.OutOfMemoryError, MemoryError)
    assert issubclass(fricreg.AccuracyWarning, UserWarning)
    with pytest.raises(fricreg.Error) as info:
        fricreg.law_eval("tanh", [float("nan")], None, [1.0], 0.1)
    assert info.value.status == 3 and info.value.name == "FRICREG_ENONFINITE"


def test_every_public_name_is_documented():
    for name in fricreg.__all__:
        if name.startswith("__") or name in ("LAWS", "ELEMENT_TYPES"):
            continue
        if name == "Interrupted":  # Python's own class (errors.py's comment says why)
            assert fricreg.Interrupted is KeyboardInterrupt
            continue
        doc = getattr(fricreg, name).__doc__
        assert doc and len(doc) > 40, name
    for function in (fricreg.law_eval, fricreg.Element, fricreg.Element.eval, fricreg.segalman):
        assert "Raises" in function.__doc__ and "shape" in function.__doc__.lower()


def python_blocks(path):
    """The ```python blocks of a Markdown page."""
    with open(path, encoding="utf-8") as page:
        return re.findall(r"```python\n(.*?)```", page.read(), flags=re.S)


def test_the_guides_examples_run(tmp_path, monkeypatch):
    blocks = python_blocks(os.path.join(ROOT, "docs", "python.md"))
    assert len(blocks) >= 3
    monkeypatch.chdir(tmp_path)
    for block in blocks:
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            exec(compile(block, "docs/python.md", "exec"), {})
