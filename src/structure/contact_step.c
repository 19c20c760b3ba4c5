/* SPDX-License-Identifier: GPL-3.0-or-later */
/* contact_step.c — fricreg_ctx_solve_step: the contact-space Newton of one implicit step
 * (Newmark, HHT-alpha, a BDF) for a caller who keeps their own integrator and their own K_eff
 * solve, with the safeguards of fricreg_structure's steps (newmark.c): the stick guess, the
 * stop of a slipping contact at zdot = 0, and the backtracking line search.
 *
 * The caller's step makes the contacts' velocities and free accelerations affine in the forces
 * (fricreg_structure.h, fricreg_ctx_solve_step):
 *   zdot(f) = zdot_pred + c W_eff f,   a_free(f) = a_pred - (W - W_eff) f,
 * and Newton solves G(f) = f - F(zdot(f), a_free(f)) = 0, F the context's law. The iterations
 * (direction, stop, line search) are step_newton.c's and the stick guess's solve and right-hand
 * side newton_matrix.c's, all shared with newmark.c; the sequence (stick guess, start, restart
 * without stops) is newmark.c's newton(). What differs is how the residual is measured.
 * newmark.c reads the structure's residual R = w J^T G on its degrees of freedom, which this
 * function does not see; the line search here reads its M^-1 norm,
 *   ||R||_{M^-1}^2 = G^T J M^-1 J^T G = G^T W G,
 * which is newmark.c's ||R||_2 up to a constant when M is a multiple of I (the building) and
 * the same kind of measure otherwise. With the plain 2-norm of G instead, the line search
 * stalled at the building's reversals (a stopped damper beside two sliding ones: 1 step of
 * 1500 unconverged at eps = 1e-3, 5 at 1e-4), where ||R|| weighs the dampers' differences.
 * The stopping rule reads max_i |G_i|, in force units.
 *
 * The solver (CHOLMOD's workspace, W's and W_eff's upper triangles, the Newton matrix with
 * W_eff's analysed pattern, the vectors) is kept in the context between calls
 * (fr_ctx_keep_workspace, ctx_driver.h): a caller steps thousands of times on one K_eff
 * pattern, and building it cost a third of a 10-contact step (bench/solve_step.c). A call
 * whose m and patterns are the kept solver's refills the values; a new W_eff also forgets
 * the factor the masked factor holds (masked_factor.h), which is otherwise kept across calls
 * as across iterations. Every vector is written before it is read within a call (valgrind
 * holds the built solver to that), CHOLMOD's analysis depends on the pattern alone and its
 * factorization on the values alone: a kept solver gives the built one's results, bit for
 * bit (tests/test_contact_step.c). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "base/matrix_input.h"
#include "base/sparse_factor.h"
#include "contact_factor.h"
#include "ctx/ctx_driver.h"
#include "fricreg_structure.h"
#include "newton_matrix.h"
#include "step_newton.h"
#include "step_pattern.h"

#define SYM_TOL 1e-12 /* |A_ij - A_ji| <= SYM_TOL sqrt(A_ii A_jj), as the context's setters */
#define DENSE_FALLBACK_MAX 64

enum {
    V_F0,
    V_FK,
    V_FT,
    V_DF,
    V_G,
    V_GT,
    V_ZDOT,
    V_AFREE,
    V_F,
    V_B,
    V_WG,
    V_PAIRS,
    VECTORS = V_PAIRS + 10
};

struct step_solver {
    size_t m;
    fricreg_ctx *ctx;
    double c;
    const double *z0, *a0, *mun;
    cholmod_common cc;
    cholmod_sparse *W, *Weff; /* upper triangles, sorted */
    struct fr_newton_matrix nm;
    double *block;         /* every vector, one allocation */
    gsl_vector v[VECTORS]; /* views of it, for the shared iterations (step_newton.h) */
    double *f0, *zdot, *afree, *F, *b, *wg, *df;
    struct fr_compliance_pair at_start, at_k, at_t, at_df, at_guess;
    unsigned char *stopped;
    SuiteSparse_long *next;           /* [m] refill's cursor per column */
    struct fr_step_pattern pw, pweff; /* the compressed inputs' maps (_csr, _csc calls only) */
    int dense; /* the Newton matrix's dense form reserved (fr_ctx_tangent_may_be_dense) */
};

