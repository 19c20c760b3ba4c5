/* SPDX-License-Identifier: GPL-3.0-or-later */
/* model_levels.c — the memory of a model at n levels (model.h). */
#include <math.h>
#include <stdlib.h>

#include "model.h"

double *fr_fit_levels_alloc(size_t n, size_t np, struct fr_fit_levels *out, double **guess)
{
    double *block = malloc(n * (4 + 2 * np) * sizeof *block);
    if (block == NULL)
        return NULL;
    out->freq_hz = block;
    out->zeta = block + n;
    out->modal = block + 2 * n;
    out->dfreq = block + 3 * n;
    out->dzeta = out->dfreq + n * np;
    *guess = out->dzeta + n * np;
    for (size_t i = 0; i < n; i++)
        (*guess)[i] = NAN;
    return block;
}
