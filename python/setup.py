# SPDX-License-Identifier: GPL-3.0-or-later
"""Builds the binding against an installed fricreg found by pkg-config (no network):

    PKG_CONFIG_PATH=PREFIX/lib/pkgconfig python3 setup.py build_ext --inplace
    PKG_CONFIG_PATH=PREFIX/lib/pkgconfig python3 -m pip install --no-build-isolation .

The CMake build (cmake/python.cmake) builds the same module beside the library it builds."""
import subprocess

from setuptools import setup

version = subprocess.run(["pkg-config", "--modversion", "fricreg"], check=True,
                         capture_output=True, text=True).stdout.strip()
# The rest of the metadata is pyproject.toml's [project] table (PEP 621); the version is
# dynamic there, the library's own.
setup(
    version=version,
    packages=["fricreg"],
    setup_requires=["cffi>=1.12"],
    cffi_modules=["build_ffi.py:ffibuilder"],
)
