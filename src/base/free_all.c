/* SPDX-License-Identifier: GPL-3.0-or-later */
#include <stdlib.h>
#include "free_all.h"

void fr_free_each(size_t n, void *const ptrs[])
{
    for (size_t i = 0; i < n; i++)
        free(ptrs[i]);
}
