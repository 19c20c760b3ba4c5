/* SPDX-License-Identifier: GPL-3.0-or-later */
/* contact_sparse.c — the near-stick block solved through K_eff + J^T T J (contact_sparse.h). */
#include <math.h>
#include <string.h>

#include "base/sparse_factor.h"
#include "base/sparse_ops.h"
#include "contact_factor.h"
#include "contact_sparse.h"
#include "masked_factor.h"
#include "fricreg.h"

/* The regularization of a row without a shift, relative to its W_eff,ii: sqrt(u), between
 * the refinement's rate (RHO) and the cancellation's rounding (u / RHO). */
#define RHO 0x1p-26
/* The refinement stops when the residual of the block's equations is below REFINE_STOP times
 * the right-hand side (rounding: dpotrf's backward error is about m u), or when it no longer
 * halves (at the rounding of W_eff y), or after REFINE_MAX corrections; a residual then above
 * REFINE_FAIL times the right-hand side means a singular block (W_eff,NN's smallest eigenvalue
 * below about RHO W_eff,ii). A correction costs a solve with the factor of K_eff + J^T T J and
 * a product with W_eff: two in all, typically (the first leaves the regularization's error,
 * about RHO). */
#define REFINE_STOP 0x1p-43
#define REFINE_MAX 30
/* A chord (the factor of other shifts on the same rows) is refined at most this many times
 * before the block is refactored: each correction costs a tenth of a refactorization, or less
 * (a stiff membrane of 10^5 unknowns). */
#define CHORD_MAX 6
#define REFINE_FAIL 1e-8

static size_t nnz_of(const cholmod_sparse *A, size_t ncol)
{
    return A ? (size_t)((const SuiteSparse_long *)A->p)[ncol] : 0;
}

void fr_contact_sparse_free(struct fr_contact_sparse *f, cholmod_common *c)
{
    size_t nnz = nnz_of(f->A, f->n), np = f->pptr ? (size_t)f->pptr[f->m] : 0;
    cholmod_l_free(nnz, sizeof *f->base, f->base, c);
    cholmod_l_free(f->pptr ? f->m + 1 : 0, sizeof *f->pptr, f->pptr, c);
    cholmod_l_free(np, sizeof *f->pos, f->pos, c);
    cholmod_l_free(np, sizeof *f->val, f->val, c);
    cholmod_l_free(f->n, sizeof *f->perm, f->perm, c);
    double **mv[] = {&f->t, &f->y, &f->res, &f->dy, &f->u, &f->e, &f->held_shift};
    for (size_t k = 0; k < sizeof mv / sizeof *mv; k++)
        cholmod_l_free(f->m, sizeof **mv[k], *mv[k], c);
    cholmod_l_free(f->n, sizeof *f->v, f->v, c);
    cholmod_l_free(f->n, sizeof *f->w, f->w, c);
    cholmod_l_free(f->n, sizeof *f->pv, f->pv, c);
    cholmod_l_free(f->m, sizeof *f->held_set, f->held_set, c);
    cholmod_l_free_sparse(&f->A, c);
    cholmod_l_free_factor(&f->L, c);
    cholmod_l_free_dense(&f->X, c);
    cholmod_l_free_dense(&f->Yw, c);
    cholmod_l_free_dense(&f->Ew, c);
    memset(f, 0, sizeof *f);
}

/* The upper triangle of K_eff + J^T J's pattern (values: K_eff's plus J^T J's, unused). */
static cholmod_sparse *union_pattern(const cholmod_sparse *Keff, const cholmod_sparse *Jt,
                                     cholmod_common *c)
{
    cholmod_sparse *JJ = cholmod_l_aat((cholmod_sparse *)Jt, NULL, 0, 1, c), *JJu = NULL, *U = NULL;
    if (JJ != NULL)
        JJu = cholmod_l_copy(JJ, 1, 1, c);
    if (JJu != NULL)
        U = cholmod_l_add((cholmod_sparse *)Keff, JJu, (double[2]){1.0, 0.0}, (double[2]){1.0, 0.0},
                          1, 1, c);
    cholmod_l_free_sparse(&JJ, c);
    cholmod_l_free_sparse(&JJu, c);
    return U;
}

