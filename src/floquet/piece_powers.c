/* SPDX-License-Identifier: GPL-3.0-or-later */
/* piece_powers.c — the exact monodromy's piece matrices kept with their powers (piece_powers.h).
 *
 * Along a branch, consecutive orbits switch through the same states of their sliders: a piece's
 * state matrix Â (monodromy.c's, at dt = 1) recurs with another duration dt, and e^(dt Â) then
 * needs fr_hb_expm_at's products only, not the powers' (Â², Â⁴, Â⁶: 3 of a [13/13]
 * approximant's 6). An entry is found by Â's content, so it is never stale: a change of the
 * model, of σ or of a slider's state is another matrix. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "expm.h"
#include "piece_powers.h"

int fr_hb_pieces_init(struct fr_hb_pieces *c, size_t pmax)
{
    size_t pp = pmax * pmax, cap = FR_HB_PIECES_MAX;
    memset(c, 0, sizeof *c);
    c->pmax = pmax;
    if (pp == 0 || pp > FR_HB_PIECES_BYTES / (6 * sizeof(double)))
        return 0;
    if (cap > FR_HB_PIECES_BYTES / (6 * pp * sizeof(double)))
        cap = FR_HB_PIECES_BYTES / (6 * pp * sizeof(double));
    c->piece = calloc(cap, sizeof *c->piece);
    c->block = malloc(cap * 6 * pp * sizeof *c->block);
    if (c->piece == NULL || c->block == NULL) {
        fr_hb_pieces_free(c);
        return -1;
    }
    for (size_t k = 0; k < cap; k++)
        c->piece[k].A = c->block + k * 6 * pp;
    c->cap = cap;
    return 0;
}

void fr_hb_pieces_free(struct fr_hb_pieces *c)
{
    free(c->piece);
    free(c->block);
    memset(c, 0, sizeof *c);
}

/* A word-wise hash of A's bytes: a cheap first test before the full comparison. */
static unsigned long content_hash(const double *A, size_t n)
{
    uint64_t h = 0x9e3779b97f4a7c15u;
    for (size_t i = 0; i < n; i++) {
        uint64_t x;
        memcpy(&x, &A[i], sizeof x);
        h = (h ^ x) * 0x100000001b3u;
    }
    return (unsigned long)(h ^ (h >> 29));
}

const struct fr_hb_piece *fr_hb_pieces_find(struct fr_hb_pieces *c, const double *A, size_t p)
{
    size_t pp = p * p;
    if (c->cap == 0 || p > c->pmax)
        return NULL;
    unsigned long hash = content_hash(A, pp);
    size_t oldest = 0;
    for (size_t k = 0; k < c->count; k++) {
        struct fr_hb_piece *e = &c->piece[k];
        if (e->p == p && e->hash == hash && memcmp(e->A, A, pp * sizeof *A) == 0) {
            e->used = ++c->clock;
            return e;
        }
        if (e->used < c->piece[oldest].used)
            oldest = k;
    }
    size_t k = c->count < c->cap ? c->count++ : oldest;
    struct fr_hb_piece *e = &c->piece[k];
    memcpy(e->A, A, pp * sizeof *A);
    e->pow = e->A + pp;
    e->p = p;
    e->nu = fr_hb_expm_powers(A, p, e->pow);
    e->hash = hash;
    e->used = ++c->clock;
    int finite = e->nu > 0.0 && e->nu < INFINITY;
    for (size_t i = 0; finite && i < 5 * pp; i++)
        finite = isfinite(e->pow[i]);
    if (!finite) { /* not kept: forgotten at once */
        e->hash = ~hash;
        e->used = 0;
        return NULL;
    }
    return e;
}
