/* SPDX-License-Identifier: GPL-3.0-or-later */
/* bench.h — shared pieces of the benchmarks (bench/): the problems, one timed run, CPU time.
 *
 * Not part of the library: the benchmark programs include this header, the library never
 * does. Every run is timed with the process CPU clock and repeated in one process; the
 * median is reported. */
#ifndef FRICREG_BENCH_H
#define FRICREG_BENCH_H

#include <stddef.h>
#include <stdio.h>

#include <fricreg.h>
#include <fricreg_sim.h>

/* ---- Problems -------------------------------------------------------------------------- */

/** One benchmark problem: a reference system of fricreg_sim.h with its parameters, and the
 *  cycle whose dissipation D is compared with a reference. */
struct bench_problem {
    const char *key;     /* short name used in file names and the CSV: "osc_stick" … */
    const char *title;   /* one line for tables and plots */
    int system;          /* enum fricreg_system */
    double a, omega;     /* forcing (oscillator, chain); the two blocks keep the paper's */
    size_t n;            /* chain length; 0 otherwise */
    int cycle;           /* D is measured on this cycle (1-based): 50 oscillator, 4 others */
    double adaptive_eps; /* eps of law (4) for the adaptive steppers (fixed, not 2 dt) */
    int event_driven;    /* 1 if the CVODE classical baseline handles it (uncoupled W = I) */
};

enum { BENCH_NPROBLEMS = 4 };

/** The four problems of the benchmark, in report order: oscillator with sustained sticking
 *  (a = 2, omega = 0.5), oscillator without (a = 3, omega = 1.5), the chain (n = 32,
 *  a = 0.25, omega = 0.5), the two blocks on a belt. */
extern const struct bench_problem bench_problems[BENCH_NPROBLEMS];

/* ---- One run and its measurements ----------------------------------------------------- */

/** What one run produced. status is a fricreg_status (FRICREG_OK on success). */
struct bench_run {
    int status;
    double D;         /* dissipation on the problem's measured cycle */
    double steps;     /* accepted steps */
    double rhs_evals; /* right-hand-side evaluations (Jacobian columns included) */
    double events;    /* mode switches (event-driven only), else 0 */
    double D_error;   /* extrapolated runs: the estimate of D's error (absolute), else 0 */
    int flagged;      /* extrapolated runs: D's levels showed no clean order */
    char msg[256];    /* why it failed, if it did */
};

/** A run to be timed: fills *out, returns out->status. */
typedef int (*bench_fn)(const void *arg, struct bench_run *out);

/** Process CPU time in seconds (clock_gettime(CLOCK_PROCESS_CPUTIME_ID)). */
double bench_cpu_seconds(void);

/** Median of x[n] (n >= 1); sorts x in place. */
double bench_median(double x[], size_t n);

/** Runs fn(arg) once into *out and returns the CPU seconds it took. Callers repeat it and
 *  take the median; interleaving the repeats of different points (whole sweeps run again)
 *  keeps a burst of load on a shared machine from spoiling every repeat of one point. */
double bench_time_once(bench_fn fn, const void *arg, struct bench_run *out);

/* ---- fricreg_sim runs ------------------------------------------------------------------- */

/** One fricreg_sim run of a problem: law (enum fricreg_law) with eps (0: the paper's rule,
 *  2 dt or 10 omega dt), integrator (enum fricreg_integrator) with fixed step dt if rtol is 0,
 *  else adaptive with rtol = atol and first step dt. */
struct bench_sim_point {
    const struct bench_problem *problem;
    int law, integrator;
    double dt, rtol, eps;
    int partition; /* enum fricreg_partition; 0: the library's default (consistent) */
    int levels;    /* >= 2: fricreg_sim_run_extrapolated with that many levels (eps, eps/2, …),
                    * D its extrapolation and rhs_evals those of every level; else a plain run */
    int order;     /* extrapolated runs: the declared leading order in eps (0: 1), used where
                    * the levels cannot show one (2 levels) */
    int window;    /* extrapolated runs: > 0: the finer levels run only the last `window`
                    * cycles from level 0's state (fricreg_sim_run_extrapolated_window) */
    int no_kink_location; /* adaptive runs: 1 turns the drivers' kink location off
                           * (fricreg_sim_set_kink_location); 0: the library's default, on */
};

/** The forcing period of a problem, as the library reports it (FRICREG_VALUE_PERIOD): the one
 *  home of 2 pi / omega. NaN if the simulation cannot be made. */
double bench_period(const struct bench_problem *p);

/** bench_fn for a struct bench_sim_point: runs problem->cycle cycles and reads D. */
int bench_sim_run(const void *point, struct bench_run *out);

/** Relative error |D - ref| / |ref|. */
double bench_rel_error(double D, double ref);

/** Opens dir/name for writing; on failure says so on stderr, naming program, and returns
 *  NULL. */
FILE *bench_open_out(const char *program, const char *dir, const char *name);

#endif
