/* SPDX-License-Identifier: GPL-3.0-or-later */
/* hb_interface_rom.c — one harmonic-balance point of an interface reduced-order model against
 * its number of contacts: m contact_3d elements on the interface nodes of a Craig–Bampton-like
 * model (3 m interface dofs and 163 modal dofs: 859 dofs at m = 232, as the Brake–Reuß beam's
 * standard ROM), H = 3, and the same model on 2 m Jenkins elements. For each m, each model
 * and each frequency: the status, the Newton iterations (the monitor's calls) and the CPU
 * seconds of fricreg_hb_solve without a guess (the library's default start), then of a solve
 * from that solution at the same Ω (the factors of D_h kept: one Newton iteration, the cost
 * of an iteration at this size), the peak resident memory, and the least normal force over a
 * period (negative: contacts lift off).
 *
 * The model: interface node e (dofs 3e, 3e + 1, 3e + 2: x, y, z), e = 0 … m − 1, unit masses
 * in a chain ground-0-1-…-(m − 1) of springs S = (2 m/π)² in x and y and 40 S in z (the first
 * mode in x and y near 1 rad/s with the contacts slipping freely, near 4.6 with them stuck);
 * 163 modal dofs of unit mass and stiffness (3 + k/2)², k = 0 … 162, coupled to the interface
 * by a dense mass block M_bm(i, k) = 0.5 cos(π (i + 1/2)(k + 1)/(3m)) / sqrt(3m · 163) (its
 * 2-norm at most 0.5: M stays positive definite), so that D_h and the receptance G_h on the
 * contacts are dense, as a ROM's. Rayleigh damping C = 0.02/√S K. Each node has a contact_3d
 * element to the ground (kt 20, μ 0.25, kn 50, n0 4, N = n0 + kn z); its Jenkins twin two
 * jenkins elements on x and y (kt 20, slip force μ n0); its normal twin two jenkins_normal
 * elements on (x, z) and (y, z), each kt 20, 2 μ, kn/2, n0/2: together the contact's normal law
 * N = max(0, n0 + kn z), and a slip force μ N on each axis that follows it, where the Jenkins
 * twin's stays μ n0 (a square around the contact's disk of radius μ N). Forced at the last node
 * with m/4 times
 *   preload  2 cos Ωt on x, 1.2 sin Ωt on y (the normal forces stay near n0: no lift-off)
 *   liftoff  as preload and 30 cos Ωt on z (the last contacts open in each period)
 * at Ω = 0.8 (below the first resonance) and 1.0 (near it).
 *
 * Then the pieces at Ω (1 + 1e-4), not factored yet: two solves of one Newton iteration
 * from q = 0, the first with D_h's factors and the condensation G_h, the second without.
 *
 * Usage: fricreg-bench-hb-interface-rom [m ...] [--load preload|liftoff]
 *        [--elements contact_3d|jenkins|jenkins_normal] [--omega 0.8|1.0] [--budget s] [--sweep] [--trace]
 *        [--dense]
 * default m = 16 32 85 232, every load, element type and frequency. --budget stops a solve
 * without a guess after s CPU seconds (its status then the monitor's stop); --sweep continues
 * from the point at 0.8 to 1.6 through the first resonance with the defaults (points,
 * iterations, seconds; the budget holds for it too); --trace prints each Newton iteration
 * with its CPU time to stderr; --dense solves each Newton's matrix by its own LU
 * (FRICREG_HB_NEWTON_DENSE: no capacitance, no refinement on an earlier factor). Run one at a
 * time, OPENBLAS_NUM_THREADS=1 for CPU seconds. */
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
#define MODAL 163
static const double PI = 3.14159265358979323846, KT = 20.0, MU = 0.25, KN = 50.0, N0 = 4.0;
static const double OMEGAS[] = {0.8, 1.0}, W_END = 1.6;

/* The models of the interface: its contacts, their Jenkins and normal twins. */
enum kind { CONTACT, JENKINS, NORMAL_TWIN, KINDS };
static const char *const KIND_NAMES[KINDS] = {"contact_3d", "jenkins", "jenkins_normal"};
static const size_t ELEMENTS_A_NODE[KINDS] = {1, 2, 2}, ROWS[KINDS] = {3, 1, 2};

