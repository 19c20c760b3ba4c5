/* SPDX-License-Identifier: GPL-3.0-or-later */
/* newton_matrix.h — internal: Newton's matrix of (R), dense or by its capacitance (newton_matrix.c). */
#ifndef FRICREG_HB_NEWTON_MATRIX_H
#define FRICREG_HB_NEWTON_MATRIX_H

#include "hb_internal.h"

/* The least nq solved by the capacitance, and the share s / nd at or below which it is. The
 * linear solve alone on a coupled chain of slipping contacts (s = 2 nq / 3): nq = 336, 0.6 ms
 * against the dense LU's 0.9; 672, 2.7 against 5.4; 1344, 16 against 36. Below 512 either
 * takes a few ms; near s = nd the capacitance is the dense LU's order and its columns more. */
#define FR_HB_CAPACITANCE_MIN 512
#define FR_HB_CAPACITANCE_SHARE 0.8

/* The least order of a dense Newton's matrix solved by iterative refinement on the LU factor
 * of an earlier one (newton_matrix.c) before its own LU. Sweeps of the interface ROM lifting
 * off (bench/hb_interface_rom.c): at order 673 (32 contacts) as fast either way; at 1786
 * (85) 65 s against 104, the same points. */
#define FR_HB_REFINE_MIN 1024

/* The capacitance's room when the model is whole and nq >= capacitance_min (allocated
 * here, at the element setters, so that a solve allocates nothing; without it, the dense
 * LU), else none. 1, or 0 where the room was wanted and could not be allocated. */
int fr_hb_newton_matrix_room(fricreg_hb *hb);

/* Newton's matrix at the Jacobians in jq and the factored Ω: I + Ĝ Ĵ (nd = nq), or bordered
 * [I + Ĝ Ĵ, col; row^T] (nd = nq + 1: col[nq], row[nq + 1]), recorded for the next
 * fr_hb_newton_solve: dense (residual.c's fr_hb_matrix into A), or by its capacitance where
 * few rows of Ĵ are not diagonal (capacitance.c). */
void fr_hb_newton_matrix(fricreg_hb *hb, size_t nd, const double *col, const double *row);

/* sol = A⁻¹ rhs (nd each; rhs == sol allowed) for the matrix recorded: by refinement on the
 * factor held (fr_hb_newton_held) where it converges, else by its own factor, made at the
 * first solve that needs it. FRICREG_OK, FRICREG_ESINGULAR (message recorded, with fn). */
int fr_hb_newton_solve(fricreg_hb *hb, const char *fn, double *rhs, double *sol);

/* Whether the recorded matrix, not yet factored, will first be solved by refinement on the
 * dense LU factor A holds from an earlier matrix of its order (the order at least held_min). */
int fr_hb_newton_held(const fricreg_hb *hb);

/* Forgets the factor held, unless it is the recorded matrix's own: a public solve or
 * continuation starts from factors of its own, so the same call gives the same bits whatever
 * ran before it. */
void fr_hb_newton_forget(fricreg_hb *hb);

/* The sign of the determinant of the matrix factored last; after a solve by refinement, the
 * recorded matrix's too: refinement converged where the eigenvalues of A_held⁻¹ A lie within
 * the unit disk about 1, so det(A_held⁻¹ A) > 0. */
double fr_hb_newton_det_sign(const fricreg_hb *hb);

#endif
