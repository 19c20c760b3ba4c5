/* SPDX-License-Identifier: GPL-3.0-or-later */
/* workprecision.c — fricreg-bench-wp OUTDIR: work against precision of every method on the
 * four problems (bench.h), in one process.
 *
 * For each problem: its reference D (reference.c) and the order of law (4)'s regularization
 * error in eps; then every method over its sweep, each point with its relative error in D,
 * steps, right-hand-side evaluations and the median CPU seconds of repeated runs. The repeats
 * are interleaved: the whole sweep runs again (PASSES times; slow points only MIN_PASSES
 * times), so a burst of load from other processes on a shared machine spoils one repeat of
 * many points rather than every repeat of one. Writes to OUTDIR:
 *   workprecision.csv    one row per point
 *   orders.csv           observed convergence order of each law (fixed-step RK4)
 *   summary.csv          CPU time each method needs to reach 1% and 0.01% error
 *   best.csv             per problem and target 1e-2 … 1e-8: fricreg's cheapest method and the
 *                        CPU ratio of event-driven CVODE (Adams, BDF) to it, each CVODE
 *                        method at its best: the cheapest of its configurations (rtol =
 *                        atol = 1e-2 … 1e-12; on the chain also atol = 1e-2 rtol) that
 *                        reaches the target, the same rule as fricreg's cheapest method
 *   wp_<problem>.dat     the points, one block per method, for gnuplot
 *   workprecision.gp     the gnuplot script: wp_<problem>.png and conv_<problem>.png
 * and prints the references, the tables and the summary. With PROBLEM keys after OUTDIR
 * (osc_stick, osc_slip, chain, twoblock) only those problems run. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"
#include "reference.h"
#ifdef FRICREG_BENCH_CVODE
#include "event_driven.h"
#endif

/* ---- Methods and sweeps ---------------------------------------------------------------- */

enum kind { FIXED, ADAPTIVE, EVENT };

/* The event-driven methods' ids without CVODE built (no EVENT method is then listed). */
#ifdef FRICREG_BENCH_CVODE
#define ED_ADAMS_ID ED_ADAMS
#define ED_BDF_ID ED_BDF
#else
#define ED_ADAMS_ID 2
#define ED_BDF_ID 1
#endif

/* Where an adaptive law run takes its eps from (method_eps). */
enum eps_choice {
    EPS_PROBLEM,     /* the problem's adaptive_eps, or extrap_eps when extrapolated */
    EPS_TINY,        /* tiny_eps: problems whose motion never sticks */
    EPS_DECLARED,    /* extrap2_eps, extrapolated with the leading order declared */
    EPS_WINDOW,      /* as EPS_DECLARED, the finer level over the last window_cycles only */
    EPS_TWICE_PAPER, /* fixed steps: twice the paper's rule (4 dt; the chain 20 omega dt), since
                      * central differences' stick-zone bound dt*lambda < 0.9 refuses eps = 2 dt
                      * wherever mun W_ii >= 0.9 (fricreg_sim.h) */
    EPS_WINDOW_TWICE_PAPER, /* as EPS_WINDOW, at EPS_TWICE_PAPER's eps (central differences) */
};

struct method {
    const char *name; /* CSV and plot name */
    enum kind kind;
    int law, integrator, ed_method;
    int partition; /* FRICREG_PARTITION_PAPER: coupled problems only; 0: the default */
    int levels;    /* >= 2: extrapolated in eps over that many levels (fricreg_sim.h) */
    enum eps_choice eps_choice;
    int atol_scaled; /* EVENT: atol = ed_atol_scale * rtol (problems where that is not 1) */
    int kinks_off;   /* ADAPTIVE: the drivers' kink location off (fricreg_sim_set_kink_location) */
};

