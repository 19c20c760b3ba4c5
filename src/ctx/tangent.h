/* SPDX-License-Identifier: GPL-3.0-or-later */
/* tangent.h — internal: what the tangent (tangent.c) and its product with vectors
 * (tangent_apply.c) share: the checks, the preparation, and each contact's slopes. */
#ifndef FRICREG_TANGENT_H
#define FRICREG_TANGENT_H

#include <stddef.h>

#include "ctx_internal.h"

/* FRICREG_ESIZE unless m is the context's; FRICREG_EINVAL if the last evaluation's inputs are
 * not kept or no evaluation succeeded since the last setter. Recorded, led by who. */
int fr_tangent_check_size(fricreg_ctx *ctx, size_t m, const char *who);
int fr_tangent_check_kept(fricreg_ctx *ctx, const char *who);

/* The Stribeck bounds of the evaluation's velocities; *coupled: W is dense or sparse and the
 * law reads f_eq; then the evaluation's split (ctx->stick, ctx->f holding f_L) and the factor
 * the tangent solves with, W_SS (paper) or W_FF of the final free set F = ctx->qp.free_set[*nf]
 * (consistent). FRICREG_OK, or FRICREG_ESINGULAR from a refactorization (recorded). */
int fr_tangent_prepare(fricreg_ctx *ctx, const char *who, int *coupled, size_t *nf);

/* Contact i of a diagonal W or of a law that does not read f_eq: d f_i/d zdot_i into *dv and
 * d f_i/d a_free,i into *da, from the evaluation's inputs or the diagonal pass's codes. */
void fr_tangent_diagonal_slopes(const fricreg_ctx *ctx, size_t i, double *dv, double *da);

/* d f/d zdot of a contact off the band (the law's own slope, and Stribeck's bound's). */
double fr_tangent_off_band_slope(const fricreg_ctx *ctx, size_t i, double v);

/* d bound_i/d zdot_i at v: 0 but for Stribeck friction. */
double fr_tangent_bound_slope(const fricreg_ctx *ctx, size_t i, double v);

/* d f/d zdot and d f/d f_eq of a near-stick contact at (v, f_eq) with f_eq fixed, bound mun
 * moving with v at the rate dmun. */
void fr_tangent_near_slopes(const fricreg_ctx *ctx, double v, double feq, double mun, double dmun,
                            double *dv, double *dfeq);

/* The consistent law: d f_i/d zdot_i of a contact of S held at its bound (ctx->side), and
 * d(c_k bound_k)/d zdot_k of a free one (d b_k/d zdot_k = W_kk times it). */
double fr_tangent_held_slope(const fricreg_ctx *ctx, size_t i);
double fr_tangent_free_slope(const fricreg_ctx *ctx, size_t k);

#endif
