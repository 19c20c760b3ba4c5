/* SPDX-License-Identifier: GPL-3.0-or-later */
/* ctx_carried.c — what a context carries from one evaluation to the next that the next one's
 * rounding depends on, for a driver's checkpoint (fricreg_structure_save): the consistent
 * law's warm start (the QP's last working set per contact, partition_consistent.c) and, with a
 * dense W, the cached factor of W's near-stick block, which factor.c updates contact by
 * contact (an updated factor and a fresh one of the same block differ in their last bits).
 * Everything else an evaluation reads is set by the setters or rebuilt by the evaluation.
 *
 * Layout, native byte order (the checkpoint is for the same build): side[m] (signed char);
 * then, with a dense W, uint64 n, valid, updates, fragile, set[n] (uint64), d[n] and the n x n
 * block of U row by row (doubles; zeros below its diagonal, which the factor never writes).
 * The factor only with `factor` set (the driver's model set up: the coupling is its model's;
 * otherwise the next coupling setter forgets the factor, while the warm start stays). A sparse
 * W's factor (CHOLMOD's, updated row by row) is not carried:
 * fr_ctx_carried_size says so. */
#include <stdint.h>
#include <string.h>

#include "ctx_internal.h"

/* The dense factor's part: four counts, set, d and U's block. */
static size_t factor_bytes(const fricreg_ctx *ctx)
{
    size_t n = ctx->fac.valid ? ctx->fac.n : 0;
    return 4 * sizeof(uint64_t) + n * sizeof(uint64_t) + (n + n * n) * sizeof(double);
}

size_t fr_ctx_carried_size(const fricreg_ctx *ctx, int factor)
{
    if (factor && ctx->sp != NULL)
        return 0;
    return ctx->m + (factor && ctx->W != NULL ? factor_bytes(ctx) : 0);
}

static unsigned char *put_u64(unsigned char *p, uint64_t x)
{
    memcpy(p, &x, sizeof x);
    return p + sizeof x;
}

static const unsigned char *get_u64(const unsigned char *p, uint64_t *x)
{
    memcpy(x, p, sizeof *x);
    return p + sizeof *x;
}

void fr_ctx_carried_save(const fricreg_ctx *ctx, int factor, unsigned char out[])
{
    memcpy(out, ctx->side, ctx->m);
    if (!factor || ctx->W == NULL)
        return;
    const struct fr_factor *fa = &ctx->fac;
    size_t n = fa->valid ? fa->n : 0;
    unsigned char *p = out + ctx->m;
    p = put_u64(p, n);
    p = put_u64(p, (uint64_t)fa->valid);
    p = put_u64(p, fa->updates);
    p = put_u64(p, (uint64_t)fa->fragile);
    for (size_t k = 0; k < n; k++)
        p = put_u64(p, fa->set[k]);
    memcpy(p, fa->d, n * sizeof *fa->d);
    p += n * sizeof *fa->d;
    for (size_t i = 0; i < n; i++, p += n * sizeof(double)) { /* row i: zeros, then U's */
        memset(p, 0, i * sizeof(double)); /* never written by factor.c: not read */
        memcpy(p + i * sizeof(double), fa->U + i * ctx->m + i, (n - i) * sizeof(double));
    }
}

/* A working-set mark: FR_LOWER, FR_FREE, FR_UPPER or partition_consistent.c's mark of a
 * contact outside S (any other value: a corrupted blob). */
static int side_valid(signed char s)
{
    return s >= -1 && s <= 2;
}

int fr_ctx_carried_restore(fricreg_ctx *ctx, const unsigned char in[], size_t len, int factor)
{
    size_t m = ctx->m;
    if ((factor && ctx->sp != NULL) || len < m)
        return FRICREG_EINVAL;
    int dense = factor && ctx->W != NULL;
    for (size_t i = 0; i < m; i++)
        if (!side_valid((signed char)in[i]))
            return FRICREG_EINVAL;
    uint64_t n = 0, valid = 0, updates = 0, fragile = 0;
    const unsigned char *p = in + m;
    if (dense) {
        if (len < m + 4 * sizeof(uint64_t))
            return FRICREG_EINVAL;
        p = get_u64(get_u64(get_u64(get_u64(p, &n), &valid), &updates), &fragile);
        if (n > m || valid > 1 || fragile > 1 || (valid == 0 && n != 0))
            return FRICREG_EINVAL;
    }
    size_t need = dense ? m + 4 * sizeof(uint64_t) + n * sizeof(uint64_t) +
                              (n + n * n) * sizeof(double)
                        : m;
    if (len != need)
        return FRICREG_EINVAL;
    /* set: n distinct contacts; checked before anything is written (hit marks them) */
    struct fr_factor *fa = &ctx->fac;
    if (dense) {
        memset(fa->hit, 0, m);
        for (size_t k = 0; k < n; k++) {
            uint64_t c;
            get_u64(p + k * sizeof c, &c);
            if (c >= m || fa->hit[c])
                return FRICREG_EINVAL;
            fa->hit[c] = 1;
        }
    }
    memcpy(ctx->side, in, m);
    if (!dense)
        return FRICREG_OK;
    for (size_t i = 0; i < m; i++)
        fa->pos[i] = SIZE_MAX; /* factor.c's FR_NOT_HELD */
    for (size_t k = 0; k < n; k++) {
        uint64_t c;
        p = get_u64(p, &c);
        fa->set[k] = (size_t)c;
        fa->pos[c] = k;
    }
    fa->n = (size_t)n;
    fa->valid = (int)valid;
    fa->updates = (size_t)updates;
    fa->fragile = (int)fragile;
    memcpy(fa->d, p, n * sizeof *fa->d);
    p += n * sizeof *fa->d;
    for (size_t i = 0; i < n; i++, p += n * sizeof(double))
        memcpy(fa->U + i * m, p, n * sizeof(double));
    return FRICREG_OK;
}