static const struct method methods[] = {
    {"rk4/quinn(4)", FIXED, FRICREG_LAW_QUINN, FRICREG_INT_RK4, 0, 0, 0, EPS_PROBLEM, 0, 0},
    {"rk4/coulomb(1)", FIXED, FRICREG_LAW_COULOMB, FRICREG_INT_RK4, 0, 0, 0, EPS_PROBLEM, 0, 0},
    {"rk4/force-balance(2)", FIXED, FRICREG_LAW_FORCE_BALANCE, FRICREG_INT_RK4, 0, 0, 0,
     EPS_PROBLEM, 0, 0},
    {"rk4/karnopp", FIXED, FRICREG_LAW_KARNOPP, FRICREG_INT_RK4, 0, 0, 0, EPS_PROBLEM, 0, 0},
    {"rk4/velocity-limited(3)", FIXED, FRICREG_LAW_VELOCITY_LIMITED, FRICREG_INT_RK4, 0, 0, 0,
     EPS_PROBLEM, 0, 0},
    {"rk4/tanh", FIXED, FRICREG_LAW_TANH, FRICREG_INT_RK4, 0, 0, 0, EPS_PROBLEM, 0, 0},
    {"rkf45/quinn(4)", ADAPTIVE, FRICREG_LAW_QUINN, FRICREG_INT_RKF45, 0, 0, 0, EPS_PROBLEM, 0, 0},
    {"rk8pd/quinn(4)", ADAPTIVE, FRICREG_LAW_QUINN, FRICREG_INT_RK8PD, 0, 0, 0, EPS_PROBLEM, 0, 0},
    {"msbdf/quinn(4)", ADAPTIVE, FRICREG_LAW_QUINN, FRICREG_INT_MSBDF, 0, 0, 0, EPS_PROBLEM, 0, 0},
    /* The paper's partition of coupled contacts beside the default consistent law (the rows
     * above), where they differ: the two blocks. */
    {"rk4/quinn(4)/paper", FIXED, FRICREG_LAW_QUINN, FRICREG_INT_RK4, 0, FRICREG_PARTITION_PAPER, 0,
     EPS_PROBLEM, 0, 0},
    {"rkf45/quinn(4)/paper", ADAPTIVE, FRICREG_LAW_QUINN, FRICREG_INT_RKF45, 0,
     FRICREG_PARTITION_PAPER, 0, EPS_PROBLEM, 0, 0},
    {"msbdf/quinn(4)/paper", ADAPTIVE, FRICREG_LAW_QUINN, FRICREG_INT_MSBDF, 0,
     FRICREG_PARTITION_PAPER, 0, EPS_PROBLEM, 0, 0},
    /* Extrapolation in eps (fricreg_sim_run_extrapolated): fixed RK4 under the paper's rule
     * (dt halves with eps), and adaptive steppers from extrap_eps (below) down. */
    {"rk4/quinn(4)/extrap3", FIXED, FRICREG_LAW_QUINN, FRICREG_INT_RK4, 0, 0, 3, EPS_PROBLEM, 0, 0},
    {"rk8pd/quinn(4)/extrap3", ADAPTIVE, FRICREG_LAW_QUINN, FRICREG_INT_RK8PD, 0, 0, 3, EPS_PROBLEM,
     0, 0},
    {"rk8pd/quinn(4)/extrap4", ADAPTIVE, FRICREG_LAW_QUINN, FRICREG_INT_RK8PD, 0, 0, 4, EPS_PROBLEM,
     0, 0},
    {"msbdf/quinn(4)/extrap3", ADAPTIVE, FRICREG_LAW_QUINN, FRICREG_INT_MSBDF, 0, 0, 3, EPS_PROBLEM,
     0, 0},
    /* Two levels, the leading order declared from the motion (leading_order), and law (4) at
     * a tiny eps where the motion never sticks (tiny_eps): the cheap ways to 1e-5 … 1e-8. */
    {"rk4/quinn(4)/extrap2", FIXED, FRICREG_LAW_QUINN, FRICREG_INT_RK4, 0, 0, 2, EPS_DECLARED, 0,
     0},
    {"rk8pd/quinn(4)/extrap2", ADAPTIVE, FRICREG_LAW_QUINN, FRICREG_INT_RK8PD, 0, 0, 2,
     EPS_DECLARED, 0, 0},
    {"rk8pd/quinn(4)/tiny-eps", ADAPTIVE, FRICREG_LAW_QUINN, FRICREG_INT_RK8PD, 0, 0, 0, EPS_TINY,
     0, 0},
    /* Cash-Karp at the tiny eps, the band's edges located: on osc_slip D is 4.7e-7 off at
     * rtol 1e-3 (0.0013 s) and 7e-9 from rtol 1e-4 on, where rkf45 with location is still
     * 2e-5 off at 1e-5. Measured, not derived: the two (4, 5) pairs differ in their error
     * estimate and in the solution they carry on. */
    {"rkck/quinn(4)/tiny-eps", ADAPTIVE, FRICREG_LAW_QUINN, FRICREG_INT_RKCK, 0, 0, 0, EPS_TINY, 0,
     0},
    /* extrap2 with the finer level over the last cycles only, from level 0's state there
     * (fricreg_sim_run_extrapolated_window): where the motion forgets its start fast. */
    {"rk4/quinn(4)/extrap2-window", FIXED, FRICREG_LAW_QUINN, FRICREG_INT_RK4, 0, 0, 2, EPS_WINDOW,
     0, 0},
    {"rk8pd/quinn(4)/extrap2-window", ADAPTIVE, FRICREG_LAW_QUINN, FRICREG_INT_RK8PD, 0, 0, 2,
     EPS_WINDOW, 0, 0},
    /* The adaptive methods that are the cheapest at some target, with the drivers' kink
     * location off (fricreg_sim_set_kink_location(sim, 0)): each location costs 10-15 trial
     * steps, and where the steps are short against the kinks' spacing anyway (law (4)'s zone
     * held to tolerances well below eps) the error is as small without it, at 0.5-0.7x the
     * CPU (osc_slip, rkf45: 1e-3 at rtol 1e-4 in 0.41x; the chain, rk8pd extrap3: 3.4e-9 at
     * rtol 1e-9 in 0.53x). rkf45 at the tiny eps too: without location its steps no longer
     * stop at the band's edges, and 4th order reaches 1e-7 on osc_slip in half rk8pd's time. Location stays the library's default: where the steps are long
     * against the kinks (msbdf at small eps) it is what makes the answer right. */
    {"rkf45/quinn(4)/kinks-off", ADAPTIVE, FRICREG_LAW_QUINN, FRICREG_INT_RKF45, 0, 0, 0,
     EPS_PROBLEM, 0, 1},
    {"rk8pd/quinn(4)/extrap3/kinks-off", ADAPTIVE, FRICREG_LAW_QUINN, FRICREG_INT_RK8PD, 0, 0, 3,
     EPS_PROBLEM, 0, 1},
    {"rk8pd/quinn(4)/extrap2/kinks-off", ADAPTIVE, FRICREG_LAW_QUINN, FRICREG_INT_RK8PD, 0, 0, 2,
     EPS_DECLARED, 0, 1},
    {"rkf45/quinn(4)/tiny-eps/kinks-off", ADAPTIVE, FRICREG_LAW_QUINN, FRICREG_INT_RKF45, 0, 0, 0,
     EPS_TINY, 0, 1},
    {"rk8pd/quinn(4)/tiny-eps/kinks-off", ADAPTIVE, FRICREG_LAW_QUINN, FRICREG_INT_RK8PD, 0, 0, 0,
     EPS_TINY, 0, 1},
    {"rkck/quinn(4)/tiny-eps/kinks-off", ADAPTIVE, FRICREG_LAW_QUINN, FRICREG_INT_RKCK, 0, 0, 0,
     EPS_TINY, 0, 1},
    {"rk8pd/quinn(4)/extrap2-window/kinks-off", ADAPTIVE, FRICREG_LAW_QUINN, FRICREG_INT_RK8PD, 0,
     0, 2, EPS_WINDOW, 0, 1},
    /* explicit central differences, one friction evaluation per step (FRICREG_INT_CENTRAL) */
    {"central/quinn(4)", FIXED, FRICREG_LAW_QUINN, FRICREG_INT_CENTRAL, 0, 0, 0, EPS_TWICE_PAPER, 0,
     0},
    /* The same extrapolated in eps, dt halving with eps: central differences' error is even in
     * dt, and where every switch is a stick (the chain) law (4)'s is second order in eps, so
     * three or four levels remove both at once. On the chain from dt = 1e-3: 5.3e-8 in
     * 0.041 s with three levels, 7.3e-9 in 0.09 s with four, where RK4's extrap2 needs
     * dt = 5e-4 (0.095 s) for 2.8e-8. */
    {"central/quinn(4)/extrap3", FIXED, FRICREG_LAW_QUINN, FRICREG_INT_CENTRAL, 0, 0, 3,
     EPS_TWICE_PAPER, 0, 0},
    {"central/quinn(4)/extrap4", FIXED, FRICREG_LAW_QUINN, FRICREG_INT_CENTRAL, 0, 0, 4,
     EPS_TWICE_PAPER, 0, 0},
    /* extrap2-window (below window_cycles) with central steps: on osc_stick 1.2e-8 from
     * dt = 0.02 in 0.0021 s, where RK4's needs 0.0043 s for 7.2e-8. */
    {"central/quinn(4)/extrap2-window", FIXED, FRICREG_LAW_QUINN, FRICREG_INT_CENTRAL, 0, 0, 2,
     EPS_WINDOW_TWICE_PAPER, 0, 0},
#ifdef FRICREG_BENCH_CVODE
    {"cvode-bdf/event-driven", EVENT, 0, 0, ED_BDF, 0, 0, EPS_PROBLEM, 0, 0},
    {"cvode-adams/event-driven", EVENT, 0, 0, ED_ADAMS, 0, 0, EPS_PROBLEM, 0, 0},
    /* The same with atol scaled to the problem's magnitudes (ed_atol_scale). */
    {"cvode-bdf/event-driven/atol-scaled", EVENT, 0, 0, ED_BDF, 0, 0, EPS_PROBLEM, 1, 0},
    {"cvode-adams/event-driven/atol-scaled", EVENT, 0, 0, ED_ADAMS, 0, 0, EPS_PROBLEM, 1, 0},
#endif
};
enum { NMETHODS = sizeof methods / sizeof methods[0], NSWEEP = 10, NSWEEP_EVENT = 11 };

