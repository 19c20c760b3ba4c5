/* SPDX-License-Identifier: GPL-3.0-or-later */
/* sim.c — fricreg_sim: runs a reference system (system.h) on GSL's gsl_odeiv2 steppers.
 *
 * The state is y = (x, v, D): body positions, velocities and the dissipated energy, all
 * advanced by the same scheme. Each forcing cycle is integrated to its exact end, so D per
 * cycle is a difference of two states. After every step the state is checked for finiteness,
 * because GSL carries a NaN to the end and reports success. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_math.h>
#include <gsl/gsl_odeiv2.h>

#include "base/companion_estimate.h" /* FR_ANSWER_RTOL */
#include "base/fr_math.h"
#include "central_imex.h"
#include "central_step.h"
#include "ctx/ctx_driver.h"
#include "ode/integrator.h"
#include "law/law.h"
#include "ode/ode_driver.h"
#include "kinks.h"
#include "ode/step_guard.h"
#include "sim_internal.h"

#define MAX_GSL_STEPS 2147483648.0     /* 2^31 fixed steps in one run */
#define MAX_CYCLES 1e9                 /* forcing cycles recorded in one run */
#define STOP_REQUESTED (-1)            /* the observer asked to stop: not an error */
#define MAX_STEP_PER_PERIOD (1.0 / 32) /* an adaptive step's cap, in forcing periods (advance) */

/* ---- Life cycle and settings ------------------------------------------------------------- */

/* extrapolate.c's results, held by the simulation until its next run. */
void fr_extrap_free(struct fr_extrap *x)
{
    if (x == NULL)
        return;
    free(x->D);
    free(x->D_err);
    free(x);
}

static void free_run(fricreg_sim *sim)
{
    fricreg_ctx_free(sim->ctx);
    free(sim->y);
    free(sim->zdot_buf);
    free(sim->a_free);
    free(sim->f);
    free(sim->f_eq);
    free(sim->stick_time);
    free(sim->stick_fraction);
    free(sim->D);
    free(sim->jac_work);
    fr_jacobian_free(sim->jac);
    fr_extrap_free(sim->extrap);
    sim->extrap = NULL;
    free(sim->D_err);
    free(sim->D_kind);
    sim->D_err = NULL;
    sim->D_kind = NULL;
    sim->total_err = NAN;
    sim->estimate_failed = 0;
    sim->jac_work = NULL;
    sim->jac = NULL;
    sim->ctx = NULL;
    sim->y = sim->zdot_buf = sim->a_free = sim->f = sim->f_eq = NULL;
    sim->zdot = NULL;
    sim->stick_time = sim->stick_fraction = sim->D = NULL;
    sim->ndof = sim->m = sim->cycles = 0;
    sim->t = 0.0;
    sim->steps = sim->rhs_evals = sim->rejected_steps = sim->kinks = 0;
}

void fricreg_sim_free(fricreg_sim *sim)
{
    if (sim == NULL)
        return;
    free_run(sim);
    free(sim->atol_vec);
    free(sim);
}

int fricreg_sim_create(int system, fricreg_sim **out)
{
    if (out == NULL)
        return FRICREG_ENULL;
    const struct fr_system_type *type = fr_system_type_find(system);
    if (type == NULL)
        return FRICREG_EINVAL;
    fricreg_sim *sim = calloc(1, sizeof *sim);
    if (sim == NULL)
        return FRICREG_ENOMEM;
    fr_system_init(&sim->sys, type); /* the paper's parameters */
    sim->law = FRICREG_LAW_QUINN;
    sim->partition = FRICREG_PARTITION_CONSISTENT;
    sim->eps_set = 0.0;
    sim->integrator = FRICREG_INT_RK4;
    sim->dt = 0.01;
    sim->max_steps = -1; /* the law's default (fr_law_max_adaptive_steps) */
    sim->rule_scale = 1.0;
    sim->kink_location = 1;
    sim->total_err = NAN;
    sim->answer_rtol = FR_ANSWER_RTOL;
    *out = sim;
    return FRICREG_OK;
}

