/* SPDX-License-Identifier: GPL-3.0-or-later */
/* disk_factor.c — the reduced Hessian of the near-stick QP on W's block pattern and its
 * CHOLMOD LDL^T factor, or LAPACK's dense Cholesky one where that would fill (disk_factor.h). */
#include <limits.h>
#include <stdint.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/lapack.h"
#include "base/sparse_factor.h"
#include "disk_factor.h"
#include "disk_kind.h"
#include "fricreg.h"

#define PIVOT_RTOL 1e-12 /* d_k / H_kk of LDL^T, as the 1-D context's factor (docs/coupled.md) */
#define DENSE_FILL 0.5   /* dense where nnz(L) >= DENSE_FILL n (n + 1) / 2 (disk_factor.h) */

void fr_disk_factor_free(struct fr_disk_factor *F)
{
    if (F->A != NULL || F->L != NULL || F->B != NULL) {
        cholmod_l_free_sparse(&F->A, &F->c);
        cholmod_l_free_factor(&F->L, &F->c);
        cholmod_l_free_dense(&F->B, &F->c);
        cholmod_l_free_dense(&F->X, &F->c);
        cholmod_l_free_dense(&F->Y, &F->c);
        cholmod_l_free_dense(&F->E, &F->c);
    }
    fr_cholmod_finish(&F->c);
    free(F->order), free(F->pos), free(F->src), free(F->held);
    free(F->D), free(F->hd), free(F->bc), free(F->unk), free(F->at);
    memset(F, 0, sizeof *F);
}

/* ---- Set-up: order, pattern, analysis ----------------------------------------------------- */

/* The contacts' graph as CHOLMOD's upper pattern (block (i, j), i <= j, for each block of w),
 * and CHOLMOD's fill-reducing order of it into F->order. */
static int contact_order(struct fr_disk_factor *F, const struct fr_disk_coupling *w)
{
    size_t m = w->m, nnz = 0;
    for (size_t j = 0; j < m; j++)
        for (int64_t k = w->ptr[j]; k < w->ptr[j + 1] && w->col[k] <= (int64_t)j; k++)
            nnz++;
    cholmod_sparse *P = cholmod_l_allocate_sparse(m, m, nnz, 1, 1, 1, CHOLMOD_PATTERN, &F->c);
    if (P == NULL)
        return FRICREG_ENOMEM;
    SuiteSparse_long *Pp = P->p, *Pi = P->i, e = 0;
    for (size_t j = 0; j < m; j++) {
        Pp[j] = e;
        for (int64_t k = w->ptr[j]; k < w->ptr[j + 1] && w->col[k] <= (int64_t)j; k++)
            Pi[e++] = (SuiteSparse_long)w->col[k];
    }
    Pp[m] = e;
    F->c.nmethods = 1; /* AMD alone: CHOLMOD's default would fall back to another
                        * ordering when one runs out of memory, a different factor */
    F->c.method[0].ordering = CHOLMOD_AMD;
    F->c.supernodal = CHOLMOD_SIMPLICIAL;
    cholmod_factor *L0 = cholmod_l_analyze(P, &F->c);
    cholmod_l_free_sparse(&P, &F->c);
    if (L0 == NULL)
        return FRICREG_ENOMEM;
    const SuiteSparse_long *perm = L0->Perm;
    for (size_t p = 0; p < m; p++)
        F->order[p] = perm != NULL ? (int64_t)perm[p] : (int64_t)p;
    cholmod_l_free_factor(&L0, &F->c);
    for (size_t p = 0; p < m; p++)
        F->pos[F->order[p]] = (int64_t)p;
    return FRICREG_OK;
}

/* One stored block of A: its row position q and W's block index (row order[p], read
 * transposed). */
struct block_ref {
    int64_t q, k;
};

static int by_position(const void *a, const void *b)
{
    int64_t x = ((const struct block_ref *)a)->q, y = ((const struct block_ref *)b)->q;
    return (x > y) - (x < y);
}

/* The blocks (q <= p) of A's block column p, sorted, into refs; returns how many. */
static size_t column_blocks(const struct fr_disk_factor *F, const struct fr_disk_coupling *w,
                            size_t p, struct block_ref *refs)
{
    int64_t j = F->order[p];
    size_t n = 0;
    for (int64_t k = w->ptr[j]; k < w->ptr[j + 1]; k++) {
        int64_t q = F->pos[w->col[k]];
        if (q <= (int64_t)p)
            refs[n++] = (struct block_ref){q, k};
    }
    qsort(refs, n, sizeof *refs, by_position);
    return n;
}

