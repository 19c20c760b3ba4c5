/* SPDX-License-Identifier: GPL-3.0-or-later */
/* estimate_companions.c — the error estimate's companions (error_estimate.c reads them) and
 * their settings (fricreg_structure_set_error_estimate, _set_error_companions): structures made
 * as copies of the structure at its run's first step and stepped to its time at the end of
 * each stepping call, along the path (eps, dt) -> (eps / 2, dt / 2) -> (eps / 4, dt / 4) (an
 * adaptive GSL run: its tolerances / TOL_SCALE at each level), or coarser (eps, dt) ->
 * (2 eps, 2 dt) -> (4 eps, 4 dt) (tolerances x TOL_COARSER), or both (FRICREG_COMPANIONS_AUTO:
 * the coarser screen, and a finer pair kept at the start and stepped only where the screen
 * doubts, then in its place).
 *
 * The second companion is the first's own companion: the first runs with the estimate on and
 * one companion, so every change passed on to the first reaches the second the same way. It
 * cannot be run only where the first shows a problem: a stall is exactly a first companion
 * that agrees with the run.
 *
 * The setters mark what they change (changed.c): a change of what the companion copied (the
 * model, the scheme, the start) ends the estimate until the next run's start; the others
 * (bounds, law, records, Newton, the step bound, the adaptive tolerances) are passed on to it
 * before it follows the structure (fr_estimate_sync); the parked finer pair first steps to
 * the change's time, so that it sees every setting when the structure did. The companions are
 * stepped by the plain runs (step.c, structure_ode.c), beneath the public ones. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "ctx/ctx_driver.h"
#include "fricreg_sim.h"
#include "structure_internal.h"

#define TOL_SCALE 16.0 /* the finer companion's tolerances / 16 (fricreg_sim's) */
/* The coarser companions' tolerances x 2 a level, the path's own factor. An adaptive run's
 * error has a part of its tolerance, about proportional to it; scaled by 2 with eps, that part
 * follows the law's lower order (ratio 2 a level) and base/companion_estimate.c's bound on
 * Richardson's quotient holds. At x 16 it is a third order of ratio 16, and a mix of ratios 2
 * and 16 puts Richardson's estimate up to (2 + 16 - 2)^2 / (4 x 1 x 15) = 4.3x under. */
#define TOL_COARSER 2.0

/* The factor from s's eps and dt to its companion's at `level`: 1/2 finer, 2 coarser
 * (fricreg_structure_set_error_companions). */
static double level_factor(int level)
{
    return level == FRICREG_COMPANIONS_COARSER ? 2.0 : 0.5;
}

static void free_companions(fricreg_structure *s)
{
    fricreg_structure_free(s->companion);
    fricreg_structure_free(s->confirm);
    s->companion = s->confirm = NULL;
}

static void estimate_failed(fricreg_structure *s, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(s->estimate_msg, sizeof s->estimate_msg, fmt, ap);
    va_end(ap);
    free_companions(s);
    s->estimate_state = FR_ESTIMATE_FAILED;
}

/* A copy of A (J^T: its transpose, J) installed as c's model matrix `which`. */
static int install_copy(fricreg_structure *c, int which, cholmod_sparse *A)
{
    cholmod_sparse *B = which == FR_CONTACTS ? cholmod_l_transpose(A, 1, &c->cc)
                                             : cholmod_l_copy_sparse(A, &c->cc);
    if (B == NULL)
        return fr_fail(c, FRICREG_ENOMEM, "no memory for a copy of the model");
    return fr_structure_install(c, which, B, "companion");
}

/* The companion's configuration and state from s's at `level`; FRICREG_OK or c's failure
 * (recorded). */
