/* SPDX-License-Identifier: GPL-3.0-or-later */
/* error_estimate.c — fricreg_structure_set_error_estimate: an a-posteriori estimate of the
 * error of the peak displacements and of each contact's dissipation against the Coulomb
 * problem (eps -> 0), from companion structures stepped alongside the structure along the
 * path (eps, dt) -> (eps / 2, dt / 2) -> (eps / 4, dt / 4) (an adaptive GSL run: its
 * tolerances / TOL_SCALE at each level), or with coarser companions (eps, dt) -> (2 eps, 2 dt)
 * -> (4 eps, 4 dt) (tolerances x TOL_COARSER).
 *
 * The estimate of each quantity from q, q2 = q(eps / 2), q4 = q(eps / 4) is
 * base/companion_estimate.c's, fricreg_sim's too: Richardson's correction with the observed
 * order in range (kind ASYMPTOTIC), a safe bound below it (kind BOUND); one companion (1.6's):
 * 3 |q - q2| (kind ASSUMED). FRICREG_WARN_ERROR_ESTIMATE where half the largest peak's or
 * the summed dissipations' estimate (its central value, fr_estimate_exceeds) exceeds the answer
 * tolerance (fricreg_structure_set_answer_rtol), whatever the kind.
 *
 * The second companion is the first's own companion: the first runs with the estimate on and
 * one companion, so every change passed on to the first reaches the second the same way. It
 * cannot be run only where the first shows a problem: a stall is exactly a first companion
 * that agrees with the run.
 *
 * The companion is a copy of the structure (model, excitation, law at eps / 2, bounds, scheme,
 * Newton, elements, initial state) made at the first stepping call after set_initial with the
 * estimate on (run.c). The setters mark what they change (changed.c): a change of what it
 * copied (the model, the scheme, the start) ends the estimate until the next run's start; the
 * others (bounds, law, records, Newton, the step bound, the adaptive tolerances) are passed on
 * to it before it follows the structure (fr_estimate_sync). It is stepped by the plain runs
 * (step.c, structure_ode.c), beneath the public ones. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "base/companion_estimate.h"
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

/* The factor from s's eps and dt to its companion's: 1/2 finer, 2 coarser
 * (fricreg_structure_set_error_companions). */
static double level(const fricreg_structure *s)
{
    return s->companions == FRICREG_COMPANIONS_COARSER ? 2.0 : 0.5;
}

static void companion_free(fricreg_structure *s)
{
    fricreg_structure_free(s->companion);
    s->companion = NULL;
}

