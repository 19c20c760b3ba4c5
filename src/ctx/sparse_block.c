/* SPDX-License-Identifier: GPL-3.0-or-later */
/* sparse_block.c — the cached LDL^T factor of a principal block B of a sparse W: the sparse
 * twin of factor.c, behind the same fr_factor_ensure / fr_factor_solve.
 *
 * The factor is of the whole m x m matrix C_B = P (W_BB + I on the rest) P^T: the rows and
 * columns of the contacts outside B are the identity's, so that B can change without a new
 * symbolic analysis. P is the AMD ordering chosen once per coupling (sparse_coupling.c), and
 * C_B is factored in that (natural, for CHOLMOD) order, simplicial LDL^T, so that CHOLMOD's
 * row updates apply:
 *   - a contact that enters B is a row and column added, cholmod_l_rowadd (its row of L by a
 *     sparse triangular solve, then a rank-one downdate of the trailing factor along its path
 *     in the elimination tree);
 *   - one that leaves is a row deleted, cholmod_l_rowdel (its row and column back to the
 *     identity's, then a rank-one update), given the pattern of its row of L (the row
 *     subtree of C's whole pattern, a superset) so that it does not search all of L;
 *   - a fresh factorization, cholmod_l_rowfac on C_B's upper triangle holding only B's
 *     entries, so that L's pattern is that of W_BB's factor: separate clusters of B stay
 *     separate trees, and the updates that follow run along short paths.
 * As in factor.c, updates are used when at most 2 + |B|/8 contacts change, at most 1000
 * since the last fresh factorization, and while no pivot ratio (of an added row, or of the
 * ancestors its downdate touched) falls below UPDATE_PIVOT_MIN and, after deletions, the
 * diagonal of L D L^T stays within DRIFT_MAX of W_BB's (one pass over L); and, as the dense rule is
 * itself a cost rule (an update costs |B|^2, a factorization |B|^3/3), only when their
 * estimated cost is below a fresh factorization's: a row update walks the elimination tree
 * from its row to the root, and on a chain that AMD orders end to end that is a path of up
 * to m columns, measured at 0.8-0.9 ms per update at m = 10^5 against 1.1 ms for the whole
 * factorization (a tridiagonal W).
 *
 * Allocation: none after fr_sparse_block_alloc. CHOLMOD's workspace (Flag, Head, Iwork 2m,
 * Xwork 2m: cholmod_l_rowadd's and _rowdel's needs, which cover _rowfac's, _updown's and
 * _row_subtree's) and the solve's dense matrices are allocated there; the numeric factor is
 * allocated there too, by a first factorization (of the identity), with room in every column
 * for the whole pattern of C's factor plus CHOLMOD's growth (grow1 = 1.2, grow2 = 5): every
 * pattern an update or a refactorization forms lies within it (updates walk the elimination
 * tree towards ancestors, whose columns hold every row of their descendants' columns), so
 * cholmod_l_reallocate_column never moves a column and the updates never allocate
 * (CHOLMOD 3.0.14: Modify/cholmod_rowadd.c, cholmod_rowdel.c, cholmod_updown.c allocate only
 * through allocate_work, change_factor and reallocate_column; Cholesky/t_cholmod_rowfac.c
 * through change_factor and reallocate_column; cholmod_l_solve2 reuses X and Y of the right
 * size, once Y's shape is restored: fr_sparse_block_solve). tests/alloc/test_alloc_failure.c
 * checks it with every allocation failing.
 *
 * Singularity: a fresh factorization's pivot ratio d_p / W_kk below FR_PIVOT_MIN (1e-12), k
 * the contact at factor position p, positions in the factor's (AMD's) order. The ratio does
 * not depend on the contacts' units, and a redundant set's last redundant contact has ratio 0
 * to rounding in any order; a nearly singular one can be judged by its order, which differs
 * from the dense path's ascending contact order. */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "ctx_internal.h"
#include "sparse_block.h"

/* As factor.c: an update that adds a contact with a smaller pivot ratio (on its own or on
 * any downdated ancestor) refactors afresh instead; the largest relative drift of the
 * diagonal of L D L^T kept after updates; the updates after which the next change refactors. */
#define UPDATE_PIVOT_MIN 1e-8
#define DRIFT_MAX 1e-13
#define MAX_UPDATES 1000
/* The cost of a row update per entry of L on its path, in the units of a fresh factorization
 * (entries of C_B built plus CHOLMOD's flop count): measured, a tridiagonal W at m = 10^5,
 * AMD: an update's path of about m/2 columns of 2 entries 0.8-0.9 ms, a factorization
 * (7 m units) 1.1 ms. */
