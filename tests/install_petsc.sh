#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# Installs the build into a temporary prefix, then builds a user's PETSc program against the
# installed libfricreg_petsc only, with find_package(fricreg COMPONENTS petsc) and with
# pkg-config fricreg_petsc (compiled by the MPI wrapper), and runs each on one rank.
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
export LD_LIBRARY_PATH="$libdir${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"

# 1. CMake: find_package(fricreg CONFIG COMPONENTS petsc).
check "cmake configure" cmake -S "$src/tests/consumer/petsc" -B "$work/cmake" \
    -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_C_COMPILER="$mpicc"
check "cmake build" cmake --build "$work/cmake"
check "find_package consumer" "$mpiexec" -n 1 "$work/cmake/consumer_petsc"
check "the consumer loads the installed adapter" \
    sh -c "ldd '$work/cmake/consumer_petsc' | grep -q '$libdir/libfricreg_petsc.so'"

# 2. pkg-config (PETSc.pc is found where the system keeps it).
export PKG_CONFIG_PATH="$libdir/pkgconfig${PKG_CONFIG_PATH:+:$PKG_CONFIG_PATH}"
check "pkg-config knows fricreg_petsc" pkg-config --exists fricreg_petsc
check "pkg-config consumer build" sh -c "'$mpicc' '$src/tests/consumer/petsc/consumer_petsc.c' \
    \$(pkg-config --cflags fricreg_petsc) \$(pkg-config --libs fricreg_petsc) -lm \
    -o '$work/pc_consumer'"
check "pkg-config consumer" "$mpiexec" -n 1 "$work/pc_consumer"
echo "$passes passed, $fails failed"
[ $fails -eq 0 ]