static void estimate_failed(fricreg_structure *s, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(s->estimate_msg, sizeof s->estimate_msg, fmt, ap);
    va_end(ap);
    companion_free(s);
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

/* The companion's configuration and state from s's; FRICREG_OK or c's failure (recorded). */
static int copy_structure(fricreg_structure *c, const fricreg_structure *s)
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
        status = fricreg_structure_set_law(c, fr_ctx_law(s->ctx), level(s) * fr_ctx_eps(s->ctx));
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
    c->tol_scale = s->tol_scale * (level(s) > 1.0 ? TOL_COARSER : 1.0 / TOL_SCALE);
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

int fr_estimate_companion(const fricreg_structure *s, fricreg_structure **out, char msg[])
{
    fricreg_structure *c = NULL;
    if (fricreg_structure_create(s->n, s->m, &c) != FRICREG_OK) {
        snprintf(msg, 256, "no memory for the companion structure");
        return FRICREG_ENOMEM;
    }
    int status = copy_structure(c, s);
    if (status != FRICREG_OK) {
        snprintf(msg, 256, "the companion could not be made: %s", fricreg_structure_errmsg(c));
        fricreg_structure_free(c);
        return status;
    }
    if (s->estimate_on == FRICREG_ESTIMATE_TWO_COMPANIONS) /* the second: c's own */
        c->estimate_on = FRICREG_ESTIMATE_ONE_COMPANION;
    c->companions = s->companions;
    *out = c;
    return FRICREG_OK;
}

void fr_estimate_begin(fricreg_structure *s)
{
    if (s->estimate_state == FR_ESTIMATE_NONE && s->companion != NULL)
        companion_free(s); /* stale: a setter changed what it copied */
    if (!s->estimate_on || s->estimate_state != FR_ESTIMATE_NONE || !s->fresh)
        return;
    char msg[256];
    if (fr_estimate_companion(s, &s->companion, msg) != FRICREG_OK) {
        estimate_failed(s, "%s", msg);
        return;
    }
    s->companion_pending = 0; /* the copy has them */
    s->estimate_state = FR_ESTIMATE_ACTIVE;
    s->companion_cpu = 0.0;
}

/* The status of a setter passed on to the companion: a refusal ends the estimate. */
static int passed_on(fricreg_structure *s, int status, const char *who)
{
    if (status != FRICREG_OK)
        estimate_failed(s, "the companion refused %s: %s", who,
                        fricreg_structure_errmsg(s->companion));
    return status;
}

void fr_estimate_sync(fricreg_structure *s)
{
    unsigned what = s->companion_pending;
    s->companion_pending = 0;
    if (s->estimate_state != FR_ESTIMATE_ACTIVE || what == 0)
        return;
    fricreg_structure *c = s->companion;
    int status = FRICREG_OK;
    if (what & FR_CHANGED_BOUNDS)
        status = passed_on(s, fricreg_structure_set_bounds(c, s->m, s->mun), "set_bounds");
    if (status == FRICREG_OK && (what & FR_CHANGED_LAW)) /* the companion's eps: half, twice */
        status = passed_on(s,
                           fricreg_structure_set_law(c, fr_ctx_law(s->ctx),
                                                     level(s) * fr_ctx_eps(s->ctx)),
                           "set_law");
    if (status == FRICREG_OK && (what & FR_CHANGED_GROUND))
        status = passed_on(s,
                           fricreg_structure_set_ground_accel(c, s->ground.t0, s->ground.dt,
                                                              s->ground.n, s->ground.x),
                           "set_ground_accel");
    if (status == FRICREG_OK && (what & FR_CHANGED_LOAD))
        status = passed_on(s,
                           fricreg_structure_set_load(c, s->n, s->p->data, s->load.t0, s->load.dt,
                                                      s->load.n, s->load.x),
                           "set_load");
    if (status == FRICREG_OK && (what & FR_CHANGED_NEWTON))
        status = passed_on(s, fricreg_structure_set_newton(c, s->newton_tol, s->newton_max),
                           "set_newton");
    if (status == FRICREG_OK && (what & FR_CHANGED_MAX_STEPS))
        status = passed_on(s, fricreg_structure_set_max_steps(c, s->max_steps), "set_max_steps");
    if (status == FRICREG_OK && (what & FR_CHANGED_ODE_ATOL)) /* at its tolerances / 16 */
        passed_on(s,
                  fricreg_structure_set_ode_abs_tolerances(
                      c, s->ode_atol != NULL ? 2 * s->n + 2 + s->m : 0, s->ode_atol),
                  "set_ode_abs_tolerances");
}

/* Coarser fixed steps need a call spanning the coarsest companion's step: a shorter one (a
 * step per call) would step the companions at s's own dt, off the path. */
static int span_too_short(const fricreg_structure *s, double c_dt)
{
    double coarsest = s->estimate_on == FRICREG_ESTIMATE_TWO_COMPANIONS ? 2.0 * c_dt : c_dt;
    return s->companions == FRICREG_COMPANIONS_COARSER &&
           s->t - s->companion->t < coarsest * (1.0 - 1e-9);
}

static void follow(fricreg_structure *s, int integrator, double dt, double rtol, double atol)
{
    fricreg_structure *c = s->companion;
    /* The companion's call: fixed steps of dt / 2 (coarser: 2 dt), or an adaptive run at the
     * tolerances / 16 (coarser: x 2; the rule's and the set levels: c->tol_scale). */
    double c_dt = level(s) * dt, c_rtol = 0.0, c_atol = 0.0;
    if (integrator != 0 && (rtol > 0.0 || atol != 0.0)) {
        double scale = level(s) > 1.0 ? TOL_COARSER : 1.0 / TOL_SCALE;
        c_dt = dt;
        c_rtol = rtol * scale;
        c_atol = atol == FRICREG_ATOL_FROM_EPS ? FRICREG_ATOL_FROM_EPS : atol * scale;
    } else if (span_too_short(s, c_dt)) {
        estimate_failed(s,
                        "coarser companions need each stepping call to span their largest step, "
                        "4 dt (this one spanned %g s at dt = %g): run to t_end in one call, or "
                        "use finer companions",
                        s->t - c->t, dt);
        return;
    }
    fr_estimate_begin(c); /* the second companion, at the first's first step */
    int status = integrator == 0
                     ? fr_structure_run_plain(c, c_dt, s->t)
                     : fr_structure_run_ode_plain(c, integrator, c_dt, c_rtol, c_atol, s->t);
    fr_estimate_follow(c, integrator, c_dt, c_rtol, c_atol);
    if (status != FRICREG_OK)
        estimate_failed(s, "the companion run at eps = %g failed: %s", fr_ctx_eps(c->ctx),
                        fricreg_structure_errmsg(c));
    else if (c->estimate_state == FR_ESTIMATE_FAILED) /* the second companion's failure */
        estimate_failed(s, "%s", c->estimate_msg);
}

void fr_estimate_follow(fricreg_structure *s, int integrator, double dt, double rtol, double atol)
{
    if (s->estimate_state != FR_ESTIMATE_ACTIVE || !(s->t > s->companion->t))
        return;
    fr_estimate_sync(s);
    if (s->estimate_state != FR_ESTIMATE_ACTIVE)
        return;
    clock_t start = clock(); /* the second companion's inside the first's */
    follow(s, integrator, dt, rtol, atol);
    s->companion_cpu += (double)(clock() - start) / CLOCKS_PER_SEC;
}

/* The estimate of one quantity from its values on s, its companion and (with two) the
 * second companion (base/companion_estimate.h, shared with fricreg_sim), its kind into *kind. */
static double estimate_of(const fricreg_structure *s, double q, double q2, double q4, int *kind)
{
    if (s->companions == FRICREG_COMPANIONS_COARSER)
        return fr_companion_estimate_coarser(s->estimate_on, q, q2, q4, kind);
    return fr_companion_estimate(s->estimate_on, q, q2, q4, kind);
}

/* The three structures along the path (the second companion is the first when there is one
 * companion only; estimate_of then ignores it). */
static const fricreg_structure *second(const fricreg_structure *s)
{
    const fricreg_structure *c = s->companion;
    return c->estimate_state == FR_ESTIMATE_ACTIVE ? c->companion : c;
}

/* Every step's peak takes in the turning points between its ends (peak.c), so a peak
 * converges at an order as a dissipation does, and its kind is read the same way. */
static double peak_estimate(const fricreg_structure *s, size_t i, int *kind)
{
    return estimate_of(s, s->peak[i], s->companion->peak[i], second(s)->peak[i], kind);
}

static double dissipation_estimate(const fricreg_structure *s, size_t j, int *kind)
{
    return estimate_of(s, s->energy.per_contact[j], s->companion->energy.per_contact[j],
                       second(s)->energy.per_contact[j], kind);
}

/* The estimate of joint element i's dissipation (the elements have no eps: their error is
 * dt's, along the same path). */
static double element_dissipation_estimate(const fricreg_structure *s, size_t i, int *kind)
{
    return estimate_of(s, s->el.dissipation[i], s->companion->el.dissipation[i],
                       second(s)->el.dissipation[i], kind);
}

/* One of the warning's two quantities: its value, its estimate, and the kind of the largest
 * estimate in it (the one that weighs most in a sum). */
struct judged {
    double q, err, largest;
    int kind;
};

static void add_estimate(struct judged *sum, double q, double err, int kind)
{
    sum->q += fabs(q);
    sum->err += err;
    if (err > sum->largest || sum->kind == 0)
        sum->largest = err, sum->kind = kind;
}

static void warn_above_tolerance(fricreg_structure *s, const char *what, const struct judged *x)
{
    fr_warn(&s->warnings, FRICREG_WARN_ERROR_ESTIMATE,
            "the error estimate %.3g of %s %.7g (kind %s) exceeds twice the answer tolerance "
            "%.3g of it (the estimate bounds the error at about twice its size): halve eps and "
            "dt, or raise --answer-rtol (set_answer_rtol)",
            x->err, what, x->q, fr_estimate_kind_name(x->kind), s->answer_rtol);
}

void fr_estimate_check(fricreg_structure *s)
{
    if (s->estimate_state == FR_ESTIMATE_FAILED) {
        fr_warn(&s->warnings, FRICREG_WARN_ERROR_ESTIMATE,
                "no error estimate could be formed (reported as infinite): %s", s->estimate_msg);
        return;
    }
    if (s->estimate_state != FR_ESTIMATE_ACTIVE)
        return;
    /* The peaks: the largest estimate against the largest peak (a building's drift is read at
     * its largest storey); the dissipations, contacts' and joint elements', summed. */
    struct judged peak = {0}, D = {0};
    for (size_t i = 0; i < s->n; i++) {
        int kind;
        double err = peak_estimate(s, i, &kind);
        peak.q = fmax(peak.q, fabs(s->peak[i]));
        if (err > peak.err || peak.kind == 0)
            peak.err = err, peak.kind = kind;
    }
    for (size_t j = 0; j < s->m; j++) {
        int kind;
        double err = dissipation_estimate(s, j, &kind);
        add_estimate(&D, s->energy.per_contact[j], err, kind);
    }
    for (size_t i = 0; i < s->el.me; i++) {
        int kind;
        double err = element_dissipation_estimate(s, i, &kind);
        add_estimate(&D, s->el.dissipation[i], err, kind);
    }
    /* The floors (fr_estimate_exceeds): what the contacts' band, |zdot| < eps, moves in the
     * run's time, and the work their bounds do over it. */
    double band = fr_ctx_eps(s->ctx) * s->t, work = 0.0;
    for (size_t j = 0; j < s->m; j++)
        work += s->mun[j] * band;
    if (fr_estimate_exceeds(peak.err, peak.q, s->answer_rtol, band))
        warn_above_tolerance(s, "the largest peak displacement", &peak);
    if (fr_estimate_exceeds(D.err, D.q, s->answer_rtol, work))
        warn_above_tolerance(s, "the summed dissipation", &D);
}

int fricreg_structure_set_answer_rtol(fricreg_structure *s, double rtol)
{
    if (s == NULL)
        return FRICREG_ENULL;
    if (!(rtol > 0.0 && rtol < INFINITY)) /* NaN fails both */
        return fr_fail(s, FRICREG_EINVAL, "set_answer_rtol: rtol = %g must be finite and > 0",
                       rtol);
    s->answer_rtol = rtol;
    return FRICREG_OK;
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
        companion_free(s);
        s->estimate_state = FR_ESTIMATE_NONE;
    }
    s->estimate_on = on;
    return FRICREG_OK;
}

