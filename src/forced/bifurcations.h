/* SPDX-License-Identifier: GPL-3.0-or-later */
/* bifurcations.h — the bifurcations between a branch's stored points located
 * (bifurcations.c), once the continuation loop has stored them. */
#ifndef FRICREG_HB_BIFURCATIONS_H
#define FRICREG_HB_BIFURCATIONS_H

#include "corrector.h"

/* Each pair of successive stored points: the first test whose sign changed (turning point,
 * branch point, change of stability), located by bisection into bifs (nbif). */
void fr_hb_locate_bifurcations(fricreg_hb *hb, struct fr_hb_branch *b);

#endif