#define UPDATE_WEIGHT 6.0

static size_t few_changes(size_t n)
{
    return 2 + n / 8;
}

/* ---- Storage --------------------------------------------------------------------------- */

/* C_B for B empty: the identity, one entry per column. */
static void identity(cholmod_sparse *CB, size_t m)
{
    SuiteSparse_long *Bp = CB->p, *Bi = CB->i;
    double *Bx = CB->x;
    for (size_t j = 0; j < m; j++) {
        Bp[j] = (SuiteSparse_long)j;
        Bi[j] = (SuiteSparse_long)j;
        Bx[j] = 1.0;
    }
    Bp[m] = (SuiteSparse_long)m;
}

/* The symbolic factor of C's pattern in natural order, simplicial LDL^T left unpacked (room
 * in each column), and its numeric storage, by factoring the identity. */
static int analyze(struct fr_sparse_coupling *sp)
{
    cholmod_common *c = &sp->c;
    struct fr_sparse_block *b = &sp->block;
    double zero[2] = {0.0, 0.0};
    c->nmethods = 1;
    c->method[0].ordering = CHOLMOD_NATURAL;
    c->postorder = 0;
    c->supernodal = CHOLMOD_SIMPLICIAL;
    c->final_ll = 0;
    c->final_pack = 0;
    c->final_asis = 1;
    b->L = cholmod_l_analyze(sp->C, c);
    if (b->L == NULL)
        return FRICREG_ENOMEM;
    b->fresh_cost = c->fl + (double)((SuiteSparse_long *)sp->C->p)[sp->m] + (double)sp->m;
    identity(b->CB, sp->m);
    if (!cholmod_l_rowfac(b->CB, NULL, zero, 0, sp->m, b->L, c) || b->L->xtype != CHOLMOD_REAL)
        return FRICREG_ENOMEM;
    return FRICREG_OK;
}

int fr_sparse_block_alloc(struct fr_sparse_coupling *sp)
{
    cholmod_common *c = &sp->c;
    struct fr_sparse_block *b = &sp->block;
    size_t m = sp->m, nnz = (size_t)((SuiteSparse_long *)sp->C->p)[m];
    b->parent = cholmod_l_malloc(m, sizeof *b->parent, c);
    b->held = cholmod_l_calloc(m, sizeof *b->held, c);
    b->next = cholmod_l_calloc(m, sizeof *b->next, c);
    b->order = cholmod_l_malloc(m, sizeof *b->order, c);
    b->CB = cholmod_l_allocate_sparse(m, m, nnz + m, 1, 1, 1, CHOLMOD_REAL, c);
    b->R = cholmod_l_allocate_sparse(m, 1, m, 0, 1, 0, CHOLMOD_REAL, c);
    b->rhs = cholmod_l_zeros(m, 1, CHOLMOD_REAL, c);
    b->x = cholmod_l_zeros(m, 1, CHOLMOD_REAL, c);
    b->y = cholmod_l_zeros(4, m, CHOLMOD_REAL, c); /* cholmod_l_solve2's, simplicial and real */
    if (!b->parent || !b->held || !b->next || !b->order || !b->CB || !b->R || !b->rhs || !b->x ||
        !b->y)
        return FRICREG_ENOMEM;
    if (!cholmod_l_etree(sp->C, b->parent, c) || !cholmod_l_allocate_work(m, 2 * m, 2 * m, c))
        return FRICREG_ENOMEM;
    return analyze(sp);
}

void fr_sparse_block_free(struct fr_sparse_coupling *sp)
{
    cholmod_common *c = &sp->c;
    struct fr_sparse_block *b = &sp->block;
    size_t m = sp->m > 0 ? sp->m : 1;
    cholmod_l_free_factor(&b->L, c);
    cholmod_l_free_sparse(&b->CB, c);
    cholmod_l_free_sparse(&b->R, c);
    cholmod_l_free_dense(&b->rhs, c);
    cholmod_l_free_dense(&b->x, c);
    cholmod_l_free_dense(&b->y, c);
    b->parent = cholmod_l_free(m, sizeof *b->parent, b->parent, c);
    b->held = cholmod_l_free(m, sizeof *b->held, b->held, c);
    b->next = cholmod_l_free(m, sizeof *b->next, b->next, c);
    b->order = cholmod_l_free(m, sizeof *b->order, b->order, c);
}

