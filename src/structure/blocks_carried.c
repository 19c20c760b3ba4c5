/* SPDX-License-Identifier: GPL-3.0-or-later */
/* blocks_carried.c — the near-stick block's held factor in a checkpoint (blocks_carried.h).
 *
 * Layout, native byte order (the checkpoint is for the same build): a kind byte, then
 *   NONE    nothing (no block held, or K_eff not factored);
 *   DENSE   a flags byte (1: the current factor held, 2: the spare held, 4: the spare is the
 *           one kept, masked_factor.h), then each factor held, the current one first:
 *           uint64 order, rows[order] (int64, W's row of each factor row), shift[order], the
 *           factor U's upper triangle column by column, order (order + 1) / 2 doubles, then
 *           uint64 schur_from and the kept Schur complement's upper triangle of the rows from
 *           there (masked_factor.h), column by column;
 *   SPARSE  set[m] (bytes, 0 or 1) and shift[m] (doubles, 0 off the set).
 * The dense path's held block is its factor rows' set; the sparse path's factor is formed from
 * its set and shifts alone, so those are all it needs. */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "blocks_carried.h"
#include "contact_sparse.h"
#include "masked_factor.h"

enum { NONE = 0, DENSE = 1, SPARSE = 2 };

/* The block s holds, by its path: the sparse one where the structure's space solves it. */
static int kind_of(const fricreg_structure *s)
{
    if (!(s->scheme == FR_SCHEME_NEWMARK && s->prepared && s->step_dt > 0.0))
        return NONE;
    if (s->newton.sparse != NULL)
        return s->newton.sparse->held ? SPARSE : NONE;
    const struct fr_masked_factor *f = &s->newton.block;
    return f->dense && (f->held || f->spare.held) ? DENSE : NONE;
}

enum { CURRENT_HELD = 1, SPARE_HELD = 2, SPARE_KEPT = 4 };

/* f with its spare as the current factor (a shallow copy, for reading). */
static struct fr_masked_factor spare_of(const struct fr_masked_factor *f)
{
    struct fr_masked_factor g = *f;
    fr_masked_factor_swap(&g);
    return g;
}

/* The dense part before schur_from, and the whole with it. */
static size_t dense_head_bytes(size_t order)
{
    return sizeof(uint64_t) + order * (sizeof(int64_t) + sizeof(double)) +
           order * (order + 1) / 2 * sizeof(double);
}

static size_t dense_bytes(size_t order, size_t schur_from)
{
    size_t q = order - schur_from;
    return dense_head_bytes(order) + sizeof(uint64_t) + q * (q + 1) / 2 * sizeof(double);
}

/* The flags byte and each factor held. */
static size_t dense_pair_bytes(const struct fr_masked_factor *f)
{
    return 1 + (f->held ? dense_bytes(f->order, f->schur_from) : 0) +
           (f->spare.held ? dense_bytes(f->spare.order, f->spare.schur_from) : 0);
}

size_t fr_blocks_carried_size(const fricreg_structure *s)
{
    switch (kind_of(s)) {
    case DENSE: return 1 + dense_pair_bytes(&s->newton.block);
    case SPARSE: return 1 + s->m * (1 + sizeof(double));
    default: return 1;
    }
}

static unsigned char *put(unsigned char *out, const void *bytes, size_t len)
{
    memcpy(out, bytes, len);
    return out + len;
}

static unsigned char *save_dense(const struct fr_masked_factor *f, unsigned char *out)
{
    uint64_t order = f->order;
    out = put(out, &order, sizeof order);
    for (size_t r = 0; r < f->order; r++) {
        int64_t row = f->rows[r];
        out = put(out, &row, sizeof row);
    }
    for (size_t r = 0; r < f->order; r++)
        out = put(out, &f->held_shift[f->rows[r]], sizeof(double));
    for (size_t col = 0; col < f->order; col++)
        out = put(out, f->D + col * f->m, (col + 1) * sizeof(double));
    uint64_t from = f->schur_from;
    out = put(out, &from, sizeof from);
    for (size_t col = f->schur_from; col < f->order; col++) {
        for (size_t row = f->schur_from; row < col; row++) /* kept transposed */
            out = put(out, &f->D[col + row * f->m], sizeof(double));
        out = put(out, &f->schur_diag[col], sizeof(double));
    }
    return out;
}

