/* SPDX-License-Identifier: GPL-3.0-or-later */
/* contact_factor.c — a CHOLMOD factor with the contacts seen through it (contact_factor.h).
 *
 * Y's columns are sparse triangular solves: contact i's column of P J^T, solved with L on the
 * rows it reaches only (cholmod_l_solve2 with a sparse right-hand side, Bset), O(|reach|) each
 * instead of O(nnz(L)). D = Y^T Y by CHOLMOD's sparse product, the rows of Y that most contacts
 * share (a stiff continuum's top separators) by BLAS's dsyrk; a D that at least half fills is
 * stored whole, LAPACK's packed triangle, and its products are BLAS's dspmv. */
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "base/lapack.h"
#include "base/sparse_factor.h"
#include "base/sparse_ops.h"
#include "contact_factor.h"
#include "fricreg.h"

static int failed(cholmod_common *c, struct fr_error *err, const char *who, const char *name)
{
    int status = fr_cholmod_status(c->status);
    if (status == FRICREG_OK)
        status = FRICREG_ENOMEM;
    return fr_error_set(err, status, "%s: no memory to factor %s", who, name);
}

void fr_cfactor_free(struct fr_cfactor *f, cholmod_common *c)
{
    cholmod_l_free_factor(&f->L, c);
    cholmod_l_free_sparse(&f->Y, c);
    cholmod_l_free_sparse(&f->D, c);
    cholmod_l_free_dense(&f->X, c);
    cholmod_l_free_dense(&f->Ywork, c);
    cholmod_l_free_dense(&f->Ework, c);
    cholmod_l_free(f->n, sizeof *f->pb, f->pb, c);
    cholmod_l_free(f->n, sizeof *f->work, f->work, c);
    memset(f, 0, sizeof *f);
}

/* Analyse (nested dissection from FR_CFACTOR_NESTED_FROM) and factor A = L L^T. */
static int factor(struct fr_cfactor *f, cholmod_sparse *A, cholmod_common *c, struct fr_error *err,
                  const char *who, const char *name)
{
    /* L L^T (fr_cholmod_start), so that Y^T Y is J A^-1 J^T without a diagonal */
    fr_cholmod_ordering(c, A->nrow >= FR_CFACTOR_NESTED_FROM ? CHOLMOD_NESDIS : CHOLMOD_AMD, 0);
    f->L = cholmod_l_analyze(A, c);
    if (f->L == NULL || !cholmod_l_factorize(A, f->L, c) || c->status < CHOLMOD_OK)
        return failed(c, err, who, name);
    if (c->status == CHOLMOD_NOT_POSDEF)
        return fr_error_set(err, FRICREG_ENOTPSD,
                            "%s: %s is not positive definite (no pivot at its column %ld)", who,
                            name, (long)f->L->minor);
    f->perm = f->L->ordering == CHOLMOD_NATURAL ? NULL : f->L->Perm;
    return FRICREG_OK;
}

/* Appends column j of Y: contact j's column of P J^T solved with L on its reach. B (dense,
 * zero) and Bset are scratch; iperm the inverse of perm. */
static int y_column(struct fr_cfactor *f, cholmod_factor *Ls, const cholmod_sparse *Jt, size_t j,
                    const SuiteSparse_long *iperm, cholmod_dense *B, cholmod_sparse *Bset,
                    cholmod_sparse **Xset, cholmod_dense **X, cholmod_dense **Yw,
                    cholmod_dense **Ew, cholmod_common *c)
{
    const SuiteSparse_long *Jp = Jt->p, *Ji = Jt->i;
    const double *Jx = Jt->x;
    double *b = B->x;
    SuiteSparse_long *bset = Bset->i, *bp = Bset->p;
    SuiteSparse_long len = 0;
    for (SuiteSparse_long p = Jp[j]; p < Jp[j + 1]; p++) {
        SuiteSparse_long row = iperm ? iperm[Ji[p]] : Ji[p];
        b[row] = Jx[p];
        bset[len++] = row;
    }
    bp[0] = 0;
    bp[1] = len;
    int ok = cholmod_l_solve2(CHOLMOD_L, Ls, B, Bset, X, Xset, Yw, Ew, c);
    for (SuiteSparse_long k = 0; k < len; k++)
        b[bset[k]] = 0.0;
    if (!ok)
        return 0;
    cholmod_sparse *Y = f->Y;
    const SuiteSparse_long *xi = (*Xset)->i, nx = ((SuiteSparse_long *)(*Xset)->p)[1];
    SuiteSparse_long *Yp = Y->p, start = Yp[j];
    if ((size_t)(start + nx) > Y->nzmax &&
        !cholmod_l_reallocate_sparse(2 * (size_t)(start + nx), Y, c))
        return 0;
    SuiteSparse_long *Yi = Y->i;
    double *Yx = Y->x;
    const double *x = (*X)->x;
    for (SuiteSparse_long k = 0; k < nx; k++) {
        Yi[start + k] = xi[k];
        Yx[start + k] = x[xi[k]];
    }
    Yp[j + 1] = start + nx;
    return 1;
}

