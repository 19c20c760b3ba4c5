/* SPDX-License-Identifier: GPL-3.0-or-later */
/* closed_form.h — internal: the closed forms of Eq. (5) on one phase of the exact solution
 * (closed_form.c), read by the phases' search (phases.c) and the results (results.c). */
#ifndef FRICREG_EXACT_CLOSED_FORM_H
#define FRICREG_EXACT_CLOSED_FORM_H

#include "exact_internal.h"

/* The forced response to a sin(omega t) and its rate: a sin(wt)/(1 - w^2), or at resonance
 * the secular -(a/2) t cos t. */
void fr_exact_forced(const fricreg_exact *ex, double t, double *xp, double *vp);

/* Closed-form state in phase p at time t (Eq. (5) with f = -s mun constant). */
void fr_exact_phase_state(const fricreg_exact *ex, const struct fr_phase *p, double t, double *x,
                          double *v);

/* The forcing period 2 pi / omega. */
double fr_exact_period(const fricreg_exact *ex);

#endif
