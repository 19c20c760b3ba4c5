/* SPDX-License-Identifier: GPL-3.0-or-later */
/* dynamic.h — internal: the dynamic stiffnesses D_h factored and condensed on the elements' coordinates (dynamic.c). */
#ifndef FRICREG_HB_DYNAMIC_H
#define FRICREG_HB_DYNAMIC_H

#include "hb_internal.h"

/* Factors D_h(omega) for h = 0..H and forms Y, G, ql (and dql when deriv); keeps them while
 * omega stays. FRICREG_OK or FRICREG_ESINGULAR (message recorded, with fn). */
int fr_hb_factor(fricreg_hb *hb, const char *fn, double omega, int deriv);

/* The largest over h of D_h's 1-norm condition number at the factored frequency, estimated
 * from its LU factor (KLU's klu_condest, or LAPACK's zgecon for a dense model: Higham's
 * estimator, a few solves a harmonic), into *kappa; 0 when nothing is factored or there are
 * no elements. u kappa bounds the relative forward error of the solves Y_h (Higham, Accuracy
 * and Stability of Numerical Algorithms, 2nd ed., Thm. 7.2 and 9.3), the level below which
 * the residual of (R) is noise as Ω moves. hb->D (dense) holds D_H's factor again after it.
 * FRICREG_OK, FRICREG_ESINGULAR, FRICREG_ENOMEM (message recorded, with fn). */
int fr_hb_condition(fricreg_hb *hb, const char *fn, double *kappa);

/* out[e (m+1) + c] (complex, c <= m) = s sum_k L(e, k) B[k (m+1) + c] into G (c < m) and q
 * (c = m), L(e, k) = J(e, k) when left is NULL, else left[k (m+1) + e] (a column of Y as a row):
 * the condensation J Y_h, or with left = Y_h the derivative −Y_h^T D' Y_h from Z = D' Y_h. */
void fr_hb_project(const fricreg_hb *hb, const double *left, const double *B, double s, double *G,
                   double *q);

/* dR/dΩ of (R) at the forces fq: (dG/dΩ) F − load dql/dΩ, into out[nq], at the factored Ω
 * (Y_h's): −Y_J^T D_h' (Y_h [F; −load]) a harmonic, products with vectors (O(n m + n²) a
 * harmonic; no dG/dΩ is formed), residual.c's real form. */
void fr_hb_domega(fricreg_hb *hb, double *out);

/* D_h(omega)^-1 B in place for nrhs complex right-hand sides B[nrhs n] (each contiguous), with
 * the damping in force (hb->xi, no_c): a dense model's D_h factored again into hb->D (the
 * scratch of one harmonic's factor), a sparse one's by KLU (sparse.c). FRICREG_OK,
 * FRICREG_ESINGULAR, FRICREG_ENONFINITE, FRICREG_ENOMEM (message recorded, with fn). */
int fr_hb_harmonic_solve(fricreg_hb *hb, const char *fn, int h, double omega, size_t nrhs,
                         double *B);

#endif
