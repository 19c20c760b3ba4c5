/* SPDX-License-Identifier: GPL-3.0-or-later */
/* minimal.c — the yardstick loops of bench/kernels.c (minimal.h). */
#include "minimal.h"

static double clamp(double x, double lo, double hi)
{
    double y = x > lo ? x : lo;
    return y < hi ? y : hi;
}

static double quinn(double c, double f_eq, double mun)
{
    return clamp(clamp(f_eq, -mun, mun) - c * mun, -mun, mun);
}

void minimal_quinn(double eps, size_t m, const double v[], const double f_eq[], const double mun[],
                   double f[])
{
    double k = 2.0 / eps;
    for (size_t i = 0; i < m; i++)
        f[i] = quinn(k * v[i], f_eq[i], mun[i]);
}

void minimal_quinn_diagonal(double eps, size_t m, const double v[], const double a_free[],
                            const double w[], const double mun[], double f[])
{
    double k = 2.0 / eps;
    for (size_t i = 0; i < m; i++)
        f[i] = quinn(k * v[i], -a_free[i] / w[i], mun[i]);
}

void minimal_quinn_diagonal_copies(double eps, size_t m, const double v[], const double a_free[],
                                   const double w[], const double mun[], double f[],
                                   double *restrict v_copy, double *restrict a_copy)
{
    double k = 2.0 / eps;
    for (size_t i = 0; i < m; i++) {
        v_copy[i] = v[i];
        a_copy[i] = a_free[i];
        f[i] = quinn(k * v[i], -a_free[i] / w[i], mun[i]);
    }
}

void minimal_triad(size_t m, double a[], const double b[], const double c[], double s)
{
    for (size_t i = 0; i < m; i++)
        a[i] = b[i] + s * c[i];
}

/* The same two loops compiled for AVX2 (no FMA: it would change the rounding), the code the
 * library's kernels run on a CPU with AVX2 (src/base/dispatch.h), so that the benchmark shows the
 * kernels' ratios to both. Where the compiler cannot dispatch, the portable loops. */
#ifdef FRICREG_AVX2_DISPATCH
#define AVX2 __attribute__((target("avx2")))
int minimal_have_avx2(void)
{
    return __builtin_cpu_supports("avx2");
}
#else
#define AVX2
int minimal_have_avx2(void)
{
    return 0;
}
#endif

AVX2 void minimal_quinn_avx2(double eps, size_t m, const double v[], const double f_eq[],
                             const double mun[], double f[])
{
    double k = 2.0 / eps;
    for (size_t i = 0; i < m; i++)
        f[i] = quinn(k * v[i], f_eq[i], mun[i]);
}

AVX2 void minimal_quinn_diagonal_avx2(double eps, size_t m, const double v[], const double a_free[],
                                      const double w[], const double mun[], double f[])
{
    double k = 2.0 / eps;
    for (size_t i = 0; i < m; i++)
        f[i] = quinn(k * v[i], -a_free[i] / w[i], mun[i]);
}
