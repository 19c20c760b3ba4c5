/* SPDX-License-Identifier: GPL-3.0-or-later */
/* masked_factor.c — principal blocks of one sparse SPD matrix, factored without allocating
 * (masked_factor.h). */
#include <limits.h>
#include <math.h>
#include <string.h>

#include "base/lapack.h"
#include "base/sparse_factor.h"
#include "contact_factor.h"
#include "fricreg.h"
#include "masked_factor.h"

/* dtpqrt's block size, q / 8 for q rows deleted within these bounds: with OpenBLAS 0.3.21, 32
 * is best for a few hundred rows, and 128 runs 10-25 % faster from a thousand on (1000 or 3000
 * rows before 3000-7000). Its T and work take 2 DELETE_NB_MAX m doubles (f->qr_work). */
#define DELETE_NB_MIN 32
#define DELETE_NB_MAX 128

void fr_masked_factor_free(struct fr_masked_factor *f, cholmod_common *c)
{
    size_t nnz = f->A ? (size_t)((SuiteSparse_long *)f->A->p)[f->m] : 0;
    cholmod_l_free(nnz, sizeof *f->src, f->src, c);
    cholmod_l_free(f->m, sizeof *f->perm, f->perm, c);
    cholmod_l_free(f->m, sizeof *f->b, f->b, c);
    cholmod_l_free(f->m, sizeof *f->held_shift, f->held_shift, c);
    cholmod_l_free(f->m, sizeof *f->held_set, f->held_set, c);
    cholmod_l_free_sparse(&f->A, c);
    cholmod_l_free_factor(&f->L, c);
    cholmod_l_free_dense(&f->X, c);
    cholmod_l_free_dense(&f->Yw, c);
    cholmod_l_free_dense(&f->Ew, c);
    cholmod_l_free(f->m * f->m > 0 ? f->m * f->m : 1, sizeof *f->D, f->D, c);
    cholmod_l_free(2 * DELETE_NB_MAX * (f->m > 0 ? f->m : 1), sizeof *f->qr_work, f->qr_work, c);
    cholmod_l_free(f->m, sizeof *f->at, f->at, c);
    cholmod_l_free(f->m, sizeof *f->rows, f->rows, c);
    cholmod_l_free(f->m, sizeof *f->schur_diag, f->schur_diag, c);
    struct fr_spare_factor *g = &f->spare;
    cholmod_l_free(f->m * f->m > 0 ? f->m * f->m : 1, sizeof *g->D, g->D, c);
    cholmod_l_free(f->m, sizeof *g->schur_diag, g->schur_diag, c);
    cholmod_l_free(f->m, sizeof *g->held_shift, g->held_shift, c);
    cholmod_l_free(f->m, sizeof *g->rows, g->rows, c);
    cholmod_l_free(f->m, sizeof *g->held_set, g->held_set, c);
    memset(f, 0, sizeof *f);
}

/* A fill-reducing order of W's pattern (AMD, postordered) into f->perm, and the number of
 * entries of the factor in that order into *lnz. */
static int order(struct fr_masked_factor *f, const cholmod_sparse *W, double *lnz,
                 cholmod_common *c)
{
    fr_cholmod_ordering(c, CHOLMOD_AMD, 0);
    cholmod_factor *L = cholmod_l_analyze((cholmod_sparse *)W, c);
    f->perm = cholmod_l_malloc(f->m, sizeof *f->perm, c);
    int ok = L != NULL && f->perm != NULL;
    if (ok) {
        memcpy(f->perm, L->Perm, f->m * sizeof *f->perm);
        *lnz = 0.0;
        for (size_t j = 0; j < f->m; j++)
            *lnz += (double)((const SuiteSparse_long *)L->ColCount)[j];
    }
    cholmod_l_free_factor(&L, c);
    return ok;
}

/* The storage the fill rule (masked_factor.h) gives W's factor of nnz(L) = lnz; dense needs its
 * order to fit LAPACK's int. */
static int fill_is_dense(size_t m, double lnz)
{
    return m <= (size_t)INT_MAX && lnz >= FR_BLOCK_DENSE_FILL * (double)m * ((double)m + 1.0) / 2.0;
}