/* W and W_eff as the caller gave them: dense row-major, or compressed (then dense is NULL). */
struct step_inputs {
    const double *W, *Weff;
    const struct fr_compressed *sw, *sweff;
};

static int fail_as(fricreg_ctx *ctx, int code, const char *who, const char *what)
{
    return fr_error_set(fr_ctx_error(ctx), code, "%s: %s", who, what);
}

static int fail(fricreg_ctx *ctx, int code, const char *what)
{
    return fail_as(ctx, code, "solve_step", what);
}

/* A's upper triangle (m x m, row-major) as CHOLMOD's symmetric upper form, the diagonal kept
 * and the zeros above it left out; NULL when out of memory. */
static cholmod_sparse *upper_of(const double A[], size_t m, cholmod_common *cc)
{
    size_t nnz = 0;
    for (size_t j = 0; j < m; j++)
        for (size_t i = 0; i <= j; i++)
            nnz += i == j || A[i * m + j] != 0.0;
    cholmod_sparse *S = cholmod_l_allocate_sparse(m, m, nnz, 1, 1, 1, CHOLMOD_REAL, cc);
    if (S == NULL)
        return NULL;
    SuiteSparse_long *Sp = S->p, *Si = S->i, p = 0;
    double *Sx = S->x;
    for (size_t j = 0; j < m; j++) {
        Sp[j] = p;
        for (size_t i = 0; i <= j; i++)
            if (i == j || A[i * m + j] != 0.0) {
                Si[p] = (SuiteSparse_long)i;
                Sx[p++] = A[i * m + j];
            }
    }
    Sp[m] = p;
    return S;
}

/* A's upper triangle into S's values when its nonzeros (the diagonal kept) are S's pattern,
 * the pattern upper_of(A) would build: 1, with *changed set if a value differs from S's; 0 at
 * the first entry outside the pattern (S's values then partly overwritten: rebuild it). A is
 * read row by row, in the order it lies in memory (column by column, each entry m doubles
 * from the last, made the refill of m = 2000 three times slower): next[m] holds each column's
 * next entry of S. */
static int refill(cholmod_sparse *S, const double A[], size_t m, SuiteSparse_long next[],
                  int *changed)
{
    const SuiteSparse_long *Sp = S->p, *Si = S->i;
    double *Sx = S->x;
    int differ = 0;
    memcpy(next, Sp, m * sizeof *next);
    for (size_t i = 0; i < m; i++) {
        const double *row = A + i * m;
        for (size_t j = i; j < m; j++) {
            double a = row[j];
            if (j != i && a == 0.0)
                continue;
            SuiteSparse_long p = next[j]++;
            if (p == Sp[j + 1] || Si[p] != (SuiteSparse_long)i)
                return 0;
            differ |= Sx[p] != a;
            Sx[p] = a;
        }
    }
    for (size_t j = 0; j < m; j++)
        if (next[j] != Sp[j + 1])
            return 0;
    *changed = differ;
    return 1;
}

#define SYM_TILE 32 /* the checks' tiles: A_ji a row of a tile away, not m doubles */

/* A (m x m, row-major) read once, by tiles: FRICREG_ENONFINITE if an entry is NaN or
 * infinite, else FRICREG_ENOTPSD if a diagonal entry is below DBL_MIN, else FRICREG_ENOTSYM
 * if |A_ij - A_ji| > SYM_TOL sqrt(A_ii A_jj) somewhere, else FRICREG_OK. One pass for both
 * checks: at m = 2000 the input's O(m^2) reading is most of a step's time. */
