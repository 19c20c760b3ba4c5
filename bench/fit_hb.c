/* SPDX-License-Identifier: GPL-3.0-or-later */
/* fit_hb.c — fricreg-bench-fit-hb: the identification of a harmonic-balance model's nonlinear
 * mode (fricreg_fit_set_model_hb, fricreg_fit.h) against a derivative-free fit of the same
 * objective.
 *
 * The model: the 60-dof chain of tests/floquet/test_hb_monodromy.c (unit masses and springs, the last
 * dof free) with 10 Jenkins elements grounding dofs 3, 9, ..., 57, harmonic balance at H = 5,
 * Rayleigh's a0 with the modal damping (xi_k = a0), mode 2 (its backbone monotone in a:
 * tests/nma/test_hb_nma_sensitivity.c). The truth: the ten elements' shared kt = 0.2 and mu N =
 * 0.02, a0 = 0.004. The levels: 8 modal amplitudes from 0.53 to 3.9 (geometric), their
 * frequencies and damping ratios from the model with 0.05 % noise in f and 1 % in zeta (GSL's
 * MT19937, seeds 1..DRAWS), the deviations given; the three parameters free, started at
 * (kt/2, 2 mu N, 2 a0) (from (2 kt, mu N/2, 2 a0) the start's backbone stops near a = 0.21,
 * from (2 kt, 2 mu N, a0/2) near 0.82, out of the levels' reach: measured). For each draw:
 *   - fricreg_fit_run (one start, the default of an HB model): its CPU time, its model
 *     evaluations (residuals and Jacobian together) and its backbone marches;
 *   - GSL's Nelder-Mead (gsl_multimin_fminimizer_nmsimplex2) on r^T r in the same theta (the
 *     logs of the three; each evaluation one fricreg_fit_eval of the 8 levels), from the same
 *     start (initial steps ln 2), restarted from its best point until its cost is within 1e-6
 *     of the trust-region fit's or BUDGET evaluations are spent;
 *   - the same levels fitted by the model's quasi-static modal analysis
 *     (fricreg_fit_set_model_qsma) from the same start: its CPU time and parameters (QSMA's
 *     model is not EPMC's: its parameters differ by that model's difference).
 * Prints a line per draw and the medians. Usage: fricreg-bench-fit-hb [DRAWS [BUDGET]]
 * (default 1 draw, budget 2000: about half a minute a draw, Nelder-Mead most). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_multimin.h>
#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>

#include "bench.h"
#include "nelder_mead.h"
#include "fricreg_element.h"
#include "fricreg_fit.h"
#include "fricreg_hb.h"

#define NP 3
#define NL 8
#define N 60
#define NE 10
#define H 5
#define MODE 2

static const double truth[NP] = {0.2, 0.02, 0.004};
static const double factor[NP] = {0.5, 2.0, 2.0};

/* The chain at the truth; NULL if a call failed. */
static fricreg_hb *chain(void)
{
    static double M[N * N], K[N * N], J[NE * N];
    for (size_t i = 0; i < N; i++) {
        M[i * N + i] = 1.0;
        K[i * N + i] = i + 1 < N ? 2.0 : 1.0;
        if (i > 0)
            K[i * N + i - 1] = K[(i - 1) * N + i] = -1.0;
    }
    double p[2 * NE];
    for (size_t e = 0; e < NE; e++) {
        J[e * N + 6 * e + 3] = 1.0;
        p[2 * e] = truth[0];
        p[2 * e + 1] = truth[1];
    }
    fricreg_hb *hb = NULL;
    if (fricreg_hb_create(N, NE, H, &hb) != FRICREG_OK)
        return NULL;
    if (fricreg_hb_set_mass(hb, N, M) || fricreg_hb_set_stiffness(hb, N, K) ||
        fricreg_hb_set_rayleigh(hb, truth[2], 0.0) || fricreg_hb_set_newton(hb, 1e-10, 50) ||
        fricreg_hb_add_elements(hb, fricreg_element_lookup("jenkins"), NE, N, J, p)) {
        fricreg_hb_free(hb);
        return NULL;
    }
    return hb;
}

