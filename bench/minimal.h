/* SPDX-License-Identifier: GPL-3.0-or-later */
/* minimal.h — the least code that computes what the law kernels compute (bench/kernels.c).
 *
 * The yardsticks of the kernel benchmark: no validation, no statistics, no copies, the same
 * arithmetic as law (4) in its division-free form. Kept in their own translation unit so the
 * compiler cannot specialize them to the benchmark's call sites. */
#ifndef FRICREG_BENCH_MINIMAL_H
#define FRICREG_BENCH_MINIMAL_H

#include <stddef.h>

/** f[i] = clamp(clamp(f_eq[i], +-mun[i]) - (2 v[i]/eps) mun[i], +-mun[i]): law (4) on m
 *  contacts, what fricreg_law_eval_batch(FRICREG_LAW_QUINN, ...) computes. */
void minimal_quinn(double eps, size_t m, const double v[], const double f_eq[], const double mun[],
                   double f[]);

/** The same with f_eq[i] = -a_free[i] / w[i]: what fricreg_ctx_eval computes with a diagonal
 *  W = diag(w) under law (4). */
void minimal_quinn_diagonal(double eps, size_t m, const double v[], const double a_free[],
                            const double w[], const double mun[], double f[]);

/** minimal_quinn_diagonal, also copying v and a_free to v_copy and a_copy: the copies
 *  fricreg_ctx_eval keeps for fricreg_ctx_tangent, priced alone. */
void minimal_quinn_diagonal_copies(double eps, size_t m, const double v[], const double a_free[],
                                   const double w[], const double mun[], double f[],
                                   double *restrict v_copy, double *restrict a_copy);

/** minimal_quinn and minimal_quinn_diagonal compiled for AVX2 (no FMA), to run only where
 *  minimal_have_avx2() (1: built with FRICREG_AVX2_DISPATCH and the CPU has AVX2). */
int minimal_have_avx2(void);
void minimal_quinn_avx2(double eps, size_t m, const double v[], const double f_eq[],
                        const double mun[], double f[]);
void minimal_quinn_diagonal_avx2(double eps, size_t m, const double v[], const double a_free[],
                                 const double w[], const double mun[], double f[]);

/** a[i] = b[i] + s c[i] (STREAM's triad): the memory bandwidth yardstick. */
void minimal_triad(size_t m, double a[], const double b[], const double c[], double s);

#endif
