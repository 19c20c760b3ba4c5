/* SPDX-License-Identifier: GPL-3.0-or-later */
/* monodromy.h — the stability of a periodic HB solution from the exact monodromy of its
 * piecewise-linear orbit (monodromy.c). */
#ifndef FRICREG_HB_MONODROMY_H
#define FRICREG_HB_MONODROMY_H

#include "floquet_internal.h"

/* Whether the elements are piecewise linear in the sense of the monodromy: 1-D Jenkins and
 * Iwan elements under a constant normal load or with lift-off (not the 3-D contact), and some
 * set. */
int fr_hb_monodromy_applies(const fricreg_hb *hb);

/* The exact monodromy at the solution whose coefficients q are those of the last residual with
 * Jacobians (hb->qjac), at omega: into out[4n + 2] stable (1.0/0.0), the largest |Floquet
 * multiplier| and the 2n exponents (re, im), as fr_hb_hill. Of the driver's model, or with
 * condensed = 1 of the model condensed onto the elements' dofs (reduction.h), whose truncated
 * interior modes add their own exponents. FRICREG_OK, FRICREG_ENOMEM (the workspace, grown
 * here), FRICREG_ESINGULAR (M; condensed: K_II), FRICREG_EINVAL (condensed: too many interior
 * dofs), FRICREG_ENONFINITE (a piece's matrix), FRICREG_EINTEGRATOR (the AFT's root solver,
 * LAPACK's QR); messages recorded with fn. */
int fr_hb_monodromy(fricreg_hb *hb, const char *fn, double omega, int condensed, double *out);

/* The workspace for the driver's sizes, made or grown when they exceed its own: FRICREG_OK or
 * FRICREG_ENOMEM (message recorded, with fn; no workspace then); freed (a second call does
 * nothing). */
int fr_hb_monodromy_reserve(fricreg_hb *hb, const char *fn);
void fr_hb_monodromy_free(fricreg_hb *hb);

#endif
