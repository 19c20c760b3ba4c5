/* SPDX-License-Identifier: GPL-3.0-or-later */
/* sparse_coupling.h — internal: a sparse W in the 1-D context (fricreg_ctx_set_coupling_csr,
 * _csc): its storage, its products with vectors, and the cached LDL^T factor of its principal
 * blocks (sparse_block.c), all on one CHOLMOD workspace of the context's own.
 *
 * W is kept twice: whole (both triangles) in contact order, for products by rows (a column of
 * a symmetric matrix is its row); and as C = P W P^T, upper triangle, P the fill-reducing
 * ordering AMD chose once per coupling, for the factor. Nothing is O(m^2). */
#ifndef FRICREG_SPARSE_COUPLING_H
#define FRICREG_SPARSE_COUPLING_H

#include <stddef.h>

#include <cholmod.h>

/* The factor of a principal block B of C, held as the whole m x m matrix C_B whose rows and
 * columns outside B are the identity's (sparse_block.c). */
struct fr_sparse_block {
    cholmod_factor *L;        /* simplicial LDL^T of C_B, natural order (C is permuted) */
    cholmod_sparse *CB;       /* C_B's upper triangle, built for each fresh factorization */
    cholmod_sparse *R;        /* m x 1: a column of C_B (row add) or a row pattern (row delete) */
    cholmod_dense *rhs;       /* m x 1 right-hand side of the solves, zero outside the block */
    cholmod_dense *x, *y;     /* the solve's solution and CHOLMOD's workspace */
    SuiteSparse_long *parent; /* [m] elimination tree of C's whole pattern */
    unsigned char *held;      /* [m] by factor position: in B */
    unsigned char *next;      /* [m] scratch, zero between uses: the block an ensure asks for */
    SuiteSparse_long *order;  /* [m] factor position of the a-th contact of the last ensure */
    size_t n;                 /* |B| */
    int valid;                /* 0: stale (W or the partition changed); held still agrees */
    int fragile;              /* a pivot ratio of the held factor is below the update bound */
    size_t updates;           /* rows added or deleted since the last fresh factorization */
    double fresh_cost;        /* the entries a fresh factorization visits: nnz(L) + nnz(C) */
};

struct fr_sparse_coupling {
    cholmod_common c; /* this coupling's CHOLMOD workspace (sparse_factor.h settings) */
    size_t m;
    cholmod_sparse *W;      /* whole W, m x m, contact order, sorted columns (stype 0) */
    cholmod_sparse *C;      /* upper triangle of P W P^T, sorted (stype 1) */
    SuiteSparse_long *perm; /* [m] contact at factor position p */
    SuiteSparse_long *pinv; /* [m] factor position of contact i */
    double *by_contact;     /* [m] scratch, zero between uses: a vector indexed by contact */
    double *column;         /* [m] scratch, zero between uses: a column of W scattered */
    struct fr_sparse_block block;
};

/* sum_j W_ij x_j over the contacts j (x indexed by contact), W_ii x_i left out when
 * skip_diagonal; with size non-NULL also sum_j |W_ij x_j| into *size. */
double fr_sparse_row_dot(const struct fr_sparse_coupling *sp, size_t i, const double x[],
                         int skip_diagonal, double *size);

/* sum_j |W_ij| x_j (x >= 0). */
double fr_sparse_row_abs_dot(const struct fr_sparse_coupling *sp, size_t i, const double x[]);

/* out[a] = W_{set[a], k} for a < n. */
void fr_sparse_column_gather(struct fr_sparse_coupling *sp, size_t k, const size_t set[], size_t n,
                             double out[]);

/* The largest Gershgorin radius sum_j sqrt(s_i) |W_ij| sqrt(s_j) / (w_max s_max) over i, the
 * s_i >= 0 and w_max = max |W_ij| the caller's scales (so every term is at most 1): a bound
 * of the largest eigenvalue of D^1/2 W D^1/2 / (w_max s_max), D = diag(s). */
double fr_sparse_gershgorin(const struct fr_sparse_coupling *sp, const double s[], double s_max,
                            double w_max);

/* max_ij |W_ij|. */
double fr_sparse_max_abs(const struct fr_sparse_coupling *sp);

/* Builds the coupling in sp (zeroed but for its workspace sp->c, started) from W (whole, m x m,
 * sorted columns, checked: sparse_setup.c), which it takes over: the ordering, C and their
 * scratch (the block factor's storage follows: fr_sparse_block_alloc). FRICREG_OK or
 * FRICREG_ENOMEM; either way fr_sparse_coupling_free releases what was built. */
int fr_sparse_coupling_build(struct fr_sparse_coupling *sp, cholmod_sparse *W);

/* Releases everything but the block factor (fr_sparse_block_free, first), the workspace last;
 * safe on a zeroed struct. */
void fr_sparse_coupling_free(struct fr_sparse_coupling *sp);

#endif
