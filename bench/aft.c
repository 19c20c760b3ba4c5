/* SPDX-License-Identifier: GPL-3.0-or-later */
/* aft.c — fricreg-bench-aft: the exact AFT of a Jenkins element against the sampled one
 * (fricreg_aft.h, docs/aft.md).
 *
 * Error: the largest |f_sampled[j] − f_exact[j]|/mun over the coefficients, the envelope over
 * eight phases ψ of u = 0.1 + 1.3 cos(θ − ψ) + 0.25 cos(3θ − 2ψ) (H = 3; kt = 2.385,
 * mun = 0.7125: six reversals where the third harmonic makes minor loops, else two), at
 * N = 2^5 … 2^12.
 * Cost: CPU time per evaluation, with and without the Jacobian, of the exact AFT at H = 7 and
 * of the sampled AFT at H = 7 and N = 2^5 … 2^12, on u with all seven harmonics
 * (a_h = 1.3/h^2, b_h = −0.4/h^2: two to four reversals), each the median of 21 timings of
 * REPS evaluations, and the ratio sampled/exact.
 * Lift-off cost: the same for fricreg_aft_jenkins_normal_exact against _sampled at H = 7 and
 * N = 2^8, 2^10 (kt = 2.385, mu = 0.3, kn = 1.7, u as above, g with a_h = 0.8/h^2,
 * b_h = 0.3/h^2), with N0 = 0.5 (the contact opens over part of the period) and N0 = 3 (closed,
 * the bound moving). Prints the three tables as Markdown. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include <fricreg_aft.h>

#include "bench.h"

enum { TIMINGS = 21, REPS = 400, PMIN = 5, PMAX = 12, PHASES = 8 };
static const double KT = 2.385, MUN = 0.7125;

static fricreg_aft *make(int H, size_t N)
{
    fricreg_aft *a = NULL;
    int status = fricreg_aft_create(H, N, &a);
    if (status != FRICREG_OK) {
        fprintf(stderr, "fricreg_aft_create(%d, %zu): %s\n", H, N, fricreg_strerror(status));
        exit(1);
    }
    return a;
}

static void error_table(void)
{
    puts("| N | max error / mun | N^2 error / mun |");
    puts("|---|---|---|");
    for (int p = PMIN; p <= PMAX; p++) {
        size_t N = (size_t)1 << p;
        fricreg_aft *a = make(3, N);
        double e = 0.0;
        for (int c = 0; c < PHASES; c++) {
            double psi = 0.3 + 0.61 * c, fe[7], fs[7];
            double u[7] = {0.1, 1.3 * cos(psi),      1.3 * sin(psi),     0,
                           0,   0.25 * cos(2 * psi), 0.25 * sin(2 * psi)};
            if (fricreg_aft_jenkins_exact(a, KT, MUN, 7, u, fe, NULL) != FRICREG_OK ||
                fricreg_aft_jenkins_sampled(a, KT, MUN, 7, u, fs, NULL) != FRICREG_OK) {
                fprintf(stderr, "AFT failed: %s\n", fricreg_aft_errmsg(a));
                exit(1);
            }
            for (int j = 0; j < 7; j++)
                e = fmax(e, fabs(fs[j] - fe[j]) / MUN);
        }
        printf("| 2^%d | %.2e | %.2f |\n", p, e, e * (double)N * (double)N);
        fricreg_aft_free(a);
    }
}

/* Median CPU seconds per evaluation. */
static double per_eval(fricreg_aft *a, int sampled, int with_jac, const double *u)
{
    double t[TIMINGS], f[15], jac[225];
    for (int k = 0; k < TIMINGS; k++) {
        double t0 = bench_cpu_seconds();
        for (int r = 0; r < REPS; r++) {
            int st = sampled
                         ? fricreg_aft_jenkins_sampled(a, KT, MUN, 15, u, f, with_jac ? jac : NULL)
                         : fricreg_aft_jenkins_exact(a, KT, MUN, 15, u, f, with_jac ? jac : NULL);
            if (st != FRICREG_OK) {
                fprintf(stderr, "AFT failed: %s\n", fricreg_aft_errmsg(a));
                exit(1);
            }
        }
        t[k] = (bench_cpu_seconds() - t0) / REPS;
    }
    return bench_median(t, TIMINGS);
}