/* A fill-reducing order of U (as contact_factor.c orders K_eff) into f->perm. */
static int order(struct fr_contact_sparse *f, cholmod_sparse *U, cholmod_common *c)
{
    fr_cholmod_ordering(c, f->n >= FR_CFACTOR_NESTED_FROM ? CHOLMOD_NESDIS : CHOLMOD_AMD, 0);
    cholmod_factor *L = cholmod_l_analyze(U, c);
    f->perm = cholmod_l_malloc(f->n, sizeof *f->perm, c);
    int ok = L != NULL && f->perm != NULL;
    if (ok)
        memcpy(f->perm, L->Perm, f->n * sizeof *f->perm);
    cholmod_l_free_factor(&L, c);
    return ok;
}

/* f->A = the upper triangle of P U P^T, and at[e] its entry of U's entry e: the permutation
 * is done on a copy of U whose values are its entries' own positions (masked_factor.c). */
static int permute(struct fr_contact_sparse *f, const cholmod_sparse *U, SuiteSparse_long at[],
                   cholmod_common *c)
{
    size_t nnz = nnz_of(U, f->n);
    cholmod_sparse *index = cholmod_l_copy_sparse((cholmod_sparse *)U, c), *full = NULL, *P = NULL;
    if (index != NULL) {
        for (size_t p = 0; p < nnz; p++)
            ((double *)index->x)[p] = (double)p;
        full = cholmod_l_copy(index, 0, 1, c);
    }
    if (full != NULL)
        P = cholmod_l_submatrix(full, f->perm, (SuiteSparse_long)f->n, f->perm,
                                (SuiteSparse_long)f->n, 1, 1, c);
    if (P != NULL)
        f->A = cholmod_l_copy(P, 1, 1, c);
    cholmod_l_free_sparse(&index, c);
    cholmod_l_free_sparse(&full, c);
    cholmod_l_free_sparse(&P, c);
    if (f->A == NULL)
        return 0;
    const double *ax = f->A->x;
    for (size_t q = 0; q < nnz_of(f->A, f->n); q++)
        at[(SuiteSparse_long)ax[q]] = (SuiteSparse_long)q;
    return 1;
}

/* K_eff's values into f->base, in A's layout. */
static int base_values(struct fr_contact_sparse *f, const cholmod_sparse *Keff,
                       const cholmod_sparse *U, const SuiteSparse_long at[], cholmod_common *c)
{
    size_t nnz = nnz_of(f->A, f->n);
    f->base = cholmod_l_calloc(nnz > 0 ? nnz : 1, sizeof *f->base, c);
    if (f->base == NULL)
        return 0;
    const SuiteSparse_long *Kp = Keff->p, *Ki = Keff->i;
    const double *Kx = Keff->x;
    for (SuiteSparse_long j = 0; j < (SuiteSparse_long)f->n; j++)
        for (SuiteSparse_long p = Kp[j]; p < Kp[j + 1]; p++)
            if (Ki[p] <= j)
                f->base[at[fr_csc_position(U, Ki[p], j)]] += Kx[p];
    return 1;
}