static int copy_structure(fricreg_structure *c, const fricreg_structure *s, int level)
{
    int status = install_copy(c, FR_MASS, s->M);
    if (status == FRICREG_OK)
        status = install_copy(c, FR_STIFFNESS, s->K);
    if (status == FRICREG_OK)
        status = install_copy(c, FR_DAMPING, s->C);
    if (status == FRICREG_OK && s->contacts_set)
        status = install_copy(c, FR_CONTACTS, s->Jt);
    if (status == FRICREG_OK)
        status = fricreg_structure_set_ground_accel(c, s->ground.t0, s->ground.dt, s->ground.n,
                                                    s->ground.x);
    if (status == FRICREG_OK)
        status = fricreg_structure_set_load(c, s->n, s->p->data, s->load.t0, s->load.dt, s->load.n,
                                            s->load.x);
    if (status == FRICREG_OK)
        status = fricreg_structure_set_law(c, fr_ctx_law(s->ctx),
                                           level_factor(level) * fr_ctx_eps(s->ctx));
    if (status == FRICREG_OK)
        status = fricreg_structure_set_bounds(c, s->m, s->mun);
    if (status == FRICREG_OK)
        status = fr_elements_clone(c, s);
    if (status != FRICREG_OK)
        return status;
    c->rayleigh = s->rayleigh;
    c->a0 = s->a0;
    c->a1 = s->a1;
    gsl_vector_memcpy(c->r, s->r);
    c->scheme = s->scheme;
    c->alpha = s->alpha;
    c->beta = s->beta;
    c->gamma = s->gamma;
    c->newton_tol = s->newton_tol;
    c->newton_max = s->newton_max;
    c->contact_solver = s->contact_solver;
    c->max_steps = s->max_steps;
    /* run_ode's rule from eps and set tolerances: / 16 finer, x 2 coarser */
    c->tol_scale = s->tol_scale *
                   (level == FRICREG_COMPANIONS_COARSER ? TOL_COARSER : 1.0 / TOL_SCALE);
    if (s->ode_atol != NULL)
        status = fricreg_structure_set_ode_abs_tolerances(c, 2 * s->n + 2 + s->m, s->ode_atol);
    if (status != FRICREG_OK)
        return status;
    c->unguarded = s->unguarded;
    gsl_vector_memcpy(c->u, s->u);
    gsl_vector_memcpy(c->v, s->v);
    c->t = s->t;
    memcpy(c->peak, s->peak, s->n * sizeof *c->peak);
    return FRICREG_OK;
}

int fr_estimate_companion(const fricreg_structure *s, int level, fricreg_structure **out,
                          char msg[])
{
    fricreg_structure *c = NULL;
    if (fricreg_structure_create(s->n, s->m, &c) != FRICREG_OK) {
        snprintf(msg, 256, "no memory for the companion structure");
        return FRICREG_ENOMEM;
    }
    int status = copy_structure(c, s, level);
    if (status != FRICREG_OK) {
        snprintf(msg, 256, "the companion could not be made: %s", fricreg_structure_errmsg(c));
        fricreg_structure_free(c);
        return status;
    }
    if (s->estimate_on == FRICREG_ESTIMATE_TWO_COMPANIONS) /* the second: c's own */
        c->estimate_on = FRICREG_ESTIMATE_ONE_COMPANION;
    c->companions = level; /* the second at the first's levels */
    *out = c;
    return FRICREG_OK;
}

void fr_estimate_begin(fricreg_structure *s)
{
    if (s->estimate_state == FR_ESTIMATE_NONE && (s->companion != NULL || s->confirm != NULL))
        free_companions(s); /* stale: a setter changed what it copied */
    if (!s->estimate_on || s->estimate_state != FR_ESTIMATE_NONE || !s->fresh)
        return;
    s->companion_level = s->companions == FRICREG_COMPANIONS_FINER ? FRICREG_COMPANIONS_FINER
                                                                   : FRICREG_COMPANIONS_COARSER;
    s->parked = (struct fr_stepping_call){0}; /* no call yet: the pair is at s's time */
    s->screen_peak_err = s->screen_dissipation_err = NAN;
    char msg[256];
    if (fr_estimate_companion(s, s->companion_level, &s->companion, msg) != FRICREG_OK ||
        (s->companions == FRICREG_COMPANIONS_AUTO && /* the finer pair, kept at the start */
         fr_estimate_companion(s, FRICREG_COMPANIONS_FINER, &s->confirm, msg) != FRICREG_OK)) {
        estimate_failed(s, "%s", msg);
        return;
    }
    s->companion_pending = 0; /* the copy has them */
    s->estimate_state = FR_ESTIMATE_ACTIVE;
    s->companion_cpu = 0.0;
}

/* The status of a setter passed on to the companion c: a refusal ends the estimate. */
static int passed_on(fricreg_structure *s, const fricreg_structure *c, int status, const char *who)
{
    if (status != FRICREG_OK)
        estimate_failed(s, "the companion refused %s: %s", who, fricreg_structure_errmsg(c));
    return status;
}

