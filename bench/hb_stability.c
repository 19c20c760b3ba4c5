/* SPDX-License-Identifier: GPL-3.0-or-later */
/* hb_stability.c — the cost of stability (fricreg_hb_set_stability) per continuation point, by
 * Hill's method and by the exact monodromy (fricreg_hb_set_stability_method): the gap pair of
 * tests/floquet/test_hb_stability.c (2 dofs, one lift-off element with a gap, H = 15: Hill's companion
 * matrix of order 124) and a
 * three-mass Jenkins chain at H = 7 and 15 (orders 90 and 186), the Jenkins pair and the
 * lift-off pair of the same test (Hill's orders 124), each branch followed without
 * stability and with each method; the median over repeats of the time per stored point (the
 * bifurcations' location included: it is part of fricreg_hb_continue; their count without/with
 * printed), and the ratios with/without, target <= 1.5 for the monodromy. Usage:
 * fricreg-bench-hb-stability [repeats]. */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "bench.h"
#include "fricreg_hb.h"

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* A model: n dofs, one element (lift-off when normal), H harmonics, the branch w0 .. w1. */
struct model {
    const char *name;
    size_t n;
    int H, normal;
    double M[9], K[9], J[3], Jn[3], kt, mun, mu, n0, kn, pc[3], w0, w1;
    double c; /* C = c K */
};

/* Median seconds per stored point over repeats branches, without stability (method < 0) or by
 * the method (enum fricreg_hb_stability_method); the point count into *points. */
static double per_point(const struct model *s, int method, int repeats, size_t *points,
                        size_t *bifs)
{
    double t[64], C[9], ps[3] = {0.0, 0.0, 0.0};
    size_t n = s->n, nq = (s->normal ? 2 : 1) * (2 * (size_t)s->H + 1);
    for (size_t i = 0; i < n * n; i++)
        C[i] = s->c * s->K[i];
    for (int k = 0; k < repeats; k++) {
        fricreg_hb *hb = NULL;
        if (fricreg_hb_create(n, 1, s->H, &hb) != FRICREG_OK)
            return -1.0;
        fricreg_hb_set_mass(hb, n, s->M);
        fricreg_hb_set_stiffness(hb, n, s->K);
        fricreg_hb_set_damping(hb, n, C);
        if (s->normal)
            fricreg_hb_set_normal_elements(hb, 1, n, s->J, s->Jn, &s->kt, &s->mu, &s->n0, &s->kn);
        else
            fricreg_hb_set_elements(hb, 1, n, s->J, &s->kt, &s->mun);
        fricreg_hb_set_excitation(hb, n, s->pc, ps);
        if (method >= 0) {
            fricreg_hb_set_stability_method(hb, method);
            fricreg_hb_set_stability(hb, 1);
        }
        double t0 = now();
        int status = fricreg_hb_continue(hb, s->w0, s->w1, nq, NULL);
        double dt = now() - t0;
        *points = fricreg_hb_points(hb);
        *bifs = fricreg_hb_bifurcations(hb);
        if (status != FRICREG_OK) {
            fprintf(stderr, "%s: %s\n", s->name, fricreg_hb_errmsg(hb));
            fricreg_hb_free(hb);
            return -1.0;
        }
        t[k] = dt / (double)*points;
        fricreg_hb_free(hb);
    }
    return bench_median(t, (size_t)repeats);
}

int main(int argc, char **argv)
{
    int repeats = argc > 1 ? atoi(argv[1]) : 7;
    if (repeats < 1 || repeats > 64)
        repeats = 7;
    struct model gap = {.name = "gap pair, H = 15",
                        .n = 2,
                        .H = 15,
                        .normal = 1,
                        .M = {1, 0, 0, 1},
                        .K = {140, -20, -20, 180},
                        .J = {0, 1},
                        .Jn = {-1, 0},
                        .kt = 40.0,
                        .mu = 0.01,
                        .n0 = -10.0,
                        .kn = 500.0,
                        .pc = {2, 1},
                        .w0 = 11.0,
                        .w1 = 17.0,
                        .c = 0.002};
    struct model chain = {.name = "Jenkins chain, 3 dofs, H = 7",
                          .n = 3,
                          .H = 7,
                          .M = {1, 0, 0, 0, 1, 0, 0, 0, 1},
                          .K = {2, -1, 0, -1, 2, -1, 0, -1, 1},
                          .J = {1, 0, 0},
                          .kt = 20.0,
                          .mun = 1.0,
                          .pc = {0, 1, 0},
                          .w0 = 0.5,
                          .w1 = 2.0,
                          .c = 0.002};
    struct model chain15 = chain;
    chain15.name = "Jenkins chain, 3 dofs, H = 15";
    chain15.H = 15;
    struct model pair = {.name = "Jenkins pair, H = 15",
                         .n = 2,
                         .H = 15,
                         .M = {1, 0, 0, 1},
                         .K = {2, -1, -1, 2},
                         .J = {1, 0},
                         .kt = 3.0,
                         .mun = 0.4,
                         .pc = {1, 0},
                         .w0 = 0.3,
                         .w1 = 2.5,
                         .c = 0.05};
    struct model liftoff = gap;
    liftoff.name = "lift-off pair, H = 15";
    liftoff.J[0] = 1.0, liftoff.J[1] = 0.0;
    liftoff.Jn[0] = 0.0, liftoff.Jn[1] = -1.0;
    liftoff.mu = 0.3, liftoff.n0 = 2.0, liftoff.kn = 100.0;
    liftoff.w0 = 5.0, liftoff.w1 = 12.5;
    const struct model *models[5] = {&gap, &chain, &chain15, &pair, &liftoff};
    printf("# Stability per continuation point: median of %d branches; ratios to without\n",
           repeats);
    printf("%-30s %8s %8s %12s %10s %10s %8s %8s\n", "model", "points", "bifs", "without (ms)",
           "Hill", "monodromy", "ratio H", "ratio M");
    for (int i = 0; i < 5; i++) {
        size_t p0 = 0, p1 = 0, p2 = 0, b0 = 0, b1 = 0, b2 = 0;
        double a = per_point(models[i], -1, repeats, &p0, &b0),
               b = per_point(models[i], FRICREG_HB_STABILITY_HILL, repeats, &p1, &b1),
               c = per_point(models[i], FRICREG_HB_STABILITY_MONODROMY, repeats, &p2, &b2);
        if (a < 0.0 || b < 0.0 || c < 0.0)
            return EXIT_FAILURE;
        printf("%-30s %8zu %2zu/%zu/%zu %12.3f %10.3f %10.3f %8.2f %8.2f\n", models[i]->name, p1,
               b0, b1, b2, 1e3 * a, 1e3 * b, 1e3 * c, b / a, c / a);
    }
    return EXIT_SUCCESS;
}