/* Fixed steps (eps by the paper's rule) and tolerances (rtol = atol), coarse to fine. The
 * event-driven baseline sweeps one tolerance further, to 1e-12, so that it is at its best
 * wherever a tighter tolerance still buys accuracy; fricreg's adaptive runs stop at 1e-11. */
static const double dts[NSWEEP] = {0.1, 0.05, 0.02, 0.01, 0.005, 0.002, 0.001, 5e-4, 2e-4, 1e-4};
static const double tols[NSWEEP_EVENT] = {1e-2, 1e-3, 1e-4,  1e-5,  1e-6, 1e-7,
                                          1e-8, 1e-9, 1e-10, 1e-11, 1e-12};

/* CVODE's atol relative to its rtol in the atol-scaled runs, per problem (bench_problems
 * order; 1: not run). The chain's displacements and velocities are of order 1e-2 (its D on a
 * cycle is 4 against the oscillators' 50), so atol = rtol lets CVODE's error test ignore
 * their digits; atol = 1e-2 rtol weighs them as the oscillators' are weighed. */
static const double ed_atol_scale[BENCH_NPROBLEMS] = {1.0, 1.0, 1e-2, 1.0};
#define ADAPTIVE_DT0 1e-4 /* first step of the adaptive steppers */

/* The ranges for the observed order: the finest points, dt <= 1e-3 (asymptotic), and
 * dt <= 0.02 (whole: 0.05 and 0.1 are unstable for the chain). */
#define ORDER_FIRST 6
#define ORDER_WHOLE 2

/* Target relative errors: 1e-2 … 1e-8 for the table against CVODE (print_best); summary.csv
 * keeps 1% and 0.01% (TARGET_1PCT, TARGET_001PCT). */
enum { NTARGETS = 7, TARGET_1PCT = 0, TARGET_001PCT = 2 };
static const double targets[NTARGETS] = {1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8};

/* The first eps of the adaptive extrapolated runs, per problem (bench_problems order): in the
 * asymptotic range of each, where the ratios of differences give a clean order (the chain is
 * not there at eps = 0.02: its levels then are flagged). */
static const double extrap_eps[BENCH_NPROBLEMS] = {0.04, 0.04, 0.005, 0.004};

/* Two levels cannot show the leading order p of law (4)'s error in eps, so extrap2 (fixed RK4
 * under the paper's rule from dts[k], or rk8pd from extrap2_eps) declares it from the motion (fricreg_sim.h, docs/benchmark.md): 2 where every switch is a stick
 * (osc_stick, chain), 1 where velocities reverse without one (osc_slip, twoblock). With the
 * order right, two levels remove the eps^p term and leave O(eps^(p+1)): on osc_stick,
 * -0.0093 eps^2 (relative) leaves about 2e-9 from eps = 0.025, 0.0125, where three levels
 * from 0.04 need a third run at eps = 0.01, the costliest, since an explicit stepper's steps
 * in a stick are bounded by the band's stiffness 2 mun/eps. */
static const int leading_order[BENCH_NPROBLEMS] = {2, 1, 2, 1};
static const double extrap2_eps[BENCH_NPROBLEMS] = {0.025, 0.04, 0.005, 0.004};

/* eps of the tiny-eps runs, only where the motion never sticks (0: not run). There law (4)'s
 * band is only crossed, in a time of order eps, so the cost hardly depends on eps (osc_slip,
 * rk8pd at rtol 1e-9: about 1e5 right-hand sides from eps = 1e-2 to 1e-8) while the error,
 * first order (0.075 eps relative), drops below every target: no extrapolation needed. Where
 * it sticks, the stick's stiffness 2 mun/eps makes the cost grow as 1/eps. */
static const double tiny_eps[BENCH_NPROBLEMS] = {0.0, 1e-8, 0.0, 0.0};

/* The window of the extrap2-window runs, in forcing cycles (0: not run). On osc_stick a finer
 * level started from level 0's state forgets the difference 4.9x a cycle (extrap2's D on
 * cycle 50 against the full levels: 1.2e-6 relative with a window of 2 cycles, 1.1e-8 with
 * 5, 2e-11 with 10), so D on cycle 50 costs the finer level 10/50 of its whole run. osc_slip
 * forgets too slowly (10 cycles: D moved by 2.4e-5); the chain and the two blocks measure
 * cycle 4. */
