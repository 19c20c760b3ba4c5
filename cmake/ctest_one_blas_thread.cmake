# SPDX-License-Identifier: GPL-3.0-or-later
# Read by ctest before it runs anything (the top directory's TEST_INCLUDE_FILES): every test
# runs OpenBLAS on one thread unless the caller chose otherwise. `ctest -j2` already runs two
# tests on the two cores; OpenBLAS's pool (libopenblas0-pthread, docs/install.md) spinning
# beside the other test made the quick tier 25 % slower (hb_stability_sweeps 10.6 -> 35.6 s,
# hb_sparse 3.6 -> 15 s), where alone, on one thread, test_hb_sparse takes 1.8 s against 3.5 s
# on the reference BLAS. The variable means nothing to other BLAS libraries.
if(NOT DEFINED ENV{OPENBLAS_NUM_THREADS})
  set(ENV{OPENBLAS_NUM_THREADS} 1)
endif()
