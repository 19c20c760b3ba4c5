/* SPDX-License-Identifier: GPL-3.0-or-later */
/* problems_wp.c — fricreg-bench-problems OUTDIR: work-precision on the three reference
 * problems beyond the paper (src/problems/problems.h), in one process.
 *
 *   belt  the belt-driven Stribeck oscillator: the limit cycle's period and amplitude; error =
 *         the larger of their two relative errors;
 *   disk  the 2-D oscillator with rotating forcing: D per forcing cycle, relative error;
 *   hold  a block on an incline, load inside the friction disk: creep over 1e6 steps and the
 *         CPU seconds per 1e6 steps (no error to trade: the exact answer is 0).
 * Methods: fricreg's laws under GSL's fixed-step RK4 over a sweep of dt, run by the problems'
 * own code (prob_belt_regularized, prob_disk_run, prob_hold_run): dt here is GSL's rk4 step,
 * two classical steps of dt/2, and eps = 2 dt, the paper's rule (the hold: 20 dt); the 2-D
 * classical sliding law FRICREG_DISK_COULOMB the same way; and the event-driven CVODE
 * references (belt_cvode.c, disk_cvode.c; Adams and BDF) over rtol = 1e-3 … 1e-11. The
 * reference of each problem is CVODE Adams at rtol REF_RTOL; its convergence (rtol 1e-6 …
 * 1e-12, both methods) and its distance to the references of fricreg-bench-stribeck-belt and
 * fricreg-bench-disk, computed here as those programs compute them, are printed first. Every
 * point's CPU time is the median of PASSES interleaved passes over the whole sweep (a burst of
 * load spoils one repeat of many points, not every repeat of one). Writes to OUTDIR:
 *   problems_wp.csv    one row per point
 *   problems_refs.csv  the references' convergence
 *   problems_best.csv  per problem and target 1e-2 … 1e-8: each method's CPU seconds, the winner
 *   problems_hold.csv  the hold: creep and CPU per 1e6 steps per 2-D law
 *   problems_wp_<problem>.dat and problems_wp.gp  gnuplot data and script: problems_wp_belt.png,
 *                      problems_wp_disk.png
 * Without SUNDIALS only the hold runs (the other two have no reference). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include <gsl/gsl_errno.h>

#include "fricreg_disk.h"

#include "bench.h"
#include "problems.h"
#ifdef FRICREG_BENCH_CVODE
#include "event_driven.h"
#include "problems_cvode.h"
#endif

enum { PASSES = 3, MAXPTS = 12, NTARGETS = 7, BELT_CYCLES = 6 };
#define REF_RTOL 1e-12
#define HOLD_DT 1e-4
#define HOLD_STEPS 1000000L

static FILE *open_out(const char *dir, const char *name)
{
    return bench_open_out("fricreg-bench-problems", dir, name);
}

/* The hold of problems.h at its fixed tilt (tan theta = 0.8 mu) under `law`, HOLD_STEPS GSL
 * steps of HOLD_DT (classical steps of HOLD_DT/2), eps = 20 HOLD_DT: *creep = |x(T) - x(0)|/T,
 * *largest_speed = max |v| after a step. */
static int hold_run(int law, double *creep, double *largest_speed)
{
    struct prob_hold p = prob_hold_defaults();
    struct prob_hold_result r;
    p.law = law, p.dt = 0.5 * HOLD_DT, p.eps = 20.0 * HOLD_DT, p.steps = 2.0 * HOLD_STEPS;
    int status = prob_hold_run(&p, NULL, NULL, &r);
    *creep = status == FRICREG_OK ? r.displacement / r.t : NAN;
    *largest_speed = status == FRICREG_OK ? r.creep : NAN;
    return status;
}

