/* SPDX-License-Identifier: GPL-3.0-or-later */
/* points.h — the continuation's store of points (points.c): room for them, and one point
 * stored with its extras (the tangent's parameter component, the determinant's sign, its
 * stability) as the driver's last solution. */
#ifndef FRICREG_HB_POINTS_H
#define FRICREG_HB_POINTS_H

#include <stddef.h>

#include "corrector.h"

/* Room for `want` points (at most max_points): FRICREG_OK, or FRICREG_ENOMEM with the points
 * kept. */
int fr_hb_points_reserve(fricreg_hb *hb, size_t want);

/* The point at qt (parameter p) stored with tw and det, its stability by Hill's method when on
 * (already in xsol when hill_done); only counted when b keeps no points. */
int fr_hb_store_point(fricreg_hb *hb, const char *fn, struct fr_hb_branch *b, double p, double tw,
                      double det, int hill_done);

/* The last solution (k = FRICREG_HB_SOLUTION) or stored point k: its unknowns q, Ω and
 * excitation level; FRICREG_EINVAL when there is none or the model changed since. */
int fr_hb_stored_solution(fricreg_hb *hb, const char *fn, size_t k, const double **q, double *omega,
                          double *level);

#endif
