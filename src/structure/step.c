/* SPDX-License-Identifier: GPL-3.0-or-later */
/* step.c — stepping a fricreg_structure: the equilibrium acceleration at the start, one
 * step of the selected scheme (newmark.c, central_difference.c), the energy balance
 * (energy.c), the peaks (peak.c) and the counters; a single step and a run of fixed steps,
 * plain: the public calls (run.c) add the error estimate's companions and the warning
 * handler. */
#include <float.h>
#include <math.h>

#include "structure_internal.h"

#define STATE_LIMIT 1e100 /* |state| beyond this: diverged */
#define MAX_RUN_STEPS 2147483648.0

static void swap(gsl_vector **x, gsl_vector **y)
{
    gsl_vector *t = *x;
    *x = *y;
    *y = t;
}

/* One step from s->t to t1 (> s->t). A failed step changes nothing a getter shows: the
 * equilibrium it computed at t (after set_initial or a setter) is undone, the next step
 * computes it again, the line search's cuts are not counted, and the balance starts at the
 * first step that succeeds. */
static int step_to(fricreg_structure *s, double t1)
{
    double dt = t1 - s->t;
    int64_t cuts = s->stats[FRICREG_SSTAT_LINE_SEARCH_CUTS];
    int status = fr_structure_prepare(s);
    if (status != FRICREG_OK)
        return status;
    int equilibrium = !s->ready;
    if (equilibrium) {
        gsl_vector_memcpy(s->a_held, s->a);
        gsl_vector_memcpy(s->f_held, s->f);
        fr_elements_hold(s, 0);
        status = fr_structure_equilibrium(s);
    }
    int converged = 1, iters = 0;
    if (status == FRICREG_OK) {
        fr_structure_effective_load(s, t1, s->ptil1);
        if (s->scheme == FR_SCHEME_CENTRAL)
            status = fr_central_solve(s, dt);
        else
            status = fr_newmark_solve(s, dt, &converged, &iters);
    }
    if (status == FRICREG_OK && !(s->end_max <= STATE_LIMIT))
        status = fr_fail(s, FRICREG_EDIVERGED, "step: the state at t = %g is beyond 1e100", t1);
    if (status != FRICREG_OK) {
        s->stats[FRICREG_SSTAT_LINE_SEARCH_CUTS] = cuts;
        if (equilibrium) {
            gsl_vector_memcpy(s->a, s->a_held);
            gsl_vector_memcpy(s->f, s->f_held);
            fr_elements_hold(s, 1);
            s->ready = 0;
        }
        return status;
    }

    if (s->fresh)
        fr_energy_start(s);
    fr_energy_step(s, s->u1, s->v1, s->ptil1, s->f1);
    fr_elements_commit(s);
    fr_peak_step(s, s->u1->data, s->v1->data, dt);
    /* The step's end becomes the state: the vectors trade places, nothing is copied. */
    swap(&s->u, &s->u1);
    swap(&s->v, &s->v1);
    swap(&s->a, &s->x);
    swap(&s->ptil, &s->ptil1);
    swap(&s->f, &s->f1);
    s->t = t1;
    s->fresh = 0;
    s->stats[FRICREG_SSTAT_STEPS]++;
    s->stats[FRICREG_SSTAT_NEWTON_ITERATIONS] += iters;
    if (iters > s->stats[FRICREG_SSTAT_NEWTON_MAX])
        s->stats[FRICREG_SSTAT_NEWTON_MAX] = iters;
    if (!converged)
        s->stats[FRICREG_SSTAT_NEWTON_FAILURES]++;
    fr_warn_track_step(s, dt, 0);
    return FRICREG_OK;
}

static int check_dt(fricreg_structure *s, const char *name, double dt)
{
    if (!isfinite(dt))
        return fr_fail(s, FRICREG_ENONFINITE, "%s: dt is not finite", name);
    if (!(dt > 0.0))
        return fr_fail(s, FRICREG_EINVAL, "%s: dt = %g must be > 0", name, dt);
    return FRICREG_OK;
}

int fr_structure_step_plain(fricreg_structure *s, double dt)
{
    int status = check_dt(s, "step", dt);
    if (status != FRICREG_OK)
        return status;
    double t1 = s->t + dt;
    if (!(t1 > s->t))
        return fr_fail(s, FRICREG_EINVAL, "step: dt = %g is lost against t = %g", dt, s->t);
    status = step_to(s, t1);
    if (status == FRICREG_OK)
        s->clock_k = 0; /* off any run's grid */
    return status;
}

/* The grid a run of dt steps on: the last run's when it ended where this one starts with the
 * same dt (its origin into *t0, the steps it took into *k0), so that a run split into several
 * calls (or continued after fricreg_structure_restore) takes the steps of one call; else one
 * from the current time. */
static void run_grid(const fricreg_structure *s, double dt, double *t0, int64_t *k0)
{
    *t0 = s->t;
    *k0 = 0;
    if (s->clock_k > 0 && s->clock_k < ((int64_t)1 << 53) && s->clock_dt == dt &&
        s->t == s->clock_t0 + (double)s->clock_k * s->clock_dt) {
        *t0 = s->clock_t0;
        *k0 = s->clock_k;
    }
}

int fr_structure_run_plain(fricreg_structure *s, double dt, double t_end)
{
    int status = check_dt(s, "run", dt);
    if (status != FRICREG_OK)
        return status;
    if (!isfinite(t_end))
        return fr_fail(s, FRICREG_ENONFINITE, "run: t_end is not finite");
    if (!(t_end > s->t))
        return fr_fail(s, FRICREG_EINVAL, "run: t_end = %g must be after t = %g", t_end, s->t);
    double t0;
    int64_t k0;
    run_grid(s, dt, &t0, &k0);
    /* Steps that end within 1e-12 dt, or within rounding of the times (4 ulps of t), of t_end
     * land on it: no sliver of a last step. */
    double slack = 4.0 * DBL_EPSILON * fmax(fabs(t0), fabs(t_end)) / dt;
    double steps = ceil((t_end - t0) / dt * (1.0 - 1e-12) - slack) - (double)k0;
    if (steps > MAX_RUN_STEPS)
        return fr_fail(s, FRICREG_EINVAL, "run: %g steps of dt = %g exceed 2^31", steps, dt);
    int64_t nsteps = k0 + (steps < 1.0 ? 1 : (int64_t)steps);
    s->running = 1;
    for (int64_t k = k0 + 1; k <= nsteps && status == FRICREG_OK; k++) {
        double t1 = k == nsteps ? t_end : t0 + (double)k * dt;
        if (!(t1 > s->t))
            status = fr_fail(s, FRICREG_EINVAL, "run: dt = %g is lost against t = %g", dt, s->t);
        else
            status = step_to(s, t1);
        if (status == FRICREG_OK) {
            s->clock_t0 = t0;
            s->clock_dt = dt;
            s->clock_k = k;
        }
        if (status == FRICREG_OK &&
            fr_structure_observe(s, s->t, s->u->data, s->v->data, s->f->data))
            break; /* the observer asked to stop: not an error */
    }
    s->running = 0;
    return status;
}

int fr_structure_observe(fricreg_structure *s, double t, const double u[], const double v[],
                         const double f[])
{
    return s->observer != NULL && s->observer(s->observer_user, t, s->n, u, v, s->m, f) != 0;
}