static void print_hold(const char *dir)
{
    static const int laws[] = {FRICREG_DISK_QUINN, FRICREG_DISK_QUINN_LENS,
                               FRICREG_DISK_QUINN_NESTED, FRICREG_DISK_FORCE_BALANCE,
                               FRICREG_DISK_COULOMB};
    enum { NL = sizeof laws / sizeof laws[0] };
    double cpu[NL][PASSES], creep[NL], vmax[NL];
    int status[NL];
    for (int pass = 0; pass < PASSES; pass++)
        for (int l = 0; l < NL; l++) {
            double t0 = bench_cpu_seconds();
            status[l] = hold_run(laws[l], &creep[l], &vmax[l]);
            cpu[l][pass] = bench_cpu_seconds() - t0;
        }
    printf("== The hold: a block on an incline, tan(theta) = 0.8 mu, from rest, %ld RK4 steps of "
           "%g s (eps = 20 dt) ==\n%-14s %-14s %-14s %s\n",
           HOLD_STEPS, HOLD_DT, "2-D law", "creep m/s", "max |v| m/s", "CPU s per 1e6 steps");
    FILE *f = open_out(dir, "problems_hold.csv");
    if (f)
        fprintf(f, "law,steps,dt,creep_m_per_s,max_speed_m_per_s,cpu_s_per_1e6_steps,status\n");
    for (int l = 0; l < NL; l++) {
        double per = bench_median(cpu[l], PASSES) * 1e6 / (double)HOLD_STEPS;
        printf("%-14s %-14.3e %-14.3e %.3f%s\n", fricreg_disk_law_name(laws[l]), creep[l], vmax[l],
               per, status[l] == FRICREG_OK ? "" : "  (failed)");
        if (f)
            fprintf(f, "%s,%ld,%g,%.6e,%.6e,%.6e,%d\n", fricreg_disk_law_name(laws[l]), HOLD_STEPS,
                    HOLD_DT, creep[l], vmax[l], per, status[l]);
    }
    if (f)
        fclose(f);
}

#ifdef FRICREG_BENCH_CVODE

/* ---- Series of points ---------------------------------------------------------------------- */

enum problem { P_BELT, P_DISK, NPROBLEMS };
/* The problems as src/problems defines them; the belt's cycle measured is the BELT_CYCLES-th
 * (every event-driven cycle after the first is the limit cycle). */
static struct prob_belt belt_problem;
static struct prob_disk disk_problem;

static void set_problems(void)
{
    belt_problem = prob_belt_defaults();
    belt_problem.cycles = BELT_CYCLES;
    disk_problem = prob_disk_defaults();
}
static const char *const problem_key[NPROBLEMS] = {"belt", "disk"};
static const char *const problem_title[NPROBLEMS] = {
    "belt-driven Stribeck oscillator: period and amplitude of the limit cycle",
    "2-D oscillator with rotating forcing: D per forcing cycle"};
enum kind { RK4, CVODE };

struct series {
    const char *name;
    enum problem problem;
    enum kind kind;
    int law;    /* RK4 on the disk: enum fricreg_disk_law */
    int method; /* CVODE: enum ed_method */
    int n;
    double param[MAXPTS];       /* dt (RK4) or rtol (CVODE) */
    double value[MAXPTS][2];    /* belt: period, amplitude; disk: D */
    double err[MAXPTS];         /* relative error against the reference */
    double cpu[MAXPTS][PASSES]; /* per pass; cpu_med the median */
    double cpu_med[MAXPTS], steps[MAXPTS];
    int status[MAXPTS];
    char msg[MAXPTS][160];
};

/* The series; the rest of each row is filled by set_sweeps and the runs. */
static struct series series[] = {
    {.name = "rk4/stribeck", .problem = P_BELT, .kind = RK4},
    {.name = "cvode-adams", .problem = P_BELT, .kind = CVODE, .method = ED_ADAMS},
    {.name = "cvode-bdf", .problem = P_BELT, .kind = CVODE, .method = ED_BDF},
    {.name = "rk4/quinn", .problem = P_DISK, .kind = RK4, .law = FRICREG_DISK_QUINN},
    {.name = "rk4/quinn-lens", .problem = P_DISK, .kind = RK4, .law = FRICREG_DISK_QUINN_LENS},
    {.name = "rk4/quinn-nested", .problem = P_DISK, .kind = RK4, .law = FRICREG_DISK_QUINN_NESTED},
    {.name = "rk4/coulomb", .problem = P_DISK, .kind = RK4, .law = FRICREG_DISK_COULOMB},
    {.name = "cvode-adams", .problem = P_DISK, .kind = CVODE, .method = ED_ADAMS},
    {.name = "cvode-bdf", .problem = P_DISK, .kind = CVODE, .method = ED_BDF},
};
enum { NSERIES = sizeof series / sizeof series[0] };