/* Y, column by column (unsorted within columns, then sorted).
 *
 * The solution's pattern Xset is ours: CHOLMOD 3.0.14's cholmod_l_solve2 checks the Xset it
 * is given by its itype where it means its xtype (CHOLMOD_PATTERN, 0), so a 64-bit-index Xset
 * never passes: it is freed and allocated again at every call, and a failed allocation is
 * dereferenced (a crash, found by tests/alloc). Ours is marked with the value the check reads,
 * and its own itype is put back before it is freed. */
static int form_y(struct fr_cfactor *f, cholmod_sparse *Jt, cholmod_common *c)
{
    size_t n = f->n, m = f->m;
    SuiteSparse_long *iperm = cholmod_l_malloc(n, sizeof *iperm, c);
    cholmod_dense *B = cholmod_l_zeros(n, 1, CHOLMOD_REAL, c);
    size_t maxcol = 1;
    const SuiteSparse_long *Jp = Jt->p;
    for (size_t j = 0; j < m; j++)
        if ((size_t)(Jp[j + 1] - Jp[j]) > maxcol)
            maxcol = (size_t)(Jp[j + 1] - Jp[j]);
    cholmod_sparse *Bset = cholmod_l_allocate_sparse(n, 1, maxcol, 0, 1, 0, CHOLMOD_PATTERN, c);
    cholmod_sparse *Xset = cholmod_l_allocate_sparse(n, 1, n, 0, 1, 0, CHOLMOD_PATTERN, c);
    f->Y = cholmod_l_allocate_sparse(n, m, 4 * (size_t)Jp[m] + m, 0, 1, 0, CHOLMOD_REAL, c);
    cholmod_dense *X = NULL, *Yw = NULL, *Ew = NULL;
    int ok = iperm && B && Bset && Xset && f->Y;
    if (ok && f->perm)
        for (size_t k = 0; k < n; k++)
            iperm[f->perm[k]] = (SuiteSparse_long)k;
    if (ok) {
        ((SuiteSparse_long *)f->Y->p)[0] = 0;
        Xset->itype = CHOLMOD_PATTERN; /* see above */
    }
    /* the sparse solves convert a supernodal factor to a simplicial one (CHOLMOD's Bset path):
     * they take a copy, so that the steps' solves keep the supernodal factor's BLAS */
    cholmod_factor *Ls = ok && f->L->is_super ? cholmod_l_copy_factor(f->L, c) : f->L;
    ok = ok && Ls != NULL;
    for (size_t j = 0; ok && j < m; j++)
        ok = y_column(f, Ls, Jt, j, f->perm ? iperm : NULL, B, Bset, &Xset, &X, &Yw, &Ew, c);
    ok = ok && cholmod_l_sort(f->Y, c);
    if (Ls != f->L)
        cholmod_l_free_factor(&Ls, c);
    if (Xset != NULL)
        Xset->itype = CHOLMOD_LONG;
    cholmod_l_free(n, sizeof *iperm, iperm, c);
    cholmod_l_free_dense(&B, c);
    cholmod_l_free_sparse(&Bset, c);
    cholmod_l_free_sparse(&Xset, c);
    cholmod_l_free_dense(&X, c);
    cholmod_l_free_dense(&Yw, c);
    cholmod_l_free_dense(&Ew, c);
    return ok;
}

