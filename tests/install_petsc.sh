#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# Installs the build into a temporary prefix, then builds a user's PETSc program against the
# installed libfricreg_petsc only, with find_package(fricreg COMPONENTS petsc) and with
# pkg-config fricreg_petsc (compiled by the MPI wrapper, with -Wl,-rpath to the prefix's lib
# as a user of a private prefix links), and runs each on one rank with no LD_LIBRARY_PATH:
# the consumer's RUNPATH finds the adapter, the adapter's RUNPATH $ORIGIN finds libfricreg
# beside it (a RUNPATH is not inherited), also from the prefix moved elsewhere.
# Usage: install_petsc.sh BUILD_DIR SOURCE_DIR MPI_C_COMPILER MPIEXEC
build=$1 src=$2 mpicc=$3 mpiexec=$4
work=$(mktemp -d "${TMPDIR:-/tmp}/fricreg-install-petsc.XXXXXX")
trap 'rm -rf "$work"' EXIT
prefix=$work/prefix
fails=0 passes=0
check() { # NAME COMMAND...: runs a step, counts it
    name=$1; shift
    if "$@" >"$work/log" 2>&1; then passes=$((passes + 1)); else
        fails=$((fails + 1)); echo "FAIL: $name"; tail -n 20 "$work/log"; fi
}

check "install" cmake --install "$build" --prefix "$prefix"
libdir=$(dirname "$(find "$prefix" -name 'libfricreg_petsc.so.*' | head -n 1)")
unset LD_LIBRARY_PATH # every run below finds the libraries by RUNPATH alone

# 0. The installed adapter's RUNPATH is $ORIGIN: libfricreg is found beside it, in any prefix.
check "the installed libfricreg_petsc.so has RUNPATH \$ORIGIN" \
    sh -c "readelf -d '$libdir/libfricreg_petsc.so' | grep -q 'RUNPATH.*\[\\\$ORIGIN\]'"

# runs PROGRAM on one rank, then checks that it loaded the adapter and libfricreg from LIBDIR
runs_from() { # LIBDIR PROGRAM
    "$mpiexec" -n 1 "$2" && ldd "$2" >"$work/ldd" &&
    grep -q "=> $1/libfricreg_petsc\.so" "$work/ldd" && grep -q "=> $1/libfricreg\.so" "$work/ldd"
}

# 1. CMake: find_package(fricreg CONFIG COMPONENTS petsc).
check "cmake configure" cmake -S "$src/tests/consumer/petsc" -B "$work/cmake" \
    -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_C_COMPILER="$mpicc"
check "cmake build" cmake --build "$work/cmake"
check "find_package consumer, no LD_LIBRARY_PATH, on the installed libraries" \
    runs_from "$libdir" "$work/cmake/consumer_petsc"

# 2. pkg-config (PETSc.pc is found where the system keeps it).
export PKG_CONFIG_PATH="$libdir/pkgconfig${PKG_CONFIG_PATH:+:$PKG_CONFIG_PATH}"
check "pkg-config knows fricreg_petsc" pkg-config --exists fricreg_petsc
check "pkg-config consumer build" sh -c "'$mpicc' '$src/tests/consumer/petsc/consumer_petsc.c' \
    \$(pkg-config --cflags fricreg_petsc) \$(pkg-config --libs fricreg_petsc) -lm \
    -Wl,-rpath,'$libdir' -o '$work/pc_consumer'"
check "pkg-config consumer, no LD_LIBRARY_PATH, on the installed libraries" \
    runs_from "$libdir" "$work/pc_consumer"

# 3. The prefix moved elsewhere (fricreg_petsc.pc finds it from its own place): a consumer in
#    it, linked with -Wl,-rpath,'$ORIGIN/LIBDIR', still starts, the adapter finding libfricreg
#    by its own $ORIGIN.
moved=$work/moved rel=${libdir#"$prefix"/}
check "move the prefix" mv "$prefix" "$moved"
export PKG_CONFIG_PATH="$moved/$rel/pkgconfig${PKG_CONFIG_PATH#"$libdir/pkgconfig"}"
check "pkg-config consumer build in the moved prefix" sh -c "'$mpicc' \
    '$src/tests/consumer/petsc/consumer_petsc.c' \$(pkg-config --cflags --libs fricreg_petsc) \
    -lm -Wl,-rpath,'\$ORIGIN/$rel' -o '$moved/pc_consumer'"
check "consumer in the moved prefix, no LD_LIBRARY_PATH" runs_from "$moved/$rel" "$moved/pc_consumer"
echo "$passes passed, $fails failed"
[ $fails -eq 0 ]
