/* SPDX-License-Identifier: GPL-3.0-or-later */
/* hb_contact_3d_chain.c — a frequency sweep of a chain on 3-D contact elements against the same
 * chain on Jenkins elements: points, Newton steps and CPU seconds of each, the start without a
 * guess (fricreg_hb_solve at Ω0, the library's default route) apart from the sweep from its
 * solution (fricreg_hb_continue, the defaults: ds 0.02, ds_min 1e-6, ds_max 0.1,
 * Newton 1e-10).
 *
 * The model: `nodes` = 7 m / 2 unit masses in a chain, 3 dofs each (x, y, z: dofs 3i, 3i + 1,
 * 3i + 2), springs ground-0-1-…-(nodes − 1) of S = (2 nodes/π)² in x and y and 40 S in z
 * (the first mode in x and y near 0.96 rad/s with the contacts slipping freely), Rayleigh
 * damping C = 0.02/√S K, H = 3. The m contacts sit on nodes (e + 1) nodes/(m + 1), each a
 * contact_3d element to the ground on that node's (x, y, z) rows (kt 20, μ 0.25, kn 50, n0 4,
 * N = n0 + kn z), its Jenkins twin two jenkins elements on x and y (kt 20, slip force μ N_e,
 * N_e the contact's static normal force: n0 + kn z_0 of the 3-D model's solution at Ω0). At
 * m = 4: 14 nodes, 42 dofs, 84 unknowns (3-D) or 56 (Jenkins). Forced at the free end, the
 * three loads (at m = 4; m/4 times them at other m, as the slip forces grow with m):
 *   x    2 cos Ωt on x (the contacts' orbits on a line: the 3-D element is the 1-D one)
 *   xy   2 cos Ωt on x and 1.2 sin Ωt on y (elliptic orbits)
 *   xyz  as xy and 2 cos Ωt on z (the normal forces vary; the smallest over the sweep is printed)
 * swept from Ω0 = 0.8 to 1.6 rad/s through the first resonance.
 *
 * Usage: fricreg-bench-hb-contact-3d-chain [m [load]], defaults 4 and all three loads. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"
#include "fricreg_element.h"
#include "fricreg_hb.h"

#define H 3
#define NC (2 * H + 1)
#define W0 0.8
#define W1 1.6
static const double PI = 3.14159265358979323846, KT = 20.0, MU = 0.25, KN = 50.0, N0 = 4.0, P = 2.0;

struct load {
    const char *name;
    double px, py, pz; /* cos on x, sin on y, cos on z at the free end */
};
static const struct load LOADS[] = {{"x", P, 0.0, 0.0}, {"xy", P, 1.2, 0.0}, {"xyz", P, 1.2, P}};

static int count_steps(void *user, int64_t iterations, double parameter, double residual)
{
    (void)iterations, (void)parameter, (void)residual;
    ++*(long *)user;
    return 0;
}

static size_t node_of(size_t e, size_t m, size_t nodes)
{
    return (e + 1) * nodes / (m + 1);
}

/* The chain with m contact_3d elements (contact) or 2m Jenkins elements of slip forces mu n[e];
 * NULL on failure (the message printed). */
static fricreg_hb *chain(size_t m, const struct load *ld, int contact, const double *n, long *steps)
{
    size_t nodes = 7 * m / 2, ndof = 3 * nodes, rows = (contact ? 3 : 2) * m;
    double s = pow(2.0 * (double)nodes / PI, 2.0), ks[3] = {s, s, 40.0 * s};
    double *K = calloc(ndof * ndof, sizeof(double)), *M = calloc(ndof * ndof, sizeof(double));
    double *pc = calloc(ndof, sizeof(double)), *ps = calloc(ndof, sizeof(double));
    double *J = calloc(rows * ndof, sizeof(double)), *p = calloc(5 * m, sizeof(double));
    fricreg_hb *hb = NULL;
    int status = K && M && pc && ps && J && p ? FRICREG_OK : FRICREG_ENOMEM;
    for (size_t i = 0; status == FRICREG_OK && i < nodes; i++)
        for (size_t d = 0; d < 3; d++) {
            size_t a = 3 * i + d, b = a - 3;
            M[a * ndof + a] = 1.0;
            K[a * ndof + a] += ks[d];
            if (i > 0) {
                K[b * ndof + b] += ks[d];
                K[a * ndof + b] -= ks[d];
                K[b * ndof + a] -= ks[d];
            }
        }
    for (size_t e = 0; status == FRICREG_OK && e < m; e++) {
        size_t at = 3 * node_of(e, m, nodes);
        for (size_t r = 0; r < (contact ? 3u : 2u); r++)
            J[((contact ? 3 : 2) * e + r) * ndof + at + r] = 1.0;
        if (contact) {
            double q[5] = {KT, MU, KN, N0, 0.0};
            memcpy(p + 5 * e, q, sizeof q);
        } else {
            p[4 * e] = p[4 * e + 2] = KT;
            p[4 * e + 1] = p[4 * e + 3] = MU * n[e];
        }
    }
    if (status == FRICREG_OK) {
        double scale = (double)m / 4.0; /* the contacts' slip forces grow with m */
        pc[ndof - 3] = scale * ld->px;
        ps[ndof - 2] = scale * ld->py;
        pc[ndof - 1] = scale * ld->pz;
        status = fricreg_hb_create(ndof, contact ? m : 2 * m, H, &hb);
    }
    if (status == FRICREG_OK)
        status = fricreg_hb_set_mass(hb, ndof, M);
    if (status == FRICREG_OK)
        status = fricreg_hb_set_stiffness(hb, ndof, K);
    if (status == FRICREG_OK)
        status = fricreg_hb_set_rayleigh(hb, 0.0, 0.02 / sqrt(s));
    if (status == FRICREG_OK)
        status = fricreg_hb_set_excitation(hb, ndof, pc, ps);
    if (status == FRICREG_OK)
        status = fricreg_hb_add_elements(hb,
                                         fricreg_element_lookup(contact ? "contact_3d" : "jenkins"),
                                         contact ? m : 2 * m, ndof, J, p);
    if (status == FRICREG_OK)
        status = fricreg_hb_set_monitor(hb, count_steps, steps);
    if (status != FRICREG_OK) {
        fprintf(stderr, "set-up failed: %s\n", hb ? fricreg_hb_errmsg(hb) : "no memory");
        fricreg_hb_free(hb);
        hb = NULL;
    }
    free(K), free(M), free(pc), free(ps), free(J), free(p);
    return hb;
}