/* The setters' changes `what` (enum fr_change) passed on to c, s's companion at `level`. */
static int pass_on(fricreg_structure *s, fricreg_structure *c, int level, unsigned what)
{
    int status = FRICREG_OK;
    if (what & FR_CHANGED_BOUNDS)
        status = passed_on(s, c, fricreg_structure_set_bounds(c, s->m, s->mun), "set_bounds");
    if (status == FRICREG_OK && (what & FR_CHANGED_LAW)) /* the companion's eps: half, twice */
        status = passed_on(s, c,
                           fricreg_structure_set_law(c, fr_ctx_law(s->ctx),
                                                     level_factor(level) * fr_ctx_eps(s->ctx)),
                           "set_law");
    if (status == FRICREG_OK && (what & FR_CHANGED_GROUND))
        status = passed_on(s, c,
                           fricreg_structure_set_ground_accel(c, s->ground.t0, s->ground.dt,
                                                              s->ground.n, s->ground.x),
                           "set_ground_accel");
    if (status == FRICREG_OK && (what & FR_CHANGED_LOAD))
        status = passed_on(s, c,
                           fricreg_structure_set_load(c, s->n, s->p->data, s->load.t0, s->load.dt,
                                                      s->load.n, s->load.x),
                           "set_load");
    if (status == FRICREG_OK && (what & FR_CHANGED_NEWTON))
        status = passed_on(s, c, fricreg_structure_set_newton(c, s->newton_tol, s->newton_max),
                           "set_newton");
    if (status == FRICREG_OK && (what & FR_CHANGED_MAX_STEPS))
        status = passed_on(s, c, fricreg_structure_set_max_steps(c, s->max_steps), "set_max_steps");
    if (status == FRICREG_OK && (what & FR_CHANGED_ODE_ATOL)) /* at its tolerances / 16 */
        status = passed_on(s, c,
                           fricreg_structure_set_ode_abs_tolerances(
                               c, s->ode_atol != NULL ? 2 * s->n + 2 + s->m : 0, s->ode_atol),
                           "set_ode_abs_tolerances");
    return status;
}

/* Coarser fixed steps need a call spanning the coarsest companion's step: a shorter one (a
 * step per call) would step the companions at s's own dt, off the path. */
static int span_too_short(const fricreg_structure *s, const fricreg_structure *c, double t,
                          double c_dt)
{
    double coarsest = s->estimate_on == FRICREG_ESTIMATE_TWO_COMPANIONS ? 2.0 * c_dt : c_dt;
    return t - c->t < coarsest * (1.0 - 1e-9);
}

/* Steps c, s's companion at `level`, from its time to t as `call` stepped s: fixed steps of
 * dt / 2 (coarser: 2 dt), or an adaptive run at the tolerances / 16 (coarser: x 2; the rule's
 * and the set levels: c->tol_scale); c's own companion follows it. FRICREG_OK, or the failure
 * with its message in msg[256]. The CPU time goes to s's companion_cpu. */
static int step_companion(fricreg_structure *s, fricreg_structure *c, int level,
                          const struct fr_stepping_call *call, double t, char msg[])
{
    double c_dt = level_factor(level) * call->dt, c_rtol = 0.0, c_atol = 0.0;
    if (call->integrator != 0 && (call->rtol > 0.0 || call->atol != 0.0)) {
        double scale = level == FRICREG_COMPANIONS_COARSER ? TOL_COARSER : 1.0 / TOL_SCALE;
        c_dt = call->dt;
        c_rtol = call->rtol * scale;
        c_atol = call->atol == FRICREG_ATOL_FROM_EPS ? FRICREG_ATOL_FROM_EPS : call->atol * scale;
    } else if (level == FRICREG_COMPANIONS_COARSER && span_too_short(s, c, t, c_dt)) {
        snprintf(msg, 256,
                 "coarser companions need each stepping call to span their largest step, 4 dt "
                 "(this one spanned %g s at dt = %g): run to t_end in one call, or use finer "
                 "companions",
                 t - c->t, call->dt);
        return FRICREG_EINVAL;
    }
    clock_t start = clock(); /* the second companion's inside the first's */
    fr_estimate_begin(c);    /* the second companion, at the first's first step */
    int status = call->integrator == 0
                     ? fr_structure_run_plain(c, c_dt, t)
                     : fr_structure_run_ode_plain(c, call->integrator, c_dt, c_rtol, c_atol, t);
    fr_estimate_follow(c, call->integrator, c_dt, c_rtol, c_atol);
    s->companion_cpu += (double)(clock() - start) / CLOCKS_PER_SEC;
    if (status != FRICREG_OK)
        snprintf(msg, 256, "the companion run at eps = %g failed: %s", fr_ctx_eps(c->ctx),
                 fricreg_structure_errmsg(c));
    else if (c->estimate_state == FR_ESTIMATE_FAILED) /* the second companion's failure */
        status = FRICREG_EINVAL, snprintf(msg, 256, "%s", c->estimate_msg);
    return status;
}

/* The parked finer pair (FRICREG_COMPANIONS_AUTO) stepped to t as the calls since its time
 * stepped s: 1, or 0 where it failed (the estimate with it). */
static int catch_up(fricreg_structure *s, double t)
{
    char msg[256];
    if (!(t > s->confirm->t) ||
        step_companion(s, s->confirm, FRICREG_COMPANIONS_FINER, &s->parked, t, msg) == FRICREG_OK)
        return 1;
    estimate_failed(s, "the finer companions, confirming the coarser: %s", msg);
    return 0;
}

