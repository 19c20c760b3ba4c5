/* SPDX-License-Identifier: GPL-3.0-or-later */
/* structure_scaling.c — time and memory of a structure's Newmark step against its size, beside
 * a frictionless Newmark step on the same factor (the physical limit of a Newmark step).
 *
 * The model: a shear chain of n storeys (lumped mass 1 kg, storey stiffness 10^4 N/m, banded K,
 * Rayleigh C = 0.002 s K), shaken at its base by a_g(t) = 3 sin(2 pi t) m/s^2 (r = 1), with k
 * friction dampers on storey drifts spread evenly up the chain (contact j on storey p_j:
 * J row e_p - e_{p-1}), each of slip load mu N = 0.3 m a_max (n - p_j), the storey shear of a
 * rigid chain at 30 %, so that they stick and slip. Law (4) or the consistent coupled law
 * (FRICREG_PARTITION_CONSISTENT is the structure's default; with contacts on separate storeys
 * and a lumped M, W is diagonal and both coincide), eps = 1e-3 m/s, average-acceleration
 * Newmark, dt = 0.005 s (dt omega_max = 1).
 *
 * The baseline is Newmark written with CHOLMOD alone (linear_newmark.h): K_eff factored with
 * the ordering the structure uses, one solve a step. Each figure is the median over repeats of the
 * mean time per step of a batch (process CPU time), after a warm-up batch that factors.
 *
 *   usage: fricreg-bench-structure-scaling N K [STEPS [REPEATS [estimate]]]
 * Prints one line: n k steps setup_s fricreg_step_s linear_step_s ratio newton_mean peak_MiB.
 * With `estimate`, the error estimate's cost instead: four structures, without an estimate,
 * with finer, coarser and auto companions (fricreg_structure_set_error_companions), each a
 * first batch from the start (the companions made and factored there), then batches
 * interleaved; one line: n k steps, each one's CPU seconds per step (median of the batches,
 * the first batch's apart) and the ratios against none. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>

#include "bench.h"
#include "linear_newmark.h"
#include "fricreg_structure.h"

#define MASS 1.0
#define STOREY_K 1e4
#define RAYLEIGH_A1 0.002
#define GROUND_A 3.0
#define DT 0.005
#define EPS 1e-3
#define TWO_PI 6.283185307179586

struct chain {
    size_t n, k;
    int64_t *kp, *ki; /* K, upper triangle, CSC */
    double *kx;
    int64_t *jp, *ji; /* J, CSR: row j = contact j */
    double *jx, *mun, *ones, *ag;
    size_t nrecord;
};

/* K of the shear chain, fixed at its base: K_ii = 2 k (k for the top), K_i,i+1 = -k. */
static void chain_stiffness(struct chain *c)
{
    size_t n = c->n, q = 0;
    c->kp = malloc((n + 1) * sizeof *c->kp);
    c->ki = malloc(2 * n * sizeof *c->ki);
    c->kx = malloc(2 * n * sizeof *c->kx);
    c->kp[0] = 0;
    for (size_t j = 0; j < n; j++) {
        if (j > 0) {
            c->ki[q] = (int64_t)j - 1;
            c->kx[q++] = -STOREY_K;
        }
        c->ki[q] = (int64_t)j;
        c->kx[q++] = j + 1 < n ? 2.0 * STOREY_K : STOREY_K;
        c->kp[j + 1] = (int64_t)q;
    }
}

/* k dampers on the drifts of storeys p_j = (j + 1/2) n / k, their slip loads, the record. */
static void chain_contacts(struct chain *c)
{
    size_t n = c->n, k = c->k, q = 0;
    c->jp = malloc((k + 1) * sizeof *c->jp);
    c->ji = malloc(2 * k * sizeof *c->ji);
    c->jx = malloc(2 * k * sizeof *c->jx);
    c->mun = malloc(k * sizeof *c->mun);
    c->jp[0] = 0;
    for (size_t j = 0; j < k; j++) {
        size_t p = (size_t)(((double)j + 0.5) * (double)n / (double)k);
        if (p > 0) {
            c->ji[q] = (int64_t)p - 1;
            c->jx[q++] = -1.0;
        }
        c->ji[q] = (int64_t)p;
        c->jx[q++] = 1.0;
        c->jp[j + 1] = (int64_t)q;
        c->mun[j] = 0.3 * MASS * GROUND_A * (double)(n - p);
    }
    c->ones = malloc(n * sizeof *c->ones);
    for (size_t i = 0; i < n; i++)
        c->ones[i] = 1.0;
    c->nrecord = 4001; /* 20 s at dt */
    c->ag = malloc(c->nrecord * sizeof *c->ag);
    for (size_t i = 0; i < c->nrecord; i++)
        c->ag[i] = GROUND_A * sin(TWO_PI * (double)i * DT);
}

