/* SPDX-License-Identifier: GPL-3.0-or-later */
/* scaling.c — fricreg-bench-scaling OUTDIR: how the cost grows with the number of contacts.
 *
 * 1. The chain of Sec. 3.2 for n = 32 … 10^6 blocks, laws (4) and (1), fixed-step RK4 with
 *    dt = 0.35/n (the highest spring mode has frequency 2n; the step guard asks for
 *    dt * 2n <= 1/sqrt(2), beyond which a friction reversal within one step can put energy in)
 *    and eps by the paper's rule, over 10 to 20000 steps from rest: CPU time per step per
 *    block. Linear cost means a flat line. From rest most blocks are near stick, so (4)
 *    computes f_eq for most contacts: its worst case.
 * 2. The laws alone: fricreg_law_eval_batch over m = 10^6 contacts (random inputs, fixed
 *    seed, a mix of stuck, near-stick and slipping contacts), ns per contact for every law;
 *    and fricreg_ctx_eval (the Sec. 3.3 partition with W = I) for (4) and (1). Again over
 *    the first 4096 contacts, which stay in cache.
 * Every number is the median of interleaved repeats. Writes scaling.csv, laws.csv and
 * scaling.gp (scaling.png) to OUTDIR and prints the tables. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "bench.h"

/* ---- 1. The chain against n ------------------------------------------------------------ */

static const size_t chain_n[] = {32, 100, 1000, 10000, 100000, 1000000};
enum { NN = sizeof chain_n / sizeof chain_n[0], REPEATS = 3 };
static const int chain_laws[2] = {FRICREG_LAW_QUINN, FRICREG_LAW_COULOMB};
static const char *const chain_law_names[2] = {"quinn(4)", "coulomb(1)"};

/* Steps per run: 4 10^6 block-steps, at most 20000 steps and at least 40 (n = 10^6: 4 10^7
 * block-steps, 1.6 10^8 contact evaluations). The run's set-up, a dozen arrays of n doubles
 * allocated and first touched, is timed with it: over 10 steps at n = 10^6 it added about
 * 2 ns to each right-hand side's 4.5 per block (6.7 against 4.5 over 100 steps). Even
 * counts: the driver advances two classical steps at a time (GSL's rk4 grid). */
static int chain_steps(size_t n)
{
    double steps = fmax(40.0, fmin(20000.0, 4e6 / (double)n));
    return 2 * (int)(steps / 2.0);
}

#define CHAIN_DT_N 0.35 /* dt n: dt 2n = 0.7, within the drivers' reversal bound 1/sqrt 2 */

/* One timed run: CPU seconds of fricreg_sim_run alone; *steps gets the steps taken, *rhs the
 * right-hand sides evaluated. */
static double chain_run(size_t n, int law, double *steps, double *rhs)
{
    fricreg_sim *sim = NULL;
    double dt = CHAIN_DT_N / (double)n, t = NAN;
    int status = fricreg_sim_create(FRICREG_SYSTEM_CHAIN, &sim);
    if (status == FRICREG_OK)
        status = fricreg_sim_set_param(sim, FRICREG_PARAM_N, (double)n);
    if (status == FRICREG_OK)
        status = fricreg_sim_set_law(sim, law, 0.0);
    if (status == FRICREG_OK)
        status = fricreg_sim_set_integrator(sim, FRICREG_INT_RK4, dt, 0.0, 0.0);
    if (status == FRICREG_OK) {
        double t0 = bench_cpu_seconds();
        status = fricreg_sim_run(sim, chain_steps(n) * dt);
        t = bench_cpu_seconds() - t0;
    }
    if (status == FRICREG_OK)
        fricreg_sim_get_value(sim, FRICREG_VALUE_STEPS, steps),
            fricreg_sim_get_value(sim, FRICREG_VALUE_RHS_EVALS, rhs);
    else
        fprintf(stderr, "fricreg-bench-scaling: chain n = %zu: %s\n", n,
                sim ? fricreg_sim_errmsg(sim) : fricreg_strerror(status));
    fricreg_sim_free(sim);
    return status == FRICREG_OK ? t : NAN;
}

