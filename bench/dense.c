/* SPDX-License-Identifier: GPL-3.0-or-later */
/* dense.c — fricreg-bench-dense [OUTDIR]: fricreg_ctx_eval with a dense W whose near-stick set
 * changes on every evaluation, against the same W with the set unchanged.
 *
 * W = B B^T / m + I/4 (B uniform in [-1, 1], m = 500: dense, SPD, moderately conditioned),
 * law (4), eps = 1e-3. Contacts: 35 % deep in the band (|zdot| < eps/2), 5 % just inside its
 * edge (eps (1 - 0.05 u)), 5 % just outside (eps (1 + 0.05 u)), the rest slipping;
 * a_free = -W f* with f* inside the bounds deep in the band and the sliding force elsewhere, so
 * the near-stick forces are mostly unsaturated. Three cases, each 2 WALK evaluations:
 *   - "unchanged": the base velocities, again and again;
 *   - "crossing": a walk of WALK velocity vectors from the base, each moving one or two
 *     contacts (alternately) out across the band's edge and as many in, evaluated forwards
 *     then backwards, so every evaluation changes S by 2 to 4 contacts; what an integrator
 *     sees, since a contact crosses the edge, and the consistent law's force is continuous
 *     there;
 *   - "jumping": the same with contacts jumping between deep in the band and slipping, so the
 *     consistent law's forces jump and its QP needs more iterations: a stress case.
 * Both for the consistent law and the paper's partition. Every figure is the median of
 * REPEATS interleaved timings; the ratio to "unchanged" is the figure to read, with a target
 * of <= 2 (a changing set at most twice the cost of an unchanged one). Prints the table and
 * the counters per evaluation; with OUTDIR, also writes dense.csv there. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"

enum { M = 500, WALK = 64, REPEATS = 11, NPART = 2, NCASES = 3, NWALKS = NCASES - 1 };
#define DENSE_EPS 1e-3
#define EDGE 0.05 /* the band's edge: eps (1 -/+ EDGE u) */

static const int partitions[NPART] = {FRICREG_PARTITION_CONSISTENT, FRICREG_PARTITION_PAPER};
static const char *const partition_names[NPART] = {"consistent", "paper"};
static const char *const case_names[NCASES] = {"unchanged", "crossing", "jumping"};

/* xorshift64*: the same inputs on every machine. */
static uint64_t rng_state = 0x9E3779B97F4A7C15u;
static double uniform(void)
{
    rng_state ^= rng_state >> 12;
    rng_state ^= rng_state << 25;
    rng_state ^= rng_state >> 27;
    return (double)((rng_state * 0x2545F4914F6CDD1Du) >> 11) * 0x1.0p-53;
}

static double sign(void)
{
    return uniform() < 0.5 ? -1.0 : 1.0;
}
static double near_velocity(void)
{
    return sign() * 0.5 * DENSE_EPS * uniform();
}
static double slip_velocity(void)
{
    return sign() * (DENSE_EPS + uniform());
}
static double sign_of(double v)
{
    return v > 0.0 ? 1.0 : -1.0;
}
static int near_edge_inside(double v)
{
    return fabs(v) < DENSE_EPS && fabs(v) >= (1.0 - EDGE) * DENSE_EPS;
}
static int near_edge_outside(double v)
{
    return fabs(v) >= DENSE_EPS && fabs(v) < (1.0 + EDGE) * DENSE_EPS;
}
static int in_band(double v)
{
    return fabs(v) < DENSE_EPS;
}

struct problem {
    double *W, *mun, *a_free, *f;
    double *zdot; /* [NWALKS][WALK][M] the walks of velocity vectors, both from the base */
};

static void make_coupling(double W[])
{
    double *B = malloc((size_t)M * M * sizeof *B);
    for (size_t k = 0; k < (size_t)M * M; k++)
        B[k] = 2.0 * uniform() - 1.0;
    for (size_t i = 0; i < M; i++)
        for (size_t j = 0; j <= i; j++) {
            double s = 0.0;
            for (size_t k = 0; k < M; k++)
                s += B[i * M + k] * B[j * M + k];
            W[i * M + j] = W[j * M + i] = s / M + (i == j ? 0.25 : 0.0);
        }
    free(B);
}

/* A contact index, uniform, that satisfies test in both from and to (not moved yet). */
static size_t pick(const double from[], const double to[], int (*test)(double))
{
    size_t i;
    do
        i = (size_t)(uniform() * M);
    while (!test(from[i]) || !test(to[i]));
    return i;
}

/* zdot of step k+1 from step k: `moves` contacts leave the band and as many enter it, across
 * its edge (crossing) or from anywhere to anywhere (jumping). */