/* f->A = the upper triangle of P W P^T, with f->src mapping its entries to W's: the
 * permutation is done on a copy of W whose values are its entries' own positions. */
static int permute(struct fr_masked_factor *f, const cholmod_sparse *W, cholmod_common *c)
{
    size_t nnz = (size_t)((const SuiteSparse_long *)W->p)[f->m];
    cholmod_sparse *index = cholmod_l_copy_sparse((cholmod_sparse *)W, c), *full = NULL, *P = NULL;
    if (index != NULL) {
        for (size_t p = 0; p < nnz; p++)
            ((double *)index->x)[p] = (double)p;
        full = cholmod_l_copy(index, 0, 1, c); /* both triangles */
    }
    if (full != NULL)
        P = cholmod_l_submatrix(full, f->perm, (SuiteSparse_long)f->m, f->perm,
                                (SuiteSparse_long)f->m, 1, 1, c);
    if (P != NULL)
        f->A = cholmod_l_copy(P, 1, 1, c);
    cholmod_l_free_sparse(&index, c);
    cholmod_l_free_sparse(&full, c);
    cholmod_l_free_sparse(&P, c);
    if (f->A == NULL)
        return 0;
    size_t anz = (size_t)((SuiteSparse_long *)f->A->p)[f->m];
    f->src = cholmod_l_malloc(anz > 0 ? anz : 1, sizeof *f->src, c);
    if (f->src == NULL)
        return 0;
    const double *ax = f->A->x;
    for (size_t q = 0; q < anz; q++)
        f->src[q] = (SuiteSparse_long)ax[q];
    return 1;
}

/* The factor's symbolic analysis in the natural order (the matrix is permuted already). */
static int analyse(struct fr_masked_factor *f, cholmod_common *c)
{
    fr_cholmod_ordering(c, CHOLMOD_NATURAL, 1);
    f->L = cholmod_l_analyze(f->A, c);
    return f->L != NULL && f->L->ordering == CHOLMOD_NATURAL;
}

/* Dense: the buffer of the largest block, W itself, and the maps between W's rows and the
 * factor's. */
static int dense_allocate(struct fr_masked_factor *f, cholmod_common *c)
{
    f->D = cholmod_l_malloc(f->m * f->m > 0 ? f->m * f->m : 1, sizeof *f->D, c);
    f->at = cholmod_l_malloc(f->m, sizeof *f->at, c);
    f->rows = cholmod_l_malloc(f->m, sizeof *f->rows, c);
    f->qr_work = cholmod_l_malloc(2 * DELETE_NB_MAX * (f->m > 0 ? f->m : 1), sizeof *f->qr_work, c);
    f->schur_diag = cholmod_l_malloc(f->m, sizeof *f->schur_diag, c);
    struct fr_spare_factor *g = &f->spare;
    g->D = cholmod_l_malloc(f->m * f->m > 0 ? f->m * f->m : 1, sizeof *g->D, c);
    g->schur_diag = cholmod_l_malloc(f->m, sizeof *g->schur_diag, c);
    g->held_shift = cholmod_l_malloc(f->m, sizeof *g->held_shift, c);
    g->rows = cholmod_l_malloc(f->m, sizeof *g->rows, c);
    g->held_set = cholmod_l_malloc(f->m, sizeof *g->held_set, c);
    return f->D != NULL && f->at != NULL && f->rows != NULL && f->qr_work != NULL &&
           f->schur_diag != NULL && g->D != NULL && g->schur_diag != NULL &&
           g->held_shift != NULL && g->rows != NULL && g->held_set != NULL;
}

void fr_masked_factor_swap(struct fr_masked_factor *f)
{
    struct fr_spare_factor cur = {f->D,        f->schur_diag, f->held_shift, f->rows,
                                  f->held_set, f->order,      f->schur_from, f->held};
    f->D = f->spare.D;
    f->schur_diag = f->spare.schur_diag;
    f->held_shift = f->spare.held_shift;
    f->rows = f->spare.rows;
    f->held_set = f->spare.held_set;
    f->order = f->spare.order;
    f->schur_from = f->spare.schur_from;
    f->held = f->spare.held;
    f->spare = cur;
    f->spare_kept = !f->spare_kept;
}