int fricreg_structure_set_error_companions(fricreg_structure *s, int which)
{
    if (s == NULL || s->running)
        return fr_structure_refuse(s, "set_error_companions");
    if (which != FRICREG_COMPANIONS_FINER && which != FRICREG_COMPANIONS_COARSER)
        return fr_fail(s, FRICREG_EINVAL,
                       "set_error_companions: which = %d must be 0 (finer) or 1 (coarser)", which);
    if (which != s->companions) { /* a companion made at the other levels */
        companion_free(s);
        s->estimate_state = FR_ESTIMATE_NONE;
    }
    s->companions = which;
    return FRICREG_OK;
}

int fricreg_structure_get_peak_displacement(const fricreg_structure *s, size_t ndof, double peak[])
{
    if (s == NULL || peak == NULL)
        return FRICREG_ENULL;
    if (ndof != s->n)
        return FRICREG_ESIZE;
    memcpy(peak, s->peak, ndof * sizeof *peak);
    return FRICREG_OK;
}

/* FRICREG_OK when the estimate can be read (a run made one, the companion at s's time). */
static int estimate_ready(const fricreg_structure *s, size_t len, size_t expected, const void *out)
{
    if (s == NULL || out == NULL)
        return FRICREG_ENULL;
    if (s->estimate_state == FR_ESTIMATE_NONE || s->fresh || s->running)
        return FRICREG_EINVAL; /* no step since set_initial with the estimate on, or in a run */
    return len == expected ? FRICREG_OK : FRICREG_ESIZE;
}

