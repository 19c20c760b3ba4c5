/* SPDX-License-Identifier: GPL-3.0-or-later */
/* step_pattern.h — internal: W or W_eff of fricreg_ctx_solve_step_csr/_csc as the step's
 * solver keeps it. The caller's compressed arrays (checked by fr_compressed_check,
 * matrix_input.h) are mapped once onto the upper triangle in CHOLMOD's form that the solver
 * works on (fr_compressed_to_cholmod builds its pattern); a later call whose arrays have the
 * same pattern sums its values through the map, checks them and stores them, allocating
 * nothing: a caller steps thousands of times on one K_eff pattern. */
#ifndef FRICREG_STEP_PATTERN_H
#define FRICREG_STEP_PATTERN_H

#include <stddef.h>
#include <stdint.h>

#include <cholmod.h>

#include "base/matrix_input.h"

struct fr_step_pattern {
    int flags, by_columns;
    size_t m, nnz;
    int64_t *ptr, *ind;     /* copies of the caller's pattern: [m + 1], [nnz] */
    SuiteSparse_long *slot; /* [nnz] each entry's place in the upper triangle's values */
    double *upper, *lower;  /* [nnz(S)] the sums of the entries on or above, and below, the
                               diagonal (lower: whole matrices only); upper ends as the values */
};

/* The upper triangle's pattern into *S (sorted, stype 1; its values to be stored) and p's
 * map for the checked a (square m x m, symmetric). FRICREG_OK or FRICREG_ENOMEM; either way
 * fr_step_pattern_free releases p, and *S is the caller's. */
int fr_step_pattern_build(struct fr_step_pattern *p, const struct fr_compressed *a,
                          cholmod_common *cc, cholmod_sparse **S);

/* 1 if the checked a has p's flags and pattern (then S's values can be refilled), else 0. */
int fr_step_pattern_same(const struct fr_step_pattern *p, const struct fr_compressed *a);

/* a's values summed into p->upper (S the pattern p was built for) and checked as
 * fricreg_ctx_solve_step checks a dense matrix: FRICREG_ENOTPSD if a diagonal entry is
 * missing or below DBL_MIN (its row in *bi), else FRICREG_ENOTSYM, given whole, if
 * |A_ij - A_ji| > 1e-12 sqrt(A_ii A_jj) (the first such (i, j), i < j, in *bi, *bj), else
 * FRICREG_OK with p->upper the upper triangle of (A + A^T)/2 (given whole) or of A. */
int fr_step_pattern_values(struct fr_step_pattern *p, const struct fr_compressed *a,
                           const cholmod_sparse *S, size_t *bi, size_t *bj);

/* A_jj of the values fr_step_pattern_values accepted. */
double fr_step_pattern_diagonal(const struct fr_step_pattern *p, const cholmod_sparse *S, size_t j);

/* The accepted values into S: 1 if one differs from S's, else 0. */
int fr_step_pattern_store(const struct fr_step_pattern *p, cholmod_sparse *S);

/* Releases p's arrays; safe on a zeroed p. */
void fr_step_pattern_free(struct fr_step_pattern *p);

#endif
