/* SPDX-License-Identifier: GPL-3.0-or-later */
/* fit_modal_iwan.c — fricreg-bench-fit: the identification of a modal Iwan joint
 * (fricreg_fit.h) against a derivative-free fit of the same objective.
 *
 * The levels: 8 accelerations from 3 % to 150 % of phi_max of a joint near 170 Hz (F_S 30,
 * K_T 3e5, chi 0.3, beta 0.5, zeta0 0.002, K0 8.4e5; sensor 0.37), with 1 % noise in zeta and
 * 0.05 % in f (GSL's MT19937, seeds 1..DRAWS), the deviations given; every parameter free,
 * started 10x off (tests/fit/test_fit.c's problem). For each draw:
 *   - fricreg_fit_run (32 starts, the default; the exact Jacobian): its CPU time and backbone evaluations
 *     (residuals plus Jacobians, each the 8 levels' backbone), and whether the interval holds
 *     the truth;
 *   - GSL's Nelder-Mead (gsl_multimin_fminimizer_nmsimplex2) on r^T r in the same theta
 *     (log F_S, log K_T, log(chi + 1), log beta, log zeta0, log K0; each evaluation one
 *     fricreg_fit_eval of the 8 levels), from the same 10x-off start and, as a kinder
 *     baseline, from one 2x off (chi + 1 by 2; initial steps ln 10), restarted from its best
 *     point until its cost is within 1e-6 of the trust-region fit's or 200 000 evaluations are
 *     spent.
 * Then the four-parameter fit of the target (beta and K0 known, fixed at the truth).
 * Prints a line per draw and the medians: CPU per fit, evaluations of each, their ratio, the
 * CPU ratio (both measured in this run), the intervals' coverage, the four-parameter CPU.
 * Usage: fricreg-bench-fit [DRAWS] (default 20; about a second a draw, Nelder-Mead most). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_multimin.h>
#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>

#include "bench.h"
#include "nelder_mead.h"
#include "fricreg_fit.h"

#define NP FRICREG_FIT_NPARAMS
#define NL 8
#define SENSOR 0.37
#define TWO_PI 6.283185307179586
#define NM_BUDGET 200000

static const double truth[NP] = {30.0, 3e5, 0.3, 0.5, 0.002, 8.4e5};

struct objective {
    fricreg_fit *fit;
    const double *A, *f, *z, *sf, *sz;
    long evals;
};

static double to_p(int j, double theta)
{
    return j == FRICREG_FIT_CHI ? exp(theta) - 1.0 : exp(theta);
}

static double to_theta(int j, double p)
{
    return j == FRICREG_FIT_CHI ? log(p + 1.0) : log(p);
}

static double cost(const gsl_vector *theta, void *params)
{
    struct objective *o = params;
    double p[NP], fm[NL], zm[NL], c = 0.0;
    for (int j = 0; j < NP; j++)
        p[j] = to_p(j, gsl_vector_get(theta, (size_t)j));
    o->evals++;
    if (fricreg_fit_eval(o->fit, p, FRICREG_FIT_ACCELERATION, NL, o->A, fm, zm, NULL, NULL, NULL))
        return INFINITY;
    for (int i = 0; i < NL; i++) {
        double rf = (fm[i] - o->f[i]) / o->sf[i], rz = (zm[i] - o->z[i]) / o->sz[i];
        c += rf * rf + rz * rz;
    }
    return c;
}

/* Nelder-Mead from start (theta) until cost <= target or the budget; returns evaluations. */
static long nelder_mead(struct objective *o, const double start[], double target, double *best)
{
    gsl_multimin_function F = {cost, NP, o};
    return bench_nelder_mead(&F, start, log(10.0), target, NM_BUDGET, &o->evals, best);
}