/* Steps per turn of the disk's coarsest RK4 point: dt = 28 pi / 1100 = 0.080. */
#define DISK_N0 1100L

/* The sweeps: RK4 dt halving from 0.02 (belt) or 0.08 (disk); CVODE rtol 1e-3 … 1e-11. */
static void set_sweeps(void)
{
    double turn = prob_disk_turn(&disk_problem);
    for (int is = 0; is < NSERIES; is++) {
        struct series *s = &series[is];
        if (s->kind == CVODE) {
            s->n = 9;
            for (int k = 0; k < s->n; k++)
                s->param[k] = pow(10.0, -3 - k);
        } else if (s->problem == P_BELT) {
            s->n = 11;
            for (int k = 0; k < s->n; k++)
                s->param[k] = 0.02 / (double)(1L << k);
        } else {
            s->n = 8;
            for (int k = 0; k < s->n; k++)
                s->param[k] = turn / (double)(DISK_N0 << k);
        }
    }
}

/* The belt under fricreg_stribeck_eval, GSL steps of dt, eps = 2 dt: the period between the
 * last two downward crossings of x = 0 and the amplitude over that cycle (prob_belt_regularized
 * at the level 0); *steps counts GSL steps. */
static int belt_rk4_run(double dt, double *value, double *steps)
{
    struct prob_belt p = belt_problem;
    struct prob_belt_cycle c = {NAN, NAN, NAN, NAN, 0.0, 0.0};
    p.dt = 0.5 * dt, p.eps = 2.0 * dt;
    int status = prob_belt_regularized(&p, 0.0, NULL, NULL, &c);
    value[0] = c.period, value[1] = c.amplitude, *steps = 0.5 * c.steps;
    return status;
}

/* The 2-D oscillator under fricreg_disk_eval(law), GSL steps of dt = one turn / n (so the turns'
 * boundaries are step ends), eps = 2 dt: D per forcing cycle (prob_disk_run). */
static int disk_rk4_run(int law, double dt, double *value, double *steps)
{
    struct prob_disk p = disk_problem;
    struct prob_disk_result r = {NAN, NAN, 0.0, 0.0};
    p.law = law, p.dt = 0.5 * dt, p.eps = 2.0 * dt;
    int status = prob_disk_run(&p, NULL, NULL, &r);
    value[0] = r.dissipation, value[1] = NAN, *steps = 0.5 * r.steps;
    return status;
}

/* One run of point k of series s; fills value, steps, status, msg. */
static void run_point(struct series *s, int k)
{
    if (s->kind == RK4) {
        s->status[k] = s->problem == P_BELT
                           ? belt_rk4_run(s->param[k], s->value[k], &s->steps[k])
                           : disk_rk4_run(s->law, s->param[k], s->value[k], &s->steps[k]);
    } else if (s->problem == P_BELT) {
        struct belt_cycle c;
        s->status[k] = belt_cvode_run(&belt_problem, s->method, s->param[k], &c, s->msg[k],
                                      sizeof s->msg[k]);
        s->value[k][0] = c.period, s->value[k][1] = c.amplitude, s->steps[k] = c.steps;
    } else {
        struct disk_result d;
        s->status[k] = disk_cvode_run(&disk_problem, s->method, s->param[k], &d, s->msg[k],
                                      sizeof s->msg[k]);
        s->value[k][0] = d.dissipation, s->value[k][1] = NAN, s->steps[k] = d.steps;
    }
}

/* ---- The references ---------------------------------------------------------------------- */

static double ref_value[NPROBLEMS][2];

static double rel(double x, double ref)
{
    return fabs(x - ref) / fabs(ref);
}

/* The references of the other benchmarks, computed as their programs compute them (src/problems'
 * defaults): fricreg-bench-stribeck-belt's event-driven RK4 reference (slips at 1e-5, their
 * ends on the Hermite interpolant; the 12th cycle) and fricreg-bench-disk's tiny-eps run
 * (quinn, classical dt = 1e-5, eps = 2e-5), and the CVODE references' distance to them. */