static int check_matrix(const double A[], size_t m)
{
    int diagonal = FRICREG_OK, symmetric = FRICREG_OK;
    for (size_t i = 0; i < m; i++) {
        if (!isfinite(A[i * m + i]))
            return FRICREG_ENONFINITE;
        if (!(A[i * m + i] >= 0x1p-1022))
            diagonal = FRICREG_ENOTPSD;
    }
    for (size_t i0 = 0; i0 < m; i0 += SYM_TILE)
        for (size_t j0 = i0; j0 < m; j0 += SYM_TILE)
            for (size_t i = i0; i < i0 + SYM_TILE && i < m; i++)
                for (size_t j = j0 > i + 1 ? j0 : i + 1; j < j0 + SYM_TILE && j < m; j++) {
                    double a = A[i * m + j], b = A[j * m + i];
                    if (!isfinite(a) || !isfinite(b))
                        return FRICREG_ENONFINITE;
                    if (a != b && symmetric == FRICREG_OK && diagonal == FRICREG_OK &&
                        fabs(a - b) > SYM_TOL * sqrt(A[i * m + i]) * sqrt(A[j * m + j]))
                        symmetric = FRICREG_ENOTSYM;
                }
    return diagonal != FRICREG_OK ? diagonal : symmetric;
}

static int all_finite(const double x[], size_t n)
{
    for (size_t k = 0; k < n; k++)
        if (!isfinite(x[k]))
            return 0;
    return 1;
}

static void products_of(struct step_solver *s, const double f[], struct fr_compliance_pair *p)
{
    fr_delassus_mult(s->Weff, 1.0, f, 0.0, p->weff->data);
    fr_delassus_mult(s->W, 1.0, f, 0.0, p->w->data);
}

/* G = f - F(zdot(f), a_free(f)) from f and its products, the merit sqrt(G^T W G) into *phi
 * and ||G||_inf into *rinf; the context's status (its eval's). */
static int residual(struct step_solver *s, const gsl_vector *fv, const struct fr_compliance_pair *p,
                    gsl_vector *Gv, double *phi, double *rinf)
{
    size_t m = s->m;
    const double *f = fv->data, *weff_f = p->weff->data, *w_f = p->w->data;
    double *G = Gv->data;
    for (size_t i = 0; i < m; i++) {
        s->zdot[i] = s->z0[i] + s->c * weff_f[i];
        s->afree[i] = s->a0[i] + (weff_f[i] - w_f[i]); /* as newmark.c: the difference first */
    }
    int status = fricreg_ctx_eval(s->ctx, m, s->zdot, s->afree, s->F, NULL);
    if (status != FRICREG_OK)
        return status;
    double big = 0.0, q = 0.0;
    for (size_t i = 0; i < m; i++) {
        G[i] = f[i] - s->F[i];
        big = fmax(big, fabs(G[i]));
    }
    fr_delassus_mult(s->W, 1.0, G, 0.0, s->wg);
    for (size_t i = 0; i < m; i++)
        q += G[i] * s->wg[i];
    *phi = sqrt(fmax(q, 0.0));
    *rinf = big;
    return FRICREG_OK;
}

static void w_product_cb(void *user, const double x[], double w_x[])
{
    struct step_solver *s = user;
    fr_delassus_mult(s->W, 1.0, x, 0.0, w_x);
}

static int residual_cb(void *user, const gsl_vector *f, const struct fr_compliance_pair *p,
                       gsl_vector *G, double *phi, double *rinf)
{
    return residual(user, f, p, G, phi, rinf);
}

/* fk = x (products p) and its residual. */
static int start_at(struct step_solver *s, const gsl_vector *x, const struct fr_compliance_pair *p,
                    double *phi, double *rinf)
{
    gsl_vector_memcpy(&s->v[V_FK], x);
    gsl_vector_memcpy(s->at_k.weff, p->weff);
    gsl_vector_memcpy(s->at_k.w, p->w);
    return residual(s, &s->v[V_FK], &s->at_k, &s->v[V_G], phi, rinf);
}

/* Law (4) with a diagonal W: the stick guess solves the band's own piece (newmark.c). */
static int law_exact(const struct step_solver *s)
{
    if (fr_ctx_law(s->ctx) != FRICREG_LAW_QUINN)
        return 0;
    const SuiteSparse_long *Wp = s->W->p;
    return Wp[s->m] == (SuiteSparse_long)s->m; /* the diagonal alone */
}

/* The stick guess of newmark.c's stick_guess into s->ft, its products into at_guess: 0 if
 * there is none, 1 (2 for law_exact). Reads s->zdot (the start's residual) unless law_exact. */
