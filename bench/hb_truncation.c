/* SPDX-License-Identifier: GPL-3.0-or-later */
/* hb_truncation.c — the cost of fricreg_hb_truncation_error (one solve at 2H + 1 from the
 * padded H solution) against a solve at H: the 3-dof chain of tests/forced/test_hb_truncation.c at
 * Ω = 1.2 (every element slipping), and the sparse rod of tests/support/hb_rod.h (200 dofs,
 * Ω = 1.35). For each H the median over repeats of: fricreg_hb_solve from the solution at
 * Ω − 0.01 (a continuation step's corrector: the H + 1 factors at Ω and a few Newton
 * iterations), fricreg_hb_solve
 * without a guess (the branch in the level from the linear regime), and the estimate; the
 * estimate's ratio to each. Usage: fricreg-bench-hb-truncation [repeats]. */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "bench.h"
#include "fricreg_hb.h"
#include "hb_rod.h"

enum { MAX_REPEATS = 64 };

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* The chain of test_hb_truncation (jenkins_model_chain of tests/support), dense. */
static int set_chain(fricreg_hb *hb)
{
    double M[9] = {1.1, 0, 0, 0, 0.9, 0, 0, 0, 1.25}, K[9] = {0}, C[9], J[6] = {0};
    const double kt[2] = {2.5, 1.4}, mun[2] = {0.3, 0.12}, pc[3] = {0.8, 0, 0},
                 ps[3] = {0.25, 0, 0}, k[3] = {3.2, 2.1, 1.6};
    K[0] = k[0] + k[1], K[1] = K[3] = -k[1], K[4] = k[1] + k[2], K[5] = K[7] = -k[2], K[8] = k[2];
    for (int i = 0; i < 9; i++)
        C[i] = 0.03 * M[i] + 0.01 * K[i];
    J[2] = 1.0, J[3] = -1.0, J[4] = 1.0;
    int status = fricreg_hb_set_mass(hb, 3, M);
    if (status == FRICREG_OK)
        status = fricreg_hb_set_stiffness(hb, 3, K);
    if (status == FRICREG_OK)
        status = fricreg_hb_set_damping(hb, 3, C);
    if (status == FRICREG_OK)
        status = fricreg_hb_set_elements(hb, 2, 3, J, kt, mun);
    return status == FRICREG_OK ? fricreg_hb_set_excitation(hb, 3, pc, ps) : status;
}

/* Median seconds of the three calls at H into t[3]; -1 on a failure (printed). */
static int time_one(const struct hb_rod *rod, int H, double omega, int repeats, double t[3])
{
    size_t n = rod ? rod->n : 3, m = rod ? rod->m : 2, nq = m * (2 * (size_t)H + 1);
    double *q = malloc(2 * nq * sizeof *q), *e = malloc(n * sizeof *e), *q0 = q + nq;
    double s[3][MAX_REPEATS];
    fricreg_hb *hb = NULL;
    int status = q && e ? fricreg_hb_create(n, m, H, &hb) : FRICREG_ENOMEM;
    if (status == FRICREG_OK)
        status = rod ? hb_rod_set(hb, rod, 0, HB_ROD_UPPER, 0) : set_chain(hb);
    if (status == FRICREG_OK)
        status = fricreg_hb_solve(hb, omega - 0.01, nq, NULL, q0);
    for (int r = 0; r < repeats && status == FRICREG_OK; r++) {
        /* the factors at Ω − 0.01: the step refactors, as a continuation's does */
        status = fricreg_hb_solve(hb, omega - 0.01, nq, q0, q);
        double t0 = now();
        status = fricreg_hb_solve(hb, omega, nq, q0, q);
        double t1 = now();
        if (status == FRICREG_OK)
            status = fricreg_hb_solve(hb, omega, nq, NULL, q);
        double t2 = now();
        if (status == FRICREG_OK)
            status = fricreg_hb_truncation_error(hb, FRICREG_HB_SOLUTION, n, e, NULL);
        double t3 = now();
        s[0][r] = t1 - t0, s[1][r] = t2 - t1, s[2][r] = t3 - t2;
    }
    if (status != FRICREG_OK)
        fprintf(stderr, "H = %d: %s\n", H, hb ? fricreg_hb_errmsg(hb) : "out of memory");
    for (int i = 0; i < 3 && status == FRICREG_OK; i++)
        t[i] = bench_median(s[i], (size_t)repeats);
    fricreg_hb_free(hb);
    free(q);
    free(e);
    return status == FRICREG_OK ? 0 : -1;
}

int main(int argc, char **argv)
{
    int repeats = argc > 1 ? atoi(argv[1]) : 7;
    if (repeats < 1 || repeats > MAX_REPEATS)
        repeats = 7;
    struct hb_rod rod;
    if (hb_rod_build(&rod, 200) != 0)
        return EXIT_FAILURE;
    printf("# fricreg_hb_truncation_error against solves at H: median of %d\n", repeats);
    printf("%-22s %4s %14s %14s %14s %10s %10s\n", "model", "H", "step (ms)", "no guess (ms)",
           "estimate (ms)", "/step", "/no guess");
    static const int Hs[] = {3, 5, 7, 9, 13, 19};
    for (int model = 0; model < 2; model++)
        for (size_t i = 0; i < sizeof Hs / sizeof Hs[0]; i++) {
            double t[3];
            if (time_one(model ? &rod : NULL, Hs[i], model ? 1.35 : 1.2, repeats, t) != 0) {
                hb_rod_free(&rod);
                return EXIT_FAILURE;
            }
            printf("%-22s %4d %14.3f %14.3f %14.3f %10.2f %10.3f\n",
                   model ? "rod, 200 dofs, sparse" : "chain, 3 dofs", Hs[i], 1e3 * t[0], 1e3 * t[1],
                   1e3 * t[2], t[2] / t[0], t[2] / t[1]);
        }
    hb_rod_free(&rod);
    return EXIT_SUCCESS;
}