/* Leaves out of the upper triangle D the off-diagonal entries below drop sqrt(D_ii D_jj). */
static void drop_small(cholmod_sparse *D, double drop)
{
    SuiteSparse_long *Dp = D->p, *Di = D->i;
    double *Dx = D->x;
    size_t m = D->ncol;
    SuiteSparse_long q = 0, start = 0;
    /* Compacted in place, column by column: D_jj is the last entry of the sorted upper column
     * j, read before the column moves; D_ii (i < j) the last of column i, already moved. */
    for (size_t j = 0; j < m; j++) {
        SuiteSparse_long end = Dp[j + 1];
        double djj = end > start && Di[end - 1] == (SuiteSparse_long)j ? Dx[end - 1] : 0.0;
        for (SuiteSparse_long p = start; p < end; p++) {
            SuiteSparse_long i = Di[p];
            double dii = i < (SuiteSparse_long)j ? Dx[Dp[i + 1] - 1] : 0.0;
            if (i == (SuiteSparse_long)j || fabs(Dx[p]) > drop * sqrt(dii) * sqrt(djj)) {
                Di[q] = i;
                Dx[q++] = Dx[p];
            }
        }
        start = end;
        Dp[j + 1] = q;
    }
}

/* A copy of Y without the entries below drop times their column's largest: the terms they
 * would add to an entry of Y^T Y are below drop times the product of the two columns' scales,
 * and the rows far from a contact hold only such entries (K_eff^-1 decays away from the
 * contact), so that contacts far apart share no row and Y^T Y stays sparse. */
static cholmod_sparse *significant(const cholmod_sparse *Y, double drop, cholmod_common *c)
{
    cholmod_sparse *S = cholmod_l_copy_sparse((cholmod_sparse *)Y, c);
    if (S == NULL)
        return NULL;
    SuiteSparse_long *Sp = S->p, *Si = S->i, q = 0, start = 0;
    double *Sx = S->x;
    for (size_t j = 0; j < S->ncol; j++) {
        SuiteSparse_long end = Sp[j + 1];
        double big = 0.0;
        for (SuiteSparse_long p = start; p < end; p++)
            big = fmax(big, fabs(Sx[p]));
        for (SuiteSparse_long p = start; p < end; p++)
            if (fabs(Sx[p]) > drop * big) {
                Si[q] = Si[p];
                Sx[q++] = Sx[p];
            }
        start = end;
        Sp[j + 1] = q;
    }
    return S;
}

/* Y^T Y's upper triangle by CHOLMOD's sparse product, sorted. */
static cholmod_sparse *sparse_gram(cholmod_sparse *Y, cholmod_common *c)
{
    cholmod_sparse *Yt = cholmod_l_transpose(Y, 1, c);
    cholmod_sparse *G = Yt == NULL ? NULL : cholmod_l_ssmult(Yt, Y, 1, 1, 1, c);
    cholmod_l_free_sparse(&Yt, c);
    if (G != NULL && G->stype != 1) { /* CHOLMOD may hand back the lower triangle */
        cholmod_sparse *U = cholmod_l_copy(G, 1, 1, c);
        cholmod_l_free_sparse(&G, c);
        G = U;
    }
    if (G != NULL && !cholmod_l_sort(G, c))
        cholmod_l_free_sparse(&G, c);
    return G;
}

/* The rows of Y that at least m / SHARED_ROW_SHARE contacts reach (on a stiff continuum the
 * top separators, which every contact's path to the root crosses): copied into R (d x m,
 * column-major; d returned), the rest of Y into *rest. Their part of Y^T Y, R^T R, is then
 * BLAS's dsyrk, where a sparse product spends count^2 scattered operations on each. Only where
 * D is at least half full anyway: m from SHARED_ROWS_FROM on and one row reaching at least
 * m / sqrt(2) contacts (its pairs alone fill half of D's triangle), so that the dense m x m
 * array costs no more than D itself; and where d m fits LAPACK's int. 0 (R and rest NULL)
 * elsewhere; -1 without memory. The caller frees R and rest whatever the result. */
