/* SPDX-License-Identifier: GPL-3.0-or-later */
/* hb_model.h — the fit's model of a harmonic-balance driver's nonlinear mode
 * (fricreg_fit_set_model_hb): its parameters set on the driver (its description, struct
 * fr_fit_hb, is fit_internal.h's; the backbone at the levels hb_levels.h's). */
#ifndef FRICREG_FIT_HB_MODEL_H
#define FRICREG_FIT_HB_MODEL_H

#include "model.h"

/* The modal Iwan model, its defaults (every parameter free on its own bounds, 32 starts); the
 * HB model's description freed. */
void fr_fit_use_modal_iwan(fricreg_fit *fit);

/* Releases an HB model's description (NULL: nothing). */
void fr_fit_hb_free(struct fr_fit_hb *m);

/* Sets the driver's values to p[np]: each element range's shared value, Rayleigh's (a0, a1) (the
 * one not among the parameters 0). FRICREG_OK, or the driver's status (its message in
 * fit->reason). */
int fr_fit_hb_apply(fricreg_fit *fit, const double p[]);

/* The element parameters' values the driver holds into v[np] (NaN for the others), and back. */
void fr_fit_hb_save(fricreg_fit *fit, double v[]);
void fr_fit_hb_restore(fricreg_fit *fit, const double v[]);

#endif