void fr_estimate_sync(fricreg_structure *s)
{
    unsigned what = s->companion_pending;
    s->companion_pending = 0;
    if (s->estimate_state != FR_ESTIMATE_ACTIVE || what == 0)
        return;
    if (s->confirm != NULL && /* the parked pair to the change's time, then the change */
        (!catch_up(s, s->companion->t) ||
         pass_on(s, s->confirm, FRICREG_COMPANIONS_FINER, what) != FRICREG_OK))
        return;
    pass_on(s, s->companion, s->companion_level, what);
}

static int same_call(const struct fr_stepping_call *a, const struct fr_stepping_call *b)
{
    return a->integrator == b->integrator && a->dt == b->dt && a->rtol == b->rtol &&
           a->atol == b->atol;
}

/* The parked pair keeps one kind of call since its time: another kind first steps it to
 * where the calls of the last kind ended, the screen's time. */
static void park(fricreg_structure *s, const struct fr_stepping_call *call)
{
    if (!same_call(&s->parked, call) && !catch_up(s, s->companion->t))
        return; /* before the first call the pair is at the screen's time: nothing to step */
    s->parked = *call;
}

/* The screen doubts (its estimate would warn, or it failed: screen_peak_err and
 * screen_dissipation_err +infinity): the parked finer pair steps to s's time and takes its
 * place, its estimator the finer one from here on. */
static void confirm(fricreg_structure *s)
{
    if (!catch_up(s, s->t))
        return;
    fricreg_structure_free(s->companion);
    s->companion = s->confirm;
    s->confirm = NULL;
    s->companion_level = FRICREG_COMPANIONS_FINER;
}

void fr_estimate_settle(fricreg_structure *s)
{
    double peak_err, dissipation_err;
    if (s->estimate_state != FR_ESTIMATE_ACTIVE || s->confirm == NULL || s->fresh || s->running ||
        !fr_estimate_doubts(s, &peak_err, &dissipation_err))
        return;
    s->screen_peak_err = peak_err;
    s->screen_dissipation_err = dissipation_err;
    confirm(s);
}

void fr_estimate_follow(fricreg_structure *s, int integrator, double dt, double rtol, double atol)
{
    if (s->estimate_state != FR_ESTIMATE_ACTIVE || !(s->t > s->companion->t))
        return;
    fr_estimate_sync(s);
    struct fr_stepping_call call = {integrator, dt, rtol, atol};
    if (s->estimate_state == FR_ESTIMATE_ACTIVE && s->confirm != NULL)
        park(s, &call);
    if (s->estimate_state != FR_ESTIMATE_ACTIVE)
        return;
    char msg[256];
    if (step_companion(s, s->companion, s->companion_level, &call, s->t, msg) == FRICREG_OK)
        return; /* a screen is judged where its estimate is read (fr_estimate_settle) */
    if (s->confirm == NULL) {
        estimate_failed(s, "%s", msg);
        return;
    }
    s->screen_peak_err = s->screen_dissipation_err = INFINITY; /* the screen failed */
    confirm(s);
}

int fricreg_structure_set_error_estimate(fricreg_structure *s, int on)
{
    if (s == NULL || s->running)
        return fr_structure_refuse(s, "set_error_estimate");
    if (on != FRICREG_ESTIMATE_OFF && on != FRICREG_ESTIMATE_TWO_COMPANIONS &&
        on != FRICREG_ESTIMATE_ONE_COMPANION)
        return fr_fail(s, FRICREG_EINVAL,
                       "set_error_estimate: on = %d must be 0, 1 (two companions) or 2 (one)", on);
    if (on != s->estimate_on) { /* a companion made for another estimator */
        free_companions(s);
        s->estimate_state = FR_ESTIMATE_NONE;
    }
    s->estimate_on = on;
    return FRICREG_OK;
}

int fricreg_structure_set_error_companions(fricreg_structure *s, int which)
{
    if (s == NULL || s->running)
        return fr_structure_refuse(s, "set_error_companions");
    if (which != FRICREG_COMPANIONS_FINER && which != FRICREG_COMPANIONS_COARSER &&
        which != FRICREG_COMPANIONS_AUTO)
        return fr_fail(s, FRICREG_EINVAL,
                       "set_error_companions: which = %d must be 0 (finer), 1 (coarser) or 2 "
                       "(auto: coarser, confirmed by finer where they doubt)",
                       which);
    if (which != s->companions) { /* a companion made at the other levels */
        free_companions(s);
        s->estimate_state = FR_ESTIMATE_NONE;
    }
    s->companions = which;
    return FRICREG_OK;
}
