/* SPDX-License-Identifier: GPL-3.0-or-later */
/* problems.h — the reference problems beyond the paper, shared by `fricreg-sim`
 * (hold, belt, disk) and the benchmarks (bench/disk_laws.c, bench/stribeck_belt.c): one copy.
 * Internal, not installed; built on the public laws (fricreg_disk.h, fricreg_stribeck.h) and
 * GSL only. docs/laws2d.md states the problems and the numbers they give.
 *
 * Stepping: the paper's method, classical RK4 at a fixed step dt, by the library's RK4
 * (src/ode/rk4_classic.h), which takes two classical steps of dt a call on GSL's rk4 grid,
 * through gsl_odeiv2_step_apply with no step control: 8 right-hand sides a call of 2 dt.
 * Every run counts classical steps; observers see the state after each call (every 2 dt).
 *
 * Every function returns FRICREG_OK or a fricreg status: FRICREG_EINVAL for a parameter out of
 * range, FRICREG_ENOMEM, FRICREG_EINTEGRATOR when GSL fails, FRICREG_EDIVERGED when a run does
 * not reach what it measures (no break-away, no limit cycle) within its bound, or the law's own
 * status. Nothing prints. */
#ifndef FRICREG_PROBLEMS_H
#define FRICREG_PROBLEMS_H

#include <stddef.h>

/* An observer: called with t and the row `row[n]` (the columns the problem names); a nonzero
 * return stops the run, which then returns FRICREG_ENOMEM (the observers store rows). */
typedef int (*prob_observer)(void *user, double t, const double row[], size_t n);

/* ---- The 2-D oscillator with rotating forcing (docs/laws2d.md, "Comparison") -------------
 *     x'' + x = f + a sin(omega t) (cos(Omega t), sin(Omega t)),   Omega = omega/cycles_per_turn,
 *     f_eq = x - a sin(omega t) (cos Omega t, sin Omega t),  mu N = 1, from rest at the origin.
 * D is -integral f . x' dt per forcing cycle, averaged over one turn of the forcing direction
 * after `turns_transient` turns (exactly: the window's edges interpolated inside their steps). */
struct prob_disk {
    int law;             /* enum fricreg_disk_law */
    double a, omega;     /* forcing amplitude and frequency (> 0) */
    int cycles_per_turn; /* forcing cycles per turn of the direction (>= 1) */
    int turns_transient; /* turns before the measured one (>= 0) */
    double dt, eps;      /* classical RK4 step, the law's eps (> 0) */
};
/* The problem of docs/laws2d.md: law quinn, a = 2, omega = 0.5, 7 cycles a turn, 3 turns of
 * transient, dt = 0.01, eps = 2 dt. */
struct prob_disk prob_disk_defaults(void);
/* The length of one turn of the forcing direction, 2 pi cycles_per_turn / omega (time units). */
double prob_disk_turn(const struct prob_disk *p);
/* The forcing at time t: F[2] = a sin(omega t) (cos(Omega t), sin(Omega t)). */
void prob_disk_forcing(const struct prob_disk *p, double t, double F[2]);
#define PROB_DISK_COLUMNS 6 /* x1, x2, v1, v2, f1, f2 */
struct prob_disk_result {
    double dissipation; /* D per forcing cycle over the measured turn */
    double band;        /* fraction of the GSL steps ending in the measured turn with |v| < eps */
    double steps;       /* classical RK4 steps */
    double t;           /* time at the end */
};
/* Runs p; observe (may be NULL) sees every GSL step of the measured turn. */
int prob_disk_run(const struct prob_disk *p, prob_observer observe, void *user,
                  struct prob_disk_result *r);

/* ---- The hold test on an incline (docs/laws2d.md, "The hold test") -----------------------
 * A block of mass M on an incline tilted by theta(t) = theta0 + kappa t, loaded by gravity
 * along the direction phi of the incline's plane:
 *     M v' = F + f,  F = M g sin(theta) (cos phi, sin phi),  mun = mu M g cos(theta),
 *     f_eq = -F, a 2-D law (FRICREG_DISK_QUINN unless `law` says: its exact stick at v = 0
 *     holds the block), from rest at x = 0. */
