/* SPDX-License-Identifier: GPL-3.0-or-later */
/* python_baseline.c — the C side of the Python binding's speed ratios (bench/python_speed.py,
 * docs/python.md) and of the Octave gateway's (bench/octave_speed.m, docs/matlab.md): the same
 * work as those benchmarks', from C, each repetition timed on the process CPU clock and printed
 * as "TASK SECONDS" lines.
 *
 *   hb       NLvib's 3-dof chain with two Jenkins elements (bench/nlvib/chain_jenkins.m) at
 *            H = 7: the driver built, its frequency response continued from 0.5 to 2 rad/s
 *            with stability (the exact monodromy), and every point's Ω, RMS and stability read;
 *   element  10^4 jenkins points, one fricreg_element_eval each, with the tangent.
 *
 * Usage: fricreg-bench-python-baseline TASK REPETITIONS */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <fricreg_hb.h>

#define H 7
#define NPOINTS 10000

static double cpu_seconds(void)
{
    return (double)clock() / CLOCKS_PER_SEC;
}

/* The chain's sweep, each point read as the binding reads it (Ω, RMS, coefficients,
 * stability); returns the points read (0 on failure). */
static size_t chain_sweep(void)
{
    const double M[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, K[9] = {2, -1, 0, -1, 2, -1, 0, -1, 2};
    const double J[6] = {1, 0, 0, -1, 1, 0}, params[4] = {20, 1, 20, 1};
    const double pc[3] = {0, 1, 0}, ps[3] = {0, 0, 0};
    double C[9];
    for (int i = 0; i < 9; i++)
        C[i] = 0.02 * K[i];
    fricreg_hb *hb = NULL;
    if (fricreg_hb_create(3, 2, H, &hb) != FRICREG_OK)
        return 0;
    size_t n = 0;
    if (fricreg_hb_set_matrix(hb, FRICREG_MASS, 3, 3, FRICREG_MATRIX_DENSE, NULL, NULL, M) ||
        fricreg_hb_set_matrix(hb, FRICREG_STIFFNESS, 3, 3, FRICREG_MATRIX_DENSE, NULL, NULL, K) ||
        fricreg_hb_set_matrix(hb, FRICREG_DAMPING, 3, 3, FRICREG_MATRIX_DENSE, NULL, NULL, C) ||
        fricreg_hb_add_elements(hb, fricreg_element_lookup("jenkins"), 2, 3, J, params) ||
        fricreg_hb_set_excitation(hb, 3, pc, ps) || fricreg_hb_set_stability(hb, 1) ||
        fricreg_hb_continue(hb, 0.5, 2.0, 2 * (2 * H + 1), NULL))
        goto done;
    for (size_t k = 0; k < fricreg_hb_points(hb); k++) {
        double omega, rms[3], mu, x[3 * (2 * H + 1)];
        int stable;
        if (fricreg_hb_point(hb, k, &omega, 3, rms) ||
            fricreg_hb_point_displacement(hb, k, 3, 2 * H + 1, x) ||
            fricreg_hb_point_stability(hb, k, &stable, &mu))
            goto done;
    }
    n = fricreg_hb_points(hb);
done:
    fricreg_hb_free(hb);
    return n;
}

/* 10^4 jenkins points; returns 1 on success. */
static int element_points(const double *u, const double *w, double *f, double *dfdu, double *w_new)
{
    const fricreg_element_type *t = fricreg_element_lookup("jenkins");
    const double p[2] = {2.0, 0.5};
    for (size_t i = 0; i < NPOINTS; i++)
        if (fricreg_element_eval(t, p, w + i, u + i, f + i, dfdu + i, NULL, w_new + i))
            return 0;
    return 1;
}

int main(int argc, char **argv)
{
    if (argc != 3 || atoi(argv[2]) < 1) {
        fprintf(stderr, "usage: %s hb|element REPETITIONS\n", argv[0]);
        return 2;
    }
    int reps = atoi(argv[2]);
    static double u[NPOINTS], w[NPOINTS], f[NPOINTS], dfdu[NPOINTS], w_new[NPOINTS];
    for (size_t i = 0; i < NPOINTS; i++) /* the points of bench/python_speed.py */
        u[i] = -1.0 + 2.0 * (double)i / (NPOINTS - 1), w[i] = 0.1 * u[i] * u[i];
    for (int r = 0; r < reps; r++) {
        double t0 = cpu_seconds();
        int ok = strcmp(argv[1], "hb") == 0        ? chain_sweep() > 0
                 : strcmp(argv[1], "element") == 0 ? element_points(u, w, f, dfdu, w_new)
                                                   : -1;
        double t1 = cpu_seconds();
        if (ok != 1) {
            fprintf(stderr, "%s: %s\n", argv[1], ok < 0 ? "unknown task" : "failed");
            return 1;
        }
        printf("%s %.9f\n", argv[1], t1 - t0);
    }
    return 0;
}
