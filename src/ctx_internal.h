/* ctx_internal.h — the context's layout, shared by ctx.c (set-up) and partition.c (eval). */
#ifndef FRICREG_CTX_INTERNAL_H
#define FRICREG_CTX_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include "error.h"
#include "fricreg.h"

#define FR_NSTATS 4
#define FR_MAX_CONTACTS ((size_t)1 << 26)

struct fricreg_ctx {
    size_t m;
    int law;
    int partition;  /* enum fricreg_partition: used with a dense W */
    double eps;
    double *mun;    /* [m] friction bounds */
    double *w_diag; /* [m] diagonal of W (the whole of W when W is diagonal) */
    double *W;      /* [m*m] row-major dense W, or NULL when W is diagonal */

    /* Scratch, allocated with the coupling so that eval never allocates. */
    double *f;          /* [m] friction forces being built */
    double *f_eq;       /* [m] f_eq being built */
    size_t *stick;      /* [m] indices of the near-stick set S */
    size_t n_stick;
    size_t *stick_prev; /* [m] S of the last factorization; valid while factor_valid */
    size_t n_stick_prev;
    int factor_valid;
    double *factor;     /* [m*m] dense only: pivoted LDL^T of W_SS, packed |S| x |S| */
    size_t *perm;       /* [m] dense only: its pivot permutation */
    double *rhs;        /* [m] dense only: right-hand side of the W_SS solve */
    double *rcond_work; /* [3m] dense only: workspace of the condition estimate */

    int64_t stats[FR_NSTATS];
    struct fr_error err;
};

/* Records a failure (code and printf-style message) in the context and returns the code. */
#define fr_fail(ctx, ...) fr_error_set(&(ctx)->err, __VA_ARGS__)

#endif
