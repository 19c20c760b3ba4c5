/* SPDX-License-Identifier: GPL-3.0-or-later */
/* integrate.c — a run's time stepping (integrate.h): each forcing cycle integrated to its
 * exact end, by fixed steps (a failed implicit one retried in halves) or adaptive ones (capped,
 * stopped at the law's kinks: kinks.c); after every step the state is checked for finiteness,
 * because GSL carries a NaN to the end and reports success, the near-stick time is added and
 * the observer called; D per cycle is a difference of two states. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include "integrate.h"
#include "kinks.h"
#include "law/law.h"
#include "ode/integrator.h"
#include "ode/ode_driver.h"
#include "settings.h"
#include "sim_internal.h"

#define STOP_REQUESTED (-1)            /* the observer asked to stop: not an error */
#define MAX_STEP_PER_PERIOD (1.0 / 32) /* an adaptive step's cap, in forcing periods (advance) */

/* The first component of y that has diverged: not finite or beyond FR_SIM_STATE_LIMIT, which no
 * motion of these systems comes near, so an unstable step on its way to overflow. dim if
 * none has. Counted first in one vectorized pass, in DIVERGED_LANES partial counts (an early
 * exit is a branch per component, and one count a serial add), then searched for only when
 * the count is not 0. */
enum { DIVERGED_LANES = 8 };
static size_t first_diverged(const double y[], size_t dim)
{
    double count[DIVERGED_LANES] = {0.0}, diverged = 0.0;
    size_t k = 0;
    for (; k + DIVERGED_LANES <= dim; k += DIVERGED_LANES)
        for (size_t l = 0; l < DIVERGED_LANES; l++)
            count[l] += fabs(y[k + l]) <= FR_SIM_STATE_LIMIT ? 0.0 : 1.0;
    for (; k < dim; k++) /* the tail */
        count[0] += fabs(y[k]) <= FR_SIM_STATE_LIMIT ? 0.0 : 1.0;
    for (size_t l = 0; l < DIVERGED_LANES; l++)
        diverged += count[l];
    for (k = 0; diverged > 0.0 && k < dim && fabs(y[k]) <= FR_SIM_STATE_LIMIT; k++)
        continue;
    return diverged > 0.0 ? k : dim;
}

/* Names component k of the state y = (x, v, D), e.g. "velocity of body 7". */
static const char *state_part(const fricreg_sim *sim, size_t k, char *buf, size_t len)
{
    size_t n = sim->ndof;
    if (k >= 2 * n)
        snprintf(buf, len, "dissipation");
    else
        snprintf(buf, len, "%s of body %zu", k < n ? "position" : "velocity", k % n);
    return buf;
}

static int observe(fricreg_sim *sim)
{
    int status = fr_sim_eval_friction(sim, sim->t, sim->y, 1);
    if (status != FRICREG_OK)
        return fr_fail(sim, status, "run: t = %.17g: %s", sim->t, fricreg_ctx_errmsg(sim->ctx));
    const double *x = sim->y, *v = sim->y + sim->ndof;
    int stop = sim->observer(sim->observer_user, sim->t, sim->ndof, x, v, sim->m, sim->f,
                             sim->f_eq);
    return stop ? STOP_REQUESTED : FRICREG_OK;
}

/* The step's h to the near-stick time of each contact within the band |zdot| < eps. */
static void add_stick_time(fricreg_sim *sim, double h)
{
    const double *zdot = sim->sys.type->contacts(&sim->sys, sim->t, sim->y, sim->y + sim->ndof,
                                                 sim->zdot_buf, NULL);
    for (size_t i = 0; i < sim->m; i++)
        sim->stick_time[i] += fabs(zdot[i]) < sim->eps ? h : 0.0;
}

/* After a step from t_before: finiteness, near-stick time, the observer. */
static int after_step(fricreg_sim *sim, double t_before)
{
    size_t dim = 2 * sim->ndof + 1;
    int checked = sim->step_checked; /* by the step's own last pass: no pass here */
    sim->step_checked = 0;
    size_t k = checked && sim->step_diverged == 0 ? dim : first_diverged(sim->y, dim);
    char part[64];
    if (k < dim)
        return fr_fail(sim, FRICREG_EDIVERGED,
                       "run: state diverged at t = %.17g (%s): the step is unstable; reduce dt",
                       sim->t, state_part(sim, k, part, sizeof part));
    if (!checked)
        add_stick_time(sim, sim->t - t_before);
    return sim->observer ? observe(sim) : FRICREG_OK;
}