static void cost_table(void)
{
    double u[15] = {0.1};
    for (int h = 1; h <= 7; h++) {
        u[2 * h - 1] = 1.3 / (h * h);
        u[2 * h] = -0.4 / (h * h);
    }
    fricreg_aft *ex = make(7, 0);
    double e0 = per_eval(ex, 0, 0, u), e1 = per_eval(ex, 0, 1, u);
    fricreg_aft_free(ex);
    printf("\nexact, H = 7: %.1f us (f), %.1f us (f and Jacobian)\n\n", 1e6 * e0, 1e6 * e1);
    puts("| N | sampled f (us) | sampled/exact | sampled f, Jacobian (us) | sampled/exact |");
    puts("|---|---|---|---|---|");
    for (int p = PMIN; p <= PMAX; p++) {
        fricreg_aft *a = make(7, (size_t)1 << p);
        double s0 = per_eval(a, 1, 0, u), s1 = per_eval(a, 1, 1, u);
        printf("| 2^%d | %.1f | %.2f | %.1f | %.2f |\n", p, 1e6 * s0, s0 / e0, 1e6 * s1, s1 / e1);
        fricreg_aft_free(a);
    }
}

static double per_eval_normal(fricreg_aft *a, int sampled, int with_jac, double n0, const double *u,
                              const double *g)
{
    double t[TIMINGS], f[15], nf[15], jac[900];
    for (int k = 0; k < TIMINGS; k++) {
        double t0 = bench_cpu_seconds();
        for (int r = 0; r < REPS; r++) {
            int st = sampled ? fricreg_aft_jenkins_normal_sampled(a, KT, 0.3, n0, 1.7, 15, u, g, f,
                                                                  nf, with_jac ? jac : NULL)
                             : fricreg_aft_jenkins_normal_exact(a, KT, 0.3, n0, 1.7, 15, u, g, f,
                                                                nf, with_jac ? jac : NULL);
            if (st != FRICREG_OK) {
                fprintf(stderr, "AFT failed: %s\n", fricreg_aft_errmsg(a));
                exit(1);
            }
        }
        t[k] = (bench_cpu_seconds() - t0) / REPS;
    }
    return bench_median(t, TIMINGS);
}

static void normal_cost_table(void)
{
    double u[15] = {0.1}, g[15] = {0.0};
    for (int h = 1; h <= 7; h++) {
        u[2 * h - 1] = 1.3 / (h * h);
        u[2 * h] = -0.4 / (h * h);
        g[2 * h - 1] = 0.8 / (h * h);
        g[2 * h] = 0.3 / (h * h);
    }
    puts("\n| lift-off, H = 7 | N0 | exact f (us) | exact f, Jacobian (us) | sampled f (us) | "
         "sampled/exact | sampled f, Jacobian (us) | sampled/exact |");
    puts("|---|---|---|---|---|---|---|---|");
    const double n0s[2] = {0.5, 3.0};
    for (int c = 0; c < 2; c++)
        for (int p = 8; p <= 10; p += 2) {
            fricreg_aft *a = make(7, (size_t)1 << p);
            double e0 = per_eval_normal(a, 0, 0, n0s[c], u, g);
            double e1 = per_eval_normal(a, 0, 1, n0s[c], u, g);
            double s0 = per_eval_normal(a, 1, 0, n0s[c], u, g);
            double s1 = per_eval_normal(a, 1, 1, n0s[c], u, g);
            printf("| N = 2^%d | %.1f | %.1f | %.1f | %.1f | %.2f | %.1f | %.2f |\n", p, n0s[c],
                   1e6 * e0, 1e6 * e1, 1e6 * s0, s0 / e0, 1e6 * s1, s1 / e1);
            fricreg_aft_free(a);
        }
}

int main(void)
{
    error_table();
    cost_table();
    normal_cost_table();
    return 0;
}