static int stick_guess(struct step_solver *s, const double zstart[])
{
    size_t m = s->m, k = 0;
    for (size_t i = 0; i < m; i++) {
        s->stopped[i] = fabs(s->f0[i]) < s->mun[i];
        k += s->stopped[i];
        s->df[i] = 0.0;
    }
    if (k == 0)
        return 0;
    int exact = law_exact(s);
    fr_newton_stick_rhs(m, exact, s->c, fr_ctx_eps(s->ctx), s->mun,
                        fr_ctx_coupling_diagonal(s->ctx), s->z0, s->a0, s->at_start.weff->data,
                        zstart, s->zdot, s->b);
    if (fr_newton_stick_solve(&s->nm, s->Weff, s->stopped, s->b, s->df, s->at_guess.weff->data,
                              &s->cc) != FRICREG_OK)
        return 0;
    double *guess = s->v[V_FT].data;
    for (size_t i = 0; i < m; i++) {
        guess[i] = s->f0[i] + s->df[i];
        if (!isfinite(guess[i]))
            return 0; /* beyond the range (a tiny c): no guess, Newton from f0 */
    }
    fr_delassus_mult(s->W, 1.0, s->df, 0.0, s->at_guess.w->data);
    fr_step_combine(&s->at_start, 1.0, &s->at_guess, &s->at_guess);
    return exact ? 2 : 1;
}

/* The shared iterations (step_newton.c) from fk; plain: full steps, no stops, no search. */
static int iterate(struct step_solver *s, double tol, int max_iter, int stops, int search,
                   double *phi, double *rinf, int *iters)
{
    struct fr_step_newton e = {
        .m = s->m,
        .coef = s->c,
        .eps = fr_ctx_eps(s->ctx),
        .mun = s->mun,
        .max_iter = max_iter,
        .ctx = s->ctx,
        .nm = &s->nm,
        .W = s->W,
        .Weff = s->Weff,
        .cc = &s->cc,
        .fk = &s->v[V_FK],
        .ft = &s->v[V_FT],
        .df = &s->v[V_DF],
        .G = &s->v[V_G],
        .Gt = &s->v[V_GT],
        .at_k = &s->at_k,
        .at_t = &s->at_t,
        .at_df = &s->at_df,
        .zdot = &s->v[V_ZDOT],
        .stopped = s->stopped,
        .cuts = NULL,
        .user = s,
        .w_product = w_product_cb,
        .residual = residual_cb,
    };
    return fr_step_newton_iterate(&e, tol, stops, search, phi, rinf, iters);
}

/* Newton as newmark.c's newton(), or plain (full steps from f0, no guess). */
static int solve(struct step_solver *s, const double zstart[], double tol, int max_iter, int plain,
                 int *converged, int *iters)
{
    double phi = 0.0, rinf = 0.0, phi_guess = 0.0;
    int guess = 0, status;
    *iters = 0;
    products_of(s, s->f0, &s->at_start);
    if (!plain && law_exact(s) && (guess = stick_guess(s, zstart)) != 0) {
        if ((status = start_at(s, &s->v[V_FT], &s->at_guess, &phi, &rinf)) != FRICREG_OK)
            return status;
        if (rinf <= tol) {
            *iters = 1;
            *converged = 1;
            return FRICREG_OK;
        }
        phi_guess = phi;
    }
    if ((status = start_at(s, &s->v[V_F0], &s->at_start, &phi, &rinf)) != FRICREG_OK)
        return status;
    if (!plain && rinf > tol) {
        double phi_start = phi;
        if (guess != 0) {
            if (phi_guess < phi_start)
                status = start_at(s, &s->v[V_FT], &s->at_guess, &phi, &rinf);
        } else if (stick_guess(s, zstart)) {
            status = start_at(s, &s->v[V_FT], &s->at_guess, &phi, &rinf);
            if (status == FRICREG_OK && !(phi < phi_start))
                status = start_at(s, &s->v[V_F0], &s->at_start, &phi, &rinf);
        }
        if (status != FRICREG_OK)
            return status;
    }
    memset(s->stopped, 0, s->m);
    if ((status = iterate(s, tol, max_iter, !plain, !plain, &phi, &rinf, iters)) != FRICREG_OK)
        return status;
    if (!plain && rinf > tol && isfinite(phi) && *iters < max_iter) {
        if ((status = start_at(s, &s->v[V_F0], &s->at_start, &phi, &rinf)) != FRICREG_OK ||
            (status = iterate(s, tol, max_iter, 0, 1, &phi, &rinf, iters)) != FRICREG_OK)
            return status;
    }
    *converged = rinf <= tol;
    return isfinite(phi) ? FRICREG_OK : FRICREG_EDIVERGED;
}