/* Records why `param` = value was refused: not finite, not read by this system, or outside
 * the range of the system's table row `spec`. */
static int reject_param(fricreg_sim *sim, int param, double value, const struct fr_param_spec *spec)
{
    const char *name = fr_param_name(param);
    char label[32];
    if (name == NULL)
        snprintf(label, sizeof label, "parameter %d", param);
    else
        snprintf(label, sizeof label, "%s", name);
    if (!isfinite(value))
        return fr_fail(sim, FRICREG_ENONFINITE, "set_param: %s = %g is not finite", label, value);
    if (name == NULL)
        return fr_fail(sim, FRICREG_EINVAL, "set_param: %s = %g is not a known parameter", label,
                       value);
    if (spec == NULL)
        return fr_fail(sim, FRICREG_EINVAL, "set_param: %s = %g is not a parameter of the %s",
                       label, value, sim->sys.type->name);
    return fr_fail(sim, FRICREG_EINVAL, "set_param: %s = %g %s", label, value, spec->rule);
}

int fr_sim_refuse_during_run(fricreg_sim *sim, const char *who)
{
    return fr_fail(sim, FRICREG_EINVAL,
                   "%s: not allowed during a run (called from the observer or the warning "
                   "handler)",
                   who);
}

int fricreg_sim_set_param(fricreg_sim *sim, int param, double value)
{
    if (sim == NULL)
        return FRICREG_ENULL;
    if (sim->running)
        return fr_sim_refuse_during_run(sim, "set_param");
    size_t slot = 0;
    const struct fr_param_spec *spec = fr_system_param(sim->sys.type, param, &slot);
    if (spec == NULL || !isfinite(value) || (spec->valid && !spec->valid(value)))
        return reject_param(sim, param, value, spec);
    free_run(sim);
    sim->sys.p[slot] = value;
    return FRICREG_OK;
}

int fricreg_sim_get_param(const fricreg_sim *sim, int param, double *value)
{
    if (sim == NULL || value == NULL)
        return FRICREG_ENULL;
    size_t slot = 0;
    if (fr_system_param(sim->sys.type, param, &slot) == NULL)
        return FRICREG_EINVAL;
    *value = sim->sys.p[slot];
    return FRICREG_OK;
}

int fricreg_sim_set_law(fricreg_sim *sim, int law, double eps)
{
    if (sim == NULL)
        return FRICREG_ENULL;
    if (sim->running)
        return fr_sim_refuse_during_run(sim, "set_law");
    if (!fr_law_known(law))
        return fr_fail(sim, FRICREG_EINVAL, "set_law: unknown law %d", law);
    if (!isfinite(eps))
        return fr_fail(sim, FRICREG_ENONFINITE, "set_law: eps is not finite");
    if (eps < 0.0)
        return fr_fail(sim, FRICREG_EINVAL, "set_law: eps = %g must be >= 0", eps);
    free_run(sim);
    sim->law = law;
    sim->eps_set = eps;
    return FRICREG_OK;
}

int fricreg_sim_set_partition(fricreg_sim *sim, int partition)
{
    if (sim == NULL)
        return FRICREG_ENULL;
    if (sim->running)
        return fr_sim_refuse_during_run(sim, "set_partition");
    if (partition != FRICREG_PARTITION_CONSISTENT && partition != FRICREG_PARTITION_PAPER)
        return fr_fail(sim, FRICREG_EINVAL, "set_partition: unknown partition %d", partition);
    free_run(sim);
    sim->partition = partition;
    return FRICREG_OK;
}

