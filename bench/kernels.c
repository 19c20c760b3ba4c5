/* SPDX-License-Identifier: GPL-3.0-or-later */
/* kernels.c — fricreg-bench-kernels [OUTDIR]: the law kernels against the roofline.
 *
 * ns per contact of fricreg_law_eval_batch (law (4)) and fricreg_ctx_eval (W = I, law (4)),
 * each beside a minimal loop of the same math (minimal.c: no validation, no bookkeeping) and
 * STREAM's triad a = b + s c, at m = 10^3 contacts (in cache, swept many times per timing)
 * and m = 10^6 (40 MB of arrays: memory traffic counts). Inputs as bench/scaling.c: 40 %
 * stuck (v = 0), 20 % near stick (|v| < eps), 40 % slipping, in random order, fixed seed.
 * fricreg_ctx_eval runs as created, and with fricreg_ctx_set_keep_tangent(0) (no copies of
 * zdot and a_free for the tangent). Where the library runs AVX2 kernels (src/base/dispatch.h), the
 * minimal loops compiled for AVX2 too. Every figure is the median of REPEATS interleaved
 * timings.
 * Prints the table and the ratios to the minimal loops; with OUTDIR, also writes kernels.csv
 * there. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "bench.h"
#include "minimal.h"

enum { NSIZES = 2, REPEATS = 21, NITEMS = 10 };
static const size_t sizes[NSIZES] = {1000, 1000000};
#define KERNEL_EPS 1e-3
#define CONTACTS_PER_TIMING 4e6 /* small sizes are swept until a timing covers this many */

/* What each item is; the minimal loop it is compared with (-1: none). */
enum item {
    TRIAD,
    MIN_BATCH,
    BATCH,
    MIN_CTX,
    MIN_CTX_COPIES,
    CTX,
    CTX_FEQ,
    CTX_NO_TANGENT,
    MIN_BATCH_AVX2,
    MIN_CTX_AVX2
};
static const char *const item_names[NITEMS] = {
    "triad a = b + s c (per element)",      "minimal loop, law (4)",
    "fricreg_law_eval_batch, law (4)",      "minimal loop, law (4), f_eq = -a/w",
    "  the same + copies of v, a_free",     "fricreg_ctx_eval, W = I, law (4)",
    "fricreg_ctx_eval, the same, f_eq out", "fricreg_ctx_eval, no tangent inputs",
    "minimal loop, law (4), AVX2",          "minimal loop, f_eq = -a/w, AVX2"};
static const int item_yardstick[NITEMS] = {-1,      -1,      MIN_BATCH, -1, MIN_CTX,
                                           MIN_CTX, MIN_CTX, MIN_CTX,   -1, -1};

struct arrays {
    size_t m;
    double *v, *f_eq, *mun, *a_free, *w, *f, *f_eq_out, *v_copy, *a_copy;
    fricreg_ctx *ctx, *ctx_no_tangent; /* the second: fricreg_ctx_set_keep_tangent(0) */
};

/* xorshift64*: the same inputs on every machine. */
static uint64_t rng_state = 0x9E3779B97F4A7C15u;
static double uniform(void)
{
    rng_state ^= rng_state >> 12;
    rng_state ^= rng_state << 25;
    rng_state ^= rng_state >> 27;
    return (double)((rng_state * 0x2545F4914F6CDD1Du) >> 11) * 0x1.0p-53;
}

static void fill_inputs(struct arrays *a)
{
    for (size_t i = 0; i < a->m; i++) {
        double u = uniform(), sign = uniform() < 0.5 ? -1.0 : 1.0;
        a->v[i] = u < 0.4   ? 0.0
                  : u < 0.6 ? sign * KERNEL_EPS * uniform()
                            : sign * (KERNEL_EPS + (1.0 - KERNEL_EPS) * uniform());
        a->mun[i] = 0.5 + uniform();
        a->f_eq[i] = (4.0 * uniform() - 2.0) * a->mun[i];
        a->a_free[i] = -a->f_eq[i]; /* W = I: f_eq = -a_free */
        a->w[i] = 1.0;
    }
}

