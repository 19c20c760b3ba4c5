/* SPDX-License-Identifier: GPL-3.0-or-later */
/* disk_chain.c — fricreg-bench-disk-chain [OUTDIR]: the 2-D context on stuck chains, per
 * evaluation and contact, beside the 1-D context on the same data in the same run.
 *
 * A chain of m contacts: W1 = w tridiag(-1, 2, -1) (the Delassus matrix of a chain whose
 * contacts sit between neighbouring bodies; cond 0.4 m^2), law (4), eps = 1e-3, every
 * contact at rest. Collinear data: every velocity, free acceleration and force along x, so
 * the 2-D context (W = W1 (x) I2, fricreg_disk_ctx_set_coupling_csr) solves the 1-D context's
 * problem and its forces' x components are the 1-D forces (the program prints the largest
 * difference). Two cases: "stuck", every target force inside its bound (a_free = -W1 f*),
 * and "saturating", a tenth of them beyond (those contacts on their bounds, the others'
 * forces moved). Each timing is a walk of the load, WALK states (the targets moved by up to
 * 0.2 % of the bounds each) evaluated forwards then backwards from a warm start, what an
 * integrator's steps ask of a context.
 *
 * The 1-D contexts are a table (one_d below): the dense W1 (fricreg_ctx_set_coupling_dense)
 * up to m = 3000, its O(m^2) memory and O(m^3) set-up being the limit, and the sparse W1
 * (fricreg_ctx_set_coupling_csr) at every size. Sizes 10^2 ... 10^5, to 10^6 with
 * FRICREG_BENCH_BIG=1.
 *
 * Every figure is the median of REPEATS timings, interleaved over the whole sweep (every
 * size and context timed once per pass); the ratio is the 2-D context's CPU time per contact
 * over the 1-D context's. Prints the table; with OUTDIR also writes disk_chain.csv. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <fricreg_disk_ctx.h>

#include "bench.h"

enum { WALK = 8, REPEATS = 7, NCASES = 2, MAX_SIZES = 10 };
#define CHAIN_W 2.385
#define CHAIN_EPS 1e-3
#define DENSE_MAX_M 3000

static const char *const case_names[NCASES] = {"stuck", "saturating"};
static const double case_beyond[NCASES] = {0.0, 0.1}; /* share of targets beyond the bound */

/* xorshift64*: the same inputs on every machine. */
static uint64_t rng_state = 0x9E3779B97F4A7C15u;
static double uniform(double lo, double hi)
{
    rng_state ^= rng_state >> 12;
    rng_state ^= rng_state << 25;
    rng_state ^= rng_state >> 27;
    return lo + (hi - lo) * (double)((rng_state * 0x2545F4914F6CDD1Du) >> 11) * 0x1.0p-53;
}

/* One chain and its load walk, the 1-D data and the 2-D (collinear) data. */
struct chain {
    size_t m;
    double *mun, *zdot1, *walk1; /* walk1: WALK states of a_free, m each */
    double *zdot2, *walk2, *f1, *f2;
    int64_t *ptr, *ind; /* W1 (x) I2 by rows */
    double *val;
};

static void chain_free(struct chain *c)
{
    free(c->mun), free(c->zdot1), free(c->walk1), free(c->zdot2), free(c->walk2);
    free(c->f1), free(c->f2), free(c->ptr), free(c->ind), free(c->val);
}

static void chain_rows(struct chain *c)
{
    int64_t e = 0;
    for (size_t r = 0; r < 2 * c->m; r++) {
        c->ptr[r] = e;
        if (r >= 2)
            c->ind[e] = (int64_t)(r - 2), c->val[e++] = -CHAIN_W;
        c->ind[e] = (int64_t)r, c->val[e++] = 2.0 * CHAIN_W;
        if (r + 2 < 2 * c->m)
            c->ind[e] = (int64_t)(r + 2), c->val[e++] = -CHAIN_W;
    }
    c->ptr[2 * c->m] = e;
}

/* The walk of the load: targets f* (a share `beyond` past their bounds, by 20 to 50 %), each
 * state's moved by up to 0.2 % of the bounds, and a_free = -W1 f*. The load moves through the
 * forces, not through a_free: W1's lowest mode would turn a random change of a_free into
 * forces cond(W1) times larger, no longer a stuck chain. */