static void print_other_references(const struct belt_cycle *bref, const struct disk_result *dref)
{
    struct prob_belt belt = prob_belt_defaults();
    struct prob_belt_cycle c;
    if (prob_belt_reference(&belt, NULL, NULL, &c) == FRICREG_OK)
        printf("belt: against the event-driven RK4 reference of fricreg-bench-stribeck-belt "
               "(%.12f, %.12f): period %.2e, amplitude %.2e\n",
               c.period, c.amplitude, rel(bref->period, c.period),
               rel(bref->amplitude, c.amplitude));
    else
        printf("belt: the event-driven RK4 reference failed\n");
    struct prob_disk disk = prob_disk_defaults();
    struct prob_disk_result r;
    disk.law = FRICREG_DISK_QUINN, disk.dt = 1e-5, disk.eps = 2e-5;
    if (prob_disk_run(&disk, NULL, NULL, &r) == FRICREG_OK)
        printf("disk: against the tiny-eps reference of fricreg-bench-disk (quinn, dt = 1e-5, "
               "eps = 2e-5: %.12f): %.2e\n",
               r.dissipation, rel(dref->dissipation, r.dissipation));
    else
        printf("disk: the tiny-eps reference failed\n");
}

/* CVODE at rtol 1e-6 … 1e-12, both methods: the convergence of the references. */
static int print_references(const char *dir)
{
    FILE *f = open_out(dir, "problems_refs.csv");
    if (f)
        fprintf(f, "problem,method,rtol,value1,value2,steps,events,rel_diff_to_ref\n");
    struct belt_cycle bref;
    struct disk_result dref;
    char msg[200] = "";
    if (belt_cvode_run(&belt_problem, ED_ADAMS, REF_RTOL, &bref, msg, sizeof msg) != FRICREG_OK ||
        disk_cvode_run(&disk_problem, ED_ADAMS, REF_RTOL, &dref, msg, sizeof msg) != FRICREG_OK) {
        fprintf(stderr, "fricreg-bench-problems: the reference failed: %s\n", msg);
        return 1;
    }
    ref_value[P_BELT][0] = bref.period, ref_value[P_BELT][1] = bref.amplitude;
    ref_value[P_DISK][0] = dref.dissipation;
    printf("\n== The event-driven CVODE references, rtol = atol = 1e-6 … 1e-12 ==\n"
           "(the reference of the rows below: Adams at rtol %g; diff = relative difference to "
           "it)\n%-6s %-6s %-7s %-18s %-18s %-9s %-7s %s\n",
           REF_RTOL, "", "method", "rtol", "period / D", "amplitude", "steps", "events", "diff");
    for (int ip = 0; ip < NPROBLEMS; ip++)
        for (int m = ED_BDF; m <= ED_ADAMS; m++)
            for (int e = 6; e <= 12; e++) {
                double rtol = pow(10.0, -e), v[2] = {NAN, NAN}, steps = 0, events = 0;
                int st;
                if (ip == P_BELT) {
                    struct belt_cycle c;
                    st = belt_cvode_run(&belt_problem, m, rtol, &c, msg, sizeof msg);
                    v[0] = c.period, v[1] = c.amplitude, steps = c.steps, events = c.events;
                } else {
                    struct disk_result d;
                    st = disk_cvode_run(&disk_problem, m, rtol, &d, msg, sizeof msg);
                    v[0] = d.dissipation, steps = d.steps, events = d.events;
                }
                double diff = rel(v[0], ref_value[ip][0]);
                if (ip == P_BELT)
                    diff = fmax(diff, rel(v[1], ref_value[ip][1]));
                char second[32] = ""; /* the amplitude (belt only) */
                if (ip == P_BELT)
                    snprintf(second, sizeof second, "%.13f", v[1]);
                printf("%-6s %-7s %-7.0e %-18.13f %-18s %-9.0f %-7.0f %.2e%s\n", problem_key[ip],
                       m == ED_BDF ? "bdf" : "adams", rtol, v[0], second, steps, events, diff,
                       st == FRICREG_OK ? "" : "  (failed)");
                if (f)
                    fprintf(f, "%s,%s,%g,%.15g,%.15g,%.0f,%.0f,%.3e\n", problem_key[ip],
                            m == ED_BDF ? "bdf" : "adams", rtol, v[0], v[1], steps, events, diff);
            }
    print_other_references(&bref, &dref);
    if (f)
        fclose(f);
    return 0;
}

/* ---- The sweeps and their tables ----------------------------------------------------------- */