/* ns per step per block, [law][n]; right-hand sides per step. */
static double chain_ns[2][NN], chain_steps_done[NN], chain_rhs_per_step[NN];

static void chain_scaling(void)
{
    double t[2][NN][REPEATS];
    for (int r = 0; r < REPEATS; r++)
        for (int i = 0; i < NN; i++)
            for (int l = 0; l < 2; l++)
                t[l][i][r] = chain_run(chain_n[i], chain_laws[l], &chain_steps_done[i],
                                       &chain_rhs_per_step[i]);
    for (int i = 0; i < NN; i++)
        chain_rhs_per_step[i] /= chain_steps_done[i];
    for (int l = 0; l < 2; l++)
        for (int i = 0; i < NN; i++)
            chain_ns[l][i] = 1e9 * bench_median(t[l][i], REPEATS) /
                             (chain_steps_done[i] * (double)chain_n[i]);
}

/* ---- 2. The laws alone ------------------------------------------------------------------ */

enum { M = 1000000, LAW_REPEATS = 11, NLAWS = 6 };
static const int all_laws[NLAWS] = {FRICREG_LAW_COULOMB, FRICREG_LAW_FORCE_BALANCE,
                                    FRICREG_LAW_KARNOPP, FRICREG_LAW_VELOCITY_LIMITED,
                                    FRICREG_LAW_TANH,    FRICREG_LAW_QUINN};
static const char *const all_law_names[NLAWS] = {"coulomb(1)", "force-balance(2)",
                                                 "karnopp",    "velocity-limited(3)",
                                                 "tanh",       "quinn(4)"};
#define LAW_EPS 1e-3

/* xorshift64*: the same inputs on every machine. */
static uint64_t rng_state = 0x9E3779B97F4A7C15u;
static double uniform(void)
{
    rng_state ^= rng_state >> 12;
    rng_state ^= rng_state << 25;
    rng_state ^= rng_state >> 27;
    return (double)((rng_state * 0x2545F4914F6CDD1Du) >> 11) * 0x1.0p-53;
}

/* 40% stuck (v = 0), 20% near stick (|v| < eps), 40% slipping (eps <= |v| < 1), in random
 * order; f_eq within +-2 mun, so about half the stuck contacts are at their bound. */
static void law_inputs(double v[], double f_eq[], double mun[], double a_free[])
{
    for (size_t i = 0; i < M; i++) {
        double u = uniform(), sign = uniform() < 0.5 ? -1.0 : 1.0;
        v[i] = u < 0.4   ? 0.0
               : u < 0.6 ? sign * LAW_EPS * uniform()
                         : sign * (LAW_EPS + (1.0 - LAW_EPS) * uniform());
        mun[i] = 0.5 + uniform();
        f_eq[i] = (4.0 * uniform() - 2.0) * mun[i];
        a_free[i] = -f_eq[i]; /* W = I: f_eq = -a_free */
    }
}

/* ns per contact, [size][law] for the batch and [size][0 quinn, 1 coulomb] for the context;
 * size 0: m = M contacts (40 MB of arrays: memory traffic counts), size 1: the first M_SMALL
 * of them, swept INNER times per timing (in cache: arithmetic counts). */
enum { M_SMALL = 4096, INNER = 250 };
static const size_t law_m[2] = {M, M_SMALL};
static double batch_ns[2][NLAWS], ctx_ns[2][2];

