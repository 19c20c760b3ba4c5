/* SPDX-License-Identifier: GPL-3.0-or-later */
/* kinks.c — fricreg_sim's adaptive steps stopped at the friction law's kinks (kinks.h;
 * fricreg_sim_set_kink_location; docs/integrators.md, "Kink location in fricreg's drivers").
 *
 * Law (4) is piecewise smooth: an error-controlled step across one of its kinks has neither
 * the order nor the error estimate the control assumes, and a multistep stepper's history
 * spans the kink for steps after it. fricreg_ctx_switching gives each contact's signed
 * distances to its law's kinks, continuous in the state. After every accepted step they are
 * compared with the step's start; where one changed sign, the first crossing within the step
 * is found by Brent's method (gsl_root_fsolver_brent) on trial steps of length tau from the
 * step's start, so that the crossing is that of the stepper's own solution. GSL's steppers
 * have no dense output, hence the trial steps: for a one-step stepper its own step (a step
 * within one smooth piece, no longer than the one the control accepted), for a multistep one,
 * whose step depends on its history, the one-step locator of the integrator table
 * (integrator.h). The step is cut just past the crossing, where the sign has changed: on the
 * trial step's state where the control accepts its error estimate, else by returning to the
 * step's start and letting the control step up to that time. Then the driver is reset, so
 * that the stepper starts afresh on the new smooth piece (a multistep one at order 1), as
 * CVODE's users do with CVodeReInit after a root.
 *
 * GSL's error handler, process-wide and aborting by default, is kept out: Brent's solver is
 * on fricreg's memory (as src/exact/exact.c's), its bracket is set only on a strict change of
 * sign, the function it sees is finite, and the interval test is fricreg's own. */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include "kinks.h"

#define ROOT_REL_TOL 1e-10 /* the crossing's time, to 1e-10 of the step ... */
#define ROOT_ULPS 4.0      /* ... or to 4 ulps of t, whichever is larger */
#define ROOT_MAX_ITER 100  /* Brent's iterations (about 40 halve a step to 1e-10 of it) */
#define MAX_EARLIER 8      /* brackets narrowed to a component that crossed earlier */
#define MAX_PAST 4         /* trial steps to leave a crossing behind (past) */

struct fr_kinks {
    size_t dim, ng;
    double *block;                            /* the one allocation behind the arrays below */
    double *g_start, *g_end, *g_trial;        /* [ng] switching functions */
    double *y_start, *y_trial, *y_err, *dydt; /* [dim]; dydt zero: the control's a_dydt = 0 */
    double t_start;                           /* the step's start */
    double t_pending;         /* a crossing re-approached under the control: where the step ends */
    int reads_f;              /* the switching functions read the forces (a coupled W) */
    gsl_odeiv2_step *own;     /* a multistep integrator's locator, else NULL */
    gsl_odeiv2_step *stepper; /* the trial steps': own, or the driver's stepper */
    gsl_root_fsolver brent;   /* on fricreg's memory */
    /* The root's function: component comp along the trial steps; its value at tau_known,
     * the bracket's upper end, kept so that Brent sees the sign the bracket was chosen by. */
    fricreg_sim *sim;
    const gsl_odeiv2_system *sys;
    size_t comp;
    double tau_known, g_known;
};

struct fr_kinks *fr_kinks_new(fricreg_sim *sim, gsl_odeiv2_driver *d,
                              const struct fr_integrator *integ)
{
    struct fr_kinks *k = calloc(1, sizeof *k);
    if (k == NULL)
        return NULL;
    k->dim = 2 * sim->ndof + 1;
    k->ng = fricreg_ctx_switching_count(sim->ctx);
    double *block = calloc(3 * k->ng + 4 * k->dim, sizeof *block);
    k->brent.state = malloc(gsl_root_fsolver_brent->size);
    const gsl_odeiv2_step_type *T = integ->locator ? integ->locator() : NULL;
    k->own = block && k->brent.state && T ? gsl_odeiv2_step_alloc(T, k->dim) : NULL;
    if (block == NULL || k->brent.state == NULL || (integ->locator && k->own == NULL)) {
        free(block);
        fr_kinks_free(k);
        return NULL;
    }
    k->block = block;
    k->g_start = block, k->g_end = block + k->ng, k->g_trial = block + 2 * k->ng;
    k->y_start = block + 3 * k->ng, k->y_trial = k->y_start + k->dim;
    k->y_err = k->y_trial + k->dim, k->dydt = k->y_err + k->dim;
    k->brent.type = gsl_root_fsolver_brent;
    if (k->own != NULL)
        gsl_odeiv2_step_set_driver(k->own, d);
    k->stepper = k->own ? k->own : d->s;
    k->reads_f = !sim->sys.type->contacts_are_bodies; /* the bodies' W is diagonal */
    k->sim = sim;
    k->sys = d->sys;
    k->t_pending = INFINITY;
    k->tau_known = -1.0;
    return k;
}

