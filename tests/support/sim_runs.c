/* SPDX-License-Identifier: GPL-3.0-or-later */
/* sim_runs.c — the runs of sim_runs.h. */
#include "sim_runs.h"

#include <check.h>
#include <math.h>

fricreg_sim *sim_runs_make(int system, int integrator, double dt, double eps)
{
    fricreg_sim *sim = NULL;
    ck_assert_int_eq(fricreg_sim_create(system, &sim), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_law(sim, FRICREG_LAW_QUINN, eps), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_integrator(sim, integrator, dt, 0.0, 0.0), FRICREG_OK);
    return sim;
}

fricreg_sim *sim_runs_sticking_oscillator(int integrator, double dt, double eps)
{
    fricreg_sim *sim = sim_runs_make(FRICREG_SYSTEM_OSCILLATOR, integrator, dt, eps);
    ck_assert_int_eq(fricreg_sim_set_param(sim, FRICREG_PARAM_A, 2.0), FRICREG_OK);
    ck_assert_int_eq(fricreg_sim_set_param(sim, FRICREG_PARAM_OMEGA, 0.5), FRICREG_OK);
    return sim;
}

int sim_runs_dissipation(fricreg_sim *sim, int cycles, double D[])
{
    int status = fricreg_sim_run_cycles(sim, cycles);
    if (status == FRICREG_OK)
        ck_assert_int_eq(fricreg_sim_get_dissipation(sim, (size_t)cycles, D), FRICREG_OK);
    return status;
}

double sim_runs_period(const fricreg_sim *sim)
{
    double T = NAN;
    ck_assert_int_eq(fricreg_sim_get_value(sim, FRICREG_VALUE_PERIOD, &T), FRICREG_OK);
    return T;
}

double sim_runs_extrapolation(const fricreg_sim *sim, int which)
{
    double v = NAN;
    ck_assert_int_eq(fricreg_sim_get_extrapolation(sim, which, &v), FRICREG_OK);
    return v;
}