static void run_sweeps(void)
{
    for (int pass = 0; pass < PASSES; pass++)
        for (int is = 0; is < NSERIES; is++)
            for (int k = 0; k < series[is].n; k++) {
                double t0 = bench_cpu_seconds();
                run_point(&series[is], k);
                series[is].cpu[k][pass] = bench_cpu_seconds() - t0;
            }
    for (int is = 0; is < NSERIES; is++) {
        struct series *s = &series[is];
        for (int k = 0; k < s->n; k++) {
            s->cpu_med[k] = bench_median(s->cpu[k], PASSES);
            const double *r = ref_value[s->problem];
            s->err[k] = rel(s->value[k][0], r[0]);
            if (s->problem == P_BELT)
                s->err[k] = fmax(s->err[k], rel(s->value[k][1], r[1]));
            if (s->status[k] != FRICREG_OK || !isfinite(s->err[k]))
                s->err[k] = NAN;
        }
    }
}

static void print_points(const char *dir)
{
    FILE *f = open_out(dir, "problems_wp.csv");
    if (f)
        fprintf(f, "problem,method,param_name,param,value1,value2,rel_error,cpu_s,steps,status,"
                   "message\n");
    for (int ip = 0; ip < NPROBLEMS; ip++) {
        printf("\n== %s ==\n(reference: CVODE Adams at rtol %g: %.13f", problem_title[ip], REF_RTOL,
               ref_value[ip][0]);
        if (ip == P_BELT)
            printf(", %.13f", ref_value[ip][1]);
        printf(")\n%-18s %-10s %-18s %-18s %-10s %-10s %s\n", "method", "dt / rtol",
               ip == P_BELT ? "period" : "D/cycle", ip == P_BELT ? "amplitude" : "", "rel.err",
               "CPU s", "steps");
        for (int is = 0; is < NSERIES; is++) {
            const struct series *s = &series[is];
            if (s->problem != (enum problem)ip)
                continue;
            for (int k = 0; k < s->n; k++) {
                char second[32] = ""; /* the amplitude (belt only) */
                if (ip == P_BELT)
                    snprintf(second, sizeof second, "%.13f", s->value[k][1]);
                printf("%-18s %-10.3g %-18.13f %-18s %-10.2e %-10.3g %.0f%s\n", s->name,
                       s->param[k], s->value[k][0], second, s->err[k], s->cpu_med[k], s->steps[k],
                       s->status[k] == FRICREG_OK ? "" : "  (failed)");
                if (f)
                    fprintf(f, "%s,%s,%s,%g,%.15g,%.15g,%.6e,%.6e,%.0f,%d,\"%s\"\n",
                            problem_key[ip], s->name, s->kind == RK4 ? "dt" : "rtol", s->param[k],
                            s->value[k][0], s->value[k][1], s->err[k], s->cpu_med[k], s->steps[k],
                            s->status[k], s->status[k] == FRICREG_OK ? "" : s->msg[k]);
            }
        }
    }
    if (f)
        fclose(f);
}

/* The cheapest point of a series from which every finer point stays below the target (the
 * rule of fricreg-bench-wp); NaN if none. *bound: reached already at the coarsest point. */
static double time_to_reach(const struct series *s, double target, int *bound)
{
    double best = NAN;
    int k = s->n - 1;
    for (; k >= 0 && s->err[k] <= target; k--)
        best = isnan(best) ? s->cpu_med[k] : fmin(best, s->cpu_med[k]);
    *bound = !isnan(best) && k < 0;
    return best;
}

