/* SPDX-License-Identifier: GPL-3.0-or-later */
/* block_held.c — the block and shifts a near-stick factor holds, compared and kept
 * (block_held.h). */
#include "block_held.h"

int fr_block_is_held(size_t m, int held, const unsigned char *held_set, const double *held_shift,
                     const unsigned char *set, const double *shift)
{
    if (!held)
        return 0;
    for (size_t i = 0; i < m; i++) {
        unsigned char in = set != NULL && set[i];
        if (in != held_set[i] || (in && (shift ? shift[i] : 0.0) != held_shift[i]))
            return 0;
    }
    return 1;
}

int fr_block_holds_rows(size_t m, int held, const unsigned char *held_set, const unsigned char *set)
{
    if (!held)
        return 0;
    for (size_t i = 0; i < m; i++)
        if ((set != NULL && set[i]) != held_set[i])
            return 0;
    return 1;
}

void fr_block_hold(size_t m, unsigned char *held_set, double *held_shift, const unsigned char *set,
                   const double *shift)
{
    for (size_t i = 0; i < m; i++) {
        held_set[i] = set != NULL && set[i];
        held_shift[i] = held_set[i] && shift ? shift[i] : 0.0;
    }
}