static const int window_cycles[BENCH_NPROBLEMS] = {10, 0, 0, 0};

enum { PASSES = 5, MIN_PASSES = 3 };
#define SLOW_POINT 0.25 /* CPU seconds of a first run above which a point gets MIN_PASSES */

struct point {
    int ok;       /* the run succeeded */
    double param; /* dt or tolerance */
    double eps;   /* eps used (fixed-step and adaptive law runs) */
    double err;   /* relative error in D */
    double t[PASSES];
    int nt;               /* runs timed */
    int nondeterministic; /* a repeat gave another D */
    double cpu;           /* median of t */
    struct bench_run run; /* the first run's results */
};

static struct point results[BENCH_NPROBLEMS][NMETHODS][NSWEEP_EVENT];
static struct bench_reference refs[BENCH_NPROBLEMS];
static int
    selected[BENCH_NPROBLEMS]; /* the problems run: all, or those named on the command line */

/* Whether method m runs its finer levels over the last window_cycles only. */
static int has_window(const struct method *m)
{
    return m->eps_choice == EPS_WINDOW || m->eps_choice == EPS_WINDOW_TWICE_PAPER;
}

/* Whether method m declares the leading order (leading_order): its two levels cannot show it. */
static int declares_order(const struct method *m)
{
    return m->eps_choice == EPS_DECLARED || has_window(m);
}

static int applies(const struct method *m, const struct bench_problem *p)
{
    if (!selected[p - bench_problems])
        return 0;
    if (m->partition && p->system != FRICREG_SYSTEM_TWOBLOCK)
        return 0; /* uncoupled contacts: both partitions are law (4) */
    if (m->eps_choice == EPS_TINY && tiny_eps[p - bench_problems] == 0.0)
        return 0;
    if (has_window(m) && window_cycles[p - bench_problems] == 0)
        return 0;
    if (m->atol_scaled && ed_atol_scale[p - bench_problems] == 1.0)
        return 0;
    return m->kind != EVENT || p->event_driven;
}

/* The points of method m's sweep: dts or tols. */
static int sweep_len(const struct method *m)
{
    return m->kind == EVENT ? NSWEEP_EVENT : NSWEEP;
}

/* The eps a law run of method m sets at sweep point k (0: the paper's rule, fixed steps). */
static double paper_eps(const struct bench_problem *p, double dt)
{
    return p->system == FRICREG_SYSTEM_CHAIN ? 10.0 * p->omega * dt : 2.0 * dt;
}

static double method_eps(const struct method *m, const struct bench_problem *p, int k)
{
    if (m->kind == FIXED)
        return m->eps_choice == EPS_TWICE_PAPER || m->eps_choice == EPS_WINDOW_TWICE_PAPER
                   ? 2.0 * paper_eps(p, dts[k])
                   : 0.0;
    switch (m->eps_choice) {
    case EPS_TINY: return tiny_eps[p - bench_problems];
    case EPS_DECLARED:
    case EPS_WINDOW: return extrap2_eps[p - bench_problems];
    default: return m->levels >= 2 ? extrap_eps[p - bench_problems] : p->adaptive_eps;
    }
}

/* Runs one point of one method on one problem once, in pass `pass`. */
static void run_point(const struct bench_problem *p, const struct method *m, int k,
                      struct point *pt, int pass)
{
    struct bench_run run;
    double t;
    if (m->kind == EVENT) {
#ifdef FRICREG_BENCH_CVODE
        double atol = m->atol_scaled ? ed_atol_scale[p - bench_problems] * tols[k] : tols[k];
        struct ed_point ep = {p, m->ed_method, tols[k], 0.0, atol};
        t = bench_time_once(ed_run, &ep, &run);
#else
        return;
#endif
    } else {
        struct bench_sim_point sp = {p,
                                     m->law,
                                     m->integrator,
                                     m->kind == FIXED ? dts[k] : ADAPTIVE_DT0,
                                     m->kind == FIXED ? 0.0 : tols[k],
                                     method_eps(m, p, k),
                                     m->partition,
                                     m->levels,
                                     declares_order(m) ? leading_order[p - bench_problems] : 0,
                                     has_window(m) ? window_cycles[p - bench_problems] : 0,
                                     m->kinks_off};
        t = bench_time_once(bench_sim_run, &sp, &run);
    }
    pt->t[pt->nt++] = t;
    if (pass > 0) {
        pt->nondeterministic |= pt->ok && !(run.D == pt->run.D);
        return;
    }
    pt->run = run;
    pt->param = m->kind == FIXED ? dts[k] : tols[k];
    pt->eps = m->kind == EVENT ? 0.0
              : m->kind == FIXED
                  ? (method_eps(m, p, k) > 0.0 ? method_eps(m, p, k) : paper_eps(p, dts[k]))
                  : method_eps(m, p, k);
    pt->ok = run.status == FRICREG_OK;
    pt->err = pt->ok ? bench_rel_error(run.D, refs[p - bench_problems].D) : NAN;
}

/* Whether pass `pass` runs this point: every pass for fast points, MIN_PASSES for slow ones,
 * only the first for a failed one. */
static int runs_in_pass(const struct point *pt, int pass)
{
    if (pass == 0)
        return 1;
    return pt->ok && (pass < MIN_PASSES || pt->t[0] < SLOW_POINT);
}

static const char *status_word(const struct point *pt)
{
    if (pt->ok)
        return "ok";
    switch (pt->run.status) {
    case FRICREG_ESTEP: return "unstable";
    case FRICREG_EDIVERGED: return "diverged";
    default: return "failed";
    }
}

/* ---- Derived numbers ------------------------------------------------------------------- */

/* CPU time from which the method stays below `target`: the cheapest successful point such
 * that every finer successful point of the sweep also reaches the target. NAN if none.
 * *bound is set when that holds from the first successful point on: the sweep starts too
 * fine to tell, and the time is an upper bound. */
