/* SPDX-License-Identifier: GPL-3.0-or-later */
/* phases.h — internal: the phases of the exact solution, each one's end found by a scan and
 * Brent's method (phases.c). */
#ifndef FRICREG_EXACT_PHASES_H
#define FRICREG_EXACT_PHASES_H

#include "base/error.h"
#include "exact_internal.h"

/* The phases from t = 0 to ex->t_end into ex->ph, which is empty. A phase of zero length (a
 * stick broken at once, a slip with no motion) is replaced by its successor, so no switch is
 * reported for it; two in a row would mean no progress, which the closed forms exclude. */
int fr_exact_phases(fricreg_exact *ex, struct fr_error *err);

#endif