int fricreg_sim_set_integrator(fricreg_sim *sim, int integrator, double dt, double rtol,
                               double atol)
{
    if (sim == NULL)
        return FRICREG_ENULL;
    if (sim->running)
        return fr_sim_refuse_during_run(sim, "set_integrator");
    if (fr_integrator_find(integrator) == NULL)
        return fr_fail(sim, FRICREG_EINVAL, "set_integrator: unknown integrator %d", integrator);
    if (!isfinite(dt) || !isfinite(rtol) || !isfinite(atol))
        return fr_fail(sim, FRICREG_ENONFINITE, "set_integrator: dt, rtol or atol not finite");
    if (!(dt > 0.0))
        return fr_fail(sim, FRICREG_EINVAL, "set_integrator: dt = %g must be > 0", dt);
    int from_eps = atol == FRICREG_ATOL_FROM_EPS;
    if (rtol < 0.0 || (atol < 0.0 && !from_eps))
        return fr_fail(sim, FRICREG_EINVAL,
                       "set_integrator: rtol = %g, atol = %g must be >= 0 (or atol = "
                       "FRICREG_ATOL_FROM_EPS = -1)",
                       rtol, atol);
    if (from_eps && !(rtol > 0.0))
        return fr_fail(sim, FRICREG_EINVAL,
                       "set_integrator: atol = FRICREG_ATOL_FROM_EPS needs rtol > 0, got %g", rtol);
    if (fr_integrator_find(integrator)->atol_required && rtol > 0.0 && atol == 0.0)
        return fr_fail(sim, FRICREG_EINVAL,
                       "set_integrator: %s needs atol > 0: its iteration converges to atol + rtol "
                       "|y|, which is 0 where a state component is 0 (a start at rest)",
                       fricreg_integrator_name(integrator));
    if (fr_integrator_find(integrator)->central && (rtol > 0.0 || atol != 0.0))
        return fr_fail(sim, FRICREG_EINVAL,
                       "set_integrator: central differences have no error estimate: fixed "
                       "steps only (rtol = atol = 0), got rtol = %g, atol = %g",
                       rtol, atol);
    free_run(sim);
    sim->integrator = integrator;
    sim->dt = dt;
    sim->rtol = rtol;
    sim->atol = from_eps ? 0.0 : atol;
    sim->atol_from_eps = from_eps;
    free(sim->atol_vec); /* the last tolerance setter wins */
    sim->atol_vec = NULL;
    sim->atol_n = 0;
    return FRICREG_OK;
}

int fricreg_sim_set_abs_tolerances(fricreg_sim *sim, size_t n, const double atol[])
{
    if (sim == NULL || atol == NULL)
        return sim ? fr_fail(sim, FRICREG_ENULL, "set_abs_tolerances: atol is NULL")
                   : FRICREG_ENULL;
    if (sim->running)
        return fr_sim_refuse_during_run(sim, "set_abs_tolerances");
    size_t dim = 2 * fricreg_sim_ndof(sim) + 1;
    if (n != dim)
        return fr_fail(sim, FRICREG_ESIZE,
                       "set_abs_tolerances: n = %zu, the state (x, v, D) has 2 ndof + 1 = %zu "
                       "components",
                       n, dim);
    if (fr_integrator_find(sim->integrator)->central)
        return fr_fail(sim, FRICREG_EINVAL,
                       "set_abs_tolerances: %s has no error estimate: fixed steps only",
                       fricreg_integrator_name(sim->integrator));
    for (size_t i = 0; i < n; i++) {
        if (!isfinite(atol[i]))
            return fr_fail(sim, FRICREG_ENONFINITE, "set_abs_tolerances: atol[%zu] is not finite",
                           i);
        if (!(atol[i] > 0.0))
            return fr_fail(sim, FRICREG_EINVAL, "set_abs_tolerances: atol[%zu] = %g must be > 0", i,
                           atol[i]);
    }
    double *copy = malloc(n * sizeof *copy);
    if (copy == NULL)
        return fr_fail(sim, FRICREG_ENOMEM, "set_abs_tolerances: out of memory");
    memcpy(copy, atol, n * sizeof *copy);
    free_run(sim);
    free(sim->atol_vec);
    sim->atol_vec = copy;
    sim->atol_n = n;
    sim->atol = 0.0;
    sim->atol_from_eps = 0;
    return FRICREG_OK;
}

int fricreg_sim_set_max_steps(fricreg_sim *sim, int64_t max_steps)
{
    if (sim == NULL)
        return FRICREG_ENULL;
    if (sim->running)
        return fr_sim_refuse_during_run(sim, "set_max_steps");
    if (max_steps < 0)
        return fr_fail(sim, FRICREG_EINVAL,
                       "set_max_steps: max_steps = %lld must be >= 0 (0: no bound)",
                       (long long)max_steps);
    sim->max_steps = max_steps;
    return FRICREG_OK;
}

