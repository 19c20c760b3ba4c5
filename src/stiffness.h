/* SPDX-License-Identifier: GPL-3.0-or-later */
/* stiffness.h — internal: the step guard's stiffnesses, times eps (stiffness.c). */
#ifndef FRICREG_STIFFNESS_H
#define FRICREG_STIFFNESS_H

#include "fricreg.h"

/* lambda * eps, finite where lambda = mun/eps overflows, so that the step guard can still name
 * the eps that passes (eps >= dt lambda eps / bound). chord = 0: the stick-zone stiffness of
 * fricreg_ctx_stick_stiffness. chord = 1: the chord stiffness of (1), (2) and Karnopp, their
 * jump 2 mun_i across the band 2 eps seen as the slope mun_i/eps of law (3), with (3)'s
 * coupling (the largest eigenvalue of D^1/2 W D^1/2 for a dense W). A fricreg status
 * (FRICREG_ENOMEM, recorded in ctx). */
int fr_stiffness_times_eps(fricreg_ctx *ctx, int chord, double *rate);

#endif