struct load {
    const char *name;
    double px, py, pz; /* cos on x, sin on y, cos on z at the last node, times m/4 */
};
static const struct load LOADS[] = {{"preload", 2.0, 1.2, 0.0}, {"liftoff", 2.0, 1.2, 30.0}};

/* What the command line picks: the loads, element types and frequencies run, and whether the
 * monitor prints each Newton iteration to stderr. */
static const char *only_load, *only_elements;
static double only_omega, budget, started;
static int trace, sweep, dense;

/* Counts the Newton iterations; stops a solve past the budget of CPU seconds (0: none). */
static int count_steps(void *user, int64_t iterations, double parameter, double residual)
{
    ++*(long *)user;
    if (trace)
        fprintf(stderr, "%8ld %10.3f s  iteration %lld  parameter %.6g  |R|/bound %.3g\n",
                *(long *)user, bench_cpu_seconds(), (long long)iterations, parameter, residual);
    return budget > 0.0 && bench_cpu_seconds() - started > budget;
}

/* The CPU seconds of D_h's factors and the condensation at omega (a frequency not factored
 * yet) and of one Newton iteration from q = 0 with its line search: two solves of one
 * iteration at omega, the second on the kept factors. */
static void pieces(fricreg_hb *hb, double omega, size_t nq, double *q, double *factor,
                   double *iteration)
{
    double t[3];
    fricreg_hb_set_newton(hb, 1e-10, 1);
    t[0] = bench_cpu_seconds();
    for (int k = 0; k < 2; k++) {
        memset(q, 0, nq * sizeof(double));
        fricreg_hb_solve(hb, omega, nq, q, q);
        t[k + 1] = bench_cpu_seconds();
    }
    fricreg_hb_set_newton(hb, 1e-10, 50);
    *iteration = t[2] - t[1];
    *factor = t[1] - t[0] - *iteration;
}

/* The peak resident memory of the process so far, MiB (Linux's VmHWM; 0 elsewhere). */
static double peak_mib(void)
{
    FILE *f = fopen("/proc/self/status", "r");
    char line[256];
    double kib = 0.0;
    while (f != NULL && fgets(line, sizeof line, f) != NULL)
        if (strncmp(line, "VmHWM:", 6) == 0)
            kib = atof(line + 6);
    if (f != NULL)
        fclose(f);
    return kib / 1024.0;
}

/* M and K of the model (zeroed on entry), n = 3 m + MODAL, row-major; *s the chain's S. */
static void model(size_t m, double *M, double *K, double *s)
{
    size_t nb = 3 * m, n = nb + MODAL;
    double S = pow(2.0 * (double)m / PI, 2.0), ks[3] = {S, S, 40.0 * S};
    *s = S;
    for (size_t e = 0; e < m; e++)
        for (size_t d = 0; d < 3; d++) {
            size_t a = 3 * e + d, b = a - 3;
            K[a * n + a] += ks[d];
            if (e > 0) {
                K[b * n + b] += ks[d];
                K[a * n + b] -= ks[d];
                K[b * n + a] -= ks[d];
            }
        }
    for (size_t i = 0; i < n; i++)
        M[i * n + i] = 1.0;
    for (size_t k = 0; k < MODAL; k++) {
        size_t c = nb + k;
        K[c * n + c] = pow(3.0 + 0.5 * (double)k, 2.0);
        for (size_t i = 0; i < nb; i++) {
            double v = 0.5 * cos(PI * ((double)i + 0.5) * (double)(k + 1) / (double)nb) /
                       sqrt((double)nb * MODAL);
            M[i * n + c] = M[c * n + i] = v;
        }
    }
}

