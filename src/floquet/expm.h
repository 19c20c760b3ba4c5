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

#endif