static int law_costs(void)
{
    double *v = malloc(M * sizeof *v), *f_eq = malloc(M * sizeof *f_eq);
    double *mun = malloc(M * sizeof *mun), *a_free = malloc(M * sizeof *a_free);
    double *f = malloc(M * sizeof *f);
    fricreg_ctx *ctx[2] = {NULL, NULL};
    int status = v && f_eq && mun && a_free && f ? FRICREG_OK : FRICREG_ENOMEM;
    static double tb[2][NLAWS][LAW_REPEATS], tc[2][2][LAW_REPEATS];
    if (status == FRICREG_OK)
        law_inputs(v, f_eq, mun, a_free);
    for (int z = 0; status == FRICREG_OK && z < 2; z++) {
        status = fricreg_ctx_create(law_m[z], &ctx[z]);
        if (status == FRICREG_OK)
            status = fricreg_ctx_set_bounds(ctx[z], law_m[z], mun);
    }
    for (int r = 0; status == FRICREG_OK && r < LAW_REPEATS; r++)
        for (int z = 0; status == FRICREG_OK && z < 2; z++) {
            size_t m = law_m[z];
            int inner = z == 0 ? 1 : INNER;
            for (int l = 0; status == FRICREG_OK && l < NLAWS; l++) {
                double t0 = bench_cpu_seconds();
                for (int k = 0; status == FRICREG_OK && k < inner; k++)
                    status = fricreg_law_eval_batch(all_laws[l], LAW_EPS, m, v, f_eq, mun, f);
                tb[z][l][r] = (bench_cpu_seconds() - t0) / ((double)inner * (double)m);
            }
            for (int l = 0; status == FRICREG_OK && l < 2; l++) {
                status = fricreg_ctx_set_law(ctx[z], chain_laws[l], LAW_EPS);
                double t0 = bench_cpu_seconds();
                for (int k = 0; status == FRICREG_OK && k < inner; k++)
                    status = fricreg_ctx_eval(ctx[z], m, v, a_free, f, NULL);
                tc[z][l][r] = (bench_cpu_seconds() - t0) / ((double)inner * (double)m);
            }
        }
    if (status == FRICREG_OK) {
        for (int z = 0; z < 2; z++) {
            for (int l = 0; l < NLAWS; l++)
                batch_ns[z][l] = 1e9 * bench_median(tb[z][l], LAW_REPEATS);
            for (int l = 0; l < 2; l++)
                ctx_ns[z][l] = 1e9 * bench_median(tc[z][l], LAW_REPEATS);
        }
    } else {
        fprintf(stderr, "fricreg-bench-scaling: law evaluation failed: %s\n",
                fricreg_strerror(status));
    }
    fricreg_ctx_free(ctx[0]);
    fricreg_ctx_free(ctx[1]);
    free(v), free(f_eq), free(mun), free(a_free), free(f);
    return status;
}

/* ---- Output ---------------------------------------------------------------------------- */

static FILE *open_out(const char *dir, const char *name)
{
    return bench_open_out("fricreg-bench-scaling", dir, name);
}

