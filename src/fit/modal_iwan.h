/* SPDX-License-Identifier: GPL-3.0-or-later */
/* modal_iwan.h — the modal Iwan model's backbone (fricreg_fit.h's closed forms): frequency and
 * damping ratio at a modal amplitude, and at a measured level, with exact sensitivities. */
#ifndef FRICREG_FIT_MODAL_IWAN_H
#define FRICREG_FIT_MODAL_IWAN_H

#include <gsl/gsl_roots.h>

#include "dual.h"

/* omega (rad/s) and zeta at the modal amplitude a > 0, differentiated along the parameters
 * p[FRICREG_FIT_NPARAMS] (in range) and a (direction FR_DUAL_A). */
void fr_modal_iwan_backbone(const double p[], double a, fr_dual *omega, fr_dual *zeta);

/* The model at one measured level. */
struct fr_level_model {
    double freq_hz, zeta, modal;                                   /* f (Hz), zeta, a */
    double dfreq[FRICREG_FIT_NPARAMS], dzeta[FRICREG_FIT_NPARAMS]; /* d/dp, the level held */
};

/* The model at the measured amplitude A > 0 of kind (enum fricreg_fit_amplitude) at a sensor
 * of mode shape s != 0: a from |s| omega(a)^kind a = A by Brent's method on brent, then the
 * backbone there and its total derivatives (da/dp by the implicit function theorem).
 * Returns 0, or -1 if no a reaches A (an acceleration with K0 = 0 beyond |s| F_S). */
int fr_modal_iwan_level(const double p[], int kind, double s, double A, gsl_root_fsolver *brent,
                        struct fr_level_model *m);

#endif