static void walk_step(const double from[], double to[], int moves, int crossing)
{
    memcpy(to, from, M * sizeof *to);
    for (int k = 0; k < moves; k++) {
        if (crossing) {
            size_t out = pick(from, to, near_edge_inside), in = pick(from, to, near_edge_outside);
            to[out] = sign_of(to[out]) * DENSE_EPS * (1.0 + EDGE * uniform());
            to[in] = sign_of(to[in]) * DENSE_EPS * (1.0 - EDGE * (1.0 - uniform()));
        } else {
            size_t out = pick(from, to, in_band);
            size_t in = (size_t)(uniform() * M);
            while (in_band(from[in]) || in_band(to[in]))
                in = (size_t)(uniform() * M);
            to[out] = slip_velocity();
            to[in] = near_velocity();
        }
    }
}

/* The base velocities and the target forces f* (a_free = -W f*). */
static void base_state(struct problem *p, double target[])
{
    for (size_t i = 0; i < M; i++) {
        double u = uniform(), v;
        p->mun[i] = 0.5 + uniform();
        if (u < 0.35)
            v = near_velocity();
        else if (u < 0.40)
            v = sign() * DENSE_EPS * (1.0 - EDGE * (1.0 - uniform()));
        else if (u < 0.45)
            v = sign() * DENSE_EPS * (1.0 + EDGE * uniform());
        else
            v = slip_velocity();
        p->zdot[i] = v;
        target[i] = u < 0.35 ? 0.3 * (2.0 * uniform() - 1.0) * p->mun[i] : -p->mun[i] * sign_of(v);
    }
}

static int problem_init(struct problem *p)
{
    p->W = malloc((size_t)M * M * sizeof *p->W);
    p->mun = malloc(M * sizeof *p->mun);
    p->a_free = malloc(M * sizeof *p->a_free);
    p->f = malloc(M * sizeof *p->f);
    p->zdot = malloc((size_t)NWALKS * WALK * M * sizeof *p->zdot);
    if (!p->W || !p->mun || !p->a_free || !p->f || !p->zdot)
        return FRICREG_ENOMEM;
    make_coupling(p->W);
    double *target = p->f; /* f*, then scratch for the forces */
    base_state(p, target);
    for (size_t i = 0; i < M; i++) {
        double s = 0.0;
        for (size_t j = 0; j < M; j++)
            s += p->W[i * M + j] * target[j];
        p->a_free[i] = -s;
    }
    for (int w = 0; w < NWALKS; w++) {
        double *walk = p->zdot + (size_t)w * WALK * M;
        if (w > 0)
            memcpy(walk, p->zdot, M * sizeof *walk);
        for (int k = 1; k < WALK; k++)
            walk_step(walk + (size_t)(k - 1) * M, walk + (size_t)k * M, 1 + k % 2, w == 0);
    }
    return FRICREG_OK;
}

static void problem_free(struct problem *p)
{
    free(p->W), free(p->mun), free(p->a_free), free(p->f), free(p->zdot);
}

static int make_ctx(const struct problem *p, int partition, fricreg_ctx **ctx)
{
    int status = fricreg_ctx_create(M, ctx);
    if (status == FRICREG_OK)
        status = fricreg_ctx_set_coupling_dense(*ctx, M, p->W);
    if (status == FRICREG_OK)
        status = fricreg_ctx_set_bounds(*ctx, M, p->mun);
    if (status == FRICREG_OK)
        status = fricreg_ctx_set_law(*ctx, FRICREG_LAW_QUINN, DENSE_EPS);
    if (status == FRICREG_OK)
        status = fricreg_ctx_set_partition(*ctx, partition);
    return status;
}

/* One timing: 2 WALK evaluations, a walk forwards and back (case 1, 2) or the base
 * velocities (case 0). Returns CPU ms per evaluation. */
static double time_case(fricreg_ctx *ctx, const struct problem *p, int c, int *status)
{
    const double *walk = p->zdot + (size_t)(c > 0 ? c - 1 : 0) * WALK * M;
    double t0 = bench_cpu_seconds();
    for (int k = 0; k < 2 * WALK && *status == FRICREG_OK; k++) {
        int step = c == 0 ? 0 : k < WALK ? k : 2 * WALK - 1 - k;
        *status = fricreg_ctx_eval(ctx, M, walk + (size_t)step * M, p->a_free, p->f, NULL);
    }
    return 1e3 * (bench_cpu_seconds() - t0) / (2.0 * WALK);
}

static double ms[NPART][NCASES];
enum { NCOUNTED = 4 };
/* near-stick contacts, factorizations, updates, QP iterations */
static double per_eval[NPART][NCASES][NCOUNTED];
static const int counted[NCOUNTED] = {FRICREG_STAT_FEQ_CONTACTS, FRICREG_STAT_FACTORIZATIONS,
                                      FRICREG_STAT_FACTOR_UPDATES, FRICREG_STAT_QP_ITERATIONS};

