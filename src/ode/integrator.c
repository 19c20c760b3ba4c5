/* SPDX-License-Identifier: GPL-3.0-or-later */
/* integrator.c — the table of GSL steppers behind enum fricreg_integrator.
 *
 * GSL's "rk4" estimates its error by step doubling: one GSL step of size 2h returns two
 * classical RK4 steps of size h (equal to them to rounding). So fricreg's RK4 with step dt,
 * the paper's method, is GSL's rk4 with step 2 dt: `substeps` = 2.
 *
 * The real-axis bounds were measured by applying each GSL stepper with a fixed step to
 * y' = -y (tests/ode/test_integrator.c checks them) and rounded down: rk2 is Kutta's third-order
 * scheme (2.51), rk4 the classical one per half step (2.785), rkf45 3.67, rkck 3.73,
 * rk8pd 5.16. The imaginary-axis bounds likewise, on y' = i y, where the amplification per
 * step reaches 1 + 1e-4: rk2 1.73, rk4 2.83 per half step, rkf45 0.71, rkck 0.88 (the two
 * embedded 4(5) pairs are weakly unstable on that axis), rk8pd 3.71. Implicit steppers are
 * A-stable; the multistep ones report their own failure.
 *
 * The step guard (step_guard.c) uses a third column, the stick-zone bound on dt*lambda. |R(-z)| <= 1
 * is necessary but not sufficient there: the zone is linear only for |zdot - xi| < eps/2, and a
 * stage that overshoots it meets the saturated (weaker) force, so the step is no longer the
 * linear one. Measured with tests/ode/test_guard.c's sweep (the three systems; (3), tanh and (4);
 * both partitions; mun up to (10, 5)), rkf45, whose stages overshoot most (largest stage
 * |Y_i/y0| at z = 2.78: rkf45 9.7, rkck 3.8, rk8pd 1.0), puts energy in from dt*lambda = 2.5
 * (two blocks, mun = (10, 5), eps = 0.02, (4), consistent: 0.58 of 3.4) and leaves a stick from
 * 2.77 (oscillator, mun = 3, eps = 0.05, (3)); at 2.25 it passes everywhere: it gets 2.2.
 * rk8pd, whose |R(-z)| is close to 1 over the last part of its interval, lets the stick zone's
 * velocity ring: the structure sweep (tests/ode/test_guard_structure.c: the paper's oscillator as a
 * structure, eps = 0.05, under ground motion) leaves the stick from dt*lambda = 4.75 under (3)
 * (near-stick fraction 0 instead of 0.195; 0.19 at 4.7) and at 5.1 under tanh (0.081 for
 * 0.132); it gets 4.5. For the others the first failure lies beyond the real-axis bound (rk2
 * 3.1, rk4 2.99, rkck 4.26: chain n = 8, eps = 0.002, law (3)), which is kept.
 *
 * Fixed steps of rk4 are not GSL's (rk4_classic.c): GSL's rk4 grid (two classical steps per
 * call, `substeps` = 2) without the error estimate, 4 right-hand sides per step where GSL's
 * rk4 spends 6, for the same numbers to rounding. "rk4-gsl" keeps GSL's for comparison.
 *
 * "central" is not GSL's: explicit central differences (central_step.c), one right-hand side
 * per step, for fixed steps of fricreg_sim only (no error estimate, and the stepper needs the
 * state layout (x, v, D)). "central-imex" is the same scheme with law (4)'s friction at the
 * step's end solved implicitly, contact by contact (central_imex.c). */
#include <math.h>
#include <stddef.h>
#include <string.h>

#include "fricreg_sim.h"
#include "integrator.h"
#include "rk4_classic.h"

#define ROW(ID, NAME, REAL, ZONE, IMAG, SUB, TOL)                                      \
    {                                                                                  \
        ID, #NAME, gsl_type_##NAME, REAL, ZONE, IMAG, SUB, TOL, NULL, 0, 0, 0, 0, NULL \
    }
/* An implicit stepper with GSL's LU on its Newton matrix (integrator.h, lu_newton), and
 * whether it iterates to the control's error level (atol_required) */
#define ROW_LU(ID, NAME, TOL, ATOL, LOCATOR)                                            \
    {                                                                                   \
        ID, #NAME, gsl_type_##NAME, 0.0, 0.0, 0.0, 1, TOL, NULL, 0, 0, 1, ATOL, LOCATOR \
    }

/* gsl_odeiv2_step_* are data symbols; functions returning them keep the table constant. */
#define GSL_TYPE(NAME)                                       \
    static const gsl_odeiv2_step_type *gsl_type_##NAME(void) \
    {                                                        \
        return gsl_odeiv2_step_##NAME;                       \
    }
