/* SPDX-License-Identifier: GPL-3.0-or-later */
/* switches.h — when every slider and contact of a periodic HB solution switches (switches.c):
 * the exact monodromy's schedule (monodromy.c), from the exact AFT's marches. */
#ifndef FRICREG_HB_SWITCHES_H
#define FRICREG_HB_SWITCHES_H

#include "base/fr_math.h"
#include "hb/hb_internal.h"

/* One switch at the angle θ = Ω t in [0, 2π): a slider of the state (index: its place among
 * them) entering mode (joint/aft_slips.h: FR_AFT_OPEN, _STICK, _SLIP) in direction dir, its
 * offset moved by reset (FR_AFT_KEEP, _ONSET, _TOUCHDOWN with ratio = u'/g'); or (contact) an
 * element's contact closing (mode 1) or opening (0). seq keeps the march's order at one angle. */
struct fr_hb_switch {
    double theta, ratio;
    size_t index, seq;
    int contact, mode, dir, reset;
};

/* The schedule: the sliders that switch (the state's, S of them: element, stiffness kt, mu kn,
 * mode and direction at θ = 0), those stuck over the whole period (their element and kt: a
 * constant spring), each contact's state at θ = 0 and normal stiffness, and the switches
 * sorted by angle. Sized for me elements of ns sliders at H harmonics. */
struct fr_hb_schedule {
    size_t S, nstuck, count;
    struct fr_hb_switch *sw;  /* [me ns (8H + 4) + 2H me] */
    size_t *element;          /* [me ns] */
    double *k, *c;            /* [me ns] each */
    int *mode, *dir;          /* [me ns] each */
    size_t *stuck_element;    /* [me ns] */
    double *stuck_k;          /* [me ns] */
    int *closed;              /* [me]: 1 closed (always, without a normal law), 0 open */
    double *kn;               /* [me]: the normal stiffness, 0 without a normal law */
    double *scratch;          /* the AFT calls' */
    struct fr_aft_switch *lo; /* [8H + 4] one slider's */
    int *lo_dir;              /* [2H] */
};

/* The schedule's arrays for hb's sizes: FRICREG_OK or FRICREG_ENOMEM (nothing allocated); freed
 * (a second call does nothing). */
int fr_hb_schedule_alloc(const fricreg_hb *hb, struct fr_hb_schedule *sc);
void fr_hb_schedule_free(struct fr_hb_schedule *sc);

/* Every slider's and contact's switches at the coefficients hb->qjac (1-D Jenkins and Iwan
 * elements, with or without lift-off: rpe 1 or 2). FRICREG_OK or FRICREG_EINTEGRATOR (the AFT,
 * message recorded with fn). */
int fr_hb_schedule(fricreg_hb *hb, const char *fn, struct fr_hb_schedule *sc);

/* Whether the orbit's second half period repeats its first: a 1-D slider without a normal
 * law (hb->rpe 1, mu kn = 0) has the same piece matrices and saltations in either direction,
 * so where switch i + count/2 is switch i's half a period on (to FR_HB_HALF_WAVE_TOL), for the
 * same slider, mode and reset, the period's product is the square of the first half's (Φ =
 * Φ_h², monodromy.c). These are the odd orbits, x(t + T/2) = −x(t), of forces odd in x under a
 * harmonic load: every orbit of such a model that keeps HB's symmetry. 1 if so, else 0. */
#define FR_HB_HALF_WAVE_TOL (1e-12 * FR_TWO_PI)
int fr_hb_schedule_half_wave(const fricreg_hb *hb, const struct fr_hb_schedule *sc);

#endif