#define SHARED_ROW_SHARE 4
#define SHARED_ROWS_FROM 64
static long split_shared_rows(const cholmod_sparse *Y, cholmod_dense **R, cholmod_sparse **rest,
                              cholmod_common *c)
{
    size_t n = Y->nrow, m = Y->ncol;
    const SuiteSparse_long *Yp = Y->p, *Yi = Y->i;
    const double *Yx = Y->x;
    *R = NULL;
    *rest = NULL;
    if (m < SHARED_ROWS_FROM)
        return 0;
    SuiteSparse_long *at = cholmod_l_calloc(n, sizeof *at, c); /* row count, then R's row */
    if (at == NULL)
        return -1;
    for (SuiteSparse_long p = 0; p < Yp[m]; p++)
        at[Yi[p]]++;
    size_t d = 0, moved = 0, most = 0;
    for (size_t i = 0; i < n; i++) {
        most = (size_t)at[i] > most ? (size_t)at[i] : most;
        moved += at[i] * SHARED_ROW_SHARE >= (SuiteSparse_long)m ? (size_t)at[i] : 0;
        at[i] = at[i] * SHARED_ROW_SHARE >= (SuiteSparse_long)m ? (SuiteSparse_long)d++ : -1;
    }
    if (2.0 * (double)most * (double)most < (double)m * (double)m || d > (size_t)INT_MAX / m)
        d = 0;
    if (d > 0) {
        *R = cholmod_l_zeros(d, m, CHOLMOD_REAL, c);
        *rest = cholmod_l_allocate_sparse(n, m, (size_t)Yp[m] - moved, 1, 1, 0, CHOLMOD_REAL, c);
    }
    if (*R != NULL && *rest != NULL) {
        SuiteSparse_long *rp = (*rest)->p, *ri = (*rest)->i, q = 0;
        double *rx = (*rest)->x, *Rx = (*R)->x;
        for (size_t j = 0; j < m; j++) {
            rp[j] = q;
            for (SuiteSparse_long p = Yp[j]; p < Yp[j + 1]; p++)
                if (at[Yi[p]] >= 0) {
                    Rx[(size_t)at[Yi[p]] + j * d] = Yx[p];
                } else {
                    ri[q] = Yi[p];
                    rx[q++] = Yx[p];
                }
        }
        rp[m] = q;
    }
    cholmod_l_free(n, sizeof *at, at, c);
    return d > 0 && (*R == NULL || *rest == NULL) ? -1 : (long)d;
}

/* Whether D's entry w_ij (w_ii, w_jj its diagonal's) is kept: drop_small's rule; with drop 0
 * every entry but an exact zero (the sparse product would keep those of its pattern: the same
 * D as a matrix). */
static int kept(size_t i, size_t j, double w, double wii, double wjj, double drop)
{
    return i == j || (drop > 0.0 ? fabs(w) > drop * sqrt(wii) * sqrt(wjj) : w != 0.0);
}

/* The upper triangle of W (m x m, column-major) as CHOLMOD's sorted upper triangle, without
 * the entries kept() leaves out; where at least half of the triangle is kept, whole
 * (every entry, zeros too): LAPACK's packed storage, which fr_delassus_mult hands to BLAS. */
static cholmod_sparse *upper_of_dense(const double *W, size_t m, double drop, cholmod_common *c)
{
    size_t count = 0, whole = m * (m + 1) / 2;
    for (size_t j = 0; j < m; j++)
        for (size_t i = 0; i <= j; i++)
            count += kept(i, j, W[i + j * m], W[i + i * m], W[j + j * m], drop);
    int packed = 2 * count >= whole;
    cholmod_sparse *D = cholmod_l_allocate_sparse(m, m, packed ? whole : count, 1, 1, 1,
                                                  CHOLMOD_REAL, c);
    if (D == NULL)
        return NULL;
    SuiteSparse_long *Dp = D->p, *Di = D->i, q = 0;
    double *Dx = D->x;
    for (size_t j = 0; j < m; j++) {
        Dp[j] = q;
        for (size_t i = 0; i <= j; i++)
            if (packed || kept(i, j, W[i + j * m], W[i + i * m], W[j + j * m], drop)) {
                Di[q] = (SuiteSparse_long)i;
                Dx[q++] = W[i + j * m];
            }
    }
    Dp[m] = q;
    return D;
}

