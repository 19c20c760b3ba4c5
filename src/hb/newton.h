/* SPDX-License-Identifier: GPL-3.0-or-later */
/* newton.h — internal: Newton's method on (R) at one frequency and its starting guesses (newton.c). */
#ifndef FRICREG_HB_NEWTON_H
#define FRICREG_HB_NEWTON_H

#include "hb_internal.h"

/* Newton's method at the factored Ω from qw (in place), tolerance relative to the scale.
 * FRICREG_OK, FRICREG_ESINGULAR, FRICREG_EWORK, FRICREG_EINTEGRATOR (message recorded). */
int fr_hb_newton(fricreg_hb *hb, const char *fn);

/* The starting guess into qw: every element stuck (stuck) or slipping freely (F = 0). */
int fr_hb_guess(fricreg_hb *hb, const char *fn, int stuck);

#endif
