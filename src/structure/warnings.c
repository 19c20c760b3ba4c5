/* SPDX-License-Identifier: GPL-3.0-or-later */
/* warnings.c — the structure's checks of plausibility (fricreg_structure_warning_count): the
 * model, its excitation and the run so far judged against physical scales in SI units, each
 * check one function with its threshold and its reason (docs/structural.md, "Warnings"), from
 * what the run tracked (warn_track.c). A warning never changes a result: the checks only
 * read. */
#include <math.h>
#include <string.h>

#include "base/fr_math.h"
#include "ctx/ctx_driver.h"
#include "structure_internal.h"

/* Standard gravity (m/s^2): the scale of ground accelerations and of a structure's weight. */
#define G_STANDARD 9.80665

/* A ground record's peak within [0.05 g, 5 g]: a record in g (peak <= ~2, read as m/s^2 below
 * 0.2 g) is caught when its true peak is below 0.49 g, one in cm/s^2 (Gal) when its true peak
 * is above 0.05 g; the strongest records measured are about 3-4 g. */
#define GROUND_PEAK_LO (0.05 * G_STANDARD)
#define GROUND_PEAK_HI (5.0 * G_STANDARD)
/* eps against the ground's peak velocity: law (4) approaches Coulomb's as eps / v shrinks, and
 * slip speeds are of the order of the ground's velocity; fricreg-sim's default is 0.01 PGV. */
#define EPS_PGV_HI 0.1
#define EPS_PGV_LO 1e-9
/* eps against the run's fastest contact: below 10 eps the law is in its regularized band. */
#define EPS_SPEED_RATIO 10.0
/* A run this many times its record's duration past the record's start: the record in ms? */
#define RECORD_RUN_RATIO 10.0
/* The bounds together against the structure's weight, sum_i mun_i max_k |J_ik| / (g 1^T M 1). */
#define BOUND_ACCEL_LO (1e-3 * G_STANDARD)
#define BOUND_ACCEL_HI (10.0 * G_STANDARD)
/* dt against the fundamental period 2 pi/omega_1: at least 10 steps per period (average
 * acceleration's period error (omega dt)^2/12 is then 3.3 %). */
#define STEPS_PER_PERIOD 10.0
#define NEWTON_MEAN_MAX 5.0
/* An adaptive run_ode's contact velocity tolerance against eps, fricreg_sim's threshold
 * (src/sim/warnings.c, docs/integrators.md "Warnings"): law (4) reads zdot_i within its band
 * |zdot_i| < eps at a stick, and a level of 1e-2 eps already moved D by 1.2e-4 there. */
#define TOL_PER_EPS 1e-2
#define ENERGY_RTOL 1e-6

static void check_tolerances(fricreg_structure *s)
{
    double eps = fr_ctx_eps(s->ctx);
    double level = s->ode_tol_level + s->ode_rtol_max * s->peak_dof_speed;
    if (level > TOL_PER_EPS * eps)
        fr_warn(&s->warnings, FRICREG_WARN_TOL_LOOSE,
                "an adaptive run_ode held a contact velocity to %.3g (sum_j |J_ij| (atol_j + "
                "rtol |v_j|)), above 0.01 eps = %.3g: inside the band |zdot| < eps law (4)'s "
                "force is then uncontrolled; take atol FRICREG_ATOL_FROM_EPS (fricreg-sim: no "
                "--atol)",
                level, TOL_PER_EPS * eps);
}

static int moves_with_ground(const fricreg_structure *s)
{
    for (size_t k = 0; k < s->n; k++)
        if (gsl_vector_get(s->r, k) != 0.0)
            return 1;
    return 0;
}

static void check_ground(fricreg_structure *s)
{
    if (s->ground.n < 2)
        return;
    double pga, pgv, eps = fr_ctx_eps(s->ctx);
    fr_record_peaks(&s->ground, &pga, &pgv);
    if (!(pga >= GROUND_PEAK_LO && pga <= GROUND_PEAK_HI))
        fr_warn(&s->warnings, FRICREG_WARN_GROUND_PEAK,
                "the ground acceleration record peaks at %.4g m/s^2 = %.3g g, outside 0.05 g "
                "to 5 g: is it in m/s^2 (not g or cm/s^2)?",
                pga, pga / G_STANDARD);
    if (!moves_with_ground(s) || !(pgv > 0.0))
        return;
    if (eps > EPS_PGV_HI * pgv)
        fr_warn(&s->warnings, FRICREG_WARN_EPS_LARGE,
                "eps = %.4g m/s is above 0.1 x the ground's peak velocity %.4g m/s: the "
                "regularized law smears stick and slip; is eps in m/s (not mm/s)?",
                eps, pgv);
    else if (eps < EPS_PGV_LO * pgv)
        fr_warn(&s->warnings, FRICREG_WARN_EPS_SMALL,
                "eps = %.4g m/s is below 1e-9 x the ground's peak velocity %.4g m/s: the stick "
                "zone's stiffness 2 mun W/eps makes Newton's steps ill-conditioned",
                eps, pgv);
}