int fr_masked_factor_prepare(struct fr_masked_factor *f, const cholmod_sparse *W,
                             enum fr_block_storage storage, cholmod_common *c)
{
    memset(f, 0, sizeof *f);
    f->m = W->ncol;
    f->b = cholmod_l_malloc(f->m, sizeof *f->b, c);
    f->held_shift = cholmod_l_malloc(f->m, sizeof *f->held_shift, c);
    f->held_set = cholmod_l_malloc(f->m, sizeof *f->held_set, c);
    double lnz = 0.0;
    int ok = f->b && f->held_shift && f->held_set && order(f, W, &lnz, c);
    if (ok) {
        f->dense = storage == FR_BLOCK_DENSE ||
                   (storage == FR_BLOCK_CHOSEN && fill_is_dense(f->m, lnz));
        if (f->dense) {
            ok = dense_allocate(f, c);
            if (!ok)
                fr_masked_factor_free(f, c);
            return ok ? FRICREG_OK : FRICREG_ENOMEM;
        }
    }
    ok = ok && permute(f, W, c) && analyse(f, c);
    if (ok) { /* the identity (an empty block) once: CHOLMOD sizes its workspaces */
        memset(f->b, 0, f->m * sizeof *f->b);
        ok = fr_masked_factor_solve(f, W, NULL, NULL, f->b, f->b, c) == FRICREG_OK;
    }
    if (!ok)
        fr_masked_factor_free(f, c);
    return ok ? FRICREG_OK : FRICREG_ENOMEM;
}

static void fill(struct fr_masked_factor *f, const cholmod_sparse *W, const unsigned char *set,
                 const double *shift)
{
    const SuiteSparse_long *Ap = f->A->p, *Ai = f->A->i;
    const double *Wx = W->x;
    double *Ax = f->A->x;
    for (size_t l = 0; l < f->m; l++) {
        size_t j = (size_t)f->perm[l];
        for (SuiteSparse_long q = Ap[l]; q < Ap[l + 1]; q++) {
            size_t i = (size_t)f->perm[Ai[q]];
            if (set && set[i] && set[j])
                Ax[q] = Wx[f->src[q]] + (i == j && shift ? shift[i] : 0.0);
            else
                Ax[q] = i == j ? 1.0 : 0.0;
        }
    }
}

/* The block and shifts of the factor held: those of the last factorization (f->held). */
static int holds(const struct fr_masked_factor *f, const unsigned char *set, const double *shift)
{
    return fr_block_is_held(f->m, f->held, f->held_set, f->held_shift, set, shift);
}

static void hold(struct fr_masked_factor *f, const unsigned char *set, const double *shift)
{
    fr_block_hold(f->m, f->held_set, f->held_shift, set, shift);
    f->held = 1;
}

static double shift_of(const double *shift, size_t i)
{
    return shift ? shift[i] : 0.0;
}

/* The leading rows of the held factor that the block set, shift keeps: in S, same shift. */
static size_t kept_rows(const struct fr_masked_factor *f, const unsigned char *set,
                        const double *shift)
{
    size_t r = 0;
    while (f->held && r < f->order) {
        size_t i = (size_t)f->rows[r];
        if (!(set && set[i]) || shift_of(shift, i) != f->held_shift[i])
            break;
        r++;
    }
    return r;
}

/* The factor's rows: its first p kept, then S's others without a shift, then the shifted
 * ones, each in W's order; f->at numbers them. Returns |S|. */
