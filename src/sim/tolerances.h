/* SPDX-License-Identifier: GPL-3.0-or-later */
/* tolerances.h — internal: the absolute tolerances of an adaptive run (tolerances.c), for
 * the GSL driver of the run (sim.c). */
#ifndef FRICREG_SIM_TOLERANCES_H
#define FRICREG_SIM_TOLERANCES_H

#include "sim_internal.h"

/* The rule from eps at eps: absolute tolerances atol[2 ndof + 1] of y = (x, v, D) and the
 * weights w[2 ndof + 1] of rtol in each component (w NULL: not asked for). */
void fr_sim_rule_tolerances(const fricreg_sim *sim, double eps, double atol[], double w[]);

#endif
