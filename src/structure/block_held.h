/* SPDX-License-Identifier: GPL-3.0-or-later */
/* block_held.h — internal: the block and shifts a near-stick factor holds (masked_factor.h's
 * and contact_sparse.h's), compared and kept. */
#ifndef FRICREG_BLOCK_HELD_H
#define FRICREG_BLOCK_HELD_H

#include <stddef.h>

/* Whether the block set[m] with shift[m] (either NULL: none) is the one a factor holds,
 * held_set[m] and held_shift[m] (held 0: none held); and the block kept as held. The factors
 * of the near-stick block (masked_factor.c's, contact_sparse.c's) refactor only when it
 * moves. */
int fr_block_is_held(size_t m, int held, const unsigned char *held_set, const double *held_shift,
                     const unsigned char *set, const double *shift);
/* Whether set[m] (NULL: none) holds the same rows as held_set[m], whatever the shifts (held 0:
 * none held). */
int fr_block_holds_rows(size_t m, int held, const unsigned char *held_set,
                        const unsigned char *set);
void fr_block_hold(size_t m, unsigned char *held_set, double *held_shift, const unsigned char *set,
                   const double *shift);

#endif
