/* SPDX-License-Identifier: GPL-3.0-or-later */
/* aft_slips.h — when a Jenkins slider slips over the stabilized period of the exact AFT
 * (aft_exact.c): the switch instants that harmonic balance's exact monodromy (floquet/monodromy.c)
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

/* A slider under a normal load with lift-off (aft_normal_exact.c): the modes it enters. */
enum fr_aft_mode { FR_AFT_OPEN = 0, FR_AFT_STICK = 1, FR_AFT_SLIP = 2 };

/* How a switch moves the slider's offset w: not at all, to follow u − dir mu P/kt (a slip
 * onset), or to u at a touchdown, whose instant moves with g (w = u(θt): δw = δu − ratio δg,
 * ratio = u'/g' there, 0 at a grazing touchdown as in the AFT's Jacobian). */
enum fr_aft_reset { FR_AFT_KEEP = 0, FR_AFT_ONSET = 1, FR_AFT_TOUCHDOWN = 2 };

/* One switch: at theta (the march's angle, one period from its start) the slider enters mode,
 * dir the slip's direction (or the one a stick follows), its offset moved by reset. */
struct fr_aft_switch {
    double theta, ratio;
    int mode, dir, reset;
};

/* The schedule of one slider with lift-off over the stabilized period. The contact: closed
 * where P = N0 + kn g > 0, its sign changes at[i] with P's sign dir[i] after each (count <=
 * 2H), or P's sign throughout (count 0). The slider: kind FR_AFT_STUCK (closed and stuck
 * throughout), FR_AFT_SLIDES (no tangential force: mu P = 0 throughout), or FR_AFT_SLIPS with
 * its switches sw[0 .. nsw), the first at the march's start in the state it starts in. */
struct fr_aft_liftoff {
    int kind, count, nsw, cap, sign;
    double *at;               /* [2H], the caller's */
    int *dir;                 /* [2H], the caller's */
    struct fr_aft_switch *sw; /* [cap], the caller's */
};

/* The schedule of one slider with lift-off (fricreg_aft_jenkins_normal_exact's kt, mu, n0, kn
 * under the checked u[2H + 1] and g[2H + 1]) as that function's march finds it, into lo (cap
 * set by the caller: 8H + 4 is enough); scratch[2 (2H + 1)]. FRICREG_OK, or FRICREG_EINTEGRATOR
 * (message recorded) if GSL's root solver failed or the switches exceed cap. */
int fr_aft_exact_normal_switches(fricreg_aft *aft, const char *fn, double kt, double mu, double n0,
                                 double kn, const double *u, const double *g, double *scratch,
                                 struct fr_aft_liftoff *lo);

#endif