static int arrays_init(struct arrays *a, size_t m)
{
    double **p[] = {&a->v, &a->f_eq,     &a->mun,    &a->a_free, &a->w,
                    &a->f, &a->f_eq_out, &a->v_copy, &a->a_copy};
    int ok = 1;
    a->m = m;
    a->ctx = a->ctx_no_tangent = NULL;
    for (size_t k = 0; k < sizeof p / sizeof p[0]; k++)
        ok &= (*p[k] = malloc(m * sizeof **p[k])) != NULL;
    if (!ok)
        return FRICREG_ENOMEM;
    fill_inputs(a);
    int status = FRICREG_OK;
    fricreg_ctx **ctx[2] = {&a->ctx, &a->ctx_no_tangent};
    for (int c = 0; c < 2 && status == FRICREG_OK; c++) {
        status = fricreg_ctx_create(m, ctx[c]); /* W = I until set otherwise */
        if (status == FRICREG_OK)
            status = fricreg_ctx_set_bounds(*ctx[c], m, a->mun);
        if (status == FRICREG_OK)
            status = fricreg_ctx_set_law(*ctx[c], FRICREG_LAW_QUINN, KERNEL_EPS);
    }
    if (status == FRICREG_OK)
        status = fricreg_ctx_set_keep_tangent(a->ctx_no_tangent, 0);
    return status;
}

static void arrays_free(struct arrays *a)
{
    free(a->v), free(a->f_eq), free(a->mun), free(a->a_free), free(a->w), free(a->f);
    free(a->f_eq_out), free(a->v_copy), free(a->a_copy);
    fricreg_ctx_free(a->ctx);
    fricreg_ctx_free(a->ctx_no_tangent);
}

/* One pass of item it over the arrays; returns a fricreg status. */
static int run_item(int it, struct arrays *a)
{
    size_t m = a->m;
    switch (it) {
    case TRIAD: minimal_triad(m, a->f, a->v, a->mun, 1.0001); return FRICREG_OK;
    case MIN_BATCH: minimal_quinn(KERNEL_EPS, m, a->v, a->f_eq, a->mun, a->f); return FRICREG_OK;
    case BATCH:
        return fricreg_law_eval_batch(FRICREG_LAW_QUINN, KERNEL_EPS, m, a->v, a->f_eq, a->mun,
                                      a->f);
    case MIN_CTX:
        minimal_quinn_diagonal(KERNEL_EPS, m, a->v, a->a_free, a->w, a->mun, a->f);
        return FRICREG_OK;
    case MIN_CTX_COPIES:
        minimal_quinn_diagonal_copies(KERNEL_EPS, m, a->v, a->a_free, a->w, a->mun, a->f, a->v_copy,
                                      a->a_copy);
        return FRICREG_OK;
    case MIN_BATCH_AVX2: /* the portable loop where AVX2 is not there (the table says n/a) */
        if (minimal_have_avx2())
            minimal_quinn_avx2(KERNEL_EPS, m, a->v, a->f_eq, a->mun, a->f);
        else
            minimal_quinn(KERNEL_EPS, m, a->v, a->f_eq, a->mun, a->f);
        return FRICREG_OK;
    case MIN_CTX_AVX2:
        if (minimal_have_avx2())
            minimal_quinn_diagonal_avx2(KERNEL_EPS, m, a->v, a->a_free, a->w, a->mun, a->f);
        else
            minimal_quinn_diagonal(KERNEL_EPS, m, a->v, a->a_free, a->w, a->mun, a->f);
        return FRICREG_OK;
    case CTX: return fricreg_ctx_eval(a->ctx, m, a->v, a->a_free, a->f, NULL);
    case CTX_NO_TANGENT: return fricreg_ctx_eval(a->ctx_no_tangent, m, a->v, a->a_free, a->f, NULL);
    default: return fricreg_ctx_eval(a->ctx, m, a->v, a->a_free, a->f, a->f_eq_out);
    }
}

/* CPU ns per contact of one timing of item it: enough sweeps to cover CONTACTS_PER_TIMING. */
static double time_item(int it, struct arrays *a, int *status)
{
    int sweeps = (int)fmax(1.0, CONTACTS_PER_TIMING / (double)a->m);
    double t0 = bench_cpu_seconds();
    for (int k = 0; k < sweeps && *status == FRICREG_OK; k++)
        *status = run_item(it, a);
    return 1e9 * (bench_cpu_seconds() - t0) / ((double)sweeps * (double)a->m);
}

static double ns[NSIZES][NITEMS];