/* Judged once the run has lasted a fundamental period (when known): a structure starting from
 * rest takes that long to reach its speeds. */
static void check_speed(fricreg_structure *s, double period)
{
    double eps = fr_ctx_eps(s->ctx), friction = 0.0;
    for (size_t i = 0; i < s->m; i++)
        friction = fmax(friction, s->mun[i]);
    if (friction > 0.0 && s->stats[FRICREG_SSTAT_STEPS] > 0 && s->t >= period &&
        s->peak_speed < EPS_SPEED_RATIO * eps)
        fr_warn(&s->warnings, FRICREG_WARN_EPS_SPEED,
                "no contact slid faster than 10 eps = %.4g m/s in the run (peak %.4g m/s): "
                "the law never left its regularized band; either the contacts held throughout "
                "or eps, the load or the bounds are off (units?)",
                EPS_SPEED_RATIO * eps, s->peak_speed);
}

/* 1^T M 1, the sum of M's entries (M is held by its upper triangle): the total mass once per
 * translational direction, a scale of what the structure weighs. */
static double mass_sum(const fricreg_structure *s)
{
    const SuiteSparse_long *Mp = s->M->p, *Mi = s->M->i;
    const double *Mx = s->M->x;
    double sum = 0.0;
    for (size_t j = 0; j < s->n; j++)
        for (SuiteSparse_long p = Mp[j]; p < Mp[j + 1]; p++)
            sum += (size_t)Mi[p] == j ? Mx[p] : 2.0 * Mx[p];
    return sum;
}

/* Row i's largest |J_ik|: the contact's bound acts on the structure as J^T f, up to
 * mun_i max_k |J_ik| on one degree of freedom. */
static double row_scale(const fricreg_structure *s, size_t i)
{
    const SuiteSparse_long *Jp = s->Jt->p;
    const double *Jx = s->Jt->x;
    double big = 0.0;
    for (SuiteSparse_long p = Jp[i]; p < Jp[i + 1]; p++)
        big = fmax(big, fabs(Jx[p]));
    return big;
}

/* The bounds are judged together against the weight, not one by one against a node's own
 * effective mass 1/W_ii: on a continuum that mass shrinks as the mesh is refined while the
 * bound stays what the contact carries, and every refined mesh in correct units was flagged.
 * Each bound counts as the force it puts on the structure, mun_i max_k |J_ik| (mun_i for the
 * usual rows of +-1): a row of J scaled by c is the contact of bound c mun_i, and J = 1e100
 * beside mun = 1 broke the steps as mun = 1e100 does (a 100 % energy residual) unflagged. */
static void check_bounds(fricreg_structure *s)
{
    if (!s->prepared)
        return;
    double bounds = 0.0, mass = mass_sum(s), largest = -1.0;
    size_t at = 0;
    for (size_t i = 0; i < s->m; i++) {
        double bound = s->mun[i] * row_scale(s, i);
        bounds += bound;
        if (bound > largest) {
            largest = bound;
            at = i;
        }
    }
    double accel = bounds / mass; /* the acceleration the bounds give the whole mass */
    if (!(bounds > 0.0) || !(mass > 0.0) || (accel >= BOUND_ACCEL_LO && accel <= BOUND_ACCEL_HI))
        return;
    fr_warn(&s->warnings, FRICREG_WARN_BOUND_SCALE,
            "the bounds mun_i max_k |J_ik| sum to %.4g N, %.3g times the weight g 1^T M 1 = "
            "%.4g N, outside 1e-3 to 10 (largest: contact %zu, mun = %.4g N times |J| = %.4g): "
            "are mun in N, M in kg, J dimensionless?",
            bounds, accel / G_STANDARD, G_STANDARD * mass, at, s->mun[at], row_scale(s, at));
}

/* A run far past the end of its ground or load record: the record's time step is likely in ms
 * where s was meant (a 20 s record read as 0.02 s is 1000 times too short). A run is often
 * longer than its record (the free vibration after an earthquake), so only 10 times is
 * judged. */
static void check_record_length(fricreg_structure *s)
{
    const struct fr_record *records[2] = {&s->ground, &s->load};
    const char *names[2] = {"ground acceleration", "load"};
    for (int k = 0; k < 2; k++) {
        const struct fr_record *rec = records[k];
        double duration = rec->n > 1 ? (double)(rec->n - 1) * rec->dt : 0.0;
        if (!(duration > 0.0) || !(s->t - rec->t0 > RECORD_RUN_RATIO * duration))
            continue;
        fr_warn(&s->warnings, FRICREG_WARN_RECORD_SHORT,
                "the run reached t = %.4g s, more than 10 times past the start of its %s record, "
                "which lasts %.4g s (%zu samples, dt = %.4g s): is the record's time step in s "
                "(not ms)?",
                s->t, names[k], duration, rec->n, rec->dt);
        return;
    }
}

