/* SPDX-License-Identifier: GPL-3.0-or-later */
/* orbit_state.h — the state of a harmonic-balance orbit at an instant, from its coefficients:
 * the event-driven shootings' starts (jenkins_events.c, liftoff_events.c). */
#ifndef FRICREG_TEST_ORBIT_STATE_H
#define FRICREG_TEST_ORBIT_STATE_H

#include <stddef.h>

/* x_k(t) and v_k(t) into z[2n] from the coefficients x[n (2H + 1)] (per dof x0, a_1, b_1, ...,
 * a_H, b_H) at Ω. */
void orbit_state_at(size_t n, int H, const double *x, double omega, double t, double *z);

#endif