/* The upper triangles of the inputs into s->W and s->Weff, their values those of a dense
 * input (a compressed one's are stored by the caller once checked). */
static int build_matrices(struct step_solver *s, const struct step_inputs *in)
{
    if (in->sw == NULL) {
        s->W = upper_of(in->W, s->m, &s->cc);
        s->Weff = upper_of(in->Weff, s->m, &s->cc);
        return s->W != NULL && s->Weff != NULL ? FRICREG_OK : FRICREG_ENOMEM;
    }
    int status = fr_step_pattern_build(&s->pw, in->sw, &s->cc, &s->W);
    return status == FRICREG_OK ? fr_step_pattern_build(&s->pweff, in->sweff, &s->cc, &s->Weff)
                                : status;
}

static int allocate(struct step_solver *s, const struct step_inputs *in)
{
    size_t m = s->m;
    if (fr_cholmod_start(&s->cc) != FRICREG_OK || build_matrices(s, in) != FRICREG_OK)
        return FRICREG_ENOMEM;
    s->block = malloc(VECTORS * m * sizeof *s->block);
    s->stopped = malloc(m);
    s->next = malloc(m * sizeof *s->next);
    if (s->block == NULL || s->stopped == NULL || s->next == NULL)
        return FRICREG_ENOMEM;
    for (size_t k = 0; k < VECTORS; k++)
        s->v[k] = (gsl_vector){.size = m, .stride = 1, .data = s->block + k * m};
    s->f0 = s->v[V_F0].data;
    s->df = s->v[V_DF].data;
    s->zdot = s->v[V_ZDOT].data;
    s->afree = s->v[V_AFREE].data;
    s->F = s->v[V_F].data;
    s->b = s->v[V_B].data;
    s->wg = s->v[V_WG].data;
    struct fr_compliance_pair *pairs[] = {&s->at_start, &s->at_k, &s->at_t, &s->at_df,
                                          &s->at_guess};
    for (size_t k = 0; k < 5; k++)
        *pairs[k] = (struct fr_compliance_pair){&s->v[V_PAIRS + 2 * k], &s->v[V_PAIRS + 2 * k + 1]};
    return fr_newton_matrix_prepare(&s->nm, s->Weff, s->dense, &s->cc);
}

static void release(void *p)
{
    struct step_solver *s = p;
    fr_newton_matrix_free(&s->nm, &s->cc);
    cholmod_l_free_sparse(&s->W, &s->cc);
    cholmod_l_free_sparse(&s->Weff, &s->cc);
    free(s->block);
    free(s->stopped);
    free(s->next);
    fr_step_pattern_free(&s->pw);
    fr_step_pattern_free(&s->pweff);
    fr_cholmod_finish(&s->cc);
    free(s);
}

/* The solver of the context's previous call when m and the patterns of W and W_eff are its
 * (a dense input's values refilled, the analysis kept), else a new one, kept in the context;
 * NULL when out of memory (the context then holds none). A compressed input's values are
 * stored by the caller (store_compressed). A refill that meets another pattern leaves the old
 * solver's values half written: it is dropped either way. */