/* Each contact's products J_ai J_bi, a <= b, and their entries of A. */
static int products(struct fr_contact_sparse *f, const cholmod_sparse *U,
                    const SuiteSparse_long at[], cholmod_common *c)
{
    const SuiteSparse_long *Jp = f->Jt->p, *Ji = f->Jt->i;
    const double *Jx = f->Jt->x;
    f->pptr = cholmod_l_malloc(f->m + 1, sizeof *f->pptr, c);
    if (f->pptr == NULL)
        return 0;
    f->pptr[0] = 0;
    for (size_t i = 0; i < f->m; i++) {
        SuiteSparse_long k = Jp[i + 1] - Jp[i];
        f->pptr[i + 1] = f->pptr[i] + k * (k + 1) / 2;
    }
    size_t np = (size_t)f->pptr[f->m];
    f->pos = cholmod_l_malloc(np > 0 ? np : 1, sizeof *f->pos, c);
    f->val = cholmod_l_malloc(np > 0 ? np : 1, sizeof *f->val, c);
    if (f->pos == NULL || f->val == NULL)
        return 0;
    for (size_t i = 0; i < f->m; i++) {
        SuiteSparse_long q = f->pptr[i];
        for (SuiteSparse_long p = Jp[i]; p < Jp[i + 1]; p++)
            for (SuiteSparse_long r = p; r < Jp[i + 1]; r++, q++) {
                SuiteSparse_long a = Ji[p] < Ji[r] ? Ji[p] : Ji[r];
                SuiteSparse_long b = Ji[p] < Ji[r] ? Ji[r] : Ji[p];
                f->pos[q] = at[fr_csc_position(U, a, b)];
                /* a repeated row of J: its cross term lands on the diagonal twice */
                f->val[q] = Jx[p] * Jx[r] * (a == b && p != r ? 2.0 : 1.0);
            }
    }
    return 1;
}

static int vectors(struct fr_contact_sparse *f, cholmod_common *c)
{
    size_t m = f->m > 0 ? f->m : 1;
    double **mv[] = {&f->t, &f->y, &f->res, &f->dy, &f->u, &f->e, &f->held_shift};
    int ok = 1;
    for (size_t k = 0; k < sizeof mv / sizeof *mv; k++)
        ok &= (*mv[k] = cholmod_l_calloc(m, sizeof **mv[k], c)) != NULL;
    f->v = cholmod_l_calloc(f->n, sizeof *f->v, c);
    f->w = cholmod_l_calloc(f->n, sizeof *f->w, c);
    f->pv = cholmod_l_calloc(f->n, sizeof *f->pv, c);
    f->held_set = cholmod_l_calloc(m, 1, c);
    return ok && f->v && f->w && f->pv && f->held_set;
}

/* A's values for the rows' T (f->t), and its factor. */
static int refactor(struct fr_contact_sparse *f, cholmod_common *c)
{
    double *Ax = f->A->x;
    memcpy(Ax, f->base, nnz_of(f->A, f->n) * sizeof *Ax);
    for (size_t i = 0; i < f->m; i++)
        if (f->t[i] != 0.0)
            for (SuiteSparse_long q = f->pptr[i]; q < f->pptr[i + 1]; q++)
                Ax[f->pos[q]] += f->t[i] * f->val[q];
    if (!cholmod_l_factorize(f->A, f->L, c) || c->status < CHOLMOD_OK)
        return FRICREG_ENOMEM;
    return c->status == CHOLMOD_NOT_POSDEF ? FRICREG_ESINGULAR : FRICREG_OK;
}

/* w = (K_eff + J^T T J)^-1 v, both [n] in the structure's order. */
static int sparse_solve(struct fr_contact_sparse *f, const double v[], double w[],
                        cholmod_common *c)
{
    double *pv = f->pv;
    for (size_t k = 0; k < f->n; k++)
        pv[k] = v[f->perm[k]];
    cholmod_dense B = {.nrow = f->n,
                       .ncol = 1,
                       .nzmax = f->n,
                       .d = f->n,
                       .x = pv,
                       .xtype = CHOLMOD_REAL,
                       .dtype = CHOLMOD_DOUBLE};
    fr_cholmod_keep_workspace(f->Yw);
    if (!cholmod_l_solve2(CHOLMOD_A, f->L, &B, NULL, &f->X, NULL, &f->Yw, &f->Ew, c))
        return FRICREG_ENOMEM;
    const double *sol = f->X->x;
    for (size_t k = 0; k < f->n; k++)
        w[f->perm[k]] = sol[k];
    return FRICREG_OK;
}

/* The factor's analysis in the natural order: A is permuted already, and CHOLMOD factors its
 * upper triangle in place, simplicial (a supernodal factorization allocates its update matrix
 * at every call, and on the benchmark's membranes costs as much: docs/benchmark.md). The flop
 * count is kept (Common->fl). */
static int analyse(struct fr_contact_sparse *f, cholmod_common *c)
{
    fr_cholmod_ordering(c, CHOLMOD_NATURAL, 1);
    f->L = cholmod_l_analyze(f->A, c);
    f->flops = c->fl;
    return f->L != NULL;
}

