/* SPDX-License-Identifier: GPL-3.0-or-later */
/* integrate.h — internal: a run's time stepping, cycle by cycle (integrate.c), on the GSL
 * driver its set-up made (sim.c). */
#ifndef FRICREG_SIM_INTEGRATE_H
#define FRICREG_SIM_INTEGRATE_H

#include <stddef.h>

#include <gsl/gsl_odeiv2.h>

#include "ode/integrator.h"
#include "sim_internal.h"

/* Integrates the `cycles` whole forcing cycles within t_end (after the start_cycle ones a
 * window's run skips), then the rest of the way.
 * The state starts at sim->y, t at sim->t; the observer sees it first. FRICREG_OK (also when
 * the observer stops the run), or the failure recorded in sim. */
int fr_sim_integrate(fricreg_sim *sim, gsl_odeiv2_driver *d, const struct fr_integrator *integ,
                     double t_end, size_t cycles);

#endif