static void chain_load(struct chain *c, double beyond)
{
    size_t m = c->m;
    double *target = c->f1;
    for (size_t i = 0; i < m; i++) {
        int past = uniform(0.0, 1.0) < beyond;
        double sign = uniform(0.0, 1.0) < 0.5 ? -1.0 : 1.0;
        target[i] = (past ? sign * uniform(1.2, 1.5) : uniform(-0.9, 0.9)) * c->mun[i];
    }
    for (int k = 0; k < WALK; k++) {
        double *a = c->walk1 + (size_t)k * m;
        for (size_t i = 0; k > 0 && i < m; i++)
            target[i] += 0.002 * c->mun[i] * uniform(-1.0, 1.0);
        for (size_t i = 0; i < m; i++)
            a[i] = -CHAIN_W * (2.0 * target[i] - (i > 0 ? target[i - 1] : 0.0) -
                               (i + 1 < m ? target[i + 1] : 0.0));
    }
    for (size_t k = 0; k < (size_t)WALK * m; k++)
        c->walk2[2 * k] = c->walk1[k], c->walk2[2 * k + 1] = 0.0;
}

static int chain_init(struct chain *c, size_t m, double beyond)
{
    *c = (struct chain){m,
                        malloc(m * sizeof(double)),
                        calloc(m, sizeof(double)),
                        malloc((size_t)WALK * m * sizeof(double)),
                        calloc(2 * m, sizeof(double)),
                        malloc((size_t)WALK * 2 * m * sizeof(double)),
                        malloc(m * sizeof(double)),
                        malloc(2 * m * sizeof(double)),
                        malloc((2 * m + 1) * sizeof(int64_t)),
                        malloc(6 * m * sizeof(int64_t)),
                        malloc(6 * m * sizeof(double))};
    if (!c->mun || !c->zdot1 || !c->walk1 || !c->zdot2 || !c->walk2 || !c->f1 || !c->f2 ||
        !c->ptr || !c->ind || !c->val)
        return FRICREG_ENOMEM;
    for (size_t i = 0; i < m; i++)
        c->mun[i] = uniform(0.5, 1.5);
    chain_rows(c);
    chain_load(c, beyond);
    return FRICREG_OK;
}

/* ---- The 1-D contexts: one row per way of giving W1 -------------------------------------- */

static int couple_dense(fricreg_ctx *ctx, const struct chain *c)
{
    size_t m = c->m;
    double *W1 = calloc(m * m, sizeof *W1);
    if (W1 == NULL)
        return FRICREG_ENOMEM;
    for (size_t i = 0; i < m; i++) {
        W1[i * m + i] = 2.0 * CHAIN_W;
        if (i + 1 < m)
            W1[i * m + i + 1] = W1[(i + 1) * m + i] = -CHAIN_W;
    }
    int status = fricreg_ctx_set_coupling_dense(ctx, m, W1);
    free(W1);
    return status;
}

/* W1 by rows: every other row of W1 (x) I2, its columns halved. */
static int couple_csr(fricreg_ctx *ctx, const struct chain *c)
{
    size_t m = c->m;
    int64_t *ptr = malloc((m + 1) * sizeof *ptr), *ind = malloc(3 * m * sizeof *ind), e = 0;
    double *val = malloc(3 * m * sizeof *val);
    int status = FRICREG_ENOMEM;
    if (ptr && ind && val) {
        for (size_t i = 0; i < m; i++) {
            ptr[i] = e;
            for (int64_t k = c->ptr[2 * i]; k < c->ptr[2 * i + 1]; k++)
                ind[e] = c->ind[k] / 2, val[e++] = c->val[k];
        }
        ptr[m] = e;
        status = fricreg_ctx_set_coupling_csr(ctx, m, FRICREG_SPARSE_ZERO_BASED, ptr, ind, val);
    }
    free(ptr), free(ind), free(val);
    return status;
}

struct one_d {
    const char *name;
    size_t max_m; /* larger chains skip this row */
    int (*couple)(fricreg_ctx *ctx, const struct chain *c);
};

static const struct one_d one_d[] = {
    {"1-D dense", DENSE_MAX_M, couple_dense},
    {"1-D sparse", SIZE_MAX, couple_csr},
};
enum { NONE_D = sizeof one_d / sizeof one_d[0] };

/* ---- One point: a chain, its 2-D context and the 1-D contexts that take it -------------- */

struct point {
    struct chain chain;
    fricreg_disk_ctx *two;
    fricreg_ctx *one[NONE_D];   /* NULL where the row skips this size */
    double t2[REPEATS];         /* seconds per evaluation */
    double t1[NONE_D][REPEATS]; /* likewise */
    double diff[NONE_D];        /* max |f2_x - f1| / mun over the timed walks */
};

