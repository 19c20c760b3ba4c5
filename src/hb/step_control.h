/* SPDX-License-Identifier: GPL-3.0-or-later */
/* step_control.h — the pseudo-arclength step control that the forced response's continuation
 * (forced/arclength.c) and the nonlinear modes' (nma/nma_arclength.c) share: its nominal
 * values, the next step's length, and the scaled vectors' dot product and distance. */
#ifndef FRICREG_HB_STEP_CONTROL_H
#define FRICREG_HB_STEP_CONTROL_H

#include <math.h>
#include <stddef.h>

#include "hb_internal.h"

/* The step control's nominal values (Allgower & Georg give the form; these were chosen on
 * tests/forced/test_hb_continuation.c's chains and lift-off pair): the corrector's contraction, its
 * first step relative to ds, the angle between successive tangents (rad), the iterations; the
 * bounds on the angle (20°; a kink's 90°), on the contraction (1/2: Newton's convergence is
 * slow beyond) and on the distance from the last point (4 ds: the hyperplane of a kink of up
 * to 75° meets the branch within ds / cos 75° < 4 ds); the chord's slack over twice the
 * tangents' angle. */
#define KAPPA0 0.25
#define DELTA0 0.3
#define ALPHA0 0.1745329251994330 /* 10° */
#define ITS0 4.0
#define ALPHA_MAX 0.3490658503988659 /* 20° */
#define KAPPA_MAX 0.5
#define KINK_MAX 1.5707963267948966 /* 90°: a larger turn goes back along the branch */
#define JUMP 4.0
#define NEAR_REACH \
    1e-4 /* scaled: a fold or kink finer than a plot shows or a sampled AFT's error */
#define CHORD_SLACK 1e-3 /* rad: above the chord's rounding, about tol/ds_min = 1e-4 */

/* The next step after an accepted one of length ds: Allgower & Georg's factor on the
 * corrector's contraction kappa, its first step delta, the tangents' angle alpha (0 at a kink)
 * and its iterations, within [1/2, 2], the step then within [ds_min, ds_max]. The forced
 * response's (forced/arclength.c) and the backbone's (nma/nma_arclength.c). */
static inline double fr_hb_next_step(const fricreg_hb *hb, double ds, double kappa, double delta,
                                     double alpha, int its)
{
    double f = fmax(fmax(kappa / KAPPA0, delta / (ds * DELTA0)), fmax(alpha / ALPHA0, its / ITS0));
    f = fmin(fmax(f, 0.5), 2.0);
    return fmin(fmax(ds / f, hb->ds_min), hb->ds_max);
}

static inline double fr_hb_dot(const double *a, const double *b, size_t n)
{
    double s = 0.0;
    for (size_t j = 0; j < n; j++)
        s += a[j] * b[j];
    return s;
}

static inline double fr_hb_dist(const double *a, const double *b, size_t n)
{
    double s = 0.0;
    for (size_t j = 0; j < n; j++)
        s += (a[j] - b[j]) * (a[j] - b[j]);
    return sqrt(s);
}

#endif