static double time_to_reach(const struct point pts[], int npts, double target, int *bound, int *at)
{
    double best = NAN;
    int first_ok = 0, all = 1, k_best = -1;
    while (first_ok < npts && !pts[first_ok].ok)
        first_ok++;
    for (int k = npts - 1; k >= 0; k--) {
        if (!pts[k].ok)
            continue;
        if (!(pts[k].err <= target)) {
            all = 0;
            break;
        }
        if (isnan(best) || pts[k].cpu < best)
            best = pts[k].cpu, k_best = k;
    }
    *bound = !isnan(best) && all && first_ok < npts;
    if (at)
        *at = k_best;
    return best;
}

/* Least-squares slope of log(err) against log(dt) over the points k >= first whose error
 * is above the reference's floor; *used gets their number. */
static double observed_order(const struct point pts[NSWEEP], int first, double floor_err, int *used)
{
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int n = 0;
    for (int k = first; k < NSWEEP; k++) {
        if (!pts[k].ok || !(pts[k].err > floor_err))
            continue;
        double x = log(pts[k].param), y = log(pts[k].err);
        sx += x, sy += y, sxx += x * x, sxy += x * y;
        n++;
    }
    *used = n;
    return n >= 2 ? (n * sxy - sx * sy) / (n * sxx - sx * sx) : NAN;
}

/* The error floor below which a measured error is the reference's, not the method's. */
static double error_floor(int ip)
{
    return fmax(10.0 * refs[ip].uncertainty / fabs(refs[ip].D), 1e-13);
}

/* ---- Output ---------------------------------------------------------------------------- */

static FILE *open_out(const char *dir, const char *name)
{
    return bench_open_out("fricreg-bench-wp", dir, name);
}

static void write_csv(FILE *f)
{
    fprintf(f, "problem,method,kind,param_name,param,eps,status,D,D_ref,rel_error,cpu_s,"
               "cpu_min,cpu_max,repeats,steps,rhs_evals,events,message\n");
    for (int ip = 0; ip < BENCH_NPROBLEMS; ip++)
        for (int im = 0; im < NMETHODS; im++) {
            if (!applies(&methods[im], &bench_problems[ip]))
                continue;
            for (int k = 0; k < sweep_len(&methods[im]); k++) {
                const struct point *pt = &results[ip][im][k];
                const struct bench_run *r = &pt->run;
                double lo = INFINITY, hi = 0.0;
                for (int j = 0; j < pt->nt; j++)
                    lo = fmin(lo, pt->t[j]), hi = fmax(hi, pt->t[j]);
                fprintf(f,
                        "%s,%s,%s,%s,%g,%g,%s,%.15g,%.15g,%.6e,%.6e,%.6e,%.6e,%d,%.0f,%.0f,"
                        "%.0f,\"%s\"\n",
                        bench_problems[ip].key, methods[im].name,
                        methods[im].kind == FIXED      ? "fixed"
                        : methods[im].kind == ADAPTIVE ? "adaptive"
                                                       : "event",
                        methods[im].kind == FIXED ? "dt" : "tol", pt->param, pt->eps,
                        status_word(pt), r->D, refs[ip].D, pt->err, pt->cpu, lo, hi, pt->nt,
                        r->steps, r->rhs_evals, r->events, pt->ok ? "" : r->msg);
            }
        }
}

/* One data file per problem: a block per method (two blank lines apart), cpu and error. */
static void write_dat(const char *dir, int ip)
{
    char name[128];
    snprintf(name, sizeof name, "wp_%s.dat", bench_problems[ip].key);
    FILE *f = open_out(dir, name);
    if (f == NULL)
        return;
    for (int im = 0; im < NMETHODS; im++) {
        if (!applies(&methods[im], &bench_problems[ip]))
            continue;
        fprintf(f, "# %s\n# param cpu_s rel_error steps rhs_evals\n", methods[im].name);
        for (int k = 0; k < sweep_len(&methods[im]); k++) {
            const struct point *pt = &results[ip][im][k];
            if (pt->ok) /* an exact hit would be 0 on a log axis: floor it */
                fprintf(f, "%g %.6e %.6e %.0f %.0f\n", pt->param, pt->cpu, fmax(pt->err, 1e-16),
                        pt->run.steps, pt->run.rhs_evals);
        }
        fprintf(f, "\n\n");
    }
    fclose(f);
}

static void write_gnuplot(const char *dir)
{
    FILE *f = open_out(dir, "workprecision.gp");
    if (f == NULL)
        return;
    fprintf(f, "# generated by fricreg-bench-wp; run in this folder: gnuplot workprecision.gp\n"
               "set terminal pngcairo noenhanced size 1000,650\n"
               "set logscale xy; set grid; set key outside right\n"
               "set yrange [*:10] # an error above 1000%% is off the chart\n"
               "set format x '%%.0e'; set format y '%%.0e'\n");
    for (int ip = 0; ip < BENCH_NPROBLEMS; ip++) {
        const struct bench_problem *p = &bench_problems[ip];
        fprintf(f, "set output 'wp_%s.png'\nset title \"work-precision\\n%s\"\n", p->key, p->title);
        fprintf(f, "set xlabel 'CPU seconds (median)'; set ylabel 'relative error in D'\n");
        fprintf(f, "plot ");
        int block = 0, first = 1;
        for (int im = 0; im < NMETHODS; im++) {
            if (!applies(&methods[im], p))
                continue;
            fprintf(f, "%s'wp_%s.dat' index %d using 2:3 with linespoints title '%s'",
                    first ? "" : ", \\\n     ", p->key, block++, methods[im].name);
            first = 0;
        }
        fprintf(f, ", 1e-2 with lines dt 2 lc 'gray' notitle, 1e-4 with lines dt 2 lc 'gray' "
                   "notitle\n");
        fprintf(f,
                "set output 'conv_%s.png'\nset title \"convergence in dt (RK4, the paper's "
                "eps rules)\\n%s\"\n",
                p->key, p->title);
        fprintf(f, "set xlabel 'dt'; set ylabel 'relative error in D'\nplot ");
        first = 1;
        block = 0; /* the data file holds a block per applicable method only */
        for (int im = 0; im < NMETHODS; im++) {
            if (!applies(&methods[im], p))
                continue;
            if (methods[im].kind != FIXED) {
                block++;
                continue;
            }
            fprintf(f, "%s'wp_%s.dat' index %d using 1:3 with linespoints title '%s'",
                    first ? "" : ", \\\n     ", p->key, block++, methods[im].name);
            first = 0;
        }
        fprintf(f, ", 0.5*x with lines dt 3 lc 'black' title 'slope 1', "
                   "5*x**2 with lines dt 4 lc 'black' title 'slope 2'\n");
    }
    fclose(f);
}