static int make_two(struct point *p)
{
    const struct chain *c = &p->chain;
    int status = fricreg_disk_ctx_create(c->m, &p->two);
    if (status == FRICREG_OK)
        status = fricreg_disk_ctx_set_law(p->two, FRICREG_DISK_QUINN, CHAIN_EPS);
    if (status == FRICREG_OK)
        status = fricreg_disk_ctx_set_bounds(p->two, c->m, c->mun);
    if (status == FRICREG_OK)
        status = fricreg_disk_ctx_set_coupling_csr(p->two, c->m, FRICREG_SPARSE_ZERO_BASED, c->ptr,
                                                   c->ind, c->val);
    return status;
}

static int make_one(struct point *p, size_t d)
{
    const struct chain *c = &p->chain;
    if (c->m > one_d[d].max_m)
        return FRICREG_OK;
    int status = fricreg_ctx_create(c->m, &p->one[d]);
    if (status == FRICREG_OK)
        status = fricreg_ctx_set_law(p->one[d], FRICREG_LAW_QUINN, CHAIN_EPS);
    if (status == FRICREG_OK)
        status = fricreg_ctx_set_bounds(p->one[d], c->m, c->mun);
    if (status == FRICREG_OK)
        status = one_d[d].couple(p->one[d], c);
    return status;
}

/* Evaluations per timing: about 2e5 contacts' worth, at least one walk forwards and back. */
static int walks_of(size_t m)
{
    size_t n = 200000 / (2 * WALK * m);
    return n < 1 ? 1 : n > 100 ? 100 : (int)n;
}

/* One timing of the 2-D context (d < 0) or of 1-D row d: seconds per evaluation; compares
 * the forces of the last state with the other context's when both have run it. */
static double time_walks(struct point *p, int d, int *status)
{
    struct chain *c = &p->chain;
    int walks = walks_of(c->m), evals = 0;
    double t0 = bench_cpu_seconds();
    for (int w = 0; w < walks && *status == FRICREG_OK; w++)
        for (int k = 0; k < 2 * WALK && *status == FRICREG_OK; k++, evals++) {
            int s = k < WALK ? k : 2 * WALK - 1 - k;
            if (d < 0)
                *status = fricreg_disk_ctx_eval(p->two, c->m, c->zdot2,
                                                c->walk2 + (size_t)s * 2 * c->m, c->f2);
            else
                *status = fricreg_ctx_eval(p->one[d], c->m, c->zdot1, c->walk1 + (size_t)s * c->m,
                                           c->f1, NULL);
        }
    return (bench_cpu_seconds() - t0) / evals;
}

/* The x components of the 2-D forces against 1-D row d's, both at the walk's first state. */
static int compare(struct point *p, size_t d)
{
    struct chain *c = &p->chain;
    int status = fricreg_ctx_eval(p->one[d], c->m, c->zdot1, c->walk1, c->f1, NULL);
    if (status == FRICREG_OK)
        status = fricreg_disk_ctx_eval(p->two, c->m, c->zdot2, c->walk2, c->f2);
    for (size_t i = 0; status == FRICREG_OK && i < c->m; i++)
        p->diff[d] = fmax(p->diff[d], fabs(c->f2[2 * i] - c->f1[i]) / c->mun[i]);
    return status;
}

static size_t sizes[MAX_SIZES];
static size_t nsizes;
static struct point points[NCASES][MAX_SIZES];

static int setup(void)
{
    int status = FRICREG_OK;
    for (int q = 0; q < NCASES; q++)
        for (size_t s = 0; s < nsizes && status == FRICREG_OK; s++) {
            struct point *p = &points[q][s];
            status = chain_init(&p->chain, sizes[s], case_beyond[q]);
            if (status == FRICREG_OK)
                status = make_two(p);
            for (size_t d = 0; d < NONE_D && status == FRICREG_OK; d++)
                status = make_one(p, d);
            for (size_t d = 0; d < NONE_D && status == FRICREG_OK; d++)
                if (p->one[d] != NULL) /* also the cold start, before the timings */
                    status = compare(p, d);
            if (status != FRICREG_OK)
                fprintf(stderr, "fricreg-bench-disk-chain: %s, m = %zu: %s\n", case_names[q],
                        sizes[s], p->two ? fricreg_disk_ctx_errmsg(p->two) : "");
        }
    return status;
}

/* REPEATS passes over every point and context. */
static int measure(void)
{
    int status = FRICREG_OK;
    for (int r = 0; r < REPEATS && status == FRICREG_OK; r++)
        for (int q = 0; q < NCASES; q++)
            for (size_t s = 0; s < nsizes && status == FRICREG_OK; s++) {
                struct point *p = &points[q][s];
                p->t2[r] = time_walks(p, -1, &status);
                for (size_t d = 0; d < NONE_D && status == FRICREG_OK; d++)
                    if (p->one[d] != NULL)
                        p->t1[d][r] = time_walks(p, (int)d, &status);
            }
    for (int q = 0; q < NCASES; q++)
        for (size_t s = 0; s < nsizes && status == FRICREG_OK; s++)
            for (size_t d = 0; d < NONE_D && status == FRICREG_OK; d++)
                if (points[q][s].one[d] != NULL)
                    status = compare(&points[q][s], d);
    if (status != FRICREG_OK)
        fprintf(stderr, "fricreg-bench-disk-chain: an evaluation failed (%s)\n",
                fricreg_strerror(status));
    return status;
}