int fricreg_sim_set_kink_location(fricreg_sim *sim, int on)
{
    if (sim == NULL)
        return FRICREG_ENULL;
    if (sim->running)
        return fr_sim_refuse_during_run(sim, "set_kink_location");
    if (on != 0 && on != 1)
        return fr_fail(sim, FRICREG_EINVAL, "set_kink_location: on = %d must be 0 or 1", on);
    sim->kink_location = on;
    return FRICREG_OK;
}

int fricreg_sim_set_observer(fricreg_sim *sim, fricreg_sim_observer fn, void *user)
{
    if (sim == NULL)
        return FRICREG_ENULL;
    if (sim->running)
        return fr_sim_refuse_during_run(sim, "set_observer");
    sim->observer = fn;
    sim->observer_user = user;
    return FRICREG_OK;
}

static int adaptive(const fricreg_sim *sim)
{
    return sim->rtol > 0.0 || sim->atol > 0.0 || sim->atol_from_eps || sim->atol_vec != NULL;
}

static double period(const fricreg_sim *sim)
{
    return sim->sys.type->period(&sim->sys);
}

/* The eps set by fricreg_sim_set_law, or the paper's rule for the current dt. */
static double eps_in_use(const fricreg_sim *sim)
{
    return sim->eps_set > 0.0 ? sim->eps_set : sim->sys.type->paper_eps(&sim->sys, sim->dt);
}

/* ---- Absolute tolerances ---------------------------------------------------------------- */

/* The rule from eps (fricreg_sim_set_integrator, FRICREG_ATOL_FROM_EPS), measured in
 * docs/integrators.md ("Absolute tolerances from eps"): a velocity is held absolutely to
 * min(FR_SIM_ATOL_V_PER_EPS eps, rtol x 1 velocity unit), with no relative part, since the contact
 * velocity that law (4) reads is a difference of body velocities that are O(1) while it is
 * within its band |zdot| < eps. On the two blocks at eps = 1e-6 (msbdf, rtol 1e-6), D on
 * cycle 4 was 3e-3 off with 1e-1 eps, 1.2e-4 with 1e-2 eps, and within 7e-6 with 1e-3 eps
 * from rtol 1e-4 to 1e-8. Positions and D keep GSL's standard level rtol (1 + |y_i|) of the
 * nondimensional systems. */

double fr_sim_rule_atol_v(const fricreg_sim *sim, double eps)
{
    return fmin(FR_SIM_ATOL_V_PER_EPS * eps * sim->rule_scale, sim->rtol);
}

/* Component i of the rule from eps at eps for y = (x, v, D): fr_sim_rule_atol_v on the
 * velocities, rtol on the positions and on D. */
static double rule_tolerance(const fricreg_sim *sim, double eps, size_t i)
{
    size_t n = fricreg_sim_ndof(sim);
    return i >= n && i < 2 * n ? fr_sim_rule_atol_v(sim, eps) : sim->rtol;
}

/* The rule from eps at eps: absolute tolerances atol[2 ndof + 1] of y = (x, v, D) and the
 * weights w[2 ndof + 1] of rtol in each component (w NULL: not asked for). */
static void rule_tolerances(const fricreg_sim *sim, double eps, double atol[], double w[])
{
    size_t n = fricreg_sim_ndof(sim);
    for (size_t i = 0; i < 2 * n + 1; i++)
        atol[i] = rule_tolerance(sim, eps, i);
    for (size_t i = 0; w != NULL && i < 2 * n + 1; i++)
        w[i] = i >= n && i < 2 * n ? 0.0 : 1.0;
}

/* Component i of the absolute tolerances of an adaptive run at eps, y = (x, v, D): the
 * caller's, atol in every component, or the rule from eps. */
static double abs_tolerance(const fricreg_sim *sim, double eps, size_t i)
{
    if (sim->atol_vec != NULL)
        return sim->atol_vec[i];
    return sim->atol_from_eps ? rule_tolerance(sim, eps, i) : sim->atol;
}