int main(int argc, char **argv)
{
    int draws = argc > 1 ? atoi(argv[1]) : 20;
    fricreg_fit *fit = NULL;
    if (draws < 1 || fricreg_fit_create(&fit) != FRICREG_OK)
        return 1;
    fricreg_fit_set_sensor(fit, SENSOR);
    double c = truth[3] + (truth[2] + 1.0) / (truth[2] + 2.0);
    double pm = truth[0] * (1.0 + truth[3]) / (truth[1] * c), A[NL], f[NL], z[NL];
    for (int i = 0; i < NL; i++)
        A[i] = SENSOR * pm * 0.03 * pow(50.0, i / 7.0) * pow(TWO_PI * 165.0, 2);
    fricreg_fit_eval(fit, truth, FRICREG_FIT_ACCELERATION, NL, A, f, z, NULL, NULL, NULL);
    const double factor[NP] = {10.0, 0.1, 10.0, 10.0, 0.1, 10.0};
    double *cpu = malloc((size_t)draws * sizeof *cpu),
           *nm_cpu = malloc((size_t)draws * sizeof *nm_cpu);
    double *evals = malloc((size_t)draws * sizeof *evals),
           *ratio = malloc((size_t)draws * sizeof *ratio);
    double *ratio2 = malloc((size_t)draws * sizeof *ratio2);
    double *cpu4 = malloc((size_t)draws * sizeof *cpu4);
    int covered = 0, reached = 0, reached2 = 0;
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    printf("draw,fit_cpu_s,fit_evals,nm_evals,nm_reached,nm_cpu_s,nm2x_evals,nm2x_reached,"
           "fit4_cpu_s\n");
    for (int d = 0; d < draws; d++) {
        double fm[NL], zm[NL], sf[NL], sz[NL], start[NP], theta0[NP], theta2[NP], lo[NP], hi[NP];
        double p[NP], v;
        gsl_rng_set(rng, (unsigned long)d + 1);
        for (int i = 0; i < NL; i++) {
            sf[i] = 5e-4 * f[i];
            sz[i] = 0.01 * z[i];
            fm[i] = f[i] + gsl_ran_gaussian(rng, sf[i]);
            zm[i] = z[i] + gsl_ran_gaussian(rng, sz[i]);
        }
        fricreg_fit_set_levels(fit, NL, FRICREG_FIT_ACCELERATION, A, fm, zm);
        fricreg_fit_set_deviations(fit, NL, sf, sz);
        for (int j = 0; j < NP; j++) {
            start[j] = j == FRICREG_FIT_CHI ? factor[j] * (truth[j] + 1.0) - 1.0
                                            : truth[j] * factor[j];
            fricreg_fit_set_free(fit, j, start[j], j == FRICREG_FIT_CHI ? -1.0 : 0.0, INFINITY);
            theta0[j] = to_theta(j, start[j]);
            theta2[j] = j == FRICREG_FIT_CHI ? log(2.0 * (truth[j] + 1.0))
                                             : log(truth[j] * (factor[j] > 1.0 ? 2.0 : 0.5));
        }
        double t0 = bench_cpu_seconds();
        if (fricreg_fit_run(fit) != FRICREG_OK) {
            printf("%d,failed: %s\n", d, fricreg_fit_errmsg(fit));
            return 1;
        }
        cpu[d] = bench_cpu_seconds() - t0;
        fricreg_fit_get_params(fit, NP, p);
        fricreg_fit_get_covariance(fit, NP, NULL, lo, hi);
        for (int j = 0; j < NP; j++)
            covered += lo[j] <= truth[j] && truth[j] <= hi[j];
        double nfev, njev, target, best;
        fricreg_fit_get_value(fit, FRICREG_FIT_NFEV, &nfev);
        fricreg_fit_get_value(fit, FRICREG_FIT_NJEV, &njev);
        fricreg_fit_get_value(fit, FRICREG_FIT_COST, &v);
        evals[d] = nfev + njev;
        target = v * (1.0 + 1e-6);
        struct objective o = {fit, A, fm, zm, sf, sz, 0};
        t0 = bench_cpu_seconds();
        long n = nelder_mead(&o, theta0, target, &best);
        nm_cpu[d] = bench_cpu_seconds() - t0;
        reached += best <= target;
        ratio[d] = (double)n / evals[d];
        struct objective o2 = {fit, A, fm, zm, sf, sz, 0};
        double best2;
        long n2 = nelder_mead(&o2, theta2, target, &best2);
        reached2 += best2 <= target;
        ratio2[d] = (double)n2 / evals[d];
        /* The four-parameter fit: beta and K0 known (fixed at the truth), the rest as above. */
        fricreg_fit_set_fixed(fit, FRICREG_FIT_BETA, truth[FRICREG_FIT_BETA]);
        fricreg_fit_set_fixed(fit, FRICREG_FIT_K0, truth[FRICREG_FIT_K0]);
        t0 = bench_cpu_seconds();
        int st4 = fricreg_fit_run(fit);
        cpu4[d] = bench_cpu_seconds() - t0;
        printf("%d,%.4g,%.0f,%ld,%d,%.4g,%ld,%d,%.4g%s\n", d, cpu[d], evals[d], n, best <= target,
               nm_cpu[d], n2, best2 <= target, cpu4[d], st4 == FRICREG_OK ? "" : " (failed)");
    }
    printf("# fit: median %.3g s CPU per fit, %.0f backbone evaluations; coverage %.1f %% of "
           "%d intervals\n",
           bench_median(cpu, (size_t)draws), bench_median(evals, (size_t)draws),
           100.0 * covered / (NP * draws), NP * draws);
    printf("# Nelder-Mead: reached the fit's cost in %d of %d draws (budget %d); median %.0fx "
           "the evaluations, %.0fx the CPU\n",
           reached, draws, NM_BUDGET, bench_median(ratio, (size_t)draws),
           bench_median(nm_cpu, (size_t)draws) / bench_median(cpu, (size_t)draws));
    printf("# Nelder-Mead from 2x off: reached it in %d of %d draws; median %.0fx the "
           "evaluations\n",
           reached2, draws, bench_median(ratio2, (size_t)draws));
    printf("# four parameters (beta and K0 fixed): median %.3g s CPU per fit\n",
           bench_median(cpu4, (size_t)draws));
    gsl_rng_free(rng);
    fricreg_fit_free(fit);
    return 0;
}
