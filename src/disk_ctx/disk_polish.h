/* SPDX-License-Identifier: GPL-3.0-or-later */
/* disk_polish.h — internal: Newton's method on the coupled 2-D law's KKT conditions for the
 * active set of the current Gauss-Seidel iterate (disk_polish.c). */
#ifndef FRICREG_DISK_POLISH_H
#define FRICREG_DISK_POLISH_H

struct fricreg_disk_ctx;

/* Runs Newton from ctx->f, ctx->lam with the active set ctx->kind of the near-stick contacts
 * (ctx->g: a_free plus the fixed contacts' share). Returns 1 with f, lam updated if it
 * converged to a point consistent with that set; 0 with f restored (lam may have changed: the
 * next sweep recomputes it) otherwise. Uses ctx->f_last as scratch. No allocation. */
int fr_disk_polish(struct fricreg_disk_ctx *ctx);

#endif