static size_t order_rows(struct fr_masked_factor *f, const unsigned char *set, const double *shift,
                         size_t p)
{
    for (size_t i = 0; i < f->m; i++)
        f->at[i] = -1;
    for (size_t r = 0; r < p; r++)
        f->at[f->rows[r]] = (SuiteSparse_long)r;
    size_t k = p;
    for (int shifted = 0; shifted <= 1; shifted++)
        for (size_t i = 0; set && i < f->m; i++)
            if (set[i] && f->at[i] < 0 && (shift_of(shift, i) != 0.0) == shifted) {
                f->rows[k] = (SuiteSparse_long)i;
                f->at[i] = (SuiteSparse_long)k++;
            }
    return k;
}

/* Columns p..k-1 of the upper triangle of W_SS in the factor's order, into D (leading
 * dimension m); the shifts come after the Schur complement (factor_trailing). Entries of W
 * below the diagonal are not read, as CHOLMOD reads an upper (stype 1) W. */
static void dense_fill_scan(struct fr_masked_factor *f, const cholmod_sparse *W, size_t p, size_t k)
{
    const SuiteSparse_long *Wp = W->p, *Wi = W->i;
    const double *Wx = W->x;
    size_t m = f->m;
    for (size_t col = p; col < k; col++)
        memset(f->D + col * m, 0, (col + 1) * sizeof *f->D);
    for (size_t j = 0; j < m; j++) {
        if (f->at[j] < 0)
            continue;
        for (SuiteSparse_long q = Wp[j]; q < Wp[j + 1]; q++) {
            SuiteSparse_long ri = f->at[Wi[q]], rj = f->at[j]; /* their rows of the factor */
            if ((size_t)Wi[q] > j || ri < 0)
                continue;
            size_t lo = (size_t)(ri < rj ? ri : rj), hi = (size_t)(ri < rj ? rj : ri);
            if (hi >= p)
                f->D[lo + hi * m] = Wx[q];
        }
    }
}

/* The same columns where W is packed whole (fr_delassus_packed: entry (i, j), i <= j, at
 * j (j + 1) / 2 + i): each entry read where it goes, (k^2 - p^2) / 2 reads instead of a pass
 * over all of W's m^2 / 2 with its rows mapped. The same values: the factor is the same. */
static void dense_fill_packed(struct fr_masked_factor *f, const cholmod_sparse *W, size_t p,
                              size_t k)
{
    const double *Wx = W->x;
    for (size_t col = p; col < k; col++) {
        size_t j = (size_t)f->rows[col];
        const double *wj = Wx + j * (j + 1) / 2;
        double *d = f->D + col * f->m;
        for (size_t r = 0; r <= col; r++) {
            size_t i = (size_t)f->rows[r];
            d[r] = i <= j ? wj[i] : Wx[i * (i + 1) / 2 + j];
        }
    }
}

static void dense_fill(struct fr_masked_factor *f, const cholmod_sparse *W, size_t p, size_t k)
{
    if (fr_delassus_packed(W))
        dense_fill_packed(f, W, p, k);
    else
        dense_fill_scan(f, W, p, k);
}

/* Rows p..k-1 of D's upper triangle plus diag(shift) factored by dpotrf. A pivot that is not
 * positive (W_SS not positive definite, or not a number) stops it with info > 0, CHOLMOD's
 * CHOLMOD_NOT_POSDEF: 0. */
static int factor_shifted(struct fr_masked_factor *f, size_t p, size_t k, const double *shift)
{
    int lda = (int)f->m, trail = (int)(k - p), info = 0;
    for (size_t col = p; col < k; col++)
        f->D[col * (f->m + 1)] += shift_of(shift, (size_t)f->rows[col]);
    if (k > p)
        dpotrf_("U", &trail, f->D + p * (f->m + 1), &lda, &info, 1);
    return info == 0;
}

/* U's rows p..k-1 given its leading p: U12 = U11^-T A12, then U22 the factor of
 * A22 - U12^T U12 + diag(shift), the complement before the shifts kept (masked_factor.h). */