static double ns_per_contact(double t[], size_t m)
{
    return 1e9 * bench_median(t, REPEATS) / (double)m;
}

static void print_table(void)
{
    printf("fricreg %s 2-D context on stuck chains: W1 = %g tridiag(-1, 2, -1), W = W1 (x) I2 "
           "by\ncompressed rows, law (4), eps = %g, every contact at rest, collinear data; CPU ns "
           "per\nevaluation and contact, medians of %d interleaved timings of a walk of the load "
           "(%d states,\nforwards and back, warm-started); ratio: 2-D over 1-D per contact; "
           "diff: max |f_x(2-D) - f(1-D)|/mun\n\n",
           fricreg_version(), CHAIN_W, CHAIN_EPS, REPEATS, WALK);
    printf("%-11s %8s %10s", "case", "m", "2-D");
    for (size_t d = 0; d < NONE_D; d++)
        printf(" %12s %7s %9s", one_d[d].name, "ratio", "diff");
    printf("\n");
    for (int q = 0; q < NCASES; q++)
        for (size_t s = 0; s < nsizes; s++) {
            struct point *p = &points[q][s];
            double ns2 = ns_per_contact(p->t2, sizes[s]);
            printf("%-11s %8zu %10.1f", case_names[q], sizes[s], ns2);
            for (size_t d = 0; d < NONE_D; d++) {
                if (p->one[d] == NULL) {
                    printf(" %12s %7s %9s", "-", "-", "-");
                    continue;
                }
                double ns1 = ns_per_contact(p->t1[d], sizes[s]);
                printf(" %12.1f %7.3f %9.2g", ns1, ns2 / ns1, p->diff[d]);
            }
            printf("\n");
        }
}

static int write_csv(const char *dir)
{
    FILE *csv = bench_open_out("fricreg-bench-disk-chain", dir, "disk_chain.csv");
    if (!csv)
        return 1;
    fprintf(csv, "case,m,context,ns_per_contact,ratio_2d_to_this,max_diff\n");
    for (int q = 0; q < NCASES; q++)
        for (size_t s = 0; s < nsizes; s++) {
            struct point *p = &points[q][s];
            double ns2 = ns_per_contact(p->t2, sizes[s]);
            fprintf(csv, "%s,%zu,2-D,%.2f,,\n", case_names[q], sizes[s], ns2);
            for (size_t d = 0; d < NONE_D; d++)
                if (p->one[d] != NULL) {
                    double ns1 = ns_per_contact(p->t1[d], sizes[s]);
                    fprintf(csv, "%s,%zu,%s,%.2f,%.4f,%.3g\n", case_names[q], sizes[s],
                            one_d[d].name, ns1, ns2 / ns1, p->diff[d]);
                }
        }
    fclose(csv);
    return 0;
}

static void release(void)
{
    for (int q = 0; q < NCASES; q++)
        for (size_t s = 0; s < nsizes; s++) {
            struct point *p = &points[q][s];
            chain_free(&p->chain);
            fricreg_disk_ctx_free(p->two);
            for (size_t d = 0; d < NONE_D; d++)
                fricreg_ctx_free(p->one[d]);
        }
}

int main(int argc, char **argv)
{
    if (argc > 2) {
        fprintf(stderr, "usage: fricreg-bench-disk-chain [OUTDIR]\n");
        return 2;
    }
    const char *big = getenv("FRICREG_BENCH_BIG");
    double top = big != NULL && strcmp(big, "1") == 0 ? 1e6 : 1e5;
    for (double m = 100.0; m <= top * 1.01 && nsizes < MAX_SIZES; m *= sqrt(10.0))
        sizes[nsizes++] = (size_t)(m < 1000.0 ? floor(m / 10.0 + 0.5) * 10.0
                                              : floor(m / 1000.0 + 0.5) * 1000.0);
    int status = setup();
    if (status == FRICREG_OK)
        status = measure();
    if (status == FRICREG_OK)
        print_table();
    if (status == FRICREG_OK && argc == 2 && write_csv(argv[1]) != 0)
        status = FRICREG_EINVAL;
    release();
    return status == FRICREG_OK ? 0 : 1;
}
