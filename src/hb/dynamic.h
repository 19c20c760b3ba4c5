/* SPDX-License-Identifier: GPL-3.0-or-later */
/* dynamic.h — internal: the dynamic stiffnesses D_h factored and condensed on the elements' coordinates (dynamic.c). */
#ifndef FRICREG_HB_DYNAMIC_H
#define FRICREG_HB_DYNAMIC_H

#include "hb_internal.h"

/* Factors D_h(omega) for h = 0..H and forms Y, G, ql (and dG, dql when deriv); keeps them
 * while omega stays. FRICREG_OK or FRICREG_ESINGULAR (message recorded, with fn). */
int fr_hb_factor(fricreg_hb *hb, const char *fn, double omega, int deriv);

/* out[e (m+1) + c] (complex, c <= m) = s sum_k L(e, k) B[k (m+1) + c] into G (c < m) and q
 * (c = m), L(e, k) = J(e, k) when left is NULL, else left[k (m+1) + e] (a column of Y as a row):
 * the condensation J Y_h, or with left = Y_h the derivative −Y_h^T D' Y_h from Z = D' Y_h. */
void fr_hb_project(const fricreg_hb *hb, const double *left, const double *B, double s, double *G,
                   double *q);

#endif
