/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Runs of fricreg_sim shared by the central-difference and extrapolation tests: law (4) with
 * a set eps and fixed steps, and getters of their results. Failures are Check assertions.
 * Not linked to the library: each test brings its own (shared or static). */
#ifndef FRICREG_TESTS_SIM_RUNS_H
#define FRICREG_TESTS_SIM_RUNS_H

#include "fricreg_sim.h"

/* A simulation of `system` under law (4) with eps, stepped by `integrator` at the fixed dt. */
fricreg_sim *sim_runs_make(int system, int integrator, double dt, double eps);

/* The same for the oscillator with a = 2, omega = 0.5: it sticks twice a cycle. */
fricreg_sim *sim_runs_sticking_oscillator(int integrator, double dt, double eps);

/* Runs `cycles` forcing cycles; on success D of each into D[cycles]. The run's status. */
int sim_runs_dissipation(fricreg_sim *sim, int cycles, double D[]);

/* The forcing period (FRICREG_VALUE_PERIOD), asserted to be there. */
double sim_runs_period(const fricreg_sim *sim);

/* One value of the last extrapolation (fricreg_sim_get_extrapolation), asserted to be there. */
double sim_runs_extrapolation(const fricreg_sim *sim, int which);

#endif