static struct step_solver *solver_for(fricreg_ctx *ctx, size_t m, const struct step_inputs *in)
{
    struct step_solver *s = fr_ctx_workspace(ctx);
    /* The dense form for a tangent without rows, reserved here, so that no step allocates
     * it; a kept solver without it, once the context can need it, is built again. */
    int dense = m <= DENSE_FALLBACK_MAX || fr_ctx_tangent_may_be_dense(ctx);
    if (s != NULL && dense && !s->dense)
        s = NULL;
    if (s != NULL && s->m == m && in->sw != NULL && fr_step_pattern_same(&s->pw, in->sw) &&
        fr_step_pattern_same(&s->pweff, in->sweff))
        return s;
    int w_changed = 0, weff_changed = 0;
    if (s != NULL && s->m == m && in->sw == NULL && refill(s->W, in->W, m, s->next, &w_changed) &&
        refill(s->Weff, in->Weff, m, s->next, &weff_changed)) {
        if (weff_changed)
            s->nm.block.held = 0; /* the factor held is of the old values */
        return s;
    }
    fr_ctx_drop_workspace(ctx);
    s = calloc(1, sizeof *s);
    if (s == NULL)
        return NULL;
    s->m = m;
    s->dense = dense;
    if (allocate(s, in) != FRICREG_OK) {
        release(s);
        return NULL;
    }
    fr_ctx_keep_workspace(ctx, s, release);
    return s;
}

/* Checks of what every entry point takes alike, in the dense call's order: the vectors and
 * the outputs NULL, m, then c, tol, max_iter and flags. */
static int check_arguments(fricreg_ctx *ctx, const char *who, size_t m, const double zdot_start[],
                           const double zdot_pred[], const double a_pred[], double c, double tol,
                           int max_iter, int flags, const double f[], const int info[])
{
    if (zdot_start == NULL || zdot_pred == NULL || a_pred == NULL || f == NULL || info == NULL)
        return fail_as(ctx, FRICREG_ENULL, who, "a required array is NULL");
    if (m != fricreg_ctx_size(ctx))
        return fr_error_set(fr_ctx_error(ctx), FRICREG_ESIZE,
                            "%s: m = %zu, the context has %zu contacts", who, m,
                            fricreg_ctx_size(ctx));
    if (!isfinite(c) || !isfinite(tol))
        return fail_as(ctx, FRICREG_ENONFINITE, who, "c or tol is NaN or infinite");
    if (!(c > 0.0) || !(tol > 0.0) || max_iter < 1 || (flags & ~FRICREG_STEP_PLAIN) != 0)
        return fail_as(ctx, FRICREG_EINVAL, who,
                       "needs c > 0, tol > 0, max_iter >= 1, known flags");
    return FRICREG_OK;
}

/* W's diagonal against the context's coupling's (to 1e-12 relative); w_ii one of them. */
static int check_coupling_diagonal(fricreg_ctx *ctx, const char *who, size_t i, double w_ii)
{
    const double *wd = fr_ctx_coupling_diagonal(ctx);
    if (fabs(w_ii - wd[i]) <= SYM_TOL * wd[i])
        return FRICREG_OK;
    return fr_error_set(fr_ctx_error(ctx), FRICREG_EINVAL,
                        "%s: W_%zu%zu = %g, the context's coupling has %g", who, i, i, w_ii, wd[i]);
}

/* The step on the solver s, its matrices filled and checked. */
static int run(fricreg_ctx *ctx, struct step_solver *s, const char *who, const double zdot_start[],
               const double zdot_pred[], const double a_pred[], double c, double tol, int max_iter,
               int flags, double f[], int info[])
{
    size_t m = s->m;
    s->ctx = ctx;
    s->c = c;
    s->z0 = zdot_pred;
    s->a0 = a_pred;
    s->mun = fr_ctx_bounds(ctx);
    memcpy(s->f0, f, m * sizeof *f);
    int converged = 0, iters = 0;
    int status = solve(s, zdot_start, tol, max_iter, flags & FRICREG_STEP_PLAIN, &converged,
                       &iters);
    if (status == FRICREG_OK) {
        memcpy(f, s->v[V_FK].data, m * sizeof *f);
        info[0] = iters;
        info[1] = converged;
    } else if (status == FRICREG_EDIVERGED) {
        fail_as(ctx, status, who, "the residual is not finite");
    } else if (status == FRICREG_ENOMEM) {
        fr_ctx_drop_workspace(ctx); /* whatever failed half way is not kept */
        fail_as(ctx, status, who, "no memory for the dense Newton matrix");
    }
    return status;
}

