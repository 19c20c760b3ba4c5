/* SPDX-License-Identifier: GPL-3.0-or-later */
/* kinks.h — internal: fricreg_sim's adaptive steps stopped at the friction law's kinks
 * (kinks.c; fricreg_sim_set_kink_location). */
#ifndef FRICREG_SIM_KINKS_H
#define FRICREG_SIM_KINKS_H

#include <gsl/gsl_odeiv2.h>

#include "ode/integrator.h"
#include "sim_internal.h"

struct fr_kinks;

/* The locator of a run of `sim` (allocated, its state set up: alloc_run done) on the driver d
 * with the integrator integ, or NULL when out of memory. A multistep integrator's locator
 * stepper is allocated by GSL (gsl_odeiv2_step_alloc), as the driver's own stepper is
 * (ode_driver.h). */
struct fr_kinks *fr_kinks_new(fricreg_sim *sim, gsl_odeiv2_driver *d,
                              const struct fr_integrator *integ);

/* Releases a locator (NULL: nothing). */
void fr_kinks_free(struct fr_kinks *k);

/* The switching functions at the run's current state, as the first step's start: a fricreg
 * status (failures recorded in sim). */
int fr_kinks_start(struct fr_kinks *k, fricreg_sim *sim);

/* Before an adaptive step from the current state: saves the step's start and returns the time
 * the step may not pass (a kink the stepper re-approaches under its control), or t_stop. */
double fr_kinks_before_step(struct fr_kinks *k, const fricreg_sim *sim, double t_stop);

/* After an accepted adaptive step: where a switching function changed sign within it, cuts
 * the step at the first crossing (sim->t, sim->y), or returns to the step's start to
 * re-approach the crossing under the stepper's control (*moved = 0, else 1), and restarts the
 * driver's stepper; sim->kinks counts the cuts. A fricreg status, failures recorded in sim. */
int fr_kinks_after_step(struct fr_kinks *k, fricreg_sim *sim, gsl_odeiv2_driver *d, int *moved);

#endif
