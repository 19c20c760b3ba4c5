#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# GSL keeps its own CBLAS in every program that links fricreg: the shared library needs
# libgslcblas before any BLAS or LAPACK (an OpenBLAS found as LAPACK exports cblas_* too, and
# the loader binds GSL's calls to the first library that has them, breadth first: with
# OpenBLAS first, GSL's msbdf on the two blocks at eps = 1e-6 gave D = 2.50 instead of 5.24 in
# its second cycle). Usage: link_order.sh LIBRARY
needed=$(readelf -d "$1" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p')
gsl=$(echo "$needed" | grep -n '^libgslcblas' | cut -d: -f1)
blas=$(echo "$needed" | grep -n -E '^lib(open)?blas|^liblapack|^libmkl|^libflexiblas' | head -n 1 | cut -d: -f1)
if [ -z "$gsl" ]; then
    echo "FAIL: $1 does not need libgslcblas: $(echo $needed)"
    exit 1
fi
if [ -n "$blas" ] && [ "$blas" -lt "$gsl" ]; then
    echo "FAIL: $1 needs a BLAS or LAPACK before libgslcblas: $(echo $needed)"
    exit 1
fi
echo "libgslcblas is needed before any BLAS: $(echo $needed)"
