/* SPDX-License-Identifier: GPL-3.0-or-later */
/* chain_implicit.h — a prototype implicit integrator of the chain (chain_implicit.c): HHT-alpha
 * with Newton on a tridiagonal matrix, O(n) per iteration. Benchmark code, not the library. */
#ifndef FRICREG_BENCH_CHAIN_IMPLICIT_H
#define FRICREG_BENCH_CHAIN_IMPLICIT_H

#include "bench.h"

/** One run: the chain of Sec. 3.2 (n blocks, forcing a sin(omega t)), law (4) with eps, from
 *  rest, over the first forcing cycle in equal steps of about dt; HHT with alpha in
 *  [-1/3, 0] (0: Newmark's average acceleration); Newton until ||R||_inf <= newton_tol times
 *  n (|a| + 1), the scale of the accelerations. */
struct chain_implicit_opts {
    size_t n;
    double a, omega, eps, dt, alpha, newton_tol;
};

/** Fills out: D on cycle 1, steps, and in rhs_evals the Newton iterations. Returns
 *  FRICREG_OK, FRICREG_ENOMEM, or FRICREG_EDIVERGED if Newton failed (out->msg says where). */
int chain_implicit_run(const struct chain_implicit_opts *o, struct bench_run *out);

#endif
