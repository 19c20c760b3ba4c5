/* SPDX-License-Identifier: GPL-3.0-or-later */
/* central_imex.h — internal: law (4) implicit at the end of a central-difference step
 * (FRICREG_INT_CENTRAL_IMEX; central_imex.c). */
#ifndef FRICREG_CENTRAL_IMEX_H
#define FRICREG_CENTRAL_IMEX_H

#include <stddef.h>

#include "sim_internal.h"

/* Why sim cannot run FRICREG_INT_CENTRAL_IMEX (a phrase for a message), or NULL if it can:
 * law (4), on a system whose contacts are the bodies with a diagonal W (system.h). fricreg_sim
 * has no Stribeck friction, so law (4)'s bounds are constant. */
const char *fr_central_imex_refusal(const fricreg_sim *sim);

/* The per-contact constants of fr_imex_friction_acc for the step h, for n contacts with
 * bounds mun [n], W = diag(w) [n] and law (4)'s eps, into coef [3n]: the bounds in
 * acceleration w mun, then 1/(1 + h w mun/eps), then 1/w. */
void fr_central_imex_coefficients(size_t n, double h, double eps, const double mun[],
                                  const double w[], double coef[]);

/* clamp(x, -b, b); a NaN x stays NaN, so a state that overflowed is seen as diverged. */
static inline double fr_imex_clamp(double x, double b)
{
    return x > b ? b : (x < -b ? -b : x);
}

/* The friction of one contact that is a body at the end of a step of h, as the acceleration
 * g1 = W f1 it gives: law (4) at v1 = v + h (a0 + a_free + g1)/2, solved exactly
 * (central_imex.c). v the contact's velocity and a0 its acceleration at the step's start,
 * a_free its free acceleration at the step's end; bound_acc = W mun and
 * den_inv = 1/(1 + h W mun/eps) from fr_central_imex_coefficients. With G = W clamp(f_eq) and
 * Lambda = W lambda = 2 bound_acc/eps: g1 = clamp((G - Lambda c) den_inv, +-bound_acc). */
static inline double fr_imex_friction_acc(double v, double a0, double a_free, double h,
                                          double two_over_eps, double bound_acc, double den_inv)
{
    double G = fr_imex_clamp(-a_free, bound_acc); /* f_eq = -a_free/W, clamped, times W */
    double c = v + 0.5 * h * (a0 + a_free);       /* v1 without the friction */
    return fr_imex_clamp((G - two_over_eps * bound_acc * c) * den_inv, bound_acc);
}

#endif
