/* SPDX-License-Identifier: GPL-3.0-or-later */
/* problems_cvode.h — the event-driven CVODE references of two of the problems beyond the paper
 * (bench/problems_wp.c's independent check): the belt-driven Stribeck oscillator
 * (bench/belt_cvode.c) and the 2-D oscillator with rotating forcing (bench/disk_cvode.c). The
 * problems themselves (parameters, forcing, kinetic curve) and their regularized runs are
 * src/problems/ (problems.h), which fricreg-sim and the other benchmarks share; the references
 * take them from there. Built only with SUNDIALS (FRICREG_BENCH_CVODE). Not part of the
 * library. */
#ifndef FRICREG_BENCH_PROBLEMS_CVODE_H
#define FRICREG_BENCH_PROBLEMS_CVODE_H

#include <stddef.h>

#include "problems.h"

/** The limit cycle of the belt oscillator: period (time between break-aways) and amplitude
 *  (x_max - x_min)/2 of the last cycle run. */
struct belt_cycle {
    double period, amplitude;
    double steps;  /* CVODE's steps */
    double events; /* stick/slip switches */
};

/** D per forcing cycle of the 2-D oscillator, and the work it took. */
struct disk_result {
    double dissipation;
    double steps, events;
};

/** Event-driven CVODE reference of the belt oscillator p (its fs, fk, vs, delta, v_belt and
 *  cycles; dt, eps and ref_dt are the regularized run's and are not used): stick phases exact,
 *  slip phases by CVODE (method: enum ed_method of event_driven.h) at rtol = atol, p->cycles
 *  cycles from stick at x = 0. Returns FRICREG_OK; FRICREG_EINTEGRATOR if CVODE fails or a slip
 *  does not end (msg, of msg_len bytes, says why); FRICREG_ENOMEM. */
int belt_cvode_run(const struct prob_belt *p, int method, double rtol, struct belt_cycle *out,
                   char *msg, size_t msg_len);

/** Event-driven CVODE reference of the 2-D oscillator p (its a, omega, cycles_per_turn and
 *  turns_transient; classical Coulomb friction with mu N = 1, so law, dt and eps are not used),
 *  from rest at the origin. Returns FRICREG_OK; FRICREG_EINTEGRATOR if CVODE fails or the events
 *  cascade (msg says why); FRICREG_ENOMEM. */
int disk_cvode_run(const struct prob_disk *p, int method, double rtol, struct disk_result *out,
                   char *msg, size_t msg_len);

#endif
