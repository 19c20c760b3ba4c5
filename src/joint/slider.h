/* SPDX-License-Identifier: GPL-3.0-or-later */
/* slider.h — one Jenkins slider, the kernel that the Jenkins and Iwan elements share: the
 * return mapping of a spring kt in series with a Coulomb slider of bound b, its consistent
 * tangent in u and its derivative in the normal displacement g (fricreg_jenkins.h; Simo &
 * Hughes 1998, Ch. 1 and 3), and the separated slider of lift-off. */
#ifndef FRICREG_JOINT_SLIDER_H
#define FRICREG_JOINT_SLIDER_H

/* |d| of a vector of dim (1, 2 or 3) components. */
double fr_slider_norm(const double *d, int dim);

/* The return mapping of one slider (dim 1, 2 or 3) from its committed position wc[dim] at u[dim], with bound
 * b >= 0 and db/dg = dbdg (0 under a fixed bound), u - wc and |u - wc| finite (the caller
 * checks). Writes the force f[dim], the slider's trial position w[dim] (wc in a stick), and,
 * where not NULL, the tangent t[dim dim] (row-major) and df/dg dfdg[dim]:
 *   stick (kt |d| <= b): f = kt d, t = kt I, df/dg = 0;
 *   slip:  f = b n, w = u - f/kt, t = (b/|d|)(I - n n^T) (0 in 1-D), df/dg = dbdg n,
 * with d = u - wc and n = d/|d|. f may alias u (u is read before f is written). Returns 1 in
 * slip, 0 in stick. */
int fr_slider_return(double kt, double b, double dbdg, int dim, const double *u, const double *wc,
                     double *f, double *w, double *t, double *dfdg);

/* A separated slider (lift-off, N = 0 with the contact open): f = 0, the slider follows the
 * displacement (w = u, the spring unloaded), and t, dfdg (where not NULL) are 0. */
void fr_slider_separated(int dim, const double *u, double *f, double *w, double *t, double *dfdg);

#endif
