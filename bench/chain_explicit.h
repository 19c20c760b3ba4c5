/* SPDX-License-Identifier: GPL-3.0-or-later */
/* chain_explicit.h — a prototype explicit integrator of the chain (chain_explicit.c): central
 * differences, one friction evaluation a step. Benchmark code, not the library. */
#ifndef FRICREG_BENCH_CHAIN_EXPLICIT_H
#define FRICREG_BENCH_CHAIN_EXPLICIT_H

#include "bench.h"

/** One run: the chain of Sec. 3.2 (n >= 2 blocks, forcing a sin(omega t) of period `period`),
 *  law (4) with eps, from rest, over the first forcing cycle in equal steps of about dt. */
struct chain_explicit_opts {
    size_t n;
    double a, omega, period, eps, dt;
};

/** Fills out: D on cycle 1, steps and friction evaluations. Returns FRICREG_OK, FRICREG_ENOMEM,
 *  or the status of fricreg_law_eval_batch. */
int chain_explicit_run(const struct chain_explicit_opts *o, struct bench_run *out);

#endif
