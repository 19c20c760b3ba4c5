/* SPDX-License-Identifier: GPL-3.0-or-later */
/* aft_slips.h — when a Jenkins slider slips over the stabilized period of the exact AFT
 * (aft_exact.c): the switch instants that harmonic balance's exact monodromy (hb/monodromy.c)
 * integrates between. */
#ifndef FRICREG_JOINT_AFT_SLIPS_H
#define FRICREG_JOINT_AFT_SLIPS_H

#include "fricreg_aft.h"

/* How a slider moves over the period. */
enum fr_aft_slip_kind {
    FR_AFT_STUCK = 0,  /* stuck throughout (its offset a constant) */
    FR_AFT_SLIPS = 1,  /* slips on the intervals on[i] .. off[i] and sticks between them */
    FR_AFT_SLIDES = 2, /* slips throughout: mun = 0, or a stick below u's rounding */
};

/* One slider's slip intervals: each from its onset on[i] (kt |u − w| reaches mun: stick → slip)
 * to the reversal off[i] where it stops (u' = 0: slip → stick), angles θ = Ω t in [0, 2π)
 * (off[i] < on[i] for an interval across θ = 0), in the order of the march; count <= 2H. */
struct fr_aft_slips {
    int kind; /* enum fr_aft_slip_kind */
    int count;
    double *on, *off; /* [2H] each, the caller's */
};

/* The slip intervals of one slider (stiffness kt > 0, slip force mun >= 0) under the checked
 * displacement u[2H + 1] (fricreg_aft.h's layout), as fr_aft_exact's march finds them: the same
 * reversals, onsets and stabilized start. FRICREG_OK, or FRICREG_EINTEGRATOR (message recorded
 * in aft) if GSL's root solver failed. */
int fr_aft_exact_slips(fricreg_aft *aft, const char *fn, double kt, double mun, const double *u,
                       struct fr_aft_slips *slips);

#endif