static int measure(void)
{
    static double t[NSIZES][NITEMS][REPEATS];
    struct arrays a[NSIZES] = {{0}};
    int status = FRICREG_OK;
    for (int z = 0; z < NSIZES && status == FRICREG_OK; z++)
        status = arrays_init(&a[z], sizes[z]);
    for (int z = 0; z < NSIZES && status == FRICREG_OK; z++) /* warm up: page in, settle */
        for (int it = 0; it < NITEMS; it++)
            time_item(it, &a[z], &status);
    for (int r = 0; r < REPEATS && status == FRICREG_OK; r++)
        for (int z = 0; z < NSIZES; z++)
            for (int it = 0; it < NITEMS; it++)
                t[z][it][r] = time_item(it, &a[z], &status);
    for (int z = 0; z < NSIZES && status == FRICREG_OK; z++)
        for (int it = 0; it < NITEMS; it++)
            ns[z][it] = bench_median(t[z][it], REPEATS);
    if (status != FRICREG_OK)
        fprintf(stderr, "fricreg-bench-kernels: %s\n", fricreg_strerror(status));
    for (int z = 0; z < NSIZES; z++)
        arrays_free(&a[z]);
    return status;
}

/* Bytes each item moves per contact, counted as STREAM counts (reads + writes, no
 * write-allocate): the bandwidth bound is bytes / (triad's bytes per ns). fricreg_ctx_eval
 * also keeps copies of zdot and a_free for fricreg_ctx_tangent. */
static const double item_bytes[NITEMS] = {24, 32, 32, 40, 56, 56, 64, 40, 32, 40};

static void print_table(void)
{
    printf("fricreg %s kernel benchmark: CPU ns per contact, medians of %d interleaved "
           "timings;\neps = %g, contacts 40%% stuck, 20%% near stick, 40%% slipping\n\n",
           fricreg_version(), REPEATS, KERNEL_EPS);
    printf("%-38s %11s %8s %11s %8s\n", "", "m = 10^3", "ratio", "m = 10^6", "ratio");
    for (int it = 0; it < NITEMS; it++) {
        printf("%-38s", item_names[it]);
        for (int z = 0; z < NSIZES; z++) {
            int y = item_yardstick[it];
            printf(" %11.3f", ns[z][it]);
            if (y >= 0)
                printf(" %8.2f", ns[z][it] / ns[z][y]);
            else
                printf(" %8s", "");
        }
        printf("\n");
    }
    printf("\nratio: to the minimal loop of the same math, the first above it (target <= 1.5);"
           "\nfricreg_ctx_eval / (minimal + copies): m = 10^3 %.2f, m = 10^6 %.2f\n",
           ns[0][CTX] / ns[0][MIN_CTX_COPIES], ns[1][CTX] / ns[1][MIN_CTX_COPIES]);
    if (minimal_have_avx2()) /* the library runs its AVX2 kernels here: the ratios to those */
        printf("to the minimal loops in AVX2 (the code the library dispatches to here): batch "
               "%.2f / %.2f, ctx_eval %.2f / %.2f, no tangent inputs %.2f / %.2f\n",
               ns[0][BATCH] / ns[0][MIN_BATCH_AVX2], ns[1][BATCH] / ns[1][MIN_BATCH_AVX2],
               ns[0][CTX] / ns[0][MIN_CTX_AVX2], ns[1][CTX] / ns[1][MIN_CTX_AVX2],
               ns[0][CTX_NO_TANGENT] / ns[0][MIN_CTX_AVX2],
               ns[1][CTX_NO_TANGENT] / ns[1][MIN_CTX_AVX2]);
    else
        printf("minimal loops in AVX2: n/a (not built with FRICREG_AVX2_DISPATCH, or no AVX2 "
               "here; those rows ran the portable loops)\n");
    for (int z = 0; z < NSIZES; z++) {
        double bw = item_bytes[TRIAD] / ns[z][TRIAD];
        printf("m = %-8zu triad %.1f GB/s; bandwidth bound (STREAM bytes / triad rate): batch "
               "%.3f ns, ctx_eval %.3f ns (with its copies)\n",
               sizes[z], bw, item_bytes[BATCH] / bw, item_bytes[CTX] / bw);
    }
}

static int write_csv(const char *dir)
{
    FILE *csv = bench_open_out("fricreg-bench-kernels", dir, "kernels.csv");
    if (!csv)
        return 1;
    fprintf(csv, "item,m,ns_per_contact,ratio_to_minimal\n");
    for (int z = 0; z < NSIZES; z++)
        for (int it = 0; it < NITEMS; it++) {
            int y = item_yardstick[it];
            fprintf(csv, "\"%s\",%zu,%.4f,%.4f\n", item_names[it], sizes[z], ns[z][it],
                    y >= 0 ? ns[z][it] / ns[z][y] : NAN);
        }
    fclose(csv);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc > 2) {
        fprintf(stderr, "usage: fricreg-bench-kernels [OUTDIR]\n");
        return 2;
    }
    if (measure() != FRICREG_OK)
        return 1;
    print_table();
    if (argc == 2 && write_csv(argv[1]) != 0)
        return 1;
    return 0;
}
