/* SPDX-License-Identifier: GPL-3.0-or-later */
/* hb_sparse.c — the harmonic-balance driver's sparse model (KLU) against the dense one
 * (the complex LU of src/hb/lu.c) on tests/support/hb_rod.h's rod with three Jenkins elements, H = 7: the
 * time of one point solve (fricreg_hb_solve from the stuck guess, the factors at a new
 * frequency included) against the dofs, and the frequency response over the first resonance
 * (fricreg_hb_continue, 1.1 to 1.6 rad/s, Newton's tolerance 1e-7) at 10^4 dofs; wall-clock medians of repeats, the
 * process's peak resident memory after each size. Usage: fricreg-bench-hb-sparse [repeats]. */
#define _POSIX_C_SOURCE 200809L /* clock_gettime, getrusage */
#include <stdio.h>
#include <stdlib.h>
#include <sys/resource.h>
#include <time.h>

#include "bench.h"
#include "fricreg_hb.h"
#include "hb_rod.h"

#define H 7
#define NC (2 * H + 1)

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static double peak_mib(void)
{
    struct rusage u;
    getrusage(RUSAGE_SELF, &u);
    return (double)u.ru_maxrss / 1024.0;
}

/* Median seconds of a point solve (frequencies stepped, so each solve refactors), or of the
 * continuation (then *points its point count); negative on failure. */
static double run(const struct hb_rod *r, int dense, int frf, int repeats, size_t *points)
{
    double t[64], q[HB_ROD_M * NC];
    for (int k = 0; k < repeats; k++) {
        fricreg_hb *hb = NULL;
        if (fricreg_hb_create(r->n, r->m, H, &hb) != FRICREG_OK)
            return -1.0;
        int status = hb_rod_set(hb, r, dense, HB_ROD_UPPER, 0);
        if (status == FRICREG_OK && frf) /* Newton's tolerance above the solves' noise, 3e-8 */
            status = fricreg_hb_set_newton(hb, 1e-7, 50);
        if (status == FRICREG_OK && frf)
            status = fricreg_hb_set_continuation(hb, 0.05, 1e-6, 0.1, 2000);
        double t0 = now();
        if (status == FRICREG_OK)
            status = frf ? fricreg_hb_continue(hb, 1.1, 1.6, HB_ROD_M * NC, NULL)
                         : fricreg_hb_solve(hb, 1.3 + 0.01 * k, HB_ROD_M * NC, NULL, q);
        t[k] = now() - t0;
        if (status != FRICREG_OK) {
            fprintf(stderr, "n = %zu: %s (%s)\n", r->n, fricreg_strerror(status),
                    fricreg_hb_errmsg(hb));
            fricreg_hb_free(hb);
            return -1.0;
        }
        if (points)
            *points = fricreg_hb_points(hb);
        fricreg_hb_free(hb);
    }
    return bench_median(t, (size_t)repeats);
}

int main(int argc, char **argv)
{
    int repeats = argc > 1 ? atoi(argv[1]) : 5;
    if (repeats < 1 || repeats > 64)
        repeats = 5;
    const size_t sizes[] = {100, 200, 400, 1000, 2000, 10000, 100000};
    printf("# point solve, H = %d, 3 elements: ndof, dense s, sparse s, peak RSS MiB\n", H);
    for (size_t s = 0; s < sizeof sizes / sizeof *sizes; s++) {
        struct hb_rod r;
        if (hb_rod_build(&r, sizes[s]) != 0)
            return 1;
        double td = sizes[s] <= 1000 ? run(&r, 1, 0, repeats, NULL) : -1.0;
        double ts = run(&r, 0, 0, repeats, NULL);
        printf("%7zu  %10.4g  %10.4g  %8.1f\n", sizes[s], td, ts, peak_mib());
        fflush(stdout);
        hb_rod_free(&r);
    }
    struct hb_rod r;
    if (hb_rod_build(&r, 10000) != 0)
        return 1;
    size_t points = 0;
    int reps = repeats < 3 ? repeats : 3;
    double tf = run(&r, 0, 1, reps, &points);
    printf("# FRF, 10^4 dofs, H = %d, 1.1 to 1.6 rad/s: %zu points, %.3g s (median of %d), "
           "%.3g s a point; peak RSS %.1f MiB\n",
           H, points, tf, reps, tf / (double)(points ? points : 1), peak_mib());
    hb_rod_free(&r);
    return tf < 0.0;
}