/* A's pattern (2m x 2m, upper, sorted): block column p holds, for each block q < p, rows
 * 2q, 2q+1 in both its columns, then the diagonal block's upper triangle; and src. */
static int pattern(struct fr_disk_factor *F, const struct fr_disk_coupling *w,
                   struct block_ref *refs)
{
    size_t m = w->m, nbu = 0;
    for (size_t j = 0; j < m; j++)
        for (int64_t k = w->ptr[j]; k < w->ptr[j + 1]; k++)
            nbu += F->pos[w->col[k]] <= F->pos[j];
    F->src = malloc(nbu * sizeof *F->src);
    F->A = cholmod_l_allocate_sparse(2 * m, 2 * m, 4 * nbu - m, 1, 1, 1, CHOLMOD_REAL, &F->c);
    if (F->src == NULL || F->A == NULL)
        return FRICREG_ENOMEM;
    SuiteSparse_long *Ap = F->A->p, *Ai = F->A->i, e = 0;
    int64_t s = 0;
    for (size_t p = 0; p < m; p++) {
        size_t n = column_blocks(F, w, p, refs);
        for (int b = 0; b < 2; b++) {
            Ap[2 * p + (size_t)b] = e;
            for (size_t t = 0; t < n; t++) {
                SuiteSparse_long q = (SuiteSparse_long)refs[t].q;
                Ai[e++] = 2 * q;
                if (q < (SuiteSparse_long)p || b == 1)
                    Ai[e++] = 2 * q + 1;
            }
        }
        for (size_t t = 0; t < n; t++)
            F->src[s++] = refs[t].k;
    }
    Ap[2 * m] = e;
    return FRICREG_OK;
}

/* CHOLMOD's analysis of the pre-ordered A as it is (natural ordering, no postorder),
 * simplicial LDL^T, factored in place (final_asis): what makes refactorizations
 * allocation-free (cholmod_factorize's natural branch reads A, no permuted copy). */
static int analyse(struct fr_disk_factor *F)
{
    F->c.nmethods = 1;
    F->c.method[0].ordering = CHOLMOD_NATURAL;
    F->c.postorder = 0;
    F->c.supernodal = CHOLMOD_SIMPLICIAL;
    F->c.final_ll = 0;
    F->c.final_asis = 1;
    F->L = cholmod_l_analyze(F->A, &F->c);
    if (F->L == NULL)
        return FRICREG_ENOMEM;
    return F->L->ordering == CHOLMOD_NATURAL && !F->L->is_super ? FRICREG_OK : FRICREG_EINVAL;
}

/* The storage the fill rule gives the analysed factor (F->L's column counts), or the one
 * asked; dense needs its order to fit LAPACK's int and its n^2 doubles a size_t. */
static int storage_is_dense(const struct fr_disk_factor *F, enum fr_disk_storage storage)
{
    size_t n = 2 * F->m;
    int fits = n <= (size_t)INT_MAX && n <= SIZE_MAX / n / sizeof(double);
    if (storage != FR_DISK_STORAGE_CHOSEN || !fits)
        return storage == FR_DISK_STORAGE_DENSE && fits;
    double lnz = 0.0;
    for (size_t j = 0; j < n; j++)
        lnz += (double)((const SuiteSparse_long *)F->L->ColCount)[j];
    return lnz >= DENSE_FILL * (double)n * ((double)n + 1.0) / 2.0;
}

static int dense_allocate(struct fr_disk_factor *F)
{
    size_t n = 2 * F->m;
    F->D = malloc(n * n * sizeof *F->D);
    F->hd = malloc(n * sizeof *F->hd);
    F->bc = malloc(n * sizeof *F->bc);
    F->unk = malloc(n * sizeof *F->unk);
    F->at = malloc(n * sizeof *F->at);
    return F->D && F->hd && F->bc && F->unk && F->at ? FRICREG_OK : FRICREG_ENOMEM;
}

