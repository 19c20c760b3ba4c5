/* SPDX-License-Identifier: GPL-3.0-or-later */
/* residual.h — internal: the HB equations (R): the residual, Newton's matrix, their Ω and λ derivatives (residual.c). */
#ifndef FRICREG_HB_RESIDUAL_H
#define FRICREG_HB_RESIDUAL_H

#include "hb_internal.h"

/* The real LU solve of Newton's matrix A[nd nd] (factored in place) for rhs[nd] into sol[nd]
 * (may alias rhs). FRICREG_OK or FRICREG_ESINGULAR (a pivot below 1e-14 of the matrix's
 * largest entry; message recorded). */
int fr_hb_lu_solve(fricreg_hb *hb, const char *fn, size_t nd, double *rhs, double *sol);

/* The forces and, with jac, Jacobians of every element at q[nq] (fq, jq), then the residual
 * (R) into R[nq] at the factored Ω. FRICREG_OK or FRICREG_EINTEGRATOR (the AFT). */
int fr_hb_residual(fricreg_hb *hb, const char *fn, const double *q, double *R, int jac);

/* Newton's matrix I + G ∂F/∂q from the Jacobian blocks jac[me (rpe nc)²], into A with leading
 * dimension ld (rows and columns 0..nq-1). */
void fr_hb_matrix(fricreg_hb *hb, const double *jac, double *A, size_t ld);

/* out[nq] = G F − load ql in (R)'s real form from the forces f[nq] and a complex
 * G[(H+1) m m], ql[(H+1) m] (ql NULL: none), e.g. a derivative of the condensation. */
void fr_hb_apply(const fricreg_hb *hb, const double *G, const double *ql, double load,
                 const double *f, double *out);

/* dR/dλ = −ql in (R)'s real form, into out[nq] (the excitation level's derivative). */
void fr_hb_dlevel(const fricreg_hb *hb, double *out);

/* The displacement scale of the convergence test: max(|q|_inf, |ql|_inf), or 1 if both 0. */
double fr_hb_scale(const fricreg_hb *hb, const double *q);

#endif
