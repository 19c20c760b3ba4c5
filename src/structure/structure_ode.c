/* SPDX-License-Identifier: GPL-3.0-or-later */
/* structure_ode.c — a fricreg_structure integrated by GSL's gsl_odeiv2 steppers (the table of
 * integrator.c, as the reference systems' drivers use it).
 *
 * First-order form, y = (u, v, W_in, E_visc, D_1 … D_m):
 *   u' = v,   M v' = p~(t) - C v - K u + J^T f(J v, a_free),   W_in' = v.p~,
 *   E_visc' = v.C v,   D_i' = -zdot_i f_i,
 * so the energy balance is integrated by the same scheme as the motion. Fixed explicit steps
 * pass the drivers' one step guard (src/ode/step_guard.c, through guard.c). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include "base/sparse_ops.h"
#include "ctx/ctx_driver.h"
#include "law/law.h"
#include "ode/fd_jacobian.h"
#include "ode/integrator.h"
#include "fricreg_sim.h"
#include "ode/ode_driver.h"
#include "structure_internal.h"
#include "base/free_all.h"

#define MAX_GSL_STEPS 2147483648.0
#define MAX_HALVINGS 10
/* The largest step times fr_structure_newton_rate that GSL's LU-based steppers are given:
 * 1e12, below 1/DBL_EPSILON = 4.5e15 where I - h c J rounds to a singular matrix (C = 1e300
 * [[1, 1], [1, 1]] at h = 1: 1 + 1e300 = 1e300, and the LU's second pivot is exactly 0). */
#define NEWTON_RATE_LIMIT 1e12
/* The largest |J_ij| h_max of a Jacobian handed to GSL's LU-based steppers. The rates above
 * bound the motion's rows, not the energies' (v.p~ in W_in' has the load in its row) nor a
 * forward difference of a huge acceleration (its rounding, 1e-8 |a|, becomes an entry): a
 * load of -DBL_MAX at h = 3.6e6 (bsimp) made an entry -Inf, GSL's LU pivoted on it, every
 * multiplier below it was 0, and a later pivot exactly 0. Far above any useful run; below it
 * no multiplier underflows. */
#define JACOBIAN_LIMIT 1e100

struct ode_run {
    fricreg_structure *s;
    size_t dim;
    double *jac_work; /* [3 dim] */
    double h_max;     /* the largest step GSL may take */
    int rhs_status;
    size_t jac_beyond; /* the Jacobian's entry beyond JACOBIAN_LIMIT (rhs_status EINTEGRATOR) */
};

static int rhs(double t, const double y[], double dydt[], void *params)
{
    struct ode_run *run = params;
    fricreg_structure *s = run->s;
    size_t n = s->n;
    gsl_vector_const_view u = gsl_vector_const_view_array(y, n);
    gsl_vector_const_view v = gsl_vector_const_view_array(y + n, n);
    gsl_vector_view acc = gsl_vector_view_array(dydt + n, n);
    fr_structure_effective_load(s, t, s->ptil1);
    fr_structure_net_force(s, s->ptil1, &u.vector, &v.vector, s->work);
    int status = fr_structure_motion(s, s->work, &v.vector, s->f1, &acc.vector);
    if (status != FRICREG_OK) {
        run->rhs_status = status;
        return GSL_EBADFUNC; /* GSL stops the step at once */
    }
    memcpy(dydt, y + n, n * sizeof *dydt);
    double input = 0.0, viscous = 0.0;
    fr_sym_mult(s->Cd, 1.0, y + n, 0.0, s->work->data);
    for (size_t k = 0; k < n; k++) {
        input += y[n + k] * s->ptil1->data[k];
        viscous += y[n + k] * s->work->data[k];
    }
    dydt[2 * n] = input;
    dydt[2 * n + 1] = viscous;
    for (size_t i = 0; i < s->m; i++)
        dydt[2 * n + 2 + i] = -gsl_vector_get(s->zdot, i) * gsl_vector_get(s->f1, i);
    return GSL_SUCCESS;
}

/* For the implicit steppers: forward differences, as the drivers' (fd_jacobian.h). They are
 * all GSL's LU-based ones: an entry beyond JACOBIAN_LIMIT / h_max (or NaN) stops the run
 * before GSL factors I - h c J (FRICREG_EINTEGRATOR). */