int fr_disk_factor_setup(struct fr_disk_factor *F, const struct fr_disk_coupling *w,
                         enum fr_disk_storage storage)
{
    size_t m = w->m, longest = 1;
    memset(F, 0, sizeof *F);
    if (fr_cholmod_start(&F->c) != FRICREG_OK)
        return FRICREG_ENOMEM;
    F->m = m;
    for (size_t i = 0; i < m; i++)
        if ((size_t)(w->ptr[i + 1] - w->ptr[i]) > longest)
            longest = (size_t)(w->ptr[i + 1] - w->ptr[i]);
    F->order = malloc(m * sizeof *F->order);
    F->pos = malloc(m * sizeof *F->pos);
    F->held = malloc(m * sizeof *F->held);
    struct block_ref *refs = malloc(longest * sizeof *refs);
    int status = FRICREG_ENOMEM;
    if (F->order && F->pos && F->held && refs && contact_order(F, w) == FRICREG_OK &&
        pattern(F, w, refs) == FRICREG_OK) {
        status = analyse(F);
        F->dense = status == FRICREG_OK && storage_is_dense(F, storage);
        if (F->dense)
            status = dense_allocate(F);
        F->B = status == FRICREG_OK ? cholmod_l_zeros(2 * m, 1, CHOLMOD_REAL, &F->c) : NULL;
        if (status == FRICREG_OK && F->B == NULL)
            status = FRICREG_ENOMEM;
    }
    free(refs);
    if (status == FRICREG_OK) { /* the identity: L numeric, CHOLMOD's buffers allocated */
        memset(F->held, FR_DISK_FIXED, m);
        size_t pivot;
        status = fr_disk_factor_build(F, w, F->held, NULL, NULL, &pivot);
        if (status == FRICREG_OK)
            status = fr_disk_factor_solve(F, F->B->x, F->B->x);
        if (status != FRICREG_OK)
            status = FRICREG_ENOMEM;
    }
    if (status != FRICREG_OK)
        fr_disk_factor_free(F);
    return status;
}

/* ---- Assembly and factorization ----------------------------------------------------------- */

/* Contact i's frame Q (row-major: columns n and t for a circle, else the identity) and which
 * of its two unknowns are coupled. */
static void frame(signed char kind, const double *n, double Q[4], int coupled[2])
{
    if (kind == FR_DISK_CIRCLE) {
        Q[0] = n[0], Q[1] = -n[1], Q[2] = n[1], Q[3] = n[0];
    } else {
        Q[0] = 1.0, Q[1] = 0.0, Q[2] = 0.0, Q[3] = 1.0;
    }
    coupled[0] = kind == FR_DISK_FREE;
    coupled[1] = kind != FR_DISK_FIXED;
}

/* H = Qi^T M Qj, all 2x2 row-major. */
static void congruence(const double Qi[4], const double M[4], const double Qj[4], double H[4])
{
    double T[4]; /* M Qj */
    T[0] = M[0] * Qj[0] + M[1] * Qj[2], T[1] = M[0] * Qj[1] + M[1] * Qj[3];
    T[2] = M[2] * Qj[0] + M[3] * Qj[2], T[3] = M[2] * Qj[1] + M[3] * Qj[3];
    H[0] = Qi[0] * T[0] + Qi[2] * T[2], H[1] = Qi[0] * T[1] + Qi[2] * T[3];
    H[2] = Qi[1] * T[0] + Qi[3] * T[2], H[3] = Qi[1] * T[1] + Qi[3] * T[3];
}

/* The block H_ij of positions (q, p), masked: decoupled unknowns keep only a unit diagonal. */
static void reduced_block(const struct fr_disk_factor *F, const struct fr_disk_coupling *w,
                          int64_t k, int64_t q, int64_t p, const signed char kind[],
                          const double n[], const double lam[], double H[4])
{
    int64_t i = F->order[q], j = F->order[p];
    const double *b = w->blk + 4 * k; /* W_ji: W_ij is its transpose */
    double M[4] = {b[0], b[2], b[1], b[3]}, Qi[4], Qj[4];
    int ci[2], cj[2];
    if (i == j && kind[i] == FR_DISK_CIRCLE)
        M[0] += lam[i], M[3] += lam[i];
    frame(kind[i], n != NULL ? n + 2 * i : NULL, Qi, ci);
    frame(kind[j], n != NULL ? n + 2 * j : NULL, Qj, cj);
    congruence(Qi, M, Qj, H);
    for (int a = 0; a < 2; a++)
        for (int c = 0; c < 2; c++)
            if (!ci[a] || !cj[c])
                H[2 * a + c] = (i == j && a == c) ? 1.0 : 0.0;
}

/* A's values for the kinds, frames and multipliers given. */
static void assemble(struct fr_disk_factor *F, const struct fr_disk_coupling *w,
                     const signed char kind[], const double n[], const double lam[])
{
    const SuiteSparse_long *Ap = F->A->p, *Ai = F->A->i;
    double *Ax = F->A->x;
    int64_t s = 0;
    for (size_t p = 0; p < F->m; p++) {
        SuiteSparse_long e0 = Ap[2 * p], e1 = Ap[2 * p + 1];
        size_t nq = (size_t)(e1 - e0 - 1) / 2; /* blocks above the diagonal */
        for (size_t t = 0; t <= nq; t++, s++) {
            double H[4];
            int64_t q = t < nq ? (int64_t)(Ai[e0 + 2 * t] / 2) : (int64_t)p;
            reduced_block(F, w, F->src[s], q, (int64_t)p, kind, n, lam, H);
            Ax[e0 + 2 * t] = H[0];
            Ax[e1 + 2 * t] = H[1];
            if (t < nq)
                Ax[e0 + 2 * t + 1] = H[2];
            Ax[e1 + 2 * t + 1] = H[3];
        }
    }
}

