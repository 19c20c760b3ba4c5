/* SPDX-License-Identifier: GPL-3.0-or-later */
/* free_all.h — the arrays an object allocated together, freed in one line:
 * FR_FREE_ALL(a->x, a->y, a->z) where a free() per array was a line each. */
#ifndef FRICREG_FREE_ALL_H
#define FRICREG_FREE_ALL_H

#include <stddef.h>

/* Frees each of the n pointers (any may be NULL), as free() one by one would. */
void fr_free_each(size_t n, void *const ptrs[]);

/* The list is a compound literal, so its length is counted at compile time. */
#define FR_FREE_ALL(...) \
    fr_free_each(sizeof((void *[]){__VA_ARGS__}) / sizeof(void *), (void *[]){__VA_ARGS__})

#endif
