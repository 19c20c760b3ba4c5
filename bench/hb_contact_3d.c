/* SPDX-License-Identifier: GPL-3.0-or-later */
/* hb_contact_3d.c — the cost of the 3-D contact element in harmonic balance
 * (fricreg_hb_set_jenkins_2d_normal: the sampled 2-D AFT at N and N/2 samples, extrapolated)
 * against the 1-D lift-off element (fricreg_hb_set_jenkins_normal: the exact AFT) in the same
 * run: the 2-dof mass on an inclined contact of tests/hb/test_hb_contact_3d.c, continued in Ω from
 * 0.9 to 1.5 (through slip and lift-off), and the 1-D element on its x row with the same
 * normal law. For each H the median over repeats of the seconds per continuation point and per
 * Newton step (the monitor counts them), and the ratio 3-D / 1-D per step. Usage:
 * fricreg-bench-hb-contact-3d [repeats]. */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "fricreg_hb.h"

enum { MAX_REPEATS = 32 };

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int count_steps(void *user, int64_t iterations, double parameter, double residual)
{
    (void)iterations, (void)parameter, (void)residual;
    ++*(long *)user;
    return 0;
}

/* The inclined contact, with the 3-D element (three_d) or the 1-D lift-off one on x. */
static fricreg_hb *make(int H, int three_d, long *steps)
{
    const double M[4] = {1.0, 0.0, 0.0, 1.2}, K[4] = {2.0, -0.3, -0.3, 1.5},
                 C[4] = {0.06, 0.0, 0.0, 0.05}, Je[4] = {1.0, 0.0, 0.0, 1.0}, Jn[2] = {0.4, -0.3},
                 kt = 1.5, mu = 0.4, n0 = 0.5, kn = 2.0, p[2] = {0.6, 0.4}, zero[2] = {0.0, 0.0};
    fricreg_hb *hb = NULL;
    int status = fricreg_hb_create(2, 1, H, &hb);
    if (status == FRICREG_OK)
        status = fricreg_hb_set_mass(hb, 2, M);
    if (status == FRICREG_OK)
        status = fricreg_hb_set_stiffness(hb, 2, K);
    if (status == FRICREG_OK)
        status = fricreg_hb_set_damping(hb, 2, C);
    if (status == FRICREG_OK)
        status = three_d ? fricreg_hb_set_jenkins_2d_normal(hb, 1, 2, Je, Jn, &kt, &mu, &n0, &kn)
                         : fricreg_hb_set_jenkins_normal(hb, 1, 2, Je, Jn, &kt, &mu, &n0, &kn);
    if (status == FRICREG_OK)
        status = fricreg_hb_set_excitation(hb, 2, p, zero);
    if (status == FRICREG_OK)
        status = fricreg_hb_set_monitor(hb, count_steps, steps);
    if (status != FRICREG_OK) {
        fprintf(stderr, "set-up failed: %s\n", hb ? fricreg_hb_errmsg(hb) : "no memory");
        fricreg_hb_free(hb);
        return NULL;
    }
    return hb;
}

static int cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median(double *x, int n)
{
    qsort(x, (size_t)n, sizeof *x, cmp);
    return n % 2 ? x[n / 2] : 0.5 * (x[n / 2 - 1] + x[n / 2]);
}

/* Median seconds per point and per Newton step of the continuation; 1 on failure. */
static int time_branch(int H, int three_d, int repeats, double *per_point, double *per_step,
                       size_t *points)
{
    double tp[MAX_REPEATS], ts[MAX_REPEATS];
    size_t rows = three_d ? 3 : 2, nq = rows * (2 * (size_t)H + 1);
    for (int r = 0; r < repeats; r++) {
        long steps = 0;
        fricreg_hb *hb = make(H, three_d, &steps);
        if (hb == NULL)
            return 1;
        double t0 = now();
        int status = fricreg_hb_continue(hb, 0.9, 1.5, nq, NULL);
        double t = now() - t0;
        *points = fricreg_hb_points(hb);
        if (status != FRICREG_OK) {
            fprintf(stderr, "H = %d %s: %s\n", H, three_d ? "3-D" : "1-D", fricreg_hb_errmsg(hb));
            fricreg_hb_free(hb);
            return 1;
        }
        tp[r] = t / (double)*points;
        ts[r] = t / (double)steps;
        fricreg_hb_free(hb);
    }
    *per_point = median(tp, repeats);
    *per_step = median(ts, repeats);
    return 0;
}

int main(int argc, char **argv)
{
    int repeats = argc > 1 ? atoi(argv[1]) : 3;
    if (repeats < 1 || repeats > MAX_REPEATS) {
        fprintf(stderr, "usage: fricreg-bench-hb-contact-3d [repeats, 1..%d]\n", MAX_REPEATS);
        return 2;
    }
    static const int Hs[] = {3, 7, 15};
    printf("# the inclined contact continued from 0.9 to 1.5; medians of %d runs\n", repeats);
    printf("%3s %6s %12s %12s %6s %12s %12s %9s\n", "H", "pts3", "ms/pt 3-D", "ms/step 3-D", "pts1",
           "ms/pt 1-D", "ms/step 1-D", "step 3/1");
    for (size_t i = 0; i < sizeof Hs / sizeof *Hs; i++) {
        double p3, s3, p1, s1;
        size_t n3 = 0, n1 = 0;
        if (time_branch(Hs[i], 1, repeats, &p3, &s3, &n3) ||
            time_branch(Hs[i], 0, repeats, &p1, &s1, &n1))
            return 1;
        printf("%3d %6zu %12.3f %12.3f %6zu %12.3f %12.3f %9.1f\n", Hs[i], n3, 1e3 * p3, 1e3 * s3,
               n1, 1e3 * p1, 1e3 * s1, s3 / s1);
    }
    return 0;
}