static void print_best(const char *dir)
{
    FILE *f = open_out(dir, "problems_best.csv");
    if (f)
        fprintf(f, "problem,target,winner,cpu_s");
    for (int is = 0; f && is < NSERIES; is++)
        fprintf(f, ",%s %s", problem_key[series[is].problem], series[is].name);
    if (f)
        fprintf(f, "\n");
    printf("\n== Who wins: CPU seconds to reach each target (the cheapest point from which every "
           "finer one stays below it;\n   '<=' reached at the coarsest point, '-' never within "
           "the sweep) ==\n");
    for (int ip = 0; ip < NPROBLEMS; ip++) {
        printf("%-6s %-7s %-18s", problem_key[ip], "target", "winner");
        for (int is = 0; is < NSERIES; is++)
            if (series[is].problem == (enum problem)ip)
                printf(" %-17s", series[is].name);
        printf("\n");
        for (int j = 0; j < NTARGETS; j++) {
            double target = pow(10.0, -2 - j), t_best = NAN;
            char cells[NSERIES][32];
            const char *winner = "none";
            for (int is = 0; is < NSERIES; is++) {
                int bound;
                double t = time_to_reach(&series[is], target, &bound);
                snprintf(cells[is], sizeof cells[is], isnan(t) ? "-" : "%s%.3g", bound ? "<=" : "",
                         t);
                if (series[is].problem == (enum problem)ip && !isnan(t) &&
                    (isnan(t_best) || t < t_best))
                    t_best = t, winner = series[is].name;
            }
            printf("%-6s %-7.0e %-18s", problem_key[ip], target, winner);
            for (int is = 0; is < NSERIES; is++)
                if (series[is].problem == (enum problem)ip)
                    printf(" %-17s", cells[is]);
            printf("\n");
            if (!f)
                continue;
            fprintf(f, "%s,%.0e,%s,%.3g", problem_key[ip], target, winner, t_best);
            for (int is = 0; is < NSERIES; is++)
                fprintf(f, ",%s", series[is].problem == (enum problem)ip ? cells[is] : "");
            fprintf(f, "\n");
        }
    }
    if (f)
        fclose(f);
}

static void write_plots(const char *dir)
{
    for (int ip = 0; ip < NPROBLEMS; ip++) {
        char name[64];
        snprintf(name, sizeof name, "problems_wp_%s.dat", problem_key[ip]);
        FILE *f = open_out(dir, name);
        if (!f)
            return;
        for (int is = 0; is < NSERIES; is++) {
            const struct series *s = &series[is];
            if (s->problem != (enum problem)ip)
                continue;
            fprintf(f, "# %s\n# param cpu_s rel_error\n", s->name);
            for (int k = 0; k < s->n; k++)
                if (!isnan(s->err[k])) /* an exact hit would be 0 on a log axis: floor it */
                    fprintf(f, "%g %.6e %.6e\n", s->param[k], s->cpu_med[k],
                            fmax(s->err[k], 1e-16));
            fprintf(f, "\n\n");
        }
        fclose(f);
    }
    FILE *f = open_out(dir, "problems_wp.gp");
    if (!f)
        return;
    fprintf(f, "# generated by fricreg-bench-problems; run in this folder: gnuplot problems_wp.gp\n"
               "set terminal pngcairo noenhanced size 1000,650\n"
               "set logscale xy; set grid; set key outside right\n"
               "set format x '%%.0e'; set format y '%%.0e'\n"
               "set xlabel 'CPU seconds (median)'\n");
    for (int ip = 0; ip < NPROBLEMS; ip++) {
        fprintf(f, "set output 'problems_wp_%s.png'\nset title \"work-precision\\n%s\"\n",
                problem_key[ip], problem_title[ip]);
        fprintf(f, "set ylabel 'relative error%s'\nplot ",
                ip == P_BELT ? " (the larger of period, amplitude)" : " in D");
        int block = 0;
        for (int is = 0; is < NSERIES; is++)
            if (series[is].problem == (enum problem)ip)
                fprintf(f, "%s'problems_wp_%s.dat' index %d using 2:3 with linespoints title '%s'",
                        block ? ", \\\n     " : "", problem_key[ip], block, series[is].name),
                    block++;
        fprintf(f, "\n");
    }
    fclose(f);
}
#endif /* FRICREG_BENCH_CVODE */

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : ".";
    gsl_set_error_handler_off(); /* a failed step is reported by its status, never aborts */
    print_hold(dir);
#ifdef FRICREG_BENCH_CVODE
    set_problems();
    if (print_references(dir) != 0)
        return 1;
    set_sweeps();
    run_sweeps();
    print_points(dir);
    print_best(dir);
    write_plots(dir);
    printf("\nwrote to %s/: problems_wp.csv, problems_refs.csv, problems_best.csv, "
           "problems_hold.csv, problems_wp_*.dat, "
           "problems_wp.gp\n",
           dir);
#else
    printf("\nbelt and disk: not run (their event-driven references need SUNDIALS CVODE: "
           "libsundials-dev)\nwrote to %s/: problems_hold.csv\n",
           dir);
#endif
    return 0;
}