static void fmt_time(char *buf, size_t len, double t, int bound)
{
    if (isnan(t))
        snprintf(buf, len, "-");
    else
        snprintf(buf, len, "%s%.3g", bound ? "<=" : "", t);
}

static void fmt_ratio(char *buf, size_t len, double t, int bound, double t_quinn, int q_bound)
{
    if (isnan(t) || isnan(t_quinn))
        snprintf(buf, len, "-");
    else
        snprintf(buf, len, "%s%.3g", bound || q_bound ? "~" : "", t / t_quinn);
}

static void print_summary(FILE *csv)
{
    printf("\n== Summary: CPU seconds to reach 1%% and 0.01%% relative error in D ==\n"
           "(the cheapest point from which every finer point of the sweep stays below the\n"
           "target; ratio = that time / the time of rk4/quinn(4) on the same problem;\n"
           "'-' = not reached within the sweep; '<=' = reached already at the coarsest point,\n"
           "so the time is an upper bound; '~' = a ratio involving such a bound)\n");
    fprintf(csv, "problem,method,cpu_1pct,ratio_1pct,cpu_001pct,ratio_001pct,best_error\n");
    for (int ip = 0; ip < BENCH_NPROBLEMS; ip++) {
        if (!selected[ip])
            continue;
        const struct bench_problem *p = &bench_problems[ip];
        static const int shown[2] = {TARGET_1PCT, TARGET_001PCT};
        double q[2];
        int q_bound[2];
        for (int j = 0; j < 2; j++)
            q[j] = time_to_reach(results[ip][0], NSWEEP, targets[shown[j]], &q_bound[j], NULL);
        printf("\n%s\n%-40s %10s %8s %10s %8s %10s\n", p->title, "method", "t(1%)", "ratio",
               "t(0.01%)", "ratio", "best err");
        for (int im = 0; im < NMETHODS; im++) {
            if (!applies(&methods[im], p))
                continue;
            double t[2], best = INFINITY;
            int bound[2];
            char s[4][32];
            for (int j = 0; j < 2; j++) {
                t[j] = time_to_reach(results[ip][im], sweep_len(&methods[im]), targets[shown[j]],
                                     &bound[j], NULL);
                fmt_time(s[2 * j], sizeof s[0], t[j], bound[j]);
                fmt_ratio(s[2 * j + 1], sizeof s[0], t[j], bound[j], q[j], q_bound[j]);
            }
            for (int k = 0; k < sweep_len(&methods[im]); k++)
                if (results[ip][im][k].ok)
                    best = fmin(best, results[ip][im][k].err);
            printf("%-40s %10s %8s %10s %8s %10.2e\n", methods[im].name, s[0], s[1], s[2], s[3],
                   best);
            fprintf(csv, "%s,%s,%s,%s,%s,%s,%.3e\n", p->key, methods[im].name, s[0], s[1], s[2],
                    s[3], best);
        }
        if (!p->event_driven)
            printf("(event-driven baseline: not run here; the contacts are coupled, so a mode "
                   "switch needs a complementarity solve)\n");
    }
}

/* The cheapest fricreg method (any law-(4) method: fixed, adaptive, extrapolated) to reach
 * `target` on problem ip; *best gets its index (-1 if none reaches it), *bound whether the
 * time is a bound, *at the sweep point (time_to_reach). */
static double best_fricreg(int ip, double target, int *best, int *bound, int *at)
{
    double t_best = NAN;
    *best = -1;
    *at = -1;
    *bound = 0;
    for (int im = 0; im < NMETHODS; im++) {
        const struct method *m = &methods[im];
        int b = 0, k = -1;
        if (m->kind == EVENT || m->law != FRICREG_LAW_QUINN || m->partition ||
            !applies(m, &bench_problems[ip]))
            continue; /* the paper's partition is another model than the reference's */
        double t = time_to_reach(results[ip][im], NSWEEP, target, &b, &k);
        if (!isnan(t) && (isnan(t_best) || t < t_best))
            t_best = t, *best = im, *bound = b, *at = k;
    }
    return t_best;
}

/* One CVODE cell: "time" and "ratio" (CVODE time / fricreg time: above 1, fricreg ahead), the
 * peer at its best: the cheapest of its configurations (tolerance sweeps, atol = rtol and,
 * where run, atol scaled) to reach the target; "config" says which ("-" if none). */
static void cvode_cell(int ip, int ed_method, double target, double t_best, int best_bound,
                       char *time, char *ratio, char *config, size_t len)
{
    double t_ed = NAN;
    int b_ed = 0, run = 0;
    snprintf(time, len, "n/a");
    snprintf(ratio, len, "n/a");
    snprintf(config, len, "n/a");
    for (int im = 0; im < NMETHODS; im++) {
        if (methods[im].kind != EVENT || methods[im].ed_method != ed_method ||
            !applies(&methods[im], &bench_problems[ip]))
            continue;
        int b = 0, k = -1;
        double t = time_to_reach(results[ip][im], NSWEEP_EVENT, target, &b, &k);
        if (!run++)
            snprintf(config, len, "-");
        if (isnan(t) || !(isnan(t_ed) || t < t_ed))
            continue;
        double scale = methods[im].atol_scaled ? ed_atol_scale[ip] : 1.0;
        t_ed = t, b_ed = b;
        snprintf(config, len, "rtol=%.0e atol=%.0e", tols[k], scale * tols[k]);
    }
    if (!run)
        return;
    fmt_time(time, len, t_ed, b_ed);
    if (isnan(t_best))
        snprintf(ratio, len, "-");
    else if (isnan(t_ed))
        snprintf(ratio, len, "never");
    else
        snprintf(ratio, len, "%s%.3g", b_ed || best_bound ? "~" : "", t_ed / t_best);
}