static int factor_trailing(struct fr_masked_factor *f, size_t p, size_t k, const double *shift)
{
    size_t m = f->m;
    int lda = (int)m, lead = (int)p, trail = (int)(k - p);
    double one = 1.0, minus_one = -1.0, *U12 = f->D + p * m, *A22 = U12 + p;
    if (p > 0 && k > p) {
        dtrsm_("L", "U", "T", "N", &lead, &trail, &one, f->D, &lda, U12, &lda, 1, 1, 1, 1);
        dsyrk_("U", "T", &trail, &lead, &minus_one, U12, &lda, &one, A22, &lda, 1, 1);
    }
    for (size_t col = p; col < k; col++) {
        f->schur_diag[col] = f->D[col * (m + 1)];
        for (size_t row = p; row < col; row++)
            f->D[col + row * m] = f->D[row + col * m];
    }
    f->schur_from = p;
    return factor_shifted(f, p, k, shift);
}

/* Whether set holds the held rows and shift differs from the held shifts only on rows from
 * schur_from on: then refactor_from_schur gives its factor. */
static int schur_applies(const struct fr_masked_factor *f, const unsigned char *set,
                         const double *shift)
{
    return fr_block_holds_rows(f->m, f->held, f->held_set, set) &&
           kept_rows(f, set, shift) >= f->schur_from;
}

/* The held factor's rows from schur_from on, from their kept complement and the new shifts. */
static int refactor_from_schur(struct fr_masked_factor *f, const double *shift)
{
    size_t m = f->m, p = f->schur_from;
    for (size_t col = p; col < f->order; col++) {
        for (size_t row = p; row < col; row++)
            f->D[row + col * m] = f->D[col + row * m];
        f->D[col * (m + 1)] = f->schur_diag[col];
    }
    f->kept = p;
    f->deleted = 0;
    return factor_shifted(f, p, f->order, shift);
}

/* Whether row r of the held factor stays in the block set, shift (in it, same shift). */
static int stays(const struct fr_masked_factor *f, size_t r, const unsigned char *set,
                 const double *shift)
{
    size_t i = (size_t)f->rows[r];
    return set && set[i] && shift_of(shift, i) == f->held_shift[i];
}

/* factor_trailing's flops with p rows kept and q new ones. */
static double trailing_flops(double p, double q)
{
    return p * p * q + p * q * q + q * q * q / 3.0;
}

/* The flops of the block set, shift from the held factor with its first p rows kept: the
 * rows after them factored again (*again), or those that stay kept by deleting the others
 * (delete_rows: 2 q t^2 flops for q rows deleted before t staying ones) and the new rows
 * factored (*keep, infinite where none stays). */
static void refactor_costs(const struct fr_masked_factor *f, const unsigned char *set,
                           const double *shift, size_t p, double *again, double *keep)
{
    size_t t = 0, q = 0, k = 0;
    for (size_t r = p; f->held && r < f->order; r++) {
        t += stays(f, r, set, shift);
        q += !stays(f, r, set, shift);
    }
    for (size_t i = 0; set && i < f->m; i++)
        k += set[i] != 0;
    *again = trailing_flops((double)p, (double)(k - p));
    *keep = t > 0 ? 2.0 * (double)q * (double)t * (double)t +
                        trailing_flops((double)(p + t), (double)(k - p - t))
                  : INFINITY;
}

/* Whether the held factor's rows after the first p that stay are cheaper kept by deleting
 * the others than factored again with the new rows. */
static int deletion_cheaper(const struct fr_masked_factor *f, const unsigned char *set,
                            const double *shift, size_t p)
{
    if (!f->held || p == f->order)
        return 0;
    double again, keep;
    refactor_costs(f, set, shift, p, &again, &keep);
    return keep < again;
}

/* The held factor without its rows after the first p that leave the block or change their
 * shift: returns the rows it keeps, p + t. With U's staying rows T and deleted rows Q after
 * the first p, the block of T has the factor R of [U_TT; U_QT] (R^T R = U_TT^T U_TT +
 * U_QT^T U_QT, the rows of Q put back into T's columns), by LAPACK's dtpqrt (the QR of a
 * triangle on a rectangle, BLAS 3); the rows above keep U_:T. In place: T's columns are moved
 * left to p.., each with its rows p.. in the order T then Q (zero where U's row follows its
 * column). */