static int step_failure(fricreg_sim *sim, int gsl_status)
{
    if (sim->rhs_status == FRICREG_ENONFINITE) /* a stage of the step blew up */
        return fr_fail(sim, FRICREG_EDIVERGED,
                       "run: contact %zu overflowed in the step from t = %.17g: the step is "
                       "unstable; reduce dt",
                       sim->bad_contact, sim->t);
    if (sim->rhs_status == FRICREG_ENOMEM) /* the context never runs out: the Jacobian did */
        return fr_fail(sim, FRICREG_ENOMEM, "run: t = %.17g: out of memory for the Jacobian",
                       sim->t);
    if (sim->rhs_status != FRICREG_OK)
        return fr_fail(sim, sim->rhs_status, "run: t = %.17g: %s", sim->t,
                       fricreg_ctx_errmsg(sim->ctx));
    return fr_fail(sim, FRICREG_EINTEGRATOR, "run: GSL stepper failed at t = %.17g: %s", sim->t,
                   gsl_strerror(gsl_status));
}

/* One fixed step of size h. GSL's implicit and multistep steppers fail a step when their
 * Newton or corrector iteration does not converge, which happens at an exact stick, where the
 * velocity sits at the rounding floor; such a step is retried as two half steps, down to
 * h / 2^MAX_HALVINGS, so the run keeps the caller's step grid. Explicit steppers never fail.
 * Each retried step counts as rejected (FRICREG_SIM_STAT_REJECTED_STEPS), as GSL counts the
 * adaptive control's retries. */
#define MAX_HALVINGS 10

/* A step of fricreg's own fixed-step steppers (rk4_classic.c, central_step.c) straight
 * through the stepper: GSL's evolve would copy the state to restore it on failure, which
 * these steppers never write before they succeed, and have them clear an error estimate
 * they do not make. */
static int own_step(fricreg_sim *sim, gsl_odeiv2_driver *d, double h)
{
    int status = gsl_odeiv2_step_apply(d->s, sim->t, h, sim->y, NULL, NULL, NULL, d->sys);
    if (status == GSL_SUCCESS)
        sim->t += h;
    return status;
}

static int apply_fixed_step(fricreg_sim *sim, gsl_odeiv2_driver *d,
                            const struct fr_integrator *integ, double h, int depth)
{
    double t0 = sim->t, *y = sim->y;
    if (integ->central || integ->fixed_type != NULL) /* explicit: they never fail a step */
        return own_step(sim, d, h);
    int status = fr_ode_apply_fixed_step(d, &sim->t, h, y);
    if (status != GSL_FAILURE || depth == MAX_HALVINGS || sim->rhs_status != FRICREG_OK)
        return status;
    sim->rejected_steps++;
    sim->t = t0; /* GSL leaves t and y unchanged on failure */
    gsl_odeiv2_step_reset(d->s);
    status = apply_fixed_step(sim, d, integ, 0.5 * h, depth + 1);
    return status == GSL_SUCCESS ? apply_fixed_step(sim, d, integ, t0 + h - sim->t, depth + 1)
                                 : status;
}

/* The refusal of a cycle whose adaptive steps passed the bound (fricreg_sim_set_max_steps). */
static int too_much_work(fricreg_sim *sim, const struct fr_integrator *integ, int64_t bound)
{
    if (fr_law_jumps(sim->law))
        return fr_fail(sim, FRICREG_EWORK,
                       "run: more than %lld adaptive steps (%s) in the cycle to t = %.6g: laws "
                       "(1), (2) and Karnopp jump at zdot = 0, where adaptive steps shrink "
                       "without end; take law (4) or fixed steps (fricreg_sim_set_max_steps)",
                       (long long)bound, integ->name, sim->t);
    return fr_fail(sim, FRICREG_EWORK,
                   "run: more than %lld adaptive steps (%s) in the cycle to t = %.6g; "
                   "fricreg_sim_set_max_steps raises the bound",
                   (long long)bound, integ->name, sim->t);
}

/* Integrates from sim->t to t_target exactly. An adaptive step is capped at
 * MAX_STEP_PER_PERIOD of the forcing period: while every contact sticks, the state is at rest
 * and GSL's error estimate is zero whatever the step, but the forcing that will break the
 * stick is not part of the state. Uncapped, msbdf with the exact Jacobian stepped from a stick
 * at t = 0.295 to the cycle's end at 12.57 over a whole slip phase (oscillator a = 2,
 * omega = 0.5, x0 = 0.385, v0 = -0.217, eps 1e-6: D = 0 instead of 10.4). Capped, the step
 * that crosses a break-away lands in the slip phase, where the estimate rejects it. */