GSL_TYPE(rk2)
GSL_TYPE(rk4)
GSL_TYPE(rkf45)
GSL_TYPE(rkck)
GSL_TYPE(rk8pd)
GSL_TYPE(rk1imp)
GSL_TYPE(rk2imp)
GSL_TYPE(rk4imp)
GSL_TYPE(bsimp)
GSL_TYPE(msadams)
GSL_TYPE(msbdf)

static const struct fr_integrator table[] = {
    ROW(FRICREG_INT_RK2, rk2, 2.5, 2.5, 1.73, 1, 1e-6),
    /* rk4: GSL's for adaptive steps, fricreg's classical RK4 for fixed ones (same numbers) */
    {FRICREG_INT_RK4, "rk4", gsl_type_rk4, 2.78, 2.78, 2.82, 2, 1e-6, fr_step_rk4_classic, 0, 0, 0,
     0, NULL},
    ROW(FRICREG_INT_RKF45, rkf45, 3.6, 2.2, 0.7, 1, 1e-6),
    ROW(FRICREG_INT_RKCK, rkck, 3.7, 3.7, 0.88, 1, 1e-6),
    ROW(FRICREG_INT_RK8PD, rk8pd, 5.1, 4.5, 3.7, 1, 1e-6),
    ROW_LU(FRICREG_INT_RK1IMP, rk1imp, 1e300, 1, NULL),
    ROW_LU(FRICREG_INT_RK2IMP, rk2imp, 1e300, 1, NULL),
    ROW_LU(FRICREG_INT_RK4IMP, rk4imp, 1e300, 1, NULL),
    ROW_LU(FRICREG_INT_BSIMP, bsimp, 1e-6, 0, NULL),
    /* msadams: no LU (functional iteration), but iterates to the error level. The multistep
     * steppers locate kinks by a one-step stepper (integrator.h): msadams by rk8pd, msbdf by
     * rk4imp (A-stable, as the stick zone needs; measured on the two blocks at eps = 1e-6 and
     * 1e-4, rtol 1e-4 ... 1e-8: bsimp costs 5x its right-hand sides for errors as large,
     * rk1imp's first order misplaced the kinks, -6.5% at rtol 1e-4) */
    {FRICREG_INT_MSADAMS, "msadams", gsl_type_msadams, 0.0, 0.0, 0.0, 1, 1e-6, NULL, 0, 0, 0, 1,
     gsl_type_rk8pd},
    ROW_LU(FRICREG_INT_MSBDF, msbdf, 1e-6, 1, gsl_type_rk4imp),
    /* GSL's rk4 for fixed steps too, for comparison */
    {FRICREG_INT_RK4_GSL, "rk4-gsl", gsl_type_rk4, 2.78, 2.78, 2.82, 2, 1e-6, NULL, 0, 0, 0, 0,
     NULL},
    /* central differences, fixed steps only: real axis (dt lambda) 1, imaginary axis
     * (dt omega) 2, jointly (dt omega/2)^2 + dt lambda < 1; the guard takes 0.9 (step_guard.c) */
    {FRICREG_INT_CENTRAL, "central", NULL, 1.0, 0.9, 2.0, 1, 1e-6, NULL, 1, 0, 0, 0, NULL},
    /* the same with law (4) implicit at the step's end: no stick-zone bound (infinite real
     * axis), imaginary axis 2; the guard takes (dt omega/2)^2 < 0.9, and dt omega <= 1/sqrt 2
     * where the step does not resolve law (4)'s band (step_guard.c) */
    {FRICREG_INT_CENTRAL_IMEX, "central-imex", NULL, INFINITY, INFINITY, 2.0, 1, 1e-6, NULL, 1, 1,
     0, 0, NULL},
};

const struct fr_integrator *fr_integrator_find(int id)
{
    for (size_t k = 0; k < sizeof table / sizeof table[0]; k++)
        if (table[k].id == id)
            return &table[k];
    return NULL;
}

const gsl_odeiv2_step_type *fr_integrator_stepper(const struct fr_integrator *integ, int adaptive)
{
    if (integ->type == NULL) /* the central rows: the driver's own stepper */
        return NULL;
    return !adaptive && integ->fixed_type ? integ->fixed_type() : integ->type();
}

const char *fricreg_integrator_name(int integrator)
{
    const struct fr_integrator *row = fr_integrator_find(integrator);
    return row ? row->name : NULL;
}

int fricreg_integrator_from_name(const char *name)
{
    if (name == NULL)
        return 0;
    for (size_t k = 0; k < sizeof table / sizeof table[0]; k++) {
        if (strcmp(table[k].name, name) == 0)
            return table[k].id;
    }
    return 0;
}
