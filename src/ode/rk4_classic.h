/* SPDX-License-Identifier: GPL-3.0-or-later */
/* rk4_classic.h — internal: the classical fourth-order Runge-Kutta step as a
 * gsl_odeiv2_step_type (rk4_classic.c), fricreg's one RK4: the drivers' fixed steps of
 * FRICREG_INT_RK4 and the reference problems beyond the paper (src/problems/). */
#ifndef FRICREG_RK4_CLASSIC_H
#define FRICREG_RK4_CLASSIC_H

#include <gsl/gsl_odeiv2.h>

/* Two classical RK4 steps of h/2 per call of step h, as GSL's rk4 takes them (its error
 * estimate is by step doubling), with no error estimate (yerr, which may be NULL, is set to
 * 0): 8 right-hand sides per call where GSL's rk4 spends 11 or 12. dydt_in and dydt_out are
 * neither read nor written. For fixed steps only. */
const gsl_odeiv2_step_type *fr_step_rk4_classic(void);

#endif