int fr_contact_sparse_prepare(struct fr_contact_sparse *f, const cholmod_sparse *Keff,
                              const cholmod_sparse *Jt, cholmod_common *c)
{
    memset(f, 0, sizeof *f);
    f->n = Keff->ncol;
    f->m = Jt->ncol;
    f->Jt = Jt;
    cholmod_sparse *U = union_pattern(Keff, Jt, c);
    size_t unz = nnz_of(U, f->n);
    SuiteSparse_long *at = U ? cholmod_l_malloc(unz > 0 ? unz : 1, sizeof *at, c) : NULL;
    int ok = at != NULL && order(f, U, c) && permute(f, U, at, c) && analyse(f, c);
    ok = ok && base_values(f, Keff, U, at, c) && products(f, U, at, c) && vectors(f, c);
    cholmod_l_free(unz > 0 ? unz : 1, sizeof *at, at, c);
    cholmod_l_free_sparse(&U, c);
    /* T = 0 once: K_eff's factor, so that CHOLMOD sizes its storage and workspaces now */
    ok = ok && refactor(f, c) == FRICREG_OK && sparse_solve(f, f->v, f->w, c) == FRICREG_OK;
    if (!ok)
        fr_contact_sparse_free(f, c);
    return ok ? FRICREG_OK : FRICREG_ENOMEM;
}

/* The block and shifts of the factor held (masked_factor.h's rule). */
static int holds(const struct fr_contact_sparse *f, const unsigned char *set, const double *shift)
{
    return fr_block_is_held(f->m, f->held, f->held_set, f->held_shift, set, shift);
}

static void hold(struct fr_contact_sparse *f, const unsigned char *set, const double *shift)
{
    fr_block_hold(f->m, f->held_set, f->held_shift, set, shift);
    f->held = 1;
}

/* W_eff,ii: the last entry of column i of the sorted upper triangle, if it is the diagonal. */
static double diagonal(const cholmod_sparse *Weff, size_t i)
{
    const SuiteSparse_long *Wp = Weff->p, *Wi = Weff->i;
    SuiteSparse_long p = Wp[i + 1] - 1;
    return p >= Wp[i] && Wi[p] == (SuiteSparse_long)i ? ((const double *)Weff->x)[p] : 0.0;
}

/* T = 1 / s~ on the rows of set (contact_sparse.h), 0 off them; FRICREG_ESINGULAR where a row
 * without a shift has no positive W_eff,ii. */
static int rows_t(struct fr_contact_sparse *f, const cholmod_sparse *Weff, const unsigned char *set,
                  const double *shift)
{
    for (size_t i = 0; i < f->m; i++) {
        double s = shift ? shift[i] : 0.0;
        f->t[i] = 0.0;
        if (set == NULL || !set[i])
            continue;
        if (!(s > 0.0)) {
            double d = diagonal(Weff, i);
            if (!(d > 0.0))
                return FRICREG_ESINGULAR;
            s = RHO * d;
        }
        f->t[i] = 1.0 / s;
    }
    return FRICREG_OK;
}

/* dy = T (r - J (K_eff + J^T T J)^-1 J^T T r) on the rows of T (0 off them). */
static int woodbury(struct fr_contact_sparse *f, const double r[], double dy[], cholmod_common *c)
{
    for (size_t i = 0; i < f->m; i++)
        f->u[i] = f->t[i] * r[i];
    memset(f->v, 0, f->n * sizeof *f->v);
    fr_csc_mult_add(f->Jt, 1.0, f->u, f->v);
    int status = sparse_solve(f, f->v, f->w, c);
    if (status != FRICREG_OK)
        return status;
    fr_csc_mult_t(f->Jt, f->w, f->e);
    for (size_t i = 0; i < f->m; i++)
        dy[i] = f->t[i] * (r[i] - f->e[i]);
    return FRICREG_OK;
}

/* res = b - (W_eff + diag(shift)) y on the rows of set (0 off them), y = f->y; its largest
 * entry (infinite if not a number: the refinement then stops, singular). */
