/* SPDX-License-Identifier: GPL-3.0-or-later */
/* belt.c — the belt-driven stick-slip oscillator with Stribeck friction (problems.h,
 * docs/laws2d.md): its limit cycle under the regularized law, and the event-driven reference
 * it is measured against. */
#include <math.h>

#include "fricreg_stribeck.h"
#include "prob_internal.h"

struct prob_belt prob_belt_defaults(void)
{
    return (struct prob_belt){.fs = 1.0,
                              .fk = 0.5,
                              .vs = 0.05,
                              .delta = 1.0,
                              .v_belt = 0.2,
                              .dt = 0.01,
                              .eps = 0.02,
                              .cycles = 12,
                              .ref_dt = 1e-5};
}

static int valid(const struct prob_belt *p)
{
    const double finite[8] = {p->fs, p->fk, p->vs, p->delta, p->v_belt, p->dt, p->eps, p->ref_dt};
    for (int k = 0; k < 8; k++)
        if (!isfinite(finite[k]))
            return 0;
    return p->fk >= 0.0 && p->fs > 0.0 && p->fk <= p->fs && p->vs > 0.0 && p->delta > 0.0 &&
           p->v_belt > 0.0 && p->dt > 0.0 && p->eps > 0.0 && p->ref_dt > 0.0 && p->cycles >= 2 &&
           p->cycles <= 100000;
}

/* A run ends within this time, or it found no limit cycle: the cycle of the set-valued law is
 * at most one stick (2 fs/V) plus a few natural periods long. */
static double time_bound(const struct prob_belt *p)
{
    return (p->cycles + 2) * (2.0 * p->fs / p->v_belt + 100.0);
}

/* ---- The reference ---------------------------------------------------------------------- */

struct slip {
    const struct prob_belt *p;
    double s; /* the slip's direction, sgn(x' - V), held over the phase */
};

double prob_belt_kinetic(const struct prob_belt *p, double speed)
{
    return p->fk + (p->fs - p->fk) * exp(-pow(speed / p->vs, p->delta));
}

/* Slip with the direction held: x'' = -x - s k(|x' - V|) (fricreg_stribeck.h's kinetic curve). */
static int slip_rhs(double t, const double y[], double dy[], void *params)
{
    (void)t;
    const struct slip *sl = params;
    dy[0] = y[1];
    dy[1] = -y[0] - sl->s * prob_belt_kinetic(sl->p, fabs(y[1] - sl->p->v_belt));
    return GSL_SUCCESS;
}

static int emit(prob_observer observe, void *user, double t, double x, double v)
{
    double row[PROB_BELT_COLUMNS] = {x, v, NAN};
    return observe != NULL && observe(user, t, row, PROB_BELT_COLUMNS) != 0 ? FRICREG_ENOMEM
                                                                            : FRICREG_OK;
}

struct reference_run {
    const struct prob_belt *p;
    struct prob_rk4 rk;
    struct slip sl;
    gsl_root_fsolver *solver;
    double t, x, x_min, x_max;
    double steps;
};

/* The slip of a stick-slip cycle lasts about one natural period 2 pi (x'' + x = const while
 * the force is near fk), its reversals included: slip that has not stuck after
 * SLIP_PERIODS_MAX periods belongs to no stick-slip cycle (a belt so fast that x' meets V only
 * tangentially, --v-belt 1e3, slid on, phase after phase, until the run's time bound: 7e7
 * steps, 28 s), and is refused as such. */
#define SLIP_PERIODS_MAX 10.0
#define TWO_PI 6.283185307179586

/* One slip phase from (x, V) at t in direction s, to its end x' = V located inside the step;
 * observed if `observe`. Leaves run->x, run->t at the end. FRICREG_EDIVERGED past `t_max`. */