/* The driver of model k of m nodes under load ld; NULL on failure. */
static fricreg_hb *build(size_t m, const struct load *ld, enum kind k, long *steps)
{
    size_t nb = 3 * m, n = nb + MODAL, me = ELEMENTS_A_NODE[k] * m, rows = ROWS[k];
    double *M = calloc(n * n, sizeof(double)), *K = calloc(n * n, sizeof(double));
    double *pc = calloc(n, sizeof(double)), *ps = calloc(n, sizeof(double));
    double *J = calloc(me * rows * n, sizeof(double)), *p = calloc(5 * me, sizeof(double)), S;
    fricreg_hb *hb = NULL;
    int status = M && K && pc && ps && J && p ? FRICREG_OK : FRICREG_ENOMEM;
    if (status == FRICREG_OK) {
        model(m, M, K, &S);
        for (size_t e = 0; e < me; e++) {
            size_t node = e / ELEMENTS_A_NODE[k], axis = e % 2; /* twins: x (even e) or y */
            if (k == CONTACT) {
                double q[5] = {KT, MU, KN, N0, 0.0};
                memcpy(p + 5 * e, q, sizeof q);
                for (size_t r = 0; r < 3; r++)
                    J[(3 * e + r) * n + 3 * e + r] = 1.0;
            } else if (k == JENKINS) {
                p[2 * e] = KT;
                p[2 * e + 1] = MU * N0;
                J[e * n + 3 * node + axis] = 1.0;
            } else {
                double q[5] = {KT, 2.0 * MU, KN / 2.0, N0 / 2.0, 0.0};
                memcpy(p + 5 * e, q, sizeof q);
                J[2 * e * n + 3 * node + axis] = 1.0;
                J[(2 * e + 1) * n + 3 * node + 2] = 1.0;
            }
        }
        double scale = (double)m / 4.0;
        pc[nb - 3] = scale * ld->px;
        ps[nb - 2] = scale * ld->py;
        pc[nb - 1] = scale * ld->pz;
        status = fricreg_hb_create(n, me, H, &hb);
    }
    if (status == FRICREG_OK)
        status = fricreg_hb_set_mass(hb, n, M);
    if (status == FRICREG_OK)
        status = fricreg_hb_set_stiffness(hb, n, K);
    if (status == FRICREG_OK)
        status = fricreg_hb_set_rayleigh(hb, 0.0, 0.02 / sqrt(S));
    if (status == FRICREG_OK)
        status = fricreg_hb_set_excitation(hb, n, pc, ps);
    if (status == FRICREG_OK)
        status = fricreg_hb_add_elements(hb, fricreg_element_lookup(KIND_NAMES[k]), me, n, J, p);
    if (status == FRICREG_OK)
        status = fricreg_hb_set_monitor(hb, count_steps, steps);
    if (status == FRICREG_OK && dense)
        status = fricreg_hb_set_newton_solver(hb, FRICREG_HB_NEWTON_DENSE);
    if (status != FRICREG_OK) {
        fprintf(stderr, "set-up failed (%d): %s\n", status,
                hb ? fricreg_hb_errmsg(hb) : "no memory");
        fricreg_hb_free(hb);
        hb = NULL;
    }
    free(M), free(K), free(pc), free(ps), free(J), free(p);
    return hb;
}

/* The least normal force n0 + kn z over the contacts and 64 instants of the last solution. */
static double least_normal(fricreg_hb *hb, size_t m)
{
    size_t n = 3 * m + MODAL;
    double *x = malloc(n * NC * sizeof(double)), least = INFINITY;
    if (x == NULL || fricreg_hb_displacement(hb, n, NC, x) != FRICREG_OK) {
        free(x);
        return NAN;
    }
    for (size_t e = 0; e < m; e++) {
        const double *z = x + (3 * e + 2) * NC;
        for (int i = 0; i < 64; i++) {
            double th = 2.0 * PI * i / 64.0, g = z[0];
            for (int h = 1; h <= H; h++)
                g += z[2 * h - 1] * cos(h * th) + z[2 * h] * sin(h * th);
            least = fmin(least, N0 + KN * g);
        }
    }
    free(x);
    return least;
}

