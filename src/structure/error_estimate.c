/* SPDX-License-Identifier: GPL-3.0-or-later */
/* error_estimate.c — fricreg_structure_set_error_estimate: an a-posteriori estimate of the
 * error of the peak displacements and of each contact's dissipation against the Coulomb
 * problem (eps -> 0), from a companion structure at eps / 2 stepped alongside the structure at
 * half its step (an adaptive GSL run: its tolerances / TOL_SCALE), err = FACTOR |q - q_c|.
 * The estimator and its calibration are fricreg_sim's (src/sim/error_estimate.c;
 * docs/integrators.md, "Error estimate"): law (4)'s error is c eps^p, p = 1 or 2, and along
 * dt / eps fixed a fixed step's error follows eps, so q(eps) - q(0) is at most twice the
 * companion's difference.
 *
 * The companion is a copy of the structure (model, excitation, law at eps / 2, bounds, scheme,
 * Newton, elements, initial state) made at the first stepping call after set_initial with the
 * estimate on; the setters a run calls between steps are passed on to it (structure.c), those
 * that change what it copied end the estimate (fr_estimate_discard). */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "ctx/ctx_driver.h"
#include "fricreg_sim.h"
#include "structure_internal.h"

#define FACTOR 3.0     /* fricreg_sim's: 2 at p = 1, with the calibration's margin */
#define TOL_SCALE 16.0 /* the companion's tolerances (fricreg_sim's) */
#define TOO_LARGE 0.1  /* an estimate above 10% of its quantity: outside the asymptotic range */

void fr_peak_sample(fricreg_structure *s)
{
    const double *u = s->u->data;
    for (size_t i = 0; i < s->n; i++)
        s->peak[i] = fmax(s->peak[i], fabs(u[i]));
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
        status = fricreg_structure_set_law(c, fr_ctx_law(s->ctx), 0.5 * fr_ctx_eps(s->ctx));
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
    c->max_steps = s->max_steps;
    c->tol_scale = s->tol_scale / TOL_SCALE; /* run_ode's rule from eps and set tolerances */
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

void fr_estimate_begin(fricreg_structure *s)
{
    if (!s->estimate_on || s->estimate_state != FR_ESTIMATE_NONE || !s->fresh)
        return;
    fricreg_structure *c = NULL;
    if (fricreg_structure_create(s->n, s->m, &c) != FRICREG_OK) {
        estimate_failed(s, "no memory for the companion structure");
        return;
    }
    s->companion = c;
    s->estimate_state = FR_ESTIMATE_ACTIVE;
    if (copy_structure(c, s) != FRICREG_OK)
        estimate_failed(s, "the companion could not be made: %s", fricreg_structure_errmsg(c));
}

void fr_estimate_follow(fricreg_structure *s, int integrator, double dt, double rtol, double atol)
{
    fricreg_structure *c = s->companion;
    if (s->estimate_state != FR_ESTIMATE_ACTIVE || !(s->t > c->t))
        return;
    int status;
    if (integrator == 0)
        status = fricreg_structure_run(c, 0.5 * dt, s->t);
    else if (rtol > 0.0 || atol != 0.0) /* the rule's and the set levels: c->tol_scale */
        status = fricreg_structure_run_ode(c, integrator, dt, rtol / TOL_SCALE,
                                           atol == FRICREG_ATOL_FROM_EPS ? FRICREG_ATOL_FROM_EPS
                                                                         : atol / TOL_SCALE,
                                           s->t);
    else
        status = fricreg_structure_run_ode(c, integrator, 0.5 * dt, 0.0, 0.0, s->t);
    if (status != FRICREG_OK)
        estimate_failed(s, "the companion run at eps = %g failed: %s", fr_ctx_eps(c->ctx),
                        fricreg_structure_errmsg(c));
}

void fr_estimate_discard(fricreg_structure *s)
{
    companion_free(s);
    s->estimate_state = FR_ESTIMATE_NONE;
}

void fr_estimate_forwarded(fricreg_structure *s, int status, const char *who)
{
    if (status != FRICREG_OK)
        estimate_failed(s, "the companion refused %s: %s", who,
                        fricreg_structure_errmsg(s->companion));
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
    const fricreg_structure *c = s->companion;
    double peak = 0.0, peak_err = 0.0, D = 0.0, D_err = 0.0;
    for (size_t i = 0; i < s->n; i++) {
        peak = fmax(peak, s->peak[i]);
        peak_err = fmax(peak_err, FACTOR * fabs(s->peak[i] - c->peak[i]));
    }
    for (size_t j = 0; j < s->m; j++) {
        D += fabs(s->energy.per_contact[j]);
        D_err += FACTOR * fabs(s->energy.per_contact[j] - c->energy.per_contact[j]);
    }
    if (peak_err > TOO_LARGE * peak || D_err > TOO_LARGE * D)
        fr_warn(&s->warnings, FRICREG_WARN_ERROR_ESTIMATE,
                "an error estimate is above 10%% of its quantity (peak %.3g +- %.3g, "
                "dissipation %.3g +- %.3g): eps or dt is too coarse for the estimate, which may "
                "then not bound the error; halve them",
                peak, peak_err, D, D_err);
}

int fricreg_structure_set_error_estimate(fricreg_structure *s, int on)
{
    if (s == NULL)
        return FRICREG_ENULL;
    if (s->running)
        return fr_structure_busy(s, "set_error_estimate");
    if (on != 0 && on != 1)
        return fr_fail(s, FRICREG_EINVAL, "set_error_estimate: on = %d must be 0 or 1", on);
    if (!on)
        fr_estimate_discard(s);
    s->estimate_on = on;
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
static int estimate_ready(const fricreg_structure *s, size_t len, size_t expected,
                          const double out[])
{
    if (s == NULL || out == NULL)
        return FRICREG_ENULL;
    if (s->estimate_state == FR_ESTIMATE_NONE || s->running)
        return FRICREG_EINVAL;
    return len == expected ? FRICREG_OK : FRICREG_ESIZE;
}

int fricreg_structure_get_peak_displacement_error(const fricreg_structure *s, size_t ndof,
                                                  double err[])
{
    int status = estimate_ready(s, ndof, s != NULL ? s->n : 0, err);
    if (status != FRICREG_OK)
        return status;
    for (size_t i = 0; i < ndof; i++)
        err[i] = s->estimate_state == FR_ESTIMATE_FAILED
                     ? INFINITY
                     : FACTOR * fabs(s->peak[i] - s->companion->peak[i]);
    return FRICREG_OK;
}

int fricreg_structure_get_dissipation_error(const fricreg_structure *s, size_t m, double err[])
{
    int status = estimate_ready(s, m, s != NULL ? s->m : 0, err);
    if (status != FRICREG_OK)
        return status;
    for (size_t j = 0; j < m; j++)
        err[j] = s->estimate_state == FR_ESTIMATE_FAILED
                     ? INFINITY
                     : FACTOR *
                           fabs(s->energy.per_contact[j] - s->companion->energy.per_contact[j]);
    return FRICREG_OK;
}