static double residual(struct fr_contact_sparse *f, const cholmod_sparse *Weff,
                       const unsigned char *set, const double *shift, const double b[])
{
    double *res = f->res, big = 0.0;
    fr_delassus_mult(Weff, -1.0, f->y, 0.0, res);
    for (size_t i = 0; i < f->m; i++) {
        res[i] = set && set[i] ? b[i] + res[i] - (shift ? shift[i] : 0.0) * f->y[i] : 0.0;
        big = isnan(res[i]) ? INFINITY : fmax(big, fabs(res[i]));
    }
    return big;
}

/* Refines f->y (its residual in f->res, of largest entry *rnorm) with the factor held, at most
 * max corrections: *done when the residual is below REFINE_STOP |b| (the answer), or when it
 * stalls (no longer halves) at most REFINE_FAIL |b| and stall_ok (rounding, on a fresh
 * factor). FRICREG_OK or the solve's failure. */
static int refine(struct fr_contact_sparse *f, const cholmod_sparse *Weff, const unsigned char *set,
                  const double *shift, const double b[], double bnorm, int max, int stall_ok,
                  double *rnorm, int *done, cholmod_common *c)
{
    double last = INFINITY;
    *done = 0;
    for (int k = 0;; k++) {
        if (*rnorm <= REFINE_STOP * bnorm) {
            *done = 1;
            return FRICREG_OK;
        }
        if (k == max || *rnorm >= 0.5 * last) { /* stalled */
            *done = stall_ok && *rnorm <= REFINE_FAIL * bnorm;
            return FRICREG_OK;
        }
        last = *rnorm;
        int status = woodbury(f, f->res, f->dy, c);
        if (status != FRICREG_OK)
            return status;
        for (size_t i = 0; i < f->m; i++)
            f->y[i] += f->dy[i];
        *rnorm = residual(f, Weff, set, shift, b);
    }
}

int fr_contact_sparse_hold(struct fr_contact_sparse *f, const cholmod_sparse *Weff,
                           const unsigned char *set, const double *shift, cholmod_common *c)
{
    f->held = 0;
    int status = rows_t(f, Weff, set, shift);
    if (status == FRICREG_OK && (status = refactor(f, c)) == FRICREG_OK)
        hold(f, set, shift);
    return status;
}

int fr_contact_sparse_solve(struct fr_contact_sparse *f, const cholmod_sparse *Weff,
                            const unsigned char *set, const double *shift, const double b[],
                            double x[], cholmod_common *c)
{
    /* the same rows with other shifts: the held factor first (a chord), refined against the
     * block; refactored if that does not converge within CHORD_MAX corrections */
    /* the held factor's rows are set's: its shifts may differ (a chord) */
    int fresh = !fr_block_holds_rows(f->m, f->held, f->held_set, set), status, done = 0;
    if (fresh && (status = fr_contact_sparse_hold(f, Weff, set, shift, c)) != FRICREG_OK)
        return status;
    fresh = fresh || holds(f, set, shift);
    size_t m = f->m;
    double bnorm = 0.0;
    memset(f->y, 0, m * sizeof *f->y);
    for (size_t i = 0; i < m; i++) {
        f->res[i] = set && set[i] ? b[i] : 0.0; /* at y = 0 */
        bnorm = fmax(bnorm, fabs(f->res[i]));
    }
    double rnorm = bnorm;
    status = refine(f, Weff, set, shift, b, bnorm, fresh ? REFINE_MAX : CHORD_MAX, fresh, &rnorm,
                    &done, c);
    if (status == FRICREG_OK && !done && !fresh &&
        (status = fr_contact_sparse_hold(f, Weff, set, shift, c)) == FRICREG_OK)
        status = refine(f, Weff, set, shift, b, bnorm, REFINE_MAX, 1, &rnorm, &done, c);
    if (status != FRICREG_OK)
        return status;
    if (!done)
        return FRICREG_ESINGULAR;
    for (size_t i = 0; i < m; i++)
        if (set && set[i])
            x[i] = f->y[i];
    return FRICREG_OK;
}