/* One model at each frequency: one line each; 1 on a failed solve. */
static int run(size_t m, const struct load *ld, enum kind k)
{
    long steps = 0;
    fricreg_hb *hb = build(m, ld, k, &steps);
    if (hb == NULL)
        return 1;
    size_t nq = ELEMENTS_A_NODE[k] * ROWS[k] * m * NC;
    double *q = malloc(nq * sizeof(double));
    int failed = q == NULL;
    for (size_t w = 0; q != NULL && w < sizeof OMEGAS / sizeof OMEGAS[0]; w++) {
        if (only_omega > 0.0 && OMEGAS[w] != only_omega)
            continue;
        steps = 0;
        double t0 = started = bench_cpu_seconds();
        int status = fricreg_hb_solve(hb, OMEGAS[w], nq, NULL, q);
        double ts = bench_cpu_seconds() - t0, ta = NAN, least = NAN, tf, ti;
        long ss = steps;
        char why[300] = "";
        if (status != FRICREG_OK)
            snprintf(why, sizeof why, "%s", fricreg_hb_errmsg(hb));
        if (status == FRICREG_OK) {
            least = k != JENKINS ? least_normal(hb, m) : NAN;
            steps = 0;
            t0 = bench_cpu_seconds();
            fricreg_hb_solve(hb, OMEGAS[w], nq, q, q);
            ta = bench_cpu_seconds() - t0;
        }
        if (sweep && status == FRICREG_OK && w == 0) {
            steps = 0;
            t0 = started = bench_cpu_seconds();
            int swept = fricreg_hb_continue(hb, OMEGAS[w], W_END, nq, q);
            printf("      sweep %.1f to %.1f: status %d, %zu points, %ld iterations, %.3f s\n",
                   OMEGAS[w], W_END, swept, fricreg_hb_points(hb), steps, bench_cpu_seconds() - t0);
            fricreg_hb_solve(hb, OMEGAS[w], nq, NULL, q); /* the start's state again */
        }
        started = bench_cpu_seconds() + 1e9; /* no budget for the pieces */
        pieces(hb, OMEGAS[w] * (1.0 + 1e-4), nq, q, &tf, &ti);
        printf("%5zu %5zu %6zu %-8s %-10s %4.2f | %2d %5ld %9.3f | %8.3f | %8.3f %8.3f | %8.1f "
               "| %7.3f\n",
               m, 3 * m + MODAL, nq, ld->name, KIND_NAMES[k], OMEGAS[w], status, ss, ts, ta, tf, ti,
               peak_mib(), least);
        if (status != FRICREG_OK)
            printf("      %s\n", why);
        fflush(stdout);
        failed |= status != FRICREG_OK;
    }
    free(q);
    fricreg_hb_free(hb);
    return failed;
}

int main(int argc, char **argv)
{
    static const size_t DEFAULT_M[] = {16, 32, 85, 232};
    size_t ms[64], count = 0;
    for (int a = 1; a < argc; a++) {
        if (strcmp(argv[a], "--trace") == 0)
            trace = 1;
        else if (strcmp(argv[a], "--load") == 0 && a + 1 < argc)
            only_load = argv[++a];
        else if (strcmp(argv[a], "--elements") == 0 && a + 1 < argc)
            only_elements = argv[++a];
        else if (strcmp(argv[a], "--sweep") == 0)
            sweep = 1;
        else if (strcmp(argv[a], "--dense") == 0)
            dense = 1;
        else if (strcmp(argv[a], "--budget") == 0 && a + 1 < argc)
            budget = atof(argv[++a]);
        else if (strcmp(argv[a], "--omega") == 0 && a + 1 < argc)
            only_omega = atof(argv[++a]);
        else if (count < 64 && strtoul(argv[a], NULL, 10) > 0)
            ms[count++] = (size_t)strtoul(argv[a], NULL, 10);
    }
    if (count == 0)
        for (; count < sizeof DEFAULT_M / sizeof DEFAULT_M[0]; count++)
            ms[count] = DEFAULT_M[count];
    int failed = 0;
    printf("H = %d; a point: status, Newton iterations, CPU s without a guess | CPU s from the "
           "solution (one iteration) | CPU s of D_h's factors and G_h, of an iteration from 0 "
           "with its line search | peak MiB | least N\n",
           H);
    printf("%5s %5s %6s %-8s %-10s %4s\n", "m", "dofs", "nq", "load", "elements", "Omega");
    for (size_t i = 0; i < count; i++)
        for (size_t l = 0; l < sizeof LOADS / sizeof LOADS[0]; l++)
            for (enum kind k = CONTACT; k < KINDS; k++) {
                if ((only_load && strcmp(only_load, LOADS[l].name) != 0) ||
                    (only_elements && strcmp(only_elements, KIND_NAMES[k]) != 0))
                    continue;
                failed |= run(ms[i], &LOADS[l], k);
            }
    return failed;
}
