/* SPDX-License-Identifier: GPL-3.0-or-later */
/* aft_roots.h — internal: the switch points of the exact AFT of 1-D Jenkins sliders
 * (aft_roots.c): the velocity reversals of u and the angle where a stick ends in a slip, roots
 * of trigonometric polynomials, for the march (aft_exact.c). */
#ifndef FRICREG_JOINT_AFT_ROOTS_H
#define FRICREG_JOINT_AFT_ROOTS_H

#include "aft_internal.h"

/* Angles of the velocity reversals into a->rev (sorted), the direction after each into
 * a->rdir; their count into *m (0 for a constant u). du: u' scaled, as coefficients. */
int fr_aft_reversals(fricreg_aft *a, const char *fn, const double *u, int *m);

/* The angle in [al, be] where u = target: u is monotone there in the direction dir (al, be
 * consecutive reversals) and dir (u(be) − target) > 0, so the root is unique and bracketed.
 * GSL's Brent on the bracket to a width of 4 DBL_EPSILON |theta| (at most 100 iterations:
 * Brent's guarantee is about 4 log2(2 pi/eps) evaluations), then one Newton step. The
 * function is finite (inputs checked) and the bracket valid, so GSL has nothing to report to
 * its error handler. Where rounding puts u(al) beyond the target already, the slip starts at
 * al. */
double fr_aft_slip_onset(fricreg_aft *a, const double *u, double target, int dir, double al,
                         double be);

#endif
