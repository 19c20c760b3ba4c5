/* SPDX-License-Identifier: GPL-3.0-or-later */
/* shared.c — what the reference systems' types share (system.h): their parameters' range
 * checks, the paper's eps = 2 dt and the unit dissipation weight. Below every system and the
 * table that lists them (systems.c). */
#include "sim/system.h"

int fr_param_positive(double value)
{
    return value > 0.0;
}

int fr_param_nonnegative(double value)
{
    return value >= 0.0;
}

/* The oscillator's (Sec. 3.1) and the two blocks' (Sec. 3.3) choice of eps. */
double fr_paper_eps_two_dt(const struct fr_system *sys, double dt)
{
    (void)sys;
    return 2.0 * dt;
}

double fr_unit_weight(const struct fr_system *sys)
{
    (void)sys;
    return 1.0;
}