double fr_sim_dissipation_tolerance(const fricreg_sim *sim, double D)
{
    size_t i = 2 * fricreg_sim_ndof(sim); /* D, the last component of y */
    return abs_tolerance(sim, eps_in_use(sim), i) + sim->rtol * fabs(D);
}

int fricreg_sim_get_abs_tolerances(const fricreg_sim *sim, size_t n, double atol[])
{
    if (sim == NULL || atol == NULL)
        return FRICREG_ENULL;
    if (n != 2 * fricreg_sim_ndof(sim) + 1 || (sim->atol_vec != NULL && sim->atol_n != n))
        return FRICREG_ESIZE;
    double eps = eps_in_use(sim); /* fixed steps: no tolerances, zeros */
    for (size_t i = 0; i < n; i++)
        atol[i] = adaptive(sim) ? abs_tolerance(sim, eps, i) : 0.0;
    return FRICREG_OK;
}

/* ---- The run's state checks -------------------------------------------------------------- */

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

/* ---- Running ----------------------------------------------------------------------------- */

static int alloc_run(fricreg_sim *sim, size_t cycles)
{
    size_t n = sim->sys.type->ndof(&sim->sys), m = sim->sys.type->ncontacts(&sim->sys);
    sim->ndof = n;
    sim->m = m;
    sim->y = malloc((2 * n + 1) * sizeof *sim->y);
    sim->zdot_buf = malloc(m * sizeof *sim->zdot_buf);
    sim->a_free = malloc(m * sizeof *sim->a_free);
    sim->f = malloc(m * sizeof *sim->f);
    sim->f_eq = malloc(m * sizeof *sim->f_eq);
    sim->stick_time = calloc(m, sizeof *sim->stick_time);
    sim->stick_fraction = calloc(m, sizeof *sim->stick_fraction);
    sim->D = calloc(cycles + 1, sizeof *sim->D);
    sim->jac_work = malloc(3 * (2 * n + 1) * sizeof *sim->jac_work);
    if (!sim->jac_work || !sim->y || !sim->zdot_buf || !sim->a_free || !sim->f || !sim->f_eq ||
        !sim->stick_time || !sim->stick_fraction || !sim->D)
        return fr_fail(sim, FRICREG_ENOMEM, "run: out of memory for %zu bodies", n);
    int status = fricreg_ctx_create(m, &sim->ctx);
    if (status == FRICREG_OK)
        status = fricreg_ctx_set_law(sim->ctx, sim->law, sim->eps);
    if (status == FRICREG_OK)
        status = fricreg_ctx_set_partition(sim->ctx, sim->partition);
    if (status == FRICREG_OK)
        status = sim->sys.type->configure(&sim->sys, sim->ctx);
    if (status == FRICREG_OK) /* until a Jacobian is asked for (fr_sim_jacobian) */
        status = fricreg_ctx_set_keep_tangent(sim->ctx, 0);
    if (status != FRICREG_OK)
        return fr_fail(sim, status, "run: %s",
                       sim->ctx ? fricreg_ctx_errmsg(sim->ctx) : fricreg_strerror(status));
    return FRICREG_OK;
}

/* A fixed explicit step must pass the guard (src/ode/step_guard.c) with lambda the context's
 * stick-zone stiffness (fricreg_ctx_stick_stiffness: coupled contacts included; the chord's
 * for a law that jumps) and omega the system's highest natural frequency (the chain's
 * springs: 2n). central-imex's refusal comes first: it is what the step solves, not a
 * stability limit, so it holds unguarded too. */