static int jacobian(double t, const double y[], double *dfdy, double dfdt[], void *params)
{
    struct ode_run *run = params;
    int status = fr_fd_jacobian(rhs, run, run->dim, run->jac_work, t, y, dfdy, dfdt);
    for (size_t k = 0; status == GSL_SUCCESS && k < run->dim * run->dim; k++)
        if (!(fabs(dfdy[k]) * run->h_max <= JACOBIAN_LIMIT)) {
            run->rhs_status = FRICREG_EINTEGRATOR;
            run->jac_beyond = k;
            return GSL_EBADFUNC; /* GSL stops the step at once */
        }
    return status;
}

/* One fixed step of size h; an implicit or multistep stepper whose iteration fails (at an
 * exact stick) retries it as two half steps, as the drivers do. */
static int fixed_step(gsl_odeiv2_driver *d, double *t, double h, double y[], int depth)
{
    double t0 = *t;
    int status = fr_ode_apply_fixed_step(d, t, h, y);
    if (status != GSL_FAILURE || depth == MAX_HALVINGS)
        return status;
    *t = t0;
    gsl_odeiv2_step_reset(d->s);
    status = fixed_step(d, t, 0.5 * h, y, depth + 1);
    return status == GSL_SUCCESS ? fixed_step(d, t, t0 + h - *t, y, depth + 1) : status;
}

static int beyond(const double y[], size_t dim)
{
    for (size_t k = 0; k < dim; k++)
        if (!(fabs(y[k]) <= 1e100))
            return 1;
    return 0;
}

/* The refusal of a call whose adaptive steps passed the bound (set_max_steps). */
static int too_much_work(fricreg_structure *s, const struct fr_integrator *integ, double t,
                         int64_t bound)
{
    if (fr_law_jumps(fr_ctx_law(s->ctx)))
        return fr_fail(s, FRICREG_EWORK,
                       "run_ode: more than %lld adaptive steps (%s) by t = %.6g: laws (1), (2) "
                       "and Karnopp jump at zdot = 0, where adaptive steps shrink without end; "
                       "take law (4) or Newmark (fricreg_structure_set_max_steps)",
                       (long long)bound, integ->name, t);
    return fr_fail(s, FRICREG_EWORK,
                   "run_ode: more than %lld adaptive steps (%s) by t = %.6g; "
                   "fricreg_structure_set_max_steps raises the bound",
                   (long long)bound, integ->name, t);
}

/* Integrates y from s->t to t_end; on success or failure s->t is where y is. */
static int integrate(fricreg_structure *s, struct ode_run *run, gsl_odeiv2_driver *d,
                     const struct fr_integrator *integ, int adaptive, double dt, double t_end,
                     double y[])
{
    double gsl_dt = dt * integ->substeps, h = gsl_dt, t = s->t;
    int64_t steps = 0; /* adaptive steps accepted by this call */
    int64_t bound = s->max_steps >= 0 ? s->max_steps
                                      : fr_law_max_adaptive_steps(fr_ctx_law(s->ctx));
    while (t < t_end) {
        int status;
        if (adaptive && bound > 0 && ++steps > bound)
            return too_much_work(s, integ, t, bound);
        if (adaptive) {
            status = gsl_odeiv2_evolve_apply(d->e, d->c, d->s, d->sys, &t, t_end, &h, y);
        } else {
            int last = t_end - t <= gsl_dt * (1.0 + 1e-9);
            status = fixed_step(d, &t, last ? t_end - t : gsl_dt, y, 0);
            if (last && status == GSL_SUCCESS)
                t = t_end;
        }
        if (status != GSL_SUCCESS) {
            if (run->rhs_status == FRICREG_EINTEGRATOR)
                return fr_fail(s, FRICREG_EINTEGRATOR,
                               "run_ode: t = %.17g: the Jacobian's entry (%zu, %zu) times the "
                               "step %g is beyond 1e100 (or NaN): GSL's LU could round I - h J "
                               "to a singular matrix; the load or the state is too large for %s",
                               t, run->jac_beyond / run->dim, run->jac_beyond % run->dim,
                               run->h_max, integ->name);
            if (run->rhs_status != FRICREG_OK)
                return fr_fail(s,
                               run->rhs_status == FRICREG_ENONFINITE ? FRICREG_EDIVERGED
                                                                     : run->rhs_status,
                               "run_ode: t = %.17g: %s", t, fricreg_ctx_errmsg(s->ctx));
            return fr_fail(s, FRICREG_EINTEGRATOR,
                           "run_ode: GSL stepper failed at t = %.17g:"
                           " %s",
                           t, gsl_strerror(status));
        }
        if (beyond(y, run->dim))
            return fr_fail(s, FRICREG_EDIVERGED,
                           "run_ode: the state at t = %.17g is beyond "
                           "1e100: the step is unstable; reduce dt",
                           t);
        /* accept: the structure's state follows the integration; the peaks take in the step's
         * end and its turning points, adaptive steps as fixed ones (peak.c) */
        fr_peak_step(s, y, y + s->n, t - s->t);
        memcpy(s->u->data, y, s->n * sizeof *y);
        memcpy(s->v->data, y + s->n, s->n * sizeof *y);
        s->energy.input = y[2 * s->n];
        s->energy.viscous = y[2 * s->n + 1];
        s->energy.friction = 0.0;
        for (size_t i = 0; i < s->m; i++) {
            s->energy.per_contact[i] = y[2 * s->n + 2 + i];
            s->energy.friction += y[2 * s->n + 2 + i];
        }
        s->t = t;
        s->stats[FRICREG_SSTAT_STEPS] += adaptive ? 1 : integ->substeps;
        fr_warn_track_step(s, adaptive ? 0.0 : dt, 1); /* a fixed step's length: dt_coarse */
        if (s->observer != NULL && rhs(t, y, run->jac_work, run) == GSL_SUCCESS &&
            fr_structure_observe(s, t, y, y + s->n, s->f1->data))
            break; /* the observer asked to stop (its forces at (t, y)): not an error */
    }
    return FRICREG_OK;
}