/* The pivot test of the LDL^T just computed: FRICREG_OK or FRICREG_ESINGULAR (*pivot the
 * contact of the first failing unknown). */
static int check_pivots(const struct fr_disk_factor *F, size_t *pivot)
{
    const SuiteSparse_long *Lp = F->L->p, *Ap = F->A->p;
    const double *Lx = F->L->x, *Ax = F->A->x;
    size_t n = 2 * F->m, bad = (size_t)F->L->minor; /* a zero pivot stopped CHOLMOD there */
    for (size_t k = 0; k < n && k < bad; k++) {
        double d = Lx[Lp[k]], hkk = Ax[Ap[k + 1] - 1]; /* diagonals: first in L, last in A */
        if (!(d > PIVOT_RTOL * hkk))
            bad = k;
    }
    if (bad >= n)
        return FRICREG_OK;
    *pivot = (size_t)F->order[bad / 2];
    return FRICREG_ESINGULAR;
}

/* Dense: the coupled unknowns of the kinds (position order) numbered into F->unk, F->at. */
static void number_coupled(struct fr_disk_factor *F, const signed char kind[])
{
    F->nc = 0;
    for (size_t u = 0; u < 2 * F->m; u++) {
        signed char k = kind[F->order[u / 2]];
        int coupled = u % 2 == 0 ? k == FR_DISK_FREE : k != FR_DISK_FIXED; /* frame()'s */
        F->at[u] = coupled ? (int64_t)F->nc : -1;
        if (coupled)
            F->unk[F->nc++] = (int64_t)u;
    }
}

/* Dense: A's entries among the coupled unknowns into F->D (upper, column-major, order nc) and
 * their diagonal into F->hd; dpotrf; the pivot test of check_pivots on U_cc^2. */
static int dense_factor(struct fr_disk_factor *F, size_t *pivot)
{
    const SuiteSparse_long *Ap = F->A->p, *Ai = F->A->i;
    const double *Ax = F->A->x;
    size_t nc = F->nc;
    for (size_t c = 0; c < nc; c++)
        memset(F->D + c * nc, 0, (c + 1) * sizeof *F->D);
    for (size_t k = 0; k < 2 * F->m; k++) {
        int64_t col = F->at[k];
        if (col < 0)
            continue;
        for (SuiteSparse_long e = Ap[k]; e < Ap[k + 1]; e++) {
            int64_t row = F->at[Ai[e]];
            if (row >= 0)
                F->D[(size_t)row + (size_t)col * nc] = Ax[e];
        }
        F->hd[col] = Ax[Ap[k + 1] - 1]; /* the diagonal: last in A's column */
    }
    int order = (int)nc, info = 0;
    if (nc > 0)
        dpotrf_("U", &order, F->D, &order, &info, 1);
    size_t bad = info > 0 ? (size_t)info - 1 : nc; /* a pivot <= 0 stopped dpotrf there */
    for (size_t c = 0; c < bad; c++) {
        double u = F->D[c * (nc + 1)];
        if (!(u * u > PIVOT_RTOL * F->hd[c]))
            bad = c;
    }
    if (bad >= nc)
        return FRICREG_OK;
    *pivot = (size_t)F->order[F->unk[bad] / 2];
    return FRICREG_ESINGULAR;
}

int fr_disk_factor_build(struct fr_disk_factor *F, const struct fr_disk_coupling *w,
                         const signed char kind[], const double n[], const double lam[],
                         size_t *pivot)
{
    int circle = 0;
    for (size_t i = 0; i < F->m; i++) {
        F->held[i] = kind[i];
        circle |= kind[i] == FR_DISK_CIRCLE;
    }
    F->reusable = 0;
    assemble(F, w, kind, n, lam);
    int status;
    if (F->dense) {
        number_coupled(F, kind);
        status = dense_factor(F, pivot);
    } else {
        cholmod_l_factorize(F->A, F->L, &F->c); /* a zero pivot ends it early: L->minor */
        if (F->L->xtype == CHOLMOD_PATTERN)     /* only at set-up: later ones allocate nothing */
            return FRICREG_ENOMEM;
        status = check_pivots(F, pivot);
    }
    F->reusable = status == FRICREG_OK && !circle;
    return status;
}

