/* SPDX-License-Identifier: GPL-3.0-or-later */
/* step_guard.c — the stability guard of a fixed explicit step with friction contacts
 * (step_guard.h): every bound derived once here, with the measurement that set it, for
 * fricreg_sim and fricreg_structure alike.
 *
 * The linear model of a contact near stick is z'' = -omega^2 z - c z': omega the system's
 * highest natural frequency, c the stick zone's damping-like rate lambda (lambda = the law's
 * slope at rest times W, fricreg_ctx_stick_stiffness) plus any viscous damping. A fixed step
 * must keep dt c inside its stepper's stable interval on the negative real axis and dt omega
 * inside it on the imaginary axis (the table's columns, integrator.c); central differences
 * have one joint bound; laws that jump and friction reversals add two more. */
#include <math.h>
#include <stdio.h>

#include <gsl/gsl_math.h>

#include "fricreg.h"
#include "step_guard.h"

/* Laws whose force jumps by 2 mun at zdot = 0 (or at Karnopp's band edge) have no linear
 * zone: a fixed step chatters. Their stiffness is the chord of the jump across the band the
 * run resolves, lambda = W_ii mun_i/eps (fr_stiffness_times_eps). One step from the band edge
 * with the whole swing moves zdot_i by at most 2 dt W_ii mun_i = 2 eps dt lambda: it lands
 * inside the band, of width 2 eps, for every stepper while dt * lambda <= 1. Measured: against
 * the steppers' real-axis bounds instead (up to 5.1), the chain (n = 8, eps = 0.002) gained
 * energy under (1) with rk8pd, and the two blocks with mun = (10, 5) by up to 300x their
 * scale. */
#define CHORD_STEP_BOUND 1.0

/* A reversal of the friction force within one step. A law that jumps ((1), (2), Karnopp) swings
 * by 2 mun at zdot = 0; a regularized one does so across its band, within one step whenever
 * eps <= dt |zddot| (the paper's rule eps = 2 dt: whenever |zddot| > 2). A step across the swing
 * takes its friction impulse with the wrong sign for part of the step, an error J <= 2 mun dt
 * (unit mass), while the velocity moves by at most v <= dt omega^2 A at amplitude A: an energy
 * error of at most J v + J^2/2 <= 2 mun dt^2 (omega^2 A + mun). The swing that ends in the
 * reversal dissipates at least 2 mun A, and a swing worth a reversal has A >= mun/omega^2, the
 * friction's offset of its centre (a smaller one ends in the stick zone, the stick-zone
 * bound's business): no energy is gained while 2 omega^2 dt^2 <= 1, dt * omega <= 1/sqrt 2.
 * Measured without it: rk8pd at dt = 3.7 (its imaginary-axis bound) grew the unforced
 * oscillator's energy 3.78 -> 104 under (1); the two blocks under (4) with the paper's eps gain
 * energy from dt * omega = 0.9 with RK4, not at 0.75. */
#define REVERSAL_STEP_BOUND M_SQRT1_2

/* The refusal where the stick zone's stiffness is beyond the double range: no dt and no eps
 * to name. */
static int refuse_overflowing_stick_zone(const struct fr_guard_run *run, struct fr_error *err,
                                         const char *who)
{
    return fr_error_set(err, FRICREG_ESTEP,
                        "%s: the stick zone's stiffness, of order mun/eps, is beyond the double "
                        "range for eps = %g: lower the bounds mun or raise eps",
                        who, run->eps);
}

/* The stick zone's refusal, dt (lambda + c) > bound (`what` names the bound). lambda is
 * proportional to 1/eps, so eps >= dt lambda eps / (bound - dt c) passes at this dt. Under the
 * paper's rule eps is proportional to dt and dt * lambda does not depend on dt: no dt passes,
 * and only an explicit eps helps (oscillator, mun = 3: eps = 2 dt gives dt * lambda = 3 > 2.78
 * for RK4). That is said rather than an eps chosen silently: eps is part of the model (the stick
 * band, an O(eps) change of the results), and a default that followed the stepper's bound
 * would move the results whenever the bound table is corrected. */
