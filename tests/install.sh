#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# Installs the build into a temporary prefix, then builds and runs consumers against the
# installed copy only: C with find_package(fricreg CONFIG), C with pkg-config, and (when the
# Fortran interface was built) Fortran with the installed module, with pkg-config
# fricreg-fortran, fixed-form F77 with -fdefault-integer-8 through fricreg-fortran-ilp64, and
# with the installed module sources. Runs the installed fricreg-sim (when the drivers were
# built) from its prefix, and from the prefix moved elsewhere, with no LD_LIBRARY_PATH; checks
# the documentation (with fortran/README.md and the example sources its links and paths name)
# and fricreg-sim's man page are installed and man renders the page. With the Python binding
# built: the installed package imports from the prefix (and the moved prefix) with no
# LD_LIBRARY_PATH, and python/setup.py builds it against the installed library (pkg-config).
# With the MATLAB/Octave gateway built and octave-cli present: it runs from the prefix (and the
# moved prefix) with no LD_LIBRARY_PATH.
# Usage: install.sh BUILD_DIR SOURCE_DIR C_COMPILER FORTRAN_COMPILER|- [PYTHON|-]
build=$1 src=$2 cc=$3 fc=$4 python=${5:--}
work=$(mktemp -d "${TMPDIR:-/tmp}/fricreg-install.XXXXXX")
trap 'rm -rf "$work"' EXIT
prefix=$work/prefix
fails=0 passes=0
check() { # NAME COMMAND...: runs a step, counts it
    name=$1; shift
    if "$@" >"$work/log" 2>&1; then passes=$((passes + 1)); else
        fails=$((fails + 1)); echo "FAIL: $name"; tail -n 20 "$work/log"; fi
}

check "install" cmake --install "$build" --prefix "$prefix"
libdir=$(dirname "$(find "$prefix" -name 'libfricreg.so.*' | head -n 1)")

# 0. The installed fricreg-sim finds libfricreg by its RPATH ($ORIGIN/../lib), no
#    LD_LIBRARY_PATH: the paper's oscillator rests at x(20) = -0.750090 (Sec. 3.1.1).
sim_runs() { # PREFIX: runs its fricreg-sim, and checks it loaded that prefix's library
    env -u LD_LIBRARY_PATH "$1/bin/fricreg-sim" --version | grep -q '^fricreg-sim ' &&
    env -u LD_LIBRARY_PATH "$1/bin/fricreg-sim" oscillator --t-end 20 |
        grep -q '"x": \[-0\.7500899' &&
    env -u LD_LIBRARY_PATH ldd "$1/bin/fricreg-sim" | grep -q "=> $1/.*libfricreg\.so"
}
if [ -x "$prefix/bin/fricreg-sim" ]; then
    check "installed fricreg-sim runs from its prefix" sim_runs "$prefix"
