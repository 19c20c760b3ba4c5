/* SPDX-License-Identifier: GPL-3.0-or-later */
/* starts.h — a fit's starts (docs/identification.md, "Starts"): the first from the levels where
 * the caller gave none, the others moved from it along a Halton sequence in theta. */
#ifndef FRICREG_FIT_STARTS_H
#define FRICREG_FIT_STARTS_H

#include "residuals.h"

/* theta[nfree] of start s (0: the first). */
void fr_fit_start(const struct fr_fit_problem *pb, size_t s, double theta[]);

#endif
