/* SPDX-License-Identifier: GPL-3.0-or-later */
/* issue13.h — the three reference problems of issue 13 as the work-precision benchmark
 * (bench/wp13.c) sees them, and their event-driven CVODE references (bench/belt_cvode.c,
 * bench/disk_cvode.c).
 *
 * The parameters are those of bench/stribeck_belt.c (the belt), bench/disk_laws.c (the 2-D
 * oscillator with rotating forcing) and tests/test_hold.c (the hold), copied here because
 * those files are being moved into a shared problem module (branch sims16); once it lands, this
 * header's constants should come from there. Not part of the library. */
#ifndef FRICREG_BENCH_ISSUE13_H
#define FRICREG_BENCH_ISSUE13_H

#include <stddef.h>

/* ---- (c) the belt-driven stick-slip oscillator with Stribeck friction ---------------------
 *     x'' + x = f(x' - V),   f_eq = x,   k(s) = fk + (fs - fk) exp(-(s/vs)^delta). */
#define BELT_FS 1.0
#define BELT_FK 0.5
#define BELT_VS 0.05
#define BELT_DELTA 1.0
#define BELT_V 0.2

/* ---- (a) the 2-D oscillator with rotating forcing, mun = 1 -------------------------------
 *     x'' + x = f + a sin(omega t) (cos(Omega t), sin(Omega t)),   Omega = omega / 7,
 * D per forcing cycle = the energy -integral f . x' dt over one turn of the direction (7
 * forcing cycles) after 3 turns of transient, divided by 7. */
#define DISK_A 2.0
#define DISK_OMEGA 0.5
#define DISK_CYCLES_PER_TURN 7
#define DISK_TURNS_TRANSIENT 3

/* ---- (b) the hold: a block on an incline, load inside the friction disk ------------------
 *     M v' = F + f,   |F| = M g sin(theta),   mun = mu M g cos(theta),   tan(theta) = 0.8 mu. */
#define HOLD_MASS 2.385
#define HOLD_GRAV 9.81
#define HOLD_MU 0.5385
#define HOLD_PHI 0.6180339887

#define ISSUE13_PI 3.14159265358979323846

/** The limit cycle of the belt oscillator: period (time between break-aways) and amplitude
 *  (x_max - x_min)/2 of the last cycle run. */
struct belt_cycle {
    double period, amplitude;
    double steps;  /* CVODE's steps (0 for the regularized runs) */
    double events; /* stick/slip switches */
};

/** D per forcing cycle of the 2-D oscillator, and the work it took. */
struct disk_result {
    double dissipation;
    double steps, events;
};

/* ---- Under fricreg's regularized laws, GSL's fixed-step RK4 (bench/regularized13.c) ------ */

/** The belt under fricreg_stribeck_eval with eps = 2 dt: `cycles` + 1 downward crossings of
 *  x = 0 from x = 0, x' = V; the period and amplitude of the last cycle. Returns FRICREG_OK;
 *  FRICREG_EINVAL or FRICREG_EINTEGRATOR if the law refuses a state or the state is not finite;
 *  FRICREG_ENOMEM. */
int belt_rk4_run(double dt, int cycles, struct belt_cycle *out);

/** The 2-D oscillator under fricreg_disk_eval(law), dt = one turn / steps_per_turn,
 *  eps = 2 dt, from rest at the origin: D per forcing cycle. Returns as belt_rk4_run. */
int disk_rk4_run(int law, long steps_per_turn, struct disk_result *out);

/** The hold under fricreg_disk_eval(law), eps = 20 dt, `steps` steps from rest: *creep =
 *  |x(T) - x(0)| / T (m/s) and *largest_speed = max |v| over the steps. Returns as
 *  belt_rk4_run. */
int hold_rk4_run(int law, double dt, long steps, double *creep, double *largest_speed);

#ifdef FRICREG_BENCH_CVODE
/** Event-driven CVODE reference of the belt oscillator (bench/belt_cvode.c): stick phases
 *  exact, slip phases by CVODE (method: enum ed_method of event_driven.h) at rtol = atol,
 *  `cycles` cycles from stick at x = 0. Returns FRICREG_OK; FRICREG_EINTEGRATOR if CVODE fails
 *  or a slip does not end (msg, of msg_len bytes, says why); FRICREG_ENOMEM. */
int belt_cvode_run(int method, double rtol, int cycles, struct belt_cycle *out, char *msg,
                   size_t msg_len);

/** Event-driven CVODE reference of the 2-D oscillator (bench/disk_cvode.c), from rest at the
 *  origin. Returns FRICREG_OK; FRICREG_EINTEGRATOR if CVODE fails or the events cascade (msg
 *  says why); FRICREG_ENOMEM. */
int disk_cvode_run(int method, double rtol, struct disk_result *out, char *msg, size_t msg_len);
#endif

#endif