static size_t delete_rows(struct fr_masked_factor *f, const unsigned char *set, const double *shift,
                          size_t p)
{
    size_t m = f->m, order = f->order, t = 0, q = 0;
    for (size_t r = p; r < order; r++) /* the new row of each old one, T's then Q's */
        if (stays(f, r, set, shift))
            f->at[f->rows[r]] = (SuiteSparse_long)t++;
    for (size_t r = p; r < order; r++)
        if (!stays(f, r, set, shift))
            f->at[f->rows[r]] = (SuiteSparse_long)(t + q++);
    double *scratch = f->b;
    for (size_t r = p, col = p; r < order; r++) {
        if (!stays(f, r, set, shift))
            continue;
        double *from = f->D + r * m, *to = f->D + col++ * m;
        memmove(to, from, p * sizeof *to);
        for (size_t s = p; s < order; s++)
            scratch[f->at[f->rows[s]]] = s <= r ? from[s] : 0.0;
        memcpy(to + p, scratch, (order - p) * sizeof *to);
    }
    for (size_t r = p, k = p; r < order; r++) /* T's rows of W, in their order */
        if (stays(f, r, set, shift))
            f->rows[k++] = f->rows[r];
    int rows_q = (int)q, cols_t = (int)t, zero = 0, lda = (int)m, info = 0;
    size_t block = q / 8 < DELETE_NB_MIN ? DELETE_NB_MIN : q / 8;
    block = block > DELETE_NB_MAX ? DELETE_NB_MAX : block;
    int nb = (int)(t < block ? t : block);
    double *R = f->D + p * (m + 1); /* its diagonal may be negative: R^T R is the same */
    dtpqrt_(&rows_q, &cols_t, &zero, &nb, R, &lda, R + t, &lda, f->qr_work, &nb,
            f->qr_work + (size_t)nb * t, &info);
    f->deleted = q;
    return p + t;
}

/* The flops dense_refactor spends on the block set, shift from the held factor. */
static double refactor_flops(const struct fr_masked_factor *f, const unsigned char *set,
                             const double *shift)
{
    if (holds(f, set, shift))
        return 0.0;
    if (schur_applies(f, set, shift)) {
        double q = (double)(f->order - f->schur_from);
        return q * q * q / 3.0;
    }
    double again, keep;
    refactor_costs(f, set, shift, kept_rows(f, set, shift), &again, &keep);
    return fmin(again, keep);
}

/* The spare made the current factor where the block costs fewer flops from it (the kept one
 * where both cost the same): returns whether it was. */
static int spare_as_base(struct fr_masked_factor *f, const unsigned char *set, const double *shift)
{
    if (!f->spare.held)
        return 0;
    double here = f->held ? refactor_flops(f, set, shift) : INFINITY;
    fr_masked_factor_swap(f);
    double there = refactor_flops(f, set, shift);
    if (there < here || (there == here && !f->spare_kept))
        return 1;
    fr_masked_factor_swap(f);
    return 0;
}

/* The held factor's first n columns, rows and held block copied into the spare and the two
 * swapped: the factor held before stays intact as the spare, kept (masked_factor.h). */
static void keep_as_spare(struct fr_masked_factor *f, size_t n)
{
    struct fr_spare_factor *g = &f->spare;
    size_t m = f->m;
    for (size_t col = 0; col < n; col++)
        memcpy(g->D + col * m, f->D + col * m, (col + 1) * sizeof *f->D);
    memcpy(g->rows, f->rows, f->order * sizeof *f->rows);
    memcpy(g->held_set, f->held_set, m * sizeof *f->held_set);
    memcpy(g->held_shift, f->held_shift, m * sizeof *f->held_shift);
    g->order = f->order;
    g->schur_from = f->order; /* no complement: the copy is factored on at once */
    g->held = f->held;
    fr_masked_factor_swap(f);
}

/* The factor of the block set, shift in f->D (masked_factor.h): from the held factor or the
 * spare, whichever costs fewer flops; from the kept complement where only the last new rows'
 * shifts changed; else its leading rows kept, the rows after them too where deleting the
 * others is cheaper, the rest factored; a kept factor that the block does not extend is left
 * intact as the spare. 0 if not positive definite (then nothing is held). */
