/* SPDX-License-Identifier: GPL-3.0-or-later */
/* contact_step_solver.h — internal: the solver of fricreg_ctx_solve_step (contact_step.c) as
 * the context keeps it between calls (contact_step_solver.c), and its vectors, which the
 * Newton iterations work on (contact_step_newton.c). */
#ifndef FRICREG_CONTACT_STEP_SOLVER_H
#define FRICREG_CONTACT_STEP_SOLVER_H

#include <stddef.h>

#include <cholmod.h>
#include <gsl/gsl_vector.h>

#include "base/matrix_input.h"
#include "fricreg.h"
#include "newton_matrix.h"
#include "step_newton.h"
#include "step_pattern.h"

enum {
    FR_STEP_V_F0,
    FR_STEP_V_FK,
    FR_STEP_V_FT,
    FR_STEP_V_DF,
    FR_STEP_V_G,
    FR_STEP_V_GT,
    FR_STEP_V_ZDOT,
    FR_STEP_V_AFREE,
    FR_STEP_V_F,
    FR_STEP_V_B,
    FR_STEP_V_WG,
    FR_STEP_V_PAIRS,
    FR_STEP_VECTORS = FR_STEP_V_PAIRS + 10
};

struct fr_step_solver {
    size_t m;
    fricreg_ctx *ctx;
    double c;
    const double *z0, *a0, *mun;
    cholmod_common cc;
    cholmod_sparse *W, *Weff; /* upper triangles, sorted */
    struct fr_newton_matrix nm;
    double *block;                 /* every vector, one allocation */
    gsl_vector v[FR_STEP_VECTORS]; /* views of it, for the shared iterations (step_newton.h) */
    double *f0, *zdot, *afree, *F, *b, *wg, *df;
    struct fr_compliance_pair at_start, at_k, at_t, at_df, at_guess;
    unsigned char *stopped;
    SuiteSparse_long *next;           /* [m] refill's cursor per column */
    struct fr_step_pattern pw, pweff; /* the compressed inputs' maps (_csr, _csc calls only) */
    int dense; /* the Newton matrix's dense form reserved (fr_ctx_tangent_may_be_dense) */
};

/* W and W_eff as the caller gave them: dense row-major, or compressed (then dense is NULL). */
struct fr_step_inputs {
    const double *W, *Weff;
    const struct fr_compressed *sw, *sweff;
};

/* The solver of the context's previous call when m and the patterns of W and W_eff are its
 * (a dense input's values refilled, the analysis kept), else a new one, kept in the context;
 * NULL when out of memory (the context then holds none). A compressed input's values are
 * stored by the caller (store_compressed). A refill that meets another pattern leaves the old
 * solver's values half written: it is dropped either way. */
struct fr_step_solver *fr_contact_step_solver(fricreg_ctx *ctx, size_t m,
                                              const struct fr_step_inputs *in);

#endif
