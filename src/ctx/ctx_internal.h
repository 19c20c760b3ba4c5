/* SPDX-License-Identifier: GPL-3.0-or-later */
/* ctx_internal.h — the context's layout, shared by ctx.c (set-up), the partitions (eval), the
 * QP, the factor cache and the tangent. */
#ifndef FRICREG_CTX_INTERNAL_H
#define FRICREG_CTX_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include "box_qp_state.h"
#include "ctx_driver.h"
#include "base/error.h"
#include "factor.h"
#include "fricreg.h"
#include "law/law_stribeck.h"

struct fr_sparse_coupling; /* sparse_coupling.h, included where it is used */

#define FR_NSTATS 6
#define FR_MAX_CONTACTS ((size_t)1 << 26)
/* From this many contacts the diagonal pass keeps the tangent's codes, not its inputs. The
 * codes cost compute, the copies memory traffic: in cache (m = 10^3) the codes made
 * fricreg_ctx_eval 1.8x slower, out of it (m = 10^6, 48 MB) the copies 1.45x
 * (bench/kernels.c). 2^16 contacts are 3 MB of arrays, beyond a core's L2. */
#define FR_CODED_TANGENT_FROM ((size_t)1 << 16)

struct fricreg_ctx {
    size_t m;
    int law;
    int partition; /* enum fricreg_partition: used with a coupled (dense or sparse) W */
    double eps;
    double *mun; /* [m] friction bounds */
    /* [m] the bounds law (4) reads in an evaluation: mun, or with Stribeck friction the
     * velocity-dependent bound of ctx_stribeck.c. The hot loops read this pointer, never a
     * flag: the default law pays nothing for Stribeck. */
    const double *bound;
    double *w_diag; /* [m] diagonal of W (the whole of W when W is diagonal) */
    int w_unit;     /* W = I: f_eq = -a_free needs no division */
    double *W;      /* [m*m] row-major dense W, or NULL when W is diagonal or sparse */
    struct fr_sparse_coupling *sp; /* a sparse W (sparse_coupling.h), or NULL */

    /* Scratch, allocated with the context or the coupling so that eval never allocates. */
    double *f;     /* [m] friction forces being built */
    double *f_eq;  /* [m] f_eq being built */
    size_t *stick; /* [m] indices of the near-stick set S */
    size_t n_stick;
    double *rhs;          /* [m] coupled W: right-hand side of the paper's W_SS solve */
    struct fr_factor fac; /* dense only: cached factor of a principal block of W */
    struct fr_box_qp qp;  /* coupled W (dense or sparse): the consistent law's QP on S */
    signed char *side;    /* [m] the QP's last working set per contact, its warm start (a mark
                           * outside S: partition_consistent.c) */

    /* The inputs of the last successful evaluation, for fricreg_ctx_tangent. */
    double *last_zdot;  /* [m] */
    double *last_afree; /* [m] */
    int last_valid;     /* an evaluation succeeded since the last setter call */
    /* The diagonal pass kept, in last_afree, fr_near_tangent_code's code per contact instead
     * of the inputs (a diagonal W, a law that reads f_eq, no Stribeck friction): one stream
     * written instead of two (partition.c). It does so from coded_from contacts on
     * (FR_CODED_TANGENT_FROM; tests set 0 to check the codes at a small m). */
    int last_coded;
    size_t coded_from;
    int keep_tangent; /* eval keeps last_zdot, last_afree (fricreg_ctx_set_keep_tangent) */

    /* Stribeck friction (fricreg_ctx_set_stribeck, ctx_stribeck.c): allocated at the first
     * set-up, kept when cleared. */
    int stribeck;              /* on: law (4) with the Stribeck bound (then law is (4)) */
    struct fr_stribeck *strib; /* [m] each contact's fs, fk, vs, delta */
    double *strib_keps;        /* [m] k(eps), refreshed when eps changes */
    double *strib_bound;       /* [m] the bound at the last zdot: B(|zdot|) or k(|zdot|) */

    /* A driver's workspace kept between its calls (fricreg_ctx_solve_step's solver,
     * contact_step.c), freed by the driver's own function: ctx_driver.h. */
    void *workspace;
    void (*workspace_free)(void *);

    int64_t stats[FR_NSTATS];
    struct fr_error err;
};

/* W couples the contacts: dense or sparse, not diagonal. */
static inline int fr_coupled(const fricreg_ctx *ctx)
{
    return ctx->W != NULL || ctx->sp != NULL;
}

/* The bound of contact i at rest: its static bound fs with Stribeck friction, else mun. It
 * bounds |f_i| at every velocity, and (4)'s slope at rest is 2/eps times it. */
static inline double fr_rest_bound(const fricreg_ctx *ctx, size_t i)
{
    return ctx->stribeck ? ctx->strib[i].fs : ctx->mun[i];
}

/* ctx.c: the coupling released (back to W = I, as set_coupling_diagonal leaves it before it
 * writes the diagonal); the cached factor, dense or sparse, marked stale. */
void fr_ctx_free_coupling(fricreg_ctx *ctx);
void fr_ctx_forget_factor(fricreg_ctx *ctx);

/* ctx_stribeck.c: the bounds of Stribeck friction at velocities zdot[m] into
 * ctx->strib_bound (ctx->stribeck on); the slope d bound_i/d zdot_i at v (at v = 0 that of
 * v > 0, the tangent's convention); k(eps) after eps changed; switching Stribeck off. */
void fr_stribeck_bounds(fricreg_ctx *ctx, const double zdot[]);
double fr_stribeck_bound_slope(const fricreg_ctx *ctx, size_t i, double v);
void fr_stribeck_refresh(fricreg_ctx *ctx);
void fr_stribeck_off(fricreg_ctx *ctx);

/* The singularity bound of the dense (factor.c) and sparse (sparse_block.c) factors: a block
 * with a pivot ratio d_k / W_kk below this (in a fresh factorization, contacts in the callers'
 * ascending order) is singular. For two contacts the ratio is 1 - rho^2, rho their correlation
 * W_ij / sqrt(W_ii W_jj). */
#define FR_PIVOT_MIN 1e-12

/* c_i = 2 zdot_i/eps for (4), 0 for Karnopp and (2): where contact i sits in the band. */
static inline double fr_band_position(const fricreg_ctx *ctx, double zdot)
{
    return ctx->law == FRICREG_LAW_QUINN ? zdot * (2.0 / ctx->eps) : 0.0;
}

#endif
