/* SPDX-License-Identifier: GPL-3.0-or-later */
/* hb_level.c — the cost of the continuation in the excitation level (fricreg_hb_continue_level)
 * and of the point solve's start along it (fricreg_hb_solve without a guess) against Newton
 * from the stuck response (a zero guess, the start until 1.6): the gap pair of
 * tests/forced/test_hb_level.c (2 dofs, one lift-off element with a gap, H = 15), its S-curve at
 * Omega = 15.2 from level 0.05 to 2 with and without stability (points, folds, median time),
 * then point solves at a few frequencies each way (median time, status). Usage:
 * fricreg-bench-hb-level [repeats]. */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "fricreg_hb.h"

#define H 15
#define NQ (2 * (2 * H + 1))

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median(double *t, int n)
{
    qsort(t, (size_t)n, sizeof *t, cmp);
    return t[n / 2];
}

static fricreg_hb *gap_pair(int stability)
{
    fricreg_hb *hb = NULL;
    const double M[4] = {1, 0, 0, 1}, K[4] = {140, -20, -20, 180}, J[2] = {0, 1}, Jn[2] = {-1, 0},
                 kt = 40, mu = 0.01, n0 = -10, kn = 500, pc[2] = {2, 1}, ps[2] = {0, 0};
    double C[4];
    for (int i = 0; i < 4; i++)
        C[i] = 0.002 * K[i];
    if (fricreg_hb_create(2, 1, H, &hb) != FRICREG_OK)
        return NULL;
    fricreg_hb_set_mass(hb, 2, M);
    fricreg_hb_set_stiffness(hb, 2, K);
    fricreg_hb_set_damping(hb, 2, C);
    fricreg_hb_set_normal_elements(hb, 1, 2, J, Jn, &kt, &mu, &n0, &kn);
    fricreg_hb_set_excitation(hb, 2, pc, ps);
    fricreg_hb_set_stability(hb, stability);
    return hb;
}

int main(int argc, char **argv)
{
    int repeats = argc > 1 ? atoi(argv[1]) : 5;
    if (repeats < 1 || repeats > 64)
        repeats = 5;
    double t[64];
    for (int stability = 0; stability <= 1; stability++) {
        fricreg_hb *hb = gap_pair(stability);
        if (hb == NULL)
            return 1;
        int status = 0;
        for (int r = 0; r < repeats; r++) {
            double t0 = now();
            status = fricreg_hb_continue_level(hb, 15.2, 0.05, 2.0, NQ, NULL);
            t[r] = now() - t0;
        }
        printf("S-curve at Omega = 15.2, level 0.05 .. 2, stability %s: status %d, %zu points, "
               "%zu folds, %.3g s (%.3g ms a point)\n",
               stability ? "on" : "off", status, fricreg_hb_points(hb), fricreg_hb_bifurcations(hb),
               median(t, repeats), 1e3 * median(t, repeats) / (double)fricreg_hb_points(hb));
        fricreg_hb_free(hb);
    }
    const double omegas[] = {11.0, 14.0, 15.2, 16.5};
    fricreg_hb *hb = gap_pair(0);
    if (hb == NULL)
        return 1;
    double q[NQ], zero[NQ];
    for (size_t w = 0; w < sizeof omegas / sizeof omegas[0]; w++) {
        int status[2] = {0, 0};
        double med[2];
        for (int start = 0; start < 2; start++) {
            for (int r = 0; r < repeats; r++) {
                memset(zero, 0, sizeof zero);
                double t0 = now();
                status[start] = fricreg_hb_solve(hb, omegas[w], NQ, start ? zero : NULL, q);
                t[r] = now() - t0;
            }
            med[start] = median(t, repeats);
        }
        printf("point solve at Omega = %g: no guess (the level's branch) status %d, %.3g ms; "
               "zero guess (the stuck response) status %d, %.3g ms; ratio %.1f\n",
               omegas[w], status[0], 1e3 * med[0], status[1], 1e3 * med[1], med[0] / med[1]);
    }
    fricreg_hb_free(hb);
    return 0;
}
