/* SPDX-License-Identifier: GPL-3.0-or-later */
/* slider.h — one Jenkins slider, the kernel that the Jenkins and Iwan elements share: the
 * return mapping of a spring kt in series with a Coulomb slider of bound b, its consistent
 * tangent in u and its derivative in the normal displacement g (fricreg_jenkins.h; Simo &
 * Hughes 1998, Ch. 1 and 3), and the separated slider of lift-off (slider.c). The return is
 * inline, as the laws' kernels of law/law.h are: a caller's constant dim specializes it (the
 * element types' kernel, element_sliders.c).
 *
 * The return works on d = u - w_c, not on f_tr = kt d: |d| and the direction d/|d| stay finite
 * whenever d does, so a stiff spring (kt d beyond 1e308) still slides to f = b n, and the
 * sliding tangent kt (b/|f_tr|) is computed as b/|d|. */
#ifndef FRICREG_JOINT_SLIDER_H
#define FRICREG_JOINT_SLIDER_H

#include <math.h>
#include <stddef.h>

/* |d| of a vector of dim (1, 2 or 3) components: inline for the return mapping, whose d has 3,
 * and out of line (slider.c) for callers with shorter arrays. */
static inline double fr_slider_norm_inline(const double *d, int dim)
{
    if (dim == 3)
        return hypot(hypot(d[0], d[1]), d[2]);
    return dim == 1 ? fabs(d[0]) : hypot(d[0], d[1]);
}
double fr_slider_norm(const double *d, int dim);

/* The return mapping of one slider (dim 1, 2 or 3) from its committed position wc[dim] at u[dim], with bound
 * b >= 0 and db/dg = dbdg (0 under a fixed bound), u - wc and |u - wc| finite (the caller
 * checks). Writes the force f[dim], the slider's trial position w[dim] (wc in a stick), and,
 * where not NULL, the tangent t[dim dim] (row-major) and df/dg dfdg[dim]:
 *   stick (kt |d| <= b): f = kt d, t = kt I, df/dg = 0;
 *   slip:  f = b n, w = u - f/kt, t = (b/|d|)(I - n n^T) (0 in 1-D), df/dg = dbdg n,
 * with d = u - wc and n = d/|d|. f may alias u (u is read before f is written). Returns 1 in
 * slip, 0 in stick. */
static inline int fr_slider_return(double kt, double b, double dbdg, int dim, const double *u,
                                   const double *wc, double *f, double *w, double *t, double *dfdg)
{
    double d[3] = {0.0, 0.0, 0.0}, ui[3] = {0.0, 0.0, 0.0};
    for (int a = 0; a < dim; a++) {
        d[a] = u[a] - wc[a];
        ui[a] = u[a];
    }
    double r = fr_slider_norm_inline(d, dim);
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
    double nrm[3] = {0.0, 0.0, 0.0};
    for (int a = 0; a < dim;
         a++) /* dim's divisions only: the caller's constant dim drops the rest */
        nrm[a] = d[a] / r;
    for (int a = 0; a < dim; a++) {
        f[a] = b * nrm[a];
        w[a] = ui[a] - f[a] / kt;
        if (dfdg != NULL)
            dfdg[a] = dbdg * nrm[a];
    }
    if (t != NULL && dim == 1) /* kt (b/|f_tr|)(I - n n^T) = (b/|d|)(I - n n^T): 0 in 1-D */
        t[0] = 0.0;
    else if (t != NULL) {
        double s = b / r;
        for (int a = 0; a < dim; a++)
            for (int c = 0; c < dim; c++)
                t[dim * a + c] = s * ((a == c) - nrm[a] * nrm[c]);
    }
    return 1;
}

/* A separated slider (lift-off, N = 0 with the contact open): f = 0, the slider follows the
 * displacement (w = u, the spring unloaded), and t, dfdg (where not NULL) are 0. */
void fr_slider_separated(int dim, const double *u, double *f, double *w, double *t, double *dfdg);

#endif
