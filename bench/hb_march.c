/* SPDX-License-Identifier: GPL-3.0-or-later */
/* hb_march.c — the cost of harmonic balance on a law it knows only by its eval (the march of
 * src/joint/aft_march.c) against the exact AFT of the same element, in one process: NLvib's
 * chain (bench/nlvib/chain_jenkins.m: unit masses and springs ground-1-2-3, C = 0.02 K,
 * cos(Omega t) on dof 2, kt = 20, mu N = 1 between dof 1 and the ground and between dofs 1 and
 * 2, H = 7) with jenkins elements (exact) or jenkins_2d elements whose second components sit on
 * dofs 4 and 5 of their own (marched), continued from 0.5 to 2 rad/s with the defaults, with
 * and without stability: points, median seconds, the ratio, and each dof's located peak.
 * Usage: fricreg-bench-hb-march [repeats]. */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "fricreg_element.h"
#include "fricreg_hb.h"

#define H 7

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

static fricreg_hb *chain(int marched, int stability)
{
    size_t n = marched ? 5 : 3, dim = marched ? 2 : 1;
    double M[25] = {0}, K[25] = {0}, C[25], pc[5] = {0, 1, 0, 0, 0}, ps[5] = {0};
    double J[20] = {0}, p[4] = {20, 1, 20, 1};
    for (size_t i = 0; i < n; i++) {
        M[i * n + i] = 1.0;
        K[i * n + i] = i < 3 ? 2.0 : 1.0;
        if (i > 0 && i < 3)
            K[i * n + i - 1] = K[(i - 1) * n + i] = -1.0;
    }
    for (size_t i = 0; i < n * n; i++)
        C[i] = 0.02 * K[i];
    J[0] = 1.0; /* element 0 on dof 1; element 1 on dof 2 - dof 1 */
    J[dim * n] = -1.0;
    J[dim * n + 1] = 1.0;
    if (marched) { /* their second components on dofs 4 and 5 */
        J[n + 3] = 1.0;
        J[3 * n + 4] = 1.0;
    }
    fricreg_hb *hb = NULL;
    if (fricreg_hb_create(n, 2, H, &hb) != FRICREG_OK)
        return NULL;
    fricreg_hb_set_mass(hb, n, M);
    fricreg_hb_set_stiffness(hb, n, K);
    fricreg_hb_set_damping(hb, n, C);
    fricreg_hb_set_excitation(hb, n, pc, ps);
    fricreg_hb_set_stability(hb, stability);
    if (fricreg_hb_add_elements(hb, fricreg_element_lookup(marched ? "jenkins_2d" : "jenkins"), 2,
                                n, J, p) != FRICREG_OK) {
        fricreg_hb_free(hb);
        return NULL;
    }
    return hb;
}

int main(int argc, char **argv)
{
    int repeats = argc > 1 ? atoi(argv[1]) : 3;
    if (repeats < 1 || repeats > 64)
        repeats = 3;
    for (int stability = 0; stability <= 1; stability++) {
        double seconds[2], peaks[2][3][2], t[64];
        for (int marched = 0; marched <= 1; marched++) {
            fricreg_hb *hb = chain(marched, stability);
            if (hb == NULL)
                return 1;
            size_t nq = (size_t)(marched ? 4 : 2) * (2 * H + 1);
            int status = 0;
            for (int r = 0; r < repeats; r++) {
                double t0 = now();
                status = fricreg_hb_continue(hb, 0.5, 2.0, nq, NULL);
                t[r] = now() - t0;
            }
            qsort(t, (size_t)repeats, sizeof *t, cmp);
            seconds[marched] = t[repeats / 2];
            for (size_t dof = 0; dof < 3; dof++)
                if (status != FRICREG_OK || fricreg_hb_peak(hb, dof, &peaks[marched][dof][0],
                                                            &peaks[marched][dof][1]) != FRICREG_OK)
                    peaks[marched][dof][0] = peaks[marched][dof][1] = NAN;
            printf("%s, stability %s: status %d, %zu points, %.3g s\n",
                   marched ? "jenkins_2d (marched)" : "jenkins (exact)", stability ? "on" : "off",
                   status, fricreg_hb_points(hb), seconds[marched]);
            fricreg_hb_free(hb);
        }
        printf("  marched / exact: %.0f\n", seconds[1] / seconds[0]);
        for (int dof = 0; dof < 3; dof++)
            printf("  dof %d's peak: Omega %.7g against %.7g, RMS %.8g against %.8g (%.2g)\n",
                   dof + 1, peaks[1][dof][0], peaks[0][dof][0], peaks[1][dof][1], peaks[0][dof][1],
                   fabs(peaks[1][dof][1] - peaks[0][dof][1]) / peaks[0][dof][1]);
    }
    return 0;
}