/* ---- The factor's state ------------------------------------------------------------------ */

/* The pivot d_p of L D L^T at factor position p. */
static double pivot(const cholmod_factor *L, SuiteSparse_long p)
{
    return ((const double *)L->x)[((const SuiteSparse_long *)L->p)[p]];
}

/* d_p / W_kk of position p (k = perm[p]); a pivot below DBL_MIN counts as 0, as in factor.c. */
static double pivot_ratio(const fricreg_ctx *ctx, SuiteSparse_long p)
{
    double d = pivot(ctx->sp->block.L, p);
    return d >= DBL_MIN ? d / ctx->w_diag[ctx->sp->perm[p]] : 0.0;
}

/* The parent of position p in the elimination tree of L's pattern (-1 at a root). */
static SuiteSparse_long parent_in(const cholmod_factor *L, SuiteSparse_long p)
{
    const SuiteSparse_long *Lp = L->p, *Li = L->i, *Lnz = L->nz;
    return Lnz[p] > 1 ? Li[Lp[p] + 1] : -1;
}

/* max over the block's positions of |(L D L^T)_pp / W_kk - 1|, with sp->column as the
 * accumulator: one pass over L. */
static double diagonal_drift(const fricreg_ctx *ctx, const size_t set[], size_t n)
{
    const struct fr_sparse_coupling *sp = ctx->sp;
    const cholmod_factor *L = sp->block.L;
    const SuiteSparse_long *Lp = L->p, *Li = L->i, *Lnz = L->nz;
    const double *Lx = L->x;
    double *diag = sp->column, drift = 0.0;
    for (size_t j = 0; j < ctx->m; j++) {
        double d = Lx[Lp[j]];
        diag[j] += d;
        for (SuiteSparse_long p = Lp[j] + 1; p < Lp[j] + Lnz[j]; p++)
            diag[Li[p]] += d * Lx[p] * Lx[p];
    }
    for (size_t a = 0; a < n; a++) {
        SuiteSparse_long p = sp->pinv[set[a]];
        drift = fmax(drift, fabs(diag[p] / ctx->w_diag[set[a]] - 1.0));
    }
    memset(diag, 0, ctx->m * sizeof *diag);
    return isnan(drift) ? INFINITY : drift;
}

static void remember_order(fricreg_ctx *ctx, const size_t set[], size_t n)
{
    struct fr_sparse_coupling *sp = ctx->sp;
    for (size_t a = 0; a < n; a++)
        sp->block.order[a] = sp->pinv[set[a]];
}

/* ---- A fresh factorization --------------------------------------------------------------- */

/* C_B's upper triangle: C's entries between held positions, 1 on the other diagonal. */
static void block_matrix(struct fr_sparse_coupling *sp)
{
    const SuiteSparse_long *Cp = sp->C->p, *Ci = sp->C->i;
    const double *Cx = sp->C->x;
    const unsigned char *held = sp->block.held;
    SuiteSparse_long *Bp = sp->block.CB->p, *Bi = sp->block.CB->i, q = 0;
    double *Bx = sp->block.CB->x;
    for (size_t j = 0; j < sp->m; j++) {
        Bp[j] = q;
        if (!held[j]) {
            Bi[q] = (SuiteSparse_long)j;
            Bx[q++] = 1.0;
            continue;
        }
        for (SuiteSparse_long p = Cp[j]; p < Cp[j + 1]; p++)
            if (held[Ci[p]]) {
                Bi[q] = Ci[p];
                Bx[q++] = Cx[p];
            }
    }
    Bp[sp->m] = q;
}

/* The block's smallest pivot ratio, and its position (the lowest of equal ones) in *at. */
static double smallest_ratio(const fricreg_ctx *ctx, const size_t set[], size_t n,
                             SuiteSparse_long *at)
{
    double smallest = INFINITY;
    *at = -1;
    for (size_t a = 0; a < n; a++) {
        SuiteSparse_long p = ctx->sp->pinv[set[a]];
        double ratio = pivot_ratio(ctx, p);
        if (ratio < smallest || (ratio == smallest && p < *at) || isnan(ratio)) {
            smallest = isnan(ratio) ? 0.0 : ratio;
            *at = p;
        }
    }
    return smallest;
}

