#!/bin/sh
# Installs the build into a temporary prefix, then builds and runs four consumers against
# the installed copy only: C with find_package(fricreg CONFIG), C with pkg-config, and
# Fortran with the installed module and with the installed module sources (when the Fortran
# interface was built).
# Usage: install.sh BUILD_DIR SOURCE_DIR C_COMPILER FORTRAN_COMPILER|-
build=$1 src=$2 cc=$3 fc=$4
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
export LD_LIBRARY_PATH="$libdir${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"

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

    # 4. Fortran from the installed module sources, compiled in the order fortran/README.md
    #    gives, as a compiler that cannot read the installed .mod files would.
    fsrc=$prefix/include/fricreg/src
    order="fricreg_constants.f90 fricreg_c.f90 fricreg.F90 fricreg_f77.f90" sim=""
    if [ -f "$fsrc/fricreg_sim_c.f90" ]; then
        order="fricreg_constants.f90 fricreg_c.f90 fricreg_sim_c.f90 fricreg.F90"
        order="$order fricreg_f77.f90 fricreg_sim_f77.f90" sim=-DFRICREG_HAVE_SIM
    fi
    mkdir -p "$work/fsrc"
    check "Fortran module sources compile" sh -c "cd '$work/fsrc' && for f in $order; do
        '$fc' -c $sim -I'$fsrc' '$fsrc/'\$f || exit 1; done"
    check "Fortran consumer build from the sources" sh -c "cd '$work/fsrc' && '$fc' -I. \
        '$src/tests/consumer/consumer.f90' *.o -L'$libdir' -lfricreg -o '$work/f_src_consumer'"
    check "Fortran consumer from the sources" "$work/f_src_consumer"
fi
echo "$passes passed, $fails failed"
[ $fails -eq 0 ]