int fr_disk_factor_holds(const struct fr_disk_factor *F, const signed char kind[])
{
    if (!F->reusable)
        return 0;
    for (size_t i = 0; i < F->m; i++)
        if (F->held[i] != kind[i] || kind[i] == FR_DISK_CIRCLE)
            return 0;
    return 1;
}

/* CHOLMOD's simplicial solve asks for its buffer Y as 4 x n (cholmod_ensure_dense: up to 4
 * right-hand sides at a time), then sets Y's shape to the 1 x n it used; the next call finds
 * the shape changed and frees and allocates Y again. Its shape put back (the struct is
 * cholmod_core.h's; Y holds 4n doubles), every later solve reuses it and allocates nothing. */
static void keep_solve_buffer(struct fr_disk_factor *F)
{
    cholmod_dense *Y = F->Y;
    size_t n = 2 * F->m;
    if (Y != NULL && Y->ncol == n && Y->nrow == 1 && Y->d == 1 && Y->nzmax >= 4 * n)
        Y->nrow = Y->d = 4;
}

/* Dense: b (position order) solved in place, the decoupled unknowns' unit rows as they are.
 * dpotrs's two triangles, each by dtrsv: with one right-hand side OpenBLAS 0.3.21's dpotrs
 * goes through dtrsm, which copies the factor first (3-5x slower from order 100 to 2000); on
 * the reference BLAS both take the same time. */
static void dense_solve(struct fr_disk_factor *F, double b[])
{
    size_t nc = F->nc;
    for (size_t c = 0; c < nc; c++)
        F->bc[c] = b[F->unk[c]];
    int order = (int)nc, one = 1;
    if (nc > 0) {
        dtrsv_("U", "T", "N", &order, F->D, &order, F->bc, &one, 1, 1, 1);
        dtrsv_("U", "N", "N", &order, F->D, &order, F->bc, &one, 1, 1, 1);
    }
    for (size_t c = 0; c < nc; c++)
        b[F->unk[c]] = F->bc[c];
}

int fr_disk_factor_solve(struct fr_disk_factor *F, const double rhs[], double x[])
{
    double *b = F->B->x;
    for (size_t p = 0; p < F->m; p++) {
        int64_t i = F->order[p];
        b[2 * p] = rhs[2 * i];
        b[2 * p + 1] = rhs[2 * i + 1];
    }
    const double *y = b;
    if (F->dense) {
        dense_solve(F, b);
    } else {
        if (!cholmod_l_solve2(CHOLMOD_LDLt, F->L, F->B, NULL, &F->X, NULL, &F->Y, &F->E, &F->c))
            return FRICREG_ENOMEM;
        keep_solve_buffer(F);
        y = F->X->x;
    }
    for (size_t p = 0; p < F->m; p++) {
        int64_t i = F->order[p];
        x[2 * i] = y[2 * p];
        x[2 * i + 1] = y[2 * p + 1];
    }
    return FRICREG_OK;
}

/* ---- The set-up's semidefiniteness check -------------------------------------------------- */

int fr_disk_factor_scaled_pd(struct fr_disk_factor *F, const struct fr_disk_coupling *w,
                             double shift)
{
    const SuiteSparse_long *Ap = F->A->p, *Ai = F->A->i;
    double *Ax = F->A->x;
    F->reusable = 0;
    memset(F->held, FR_DISK_FREE, F->m);
    assemble(F, w, F->held, NULL, NULL); /* W itself */
    for (size_t k = 0; k < 2 * F->m; k++) {
        double dk = Ax[Ap[k + 1] - 1]; /* diagonal blocks are positive definite: dk > 0 */
        for (SuiteSparse_long e = Ap[k]; e < Ap[k + 1] - 1; e++) {
            double di = Ax[Ap[Ai[e] + 1] - 1];
            Ax[e] = Ax[e] / sqrt(di) / sqrt(dk);
        }
    }
    /* the diagonal, 1 + shift, once every off-diagonal entry has read it */
    for (size_t k = 0; k < 2 * F->m; k++)
        Ax[Ap[k + 1] - 1] = 1.0 + shift;
    cholmod_l_factorize(F->A, F->L, &F->c);
    if (F->L->xtype == CHOLMOD_PATTERN)
        return -1;
    const SuiteSparse_long *Lp = F->L->p;
    const double *Lx = F->L->x;
    if ((size_t)F->L->minor < 2 * F->m)
        return 0;
    for (size_t k = 0; k < 2 * F->m; k++)
        if (!(Lx[Lp[k]] > 0.0))
            return 0;
    return 1;
}