static int slip_phase(struct reference_run *run, double s, double t_max, prob_observer observe,
                      void *user)
{
    const double V = run->p->v_belt, h = 2.0 * run->rk.dt;
    double y[2] = {run->x, V}, t0 = run->t;
    int status = FRICREG_OK, none = FRICREG_OK;
    run->sl.s = s;
    for (double k = 0.0; status == FRICREG_OK; k += 1.0) {
        if (t0 + k * h > t_max)
            return FRICREG_EDIVERGED;
        double a[3] = {y[0], y[1], 0.0}, b[3], d[2];
        slip_rhs(0.0, y, d, &run->sl);
        a[2] = d[1];
        status = prob_rk4_advance(&run->rk, t0 + k * h, y, &none);
        run->steps += 2.0;
        slip_rhs(0.0, y, d, &run->sl);
        b[0] = y[0], b[1] = y[1], b[2] = d[1];
        if (status != FRICREG_OK)
            break;
        /* the slip ends where x' - V changes sign against s (not at the phase's start) */
        if ((b[1] - V) * s <= 0.0 && (k > 0.0 || a[1] != V)) {
            double theta;
            status = prob_hermite_crossing(run->solver, a[1], a[2], b[1], b[2], h, V, &theta);
            if (status != FRICREG_OK)
                break;
            double x_end = prob_hermite(a[0], a[1], b[0], b[1], h, theta);
            double end[3] = {x_end, V, -x_end - s * run->p->fs}; /* k(0) = fs */
            status = prob_track_extremes(run->solver, a, end, theta * h, &run->x_min, &run->x_max);
            run->x = x_end;
            run->t = t0 + (k + theta) * h;
            return status == FRICREG_OK ? emit(observe, user, run->t, x_end, V) : status;
        }
        status = prob_track_extremes(run->solver, a, b, h, &run->x_min, &run->x_max);
        if (status == FRICREG_OK)
            status = emit(observe, user, t0 + (k + 1.0) * h, y[0], y[1]);
    }
    return status;
}

/* One cycle from stick at run->x: stick exact until x = fs (break-away), then slip until the
 * contact sticks again (|x| <= fs at x' = V), reversing the slip if it does not. */
static int reference_cycle(struct reference_run *run, int last, prob_observer observe, void *user,
                           double *break_time)
{
    const struct prob_belt *p = run->p;
    prob_observer obs = last ? observe : NULL;
    int status = emit(obs, user, run->t, run->x, p->v_belt);
    run->x_min = fmin(run->x_min, run->x);
    run->t += (p->fs - run->x) / p->v_belt; /* stick: x = x0 + V (t - t0), exactly */
    run->x = p->fs;
    run->x_max = fmax(run->x_max, p->fs);
    *break_time = run->t;
    if (status == FRICREG_OK)
        status = emit(obs, user, run->t, run->x, p->v_belt);
    /* at break-away f_eq = x = fs: the force falls below it, so x' < V: s = -1 */
    double t_max = fmin(time_bound(p), run->t + SLIP_PERIODS_MAX * TWO_PI);
    for (double s = -1.0; status == FRICREG_OK; s = -s) {
        status = slip_phase(run, s, t_max, obs, user);
        if (status == FRICREG_OK && fabs(run->x) <= p->fs)
            break; /* sticks */
        if (run->t > t_max)
            return FRICREG_EDIVERGED;
    }
    return status;
}

int prob_belt_reference(const struct prob_belt *p, prob_observer observe, void *user,
                        struct prob_belt_cycle *c)
{
    if (!valid(p))
        return FRICREG_EINVAL;
    struct reference_run run = {.p = p, .sl = {p, -1.0}};
    int status = prob_rk4_init(&run.rk, slip_rhs, 2, &run.sl, p->ref_dt);
    if (status != FRICREG_OK)
        return status;
    run.solver = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    if (run.solver == NULL) {
        prob_rk4_free(&run.rk);
        return FRICREG_ENOMEM;
    }
    double last_break = 0.0, break_time = 0.0, period = 0.0;
    for (int cycle = 1; status == FRICREG_OK && cycle <= p->cycles; cycle++) {
        run.x_min = INFINITY, run.x_max = -INFINITY;
        status = reference_cycle(&run, cycle == p->cycles, observe, user, &break_time);
        period = break_time - last_break;
        last_break = break_time;
    }
    gsl_root_fsolver_free(run.solver);
    prob_rk4_free(&run.rk);
    if (status != FRICREG_OK)
        return status;
    *c = (struct prob_belt_cycle){period,    0.5 * (run.x_max - run.x_min),
                                  run.x_min, run.x_max,
                                  run.steps, run.t};
    return FRICREG_OK;
}

