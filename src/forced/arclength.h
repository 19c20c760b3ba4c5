/* SPDX-License-Identifier: GPL-3.0-or-later */
/* arclength.h — one branch followed by pseudo-arclength continuation from p0 to p1
 * (arclength.c): the public continuations (continuation.c) and the default start (start.c)
 * both run it. */
#ifndef FRICREG_HB_ARCLENGTH_H
#define FRICREG_HB_ARCLENGTH_H

#include "corrector.h"
#include "hb/step_control.h"

/* The branch of b's parameter (Ω, or λ at b->omega; b's kind, par and keep set) from p0 to p1,
 * its first point solved from q0 (NULL: fr_hb_solve_at's guesses); with keep the points stored
 * (the earlier ones dropped) and the bifurcations between them located. The last point kept as
 * the driver's solution. */
int fr_hb_arclength(fricreg_hb *hb, const char *fn, struct fr_hb_branch *b, double p0, double p1,
                    const double *q0);

#endif