static int refuse_stick_zone(const struct fr_guard_run *run, struct fr_error *err, const char *who,
                             const char *what, double bound)
{
    double lambda = run->rate / run->eps + run->damping, z = run->dt * lambda;
    double room = bound - run->dt * run->damping; /* what the damping leaves the stick zone */
    if (!(room > 0.0))
        return fr_error_set(err, FRICREG_ESTEP,
                            "%s: dt = %g too large for the damping: its rate %g gives dt*c = %g "
                            "> %g, %s; reduce dt to %.6g",
                            who, run->dt, run->damping, run->dt * run->damping, bound, what,
                            bound / run->damping);
    double eps_min = run->dt * run->rate / room; /* finite where lambda overflows */
    double dt_max = bound * run->eps / (run->rate + run->damping * run->eps); /* likewise */
    if (!isfinite(eps_min) || !(dt_max > 0.0)) /* no step or eps would do */
        return refuse_overflowing_stick_zone(run, err, who);
    if (!run->eps_by_rule)
        return fr_error_set(err, FRICREG_ESTEP,
                            "%s: dt = %g too large for the stick zone: its stiffness %g gives "
                            "dt*lambda = %g > %g, %s; reduce dt to %.6g or raise eps to %.6g",
                            who, run->dt, lambda, z, bound, what, dt_max, eps_min);
    return fr_error_set(err, FRICREG_ESTEP,
                        "%s: eps by the paper's rule (eps = %g dt) makes dt*lambda = %g > %g, %s, "
                        "at every dt; set eps >= %.6g explicitly",
                        who, run->eps / run->dt, z, bound, what, eps_min);
}

static int refuse_reversal(const struct fr_guard_run *run, struct fr_error *err, const char *who,
                           const char *what)
{
    double z = run->dt * run->omega;
    return fr_error_set(err, FRICREG_ESTEP,
                        "%s: dt = %g too large for the system's highest frequency %g: "
                        "dt*omega = %g > %g lets a friction reversal %s put energy in; reduce "
                        "dt to %.6g",
                        who, run->dt, run->omega, z, REVERSAL_STEP_BOUND, what,
                        REVERSAL_STEP_BOUND / run->omega);
}

/* Central differences (Newmark beta = 0, gamma = 1/2: fricreg_sim's central_step.c and the
 * structure's central_difference.c) on the linear model z'' = -omega^2 z - c z'. With
 * p = dt omega, h = dt c, on (z, dt z', dt^2 z'') the step's characteristic polynomial is
 *   P(mu) = mu^3 - (2 - p^2 - 3h/2) mu^2 + (1 - 2h) mu + h/2,
 * P(1) = p^2 >= 0 and P(-1) = p^2 + 4h - 4: a root leaves the unit disc through -1 at
 * p^2/4 + h = 1, and nowhere before (scanned over 0 <= h <= 1, p <= 2.2 in steps of 1e-3).
 * So the step is stable for (dt omega/2)^2 + dt c < 1: dt omega < 2 undamped (the three-term
 * recurrence), dt lambda < 1 in the linear stick zone (where f_eq screens the spring: c = lambda,
 * omega = 0), and dt < 2/(c + sqrt(c^2 + omega^2)) in between. The friction-reversal bound is
 * kept for the laws that jump only: tests/ode/test_guard.c's sweep finds no energy put in by (3),
 * tanh or (4) up to the linear bound (dt omega up to 2 sqrt(1 - h)), while (1) and (2) put it in
 * from dt omega = 1.36 (two blocks, the paper's eps: 0.12 of an energy scale 3.4; the
 * oscillator from 1.41), a reversal's whole swing within one step.
 * Kept 10% inside the linear bound (FR_CENTRAL_STEP_BOUND): each cycle's last step is
 * shortened to end on the cycle's boundary, which breaks the constant-step recurrence once a
 * cycle. Measured on the unforced, frictionless oscillator over 64 cycles of 2 pi: bounded up
 * to dt omega = 1.9, grown to 8e26 at 1.98. With 0.9 the frictionless limit is
 * dt omega < 1.897. */
static int check_central(const struct fr_guard_run *run, struct fr_error *err, const char *who)
{
    const double B = FR_CENTRAL_STEP_BOUND;
    double c = run->rate / run->eps + run->damping, omega = run->omega;
    double h = run->dt * c, half_p = 0.5 * run->dt * omega;
    if (!(h < B)) /* under the paper's rule no dt passes */
        return refuse_stick_zone(run, err, who, "the stick-zone bound of central differences", B);
    if (run->jumps && run->dt * omega > REVERSAL_STEP_BOUND)
        return refuse_reversal(run, err, who, "of a law that jumps");
    double sum = half_p * half_p + h;
    if (sum < B)
        return FRICREG_OK;
    /* dt_max solves (omega dt/2)^2 + c dt = B; under the paper's rule dt c is fixed */
    double dt_max = !run->eps_by_rule ? 2.0 * B / (c + sqrt(c * c + B * omega * omega))
                                      : 2.0 * sqrt(B - h) / omega;
    return fr_error_set(err, FRICREG_ESTEP,
                        "%s: dt = %g too large for central differences: (dt*omega/2)^2 + "
                        "dt*lambda = %g >= %g (omega = %g the highest frequency, lambda = %g the "
                        "stick-zone stiffness); reduce dt below %.6g",
                        who, run->dt, sum, B, omega, c, dt_max);
}

