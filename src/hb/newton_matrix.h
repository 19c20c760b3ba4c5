/* SPDX-License-Identifier: GPL-3.0-or-later */
/* newton_matrix.h — internal: Newton's matrix of (R), dense or by its capacitance (newton_matrix.c). */
#ifndef FRICREG_HB_NEWTON_MATRIX_H
#define FRICREG_HB_NEWTON_MATRIX_H

#include "hb_internal.h"

/* The least nq solved by the capacitance, and the share s / nd at or below which it is: at
 * nq = 672 (bench/hb_interface_rom.c, 32 contacts) the dense LU costs what the capacitance's
 * columns do. */
#define FR_HB_CAPACITANCE_MIN 512
#define FR_HB_CAPACITANCE_SHARE 0.8

/* Newton's matrix at the Jacobians in jq and the factored Ω: I + Ĝ Ĵ (nd = nq), or bordered
 * [I + Ĝ Ĵ, col; row^T] (nd = nq + 1: col[nq], row[nq + 1]), recorded for the next
 * fr_hb_newton_solve: dense (residual.c's fr_hb_matrix into A), or by its capacitance where
 * few rows of Ĵ are not diagonal (capacitance.c). */
void fr_hb_newton_matrix(fricreg_hb *hb, size_t nd, const double *col, const double *row);

/* sol = A⁻¹ rhs (nd each; rhs == sol allowed) for the matrix recorded, factored at the first
 * solve after it. FRICREG_OK, FRICREG_ESINGULAR (message recorded, with fn). */
int fr_hb_newton_solve(fricreg_hb *hb, const char *fn, double *rhs, double *sol);

/* The sign of the determinant of the matrix factored last. */
double fr_hb_newton_det_sign(const fricreg_hb *hb);

#endif
