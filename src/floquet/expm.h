/* SPDX-License-Identifier: GPL-3.0-or-later */
/* expm.h — the exponential of a dense real matrix (expm.c), for the exact monodromy's pieces
 * (monodromy.c). */
#ifndef FRICREG_HB_EXPM_H
#define FRICREG_HB_EXPM_H

#include <stddef.h>

/* Z = X Y for column-major X, Y, Z [p p] (BLAS dgemm; Z aliases neither). */
void fr_hb_product(size_t p, const double *X, const double *Y, double *Z);

/* Doubles of fr_hb_expm's workspace for order p: 6 p². */
size_t fr_hb_expm_work(size_t p);

/* E = e^A for A[p p] (column-major, or row-major alike: e^(A^T) = (e^A)^T), E[p p] not aliasing
 * A, work[fr_hb_expm_work(p)], piv[p]; no allocation; p < 2^31 with p³ flops in range.
 * Returns 0; −1 if A has an entry that is not finite (E then unset); LAPACK dgesv's INFO > 0
 * if the Padé denominator is singular (not for a finite A: its norm is scaled into the
 * approximant's range). */
int fr_hb_expm(const double *A, size_t p, double *E, double *work, int *piv);

/* For one matrix Â exponentiated at many t (a piece's state matrix over the points of a
 * branch): N = Â/ν, ν = ‖Â‖₁, and N², N⁴, N⁶, N⁸ into pow[5 p p] (column-major), the products
 * every approximant of fr_hb_expm would form again (4 products, once). Returns ν: 0 for Â = 0
 * and infinity for an entry that is not finite (pow then unset). */
double fr_hb_expm_powers(const double *A, size_t p, double *pow);

/* E = e^(t Â) for t >= 0 from fr_hb_expm_powers' pow and ν (finite, > 0): fr_hb_expm's
 * algorithm on t Â, with the powers' products taken from pow, so that a [13/13] approximant
 * takes 3 products and s squarings instead of 6 and s, an [m/m] one 1 product instead of
 * m/2 + 1, besides the solve. E[p p] not aliasing pow; work[fr_hb_expm_work(p)], piv[p]; no
 * allocation. Returns fr_hb_expm's codes (−1: t ν not finite). */
int fr_hb_expm_at(const double *pow, double nu, size_t p, double t, double *E, double *work,
                  int *piv);

#endif