static void save_dense_pair(const struct fr_masked_factor *f, unsigned char *out)
{
    *out++ = (unsigned char)((f->held ? CURRENT_HELD : 0) | (f->spare.held ? SPARE_HELD : 0) |
                             (f->spare_kept ? SPARE_KEPT : 0));
    if (f->held)
        out = save_dense(f, out);
    if (f->spare.held) {
        struct fr_masked_factor g = spare_of(f);
        save_dense(&g, out);
    }
}

static void save_sparse(const struct fr_contact_sparse *f, unsigned char *out)
{
    out = put(out, f->held_set, f->m);
    put(out, f->held_shift, f->m * sizeof(double));
}

void fr_blocks_carried_save(const fricreg_structure *s, unsigned char out[])
{
    int kind = kind_of(s);
    out[0] = (unsigned char)kind;
    if (kind == DENSE)
        save_dense_pair(&s->newton.block, out + 1);
    else if (kind == SPARSE)
        save_sparse(s->newton.sparse, out + 1);
}

static double double_at(const unsigned char *in, size_t k)
{
    double x;
    memcpy(&x, in + k * sizeof x, sizeof x);
    return x;
}

static int shift_valid(double shift)
{
    return isfinite(shift) && shift >= 0.0;
}

/* The length of the factor's record at in[len], 0 if it cannot be one. */
static size_t dense_record_len(const struct fr_masked_factor *f, const unsigned char *in,
                               size_t len)
{
    uint64_t order, from;
    if (len < sizeof order)
        return 0;
    memcpy(&order, in, sizeof order);
    if (order > f->m || len < dense_head_bytes((size_t)order) + sizeof from)
        return 0;
    memcpy(&from, in + dense_head_bytes((size_t)order), sizeof from);
    size_t n = dense_bytes((size_t)order, (size_t)from);
    return from <= order && len >= n ? n : 0;
}

/* in[len], one factor's record, as f's held factor (copy) or only checked: distinct rows of
 * W, shifts finite and not negative, a finite nonzero diagonal (dtpqrt may leave it
 * negative); FRICREG_EINVAL without a change but to f->at, the factorization's scratch. */
static int restore_dense(struct fr_masked_factor *f, const unsigned char *in, size_t len, int copy)
{
    uint64_t order, from;
    if (len == 0 || dense_record_len(f, in, len) != len)
        return FRICREG_EINVAL;
    memcpy(&order, in, sizeof order);
    memcpy(&from, in + dense_head_bytes((size_t)order), sizeof from);
    size_t n = (size_t)order;
    const unsigned char *rows = in + sizeof order, *shifts = rows + n * sizeof(int64_t);
    const unsigned char *U = shifts + n * sizeof(double);
    for (size_t i = 0; i < f->m; i++)
        f->at[i] = -1;
    for (size_t r = 0, diag = 0; r < n; diag += r + 2, r++) {
        int64_t row;
        memcpy(&row, rows + r * sizeof row, sizeof row);
        double u = double_at(U, diag);
        if (row < 0 || (uint64_t)row >= f->m || f->at[row] >= 0 ||
            !shift_valid(double_at(shifts, r)) || !isfinite(u) || u == 0.0)
            return FRICREG_EINVAL;
        f->at[row] = (SuiteSparse_long)r;
    }
    if (!copy)
        return FRICREG_OK;
    memset(f->held_set, 0, f->m);
    memset(f->held_shift, 0, f->m * sizeof *f->held_shift);
    for (size_t r = 0; r < n; r++) {
        int64_t row;
        memcpy(&row, rows + r * sizeof row, sizeof row);
        f->rows[r] = (SuiteSparse_long)row;
        f->held_set[row] = 1;
        f->held_shift[row] = double_at(shifts, r);
    }
    for (size_t col = 0, at = 0; col < n; at += col + 1, col++)
        memcpy(f->D + col * f->m, U + at * sizeof(double), (col + 1) * sizeof(double));
    const unsigned char *S = in + dense_head_bytes(n) + sizeof from;
    f->schur_from = (size_t)from;
    for (size_t col = f->schur_from, at = 0; col < n; col++) {
        for (size_t row = f->schur_from; row < col; row++)
            f->D[col + row * f->m] = double_at(S, at++);
        f->schur_diag[col] = double_at(S, at++);
    }
    f->order = n;
    f->kept = 0;
    f->deleted = 0;
    f->held = 1;
    return FRICREG_OK;
}