struct objective {
    fricreg_fit *fit;
    const double *A, *f, *z, *sf, *sz;
    long evals;
};

static double cost(const gsl_vector *theta, void *params)
{
    struct objective *o = params;
    double p[NP], fm[NL], zm[NL], c = 0.0;
    for (size_t j = 0; j < NP; j++)
        p[j] = exp(gsl_vector_get(theta, j));
    o->evals++;
    if (fricreg_fit_eval(o->fit, p, FRICREG_FIT_DISPLACEMENT, NL, o->A, fm, zm, NULL, NULL, NULL))
        return INFINITY;
    for (int i = 0; i < NL; i++) {
        double rf = (fm[i] - o->f[i]) / o->sf[i], rz = (zm[i] - o->z[i]) / o->sz[i];
        c += rf * rf + rz * rz;
    }
    return c;
}

/* Nelder-Mead from start (theta) until cost <= target or the budget; returns evaluations. */
static long nelder_mead(struct objective *o, const double start[], double target, long budget,
                        double *best)
{
    gsl_multimin_function F = {cost, NP, o};
    return bench_nelder_mead(&F, start, log(2.0), target, budget, &o->evals, best);
}

/* The fit of the model's three parameters, by EPMC or QSMA, or NULL (printed why). */
static fricreg_fit *fit_of(fricreg_hb *hb, int qsma)
{
    const int kind[NP] = {FRICREG_HB_NMA_PARAM_ELEMENT, FRICREG_HB_NMA_PARAM_ELEMENT,
                          FRICREG_HB_NMA_PARAM_DAMPING};
    const size_t first[NP] = {0, 0, 0}, count[NP] = {NE, NE, 0}, index[NP] = {0, 1, 1};
    fricreg_fit *fit = NULL;
    if (fricreg_fit_create(&fit) != FRICREG_OK)
        return NULL;
    int st = qsma ? fricreg_fit_set_model_qsma(fit, hb, MODE, NP, kind, first, count, index)
                  : fricreg_fit_set_model_hb(fit, hb, MODE, FRICREG_HB_NMA_DAMPING_MODAL, NP, kind,
                                             first, count, index);
    if (st != FRICREG_OK) {
        printf("# set_model_hb: %s\n", fricreg_fit_errmsg(fit));
        fricreg_fit_free(fit);
        return NULL;
    }
    return fit;
}

