/* SPDX-License-Identifier: GPL-3.0-or-later */
/* slider.c — one Jenkins slider's norm out of line and the slider separated by lift-off
 * (slider.h, whose inline return mapping is the slider's in contact). */
#include <stddef.h>

#include "slider.h"

double fr_slider_norm(const double *d, int dim)
{
    return fr_slider_norm_inline(d, dim);
}

void fr_slider_separated(int dim, const double *u, double *f, double *w, double *t, double *dfdg)
{
    for (int a = 0; a < dim; a++) {
        w[a] = u[a];
        f[a] = 0.0;
        if (dfdg != NULL)
            dfdg[a] = 0.0;
    }
    if (t != NULL)
        for (int a = 0; a < dim * dim; a++)
            t[a] = 0.0;
}