/* The work-precision table against the event-driven baseline: per problem and target error
 * 1e-2 … 1e-8, fricreg's cheapest method and the CPU ratio of CVODE Adams and BDF to it
 * (above 1: fricreg ahead). A target finer than 3x the reference's relative uncertainty is
 * not judged. Writes best.csv. (The time of each method is time_to_reach's, so a method whose
 * error is not yet monotone in its sweep parameter is taken from where it stays below.) */
static void print_best(FILE *csv)
{
    printf("\n== Against event-driven CVODE: fricreg's cheapest method per target ==\n"
           "(CPU seconds to reach the target and stay below it over the sweep; ratio = CVODE's\n"
           "time / fricreg's: above 1, fricreg is ahead; 'never': CVODE does not reach it in\n"
           "its sweep; '~': a time is a '<=' bound; each CVODE method at its best: the cheapest\n"
           "of its tolerances, and atol scalings where run, to reach the target, shown as\n"
           "rtol/atol)\n");
    printf("%-10s %7s %-40s %-8s %10s %10s %8s %10s %8s  %-15s %-15s\n", "problem", "target",
           "fricreg best", "at", "cpu", "adams", "ratio", "bdf", "ratio", "adams config",
           "bdf config");
    fprintf(csv, "problem,target,best_method,best_cpu,adams_cpu,adams_ratio,bdf_cpu,bdf_ratio,"
                 "best_param,adams_config,bdf_config\n");
    for (int ip = 0; ip < BENCH_NPROBLEMS; ip++) {
        if (!selected[ip])
            continue;
        double rel_unc = refs[ip].uncertainty / fabs(refs[ip].D);
        for (int j = 0; j < NTARGETS; j++) {
            char tb[32], ta[32], ra[32], td[32], rd[32], ca[32], cd[32], at[32] = "-";
            const char *name = "-";
            if (targets[j] < 3.0 * rel_unc) {
                printf("%-10s %7.0e (not judged: the reference is uncertain to %.1e)\n",
                       bench_problems[ip].key, targets[j], rel_unc);
                fprintf(csv, "%s,%.0e,not judged (reference %.1e),,,,,,,,\n",
                        bench_problems[ip].key, targets[j], rel_unc);
                continue;
            }
            int best, bound, k;
            double t = best_fricreg(ip, targets[j], &best, &bound, &k);
            fmt_time(tb, sizeof tb, t, bound);
            if (best >= 0) {
                name = methods[best].name;
                snprintf(at, sizeof at, "%s=%g", methods[best].kind == FIXED ? "dt" : "tol",
                         results[ip][best][k].param);
            }
            cvode_cell(ip, ED_ADAMS_ID, targets[j], t, bound, ta, ra, ca, sizeof ta);
            cvode_cell(ip, ED_BDF_ID, targets[j], t, bound, td, rd, cd, sizeof td);
            printf("%-10s %7.0e %-40s %-8s %10s %10s %8s %10s %8s  %-15s %-15s\n",
                   bench_problems[ip].key, targets[j], name, at, tb, ta, ra, td, rd, ca, cd);
            fprintf(csv, "%s,%.0e,%s,%s,%s,%s,%s,%s,%s,%s,%s\n", bench_problems[ip].key, targets[j],
                    name, tb, ta, ra, td, rd, at, ca, cd);
        }
    }
}

static void print_orders(FILE *csv, const double eps_orders[])
{
    printf("\n== Observed convergence order in dt (RK4, eps by the paper's rule) ==\n"
           "(least-squares slope of log error against log dt, points above 10x the reference's\n"
           "uncertainty: 'a | w' = asymptotic range dt = %g … %g | whole range %g … %g;\n"
           "the paper: 2 for (4), 1 for (1) and (3) with sticking (Fig. 7a), 2 for all\n"
           "without (Fig. 7b))\n",
           dts[ORDER_FIRST], dts[NSWEEP - 1], dts[ORDER_WHOLE], dts[NSWEEP - 1]);
    printf("%-40s", "method");
    for (int ip = 0; ip < BENCH_NPROBLEMS; ip++)
        printf(" %13s", bench_problems[ip].key);
    printf("\n");
    fprintf(csv, "problem,method,order_asymptotic,points,order_whole,points_whole,"
                 "err_dt_1e-3,err_dt_1e-4\n");
    for (int im = 0; im < NMETHODS; im++) {
        if (methods[im].kind != FIXED || methods[im].levels >= 2) /* order of dt alone */
            continue;
        printf("%-40s", methods[im].name);
        for (int ip = 0; ip < BENCH_NPROBLEMS; ip++) {
            int used, used_whole;
            const struct point *pts = results[ip][im];
            double order = observed_order(pts, ORDER_FIRST, error_floor(ip), &used);
            double whole = observed_order(pts, ORDER_WHOLE, error_floor(ip), &used_whole);
            char cell[32];
            snprintf(cell, sizeof cell, "%5.2f | %4.2f", order, whole);
            printf(" %13s", cell);
            fprintf(csv, "%s,%s,%.3f,%d,%.3f,%d,%.3e,%.3e\n", bench_problems[ip].key,
                    methods[im].name, order, used, whole, used_whole, pts[ORDER_FIRST].err,
                    pts[NSWEEP - 1].err);
        }
        printf("\n");
    }
    printf("%-40s", "quinn(4): order in eps");
    for (int ip = 0; ip < BENCH_NPROBLEMS; ip++)
        printf(" %13.2f", eps_orders[ip]);
    printf("\n(the last row: law (4) at fixed dt = 1e-4, eps = 3.2e-3 … 4e-4)\n"
           "Relative errors at dt = 1e-3 and 1e-4:\n");
    for (int im = 0; im < NMETHODS; im++) {
        if (methods[im].kind != FIXED || methods[im].levels >= 2)
            continue;
        printf("%-40s", methods[im].name);
        for (int ip = 0; ip < BENCH_NPROBLEMS; ip++)
            printf("  %8.1e %8.1e", results[ip][im][ORDER_FIRST].err,
                   results[ip][im][NSWEEP - 1].err);
        printf("\n");
    }
}

