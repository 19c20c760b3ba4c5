/* SPDX-License-Identifier: GPL-3.0-or-later */
/* dispatch.h — internal: AVX2 versions of the hot loops, chosen at run time.
 *
 * With FRICREG_AVX2_DISPATCH (cmake/avx2_dispatch.cmake: x86-64, GCC or clang), a kernel's
 * loops are written once, in a FR_KERNEL_BODY function, and compiled twice: inlined into the
 * portable function (the x86-64 baseline, SSE2) and into a FR_AVX2 one, which the portable
 * function calls when fr_have_avx2(). A test at each call, not an ifunc (target_clones): an
 * ifunc resolver runs while the library is being relocated, before ThreadSanitizer's runtime
 * is set up, and crashed every program of a -fsanitize=thread build. The target "avx2" adds
 * no FMA, so no product is fused into a sum: both versions round every operation alike, and
 * the kernels' elementwise results are the same bit for bit (tests/law/test_kernels.c).
 * Elsewhere the portable loops alone. */
#ifndef FRICREG_DISPATCH_H
#define FRICREG_DISPATCH_H

#ifdef FRICREG_AVX2_DISPATCH
#define FR_AVX2 __attribute__((target("avx2")))
/* Inlined into each caller, so compiled for each caller's target. */
#define FR_KERNEL_BODY static inline __attribute__((always_inline))
#define fr_have_avx2() __builtin_cpu_supports("avx2")
#else
#define FR_KERNEL_BODY static inline
#define fr_have_avx2() 0
#endif

#endif