/* ---- The regularized law ---------------------------------------------------------------- */

struct belt_rhs {
    const struct prob_belt *p;
    int status;
};

/* y = (x, x'): x'' = -x + f, f = the Stribeck law at v = x' - V with f_eq = x. */
static int belt_force(const struct prob_belt *p, const double y[], double *f)
{
    return fricreg_stribeck_eval(y[1] - p->v_belt, y[0], p->fs, p->fk, p->vs, p->delta, p->eps, f);
}

static int belt_rhs(double t, const double y[], double dy[], void *params)
{
    (void)t;
    struct belt_rhs *r = params;
    double f;
    int status = belt_force(r->p, y, &f);
    if (status != FRICREG_OK) {
        r->status = status;
        return GSL_EBADFUNC;
    }
    dy[0] = y[1];
    dy[1] = -y[0] + f;
    return GSL_SUCCESS;
}

/* The state and its rates at the end of a step: (x, x', x''), and the force. */
static int with_rates(const struct prob_belt *p, const double y[2], double z[3], double *f)
{
    int status = belt_force(p, y, f);
    z[0] = y[0], z[1] = y[1], z[2] = -y[0] + *f;
    return status;
}

struct regularized_run {
    const struct prob_belt *p;
    struct prob_rk4 rk;
    struct belt_rhs params;
    gsl_root_fsolver *solver;
};

static int regularized(struct regularized_run *run, double level, prob_observer observe, void *user,
                       struct prob_belt_cycle *c)
{
    const struct prob_belt *p = run->p;
    const double h = 2.0 * p->dt, n_max = ceil(time_bound(p) / h);
    double y[2] = {0.0, p->v_belt}, a[3], b[3], f, crossing[2] = {0.0, 0.0};
    double x_min = INFINITY, x_max = -INFINITY, k = 0.0;
    int crossings = 0, status = with_rates(p, y, a, &f);
    for (; status == FRICREG_OK && crossings <= p->cycles; k += 1.0) {
        if (k >= n_max)
            return FRICREG_EDIVERGED;
        status = prob_rk4_advance(&run->rk, k * h, y, &run->params.status);
        if (status == FRICREG_OK)
            status = with_rates(p, y, b, &f);
        if (status != FRICREG_OK)
            break;
        int in_cycle = crossings == p->cycles;
        if (in_cycle) /* the measured cycle, between the cycles-th and next crossing */
            status = prob_track_extremes(run->solver, a, b, h, &x_min, &x_max);
        if (status == FRICREG_OK && in_cycle && observe != NULL) {
            double row[PROB_BELT_COLUMNS] = {y[0], y[1], f};
            if (observe(user, (k + 1.0) * h, row, PROB_BELT_COLUMNS) != 0)
                status = FRICREG_ENOMEM;
        }
        if (status == FRICREG_OK && a[0] > level && b[0] <= level) {
            double theta;
            status = prob_hermite_crossing(run->solver, a[0], a[1], b[0], b[1], h, level, &theta);
            crossing[0] = crossing[1];
            crossing[1] = (k + theta) * h;
            crossings++;
        }
        a[0] = b[0], a[1] = b[1], a[2] = b[2];
    }
    if (status != FRICREG_OK)
        return status;
    *c = (struct prob_belt_cycle){
        crossing[1] - crossing[0], 0.5 * (x_max - x_min), x_min, x_max, 2.0 * k, k * h};
    return FRICREG_OK;
}

int prob_belt_regularized(const struct prob_belt *p, double level, prob_observer observe,
                          void *user, struct prob_belt_cycle *c)
{
    if (!valid(p) || !isfinite(level))
        return FRICREG_EINVAL;
    struct regularized_run run = {.p = p, .params = {p, FRICREG_OK}};
    int status = prob_rk4_init(&run.rk, belt_rhs, 2, &run.params, p->dt);
    if (status != FRICREG_OK)
        return status;
    run.solver = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    status = run.solver == NULL ? FRICREG_ENOMEM : regularized(&run, level, observe, user, c);
    if (run.solver != NULL)
        gsl_root_fsolver_free(run.solver);
    prob_rk4_free(&run.rk);
    return status;
}