struct prob_hold {
    int law;            /* enum fricreg_disk_law; 0: FRICREG_DISK_QUINN */
    double mass, g, mu; /* kg, m/s^2, friction coefficient (> 0) */
    double theta0, phi; /* rad: the tilt at t = 0 (in [0, pi/2)) and the load's direction */
    double kappa;       /* tilt rate, rad/s (>= 0); 0: a fixed tilt */
    double dt, eps;     /* s, m/s (> 0) */
    double steps;       /* classical steps at most (even, >= 2) */
};
/* The block of tests/law/test_hold.c: M = 2.385 kg, g = 9.81, mu = 0.5385, phi = 0.6180339887,
 * tan(theta0) = 0.8 mu (the load at 0.8 of the bound), kappa = 0, law quinn, dt = 1e-4,
 * eps = 2e-3, 1e5 steps. */
struct prob_hold prob_hold_defaults(void);
#define PROB_HOLD_COLUMNS 5 /* theta (rad), x1, x2, v1, v2 */
struct prob_hold_result {
    double creep;        /* kappa = 0: the largest |v| after a step over the run, m/s */
    double displacement; /* |x| at the end, m */
    int broke_away;      /* the block left rest (kappa > 0: the run stops a second later) */
    double theta_rest;   /* the tilt at the start of the GSL step that left rest, rad */
    double theta_moving; /* the tilt at its end (theta_rest + 2 kappa dt), rad */
    double steps, t;
};
/* Runs p; observe (may be NULL) sees every GSL step. With kappa > 0 the run stops one second
 * after the break-away (or at p->steps). */
int prob_hold_run(const struct prob_hold *p, prob_observer observe, void *user,
                  struct prob_hold_result *r);

/* ---- The belt-driven stick-slip oscillator with Stribeck friction ------------------------
 *     x'' + x = f(x' - V),  f_eq = x,  kinetic curve k(s) = fk + (fs - fk) exp(-(s/vs)^delta),
 * the belt moving at V > 0 (fricreg_stribeck.h). Its limit cycle's period and amplitude
 * (x_max - x_min)/2, on the `cycles`-th cycle. */
struct prob_belt {
    double fs, fk, vs, delta, v_belt;
    double dt, eps; /* the regularized run's classical RK4 step and eps */
    int cycles;     /* the cycle measured (>= 2) [12] */
    double ref_dt;  /* the reference's slip phases: classical RK4 step [1e-5] */
};
/* fs = 1, fk = 0.5, vs = 0.05, delta = 1, V = 0.2; dt = 0.01, eps = 2 dt; the 12th cycle; the
 * reference at 1e-5. */
struct prob_belt prob_belt_defaults(void);
/* The kinetic curve k(speed) = fk + (fs - fk) exp(-(speed/vs)^delta), speed >= 0
 * (fricreg_stribeck.h): the friction force's magnitude in slip. */
double prob_belt_kinetic(const struct prob_belt *p, double speed);
#define PROB_BELT_COLUMNS 3 /* x, x', f (the reference: f = NaN) */
struct prob_belt_cycle {
    double period, amplitude;
    double x_min, x_max;
    double steps, t; /* classical RK4 steps taken, time at the end */
};
/* The event-driven reference: stick phases exact (x = x0 + V t until x = fs), slip phases by
 * RK4 at ref_dt with their ends x' = V located inside a step by GSL's Brent solver on the
 * cubic Hermite interpolant of (x', x''); from stick at x = 0. observe (may be NULL) sees the
 * last cycle: each slip step, and the two ends of the stick phase. */
int prob_belt_reference(const struct prob_belt *p, prob_observer observe, void *user,
                        struct prob_belt_cycle *c);
/* The regularized law fricreg_stribeck_eval under RK4 at dt, eps, from (x, x') = (0, V): the
 * period between downward crossings of the level `level` (inside the cycle: the reference's
 * (x_min + x_max)/2), located by the Hermite interpolant, and the extremes of x over the
 * cycles-th cycle, located likewise. observe (may be NULL) sees that cycle's GSL steps. */
int prob_belt_regularized(const struct prob_belt *p, double level, prob_observer observe,
                          void *user, struct prob_belt_cycle *c);

#endif