static int advance(fricreg_sim *sim, gsl_odeiv2_driver *d, const struct fr_integrator *integ,
                   double t_target, double *h)
{
    double gsl_dt = sim->dt * integ->substeps;
    int64_t cycle_steps = 0; /* adaptive steps accepted in this cycle */
    int64_t bound = sim->max_steps >= 0 ? sim->max_steps : fr_law_max_adaptive_steps(sim->law);
    while (sim->t < t_target) {
        if (fr_sim_adaptive(sim) && bound > 0 && ++cycle_steps > bound)
            return too_much_work(sim, integ, bound);
        double t_before = sim->t;
        int gsl_status, moved = 1;
        if (fr_sim_adaptive(sim)) {
            double t_stop = fmin(t_target, sim->t + MAX_STEP_PER_PERIOD * fr_sim_period(sim));
            if (sim->locate != NULL) /* a kink being re-approached ends the step there */
                t_stop = fr_kinks_before_step(sim->locate, sim, t_stop);
            gsl_status = gsl_odeiv2_evolve_apply(d->e, d->c, d->s, d->sys, &sim->t, t_stop, h,
                                                 sim->y);
        } else {
            /* The last step of a cycle is shortened to end on its boundary. */
            int last = t_target - sim->t <= gsl_dt * (1.0 + 1e-9);
            double step = last ? t_target - sim->t : gsl_dt;
            gsl_status = apply_fixed_step(sim, d, integ, step, 0);
            if (last && gsl_status == GSL_SUCCESS)
                sim->t = t_target;
        }
        if (gsl_status != GSL_SUCCESS)
            return step_failure(sim, gsl_status);
        if (sim->locate != NULL) { /* a kink crossed: the step cut there (kinks.c) */
            int64_t kinks_before = sim->kinks;
            int status = fr_kinks_after_step(sim->locate, sim, d, &moved);
            if (status != FRICREG_OK)
                return status;
            cycle_steps += sim->kinks - kinks_before; /* a location is a step of work */
        }
        if (!moved) { /* back to the step's start, to step up to the kink under control */
            sim->rejected_steps++;
            continue;
        }
        sim->steps += fr_sim_adaptive(sim) ? 1 : integ->substeps;
        int status = after_step(sim, t_before);
        if (status != FRICREG_OK)
            return status;
    }
    return FRICREG_OK;
}

/* time/span, a fraction: the steps' h summed over a cycle can pass the cycle's length by
 * rounding (1.000000000000007 for a contact stuck all cycle), which a fraction cannot. */
static double fraction_of(double time, double span)
{
    return fmin(time / span, 1.0);
}

static void close_cycle(fricreg_sim *sim, double period, double *D_start)
{
    double D_now = sim->y[2 * sim->ndof];
    sim->D[sim->cycles++] = D_now - *D_start;
    if (sim->capture_y != NULL && sim->cycles == sim->capture_cycle)
        memcpy(sim->capture_y, sim->y, (2 * sim->ndof + 1) * sizeof *sim->y);
    *D_start = D_now;
    for (size_t i = 0; i < sim->m; i++) {
        sim->stick_fraction[i] = fraction_of(sim->stick_time[i], period);
        sim->stick_time[i] = 0.0;
    }
}

int fr_sim_integrate(fricreg_sim *sim, gsl_odeiv2_driver *d, const struct fr_integrator *integ,
                     double t_end, size_t cycles)
{
    double T = fr_sim_period(sim), D_start = 0.0, h = sim->dt;
    int status = sim->observer ? observe(sim) : FRICREG_OK;
    for (size_t k = sim->start_cycle + 1; status == FRICREG_OK && sim->t < t_end; k++) {
        int whole = k <= sim->start_cycle + cycles;
        status = advance(sim, d, integ, whole ? (double)k * T : t_end, &h);
        if (status == FRICREG_OK && whole)
            close_cycle(sim, T, &D_start);
    }
    if (sim->cycles == 0 && sim->t > 0.0) /* no whole cycle: report over the whole run */
        for (size_t i = 0; i < sim->m; i++)
            sim->stick_fraction[i] = fraction_of(sim->stick_time[i], sim->t);
    return status == STOP_REQUESTED ? FRICREG_OK : status;
}
