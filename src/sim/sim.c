/* SPDX-License-Identifier: GPL-3.0-or-later */
/* sim.c — fr_sim_run_plain: one run of a reference system (system.h) on GSL's gsl_odeiv2
 * steppers, without the error estimate and the warnings' delivery (run.c): the run's checks,
 * its state and context, the step guard, the GSL driver on the run's tolerances, the kinks'
 * locator; then the cycles (integrate.c).
 *
 * The state is y = (x, v, D): body positions, velocities and the dissipated energy, all
 * advanced by the same scheme. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_odeiv2.h>

#include "base/fr_math.h"
#include "central_imex.h"
#include "central_step.h"
#include "ctx/ctx_driver.h"
#include "integrate.h"
#include "kinks.h"
#include "law/law.h"
#include "ode/integrator.h"
#include "ode/ode_driver.h"
#include "ode/step_guard.h"
#include "settings.h"
#include "sim_internal.h"
#include "tolerances.h"

#define MAX_GSL_STEPS 2147483648.0 /* 2^31 fixed steps in one run */
#define MAX_CYCLES 1e9             /* forcing cycles recorded in one run */

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
    if (fr_sim_adaptive(sim) || sim->unguarded || integ->stick_zone_bound == 0.0)
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

/* The stepper of a run: the table's (src/ode/integrator.c), or for its central rows
 * fricreg_sim's own (central_step.c). */
static const gsl_odeiv2_step_type *run_stepper(const fricreg_sim *sim,
                                               const struct fr_integrator *integ)
{
    if (integ->central)
        return integ->implicit_friction ? fr_step_central_imex() : fr_step_central();
    return fr_integrator_stepper(integ, fr_sim_adaptive(sim));
}

int fr_sim_run_plain(fricreg_sim *sim, double t_end)
{
    if (!isfinite(t_end))
        return fr_fail(sim, FRICREG_ENONFINITE, "run: t_end is not finite");
    const struct fr_integrator *integ = fr_integrator_find(sim->integrator);
    if (!(t_end > 0.0))
        return fr_fail(sim, FRICREG_EINVAL, "run: t_end = %g must be > 0", t_end);
    if (!fr_sim_adaptive(sim) && t_end / (sim->dt * integ->substeps) > MAX_GSL_STEPS)
        return fr_fail(sim, FRICREG_EINVAL, "run: t_end/dt = %g steps is too many",
                       t_end / sim->dt);
    double whole_cycles = fr_whole_cycles(t_end, fr_sim_period(sim));
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
    fr_sim_free_run(sim);
    sim->eps = fr_sim_eps_in_use(sim);
    size_t cycles = (size_t)whole_cycles - sim->start_cycle;
    int status = alloc_run(sim, cycles);
    if (status == FRICREG_OK)
        status = check_step(sim, integ);
    if (status != FRICREG_OK) {
        fr_sim_free_run(sim); /* nothing was reached: the getters report the initial state */
        return status;
    }
    sim->sys.type->initial(&sim->sys, sim->y, sim->y + sim->ndof);
    if (sim->start_y != NULL) { /* a window's level: level 0's state where the window starts */
        memcpy(sim->y, sim->start_y, 2 * sim->ndof * sizeof *sim->y);
        sim->t = (double)sim->start_cycle * fr_sim_period(sim);
    }
    sim->y[2 * sim->ndof] = 0.0;
    sim->rhs_status = FRICREG_OK;
    sim->step_checked = 0;

    size_t dim = 2 * sim->ndof + 1;
    gsl_odeiv2_system sys = {fr_sim_rhs, fr_sim_jacobian, dim, sim};
    /* Fixed steps never consult the control, but some steppers read the driver's tolerances:
     * the multistep ones to pick their order (moderate values), the implicit Runge-Kutta
     * ones for their Newton iteration (integrator.h, fixed_tolerance). */
    double tol_abs = fr_sim_adaptive(sim) ? sim->atol : integ->fixed_tolerance;
    double tol_rel = fr_sim_adaptive(sim) ? sim->rtol : 0.0;
    const gsl_odeiv2_step_type *stepper = run_stepper(sim, integ);
    double *rule = sim->atol_from_eps ? malloc(2 * dim * sizeof *rule) : NULL;
    if (rule != NULL)
        fr_sim_rule_tolerances(sim, sim->eps, rule, rule + dim);
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
    if (fr_sim_adaptive(sim) && sim->kink_location) { /* kinks.c */
        sim->locate = fr_kinks_new(sim, d, integ);
        status = sim->locate
                     ? fr_kinks_start(sim->locate, sim)
                     : fr_fail(sim, FRICREG_ENOMEM, "run: out of memory for %zu contacts", sim->m);
    }
    sim->running = 1;
    sim->unchecked_eval = !fr_sim_adaptive(sim) && (integ->central || integ->fixed_type != NULL);
    if (status == FRICREG_OK)
        status = fr_sim_integrate(sim, d, integ, t_end, cycles);
    sim->unchecked_eval = 0;
    sim->running = 0;
    sim->rejected_steps += (int64_t)d->e->failed_steps; /* the adaptive control's rejections */
    fr_kinks_free(sim->locate);
    sim->locate = NULL;
    gsl_odeiv2_driver_free(d);
    return status;
}