int fricreg_ctx_solve_step(fricreg_ctx *ctx, size_t m, const double zdot_start[],
                           const double zdot_pred[], const double a_pred[], const double W[],
                           const double Weff[], double c, double tol, int max_iter, int flags,
                           double f[], int info[])
{
    if (ctx == NULL)
        return FRICREG_ENULL;
    if (W == NULL || Weff == NULL)
        return fail(ctx, FRICREG_ENULL, "a required array is NULL");
    int status = check_arguments(ctx, "solve_step", m, zdot_start, zdot_pred, a_pred, c, tol,
                                 max_iter, flags, f, info);
    if (status != FRICREG_OK)
        return status;
    status = check_matrix(W, m);
    int status_eff = check_matrix(Weff, m);
    if (!all_finite(zdot_start, m) || !all_finite(zdot_pred, m) || !all_finite(a_pred, m) ||
        !all_finite(f, m) || status == FRICREG_ENONFINITE || status_eff == FRICREG_ENONFINITE)
        return fail(ctx, FRICREG_ENONFINITE, "an input array holds NaN or infinity");
    if (status == FRICREG_OK)
        status = status_eff;
    if (status != FRICREG_OK)
        return fail(ctx, status,
                    status == FRICREG_ENOTSYM ? "W or W_eff is not symmetric"
                                              : "W or W_eff has a diagonal entry below DBL_MIN");
    for (size_t i = 0; i < m; i++)
        if ((status = check_coupling_diagonal(ctx, "solve_step", i, W[i * m + i])) != FRICREG_OK)
            return status;

    struct step_inputs in = {W, Weff, NULL, NULL};
    struct step_solver *s = solver_for(ctx, m, &in);
    if (s == NULL)
        return fail(ctx, FRICREG_ENOMEM, "no memory");
    return run(ctx, s, "solve_step", zdot_start, zdot_pred, a_pred, c, tol, max_iter, flags, f,
               info);
}

/* The compressed inputs' values summed, checked as the dense call's and stored in s. */
static int store_compressed(fricreg_ctx *ctx, struct step_solver *s, const struct step_inputs *in,
                            const char *who)
{
    size_t i = 0, j = 0, ie = 0, je = 0;
    int status = fr_step_pattern_values(&s->pw, in->sw, s->W, &i, &j);
    int status_eff = fr_step_pattern_values(&s->pweff, in->sweff, s->Weff, &ie, &je);
    const char *name = status != FRICREG_OK ? "W" : "W_eff";
    if (status == FRICREG_OK) {
        status = status_eff;
        i = ie;
        j = je;
    }
    long long base = (in->sw->flags & FRICREG_SPARSE_ONE_BASED) ? 1 : 0;
    if (status == FRICREG_ENOTPSD)
        return fr_error_set(fr_ctx_error(ctx), status,
                            "%s: %s(%lld, %lld) is missing or below DBL_MIN", who, name,
                            (long long)i + base, (long long)i + base);
    if (status == FRICREG_ENOTSYM)
        return fr_error_set(fr_ctx_error(ctx), status,
                            "%s: %s(%lld, %lld) and %s(%lld, %lld) differ: not symmetric", who,
                            name, (long long)i + base, (long long)j + base, name,
                            (long long)j + base, (long long)i + base);
    for (size_t k = 0; k < s->m; k++)
        if ((status = check_coupling_diagonal(ctx, who, k,
                                              fr_step_pattern_diagonal(&s->pw, s->W, k))) !=
            FRICREG_OK)
            return status;
    fr_step_pattern_store(&s->pw, s->W);
    if (fr_step_pattern_store(&s->pweff, s->Weff))
        s->nm.block.held = 0; /* the factor held is of the old values */
    return FRICREG_OK;
}

/* The _csr and _csc entries: the arrays checked as the coupling setters check theirs
 * (fr_compressed_check), the values as the dense call's. */