/* The smallest normal force n0 + kn z over the contacts, the stored points and 64 instants a
 * period (the 3-D model's sweep), or the contacts' static ones into n (at the last solution). */
static double normal_forces(fricreg_hb *hb, size_t m, int sweep, double *n)
{
    size_t nodes = 7 * m / 2, ndof = 3 * nodes, npts = sweep ? fricreg_hb_points(hb) : 1;
    double *x = malloc(ndof * NC * sizeof(double)), least = INFINITY;
    for (size_t k = 0; x != NULL && k < npts; k++) {
        if (fricreg_hb_point_displacement(hb, sweep ? k : FRICREG_HB_SOLUTION, ndof, NC, x) !=
            FRICREG_OK)
            break;
        for (size_t e = 0; e < m; e++) {
            const double *z = x + (3 * node_of(e, m, nodes) + 2) * NC;
            if (!sweep)
                n[e] = N0 + KN * z[0];
            for (int i = 0; sweep && i < 64; i++) {
                double th = 2.0 * PI * i / 64.0, g = z[0];
                for (int h = 1; h <= H; h++)
                    g += z[2 * h - 1] * cos(h * th) + z[2 * h] * sin(h * th);
                least = fmin(least, N0 + KN * g);
            }
        }
    }
    free(x);
    return least;
}

/* One model's start and sweep: points, steps, seconds; 0 or 1 on failure. */
static int run(size_t m, const struct load *ld, int contact, double *n)
{
    long steps = 0;
    fricreg_hb *hb = chain(m, ld, contact, n, &steps);
    if (hb == NULL)
        return 1;
    size_t nq = (contact ? 3 : 2) * m * NC;
    double *q = malloc(nq * sizeof(double)), t0 = bench_cpu_seconds();
    int status = q ? fricreg_hb_solve(hb, W0, nq, NULL, q) : FRICREG_ENOMEM;
    double ts = bench_cpu_seconds() - t0;
    long ss = steps;
    if (status == FRICREG_OK && contact)
        normal_forces(hb, m, 0, n);
    steps = 0;
    t0 = bench_cpu_seconds();
    int sweep = status == FRICREG_OK ? fricreg_hb_continue(hb, W0, W1, nq, q) : status;
    double tw = bench_cpu_seconds() - t0, wp = NAN, rp = NAN;
    if (sweep == FRICREG_OK)
        fricreg_hb_peak(hb, 3 * (7 * m / 2) - 3, &wp, &rp);
    printf("%-4s %-10s | start %d: %5ld steps %8.3f s | sweep %d: %5zu points %6ld steps %8.3f s "
           "| tip x peak %.5g at %.5f",
           ld->name, contact ? "contact_3d" : "jenkins", status, ss, ts, sweep,
           fricreg_hb_points(hb), steps, tw, rp, wp);
    if (contact && sweep == FRICREG_OK)
        printf(" | least N %.3g", normal_forces(hb, m, 1, NULL));
    printf("\n");
    if (sweep != FRICREG_OK)
        printf("     %s\n", fricreg_hb_errmsg(hb));
    free(q);
    fricreg_hb_free(hb);
    return status != FRICREG_OK || sweep != FRICREG_OK;
}

int main(int argc, char **argv)
{
    size_t m = argc > 1 ? (size_t)atoi(argv[1]) : 4;
    if (m < 1 || m > 64)
        m = 4;
    int failed = 0;
    printf("m = %zu contacts, %zu dofs, H = %d, Omega %.1f to %.1f\n", m, 3 * (7 * m / 2), H, W0,
           W1);
    for (size_t l = 0; l < sizeof LOADS / sizeof LOADS[0]; l++) {
        if (argc > 2 && strcmp(argv[2], LOADS[l].name) != 0)
            continue;
        double *n = malloc(m * sizeof(double));
        if (n == NULL)
            return 1;
        failed |= run(m, &LOADS[l], 1, n); /* first: its static normal forces for the twin */
        failed |= run(m, &LOADS[l], 0, n);
        free(n);
    }
    return failed;
}
