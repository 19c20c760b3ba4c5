/* SPDX-License-Identifier: GPL-3.0-or-later */
/* run.c — the public stepping calls, fricreg_structure_step, _run and _run_ode: the plain
 * stepping (step.c, structure_ode.c) with the error estimate's companion made at the run's
 * start and stepped to the structure's time at each call's end (error_estimate.c), and the
 * run's warnings handed to the handler (warnings.c). */
#include "structure_internal.h"

int fricreg_structure_step(fricreg_structure *s, double dt)
{
    if (s == NULL || s->running)
        return fr_structure_refuse(s, "step");
    fr_estimate_begin(s);
    int status = fr_structure_step_plain(s, dt);
    fr_estimate_follow(s, 0, dt, 0.0, 0.0);
    return status;
}

/* The run's warnings go to the handler at its end, whether or not it failed. */
int fricreg_structure_run(fricreg_structure *s, double dt, double t_end)
{
    if (s == NULL || s->running)
        return fr_structure_refuse(s, "run");
    fr_estimate_begin(s);
    int status = fr_structure_run_plain(s, dt, t_end);
    fr_estimate_follow(s, 0, dt, 0.0, 0.0); /* to where the run ended, failed or stopped */
    fr_structure_judge_for_handler(s);
    return status;
}

int fricreg_structure_run_ode(fricreg_structure *s, int integrator, double dt, double rtol,
                              double atol, double t_end)
{
    if (s == NULL || s->running)
        return fr_structure_refuse(s, "run_ode");
    fr_estimate_begin(s);
    int status = fr_structure_run_ode_plain(s, integrator, dt, rtol, atol, t_end);
    fr_estimate_follow(s, integrator, dt, rtol, atol);
    fr_structure_judge_for_handler(s);
    return status;
}
