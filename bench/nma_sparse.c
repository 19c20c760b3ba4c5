/* SPDX-License-Identifier: GPL-3.0-or-later */
/* nma_sparse.c — the nonlinear modes (fricreg_hb_nma) of a sparse model at 10^4 dofs:
 * tests/support/hb_rod.h's rod (Rayleigh damping plus a dashpot, three Jenkins elements),
 * H = 7, Newton's tolerance 1e-7 (above the solves' noise at this size, fricreg_hb_set_newton).
 * Times (wall-clock medians of repeats): the backbone of mode 0, 100 points from a = 1e-3
 * (every element stuck) to a = 0.4 (slipping: ζ from 0.022 to 0.14; at this tolerance Newton
 * fails near a = 0.42, on 2000 dofs too); a call of 2 stuck points, the linear mode (the
 * subspace iteration on K_0's sparse factor, src/nma/nma_sparse_mode.c) and two Newton solves;
 * and the baseline measured in the same run, one forced-response point solve (fricreg_hb_solve
 * at 1.3 rad/s from the stuck guess, its H + 1 factors included). Usage:
 * fricreg-bench-nma-sparse [repeats]. */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "bench.h"
#include "fricreg_hb.h"
#include "hb_rod.h"

#define H 7
#define NC (2 * H + 1)
#define NDOF 10000
#define POINTS 100

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

enum what { POINT_SOLVE, STUCK_MODE, BACKBONE };

/* Seconds of one run of `what` on a fresh driver; negative on failure. *zeta, *omega: the
 * last point's (backbone runs). */
static double run(const struct hb_rod *r, enum what what, double *omega, double *zeta)
{
    fricreg_hb *hb = NULL;
    double q[HB_ROD_M * NC], a;
    if (fricreg_hb_create(r->n, r->m, H, &hb) != FRICREG_OK)
        return -1.0;
    int status = hb_rod_set(hb, r, 0, HB_ROD_UPPER, 0);
    if (status == FRICREG_OK)
        status = fricreg_hb_set_newton(hb, 1e-7, 50);
    if (status == FRICREG_OK)
        status = fricreg_hb_set_continuation(hb, 0.05, 1e-6, 0.1, 2000);
    double t0 = now();
    if (status == FRICREG_OK)
        status = what == POINT_SOLVE ? fricreg_hb_solve(hb, 1.3, HB_ROD_M * NC, NULL, q)
                 : what == STUCK_MODE
                     ? fricreg_hb_nma(hb, 0, FRICREG_HB_NMA_DAMPING_MATRIX, 1e-4, 2e-4, 2)
                     : fricreg_hb_nma(hb, 0, FRICREG_HB_NMA_DAMPING_MATRIX, 1e-3, 0.4, POINTS);
    double t = now() - t0;
    if (status == FRICREG_OK && what == BACKBONE)
        status = fricreg_hb_nma_point(hb, POINTS - 1, &a, omega, zeta, 0, 0, NULL);
    if (status == FRICREG_OK && what != POINT_SOLVE && omega != NULL && what == STUCK_MODE)
        status = fricreg_hb_nma_point(hb, 0, &a, omega, zeta, 0, 0, NULL);
    if (status != FRICREG_OK) {
        fprintf(stderr, "%s (%s)\n", fricreg_strerror(status), fricreg_hb_errmsg(hb));
        t = -1.0;
    }
    fricreg_hb_free(hb);
    return t;
}

int main(int argc, char **argv)
{
    int repeats = argc > 1 ? atoi(argv[1]) : 3;
    if (repeats < 1 || repeats > 64)
        repeats = 3;
    struct hb_rod r;
    if (hb_rod_build(&r, NDOF) != 0)
        return 1;
    double ts[64], tm[64], tb[64], w0 = 0.0, z0 = 0.0, w1 = 0.0, z1 = 0.0;
    for (int k = 0; k < repeats; k++) { /* interleaved: a burst of load spoils one of each */
        ts[k] = run(&r, POINT_SOLVE, NULL, NULL);
        tm[k] = run(&r, STUCK_MODE, &w0, &z0);
        tb[k] = run(&r, BACKBONE, &w1, &z1);
        if (ts[k] < 0.0 || tm[k] < 0.0 || tb[k] < 0.0) {
            hb_rod_free(&r);
            return 1;
        }
    }
    hb_rod_free(&r);
    double s = bench_median(ts, (size_t)repeats), m = bench_median(tm, (size_t)repeats),
           b = bench_median(tb, (size_t)repeats);
    printf("# nonlinear mode 0 of the %d-dof rod, H = %d, 3 Jenkins elements (medians of %d)\n",
           NDOF, H, repeats);
    printf("point solve (baseline)        %8.3f s\n", s);
    printf("linear mode + 2 stuck points  %8.3f s  (omega %.6f, zeta %.3e)\n", m, w0, z0);
    printf("backbone, %d points          %8.3f s  (%.3f s a point; last omega %.6f, zeta %.3e)\n",
           POINTS, b, b / POINTS, w1, z1);
    printf("ratio: a backbone point / a point solve = %.2f; the backbone / a point solve = %.1f\n",
           b / POINTS / s, b / s);
    return 0;
}