static int check_step(fricreg_sim *sim, const struct fr_integrator *integ)
{
    const char *refusal = integ->implicit_friction ? fr_central_imex_refusal(sim) : NULL;
    if (refusal != NULL)
        return fr_fail(sim, FRICREG_EINVAL, "run: integrator %s: %s", integ->name, refusal);
    if (adaptive(sim) || sim->unguarded || integ->stick_zone_bound == 0.0)
        return FRICREG_OK; /* implicit and multistep steppers report their own failures */
    struct fr_guard_run run = {.integ = integ,
                               .dt = sim->dt,
                               .eps = sim->eps,
                               .omega = sim->sys.type->max_frequency(&sim->sys),
                               .jumps = fr_law_jumps(sim->law),
                               .eps_by_rule = sim->eps_set == 0.0};
    if (fr_stiffness_times_eps(sim->ctx, run.jumps, &run.rate) != FRICREG_OK)
        return fr_fail(sim, FRICREG_ENOMEM, "run: %s", fricreg_ctx_errmsg(sim->ctx));
    return fr_step_guard(&run, &sim->err, "run");
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

/* Integrates from sim->t to t_target exactly. An adaptive step is capped at
 * MAX_STEP_PER_PERIOD of the forcing period: while every contact sticks, the state is at rest
 * and GSL's error estimate is zero whatever the step, but the forcing that will break the
 * stick is not part of the state. Uncapped, msbdf with the exact Jacobian stepped from a stick
 * at t = 0.295 to the cycle's end at 12.57 over a whole slip phase (oscillator a = 2,
 * omega = 0.5, x0 = 0.385, v0 = -0.217, eps 1e-6: D = 0 instead of 10.4). Capped, the step
 * that crosses a break-away lands in the slip phase, where the estimate rejects it. */
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

static int advance(fricreg_sim *sim, gsl_odeiv2_driver *d, const struct fr_integrator *integ,
                   double t_target, double *h)
{
    double gsl_dt = sim->dt * integ->substeps;
    int64_t cycle_steps = 0; /* adaptive steps accepted in this cycle */
    int64_t bound = sim->max_steps >= 0 ? sim->max_steps : fr_law_max_adaptive_steps(sim->law);
    while (sim->t < t_target) {
        if (adaptive(sim) && bound > 0 && ++cycle_steps > bound)
            return too_much_work(sim, integ, bound);
        double t_before = sim->t;
        int gsl_status, moved = 1;
        if (adaptive(sim)) {
            double t_stop = fmin(t_target, sim->t + MAX_STEP_PER_PERIOD * period(sim));
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
        sim->steps += adaptive(sim) ? 1 : integ->substeps;
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

/* Integrates the `cycles` whole forcing cycles within t_end (after the start_cycle ones a
 * window's run skips), then the rest of the way. */
static int integrate(fricreg_sim *sim, gsl_odeiv2_driver *d, const struct fr_integrator *integ,
                     double t_end, size_t cycles)
{
    double T = period(sim), D_start = 0.0, h = sim->dt;
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

/* The stepper of a run: the table's (src/ode/integrator.c), or for its central rows
 * fricreg_sim's own (central_step.c). */
static const gsl_odeiv2_step_type *run_stepper(const fricreg_sim *sim,
                                               const struct fr_integrator *integ)
{
    if (integ->central)
        return integ->implicit_friction ? fr_step_central_imex() : fr_step_central();
    return fr_integrator_stepper(integ, adaptive(sim));
}

int fr_sim_run_plain(fricreg_sim *sim, double t_end)
{
    if (!isfinite(t_end))
        return fr_fail(sim, FRICREG_ENONFINITE, "run: t_end is not finite");
    const struct fr_integrator *integ = fr_integrator_find(sim->integrator);
    if (!(t_end > 0.0))
        return fr_fail(sim, FRICREG_EINVAL, "run: t_end = %g must be > 0", t_end);
    if (!adaptive(sim) && t_end / (sim->dt * integ->substeps) > MAX_GSL_STEPS)
        return fr_fail(sim, FRICREG_EINVAL, "run: t_end/dt = %g steps is too many",
                       t_end / sim->dt);
    double whole_cycles = fr_whole_cycles(t_end, period(sim));
    if (whole_cycles > MAX_CYCLES)
        return fr_fail(sim, FRICREG_EINVAL, "run: t_end = %g spans more than 10^9 cycles", t_end);
    if (sim->start_cycle > 0 && (double)sim->start_cycle >= whole_cycles) /* extrapolate.c */
        return fr_fail(sim, FRICREG_EINVAL, "run: a window from cycle %zu of %g", sim->start_cycle,
                       whole_cycles);
    if (sim->atol_vec != NULL && sim->atol_n != 2 * fricreg_sim_ndof(sim) + 1)
        return fr_fail(sim, FRICREG_EINVAL,
                       "run: %zu absolute tolerances were set (fricreg_sim_set_abs_tolerances) "
                       "but the state has 2 ndof + 1 = %zu components: set them again",
                       sim->atol_n, 2 * fricreg_sim_ndof(sim) + 1);
    free_run(sim);
    sim->eps = eps_in_use(sim);
    size_t cycles = (size_t)whole_cycles - sim->start_cycle;
    int status = alloc_run(sim, cycles);
    if (status == FRICREG_OK)
        status = check_step(sim, integ);
    if (status != FRICREG_OK) {
        free_run(sim); /* nothing was reached: the getters report the initial state */
        return status;
    }
    sim->sys.type->initial(&sim->sys, sim->y, sim->y + sim->ndof);
    if (sim->start_y != NULL) { /* a window's level: level 0's state where the window starts */
        memcpy(sim->y, sim->start_y, 2 * sim->ndof * sizeof *sim->y);
        sim->t = (double)sim->start_cycle * period(sim);
    }
    sim->y[2 * sim->ndof] = 0.0;
    sim->rhs_status = FRICREG_OK;
    sim->step_checked = 0;

    size_t dim = 2 * sim->ndof + 1;
    gsl_odeiv2_system sys = {fr_sim_rhs, fr_sim_jacobian, dim, sim};
    /* Fixed steps never consult the control, but some steppers read the driver's tolerances:
     * the multistep ones to pick their order (moderate values), the implicit Runge-Kutta
     * ones for their Newton iteration (integrator.h, fixed_tolerance). */
    double tol_abs = adaptive(sim) ? sim->atol : integ->fixed_tolerance;
    double tol_rel = adaptive(sim) ? sim->rtol : 0.0;
    const gsl_odeiv2_step_type *stepper = run_stepper(sim, integ);
    double *rule = sim->atol_from_eps ? malloc(2 * dim * sizeof *rule) : NULL;
    if (rule != NULL)
        rule_tolerances(sim, sim->eps, rule, rule + dim);
    const double *atol = sim->atol_from_eps ? rule : sim->atol_vec;
    gsl_odeiv2_driver *d = sim->atol_from_eps && rule == NULL ? NULL
                           : atol ? fr_ode_driver_alloc_vector(&sys, stepper,
                                                               sim->dt * integ->substeps, atol,
                                                               rule ? rule + dim : NULL, tol_rel)
                                  : fr_ode_driver_alloc(&sys, stepper, sim->dt * integ->substeps,
                                                        tol_abs, tol_rel);
    free(rule);
    if (d == NULL)
        return fr_fail(sim, FRICREG_ENOMEM, "run: GSL driver allocation failed");
    if (adaptive(sim) && sim->kink_location) { /* kinks.c */
        sim->locate = fr_kinks_new(sim, d, integ);
        status = sim->locate
                     ? fr_kinks_start(sim->locate, sim)
                     : fr_fail(sim, FRICREG_ENOMEM, "run: out of memory for %zu contacts", sim->m);
    }
    sim->running = 1;
    sim->unchecked_eval = !adaptive(sim) && (integ->central || integ->fixed_type != NULL);
    if (status == FRICREG_OK)
        status = integrate(sim, d, integ, t_end, cycles);
    sim->unchecked_eval = 0;
    sim->running = 0;
    sim->rejected_steps += (int64_t)d->e->failed_steps; /* the adaptive control's rejections */
    fr_kinks_free(sim->locate);
    sim->locate = NULL;
    gsl_odeiv2_driver_free(d);
    return status;
}

/* ---- Results ----------------------------------------------------------------------------- */

size_t fricreg_sim_ndof(const fricreg_sim *sim)
{
    return sim ? sim->sys.type->ndof(&sim->sys) : 0;
}

size_t fricreg_sim_ncontacts(const fricreg_sim *sim)
{
    return sim ? sim->sys.type->ncontacts(&sim->sys) : 0;
}

int fricreg_sim_get_value(const fricreg_sim *sim, int which, double *value)
{
    if (sim == NULL || value == NULL)
        return FRICREG_ENULL;
    switch (which) {
    case FRICREG_VALUE_TIME: *value = sim->t; break;
    case FRICREG_VALUE_EPS: *value = eps_in_use(sim); break;
    case FRICREG_VALUE_DT: *value = sim->dt; break;
    case FRICREG_VALUE_PERIOD: *value = period(sim); break;
    case FRICREG_VALUE_STEPS: *value = (double)sim->steps; break;
    case FRICREG_VALUE_RHS_EVALS: *value = (double)sim->rhs_evals; break;
    case FRICREG_VALUE_CYCLES: *value = (double)sim->cycles; break;
    case FRICREG_VALUE_DISSIPATION: *value = sim->y ? sim->y[2 * sim->ndof] : 0.0; break;
    case FRICREG_VALUE_DISSIPATION_ERROR:
        if (sim->D_err == NULL)
            return FRICREG_EINVAL;
        *value = sim->total_err;
        break;
    case FRICREG_VALUE_DISS_ERROR_KIND:
        if (sim->D_kind == NULL)
            return FRICREG_EINVAL;
        *value = sim->D_kind[sim->cycles];
        break;
    default: return FRICREG_EINVAL;
    }
    return FRICREG_OK;
}

int fricreg_sim_get_stat(const fricreg_sim *sim, int which, int64_t *value)
{
    if (sim == NULL || value == NULL)
        return FRICREG_ENULL;
    switch (which) {
    case FRICREG_SIM_STAT_STEPS: *value = sim->steps; break;
    case FRICREG_SIM_STAT_RHS_EVALS: *value = sim->rhs_evals; break;
    case FRICREG_SIM_STAT_CYCLES: *value = (int64_t)sim->cycles; break;
    case FRICREG_SIM_STAT_REJECTED_STEPS: *value = sim->rejected_steps; break;
    case FRICREG_SIM_STAT_KINKS: *value = sim->kinks; break;
    default: return FRICREG_EINVAL;
    }
    return FRICREG_OK;
}

int fricreg_sim_get_state(const fricreg_sim *sim, size_t ndof, double x[], double v[])
{
    if (sim == NULL || x == NULL || v == NULL)
        return FRICREG_ENULL;
    if (ndof != fricreg_sim_ndof(sim))
        return FRICREG_ESIZE;
    if (sim->y == NULL) /* not run yet: the initial conditions */
        sim->sys.type->initial(&sim->sys, x, v);
    else {
        memcpy(x, sim->y, ndof * sizeof *x);
        memcpy(v, sim->y + ndof, ndof * sizeof *v);
    }
    return FRICREG_OK;
}

int fricreg_sim_get_dissipation(const fricreg_sim *sim, size_t ncycles, double D[])
{
    if (sim == NULL || (D == NULL && ncycles > 0))
        return FRICREG_ENULL;
    if (ncycles != sim->cycles)
        return FRICREG_ESIZE;
    if (ncycles > 0)
        memcpy(D, sim->D, ncycles * sizeof *D);
    return FRICREG_OK;
}

int fricreg_sim_get_stick_fraction(const fricreg_sim *sim, size_t m, double frac[])
{
    if (sim == NULL || frac == NULL)
        return FRICREG_ENULL;
    if (m != fricreg_sim_ncontacts(sim))
        return FRICREG_ESIZE;
    for (size_t i = 0; i < m; i++)
        frac[i] = sim->stick_fraction ? sim->stick_fraction[i] : 0.0;
    return FRICREG_OK;
}

int fricreg_sim_errcode(const fricreg_sim *sim)
{
    return sim ? sim->err.code : FRICREG_OK;
}

const char *fricreg_sim_errmsg(const fricreg_sim *sim)
{
    return sim ? sim->err.msg : "NULL simulation";
}

size_t fricreg_sim_errmsg_copy(const fricreg_sim *sim, char *buf, size_t len)
{
    return fr_error_copy(fricreg_sim_errmsg(sim), buf, len);
}
