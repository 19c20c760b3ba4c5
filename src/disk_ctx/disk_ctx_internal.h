/* SPDX-License-Identifier: GPL-3.0-or-later */
/* disk_ctx_internal.h — the 2-D context's layout, shared by disk_ctx.c (set-up), disk_qp.c
 * (eval) and disk_tangent.c (fricreg_disk_ctx.h). */
#ifndef FRICREG_DISK_CTX_INTERNAL_H
#define FRICREG_DISK_CTX_INTERNAL_H

#include <stddef.h>

#include <gsl/gsl_roots.h>

#include "disk_block.h"
#include "base/error.h"
#include "fricreg_disk_ctx.h"
#include "law/law_stribeck.h"

#define FR_DISK_CTX_MAX ((size_t)1 << 24)

/* What eval decided for a contact (kept for the tangent). */
enum fr_disk_kind {
    FR_DISK_FIXED = 0, /* sliding, mun = 0 or a radius 0: f_i does not depend on the others */
    FR_DISK_FREE = 1,  /* near stick, inside K_i */
    FR_DISK_CIRCLE = 2 /* near stick, on the circle of K_i */
};

struct fricreg_disk_ctx {
    size_t m;
    int law;
    double eps;
    double *mun;             /* [m] */
    struct fr_disk_eig *eig; /* [m] eigen-decomposition of each diagonal block W_ii */
    double *blk;             /* [4m] the diagonal blocks W_ii, row-major */
    double *W;               /* [(2m)^2] dense W, or NULL for block diagonal */

    /* The state of the last evaluation (the tangent's inputs), scratch during one. */
    double *f;         /* [2m] forces being built */
    double *f_last;    /* [2m] last successful forces: the warm start */
    double *g;         /* [2m] a_free + couplings to the fixed contacts (dense W) */
    double *p;         /* [2m] a_i u_i: K_i's centre is -p_i, c_i mun_i = 2 p_i */
    double *u;         /* [2m] zdot_i/|zdot_i|, 0 at rest */
    double *r;         /* [m] |zdot_i| */
    double *radius;    /* [m] mun_i - a_i */
    double *lam;       /* [m] the circle's multiplier (stationarity W_ii(f-h) + lam (f+p) = 0) */
    double *bound;     /* [m] the bound the law used: mun_i, or the Stribeck bound at |zdot_i| */
    signed char *kind; /* [m] enum fr_disk_kind */
    size_t *near;      /* [m] indices of the near-stick contacts */
    size_t n_near;
    int last_valid; /* an evaluation succeeded since the last setter call */
    /* The last successful evaluation's inputs: a failed one since overwrote the state above,
     * which the tangent then rebuilds from them (fr_disk_restore_state). */
    double *last_zdot;  /* [2m] */
    double *last_afree; /* [2m] */
    int state_current;  /* the state above is that of the last successful evaluation */

    /* The tangent's KKT system, order at most 3m (dense W) or 3 (blocks). */
    size_t kkt_max;
    double *kkt;  /* [kkt_max^2] */
    double *tau;  /* [kkt_max] Householder coefficients */
    double *col;  /* [kkt_max] one right-hand side */
    size_t *row;  /* [m] first KKT row of each near-stick contact; its multiplier's row */
    size_t *mrow; /* [m] */

    /* Stribeck friction (fricreg_disk_ctx_set_stribeck, disk_stribeck.c): allocated at the
     * first set-up, kept until free. */
    int stribeck;              /* on: FRICREG_DISK_QUINN with the Stribeck bound */
    struct fr_stribeck *strib; /* [m] each contact's fs, fk, vs, delta */
    double *strib_keps;        /* [m] k(eps), refreshed when eps changes */

    gsl_root_fsolver *brent; /* on fricreg's memory (disk_ctx.c): no GSL allocator */
    struct fr_error err;
};

/* disk_stribeck.c: contact i's bound at speed r = |zdot_i| (mun_i without Stribeck friction);
 * its slope d bound/d r (0 without); k(eps) after eps changed; Stribeck friction off. */
double fr_disk_bound(const fricreg_disk_ctx *ctx, size_t i, double r);
double fr_disk_bound_slope(const fricreg_disk_ctx *ctx, size_t i, double r);
void fr_disk_stribeck_refresh(fricreg_disk_ctx *ctx);

/* disk_qp.c: the state of the last successful evaluation, rebuilt from its inputs if a failed
 * evaluation overwrote it (warm-started at its forces). Returns FRICREG_OK or eval's status. */
int fr_disk_restore_state(fricreg_disk_ctx *ctx);

/* Entry (2i+a, 2j+b) of W: the dense entry, or the block's (0 between contacts). */
static inline double fr_disk_w(const fricreg_disk_ctx *ctx, size_t i, int a, size_t j, int b)
{
    if (ctx->W != NULL)
        return ctx->W[(2 * i + (size_t)a) * 2 * ctx->m + 2 * j + (size_t)b];
    return i == j ? ctx->blk[4 * i + 2 * (size_t)a + (size_t)b] : 0.0;
}

/* Rows of the KKT system of the near-stick contacts (the polish's Newton and the tangent):
 * two per near-stick contact (ctx->row), then one multiplier row per contact on its circle
 * (ctx->mrow); returns the order. */
static inline size_t fr_disk_number_rows(fricreg_disk_ctx *ctx)
{
    size_t n = 2 * ctx->n_near;
    for (size_t k = 0; k < ctx->n_near; k++) {
        size_t i = ctx->near[k];
        ctx->row[i] = 2 * k;
        if (ctx->kind[i] == FR_DISK_CIRCLE)
            ctx->mrow[i] = n++;
    }
    return n;
}

#endif