/* in[len] (after the kind) as f's two factors (save_dense_pair): both checked, then copied. */
static int restore_dense_pair(struct fr_masked_factor *f, const unsigned char *in, size_t len)
{
    if (!f->dense || len < 1 || in[0] > (CURRENT_HELD | SPARE_HELD | SPARE_KEPT))
        return FRICREG_EINVAL;
    int flags = in[0];
    size_t cur = flags & CURRENT_HELD ? dense_record_len(f, in + 1, len - 1) : 0;
    size_t spare = len - 1 - cur;
    if (((flags & CURRENT_HELD) && cur == 0) || (!(flags & SPARE_HELD) && spare != 0) ||
        ((flags & SPARE_KEPT) && !(flags & SPARE_HELD)))
        return FRICREG_EINVAL;
    const unsigned char *at = in + 1 + cur;
    if (((flags & CURRENT_HELD) && restore_dense(f, in + 1, cur, 0) != FRICREG_OK) ||
        ((flags & SPARE_HELD) && restore_dense(f, at, spare, 0) != FRICREG_OK))
        return FRICREG_EINVAL;
    fr_masked_factor_swap(f);
    f->held = 0;
    if (flags & SPARE_HELD)
        restore_dense(f, at, spare, 1);
    fr_masked_factor_swap(f);
    f->held = 0;
    if (flags & CURRENT_HELD)
        restore_dense(f, in + 1, cur, 1);
    f->spare_kept = (flags & SPARE_KEPT) != 0;
    return FRICREG_OK;
}

/* in[len] (after the kind) as the sparse path's held block: checked, then factored. */
static int restore_sparse(fricreg_structure *s, const unsigned char *in, size_t len)
{
    struct fr_contact_sparse *f = s->newton.sparse;
    if (f == NULL || len != f->m * (1 + sizeof(double)))
        return FRICREG_EINVAL;
    const unsigned char *shifts = in + f->m;
    for (size_t i = 0; i < f->m; i++) {
        double shift = double_at(shifts, i);
        if (in[i] > 1 || !shift_valid(shift) || (in[i] == 0 && shift != 0.0))
            return FRICREG_EINVAL;
    }
    memcpy(f->held_set, in, f->m);
    memcpy(f->held_shift, shifts, f->m * sizeof(double));
    return fr_contact_sparse_hold(f, s->step.D, f->held_set, f->held_shift, &s->cc);
}

int fr_blocks_carried_restore(fricreg_structure *s, const unsigned char in[], size_t len,
                              int factored)
{
    if (len < 1 || in[0] > SPARSE || (!factored && (in[0] != NONE || len != 1)))
        return FRICREG_EINVAL;
    if (!factored)
        return FRICREG_OK; /* the next step prepares the blocks afresh */
    switch (in[0]) {
    case DENSE:
        return s->newton.sparse != NULL ? FRICREG_EINVAL
                                        : restore_dense_pair(&s->newton.block, in + 1, len - 1);
    case SPARSE: return restore_sparse(s, in + 1, len - 1);
    default:
        if (len != 1)
            return FRICREG_EINVAL;
        s->newton.block.held = 0;
        s->newton.block.spare.held = 0;
        if (s->newton.sparse != NULL)
            s->newton.sparse->held = 0;
        return FRICREG_OK;
    }
}