static int fresh(fricreg_ctx *ctx, const size_t set[], size_t n, const char *who)
{
    struct fr_sparse_coupling *sp = ctx->sp;
    struct fr_sparse_block *b = &sp->block;
    double zero[2] = {0.0, 0.0};
    memset(b->held, 0, ctx->m * sizeof *b->held);
    for (size_t a = 0; a < n; a++)
        b->held[sp->pinv[set[a]]] = 1;
    b->n = n;
    block_matrix(sp);
    ctx->stats[FRICREG_STAT_FACTORIZATIONS]++;
    /* No allocation (the numeric factor exists), so nothing can fail but the pivots: a zero
     * pivot is CHOLMOD's warning CHOLMOD_NOT_POSDEF, and the scan below judges them all. */
    cholmod_l_rowfac(b->CB, NULL, zero, 0, ctx->m, b->L, &sp->c);
    SuiteSparse_long at;
    double ratio = smallest_ratio(ctx, set, n, &at);
    if (!(ratio >= FR_PIVOT_MIN)) {
        b->valid = 0;
        return fr_fail(ctx, FRICREG_ESINGULAR,
                       "%s: W on the %zu contacts (first: contact %zu) is singular: contact"
                       " %zu's pivot ratio d/W_ii %.3g (in the sparse factor's order) is below"
                       " %g: redundant contacts",
                       who, n, set[0], (size_t)sp->perm[at], ratio, FR_PIVOT_MIN);
    }
    b->fragile = ratio < UPDATE_PIVOT_MIN;
    b->updates = 0;
    b->valid = 1;
    remember_order(ctx, set, n);
    return FRICREG_OK;
}

/* ---- Updates ------------------------------------------------------------------------------- */

/* The entries of L on the elimination tree's path from position p to its root, summed until
 * they exceed budget (a row update's work: its rank-one update runs along that path). */
static double path_cost(const cholmod_factor *L, SuiteSparse_long p, double budget)
{
    const SuiteSparse_long *Lnz = L->nz;
    double cost = 0.0;
    for (; p >= 0 && cost <= budget; p = parent_in(L, p))
        cost += (double)Lnz[p];
    return cost;
}

/* The work of updating the held block (positions order[b->n]) to the one marked in next[]
 * (the set's positions): a position that leaves updates along its own path; one that enters
 * joins the trees of its held neighbours (in W) and downdates along their paths. Summed until
 * it exceeds budget. */
static double update_cost(const struct fr_sparse_coupling *sp, const size_t set[], size_t n,
                          double budget)
{
    const struct fr_sparse_block *b = &sp->block;
    const SuiteSparse_long *Wp = sp->W->p, *Wi = sp->W->i;
    double cost = 0.0;
    for (size_t a = 0; a < b->n && cost <= budget; a++)
        if (!b->next[b->order[a]])
            cost += path_cost(b->L, b->order[a], budget - cost);
    for (size_t a = 0; a < n && cost <= budget; a++) {
        SuiteSparse_long k = (SuiteSparse_long)set[a];
        if (b->held[sp->pinv[k]])
            continue;
        cost += 1.0;
        for (SuiteSparse_long t = Wp[k]; t < Wp[k + 1] && cost <= budget; t++) {
            SuiteSparse_long q = sp->pinv[Wi[t]];
            if (Wi[t] != k && b->held[q])
                cost += path_cost(b->L, q, budget - cost);
        }
    }
    return cost;
}

/* Row p deleted: its row and column become the identity's. */
static int delete_row(struct fr_sparse_coupling *sp, SuiteSparse_long p)
{
    struct fr_sparse_block *b = &sp->block;
    if (!cholmod_l_row_subtree(sp->C, NULL, (size_t)p, b->parent, b->R, &sp->c))
        return 0;
    b->held[p] = 0;
    return cholmod_l_rowdel((size_t)p, b->R, b->L, &sp->c);
}

/* Row p added: column p of C_B (both triangles, the held rows only, from W by contact). */
static int add_row(struct fr_sparse_coupling *sp, SuiteSparse_long p)
{
    struct fr_sparse_block *b = &sp->block;
    const SuiteSparse_long *Wp = sp->W->p, *Wi = sp->W->i;
    const double *Wx = sp->W->x;
    SuiteSparse_long *Rp = b->R->p, *Ri = b->R->i, k = sp->perm[p], q = 0;
    double *Rx = b->R->x;
    b->held[p] = 1;
    for (SuiteSparse_long t = Wp[k]; t < Wp[k + 1]; t++) {
        SuiteSparse_long row = sp->pinv[Wi[t]];
        if (b->held[row]) {
            Ri[q] = row;
            Rx[q++] = Wx[t];
        }
    }
    Rp[0] = 0;
    Rp[1] = q;
    b->R->sorted = 0;
    return cholmod_l_rowadd((size_t)p, b->R, b->L, &sp->c);
}

