/* SPDX-License-Identifier: GPL-3.0-or-later */
/* run.c — fricreg_sim_run and fricreg_sim_run_cycles: the run (sim.c), then the error
 * estimate's companions when it is on (error_estimate.c), then the warnings to the handler
 * (warnings.c). Above all three. */
#include "sim_internal.h"

/* A run's warnings go to the handler once each, at the end, whether or not it failed. */
int fricreg_sim_run(fricreg_sim *sim, double t_end)
{
    if (sim == NULL || sim->running)
        return fr_sim_refuse_during_run(sim, "run");
    fr_warnings_forget_delivered(&sim->warnings);
    int status = fr_sim_run_plain(sim, t_end);
    if (status == FRICREG_OK && sim->error_estimate && !sim->estimate_skip)
        fr_sim_error_estimate(sim);
    fr_sim_judge_for_handler(sim);
    return status;
}

int fricreg_sim_run_cycles(fricreg_sim *sim, int cycles)
{
    if (sim == NULL)
        return FRICREG_ENULL;
    if (cycles < 1)
        return fr_fail(sim, FRICREG_EINVAL, "run_cycles: cycles = %d must be >= 1", cycles);
    double period;
    fricreg_sim_get_value(sim, FRICREG_VALUE_PERIOD, &period);
    return fricreg_sim_run(sim, cycles * period);
}
