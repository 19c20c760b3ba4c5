/* SPDX-License-Identifier: GPL-3.0-or-later */
/* oscillator.c — the 1-dof oscillator of Eq. (5): x'' + x = f + a sin(omega t), one contact
 * at the body with bound mun, so W = 1 and f_eq = x - a sin(omega t) = -a_free. */
#include <math.h>

#include "base/fr_math.h"
#include "sim/system.h"

enum { A, OMEGA, MUN, X0, V0, NPARAMS };
FR_CHECK_NPARAMS(NPARAMS);

/* The paper's values (spec: reference system 1, Sec. 3.1.1). */
static const struct fr_param_spec params[NPARAMS] = {
    [A] = {FRICREG_PARAM_A, "a", 0.0, NULL, NULL},
    [OMEGA] = {FRICREG_PARAM_OMEGA, "omega", 1.0, fr_param_positive, "must be > 0"},
    [MUN] = {FRICREG_PARAM_MUN, "mun", 1.0, fr_param_nonnegative, "must be >= 0"},
    [X0] = {FRICREG_PARAM_X0, "x0", 2.75, NULL, NULL},
    [V0] = {FRICREG_PARAM_V0, "v0", 0.0, NULL, NULL},
};

static size_t one(const struct fr_system *sys)
{
    (void)sys;
    return 1;
}

static double period(const struct fr_system *sys)
{
    return FR_TWO_PI / sys->p[OMEGA];
}

/* The spring alone: frequency 1. */
static double max_frequency(const struct fr_system *sys)
{
    (void)sys;
    return 1.0;
}

static int configure(const struct fr_system *sys, fricreg_ctx *ctx)
{
    return fricreg_ctx_set_bounds(ctx, 1, &sys->p[MUN]); /* W = 1: the context's default */
}

static void initial(const struct fr_system *sys, double x[], double v[])
{
    x[0] = sys->p[X0];
    v[0] = sys->p[V0];
}

/* The contact is the body: zdot = v. */
static const double *contacts(struct fr_system *sys, double t, const double x[], const double v[],
                              double zdot_buf[], double a_free[])
{
    (void)zdot_buf;
    if (a_free != NULL)
        a_free[0] = -x[0] + sys->p[A] * fr_system_sin(sys, sys->p[OMEGA] * t);
    return v;
}

/* x' = v, x'' = a_free + f; the power v f. */
static double bodies(const struct fr_system *sys, double t, const double x[], const double v[],
                     const double zdot[], const double a_free[], const double f[], double dydt[])
{
    (void)sys, (void)t, (void)x;
    dydt[0] = v[0];
    dydt[1] = a_free[0] + f[0];
    return zdot[0] * f[0];
}

/* zdot = v, a_free = -x + a sin(omega t), acc = a_free + f. */
static void contact_maps(const struct fr_system *sys, double dzdot_dv[], double dafree_dx[])
{
    (void)sys;
    dzdot_dv[0] = 1.0;
    dafree_dx[0] = -1.0;
}

static void body_maps(const struct fr_system *sys, double dacc_dx[], double dacc_df[])
{
    (void)sys;
    dacc_dx[0] = -1.0;
    dacc_df[0] = 1.0;
}

static void time_rates(const struct fr_system *sys, double t, double dzdot_dt[], double dafree_dt[],
                       double dacc_dt[])
{
    double forcing_rate = sys->p[A] * sys->p[OMEGA] * cos(sys->p[OMEGA] * t);
    dzdot_dt[0] = 0.0;
    dafree_dt[0] = dacc_dt[0] = forcing_rate;
}

const struct fr_system_type fr_oscillator_type = {
    .id = FRICREG_SYSTEM_OSCILLATOR,
    .name = "oscillator",
    .params = params,
    .nparams = NPARAMS,
    .ndof = one,
    .ncontacts = one,
    .period = period,
    .max_frequency = max_frequency,
    .paper_eps = fr_paper_eps_two_dt, /* Sec. 3.1 */
    .dissipation_weight = fr_unit_weight,
    .configure = configure,
    .initial = initial,
    .contacts = contacts,
    .contacts_are_bodies = 1,
    .bodies = bodies,
    .contact_maps = contact_maps,
    .body_maps = body_maps,
    .time_rates = time_rates,
};
