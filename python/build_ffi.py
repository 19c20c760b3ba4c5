# SPDX-License-Identifier: GPL-3.0-or-later
"""The cffi builder of fricreg's Python binding, in cffi's API mode: the extension module
``fricreg._fricreg`` is C compiled against fricreg's headers and linked to libfricreg.

Two builds use it:

- CMake (``python/CMakeLists.txt``): ``python3 build_ffi.py --emit OUT.c`` writes the module's
  C source, which CMake compiles and links to the library built beside it;
- setuptools (``setup.py``, ``cffi_modules``): ``ffibuilder`` compiled against an installed
  fricreg, the flags from pkg-config.
"""
import os
import subprocess
import sys

import cffi

HERE = os.path.dirname(os.path.abspath(__file__))
# The public headers the module compiles against, and the declarations it calls: one cdef
# file per surface in cdef/, base.h first (the status codes every other one uses).
HEADERS = ("fricreg.h", "fricreg_element.h", "fricreg_aft.h", "fricreg_hb.h",
           "fricreg_structure.h", "fricreg_fit.h")
CDEFS = ["base.h"] + sorted(name for name in os.listdir(os.path.join(HERE, "cdef"))
                            if name.endswith(".h") and name != "base.h")


def make_builder(**compile_args):
    """A cffi FFI for the module ``fricreg._fricreg``, compile_args passed to set_source."""
    builder = cffi.FFI()
    for name in CDEFS:
        with open(os.path.join(HERE, "cdef", name), encoding="utf-8") as cdef:
            builder.cdef(cdef.read())
    source = "".join('#include "%s"\n' % h for h in HEADERS)
    with open(os.path.join(HERE, "callbacks.c"), encoding="utf-8") as callbacks:
        source += callbacks.read()
    builder.set_source("fricreg._fricreg", source, **compile_args)
    return builder


def _pkg_config(*args):
    """The words pkg-config prints for fricreg (an installed library)."""
    out = subprocess.run(["pkg-config", *args, "fricreg"], check=True,
                         capture_output=True, text=True).stdout
    return out.split()


def _installed_args():
    """set_source's arguments for an installed fricreg, found by pkg-config."""
    libdirs = [w[2:] for w in _pkg_config("--libs-only-L")]
    return {
        "include_dirs": [w[2:] for w in _pkg_config("--cflags-only-I")],
        "library_dirs": libdirs,
        "runtime_library_dirs": libdirs,
        "libraries": ["fricreg"],
    }


if __name__ == "__main__":
    if len(sys.argv) != 3 or sys.argv[1] != "--emit":
        sys.exit("usage: build_ffi.py --emit OUT.c")
    make_builder().emit_c_code(sys.argv[2])
else:  # cffi_modules of setup.py runs this file
    ffibuilder = make_builder(**_installed_args())
