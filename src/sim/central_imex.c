/* SPDX-License-Identifier: GPL-3.0-or-later */
/* central_imex.c — law (4) solved implicitly at the end of a central-difference step
 * (FRICREG_INT_CENTRAL_IMEX): the springs explicit, the friction implicit.
 *
 * The step of central_step.c with the friction of its end taken at the end's own velocity:
 *
 *   x1 = x + h v + h^2/2 a,   a1 = a_free(x1) + W f1,   v1 = v + h (a + a1)/2,
 *   f1 = (4)(v1, f_eq1),      f_eq1 = -a_free(x1)/W      (W diagonal, the contacts the bodies).
 *
 * Why: the explicit step sees the friction at the predictor v* = v + h a, whose stick zone
 * (slope -lambda = -2 mun W/eps) bounds the step, (h omega/2)^2 + h lambda < 1, so eps must
 * grow with h and law (4)'s O(eps) error with it. Taken at v1, the friction's velocity term
 * is the trapezoid's, which is A-stable: on x'' = -omega^2 x - c x' the step's characteristic
 * polynomial is mu ((1 + z) mu^2 - (2 - p^2) mu + (1 - z)), p = h omega, z = h c/2, whose
 * roots lie in the unit disc for every z >= 0 exactly when p <= 2 (Schur's test:
 * |1 - z| <= 1 + z always, |2 - p^2| <= 2 iff p <= 2). So eps is free of h, and the guard is
 * the springs', plus the friction-reversal bound where the step does not resolve the band
 * (src/ode/step_guard.c, check_central_imex). Still one evaluation a step and second order.
 *
 * The solve. a_free does not depend on v (system.h: a_free = Ax x + a_0(t)), so with
 * c = v + h/2 (a + a_free) and kappa = h W/2 the velocity is v1 = c + kappa f1, and f1 solves
 * f1 = clamp(F - lambda (c + kappa f1), +-mun), F = clamp(f_eq1, +-mun), in the division-free
 * form of (4) (src/law/law.h: clamp(clamp(f_eq, +-mun) - (2 mun/eps) v, +-mun)). The right side
 * decreases in f1, so the root is unique: the unclamped one, (F - lambda c)/(1 + kappa lambda),
 * clamped to +-mun (if it lies beyond mun, F - lambda (c + kappa mun) is beyond mun too, and
 * the clamp holds f1 = mun). No iteration and no branch (fr_imex_friction_acc, in W f1's
 * units, inlined into central_step.c's friction pass); the two divisions per contact (by
 * 1 + kappa lambda and by W) are made once per step size (fr_central_imex_coefficients):
 * made each step they cost as much as the rest of it (52% of a chain run). */
#include "central_imex.h"

#include "system.h"

const char *fr_central_imex_refusal(const fricreg_sim *sim)
{
    if (sim->law != FRICREG_LAW_QUINN)
        return "the implicit friction is law (4)'s: set law (4) (quinn)";
    if (!sim->sys.type->contacts_are_bodies)
        return "the implicit friction is solved contact by contact: it needs contacts that are "
               "the bodies, with a diagonal W (the oscillator, the chain), not the two blocks";
    return NULL;
}

void fr_central_imex_coefficients(size_t n, double h, double eps, const double mun[],
                                  const double w[], double coef[])
{
    for (size_t i = 0; i < n; i++) {
        coef[i] = w[i] * mun[i];                             /* W mun */
        coef[n + i] = 1.0 / (1.0 + h * w[i] * mun[i] / eps); /* 1/(1 + kappa lambda) */
        coef[2 * n + i] = 1.0 / w[i];
    }
}