/* D = R^T R + S (S the sparse rest's upper triangle), through a dense m x m array. */
static cholmod_sparse *dense_gram(const cholmod_dense *R, const cholmod_sparse *S, double drop,
                                  cholmod_common *c)
{
    size_t m = S->ncol;
    int order = (int)m, depth = (int)R->nrow;
    double one = 1.0, zero = 0.0;
    cholmod_dense *W = m <= (size_t)INT_MAX && m <= SIZE_MAX / m
                           ? cholmod_l_allocate_dense(m, m, m, CHOLMOD_REAL, c)
                           : NULL;
    if (W == NULL)
        return NULL;
    double *Wx = W->x;
    dsyrk_("U", "T", &order, &depth, &one, R->x, &depth, &zero, Wx, &order, 1, 1);
    const SuiteSparse_long *Sp = S->p, *Si = S->i;
    const double *Sx = S->x;
    for (size_t j = 0; j < m; j++)
        for (SuiteSparse_long p = Sp[j]; p < Sp[j + 1]; p++)
            Wx[(size_t)Si[p] + j * m] += Sx[p];
    cholmod_sparse *D = upper_of_dense(Wx, m, drop / (double)m, c);
    cholmod_l_free_dense(&W, c);
    return D;
}

/* D = Y^T Y, upper triangle, sorted; with drop > 0 from Y's significant entries, and its own
 * small entries left out. Rows of Y shared by many contacts go through BLAS (above). */
static int form_d(struct fr_cfactor *f, double drop, cholmod_common *c)
{
    cholmod_sparse *Ys = drop > 0.0 ? significant(f->Y, drop, c) : f->Y, *rest = NULL;
    cholmod_dense *R = NULL;
    long d = Ys == NULL ? -1 : split_shared_rows(Ys, &R, &rest, c);
    cholmod_sparse *S = d < 0 ? NULL : sparse_gram(d > 0 ? rest : Ys, c);
    if (Ys != f->Y)
        cholmod_l_free_sparse(&Ys, c);
    cholmod_l_free_sparse(&rest, c);
    if (S != NULL && d > 0) {
        f->shared_rows = (size_t)d;
        f->D = dense_gram(R, S, drop, c);
        cholmod_l_free_sparse(&S, c);
    } else {
        f->D = S;
        if (f->D != NULL && drop > 0.0)
            drop_small(f->D, drop / (double)f->m);
    }
    cholmod_l_free_dense(&R, c);
    return f->D != NULL;
}

int fr_cfactor_build(struct fr_cfactor *f, cholmod_sparse *A, cholmod_sparse *Jt, double drop,
                     cholmod_common *c, struct fr_error *err, const char *who, const char *name)
{
    memset(f, 0, sizeof *f);
    f->n = A->nrow;
    f->m = Jt->ncol;
    int status = factor(f, A, c, err, who, name);
    if (status == FRICREG_OK && !(form_y(f, Jt, c) && form_d(f, drop, c)))
        status = failed(c, err, who, name);
    if (status == FRICREG_OK) {
        f->pb = cholmod_l_malloc(f->n, sizeof *f->pb, c);
        f->work = cholmod_l_malloc(f->n, sizeof *f->work, c);
        f->X = cholmod_l_allocate_dense(f->n, 1, f->n, CHOLMOD_REAL, c);
        if (f->pb == NULL || f->work == NULL || f->X == NULL)
            status = failed(c, err, who, name);
    }
    if (status == FRICREG_OK) {
        size_t nnz_l = f->L->is_super ? f->L->xsize : f->L->nzmax;
        f->Jt = Jt;
        f->by_solves = (size_t)cholmod_l_nnz(f->Y, c) > nnz_l + f->n;
        if (f->by_solves)
            cholmod_l_free_sparse(&f->Y, c);
    }
    if (status == FRICREG_OK) { /* one solve sizes the workspaces: later ones reuse them */
        memset(f->pb, 0, f->n * sizeof *f->pb);
        fr_cfactor_forward(f, f->pb, f->pb, c);
        if (c->status < CHOLMOD_OK)
            status = failed(c, err, who, name);
    }
    if (status != FRICREG_OK)
        fr_cfactor_free(f, c);
    return status;
}

/* L^-1 or L^-T on f->pb, the result into out[n]: the solution's header is pointed at out for
 * the call (its size is right, so CHOLMOD writes into it instead of reallocating). */