fi
# 0a. The Python package from the prefix alone (its module's RPATH, $ORIGIN-relative): a
#     Jenkins element stuck below mun/kt is the spring kt u.
python_runs() { # PREFIX
    site=$(cd "$1" && dirname "$(find . -path '*/fricreg/__init__.py' | head -n 1)")
    (cd "$work" && env -u LD_LIBRARY_PATH PYTHONPATH="$1/$(dirname "$site")" "$python" -c '
import fricreg
r = fricreg.Element("jenkins", [2.0, 0.5]).eval([0.1], [0.0])
assert r.f[0] == 0.2 and fricreg.__file__.startswith("'"$1"'"), (r, fricreg.__file__)')
}
if [ "$python" != - ]; then
    check "installed Python package imports from its prefix" python_runs "$prefix"
fi
# 0b. The MATLAB/Octave gateway from the prefix alone (the .mex's RPATH, $ORIGIN-relative),
#     where it was built (FRICREG_OCTAVE) and octave-cli is there: the same Jenkins element.
octave=$(cd "$prefix" && find . -name fricreg_mex.mex | head -n 1)
octave=${octave#./}
command -v octave-cli >/dev/null 2>&1 || octave=
octave_runs() { # PREFIX
    dir=$1/$(dirname "$octave")
    (cd "$work" && env -u LD_LIBRARY_PATH octave-cli --no-gui --norc --eval "
addpath('$dir'); f = fricreg_element_eval('jenkins', [2 0.5], 0.1);
assert(f == 0.2 && strncmp(which('fricreg_mex'), '$dir', numel('$dir')))")
}
if [ -n "$octave" ]; then
    check "installed Octave gateway runs from its prefix" octave_runs "$prefix"
fi
export LD_LIBRARY_PATH="$libdir${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"

# 0b. The documentation and the man page under the prefix: README.md, CHANGELOG.md, LICENSE
#     and every docs/*.md and figure in share/doc/fricreg (docs/ kept a folder, so README.md's
#     links hold); fricreg-sim.1 in share/man/man1, which man finds from the prefix alone.
docdir=$(dirname "$(find "$prefix" -path '*/doc/fricreg/LICENSE' | head -n 1)")
docs_installed() {
    for f in README.md CHANGELOG.md LICENSE; do cmp -s "$src/$f" "$docdir/$f" || return 1; done
    for f in "$src"/docs/*.md "$src"/docs/*.png; do
        cmp -s "$f" "$docdir/docs/$(basename "$f")" || { echo "missing: $f"; return 1; }
    done
}
check "README.md, CHANGELOG.md, LICENSE and docs/ are installed" docs_installed
# 0c. The installed documents' references hold in the doc folder: fortran/README.md and the
#     example sources (examples/, as the tree lays them out) are installed, every relative
#     Markdown link of README.md, docs/*.md and fortran/README.md names a file there (but
#     src/README.md, the source tree's module map, which is not installed without the
#     sources), and every example file they name (examples/....c, .h, .f90, .f, .sh) is there.
links_hold() {
    bad=0
    cmp -s "$src/fortran/README.md" "$docdir/fortran/README.md" || { echo "missing: fortran/README.md"; bad=1; }
    for f in $(cd "$src" && find examples -name '*.c' -o -name '*.h' -o -name '*.f90' -o -name '*.f' -o -name '*.sh'); do
        cmp -s "$src/$f" "$docdir/$f" || { echo "missing: $f"; bad=1; }
    done
    for md in "$docdir/README.md" "$docdir"/docs/*.md "$docdir/fortran/README.md"; do
        [ -f "$md" ] || continue # reported above
        dir=$(dirname "$md")
        for link in $(grep -o '](\([^)#: ]*\)' "$md" | sed 's/^](//' | sort -u); do
            case $link in "" | *src/README.md) continue ;; esac
            [ -e "$dir/$link" ] || { echo "${md#"$docdir"/}: link $link dangles"; bad=1; }
        done
        for ex in $(grep -oE 'examples/[A-Za-z0-9_/.-]*\.(c|h|f90|f|sh)' "$md" | sort -u); do
            [ -f "$docdir/$ex" ] || { echo "${md#"$docdir"/}: $ex is not installed"; bad=1; }
        done
    done
    return $bad
}
check "the installed documents' links and example paths hold" links_hold
if [ -x "$prefix/bin/fricreg-sim" ]; then
    page=$(find "$prefix" -path '*/man1/fricreg-sim.1' | head -n 1)
    check "the man page is installed in share/man/man1" test -f "$prefix/share/man/man1/fricreg-sim.1"
    check "the installed man page is the installed program's" \
        sh -c "env -u LD_LIBRARY_PATH '$prefix/bin/fricreg-sim' --man | cmp -s - '$page'"
    if command -v man >/dev/null 2>&1; then
        man_renders() { # man finds the page from the prefix's share/man, or reads it by path
            MANWIDTH=80 man -M "$prefix/share/man" fricreg-sim >"$work/man.txt" 2>"$work/man.err" &&
            grep -q '^FRICREG-SIM(1)' "$work/man.txt" && grep -q '^   hb$' "$work/man.txt" &&
            MANWIDTH=80 man -l "$page" | cmp -s - "$work/man.txt" && [ ! -s "$work/man.err" ]
        }
        check "man -M PREFIX/share/man fricreg-sim renders the page" man_renders
    fi
fi

# 1. CMake: find_package(fricreg CONFIG), shared and static.
check "cmake configure" cmake -S "$src/tests/consumer" -B "$work/cmake" \
    -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_C_COMPILER="$cc"
check "cmake build" cmake --build "$work/cmake"
check "find_package consumer (shared)" "$work/cmake/consumer"
check "find_package consumer (static)" "$work/cmake/consumer_static"
check "the shared consumer loads the installed library" \
    sh -c "ldd '$work/cmake/consumer' | grep -q '$libdir/libfricreg.so'"

# 2. pkg-config.
export PKG_CONFIG_PATH="$libdir/pkgconfig"
check "pkg-config knows fricreg" pkg-config --exists fricreg
check "fricreg.pc names the licence" grep -qx 'License: GPL-3.0-or-later' "$libdir/pkgconfig/fricreg.pc"
check "the licence text is installed" sh -c "find '$prefix' -path '*/doc/fricreg/LICENSE' | grep -q ."
check "pkg-config consumer build" sh -c "$cc '$src/tests/consumer/consumer.c' \
    \$(pkg-config --cflags fricreg) \$(pkg-config --libs fricreg) -o '$work/pc_consumer'"
check "pkg-config consumer" "$work/pc_consumer"

# 3. Fortran, with the installed module (include/fricreg/<compiler-version>/).
if [ "$fc" != "-" ]; then
    moddir=$(dirname "$(find "$prefix" -name 'fricreg.mod' | head -n 1)")
    check "Fortran consumer build" "$fc" -I"$moddir" "$src/tests/consumer/consumer.f90" \
        -L"$libdir" -lfricreg_fortran -lfricreg -o "$work/f_consumer"
    check "Fortran consumer" "$work/f_consumer"

    # 3b. pkg-config fricreg-fortran: the module folder and the libraries, none typed by hand.
    check "pkg-config knows fricreg-fortran" pkg-config --exists fricreg-fortran
    check "pkg-config Fortran consumer build" sh -c "'$fc' '$src/tests/consumer/consumer.f90' \
        \$(pkg-config --cflags --libs fricreg-fortran) -o '$work/pc_f_consumer'"
    check "pkg-config Fortran consumer" "$work/pc_f_consumer"
    # 3c. Fixed-form F77 with an 8-byte INTEGER: fricreg-fortran-ilp64 gives the flag and the
    #     ILP64 library; the consumer's FRCHK, statuses and numbers pass.
    f77=$src/tests/consumer/fortran_ilp64
    if pkg-config --exists fricreg-fortran-ilp64; then
        check "pkg-config ILP64 F77 consumer build" sh -c "'$fc' -std=legacy \
            '$f77/consumer_f77.f' \$(pkg-config --cflags --libs fricreg-fortran-ilp64) \
            -o '$work/pc_f77_ilp64'"
        check "pkg-config ILP64 F77 consumer" "$work/pc_f77_ilp64"
        # The same with find_package(fricreg COMPONENTS fortran_ilp64).
        check "cmake ILP64 F77 configure" cmake -S "$f77" -B "$work/cmake_f77" \
            -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_C_COMPILER="$cc" -DCMAKE_Fortran_COMPILER="$fc"
        check "cmake ILP64 F77 build" cmake --build "$work/cmake_f77"
        check "cmake ILP64 F77 consumer" "$work/cmake_f77/consumer_f77"
    fi

    # 4. Fortran from the installed module sources, compiled in the order fortran/README.md
    #    gives, as a compiler that cannot read the installed .mod files would.
    fsrc=$prefix/include/fricreg/src
    objects="fricreg_base.F90 fricreg_laws.F90 fricreg_ctx.F90 fricreg_disk_ctx.F90"
    objects="$objects fricreg_jenkins.F90 fricreg_iwan.F90 fricreg_element.F90 fricreg_aft.F90"
    # each F77 file's generated entry points (fortran/*_f77.txt) right after it
    f77="fricreg_f77.f90 fricreg_f77_generated.f90 fricreg_f77_check.f90"
    f77="$f77 fricreg_joints_f77.f90 fricreg_joints_f77_generated.f90 fricreg_element_f77.f90"
    order="fricreg_constants.f90 fricreg_c.f90 $objects fricreg.F90 $f77" sim=""
    if [ -f "$fsrc/fricreg_sim_c.f90" ]; then
        objects="$objects fricreg_sim.F90 fricreg_exact.F90 fricreg_structure.F90 fricreg_hb.F90"
        objects="$objects fricreg_fit.F90"
        order="fricreg_constants.f90 fricreg_c.f90 fricreg_sim_c.f90 $objects fricreg.F90"
        order="$order $f77 fricreg_sim_f77.f90 fricreg_sim_f77_generated.f90"
        order="$order fricreg_structure_f77.f90 fricreg_structure_f77_generated.f90"
        order="$order fricreg_hb_f77.f90 fricreg_hb_f77_generated.f90 fricreg_warnings_f77.f90"
        sim=-DFRICREG_HAVE_SIM
    fi
    mkdir -p "$work/fsrc"
    check "Fortran module sources compile" sh -c "cd '$work/fsrc' && for f in $order; do
        '$fc' -c $sim -I'$fsrc' '$fsrc/'\$f || exit 1; done"
    check "Fortran consumer build from the sources" sh -c "cd '$work/fsrc' && '$fc' -I. \
        '$src/tests/consumer/consumer.f90' *.o -L'$libdir' -lfricreg -o '$work/f_src_consumer'"
    check "Fortran consumer from the sources" "$work/f_src_consumer"
fi

# 4b. The Python package built by setuptools (python/setup.py) against the installed library,
#     found by pkg-config; its element and law tests pass on it. Needs python3-setuptools.
if [ "$python" != - ] && "$python" -c 'import setuptools' 2>/dev/null; then
    cp -r "$src/python" "$work/pysrc"
    pc=$(dirname "$(find "$prefix" -name fricreg.pc | head -n 1)")
    check "setup.py builds the binding against the installed fricreg" sh -c "cd '$work/pysrc' &&
        PKG_CONFIG_PATH='$pc' '$python' setup.py -q build_ext --inplace"
    check "the binding built by setup.py passes its tests" sh -c "cd '$work/pysrc/tests' &&
        PYTHONPATH='$work/pysrc' PYTHONDONTWRITEBYTECODE=1 '$python' -m pytest -q \
        -p no:cacheprovider test_laws.py test_element.py"
elif [ "$python" != - ]; then
    echo "python3-setuptools absent: setup.py's build is not checked"
fi

# 5. The prefix moved elsewhere: fricreg-sim still runs, on the moved library (relative RPATH).
if [ -x "$prefix/bin/fricreg-sim" ] || [ "$python" != - ] || [ -n "$octave" ]; then
    check "move the prefix" mv "$prefix" "$work/moved"
fi
if [ -x "$work/moved/bin/fricreg-sim" ]; then
    check "installed fricreg-sim runs from a moved prefix" sim_runs "$work/moved"
fi
if [ "$python" != - ]; then
    check "installed Python package imports from a moved prefix" python_runs "$work/moved"
fi
if [ -n "$octave" ]; then
    check "installed Octave gateway runs from a moved prefix" octave_runs "$work/moved"
fi
echo "$passes passed, $fails failed"
[ $fails -eq 0 ]