int fricreg_structure_get_peak_displacement_error(const fricreg_structure *s, size_t ndof,
                                                  double err[])
{
    int status = estimate_ready(s, ndof, s != NULL ? s->n : 0, err);
    if (status != FRICREG_OK)
        return status;
    for (size_t i = 0; i < ndof; i++)
        err[i] = s->estimate_state == FR_ESTIMATE_FAILED ? INFINITY
                                                         : peak_estimate(s, i, &(int){0});
    return FRICREG_OK;
}

int fricreg_structure_get_dissipation_error(const fricreg_structure *s, size_t m, double err[])
{
    int status = estimate_ready(s, m, s != NULL ? s->m : 0, err);
    if (status != FRICREG_OK)
        return status;
    for (size_t j = 0; j < m; j++)
        err[j] = s->estimate_state == FR_ESTIMATE_FAILED ? INFINITY
                                                         : dissipation_estimate(s, j, &(int){0});
    return FRICREG_OK;
}

int fricreg_structure_get_jenkins_dissipation_error(const fricreg_structure *s, size_t me,
                                                    double err[])
{
    int status = estimate_ready(s, me, s != NULL ? s->el.me : 0, err);
    if (status != FRICREG_OK)
        return status;
    for (size_t i = 0; i < me; i++)
        err[i] = s->estimate_state == FR_ESTIMATE_FAILED
                     ? INFINITY
                     : element_dissipation_estimate(s, i, &(int){0});
    return FRICREG_OK;
}

