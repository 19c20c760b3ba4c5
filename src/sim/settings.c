/* SPDX-License-Identifier: GPL-3.0-or-later */
/* settings.c — fricreg_sim's life cycle and settings: create and free, the system's
 * parameters and sizes, the law, the partition, the integrator and its tolerances, the bound
 * on adaptive steps, kink location, the observer. A setting that changes what a run computes
 * discards the last run's state (fr_sim_free_run); none may be changed during a run. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/companion_estimate.h" /* FR_ANSWER_RTOL */
#include "law/law.h"
#include "ode/integrator.h"
#include "settings.h"
#include "sim_internal.h"
#include "base/free_all.h"

/* extrapolate.c's results, held by the simulation until its next run. */
void fr_extrap_free(struct fr_extrap *x)
{
    if (x == NULL)
        return;
    FR_FREE_ALL(x->D, x->D_err, x);
}

void fr_sim_free_run(fricreg_sim *sim)
{
    fricreg_ctx_free(sim->ctx);
    FR_FREE_ALL(sim->y, sim->zdot_buf, sim->a_free, sim->f, sim->f_eq, sim->stick_time,
                sim->stick_fraction, sim->D, sim->jac_work);
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
    fr_sim_free_run(sim);
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
    if (sim == NULL)
        return FRICREG_ENULL;
    return fr_fail(sim, FRICREG_EINVAL,
                   "%s: not allowed during a run (called from the observer or the warning "
                   "handler)",
                   who);
}

int fricreg_sim_set_param(fricreg_sim *sim, int param, double value)
{
    if (sim == NULL || sim->running)
        return fr_sim_refuse_during_run(sim, "set_param");
    size_t slot = 0;
    const struct fr_param_spec *spec = fr_system_param(sim->sys.type, param, &slot);
    if (spec == NULL || !isfinite(value) || (spec->valid && !spec->valid(value)))
        return reject_param(sim, param, value, spec);
    fr_sim_free_run(sim);
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
    if (sim == NULL || sim->running)
        return fr_sim_refuse_during_run(sim, "set_law");
    if (!fr_law_known(law))
        return fr_fail(sim, FRICREG_EINVAL, "set_law: unknown law %d", law);
    if (!isfinite(eps))
        return fr_fail(sim, FRICREG_ENONFINITE, "set_law: eps is not finite");
    if (eps < 0.0)
        return fr_fail(sim, FRICREG_EINVAL, "set_law: eps = %g must be >= 0", eps);
    fr_sim_free_run(sim);
    sim->law = law;
    sim->eps_set = eps;
    return FRICREG_OK;
}

int fricreg_sim_set_partition(fricreg_sim *sim, int partition)
{
    if (sim == NULL || sim->running)
        return fr_sim_refuse_during_run(sim, "set_partition");
    if (partition != FRICREG_PARTITION_CONSISTENT && partition != FRICREG_PARTITION_PAPER)
        return fr_fail(sim, FRICREG_EINVAL, "set_partition: unknown partition %d", partition);
    fr_sim_free_run(sim);
    sim->partition = partition;
    return FRICREG_OK;
}

int fricreg_sim_set_integrator(fricreg_sim *sim, int integrator, double dt, double rtol,
                               double atol)
{
    if (sim == NULL || sim->running)
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
    fr_sim_free_run(sim);
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
    fr_sim_free_run(sim);
    free(sim->atol_vec);
    sim->atol_vec = copy;
    sim->atol_n = n;
    sim->atol = 0.0;
    sim->atol_from_eps = 0;
    return FRICREG_OK;
}

int fricreg_sim_set_max_steps(fricreg_sim *sim, int64_t max_steps)
{
    if (sim == NULL || sim->running)
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
    if (sim == NULL || sim->running)
        return fr_sim_refuse_during_run(sim, "set_kink_location");
    if (on != 0 && on != 1)
        return fr_fail(sim, FRICREG_EINVAL, "set_kink_location: on = %d must be 0 or 1", on);
    sim->kink_location = on;
    return FRICREG_OK;
}

int fricreg_sim_set_observer(fricreg_sim *sim, fricreg_sim_observer fn, void *user)
{
    if (sim == NULL || sim->running)
        return fr_sim_refuse_during_run(sim, "set_observer");
    sim->observer = fn;
    sim->observer_user = user;
    return FRICREG_OK;
}

size_t fricreg_sim_ndof(const fricreg_sim *sim)
{
    return sim ? sim->sys.type->ndof(&sim->sys) : 0;
}

size_t fricreg_sim_ncontacts(const fricreg_sim *sim)
{
    return sim ? sim->sys.type->ncontacts(&sim->sys) : 0;
}