static int write_files(const char *dir)
{
    FILE *csv = open_out(dir, "scaling.csv"), *laws = open_out(dir, "laws.csv");
    FILE *gp = open_out(dir, "scaling.gp");
    if (!csv || !laws || !gp)
        return 1;
    fprintf(csv, "n,steps,ns_per_step_block_quinn,ns_per_step_block_coulomb,ratio\n");
    for (int i = 0; i < NN; i++)
        fprintf(csv, "%zu,%.0f,%.4f,%.4f,%.4f\n", chain_n[i], chain_steps_done[i], chain_ns[0][i],
                chain_ns[1][i], chain_ns[0][i] / chain_ns[1][i]);
    fprintf(laws, "law,path,m,ns_per_contact\n");
    for (int z = 0; z < 2; z++) {
        for (int l = 0; l < NLAWS; l++)
            fprintf(laws, "%s,fricreg_law_eval_batch,%zu,%.4f\n", all_law_names[l], law_m[z],
                    batch_ns[z][l]);
        for (int l = 0; l < 2; l++)
            fprintf(laws, "%s,fricreg_ctx_eval,%zu,%.4f\n", chain_law_names[l], law_m[z],
                    ctx_ns[z][l]);
    }
    fprintf(gp, "# generated by fricreg-bench-scaling; run in this folder: gnuplot scaling.gp\n"
                "set terminal pngcairo noenhanced size 900,560\n"
                "set datafile separator ','\n"
                "set output 'scaling.png'\n"
                "set title 'chain, RK4 dt = 0.35/n: CPU time per step per block'\n"
                "set logscale x; set grid; set yrange [0:*]\n"
                "set xlabel 'n (blocks = contacts)'; set ylabel 'ns per step per block'\n"
                "plot 'scaling.csv' using 1:3 skip 1 with linespoints title 'law (4) Quinn', \\\n"
                "     '' using 1:4 skip 1 with linespoints title 'law (1) Coulomb'\n");
    fclose(csv), fclose(laws), fclose(gp);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: fricreg-bench-scaling OUTDIR\n");
        return 2;
    }
    double t_start = bench_cpu_seconds();
    chain_scaling();
    if (law_costs() != FRICREG_OK)
        return 1;
    printf("fricreg %s scaling benchmark (medians of %d interleaved runs)\n\n", fricreg_version(),
           REPEATS);
    printf("== Chain, RK4 dt = %g/n, eps = 10 omega dt, from rest: CPU ns per step per block, "
           "and per right-hand side per block (the whole run over its right-hand sides) ==\n",
           CHAIN_DT_N);
    printf("%-9s %7s %12s %12s %10s %14s\n", "n", "steps", "quinn(4)", "coulomb(1)", "(4)/(1)",
           "(4) per RHS");
    for (int i = 0; i < NN; i++)
        printf("%-9zu %7.0f %12.2f %12.2f %10.2f %14.2f\n", chain_n[i], chain_steps_done[i],
               chain_ns[0][i], chain_ns[1][i], chain_ns[0][i] / chain_ns[1][i],
               chain_ns[0][i] / chain_rhs_per_step[i]);
    for (int l = 0; l < 2; l++) {
        double lo = INFINITY, hi = 0.0;
        for (int i = 0; i < NN; i++)
            lo = fmin(lo, chain_ns[l][i]), hi = fmax(hi, chain_ns[l][i]);
        /* least-squares exponent b of the time per step ~ n^b */
        double sx = 0, sy = 0, sxx = 0, sxy = 0;
        for (int i = 0; i < NN; i++) {
            double x = log((double)chain_n[i]), y = log(chain_ns[l][i] * (double)chain_n[i]);
            sx += x, sy += y, sxx += x * x, sxy += x * y;
        }
        double b = (NN * sxy - sx * sy) / (NN * sxx - sx * sx);
        printf("linearity, %-10s: time per step ~ n^%.3f; per-block cost at n = %zu / at "
               "n = %zu = %.2f, max/min over n = %.2f\n",
               chain_law_names[l], b, chain_n[NN - 1], chain_n[0],
               chain_ns[l][NN - 1] / chain_ns[l][0], hi / lo);
    }
    printf("\n== Laws alone: ns per contact, eps = %g; contacts 40%% stuck, 20%% near stick, "
           "40%% slipping ==\n",
           LAW_EPS);
    printf("%-24s %-20s %14s %14s\n", "", "law", "m = 10^6", "m = 4096");
    for (int l = 0; l < NLAWS; l++)
        printf("%-24s %-20s %14.2f %14.2f\n", "fricreg_law_eval_batch", all_law_names[l],
               batch_ns[0][l], batch_ns[1][l]);
    for (int l = 0; l < 2; l++)
        printf("%-24s %-20s %14.2f %14.2f\n", "fricreg_ctx_eval, W = I", chain_law_names[l],
               ctx_ns[0][l], ctx_ns[1][l]);
    printf("%-45s %14.2f %14.2f\n", "ratio (4)/(1), batch", batch_ns[0][NLAWS - 1] / batch_ns[0][0],
           batch_ns[1][NLAWS - 1] / batch_ns[1][0]);
    printf("%-45s %14.2f %14.2f\n", "ratio (4)/(1), context", ctx_ns[0][0] / ctx_ns[0][1],
           ctx_ns[1][0] / ctx_ns[1][1]);
    printf("(m = 10^6: 40 MB of arrays, memory traffic counts; m = 4096: in cache, swept %d "
           "times per timing)\n",
           INNER);
    if (write_files(argv[1]) != 0)
        return 1;
    printf("\nscaling benchmark: %.0f CPU seconds; files in %s: scaling.csv, laws.csv, "
           "scaling.gp\n",
           bench_cpu_seconds() - t_start, argv[1]);
    return 0;
}
