/* SPDX-License-Identifier: GPL-3.0-or-later */
/* twoblock.c — the two blocks of Eqs. (7): the lower block x1 on a belt
 * u(t) = belt_amp sin(belt_omega t), the upper block x2 on it, unit masses, springs 1 and k to
 * the ground. Contacts z1 = x1 - u (bound mu1) and z2 = x2 - x1 (bound mu2) couple through
 * W = [[1, -1], [-1, 2]]. */
#include <math.h>

#include "base/fr_math.h"
#include "sim/system.h"

enum { K, MU1, MU2, BELT_AMP, BELT_OMEGA, NPARAMS };
FR_CHECK_NPARAMS(NPARAMS);

/* The paper's values (spec: reference system 3, Sec. 3.3). */
static const struct fr_param_spec params[NPARAMS] = {
    [K] = {FRICREG_PARAM_K, "k", 2.0, fr_param_positive, "must be > 0"},
    [MU1] = {FRICREG_PARAM_MU1, "mu1", 0.5, fr_param_nonnegative, "must be >= 0"},
    [MU2] = {FRICREG_PARAM_MU2, "mu2", 0.25, fr_param_nonnegative, "must be >= 0"},
    [BELT_AMP] = {FRICREG_PARAM_BELT_AMP, "belt_amp", 1.0, NULL, NULL},
    [BELT_OMEGA] = {FRICREG_PARAM_BELT_OMEGA, "belt_omega", 0.5, fr_param_positive, "must be > 0"},
};

static size_t two(const struct fr_system *sys)
{
    (void)sys;
    return 2;
}

static double period(const struct fr_system *sys)
{
    return FR_TWO_PI / sys->p[BELT_OMEGA];
}

/* Without friction the blocks are independent: frequencies 1 and sqrt(k). */
static double max_frequency(const struct fr_system *sys)
{
    return sqrt(fmax(1.0, sys->p[K]));
}

static int configure(const struct fr_system *sys, fricreg_ctx *ctx)
{
    const double W[4] = {1.0, -1.0, -1.0, 2.0}; /* Eqs. (7): z'' = a_free + W f */
    const double mun[2] = {sys->p[MU1], sys->p[MU2]};
    int status = fricreg_ctx_set_coupling_dense(ctx, 2, W);
    return status ? status : fricreg_ctx_set_bounds(ctx, 2, mun);
}

static void initial(const struct fr_system *sys, double x[], double v[])
{
    (void)sys;
    x[0] = x[1] = v[0] = v[1] = 0.0;
}

static const double *contacts(struct fr_system *sys, double t, const double x[], const double v[],
                              double zdot[], double a_free[])
{
    double omega = sys->p[BELT_OMEGA], wt = omega * t;
    double belt_v = sys->p[BELT_AMP] * omega * cos(wt);
    zdot[0] = v[0] - belt_v;
    zdot[1] = v[1] - v[0];
    if (a_free != NULL) {
        double belt_a = -sys->p[BELT_AMP] * omega * omega * sin(wt);
        a_free[0] = -belt_a - x[0];
        a_free[1] = x[0] - sys->p[K] * x[1];
    }
    return zdot;
}

/* x' = v and (7a), (7b); the power zdot . f. */
static double bodies(const struct fr_system *sys, double t, const double x[], const double v[],
                     const double zdot[], const double a_free[], const double f[], double dydt[])
{
    (void)t, (void)a_free;
    dydt[0] = v[0];
    dydt[1] = v[1];
    dydt[2] = -x[0] + f[0] - f[1];
    dydt[3] = -sys->p[K] * x[1] + f[1];
    return zdot[0] * f[0] + zdot[1] * f[1];
}

/* contacts() and bodies() as matrices: z1 = x1 - u, z2 = x2 - x1. */
static void contact_maps(const struct fr_system *sys, double dzdot_dv[], double dafree_dx[])
{
    const double Zv[4] = {1.0, 0.0, -1.0, 1.0};
    const double Ax[4] = {-1.0, 0.0, 1.0, -sys->p[K]};
    for (size_t k = 0; k < 4; k++) {
        dzdot_dv[k] = Zv[k];
        dafree_dx[k] = Ax[k];
    }
}

static void body_maps(const struct fr_system *sys, double dacc_dx[], double dacc_df[])
{
    const double Cx[4] = {-1.0, 0.0, 0.0, -sys->p[K]};
    const double Cf[4] = {1.0, -1.0, 0.0, 1.0}; /* (7a), (7b): Zv Cf = W */
    for (size_t k = 0; k < 4; k++) {
        dacc_dx[k] = Cx[k];
        dacc_df[k] = Cf[k];
    }
}

/* The belt u = b sin(omega t) enters zdot_1 through -u' and a_free,1 through -u''. */
static void time_rates(const struct fr_system *sys, double t, double dzdot_dt[], double dafree_dt[],
                       double dacc_dt[])
{
    double omega = sys->p[BELT_OMEGA], b = sys->p[BELT_AMP], wt = omega * t;
    dzdot_dt[0] = b * omega * omega * sin(wt);          /* -u'' */
    dafree_dt[0] = b * omega * omega * omega * cos(wt); /* -u''' */
    dzdot_dt[1] = dafree_dt[1] = 0.0;
    dacc_dt[0] = dacc_dt[1] = 0.0;
}

const struct fr_system_type fr_twoblock_type = {
    .id = FRICREG_SYSTEM_TWOBLOCK,
    .name = "two blocks",
    .params = params,
    .nparams = NPARAMS,
    .ndof = two,
    .ncontacts = two,
    .period = period,
    .max_frequency = max_frequency,
    .paper_eps = fr_paper_eps_two_dt, /* as for the oscillator (Sec. 3.3) */
    .dissipation_weight = fr_unit_weight,
    .configure = configure,
    .initial = initial,
    .contacts = contacts,
    .bodies = bodies,
    .contact_maps = contact_maps,
    .body_maps = body_maps,
    .time_rates = time_rates,
};
