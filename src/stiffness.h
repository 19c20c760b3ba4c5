/* SPDX-License-Identifier: GPL-3.0-or-later */
/* stiffness.h — internal: the step guard's stiffness of a law that jumps (stiffness.c). */
#ifndef FRICREG_STIFFNESS_H
#define FRICREG_STIFFNESS_H

#include "fricreg.h"

/* The chord stiffness of (1), (2) and Karnopp: their jump 2 mun_i across the band 2 eps seen as
 * the slope mun_i/eps of law (3), with (3)'s coupling (the largest eigenvalue of
 * D^1/2 W D^1/2 for a dense W). A fricreg status (FRICREG_ENOMEM). */
int fr_chord_stiffness(fricreg_ctx *ctx, double *lambda);

#endif