/* The kind of quantity `quantity`'s i-th estimate (enum fricreg_estimated_quantity). */
static int kind_of(const fricreg_structure *s, int quantity, size_t i)
{
    int kind = FRICREG_EST_KIND_BOUND; /* a failed estimate: +infinity, a bound */
    if (s->estimate_state == FR_ESTIMATE_FAILED)
        return kind;
    if (quantity == FRICREG_EST_PEAK_DISPLACEMENT)
        peak_estimate(s, i, &kind);
    else if (quantity == FRICREG_EST_DISSIPATION)
        dissipation_estimate(s, i, &kind);
    else
        element_dissipation_estimate(s, i, &kind);
    return kind;
}

int fricreg_structure_get_error_kind(const fricreg_structure *s, int quantity, size_t n, int kind[])
{
    if (s == NULL || kind == NULL)
        return FRICREG_ENULL; /* before the quantity is read, as the *_error getters */
    size_t expected;
    switch (quantity) {
    case FRICREG_EST_PEAK_DISPLACEMENT: expected = s->n; break;
    case FRICREG_EST_DISSIPATION: expected = s->m; break;
    case FRICREG_EST_ELEMENT_DISSIPATION: expected = s->el.me; break;
    default: return FRICREG_EINVAL;
    }
    int status = estimate_ready(s, n, expected, kind);
    if (status != FRICREG_OK)
        return status;
    for (size_t i = 0; i < n; i++)
        kind[i] = kind_of(s, quantity, i);
    return FRICREG_OK;
}