int main(int argc, char **argv)
{
    int draws = argc > 1 ? atoi(argv[1]) : 1;
    long budget = argc > 2 ? atol(argv[2]) : 2000;
    fricreg_hb *hb = chain();
    fricreg_fit *fit = hb != NULL ? fit_of(hb, 0) : NULL, *qs = hb != NULL ? fit_of(hb, 1) : NULL;
    double A[NL], f[NL], z[NL];
    for (int i = 0; i < NL; i++)
        A[i] = 0.53 * pow(3.9 / 0.53, i / (NL - 1.0));
    if (draws < 1 || fit == NULL || qs == NULL ||
        fricreg_fit_eval(fit, truth, FRICREG_FIT_DISPLACEMENT, NL, A, f, z, NULL, NULL, NULL)) {
        printf("# set-up failed: %s\n", fit != NULL ? fricreg_fit_errmsg(fit) : "no model");
        return 1;
    }
    double *cpu = malloc((size_t)draws * sizeof *cpu),
           *ratio = malloc((size_t)draws * sizeof *ratio);
    double *models = malloc((size_t)draws * sizeof *models);
    double *marches = malloc((size_t)draws * sizeof *marches);
    double *qcpu = malloc((size_t)draws * sizeof *qcpu);
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    printf("draw,fit_cpu_s,fit_models,fit_marches,nm_evals,nm_reached,nm_cpu_s,kt,mun,a0,"
           "qsma_cpu_s,qsma_kt,qsma_mun,qsma_a0\n");
    for (int d = 0; d < draws; d++) {
        double fm[NL], zm[NL], sf[NL], sz[NL], theta0[NP], p[NP], v, best;
        gsl_rng_set(rng, (unsigned long)d + 1);
        for (int i = 0; i < NL; i++) {
            sf[i] = 5e-4 * f[i];
            sz[i] = 0.01 * z[i];
            fm[i] = f[i] + gsl_ran_gaussian(rng, sf[i]);
            zm[i] = z[i] + gsl_ran_gaussian(rng, sz[i]);
        }
        fricreg_fit_set_levels(fit, NL, FRICREG_FIT_DISPLACEMENT, A, fm, zm);
        fricreg_fit_set_deviations(fit, NL, sf, sz);
        for (int j = 0; j < NP; j++) {
            fricreg_fit_set_free(fit, j, truth[j] * factor[j], 0.0, INFINITY);
            theta0[j] = log(truth[j] * factor[j]);
        }
        double t0 = bench_cpu_seconds();
        if (fricreg_fit_run(fit) != FRICREG_OK) {
            printf("%d,failed: %s\n", d, fricreg_fit_errmsg(fit));
            return 1;
        }
        cpu[d] = bench_cpu_seconds() - t0;
        fricreg_fit_get_params(fit, NP, p);
        fricreg_fit_get_value(fit, FRICREG_FIT_NMODEL, &models[d]);
        fricreg_fit_get_value(fit, FRICREG_FIT_NMARCH, &marches[d]);
        fricreg_fit_get_value(fit, FRICREG_FIT_COST, &v);
        struct objective o = {fit, A, fm, zm, sf, sz, 0};
        t0 = bench_cpu_seconds();
        long n = nelder_mead(&o, theta0, v * (1.0 + 1e-6), budget, &best);
        double nm_cpu = bench_cpu_seconds() - t0;
        ratio[d] = (double)n / models[d];
        double q[NP] = {NAN, NAN, NAN}; /* QSMA's fit of the same levels, from the same start */
        fricreg_fit_set_levels(qs, NL, FRICREG_FIT_DISPLACEMENT, A, fm, zm);
        fricreg_fit_set_deviations(qs, NL, sf, sz);
        for (int j = 0; j < NP; j++)
            fricreg_fit_set_free(qs, j, truth[j] * factor[j], 0.0, INFINITY);
        t0 = bench_cpu_seconds();
        if (fricreg_fit_run(qs) == FRICREG_OK)
            fricreg_fit_get_params(qs, NP, q);
        qcpu[d] = bench_cpu_seconds() - t0;
        printf("%d,%.4g,%.0f,%.0f,%ld,%d,%.4g,%.6g,%.6g,%.6g,%.4g,%.6g,%.6g,%.6g\n", d, cpu[d],
               models[d], marches[d], n, best <= v * (1.0 + 1e-6), nm_cpu, p[0], p[1], p[2],
               qcpu[d], q[0], q[1], q[2]);
    }
    printf("# fit: median %.3g s CPU, %.0f model evaluations (%.0f backbone marches)\n",
           bench_median(cpu, (size_t)draws), bench_median(models, (size_t)draws),
           bench_median(marches, (size_t)draws));
    printf("# Nelder-Mead (budget %ld): median %.0fx the fit's model evaluations\n", budget,
           bench_median(ratio, (size_t)draws));
    printf("# QSMA's fit of the same levels: median %.3g s CPU\n",
           bench_median(qcpu, (size_t)draws));
    gsl_rng_free(rng);
    fricreg_fit_free(fit);
    fricreg_fit_free(qs);
    fricreg_hb_free(hb);
    free(qcpu);
    free(cpu);
    free(ratio);
    free(models);
    free(marches);
    return 0;
}