/* Whether the pivots on p's path (the ones an added row downdates) keep their ratio above
 * UPDATE_PIVOT_MIN. */
static int path_pivots_hold(const fricreg_ctx *ctx, SuiteSparse_long p)
{
    const struct fr_sparse_block *b = &ctx->sp->block;
    for (; p >= 0; p = parent_in(b->L, p))
        if (b->held[p] && !(pivot_ratio(ctx, p) >= UPDATE_PIVOT_MIN))
            return 0;
    return 1;
}

/* From the held block (positions order[b->n]) to set (marked in next[]): rows deleted, then
 * added. Returns 0 if an update gave up (a small pivot, a drift, or CHOLMOD refused): a fresh
 * factorization must follow. */
static int update(fricreg_ctx *ctx, const size_t set[], size_t n)
{
    struct fr_sparse_coupling *sp = ctx->sp;
    struct fr_sparse_block *b = &sp->block;
    size_t deleted = 0, added = 0;
    for (size_t a = 0; a < b->n; a++)
        if (!b->next[b->order[a]]) {
            if (!delete_row(sp, b->order[a]))
                return 0;
            deleted++;
        }
    for (size_t a = 0; a < n; a++) {
        SuiteSparse_long p = sp->pinv[set[a]];
        if (b->held[p])
            continue;
        if (!add_row(sp, p) || !path_pivots_hold(ctx, p))
            return 0;
        added++;
    }
    b->n = n;
    ctx->stats[FRICREG_STAT_FACTOR_UPDATES] += (int64_t)(deleted + added);
    b->updates += deleted + added;
    /* As factor.c: the drift after deletions (an added row's pivots are checked above) */
    return deleted == 0 || diagonal_drift(ctx, set, n) <= DRIFT_MAX;
}

int fr_sparse_block_ensure(fricreg_ctx *ctx, const size_t set[], size_t n, const char *who)
{
    struct fr_sparse_coupling *sp = ctx->sp;
    struct fr_sparse_block *b = &sp->block;
    if (!b->valid)
        return fresh(ctx, set, n, who);
    size_t kept = 0;
    for (size_t a = 0; a < n; a++)
        kept += b->held[sp->pinv[set[a]]];
    size_t changes = (b->n - kept) + (n - kept);
    if (changes == 0) {
        remember_order(ctx, set, n);
        return FRICREG_OK;
    }
    int worth = !b->fragile && changes <= few_changes(n > b->n ? n : b->n) &&
                b->updates + changes <= MAX_UPDATES;
    if (worth) {
        double budget = b->fresh_cost / UPDATE_WEIGHT;
        for (size_t a = 0; a < n; a++)
            b->next[sp->pinv[set[a]]] = 1;
        worth = update_cost(sp, set, n, budget) <= budget && update(ctx, set, n);
        for (size_t a = 0; a < n; a++)
            b->next[sp->pinv[set[a]]] = 0;
        if (worth) {
            remember_order(ctx, set, n);
            return FRICREG_OK;
        }
    }
    return fresh(ctx, set, n, who);
}

int fr_sparse_block_solve(fricreg_ctx *ctx, double r[])
{
    struct fr_sparse_coupling *sp = ctx->sp;
    struct fr_sparse_block *b = &sp->block;
    double *rhs = b->rhs->x;
    ctx->stats[FRICREG_STAT_SOLVES]++;
    if (b->n == 0)
        return FRICREG_OK;
    for (size_t a = 0; a < b->n; a++)
        rhs[b->order[a]] = r[a];
    /* cholmod_l_solve2 reuses Y of 4 x m, but (CHOLMOD 3.0.14, Cholesky/cholmod_solve.c,
     * ptrans) leaves it shaped 1 x m for the one column solved, and would reallocate it on the
     * next call: its 4 x m shape back, whose storage it still has. */
    b->y->nrow = b->y->d = 4;
    cholmod_dense *E = NULL; /* unused by a simplicial factor */
    cholmod_l_solve2(CHOLMOD_A, b->L, b->rhs, NULL, &b->x, NULL, &b->y, &E, &sp->c);
    const double *x = b->x->x;
    for (size_t a = 0; a < b->n; a++) {
        r[a] = x[b->order[a]];
        rhs[b->order[a]] = 0.0;
    }
    return FRICREG_OK;
}
