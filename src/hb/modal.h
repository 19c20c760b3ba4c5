/* SPDX-License-Identifier: GPL-3.0-or-later */
/* modal.h — internal: the dynamic stiffnesses' solves through the modes of (K, M) where the damping is proportional (modal.c). */
#ifndef FRICREG_HB_MODAL_H
#define FRICREG_HB_MODAL_H

#include "hb_internal.h"

/* The least n, and the least reciprocal condition number of M, at which the modes serve
 * (fricreg_hb_set_receptance's AUTO). */
#define FR_HB_MODAL_MIN_DOFS 200
#define FR_HB_MODAL_MIN_RCOND 1e-6

/* Whether Y_h is solved through the modes at this call: a dense model with Rayleigh damping
 * (or none: a zero damping matrix, or the nonlinear modes' modal option), n >= hb->modal_min, and the modes of (K, M)
 * at hand (computed here once a model: LAPACK's dsygvd). 0 where M is not positive definite,
 * its reciprocal condition number is below FR_HB_MODAL_MIN_RCOND, or memory is short: the LU
 * then serves, with the same results to rounding. */
int fr_hb_modal_ready(fricreg_hb *hb);

/* Y_h = Φ diag(1/d_k) Φ^T [J^T | P_h], d_k = λ_k (1 + i hΩ a1) + i hΩ (a0 − xi) − (hΩ)², into
 * hb->Y (h's block, dynamic.h's layout). FRICREG_OK;
 * FRICREG_ESINGULAR where some |d_k| is below 1e-14 of the terms' scale (message with fn). */
int fr_hb_modal_solve(fricreg_hb *hb, const char *fn, int h, double omega);

/* Frees the modes and their room. */
void fr_hb_modal_free(fricreg_hb *hb);

#endif
