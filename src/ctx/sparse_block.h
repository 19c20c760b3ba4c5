/* SPDX-License-Identifier: GPL-3.0-or-later */
/* sparse_block.h — internal: the factor of a principal block of a sparse W (sparse_block.c),
 * the sparse twin of factor.h's. */
#ifndef FRICREG_SPARSE_BLOCK_H
#define FRICREG_SPARSE_BLOCK_H

#include "ctx_internal.h"
#include "sparse_coupling.h"

/* The block factor's storage and CHOLMOD's workspace for it, after fr_sparse_coupling_build
 * (sparse_setup.c): FRICREG_OK or FRICREG_ENOMEM; released by fr_sparse_block_free, which is
 * safe on a zeroed block and comes before fr_sparse_coupling_free (its workspace goes last). */
int fr_sparse_block_alloc(struct fr_sparse_coupling *sp);
void fr_sparse_block_free(struct fr_sparse_coupling *sp);

/* The sparse twins of fr_factor_ensure and fr_factor_solve (factor.h), to which they hand over
 * when W is sparse:
 * the same contract, with the singularity test in the sparse factor's order. */
int fr_sparse_block_ensure(struct fricreg_ctx *ctx, const size_t set[], size_t n, const char *who);
int fr_sparse_block_solve(struct fricreg_ctx *ctx, double r[]);

#endif