int fr_structure_run_ode_plain(fricreg_structure *s, int integrator, double dt, double rtol,
                               double atol, double t_end)
{
    const struct fr_integrator *integ = fr_integrator_find(integrator);
    if (integ == NULL)
        return fr_fail(s, FRICREG_EINVAL, "run_ode: unknown integrator %d", integrator);
    if (integ->central) /* its stepper knows fricreg_sim's state layout only */
        return fr_fail(s, FRICREG_EINVAL,
                       "run_ode: integrator %s is fricreg_sim's; a structure has its "
                       "own central difference (fricreg_structure_step)",
                       integ->name);
    if (s->el.me > 0) /* a slider's commit needs accepted steps GSL's stages do not show */
        return fr_fail(s, FRICREG_EINVAL,
                       "run_ode: the structure has Jenkins elements, which only "
                       "fricreg_structure_step's schemes integrate");
    if (!isfinite(dt) || !isfinite(rtol) || !isfinite(atol) || !isfinite(t_end))
        return fr_fail(s, FRICREG_ENONFINITE, "run_ode: dt, rtol, atol or t_end not finite");
    int from_eps = atol == FRICREG_ATOL_FROM_EPS;
    if (!(dt > 0.0) || rtol < 0.0 || (atol < 0.0 && !from_eps))
        return fr_fail(s, FRICREG_EINVAL,
                       "run_ode: dt = %g must be > 0, rtol = %g and "
                       "atol = %g >= 0 (or atol = FRICREG_ATOL_FROM_EPS = -1)",
                       dt, rtol, atol);
    if (from_eps && !(rtol > 0.0))
        return fr_fail(s, FRICREG_EINVAL,
                       "run_ode: atol = FRICREG_ATOL_FROM_EPS needs rtol > 0, got %g", rtol);
    if (!(t_end > s->t))
        return fr_fail(s, FRICREG_EINVAL, "run_ode: t_end = %g must be after t = %g", t_end, s->t);
    int adaptive = rtol > 0.0 || atol != 0.0;
    /* per component (the rule from eps, or set): every level > 0 */
    int per_component = adaptive && (from_eps || s->ode_atol != NULL);
    if (adaptive && atol == 0.0 && !per_component && integ->atol_required)
        return fr_fail(s, FRICREG_EINVAL,
                       "run_ode: %s needs atol > 0: its iteration converges to atol + rtol |y|, "
                       "which is 0 where a state component is 0 (a start at rest, the energies "
                       "at t = 0)",
                       integ->name);
    if (!adaptive && (t_end - s->t) / (dt * integ->substeps) > MAX_GSL_STEPS)
        return fr_fail(s, FRICREG_EINVAL, "run_ode: (t_end - t)/dt is too many steps");

    int status = fr_structure_prepare(s);
    if (status == FRICREG_OK)
        status = fr_structure_rates(s, "run_ode");
    if (status == FRICREG_OK && integ->lu_newton && !fr_structure_stable(s))
        return fr_fail(s, FRICREG_EINVAL,
                       "run_ode: integrator %s solves its Newton matrix by GSL's LU, which a "
                       "structure whose K or C is not positive semidefinite (unstable) can make "
                       "singular; take Newmark or HHT, or an explicit stepper",
                       integ->name);
    /* The largest step GSL may take: dt, or the whole span when adaptive. */
    double h_max = adaptive ? t_end - s->t : dt * integ->substeps;
    if (status == FRICREG_OK && integ->lu_newton &&
        !(h_max * fr_structure_newton_rate(s) <= NEWTON_RATE_LIMIT))
        return fr_fail(s, FRICREG_EINVAL,
                       "run_ode: integrator %s solves I - h J by GSL's LU, which rounding can "
                       "make singular: the step %g times the stiffest rate %g (frequency, "
                       "damping or friction slope) exceeds 1e12; take a smaller %s, Newmark or "
                       "HHT, or an explicit stepper",
                       integ->name, h_max, fr_structure_newton_rate(s),
                       adaptive ? "t_end - t" : "dt");
    if (status == FRICREG_OK && !adaptive) {
        s->stick_valid = 0; /* law, eps or bounds may have changed since the last step */
        status = fr_structure_guard(s, integ, dt, "run_ode");
    }
    if (status != FRICREG_OK)
        return status;
    /* The balance starts at t = 0 with the first step accepted (below): a run that fails
     * before one changes nothing a getter shows. */
    double initial = fr_energy_kinetic(s) + fr_energy_strain(s), t_start = s->t;

    /* Everything is allocated before the run starts: a failed allocation leaves the
     * structure as it was. */
    struct ode_run run = {.s = s,
                          .dim = 2 * s->n + 2 + s->m,
                          .h_max = h_max,
                          .rhs_status = FRICREG_OK};
    double *y = malloc(run.dim * sizeof *y);
    run.jac_work = malloc(3 * run.dim * sizeof *run.jac_work);
    /* per component: the levels, then the weights of rtol (ode_tolerances.c) */
    double *tol = per_component ? malloc(2 * run.dim * sizeof *tol) : NULL;
    if (y == NULL || run.jac_work == NULL || (per_component && tol == NULL)) {
        FR_FREE_ALL(y, run.jac_work, tol);
        return fr_fail(s, FRICREG_ENOMEM, "run_ode: no memory for a state of %zu", run.dim);
    }
    gsl_odeiv2_system sys = {rhs, jacobian, run.dim, &run};
    const gsl_odeiv2_step_type *stepper = fr_integrator_stepper(integ, adaptive);
    gsl_odeiv2_driver *d;
    if (per_component) {
        fr_ode_tolerances(s, rtol, atol, tol, tol + run.dim);
        d = fr_ode_driver_alloc_vector(&sys, stepper, dt * integ->substeps, tol, tol + run.dim,
                                       rtol);
    } else {
        d = fr_ode_driver_alloc(&sys, stepper, dt * integ->substeps,
                                adaptive ? atol : integ->fixed_tolerance, adaptive ? rtol : 0.0);
    }
    free(tol);
    if (d == NULL) {
        free(y);
        free(run.jac_work);
        return fr_fail(s, FRICREG_ENOMEM, "run_ode: GSL driver allocation failed");
    }
    if (adaptive) { /* what fricreg_structure_get_ode_abs_tolerances reports */
        s->ode_rtol = rtol;
        s->ode_atol1 = atol;
        fr_warn_track_ode_tolerances(s, rtol, atol);
    }
    memcpy(y, s->u->data, s->n * sizeof *y);
    memcpy(y + s->n, s->v->data, s->n * sizeof *y);
    y[2 * s->n] = s->energy.input;
    y[2 * s->n + 1] = s->energy.viscous;
    memcpy(y + 2 * s->n + 2, s->energy.per_contact, s->m * sizeof *y);

    s->running = 1;
    status = integrate(s, &run, d, integ, adaptive, dt, t_end, y);
    s->running = 0;
    gsl_odeiv2_driver_free(d);
    free(y);
    free(run.jac_work);
    if (s->t == t_start)
        return status; /* nothing accepted (and a run ends after its start) */
    if (s->fresh)
        s->energy.initial = initial;
    s->fresh = 0;
    s->ready = 0;   /* the next step takes its acceleration from the equation of motion */
    s->clock_k = 0; /* off fricreg_structure_run's grid */
    if (status == FRICREG_OK)
        return fr_structure_equilibrium(s);
    /* Failed after some steps: the state is the last accepted step's, and so are a and f, the
     * equation of motion there; where that fails too (redundant contacts sticking, or an
     * overflow: the cause of the run's failure), they stay those of the run's start. The
     * run's error stays. */
    struct fr_error err = s->err;
    fr_structure_equilibrium(s);
    s->err = err;
    return status;
}
