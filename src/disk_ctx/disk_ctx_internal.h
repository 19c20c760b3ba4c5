/* SPDX-License-Identifier: GPL-3.0-or-later */
/* disk_ctx_internal.h — the 2-D context's layout, shared by disk_ctx.c (set-up), disk_qp.c
 * (eval) and disk_tangent.c (fricreg_disk_ctx.h). */
#ifndef FRICREG_DISK_CTX_INTERNAL_H
#define FRICREG_DISK_CTX_INTERNAL_H

#include <stddef.h>

#include <gsl/gsl_roots.h>

#include "disk_block.h"
#include "disk_coupling.h"
#include "disk_factor.h"
#include "disk_kind.h"
#include "base/error.h"
#include "fricreg_disk_ctx.h"
#include "law/law_stribeck.h"

#define FR_DISK_CTX_MAX ((size_t)1 << 24)

/* A coupled W (dense or sparse setter): its blocks, the reduced Hessian's factor, and the
 * work of the sweeps and of Newton's method (disk_newton.c), [2m] or [m]. */
struct fr_disk_coupled {
    struct fr_disk_coupling w;
    struct fr_disk_factor F;
    double *acc;        /* [2m] G_i: contact i's acceleration with f_i = 0, the others' f */
    double *grad;       /* [2m] the QP's gradient W f + b on the near-stick contacts */
    double *fl;         /* [2m] each contact's exact subproblem's solution given G_i */
    double *laml;       /* [m] its multiplier */
    signed char *onl;   /* [m] whether it is on the circle */
    signed char *nkind; /* [m] the kinds of Newton's reduced Hessian */
    double *nrm;        /* [2m] the circles' normals */
    double *step;       /* [2m] Newton's step */
    double *trial;      /* [2m] a trial point; the right-hand side */
    double *wd;         /* [2m] W times a displacement */
    int newton_last;    /* the last successful evaluation needed Newton's method */
};

/* Allocates a coupled W's work for m contacts, fr_disk_coupled_free releases it all (NULL
 * safe). The coupling and factor are the caller's to set up. */
struct fr_disk_coupled *fr_disk_coupled_new(size_t m);
void fr_disk_coupled_free(struct fr_disk_coupled *cpl);

struct fricreg_disk_ctx {
    size_t m;
    int law;
    double eps;
    double *mun;                 /* [m] */
    struct fr_disk_eig *eig;     /* [m] eigen-decomposition of each diagonal block W_ii */
    double *blk;                 /* [4m] the diagonal blocks W_ii, row-major */
    double *W;                   /* [(2m)^2] dense W (the dense tangent's), or NULL */
    struct fr_disk_coupled *cpl; /* W by blocks and its factor (dense or sparse W), or NULL
                                  * for block diagonal */

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

    gsl_root_fsolver *brent; /* on fricreg's memory (base/gsl_mem.h): no GSL allocator */
    struct fr_error err;
};

/* disk_ctx.c: checks the 2x2 block [[a, b], [c, d]] of contact i (symmetric, positive
 * definite, smallest eigenvalue at least DBL_MIN) and writes its eigen-decomposition; the
 * failure is recorded led by who. */
int fr_disk_check_block(fricreg_disk_ctx *ctx, const char *who, size_t i, double a, double b,
                        double c, double d, struct fr_disk_eig *e);

/* disk_ctx.c: makes cpl (and W, the dense copy, or NULL) the context's coupling, freeing the
 * old one; the diagonal blocks and their eigen-decompositions from cpl. Cannot fail. */
void fr_disk_install_coupled(fricreg_disk_ctx *ctx, struct fr_disk_coupled *cpl, double *W);

/* disk_stribeck.c: contact i's bound at speed r = |zdot_i| (mun_i without Stribeck friction);
 * its slope d bound/d r (0 without); k(eps) after eps changed; Stribeck friction off. */
double fr_disk_bound(const fricreg_disk_ctx *ctx, size_t i, double r);
double fr_disk_bound_slope(const fricreg_disk_ctx *ctx, size_t i, double r);
void fr_disk_stribeck_refresh(fricreg_disk_ctx *ctx);

/* disk_sweep.c: block Gauss-Seidel. g_i += sum over the contacts j != i that are fixed
 * (fixed_ones) or near stick of W_ij f_j; one contact's exact subproblem given g (returns how
 * far its force moved over its bound); one sweep over the near-stick contacts (*moved: the
 * largest such move), FRICREG_OK or FRICREG_ENONFINITE. */
void fr_disk_add_coupling(const fricreg_disk_ctx *ctx, size_t i, int fixed_ones, double g[2]);
double fr_disk_solve_contact(fricreg_disk_ctx *ctx, size_t i, const double g[2]);
int fr_disk_sweep(fricreg_disk_ctx *ctx, double *moved);

/* disk_newton.c: up to max_iter iterations of the projected Newton method on the near-stick
 * QP from ctx->f (ctx->g holding a_free plus the fixed contacts' share); *converged says
 * whether a block pass moved no force by more than tol times its bound (then ctx->f, kind and
 * lam are that pass's). FRICREG_OK or FRICREG_ENONFINITE. No allocation. */
int fr_disk_newton(fricreg_disk_ctx *ctx, int max_iter, double tol, int *converged);

/* disk_slopes.c, at the last evaluation's solution: d p_i/d zdot_i (p_i = a_i u_i, K_i's
 * centre is -p_i), row-major; d f_i/d zdot_i of a fixed contact; the unit normal
 * (f_i + p_i)/|f_i + p_i| of a circle contact; and for a circle contact j, n_j . d f_j/d zdot_{j,b}
 * = d radius_j - n_j . d p_j given P = d p_j/d zdot_j (at rest along the direction -n_j the
 * contact will slide). */
void fr_disk_centre_jacobian(const fricreg_disk_ctx *ctx, size_t i, double P[4]);
void fr_disk_fixed_jacobian(const fricreg_disk_ctx *ctx, size_t i, double D[4]);
void fr_disk_normal(const fricreg_disk_ctx *ctx, size_t i, double n[2]);
double fr_disk_normal_rate(const fricreg_disk_ctx *ctx, size_t j, int b, const double P[4]);

/* disk_tangent_sparse.c: the tangent with a sparse W from the reduced Hessian's factor:
 * fr_disk_tangent_sparse_factor builds it at the solution (FRICREG_OK or FRICREG_ESINGULAR,
 * recorded); fr_disk_tangent_sparse then writes every column of the outputs given (zeroed
 * before; dry: nothing written, returns whether every entry would be finite). */
int fr_disk_tangent_sparse_factor(fricreg_disk_ctx *ctx);
int fr_disk_tangent_sparse(fricreg_disk_ctx *ctx, double *dz, double *da, int dry);

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