void fr_kinks_free(struct fr_kinks *k)
{
    if (k == NULL)
        return;
    free(k->block);
    free(k->brent.state);
    if (k->own != NULL)
        gsl_odeiv2_step_free(k->own);
    free(k);
}

/* The switching functions at (t, y) into g: the contacts' kinematics, the forces where they
 * are read (a coupled W), then fricreg_ctx_switching. A fricreg status. */
static int switching_at(struct fr_kinks *k, double t, const double y[], double g[])
{
    fricreg_sim *sim = k->sim;
    const double *zdot = sim->sys.type->contacts(&sim->sys, t, y, y + sim->ndof, sim->zdot_buf,
                                                 sim->a_free);
    int status = FRICREG_OK;
    if (k->reads_f)
        status = fricreg_ctx_eval(sim->ctx, sim->m, zdot, sim->a_free, sim->f, NULL);
    if (status == FRICREG_OK)
        status = fricreg_ctx_switching(sim->ctx, sim->m, zdot, sim->a_free, sim->f, g, k->ng);
    return status;
}

int fr_kinks_start(struct fr_kinks *k, fricreg_sim *sim)
{
    int status = switching_at(k, sim->t, sim->y, k->g_start);
    if (status != FRICREG_OK)
        return fr_fail(sim, status, "run: t = %.17g: %s", sim->t, fricreg_ctx_errmsg(sim->ctx));
    return FRICREG_OK;
}

double fr_kinks_before_step(struct fr_kinks *k, const fricreg_sim *sim, double t_stop)
{
    memcpy(k->y_start, sim->y, k->dim * sizeof *k->y_start);
    k->t_start = sim->t;
    return fmin(t_stop, k->t_pending);
}

static int sign_of(double x)
{
    return (x > 0.0) - (x < 0.0);
}

/* Component j crossed a kink between the step's start and g: it left a nonzero value. */
static int changed(const struct fr_kinks *k, size_t j, const double g[])
{
    return k->g_start[j] != 0.0 && sign_of(g[j]) != sign_of(k->g_start[j]);
}

/* The component that changed sign from the step's start to g and crossed first by a linear
 * estimate along the way, or ng if none changed. */
static size_t first_changed(const struct fr_kinks *k, const double g[])
{
    size_t first = k->ng;
    double first_s = INFINITY;
    for (size_t j = 0; j < k->ng; j++) {
        if (!changed(k, j, g))
            continue;
        double s = k->g_start[j] / (k->g_start[j] - g[j]); /* in (0, 1] */
        if (s < first_s)
            first = j, first_s = s;
    }
    return first;
}

/* One trial step of tau from the step's start into y_trial (error estimate y_err) and its
 * switching functions into g_trial: FRICREG_OK, or a failure of the step or of the state
 * (FRICREG_EINTEGRATOR: the state is not usable), which leaves the run's status untouched. */
static int trial(struct fr_kinks *k, double tau)
{
    fricreg_sim *sim = k->sim;
    memcpy(k->y_trial, k->y_start, k->dim * sizeof *k->y_trial);
    gsl_odeiv2_step_reset(k->stepper); /* a step from the start, with no memory of another */
    int gsl_status = gsl_odeiv2_step_apply(k->stepper, k->t_start, tau, k->y_trial, k->y_err, NULL,
                                           NULL, k->sys);
    sim->rhs_status = FRICREG_OK; /* a trial's failure is no failure of the run */
    int finite = gsl_status == GSL_SUCCESS;
    for (size_t i = 0; finite && i < k->dim; i++)
        finite = isfinite(k->y_trial[i]) && isfinite(k->y_err[i]); /* bsimp: yerr = Inf */
    if (!finite || switching_at(k, k->t_start + tau, k->y_trial, k->g_trial) != FRICREG_OK)
        return FRICREG_EINTEGRATOR;
    return FRICREG_OK;
}

/* Component comp along the trial steps, for Brent: finite always (GSL reports a non-finite
 * value to its error handler). A trial that fails counts as past the crossing, so that the
 * bracket shrinks towards the start, where trial steps are short. */
static double along_trials(double tau, void *params)
{
    struct fr_kinks *k = params;
    double g0 = k->g_start[k->comp];
    if (tau <= 0.0)
        return g0;
    if (tau == k->tau_known)
        return k->g_known;
    if (trial(k, tau) != FRICREG_OK)
        return -g0;
    double g = k->g_trial[k->comp];
    return isnan(g) ? -g0 : fmax(-DBL_MAX, fmin(g, DBL_MAX));
}

/* The crossing of component comp within (0, b], where it has the value gb of the other sign
 * than at the start (or 0): [*lo, *hi] of width at most tol, *hi past the crossing. */