/* The fundamental period 2 pi/omega_1 of the model in force, every element sticking, or 0
 * where it is not known (no step yet, a rigid-body mode, no memory). */
static double fundamental_period(fricreg_structure *s)
{
    if (!s->prepared)
        return 0.0;
    double omega = fr_structure_fundamental_omega(s);
    return omega > 0.0 ? FR_TWO_PI / omega : 0.0;
}

static void check_dt(fricreg_structure *s, double period)
{
    if (period > 0.0 && s->max_dt > period / STEPS_PER_PERIOD)
        fr_warn(&s->warnings, FRICREG_WARN_DT_COARSE,
                "dt = %.4g s is above a tenth of the fundamental period %.4g s (omega_1 = %.4g "
                "rad/s): the lowest mode is not resolved; are dt in s, M in kg and K in N/m?",
                s->max_dt, period, FR_TWO_PI / period);
}

static void check_newton(fricreg_structure *s)
{
    int64_t steps = s->stats[FRICREG_SSTAT_STEPS];
    int64_t failures = s->stats[FRICREG_SSTAT_NEWTON_FAILURES];
    if (failures > 0)
        fr_warn(&s->warnings, FRICREG_WARN_NEWTON_FAILURES,
                "%lld of %lld steps ended without Newton's convergence, on their last iterate",
                (long long)failures, (long long)steps);
    double mean = steps > 0 ? (double)s->stats[FRICREG_SSTAT_NEWTON_ITERATIONS] / steps : 0.0;
    if (mean > NEWTON_MEAN_MAX)
        fr_warn(&s->warnings, FRICREG_WARN_NEWTON_SLOW,
                "%.3g Newton iterations per step on average, above 5: eps is small against dt "
                "times the contacts' accelerations",
                mean);
}

static void check_energy(fricreg_structure *s)
{
    if (s->stats[FRICREG_SSTAT_STEPS] == 0 || s->inexact_steps > 0)
        return;
    double initial = 0.0, input = 0.0, residual = 0.0;
    fricreg_structure_get_value(s, FRICREG_SVALUE_INITIAL, &initial);
    fricreg_structure_get_value(s, FRICREG_SVALUE_INPUT, &input);
    fricreg_structure_get_value(s, FRICREG_SVALUE_RESIDUAL, &residual);
    double scale = fabs(initial) + fabs(input);
    if (fabs(residual) > ENERGY_RTOL * scale)
        fr_warn(&s->warnings, FRICREG_WARN_ENERGY,
                "the energy balance's residual %.4g J is above 1e-6 of the initial and input "
                "energy %.4g J, which average-acceleration Newmark closes to Newton's tolerance",
                residual, scale);
}

size_t fricreg_structure_warning_count(fricreg_structure *s)
{
    if (s == NULL)
        return 0;
    if (s->running)
        return s->warnings.n; /* from the observer or the handler: the list as last judged */
    fr_warnings_clear(&s->warnings);
    double period = fundamental_period(s);
    check_ground(s);
    check_speed(s, period);
    check_bounds(s);
    check_record_length(s);
    check_dt(s, period);
    check_newton(s);
    check_energy(s);
    check_tolerances(s);
    fr_estimate_settle(s); /* auto's screen judged at this read (estimate_read.c) */
    fr_estimate_check(s);
    s->running = 1; /* the handler may read, not change, the structure */
    fr_warnings_deliver(&s->warnings);
    s->running = 0;
    return s->warnings.n;
}

int fricreg_structure_set_warning_handler(fricreg_structure *s, fricreg_warning_handler fn,
                                          void *user_data)
{
    if (s == NULL || s->running)
        return fr_structure_refuse(s, "set_warning_handler");
    fr_warnings_set_handler(&s->warnings, fn, user_data);
    return FRICREG_OK;
}

void fr_structure_judge_for_handler(fricreg_structure *s)
{
    if (s->warnings.handler != NULL)
        fricreg_structure_warning_count(s);
}

const char *fricreg_structure_warning_message(const fricreg_structure *s, size_t k)
{
    return s != NULL ? fr_warnings_message(&s->warnings, k) : "";
}

int fricreg_structure_get_warning(const fricreg_structure *s, size_t k, int *code, char *buf,
                                  size_t len)
{
    return s != NULL ? fr_warnings_get(&s->warnings, k, code, buf, len) : FRICREG_ENULL;
}
