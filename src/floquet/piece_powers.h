/* SPDX-License-Identifier: GPL-3.0-or-later */
/* piece_powers.h — the exact monodromy's piece matrices kept with their powers (piece_powers.c),
 * so that a piece met again at another duration is exponentiated by fr_hb_expm_at (expm.h). */
#ifndef FRICREG_HB_PIECE_POWERS_H
#define FRICREG_HB_PIECE_POWERS_H

#include <stddef.h>

/* One kept matrix Â [p p] (column-major), its fr_hb_expm_powers and ν = ‖Â‖₁. */
struct fr_hb_piece {
    double *A, *pow, nu;
    size_t p;
    unsigned long hash, used;
};

/* The kept matrices of orders up to pmax: at most cap (0: none kept), in one block. */
struct fr_hb_pieces {
    size_t pmax, cap, count;
    unsigned long clock;
    struct fr_hb_piece *piece; /* [cap] */
    double *block;             /* [cap 6 p p] */
};

/* Room for matrices of orders up to pmax: as many as FR_HB_PIECES_MAX and FR_HB_PIECES_BYTES
 * allow (cap 0 past the budget: every piece is then exponentiated afresh). Returns 0, or −1
 * without memory (nothing allocated). The results depend on pmax only, never on the memory. */
#define FR_HB_PIECES_MAX 16
#define FR_HB_PIECES_BYTES ((size_t)32 << 20)
int fr_hb_pieces_init(struct fr_hb_pieces *c, size_t pmax);

/* Frees the kept matrices (a second call does nothing). */
void fr_hb_pieces_free(struct fr_hb_pieces *c);

/* The kept entry whose Â equals A [p p] bit for bit; else A kept in the least recently used
 * place with its powers (4 products). NULL where none is kept (cap 0, p > pmax) or A's powers
 * are not finite. The entry stays valid until the next call. */
const struct fr_hb_piece *fr_hb_pieces_find(struct fr_hb_pieces *c, const double *A, size_t p);

#endif
