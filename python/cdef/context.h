/* SPDX-License-Identifier: GPL-3.0-or-later */
/* context.h — fricreg.h's context of coupled 1-D contacts (fricreg_ctx) and fricreg_structure.h's
 * contact step for one's own integrator (fricreg_ctx_solve_step_matrix), in the syntax of cffi's
 * cdef (no macros, no includes; python/build_ffi.py); the sparse flags and matrix formats are
 * base.h's. */
typedef struct fricreg_ctx fricreg_ctx;
enum fricreg_partition { FRICREG_PARTITION_CONSISTENT = 1, FRICREG_PARTITION_PAPER = 2 };
enum fricreg_step_flags { FRICREG_STEP_PLAIN = 1 };
enum fricreg_stat {
    FRICREG_STAT_EVALS = 0,
    FRICREG_STAT_FEQ_CONTACTS = 1,
    FRICREG_STAT_FACTORIZATIONS = 2,
    FRICREG_STAT_SOLVES = 3,
    FRICREG_STAT_QP_ITERATIONS = 4,
    FRICREG_STAT_FACTOR_UPDATES = 5
};
int fricreg_ctx_create(size_t m, fricreg_ctx **out);
void fricreg_ctx_free(fricreg_ctx *ctx);
size_t fricreg_ctx_size(const fricreg_ctx *ctx);
int fricreg_ctx_set_law(fricreg_ctx *ctx, int law, double eps);
int fricreg_ctx_set_bounds(fricreg_ctx *ctx, size_t m, const double mun[]);
int fricreg_ctx_set_coupling_diagonal(fricreg_ctx *ctx, size_t m, const double w[]);
int fricreg_ctx_set_coupling_dense(fricreg_ctx *ctx, size_t m, const double W[]);
int fricreg_ctx_set_coupling_csr(fricreg_ctx *ctx, size_t m, int flags, const int64_t rowptr[],
                                 const int64_t colind[], const double values[]);
int fricreg_ctx_set_coupling_csc(fricreg_ctx *ctx, size_t m, int flags, const int64_t colptr[],
                                 const int64_t rowind[], const double values[]);
int fricreg_ctx_set_partition(fricreg_ctx *ctx, int partition);
int fricreg_ctx_stick_stiffness(fricreg_ctx *ctx, double *lambda);
int fricreg_ctx_eval(fricreg_ctx *ctx, size_t m, const double zdot[], const double a_free[],
                     double f[], double f_eq[]);
int fricreg_ctx_tangent(fricreg_ctx *ctx, size_t m, double df_dzdot[], double df_dafree[]);
int fricreg_ctx_tangent_apply(fricreg_ctx *ctx, size_t m, const double dzdot[],
                              const double dafree[], double df[]);
size_t fricreg_ctx_switching_count(const fricreg_ctx *ctx);
int fricreg_ctx_switching(fricreg_ctx *ctx, size_t m, const double zdot[], const double a_free[],
                          const double f[], double g[], size_t ng);
int fricreg_ctx_set_keep_tangent(fricreg_ctx *ctx, int keep);
int fricreg_ctx_get_stat(const fricreg_ctx *ctx, int which, int64_t *value);
void fricreg_ctx_reset_stats(fricreg_ctx *ctx);
int fricreg_ctx_errcode(const fricreg_ctx *ctx);
const char *fricreg_ctx_errmsg(const fricreg_ctx *ctx);
int fricreg_ctx_solve_step(fricreg_ctx *ctx, size_t m, const double zdot_start[],
                           const double zdot_pred[], const double a_pred[], const double W[],
                           const double Weff[], double c, double tol, int max_iter, int flags,
                           double f[], int info[]);
int fricreg_ctx_solve_step_matrix(fricreg_ctx *ctx, size_t m, const double zdot_start[],
                                  const double zdot_pred[], const double a_pred[], int format,
                                  const int64_t w_ptr[], const int64_t w_ind[],
                                  const double w_values[], const int64_t weff_ptr[],
                                  const int64_t weff_ind[], const double weff_values[], double c,
                                  double tol, int max_iter, int flags, double f[], int info[]);
