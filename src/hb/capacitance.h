/* SPDX-License-Identifier: GPL-3.0-or-later */
/* capacitance.h — internal: Newton's matrix solved by its capacitance on the rows of Ĵ that are not diagonal (capacitance.c). */
#ifndef FRICREG_HB_CAPACITANCE_H
#define FRICREG_HB_CAPACITANCE_H

#include "hb_internal.h"

/* The room for the model's shape (about 32 (H + 1) m² + 16 m² bytes), kept while m and H
 * stay, so that a solve allocates nothing; 1, or 0 (none: the split says nq + 1). */
int fr_hb_capacitance_reserve(fricreg_hb *hb);

/* Newton's matrix I + Ĝ Ĵ at the Jacobians in jq and the factored Ω's G_h (nd = nq), or
 * bordered by the column col[nq] and the row row[nq + 1] (nd = nq + 1, col and row copied),
 * split into the rows of Ĵ that are a stiffness on the diagonal (a stuck element's harmonics,
 * a closed contact's normal rows, the rows of no force) and the s others. Returns s, the order
 * of the capacitance matrix it would factor (plus the border); nq + 1 without the room
 * (fr_hb_capacitance_reserve's). Nothing factored yet. */
size_t fr_hb_capacitance_split(fricreg_hb *hb, size_t nd, const double *col, const double *row);

/* Factors the split's matrix (once; later calls return at once): each harmonic's stuck block
 * I + G_h,LL K_L (LAPACK's zgetrf), the columns W = A0^-1 Ĝ P_S, the capacitance
 * C = I + Ĵ_S W, bordered, (dgetrf). FRICREG_OK; FRICREG_ESINGULAR where C is, so A is
 * (message recorded); FR_HB_STUCK_SINGULAR (no message) where A0 is, A perhaps not. */
#define FR_HB_STUCK_SINGULAR (-1)
int fr_hb_capacitance_factor(fricreg_hb *hb, const char *fn);

/* sol[nd] = A^-1 rhs[nd] on the factor (rhs == sol allowed): Woodbury's identity,
 * A^-1 = A0^-1 − W C^-1 Ĵ_S A0^-1, bordered by block elimination. */
void fr_hb_capacitance_solve(fricreg_hb *hb, const double *rhs, double *sol);

/* The sign of det A (bordered: of the bordered matrix) from the factor: det A0 det C, the
 * harmonics h >= 1 of A0 positive (|det|² of a complex block). */
double fr_hb_capacitance_det_sign(const fricreg_hb *hb);

/* The border the split copied: col[nq], row[nq + 1] (a dense solve's, where A0 is singular). */
void fr_hb_capacitance_border(const fricreg_hb *hb, const double **col, const double **row);

void fr_hb_capacitance_free(fricreg_hb *hb);

#endif