static void chain_free(struct chain *c)
{
    void *blocks[] = {c->kp, c->ki, c->kx, c->jp, c->ji, c->jx, c->mun, c->ones, c->ag};
    for (size_t i = 0; i < sizeof blocks / sizeof *blocks; i++)
        free(blocks[i]);
}

static double peak_mib(void)
{
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    return (double)ru.ru_maxrss / 1024.0;
}

static void die(const char *what, const fricreg_structure *s)
{
    fprintf(stderr, "structure_scaling: %s: %s\n", what, s ? fricreg_structure_errmsg(s) : "");
    exit(1);
}

/* ---- fricreg ------------------------------------------------------------------------------ */

static fricreg_structure *structure(const struct chain *c)
{
    fricreg_structure *s = NULL;
    size_t n = c->n;
    int64_t *mp = malloc((n + 1) * sizeof *mp), *mi = malloc(n * sizeof *mi);
    for (size_t i = 0; i <= n; i++)
        mp[i] = (int64_t)i;
    for (size_t i = 0; i < n; i++)
        mi[i] = (int64_t)i;
    double *mx = malloc(n * sizeof *mx);
    for (size_t i = 0; i < n; i++)
        mx[i] = MASS;
    if (fricreg_structure_create(n, c->k, &s) != FRICREG_OK ||
        fricreg_structure_set_mass_csc(s, n, 0, mp, mi, mx) != FRICREG_OK ||
        fricreg_structure_set_stiffness_csc(s, n, FRICREG_SPARSE_UPPER, c->kp, c->ki, c->kx) !=
            FRICREG_OK ||
        fricreg_structure_set_rayleigh(s, 0.0, RAYLEIGH_A1) != FRICREG_OK ||
        fricreg_structure_set_contacts_csr(s, c->k, n, 0, c->jp, c->ji, c->jx) != FRICREG_OK ||
        fricreg_structure_set_bounds(s, c->k, c->mun) != FRICREG_OK ||
        fricreg_structure_set_law(s, FRICREG_LAW_QUINN, EPS) != FRICREG_OK ||
        fricreg_structure_set_influence(s, n, c->ones) != FRICREG_OK ||
        fricreg_structure_set_ground_accel(s, 0.0, DT, c->nrecord, c->ag) != FRICREG_OK)
        die("set-up", s);
    free(mp);
    free(mi);
    free(mx);
    return s;
}

/* Mean CPU seconds per step of `steps` steps from where s is, the estimate read after them
 * (a read settles auto's screen: the finer companions' time, where it doubts, is the batch's). */
static double fricreg_batch(fricreg_structure *s, size_t steps)
{
    double t, used;
    fricreg_structure_get_value(s, FRICREG_SVALUE_TIME, &t);
    double t0 = bench_cpu_seconds();
    if (fricreg_structure_run(s, DT, t + (double)steps * DT) != FRICREG_OK)
        die("run", s);
    fricreg_structure_get_value(s, FRICREG_SVALUE_COMPANIONS_USED, &used);
    return (bench_cpu_seconds() - t0) / (double)steps;
}

/* The ground acceleration of the baseline, the record's function. */
static double ground_accel(double t)
{
    return GROUND_A * sin(TWO_PI * t);
}

/* The estimate's cost: CPU per step without an estimate, with finer, coarser and auto
 * companions (enum fricreg_estimate_companions), measured in turns in this one process. */
