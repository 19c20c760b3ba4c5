/* SPDX-License-Identifier: GPL-3.0-or-later */
/* plausible.h — internal: the one-pass validation of a batch's inputs, before anything is
 * written (law.c's batch, partition.c's fricreg_ctx_eval). */
#ifndef FRICREG_PLAUSIBLE_H
#define FRICREG_PLAUSIBLE_H

#include <stddef.h>

/* Whether every a[i], b[i] (b may be NULL) and c[i] (c may be NULL) is finite and every c[i]
 * is >= 0, i < m, judged in one pass: the sum of all the inputs is finite unless one is a NaN
 * or an infinity, and the least c[i] (from 0 up) is 0 unless one is negative. 1: they are.
 * 0: they may not be, and the caller runs its exact check, which names the failure (0 also
 * comes, a false alarm, when finite inputs overflow the sum, or from a c[i] = -0.0; the exact
 * check then passes). Two adds and a min per contact, in SSE2 vectors on x86-64: this pass,
 * not the law, is what a batch in cache pays for its promise to validate before it writes
 * (bench/kernels.c). */
int fr_plausible(size_t m, const double a[], const double b[], const double c[]);

#endif
