/* SPDX-License-Identifier: GPL-3.0-or-later */
/* slider.c — one Jenkins slider's return mapping (slider.h).
 *
 * The return works on d = u - w_c, not on f_tr = kt d: |d| and the direction d/|d| stay finite
 * whenever d does, so a stiff spring (kt d beyond 1e308) still slides to f = b n, and the
 * sliding tangent kt (b/|f_tr|) is computed as b/|d|. */
#include <math.h>
#include <stddef.h>

#include "slider.h"

double fr_slider_norm(const double *d, int dim)
{
    if (dim == 3)
        return hypot(hypot(d[0], d[1]), d[2]);
    return dim == 1 ? fabs(d[0]) : hypot(d[0], d[1]);
}

int fr_slider_return(double kt, double b, double dbdg, int dim, const double *u, const double *wc,
                     double *f, double *w, double *t, double *dfdg)
{
    double d[3] = {0.0, 0.0, 0.0}, ui[3] = {0.0, 0.0, 0.0};
    for (int a = 0; a < dim; a++) {
        d[a] = u[a] - wc[a];
        ui[a] = u[a];
    }
    double r = fr_slider_norm(d, dim);
    if (kt * r <= b) { /* stick: f = kt d, tangent kt I */
        for (int a = 0; a < dim; a++) {
            f[a] = kt * d[a];
            w[a] = wc[a];
            if (dfdg != NULL)
                dfdg[a] = 0.0;
        }
        if (t != NULL)
            for (int a = 0; a < dim * dim; a++)
                t[a] = (a % (dim + 1) == 0) ? kt : 0.0;
        return 0;
    }
    double nrm[3] = {d[0] / r, d[1] / r, d[2] / r}, s = b / r;
    for (int a = 0; a < dim; a++) {
        f[a] = b * nrm[a];
        w[a] = ui[a] - f[a] / kt;
        if (dfdg != NULL)
            dfdg[a] = dbdg * nrm[a];
    }
    if (t != NULL) /* kt (b/|f_tr|)(I - n n^T) = (b/|d|)(I - n n^T); 0 in 1-D */
        for (int a = 0; a < dim; a++)
            for (int c = 0; c < dim; c++)
                t[dim * a + c] = dim == 1 ? 0.0 : s * ((a == c) - nrm[a] * nrm[c]);
    return 1;
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