/* Counters per evaluation of one more (untimed) pass of a case. */
static int count_case(fricreg_ctx *ctx, const struct problem *p, int part, int c)
{
    int status = FRICREG_OK;
    fricreg_ctx_reset_stats(ctx);
    time_case(ctx, p, c, &status);
    for (int k = 0; k < NCOUNTED && status == FRICREG_OK; k++) {
        int64_t n = 0;
        status = fricreg_ctx_get_stat(ctx, counted[k], &n);
        per_eval[part][c][k] = (double)n / (2.0 * WALK);
    }
    return status;
}

static int measure(const struct problem *p)
{
    static double t[NPART][NCASES][REPEATS];
    fricreg_ctx *ctx[NPART] = {NULL};
    int status = FRICREG_OK;
    for (int q = 0; q < NPART && status == FRICREG_OK; q++)
        status = make_ctx(p, partitions[q], &ctx[q]);
    for (int q = 0; q < NPART && status == FRICREG_OK; q++) /* warm up */
        for (int c = 0; c < NCASES; c++)
            time_case(ctx[q], p, c, &status);
    for (int r = 0; r < REPEATS && status == FRICREG_OK; r++)
        for (int q = 0; q < NPART; q++)
            for (int c = 0; c < NCASES; c++)
                t[q][c][r] = time_case(ctx[q], p, c, &status);
    for (int q = 0; q < NPART && status == FRICREG_OK; q++)
        for (int c = 0; c < NCASES && status == FRICREG_OK; c++) {
            ms[q][c] = bench_median(t[q][c], REPEATS);
            status = count_case(ctx[q], p, q, c);
        }
    if (status != FRICREG_OK)
        fprintf(stderr, "fricreg-bench-dense: %s\n",
                ctx[0] ? fricreg_ctx_errmsg(ctx[0]) : fricreg_strerror(status));
    for (int q = 0; q < NPART; q++)
        fricreg_ctx_free(ctx[q]);
    return status;
}

static void print_table(void)
{
    printf("fricreg %s dense-W benchmark: fricreg_ctx_eval, m = %d, W = B B^T/m + I/4, law (4),"
           "\neps = %g, 40%% near stick; S changes by 2 to 4 contacts on every evaluation "
           "(crossing: across\nthe band's edge; jumping: deep in the band <-> slipping); CPU ms "
           "per evaluation, medians\nof %d interleaved timings of %d evaluations\n\n",
           fricreg_version(), M, DENSE_EPS, REPEATS, 2 * WALK);
    printf("%-11s %-12s %9s %8s %9s %9s %9s %9s\n", "partition", "case", "ms/eval", "ratio", "|S|",
           "factors", "updates", "QP iters");
    for (int q = 0; q < NPART; q++)
        for (int c = 0; c < NCASES; c++) {
            printf("%-11s %-12s %9.4f", partition_names[q], case_names[c], ms[q][c]);
            if (c > 0)
                printf(" %8.2f", ms[q][c] / ms[q][0]);
            else
                printf(" %8s", "");
            printf(" %9.1f %9.3f %9.3f %9.3f\n", per_eval[q][c][0], per_eval[q][c][1],
                   per_eval[q][c][2], per_eval[q][c][3]);
        }
    printf("\nratio: to S unchanged (target <= 2); per evaluation: factors,"
           " updates:\nfactorizations and factor updates (contacts added or removed), QP iters:"
           " the consistent\nlaw's active-set iterations\n");
}

static int write_csv(const char *dir)
{
    FILE *csv = bench_open_out("fricreg-bench-dense", dir, "dense.csv");
    if (!csv)
        return 1;
    fprintf(csv, "partition,case,ms_per_eval,ratio,stick,factorizations,updates,qp_iterations\n");
    for (int q = 0; q < NPART; q++)
        for (int c = 0; c < NCASES; c++)
            fprintf(csv, "%s,%s,%.5f,%.4f,%.2f,%.4f,%.4f,%.4f\n", partition_names[q], case_names[c],
                    ms[q][c], ms[q][c] / ms[q][0], per_eval[q][c][0], per_eval[q][c][1],
                    per_eval[q][c][2], per_eval[q][c][3]);
    fclose(csv);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc > 2) {
        fprintf(stderr, "usage: fricreg-bench-dense [OUTDIR]\n");
        return 2;
    }
    struct problem p = {0};
    int status = problem_init(&p);
    if (status == FRICREG_OK)
        status = measure(&p);
    problem_free(&p);
    if (status != FRICREG_OK)
        return 1;
    print_table();
    if (argc == 2 && write_csv(argv[1]) != 0)
        return 1;
    return 0;
}
