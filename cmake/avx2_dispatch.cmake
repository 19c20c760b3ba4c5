# SPDX-License-Identifier: GPL-3.0-or-later
# FRICREG_AVX2_DISPATCH: the hot loops of the batch law and of fricreg_ctx_eval (src/base/dispatch.h)
# get AVX2 versions chosen at run time, the way glibc, FFTW and OpenBLAS do: on x86-64 with
# GCC or clang (target("avx2") and __builtin_cpu_supports). Probed by compiling and linking a
# program that uses both; elsewhere the portable loops alone. "avx2" adds no FMA, so both versions
# round identically (tests/law/test_kernels.c compares them bit for bit with the scalar law).
include(CheckCSourceCompiles)
option(FRICREG_AVX2 "Dispatch the kernels to AVX2 versions at run time where supported" ON)
if(FRICREG_AVX2)
  check_c_source_compiles([=[
#if !defined(__x86_64__) || !defined(__GNUC__)
#error "x86-64 with GCC or clang only"
#endif
#include <immintrin.h>
__attribute__((target("avx2"))) static double first(const double *a)
{
    double s[4];
    _mm256_storeu_pd(s, _mm256_loadu_pd(a));
    return s[0];
}
int main(void)
{
    double a[4] = {1.0, 2.0, 3.0, 4.0};
    return __builtin_cpu_supports("avx2") ? (int)first(a) - 1 : 0;
}
]=] FRICREG_AVX2_DISPATCH)
endif()