/* Points that did not run, with why. */
static void print_failures(void)
{
    int any = 0;
    for (int ip = 0; ip < BENCH_NPROBLEMS; ip++)
        for (int im = 0; im < NMETHODS; im++)
            for (int k = 0; k < sweep_len(&methods[im]); k++) {
                const struct point *pt = &results[ip][im][k];
                if (!applies(&methods[im], &bench_problems[ip]) || pt->ok)
                    continue;
                if (!any++)
                    printf("\n== Points without a result ==\n");
                printf("%-10s %-40s %s %-8g %-9s %s\n", bench_problems[ip].key, methods[im].name,
                       methods[im].kind == FIXED ? "dt " : "tol", pt->param, status_word(pt),
                       pt->run.msg);
            }
}

/* The regularization error of law (4) alone: RK4 at a fixed small step, eps from 32 dt down
 * to 4 dt. Its slope separates what eps costs from what dt costs (the paper's rule ties
 * them). Returns the least-squares slope of log|error| against log eps. */
static double eps_order(int ip)
{
    static const double eps[4] = {3.2e-3, 1.6e-3, 8e-4, 4e-4};
    const double dt = 1e-4;
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    printf("  law (4) error against eps at fixed dt = %g (RK4):", dt);
    for (int k = 0; k < 4; k++) {
        struct bench_sim_point sp = {&bench_problems[ip],
                                     FRICREG_LAW_QUINN,
                                     FRICREG_INT_RK4,
                                     dt,
                                     0.0,
                                     eps[k],
                                     0,
                                     0,
                                     0,
                                     0,
                                     0};
        struct bench_run run;
        if (bench_sim_run(&sp, &run) != FRICREG_OK) {
            printf(" eps %g failed: %s\n", eps[k], run.msg);
            return NAN;
        }
        double e = (run.D - refs[ip].D) / fabs(refs[ip].D);
        printf(" %+.2e", e);
        double x = log(eps[k]), y = log(fabs(e));
        sx += x, sy += y, sxx += x * x, sxy += x * y;
    }
    double slope = (4 * sxy - sx * sy) / (4 * sxx - sx * sx);
    printf(" at eps = %g … %g: order %.2f in eps\n", eps[0], eps[3], slope);
    return slope;
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: fricreg-bench-wp OUTDIR [PROBLEM...]\n");
        return 2;
    }
    for (int ip = 0; ip < BENCH_NPROBLEMS; ip++) { /* no PROBLEM: all */
        selected[ip] = argc == 2;
        for (int a = 2; a < argc; a++)
            selected[ip] |= strcmp(argv[a], bench_problems[ip].key) == 0;
    }
    const char *dir = argv[1];
    double t_start = bench_cpu_seconds(), eps_orders[BENCH_NPROBLEMS];
    printf("fricreg %s work-precision benchmark\n", fricreg_version());
#ifdef FRICREG_BENCH_CVODE
    printf("event-driven baseline: %s CVODE, classical Coulomb (1)+(2), root finding on the "
           "stick/slip switching functions\n",
           ed_version());
#else
    printf("event-driven baseline: not built (libsundials-dev not found, or "
           "FRICREG_BENCH_CVODE=OFF)\n");
#endif
    printf("fixed step: RK4, dt = %g … %g, eps by the paper's rule (2 dt; chain 10 omega dt)\n"
           "adaptive: law (4), rtol = atol = %g … %g, fixed eps per problem (below)\n"
           "CPU time: median of %d interleaved runs (%d for points slower than %g s)\n",
           dts[0], dts[NSWEEP - 1], tols[0], tols[NSWEEP - 1], PASSES, MIN_PASSES, SLOW_POINT);
    for (int ip = 0; ip < BENCH_NPROBLEMS; ip++) {
        const struct bench_problem *p = &bench_problems[ip];
        eps_orders[ip] = NAN;
        if (!selected[ip])
            continue;
        printf("\n== %s ==\n", p->title);
        if (bench_reference(p, &refs[ip], stdout) != FRICREG_OK) {
            fprintf(stderr, "fricreg-bench-wp: the reference of %s failed\n", p->key);
            return 1;
        }
        eps_orders[ip] = eps_order(ip);
        printf("  adaptive runs: eps = %g\n", p->adaptive_eps);
        fflush(stdout);
    }
    for (int pass = 0; pass < PASSES; pass++) {
        double t0 = bench_cpu_seconds();
        for (int ip = 0; ip < BENCH_NPROBLEMS; ip++)
            for (int im = 0; im < NMETHODS; im++)
                for (int k = 0; k < sweep_len(&methods[im]); k++) {
                    struct point *pt = &results[ip][im][k];
                    if (applies(&methods[im], &bench_problems[ip]) && runs_in_pass(pt, pass))
                        run_point(&bench_problems[ip], &methods[im], k, pt, pass);
                }
        fprintf(stderr, "fricreg-bench-wp: pass %d of %d: %.1f CPU s\n", pass + 1, PASSES,
                bench_cpu_seconds() - t0);
    }
    int nondeterministic = 0;
    for (int ip = 0; ip < BENCH_NPROBLEMS; ip++)
        for (int im = 0; im < NMETHODS; im++)
            for (int k = 0; k < NSWEEP_EVENT; k++) {
                struct point *pt = &results[ip][im][k];
                pt->cpu = pt->nt ? bench_median(pt->t, (size_t)pt->nt) : NAN;
                nondeterministic += pt->nondeterministic;
            }
    if (nondeterministic)
        printf("\nwarning: %d points gave a different D when repeated\n", nondeterministic);

    FILE *csv = open_out(dir, "workprecision.csv");
    FILE *orders = open_out(dir, "orders.csv");
    FILE *summary = open_out(dir, "summary.csv");
    FILE *best = open_out(dir, "best.csv");
    if (!csv || !orders || !summary || !best)
        return 1;
    write_csv(csv);
    fclose(csv);
    for (int ip = 0; ip < BENCH_NPROBLEMS; ip++)
        write_dat(dir, ip);
    write_gnuplot(dir);
    print_failures();
    print_orders(orders, eps_orders);
    print_summary(summary);
    print_best(best);
    fclose(orders);
    fclose(summary);
    fclose(best);
    printf("\nwork-precision benchmark: %.0f CPU seconds; files in %s: workprecision.csv, "
           "orders.csv, summary.csv, best.csv, wp_*.dat, workprecision.gp\n",
           bench_cpu_seconds() - t_start, dir);
    return 0;
}