static int solve_step_compressed(fricreg_ctx *ctx, size_t m, int by_columns,
                                 const double zdot_start[], const double zdot_pred[],
                                 const double a_pred[], int sparse_flags, const int64_t w_ptr[],
                                 const int64_t w_ind[], const double w_values[],
                                 const int64_t weff_ptr[], const int64_t weff_ind[],
                                 const double weff_values[], double c, double tol, int max_iter,
                                 int flags, double f[], int info[], const char *who)
{
    if (ctx == NULL)
        return FRICREG_ENULL;
    int status = check_arguments(ctx, who, m, zdot_start, zdot_pred, a_pred, c, tol, max_iter,
                                 flags, f, info);
    if (status != FRICREG_OK)
        return status;
    struct fr_compressed sw = {m, m, by_columns, sparse_flags, w_ptr, w_ind, w_values};
    struct fr_compressed sweff = {m, m, by_columns, sparse_flags, weff_ptr, weff_ind, weff_values};
    if ((status = fr_compressed_check(&sw, 1, fr_ctx_error(ctx), who)) != FRICREG_OK ||
        (status = fr_compressed_check(&sweff, 1, fr_ctx_error(ctx), who)) != FRICREG_OK)
        return status;
    if (!all_finite(zdot_start, m) || !all_finite(zdot_pred, m) || !all_finite(a_pred, m) ||
        !all_finite(f, m))
        return fail_as(ctx, FRICREG_ENONFINITE, who, "an input array holds NaN or infinity");

    struct step_inputs in = {NULL, NULL, &sw, &sweff};
    struct step_solver *s = solver_for(ctx, m, &in);
    if (s == NULL)
        return fail_as(ctx, FRICREG_ENOMEM, who, "no memory");
    if ((status = store_compressed(ctx, s, &in, who)) != FRICREG_OK)
        return status;
    return run(ctx, s, who, zdot_start, zdot_pred, a_pred, c, tol, max_iter, flags, f, info);
}

int fricreg_ctx_solve_step_csr(fricreg_ctx *ctx, size_t m, const double zdot_start[],
                               const double zdot_pred[], const double a_pred[], int sparse_flags,
                               const int64_t w_rowptr[], const int64_t w_colind[],
                               const double w_values[], const int64_t weff_rowptr[],
                               const int64_t weff_colind[], const double weff_values[], double c,
                               double tol, int max_iter, int flags, double f[], int info[])
{
    return solve_step_compressed(ctx, m, 0, zdot_start, zdot_pred, a_pred, sparse_flags, w_rowptr,
                                 w_colind, w_values, weff_rowptr, weff_colind, weff_values, c, tol,
                                 max_iter, flags, f, info, "solve_step_csr");
}

int fricreg_ctx_solve_step_matrix(fricreg_ctx *ctx, size_t m, const double zdot_start[],
                                  const double zdot_pred[], const double a_pred[], int format,
                                  const int64_t w_ptr[], const int64_t w_ind[],
                                  const double w_values[], const int64_t weff_ptr[],
                                  const int64_t weff_ind[], const double weff_values[], double c,
                                  double tol, int max_iter, int flags, double f[], int info[])
{
    if (ctx == NULL)
        return FRICREG_ENULL;
    int compressed = 0, by_columns = 0, sparse_flags = 0;
    int status = fr_matrix_format(format, &compressed, &by_columns, &sparse_flags,
                                  fr_ctx_error(ctx), "solve_step_matrix");
    if (status != FRICREG_OK)
        return status;
    if (!compressed)
        return fricreg_ctx_solve_step(ctx, m, zdot_start, zdot_pred, a_pred, w_values, weff_values,
                                      c, tol, max_iter, flags, f, info);
    return solve_step_compressed(ctx, m, by_columns, zdot_start, zdot_pred, a_pred, sparse_flags,
                                 w_ptr, w_ind, w_values, weff_ptr, weff_ind, weff_values, c, tol,
                                 max_iter, flags, f, info, "solve_step_matrix");
}

int fricreg_ctx_solve_step_csc(fricreg_ctx *ctx, size_t m, const double zdot_start[],
                               const double zdot_pred[], const double a_pred[], int sparse_flags,
                               const int64_t w_colptr[], const int64_t w_rowind[],
                               const double w_values[], const int64_t weff_colptr[],
                               const int64_t weff_rowind[], const double weff_values[], double c,
                               double tol, int max_iter, int flags, double f[], int info[])
{
    return solve_step_compressed(ctx, m, 1, zdot_start, zdot_pred, a_pred, sparse_flags, w_colptr,
                                 w_rowind, w_values, weff_colptr, weff_rowind, weff_values, c, tol,
                                 max_iter, flags, f, info, "solve_step_csc");
}