static int dense_refactor(struct fr_masked_factor *f, const cholmod_sparse *W,
                          const unsigned char *set, const double *shift)
{
    f->from_spare = spare_as_base(f, set, shift);
    int base_kept = !f->spare_kept;
    f->spare_kept = 0;          /* the factor made from a base is kept unless the base is (below) */
    if (holds(f, set, shift)) { /* the spare's block: nothing to factor */
        f->kept = f->order;
        f->deleted = 0;
        return 1;
    }
    if (schur_applies(f, set, shift)) {
        f->held = 0;
        return refactor_from_schur(f, shift);
    }
    size_t p = kept_rows(f, set, shift);
    f->deleted = 0;
    int deleting = deletion_cheaper(f, set, shift, p);
    if (base_kept && f->held && p < f->order)
        keep_as_spare(f, deleting ? f->order : p);
    if (deleting)
        p = delete_rows(f, set, shift, p);
    f->held = 0;
    f->order = order_rows(f, set, shift, p);
    f->kept = p;
    dense_fill(f, W, p, f->order);
    return factor_trailing(f, p, f->order, shift);
}

/* The sparse solve's dense twin: W_SS's Cholesky factor by LAPACK in f->D (dense_refactor),
 * then its two triangles. */
static int dense_solve(struct fr_masked_factor *f, const cholmod_sparse *W,
                       const unsigned char *set, const double *shift, const double b[], double x[])
{
    if (!holds(f, set, shift)) {
        if (!dense_refactor(f, W, set, shift))
            return FRICREG_ESINGULAR;
        hold(f, set, shift);
    }
    if (f->order == 0)
        return FRICREG_OK;
    for (size_t r = 0; r < f->order; r++)
        f->b[r] = b[f->rows[r]];
    /* dpotrs's two triangles, each by dtrsv: with one right-hand side OpenBLAS's dpotrs goes
     * through dtrsm, which copies the factor first (3x slower at order 2000). */
    int order = (int)f->order, lda = (int)f->m, one = 1;
    dtrsv_("U", "T", "N", &order, f->D, &lda, f->b, &one, 1, 1, 1);
    dtrsv_("U", "N", "N", &order, f->D, &lda, f->b, &one, 1, 1, 1);
    for (size_t r = 0; r < f->order; r++)
        x[f->rows[r]] = f->b[r];
    return FRICREG_OK;
}

int fr_masked_factor_solve(struct fr_masked_factor *f, const cholmod_sparse *W,
                           const unsigned char *set, const double *shift, const double b[],
                           double x[], cholmod_common *c)
{
    if (f->dense)
        return dense_solve(f, W, set, shift, b, x);
    for (size_t k = 0; k < f->m; k++) {
        size_t i = (size_t)f->perm[k];
        f->b[k] = set && set[i] ? b[i] : 0.0;
    }
    if (!holds(f, set, shift)) {
        f->held = 0;
        fill(f, W, set, shift);
        if (!cholmod_l_factorize(f->A, f->L, c) || c->status < CHOLMOD_OK)
            return FRICREG_ENOMEM;
        if (c->status == CHOLMOD_NOT_POSDEF)
            return FRICREG_ESINGULAR;
        hold(f, set, shift);
    }
    cholmod_dense B = {.nrow = f->m,
                       .ncol = 1,
                       .nzmax = f->m,
                       .d = f->m,
                       .x = f->b,
                       .xtype = CHOLMOD_REAL,
                       .dtype = CHOLMOD_DOUBLE};
    fr_cholmod_keep_workspace(f->Yw);
    if (!cholmod_l_solve2(CHOLMOD_A, f->L, &B, NULL, &f->X, NULL, &f->Yw, &f->Ew, c))
        return FRICREG_ENOMEM;
    const double *sol = f->X->x;
    for (size_t k = 0; k < f->m; k++) {
        size_t i = (size_t)f->perm[k];
        if (set && set[i])
            x[i] = sol[k];
    }
    return FRICREG_OK;
}