static void triangular(struct fr_cfactor *f, int sys, double out[], cholmod_common *c)
{
    cholmod_dense B = {.nrow = f->n,
                       .ncol = 1,
                       .nzmax = f->n,
                       .d = f->n,
                       .x = f->pb,
                       .xtype = CHOLMOD_REAL,
                       .dtype = CHOLMOD_DOUBLE};
    fr_cholmod_keep_workspace(f->Ywork);
    void *own = f->X->x;
    f->X->x = out;
    cholmod_l_solve2(sys, f->L, &B, NULL, &f->X, NULL, &f->Ywork, &f->Ework, c);
    f->X->x = own;
}

void fr_cfactor_forward(struct fr_cfactor *f, const double b[], double y[], cholmod_common *c)
{
    for (size_t k = 0; k < f->n; k++)
        f->pb[k] = b[f->perm ? (size_t)f->perm[k] : k];
    triangular(f, CHOLMOD_L, y, c);
}

void fr_cfactor_backward(struct fr_cfactor *f, const double y[], double x[], cholmod_common *c)
{
    memcpy(f->pb, y, f->n * sizeof *y);
    double *sol = f->X->x;
    triangular(f, CHOLMOD_Lt, sol, c);
    for (size_t k = 0; k < f->n; k++)
        x[f->perm ? (size_t)f->perm[k] : k] = sol[k];
}

void fr_cfactor_solve(struct fr_cfactor *f, const double b[], double x[], cholmod_common *c)
{
    fr_cfactor_forward(f, b, x, c);
    fr_cfactor_backward(f, x, x, c);
}

void fr_cfactor_project(struct fr_cfactor *f, const double y[], double out[], cholmod_common *c)
{
    if (f->by_solves) { /* J P^T L^-T y */
        memcpy(f->pb, y, f->n * sizeof *y);
        triangular(f, CHOLMOD_Lt, f->work, c);
        for (size_t k = 0; k < f->n; k++)
            f->pb[f->perm ? (size_t)f->perm[k] : k] = f->work[k];
        fr_csc_mult_t(f->Jt, f->pb, out);
        return;
    }
    const SuiteSparse_long *Yp = f->Y->p, *Yi = f->Y->i;
    const double *Yx = f->Y->x;
    for (size_t j = 0; j < f->m; j++) {
        double sum = 0.0;
        for (SuiteSparse_long p = Yp[j]; p < Yp[j + 1]; p++)
            sum += Yx[p] * y[Yi[p]];
        out[j] = sum;
    }
}

void fr_cfactor_lift(struct fr_cfactor *f, double alpha, const double g[], double y[],
                     cholmod_common *c)
{
    if (f->by_solves) { /* L^-1 P J^T (alpha g) */
        memset(f->work, 0, f->n * sizeof *f->work);
        fr_csc_mult_add(f->Jt, alpha, g, f->work);
        for (size_t k = 0; k < f->n; k++)
            f->pb[k] = f->work[f->perm ? (size_t)f->perm[k] : k];
        triangular(f, CHOLMOD_L, f->work, c);
        for (size_t k = 0; k < f->n; k++)
            y[k] += f->work[k];
        return;
    }
    const SuiteSparse_long *Yp = f->Y->p, *Yi = f->Y->i;
    const double *Yx = f->Y->x;
    for (size_t j = 0; j < f->m; j++) {
        double gj = alpha * g[j];
        if (gj != 0.0)
            for (SuiteSparse_long p = Yp[j]; p < Yp[j + 1]; p++)
                y[Yi[p]] += Yx[p] * gj;
    }
}

int fr_delassus_packed(const cholmod_sparse *D)
{
    size_t m = D->ncol;
    return D->sorted && D->packed && D->stype == 1 && m <= (size_t)INT_MAX &&
           (size_t)((const SuiteSparse_long *)D->p)[m] == m * (m + 1) / 2;
}

void fr_delassus_mult(const cholmod_sparse *D, double alpha, const double x[], double beta,
                      double y[])
{
    if (!fr_delassus_packed(D)) {
        fr_sym_mult(D, alpha, x, beta, y);
        return;
    }
    int order = (int)D->ncol, one = 1;
    if (beta == 0.0) { /* y's old values unread, as fr_sym_mult's */
        memset(y, 0, D->ncol * sizeof *y);
        beta = 1.0;
    }
    dspmv_("U", &order, &alpha, D->x, x, &one, &beta, y, &one, 1);
}

void fr_cfactor_compliance(const struct fr_cfactor *f, const double g[], double out[])
{
    fr_delassus_mult(f->D, 1.0, g, 0.0, out);
}