static int estimate_cost(const struct chain *c, size_t steps, size_t repeats)
{
    enum { MODES = 4 }; /* none, then the companions e - 1 */
    fricreg_structure *s[MODES];
    double first[MODES], per[MODES][64], med[MODES], cpu[MODES] = {0}, used = -1.0;
    for (int e = 0; e < MODES; e++) {
        s[e] = structure(c);
        if (e > 0 && (fricreg_structure_set_error_estimate(s[e], 1) != FRICREG_OK ||
                      fricreg_structure_set_error_companions(s[e], e - 1) != FRICREG_OK))
            die("estimate", s[e]);
        first[e] = fricreg_batch(s[e], steps); /* the set-up and the companions' */
    }
    for (size_t r = 0; r < repeats; r++)
        for (int e = 0; e < MODES; e++)
            per[e][r] = fricreg_batch(s[e], steps);
    for (int e = 0; e < MODES; e++) {
        med[e] = bench_median(per[e], repeats);
        fricreg_structure_get_value(s[e], FRICREG_SVALUE_COMPANION_CPU, &cpu[e]);
    }
    fricreg_structure_get_value(s[MODES - 1], FRICREG_SVALUE_COMPANIONS_USED, &used);
    for (int e = 0; e < MODES; e++)
        fricreg_structure_free(s[e]);
    printf("n %zu k %zu steps %zu: per step none %.4g s, finer %.4g s (%.2fx), coarser %.4g s "
           "(%.2fx), auto %.4g s (%.2fx, its estimate the %s companions'); first batch none "
           "%.4g, finer %.4g, coarser %.4g, auto %.4g s/step; companions' CPU finer %.3g s, "
           "coarser %.3g s, auto %.3g s\n",
           c->n, c->k, steps, med[0], med[1], med[1] / med[0], med[2], med[2] / med[0], med[3],
           med[3] / med[0], used == FRICREG_COMPANIONS_COARSER ? "coarser" : "finer", first[0],
           first[1], first[2], first[3], cpu[1], cpu[2], cpu[3]);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc < 3) {
        fprintf(stderr, "usage: %s N K [STEPS [REPEATS]]\n", argv[0]);
        return 2;
    }
    struct chain c = {.n = strtoul(argv[1], NULL, 10), .k = strtoul(argv[2], NULL, 10)};
    size_t steps = argc > 3 ? strtoul(argv[3], NULL, 10) : 20;
    size_t repeats = argc > 4 ? strtoul(argv[4], NULL, 10) : 5;
    if (c.n < 2 || c.k < 1 || c.k > c.n / 2 || steps < 1 || repeats < 1 || repeats > 64) {
        fprintf(stderr, "structure_scaling: need N >= 2, 1 <= K <= N/2, STEPS >= 1\n");
        return 2;
    }
    chain_stiffness(&c);
    chain_contacts(&c);
    if (argc > 5 && strcmp(argv[5], "estimate") == 0) {
        int status = estimate_cost(&c, steps, repeats);
        chain_free(&c);
        return status;
    }

    double t0 = bench_cpu_seconds();
    fricreg_structure *s = structure(&c);
    fricreg_batch(s, 1); /* factors M and K_eff, forms W and W_eff */
    double setup = bench_cpu_seconds() - t0;
    double fr[64], lin[64];
    for (size_t r = 0; r < repeats; r++)
        fr[r] = fricreg_batch(s, steps);
    int64_t iterations = 0, taken = 0;
    fricreg_structure_get_stat(s, FRICREG_SSTAT_NEWTON_ITERATIONS, &iterations);
    fricreg_structure_get_stat(s, FRICREG_SSTAT_STEPS, &taken);
    double peak = peak_mib();
    fricreg_structure_free(s);

    struct linear_newmark l;
    linear_newmark_start(&l, c.n, c.kp, c.ki, c.kx, MASS, RAYLEIGH_A1, DT);
    linear_newmark_batch(&l, ground_accel, 1);
    for (size_t r = 0; r < repeats; r++)
        lin[r] = linear_newmark_batch(&l, ground_accel, steps);
    linear_newmark_free(&l);
    chain_free(&c);

    double f = bench_median(fr, repeats), b = bench_median(lin, repeats);
    printf("%zu %zu %zu %.3g %.4g %.4g %.3f %.3f %.1f\n", c.n, c.k, steps, setup, f, b, f / b,
           (double)iterations / (double)taken, peak);
    return 0;
}
