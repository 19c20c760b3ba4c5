/* SPDX-License-Identifier: GPL-3.0-or-later */
/* closed_form.c — the closed forms of Eq. (5) on one phase (closed_form.h): the forced
 * response to a sin(omega t), and the state on a stick or on a slip with f = -s mun constant.
 * Below the phases' search (phases.c) and the results (results.c), which both read them. */
#include <math.h>

#include "base/fr_math.h"
#include "closed_form.h"

void fr_exact_forced(const fricreg_exact *ex, double t, double *xp, double *vp)
{
    double a = ex->a, w = ex->omega;
    if (w == 1.0) {
        *xp = -0.5 * a * t * cos(t);
        *vp = -0.5 * a * cos(t) + 0.5 * a * t * sin(t);
    } else {
        double P = a / (1.0 - w * w);
        *xp = P * sin(w * t);
        *vp = P * w * cos(w * t);
    }
}

void fr_exact_phase_state(const fricreg_exact *ex, const struct fr_phase *p, double t, double *x,
                          double *v)
{
    if (p->s == 0) {
        *x = p->x0;
        *v = 0.0;
        return;
    }
    double c = -p->s * ex->mun, xp0, vp0, xp, vp;
    fr_exact_forced(ex, p->t0, &xp0, &vp0);
    fr_exact_forced(ex, t, &xp, &vp);
    double A = p->x0 - c - xp0, B = p->v0 - vp0, tau = t - p->t0;
    *x = c + xp + A * cos(tau) + B * sin(tau);
    *v = vp - A * sin(tau) + B * cos(tau);
}

double fr_exact_period(const fricreg_exact *ex)
{
    return FR_TWO_PI / ex->omega;
}