/* Central differences with implicit friction (fricreg_sim's central_imex.c): the friction's
 * velocity term is the trapezoid's, stable at every dt lambda, so only the springs (and any
 * explicit damping) bound the step's stability, (dt omega/2)^2 + dt c < FR_CENTRAL_STEP_BOUND
 * (its margin as above). Energy is another matter: where dt lambda >= FR_CENTRAL_STEP_BOUND the
 * step no longer resolves law (4)'s band, (4) reverses within one step like a law that jumps,
 * and the reversal bound applies. Measured without it (tests/ode/test_guard.c's sweep): the
 * oscillator with eps = 0.02 gained 0.45 of an energy scale of 3.8 at dt omega = 1.9, and with
 * mun = 3, eps = 0.05 from dt omega = 1.42; the paper's eps = 2 dt (dt lambda = 1) gained from
 * dt omega = 1.71. With the band resolved, dt lambda below the explicit scheme's own stick-zone
 * bound, the sweep finds no energy put in up to the springs' bound (the chain at
 * dt omega = 1.9). */
static int check_central_imex(const struct fr_guard_run *run, struct fr_error *err, const char *who)
{
    const double B = FR_CENTRAL_STEP_BOUND;
    double lambda = run->rate / run->eps, omega = run->omega;
    double half_p = 0.5 * run->dt * omega, h = run->dt * lambda;
    double springs = half_p * half_p + run->dt * run->damping;
    if (!isfinite(lambda))
        return refuse_overflowing_stick_zone(run, err, who);
    if (!(springs < B))
        return fr_error_set(err, FRICREG_ESTEP,
                            "%s: dt = %g too large for central differences: (dt*omega/2)^2 = %g "
                            ">= %g (omega = %g the highest frequency); reduce dt below %.6g",
                            who, run->dt, springs, B, omega, 2.0 * sqrt(B) / omega);
    if (h >= B && run->dt * omega > REVERSAL_STEP_BOUND)
        return fr_error_set(err, FRICREG_ESTEP,
                            "%s: dt = %g, eps = %g: dt*lambda = %g >= %g leaves law (4)'s band "
                            "unresolved, where dt*omega = %g > %g lets a friction reversal put "
                            "energy in; reduce dt to %.6g or raise eps to %.6g",
                            who, run->dt, run->eps, h, B, run->dt * omega, REVERSAL_STEP_BOUND,
                            REVERSAL_STEP_BOUND / omega, run->dt * run->rate / B * (1.0 + 1e-9));
    return FRICREG_OK;
}

/* A Runge-Kutta step: dt (lambda + c) within the stepper's stick-zone bound, dt omega within
 * its imaginary-axis bound and within REVERSAL_STEP_BOUND. */
static int check_runge_kutta(const struct fr_guard_run *run, struct fr_error *err, const char *who)
{
    const struct fr_integrator *integ = run->integ;
    double lambda = run->rate / run->eps + run->damping;
    if (run->dt * lambda > integ->stick_zone_bound) {
        char what[64];
        snprintf(what, sizeof what, "the stick-zone bound of %s", integ->name);
        return refuse_stick_zone(run, err, who, what, integ->stick_zone_bound);
    }
    double z = run->dt * run->omega;
    if (z > integ->imag_axis_bound)
        return fr_error_set(err, FRICREG_ESTEP,
                            "%s: dt = %g too large for the system's highest frequency %g: "
                            "dt*omega = %g > %g, the stability bound of %s; reduce dt",
                            who, run->dt, run->omega, z, integ->imag_axis_bound, integ->name);
    if (z > REVERSAL_STEP_BOUND)
        return refuse_reversal(run, err, who, "within one step");
    return FRICREG_OK;
}

int fr_step_guard(const struct fr_guard_run *run, struct fr_error *err, const char *who)
{
    if (run->integ->stick_zone_bound == 0.0)
        return FRICREG_OK; /* implicit and multistep steppers report their own failures */
    double lambda = run->rate / run->eps + run->damping; /* +inf when mun/eps overflows */
    if (run->jumps && run->dt * lambda > CHORD_STEP_BOUND)
        return refuse_stick_zone(run, err, who, "where a law that jumps chatters out of its band",
                                 CHORD_STEP_BOUND);
    if (run->integ->implicit_friction)
        return check_central_imex(run, err, who);
    if (run->integ->central)
        return check_central(run, err, who);
    return check_runge_kutta(run, err, who);
}