static void bracket_crossing(struct fr_kinks *k, double b, double gb, double tol, double *lo,
                             double *hi)
{
    *lo = 0.0, *hi = b;
    if (gb == 0.0) { /* the crossing is b itself */
        *lo = b;
        return;
    }
    k->tau_known = b, k->g_known = gb;
    gsl_function F = {along_trials, k};
    gsl_root_fsolver_set(&k->brent, &F, 0.0, b); /* a strict change of sign: no GSL error */
    double a = 0.0, c = b;                       /* the bracket, from Brent's */
    for (int it = 0; it < ROOT_MAX_ITER && c - a > tol; it++) {
        if (gsl_root_fsolver_iterate(&k->brent) != GSL_SUCCESS)
            break;
        a = gsl_root_fsolver_x_lower(&k->brent);
        c = gsl_root_fsolver_x_upper(&k->brent);
    }
    *lo = a, *hi = c;
    k->tau_known = -1.0;
}

/* The first trial step from tau on, by growing increments of at least dtau, where component
 * comp has changed sign: a step cut there leaves the crossing behind it, at least dtau on
 * (a start on the kink itself, within rounding on its old side, would cut nothing and meet
 * the kink again); 0 where none is found short of h (trial states within rounding of the
 * crossing that do not settle on its new side). */
static double past(struct fr_kinks *k, double tau, double dtau, double h)
{
    for (int n = 0; n < MAX_PAST && tau < h; n++, tau += dtau, dtau *= 4.0)
        if (trial(k, tau) == FRICREG_OK && changed(k, k->comp, k->g_trial))
            return tau;
    return 0.0;
}

/* The first crossing of any component within (0, h] along the trial steps: *tau just past it
 * (its trial state in y_trial, g_trial), or 0 where the trial steps see no change of sign
 * at h (a multistep stepper's locator may disagree with the stepper on a grazing crossing)
 * or fail at the crossing. */
static double first_crossing(struct fr_kinks *k, double h)
{
    double tol = fmax(ROOT_REL_TOL * h, ROOT_ULPS * DBL_EPSILON * fabs(k->t_start + h));
    if (trial(k, h) != FRICREG_OK)
        return 0.0;
    double b = h, lo = 0.0, hi = h;
    for (int round = 0; round < MAX_EARLIER; round++) {
        k->comp = first_changed(k, k->g_trial); /* a change at b: always found after round 0 */
        if (k->comp == k->ng)
            return 0.0;
        bracket_crossing(k, b, k->g_trial[k->comp], tol, &lo, &hi);
        if (lo <= 0.0 || trial(k, lo) != FRICREG_OK || first_changed(k, k->g_trial) == k->ng)
            break; /* no other component crossed before lo */
        b = lo;    /* one did: its crossing comes first */
    }
    return past(k, fmax(hi, tol), fmax(hi - lo, tol), h);
}

/* Whether the control accepts the trial state's error estimate for a step of tau. */
static int control_accepts(const struct fr_kinks *k, gsl_odeiv2_driver *d, double tau)
{
    double h = tau;
    return gsl_odeiv2_control_hadjust(d->c, k->stepper, k->y_trial, k->y_err, k->dydt, &h) !=
           GSL_ODEIV_HADJ_DEC;
}

/* The driver's stepper and control restarted, GSL's rejection count kept. */
static void restart(fricreg_sim *sim, gsl_odeiv2_driver *d)
{
    sim->rejected_steps += (int64_t)d->e->failed_steps;
    gsl_odeiv2_driver_reset(d);
}

static void swap(double **a, double **b)
{
    double *t = *a;
    *a = *b, *b = t;
}

int fr_kinks_after_step(struct fr_kinks *k, fricreg_sim *sim, gsl_odeiv2_driver *d, int *moved)
{
    *moved = 1;
    if (sim->t == k->t_pending) { /* the control stepped up to a crossing: start afresh */
        k->t_pending = INFINITY;
        sim->kinks++;
        restart(sim, d);
        return fr_kinks_start(k, sim);
    }
    if (switching_at(k, sim->t, sim->y, k->g_end) != FRICREG_OK)
        return FRICREG_OK; /* a state that overflowed: the after-step check reports it */
    if (first_changed(k, k->g_end) == k->ng) {
        swap(&k->g_start, &k->g_end);
        return FRICREG_OK;
    }
    double h = sim->t - k->t_start, tau = first_crossing(k, h);
    double tol = fmax(ROOT_REL_TOL * h, ROOT_ULPS * DBL_EPSILON * fabs(sim->t));
    restart(sim, d);
    if (!(tau > 0.0) || tau >= h - tol) { /* at the step's end, or not seen by the trials */
        sim->kinks += tau > 0.0;
        swap(&k->g_start, &k->g_end);
        return FRICREG_OK;
    }
    if (control_accepts(k, d, tau)) { /* the trial step to the crossing is the step */
        memcpy(sim->y, k->y_trial, k->dim * sizeof *sim->y);
        sim->t = k->t_start + tau;
        swap(&k->g_start, &k->g_trial);
        k->t_pending = INFINITY;
        sim->kinks++;
        return FRICREG_OK;
    }
    /* back to the start, and up to the crossing under the control (counted when reached) */
    memcpy(sim->y, k->y_start, k->dim * sizeof *sim->y);
    sim->t = k->t_start;
    k->t_pending = k->t_start + tau;
    *moved = 0;
    return FRICREG_OK;
}
