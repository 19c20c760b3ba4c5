/* SPDX-License-Identifier: GPL-3.0-or-later */
/* reduction.h — the linear structure condensed onto the dofs the elements touch, for the
 * condensed stability (reduction.c, Craig–Bampton); and the model as dense arrays. */
#ifndef FRICREG_HB_REDUCTION_H
#define FRICREG_HB_REDUCTION_H

#include "floquet_internal.h"

/* A linear model M x'' + C x' + K x + J^T f of order n: M, K, C [n n] symmetric (row- and
 * column-major alike), J [m n] row-major (hb->m rows). */
struct fr_hb_linear_model {
    size_t n;
    const double *M, *K, *C, *J;
};

/* The driver's M, C (or Rayleigh's a0 M + a1 K) and K into M, C, K [n n], dense, from the dense
 * arrays or the sparse pattern of D_h. */
void fr_hb_dense_model(const fricreg_hb *hb, double *M, double *C, double *K);

/* The number of dofs some row of J touches (the boundary of the reduction). */
size_t fr_hb_boundary_dofs(const fricreg_hb *hb);

/* The reduced model for a solution at omega into *out (valid until the next call or the
 * driver's model changes): at the first call after a model change the boundary's static
 * constraint modes, every interior mode and every mode of the structure are computed (O(n³)
 * once); at each call the interior
 * modes of ω_r < FR_HB_REDUCTION_CUT omega are kept (the model rebuilt when that number
 * changes). FRICREG_OK; FRICREG_ENOMEM; FRICREG_ESINGULAR (K_II not positive definite, or
 * LAPACK's dsygvd failed); FRICREG_EINVAL (more dofs than FR_HB_REDUCTION_MAX_DOFS);
 * messages recorded with fn. */
int fr_hb_reduction_update(fricreg_hb *hb, const char *fn, double omega,
                           struct fr_hb_linear_model *out);

/* The exponents (Re λ, Im λ with Im λ in (−Ω/2, Ω/2]) of the modes the last update left out,
 * as many as the structure's highest modes (no element), each a damped oscillator of its own
 * (ω², φ^T C φ), into exps: returns their number, 2 (interior dofs − kept modes). */
size_t fr_hb_reduction_truncated(const fricreg_hb *hb, double omega, double *exps);

/* Frees the reduction (a second call does nothing). */
void fr_hb_reduction_free(fricreg_hb *hb);

/* Interior modes kept: those below FR_HB_REDUCTION_CUT times the orbit's frequency Ω; the
 * others answer quasi-statically, which the constraint modes hold. The error is the first
 * left-out mode's, about (Ω/ω_r)^4 on the chains of tests/floquet/test_hb_condensed.c and
 * bench/hb_stability_size.c (the largest multiplier 2.4e-2 off with the first at 20 Ω, 1.4e-4
 * at 54 Ω); not H's: the monodromy of the orbit does not depend on how many harmonics found
 * it. */
#define FR_HB_REDUCTION_CUT 50.0

/* Dofs at most: the model and its eigenproblems are dense (8 ndof² doubles). */
#define FR_HB_REDUCTION_MAX_DOFS 4096

#endif
