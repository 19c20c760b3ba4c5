/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Checks on a fricreg_disk_ctx shared by the disk-context tests (Coulomb and Stribeck bounds):
 * evaluation that must succeed, the largest jump of f along a sweep of zdot_0, and the tangent
 * against central differences. Failures are Check assertions. */
#ifndef FRICREG_TESTS_DISK_CTX_CHECKS_H
#define FRICREG_TESTS_DISK_CTX_CHECKS_H

#include <stddef.h>

#include "fricreg_disk_ctx.h"

#define DISK_CHECK_MAXN 12 /* 2 m at most: up to 6 contacts */

/* fricreg_disk_ctx_eval, asserted to return FRICREG_OK. zdot, a_free and f hold 2 m. */
void eval_ok(fricreg_disk_ctx *ctx, size_t m, const double zdot[], const double a_free[],
             double f[]);

/* max_k |x_k| over n entries (0 for n = 0). */
double max_abs(const double x[], size_t n);

/* The largest |f(k) - f(k - 1)| over the sweep zdot_0 = (s0 + k h) dir, k = -steps..steps,
 * the other contacts fixed; zdot (2 m) is overwritten in its first two entries. */
double disk_ctx_sweep(fricreg_disk_ctx *ctx, size_t m, double zdot[], const double a_free[],
                      const double dir[2], double s0, double h, int steps);

/* fricreg_disk_ctx_tangent at (zdot, a_free) against central differences of eval with steps
 * h and h/2 (h = 1e-6 eps in zdot, 1e-6 in a_free); the tangent must agree within 1e-6 of the
 * largest entry. Returns 0 if the case sits too near a kink for differences (the two steps
 * disagree by more than 1e-7), 1 if checked. */
int disk_ctx_check_tangent(fricreg_disk_ctx *ctx, size_t m, const double zdot[],
                           const double a_free[], double eps);

#endif
