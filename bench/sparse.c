/* SPDX-License-Identifier: GPL-3.0-or-later */
/* sparse.c — fricreg-bench-sparse [OUTDIR] [MMAX]: fricreg_ctx_eval with a sparse, banded W
 * (fricreg_ctx_set_coupling_csr) from m = 10^3 to 10^6 contacts, against the dense-W context
 * at m <= 3000 in the same run.
 *
 * W is a chain: contact i coupled to its neighbours within the half-bandwidth, W = D B D with
 * B = tridiag(-0.6, 2.385, -0.6) ("tridiagonal") or B with off-diagonals -0.6 and 0.25 at
 * distances 1 and 2 ("bandwidth 5"), D in [0.75, 1.25) (unequal units): SPD, diagonally
 * dominant. Law (4), eps = 1e-3. Contacts as in bench/dense.c: 35 % deep in the band, 5 %
 * just inside its edge, 5 % just outside, the rest slipping; a_free = -W f* with f* inside the
 * bounds deep in the band and the sliding force elsewhere. Cases, each a series of
 * evaluations:
 *   - "unchanged": the base velocities, again and again;
 *   - "tenth": two velocity vectors in turn, the second with a twentieth of the contacts moved
 *     out across the band's edge and as many in: a tenth of the contacts enter or leave S on
 *     every evaluation (what an integrator sees, in bulk);
 *   - "jumping": the same with contacts jumping between deep in the band and slipping, so that
 *     the consistent law's free set changes by a tenth too: a stress case.
 * For the consistent law and the paper's partition. Every figure is the median of REPEATS
 * interleaved timings (CPU time; the dense context's, DENSE_REPEATS of 2 evaluations), printed per evaluation and per contact; the ratios read
 * against "unchanged" (target: <= 2 for "tenth") and against the dense context at the same m.
 * Targets at m = 10^5: <= 1 us per contact unchanged, <= 2x that with a tenth changing.
 * With OUTDIR (or "-" for none), also writes sparse.csv there; MMAX (default 10^6) and MMIN
 * (default 10^3) bound the sizes. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"

enum {
    REPEATS = 7,
    DENSE_REPEATS = 3,
    NPART = 2,
    NCASES = 3,
    NKINDS = 2,
    NSIZES = 7,
    NCOUNTED = 5
};
#define SPARSE_EPS 1e-3
#define EDGE 0.05
#define DENSE_MAX 3000

static const size_t sizes[NSIZES] = {1000, 3000, 10000, 30000, 100000, 300000, 1000000};
static const int partitions[NPART] = {FRICREG_PARTITION_CONSISTENT, FRICREG_PARTITION_PAPER};
static const char *const partition_names[NPART] = {"consistent", "paper"};
static const char *const case_names[NCASES] = {"unchanged", "tenth", "jumping"};
static const char *const kind_names[NKINDS] = {"tridiagonal", "bandwidth 5"};
static const int counted[NCOUNTED] = {FRICREG_STAT_FEQ_CONTACTS, FRICREG_STAT_FACTORIZATIONS,
                                      FRICREG_STAT_FACTOR_UPDATES, FRICREG_STAT_QP_ITERATIONS,
                                      FRICREG_STAT_SOLVES};

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
static double sign_of(double v)
{
    return v > 0.0 ? 1.0 : -1.0;
}
static double near_velocity(void)
{
    return sign() * 0.5 * SPARSE_EPS * uniform();
}
static double slip_velocity(void)
{
    return sign() * (SPARSE_EPS + uniform());
}

/* One problem: W as CSR (and dense for the baseline), bounds, loads, the three velocity
 * vectors (base, tenth, jumping). */
struct problem {
    size_t m, nnz;
    int64_t *ptr, *ind;
    double *val, *dense;
    double *mun, *a_free, *f, *zdot[NCASES];
};

static double band_entry(int kind, size_t distance)
{
    static const double tri[2] = {2.385, -0.6}, five[3] = {2.385, -0.6, 0.25};
    return kind == 0 ? (distance < 2 ? tri[distance] : 0.0) : (distance < 3 ? five[distance] : 0.0);
}

static int make_coupling(struct problem *p, int kind, int want_dense)
{
    size_t m = p->m, half = kind == 0 ? 1 : 2;
    double *d = malloc(m * sizeof *d);
    p->ptr = malloc((m + 1) * sizeof *p->ptr);
    p->ind = malloc(m * (2 * half + 1) * sizeof *p->ind);
    p->val = malloc(m * (2 * half + 1) * sizeof *p->val);
    p->dense = want_dense ? calloc(m * m, sizeof *p->dense) : NULL;
    if (!d || !p->ptr || !p->ind || !p->val || (want_dense && !p->dense)) {
        free(d);
        return FRICREG_ENOMEM;
    }
    for (size_t i = 0; i < m; i++)
        d[i] = 0.75 + 0.5 * uniform();
    size_t n = 0;
    for (size_t i = 0; i < m; i++) {
        p->ptr[i] = (int64_t)n;
        for (size_t j = i >= half ? i - half : 0; j <= i + half && j < m; j++) {
            double w = d[i] * band_entry(kind, i > j ? i - j : j - i) * d[j];
            p->ind[n] = (int64_t)j;
            p->val[n++] = w;
            if (p->dense)
                p->dense[i * m + j] = w;
        }
    }
    p->ptr[m] = (int64_t)n;
    p->nnz = n;
    free(d);
    return FRICREG_OK;
}

/* The base state (as bench/dense.c), then the "tenth" and "jumping" vectors from it. */
static void make_states(struct problem *p)
{
    size_t m = p->m;
    double *target = p->f;
    for (size_t i = 0; i < m; i++) {
        double u = uniform(), v;
        p->mun[i] = 0.5 + uniform();
        if (u < 0.35)
            v = near_velocity();
        else if (u < 0.40)
            v = sign() * SPARSE_EPS * (1.0 - EDGE * (1.0 - uniform()));
        else if (u < 0.45)
            v = sign() * SPARSE_EPS * (1.0 + EDGE * uniform());
        else
            v = slip_velocity();
        p->zdot[0][i] = v;
        target[i] = u < 0.35 ? 0.3 * (2.0 * uniform() - 1.0) * p->mun[i] : -p->mun[i] * sign_of(v);
    }
    for (size_t i = 0; i < m; i++) { /* a_free = -W f*, by the CSR rows */
        double s = 0.0;
        for (int64_t q = p->ptr[i]; q < p->ptr[i + 1]; q++)
            s += p->val[q] * target[p->ind[q]];
        p->a_free[i] = -s;
    }
    memcpy(p->zdot[1], p->zdot[0], m * sizeof *p->zdot[1]);
    memcpy(p->zdot[2], p->zdot[0], m * sizeof *p->zdot[2]);
    for (size_t i = 0; i < m; i++) { /* a tenth of the contacts move, half of them each way */
        double v = p->zdot[0][i], u = uniform();
        if (u >= 0.1)
            continue;
        int inside = fabs(v) < SPARSE_EPS;
        p->zdot[1][i] = sign_of(v) * SPARSE_EPS *
                        (inside ? 1.0 + EDGE * uniform() : 1.0 - EDGE * (1.0 - uniform()));
        p->zdot[2][i] = inside ? slip_velocity() : near_velocity();
    }
}

static int problem_init(struct problem *p, size_t m, int kind)
{
    memset(p, 0, sizeof *p);
    p->m = m;
    p->mun = malloc(m * sizeof *p->mun);
    p->a_free = malloc(m * sizeof *p->a_free);
    p->f = malloc(m * sizeof *p->f);
    for (int c = 0; c < NCASES; c++)
        p->zdot[c] = malloc(m * sizeof *p->zdot[c]);
    if (!p->mun || !p->a_free || !p->f || !p->zdot[0] || !p->zdot[1] || !p->zdot[2])
        return FRICREG_ENOMEM;
    int status = make_coupling(p, kind, m <= DENSE_MAX);
    if (status == FRICREG_OK)
        make_states(p);
    return status;
}

static void problem_free(struct problem *p)
{
    free(p->ptr), free(p->ind), free(p->val), free(p->dense);
    free(p->mun), free(p->a_free), free(p->f);
    for (int c = 0; c < NCASES; c++)
        free(p->zdot[c]);
}

/* A context with the sparse (dense = 0) or the dense W; set-up CPU seconds into *setup. */
static int make_ctx(const struct problem *p, int dense, int partition, fricreg_ctx **ctx,
                    double *setup)
{
    int status = fricreg_ctx_create(p->m, ctx);
    double t0 = bench_cpu_seconds();
    if (status == FRICREG_OK)
        status = dense ? fricreg_ctx_set_coupling_dense(*ctx, p->m, p->dense)
                       : fricreg_ctx_set_coupling_csr(*ctx, p->m, 0, p->ptr, p->ind, p->val);
    *setup = bench_cpu_seconds() - t0;
    if (status == FRICREG_OK)
        status = fricreg_ctx_set_bounds(*ctx, p->m, p->mun);
    if (status == FRICREG_OK)
        status = fricreg_ctx_set_law(*ctx, FRICREG_LAW_QUINN, SPARSE_EPS);
    if (status == FRICREG_OK)
        status = fricreg_ctx_set_partition(*ctx, partition);
    return status;
}

/* Evaluations per timing: sparse, about 2e6 contacts' worth, at least 4, an even count;
 * dense, 2 (a dense evaluation whose S changed by a tenth costs O(|S|^3): 1-2 s at m = 3000
 * with GSL's reference BLAS). */
static int evals_per_timing(const fricreg_ctx *ctx, size_t m, int dense)
{
    size_t n = 2000000 / m;
    (void)ctx;
    return dense ? 2 : n < 4 ? 4 : (int)(n + n % 2);
}

/* One timing of a case: CPU seconds per evaluation. An untimed evaluation of the base first
 * (the contexts run every case in turn); then "unchanged" evaluates the base again and again,
 * the others their vector and the base in turn, so that every timed evaluation changes S. */
static double time_case(fricreg_ctx *ctx, const struct problem *p, int c, int dense, int *status)
{
    int n = evals_per_timing(ctx, p->m, dense);
    *status = fricreg_ctx_eval(ctx, p->m, p->zdot[0], p->a_free, p->f, NULL);
    double t0 = bench_cpu_seconds();
    for (int k = 0; k < n && *status == FRICREG_OK; k++) {
        const double *zdot = c > 0 && k % 2 == 0 ? p->zdot[c] : p->zdot[0];
        *status = fricreg_ctx_eval(ctx, p->m, zdot, p->a_free, p->f, NULL);
    }
    return (bench_cpu_seconds() - t0) / n;
}

struct result {
    size_t m;
    int kind, dense, partition, status;
    double setup, seconds[NCASES], per_eval[NCASES][NCOUNTED];
};

static int count_case(fricreg_ctx *ctx, const struct problem *p, int c, struct result *r)
{
    int status = FRICREG_OK;
    fricreg_ctx_reset_stats(ctx);
    time_case(ctx, p, c, r->dense, &status);
    for (int k = 0; k < NCOUNTED && status == FRICREG_OK; k++) {
        int64_t n = 0;
        status = fricreg_ctx_get_stat(ctx, counted[k], &n);
        r->per_eval[c][k] = (double)n / evals_per_timing(ctx, p->m, r->dense);
    }
    return status;
}

/* Every case of both partitions, sparse and (m <= 3000) dense, with interleaved repeats. */
static int measure(const struct problem *p, int kind, struct result out[], int *nout)
{
    enum { MAXCTX = 4 };
    static double t[MAXCTX][NCASES][REPEATS];
    fricreg_ctx *ctx[MAXCTX] = {NULL};
    struct result *r = out + *nout;
    int nctx = p->dense ? 4 : 2, status = FRICREG_OK;
    for (int q = 0; q < nctx && status == FRICREG_OK; q++) {
        r[q] = (struct result){p->m, kind, q >= 2, partitions[q % 2], FRICREG_OK, 0, {0}, {{0}}};
        status = make_ctx(p, r[q].dense, r[q].partition, &ctx[q], &r[q].setup);
    }
    for (int q = 0; q < nctx && status == FRICREG_OK; q++) /* warm up: first factorizations */
        for (int c = 0; c < NCASES; c++)
            time_case(ctx[q], p, c, r[q].dense, &status);
    for (int rep = 0; rep < REPEATS && status == FRICREG_OK; rep++)
        for (int q = 0; q < nctx; q++)
            for (int c = 0; c < NCASES && (rep < DENSE_REPEATS || !r[q].dense); c++)
                t[q][c][rep] = time_case(ctx[q], p, c, r[q].dense, &status);
    for (int q = 0; q < nctx && status == FRICREG_OK; q++)
        for (int c = 0; c < NCASES && status == FRICREG_OK; c++) {
            r[q].seconds[c] = bench_median(t[q][c], r[q].dense ? DENSE_REPEATS : REPEATS);
            status = count_case(ctx[q], p, c, &r[q]);
        }
    if (status != FRICREG_OK)
        for (int q = 0; q < nctx; q++)
            if (ctx[q] && fricreg_ctx_errcode(ctx[q]) != FRICREG_OK)
                fprintf(stderr, "fricreg-bench-sparse: m = %zu: %s\n", p->m,
                        fricreg_ctx_errmsg(ctx[q]));
    for (int q = 0; q < nctx; q++)
        fricreg_ctx_free(ctx[q]);
    *nout += nctx;
    return status;
}

/* The dense result of the same m, kind and partition, or NULL. */
static const struct result *dense_twin(const struct result all[], int n, const struct result *r)
{
    for (int k = 0; k < n; k++)
        if (all[k].dense && all[k].m == r->m && all[k].kind == r->kind &&
            all[k].partition == r->partition)
            return &all[k];
    return NULL;
}

static void print_table(const struct result all[], int n)
{
    printf("fricreg %s sparse-W benchmark: fricreg_ctx_eval, W a chain (tridiagonal or "
           "bandwidth 5) given\nas CSR, law (4), eps = %g, 40%% near stick; 'tenth': a tenth of "
           "the contacts enter or\nleave S on every evaluation (across the band's edge), "
           "'jumping': the same, deep in the\nband <-> slipping; CPU time, medians of %d "
           "interleaved timings\n\n",
           fricreg_version(), SPARSE_EPS, REPEATS);
    printf("%-11s %8s %-6s %-10s %-9s %10s %8s %6s %6s %8s %8s %8s %7s\n", "W", "m", "store",
           "partition", "case", "ms/eval", "ns/cont", "x unch", "x dens", "factors", "updates",
           "QP its", "setup s");
    for (int k = 0; k < n; k++) {
        const struct result *r = &all[k], *d = r->dense ? NULL : dense_twin(all, n, r);
        for (int c = 0; c < NCASES; c++) {
            printf("%-11s %8zu %-6s %-10s %-9s %10.3f %8.1f", kind_names[r->kind], r->m,
                   r->dense ? "dense" : "sparse", partition_names[r->partition - 1], case_names[c],
                   1e3 * r->seconds[c], 1e9 * r->seconds[c] / (double)r->m);
            if (c > 0)
                printf(" %6.2f", r->seconds[c] / r->seconds[0]);
            else
                printf(" %6s", "");
            if (d)
                printf(" %6.3f", r->seconds[c] / d->seconds[c]);
            else
                printf(" %6s", "");
            printf(" %8.3f %8.1f %8.2f", r->per_eval[c][1], r->per_eval[c][2], r->per_eval[c][3]);
            printf(c == 0 ? " %7.3f\n" : "\n", r->setup);
        }
    }
    printf("\nns/cont: per contact; x unch: against 'unchanged' (target <= 2 for 'tenth'); "
           "x dens:\nagainst the dense context at the same m; per evaluation: factors "
           "(fresh factorizations),\nupdates (rows added or deleted), QP its (the consistent "
           "law's active-set iterations);\nsetup s: the coupling setter's CPU seconds. Targets "
           "at m = 10^5: <= 1000 ns per contact\nunchanged, <= 2x that with a tenth "
           "changing.\n");
}

static int write_csv(const char *dir, const struct result all[], int n)
{
    FILE *csv = bench_open_out("fricreg-bench-sparse", dir, "sparse.csv");
    if (!csv)
        return 1;
    fprintf(csv, "coupling,m,storage,partition,case,ms_per_eval,ns_per_contact,ratio_unchanged,"
                 "ratio_dense,stick,factorizations,updates,qp_iterations,solves,setup_s\n");
    for (int k = 0; k < n; k++) {
        const struct result *r = &all[k], *d = r->dense ? NULL : dense_twin(all, n, r);
        for (int c = 0; c < NCASES; c++)
            fprintf(csv, "%s,%zu,%s,%s,%s,%.5f,%.2f,%.4f,%.4f,%.1f,%.4f,%.2f,%.3f,%.3f,%.4f\n",
                    kind_names[r->kind], r->m, r->dense ? "dense" : "sparse",
                    partition_names[r->partition - 1], case_names[c], 1e3 * r->seconds[c],
                    1e9 * r->seconds[c] / (double)r->m, r->seconds[c] / r->seconds[0],
                    d ? r->seconds[c] / d->seconds[c] : NAN, r->per_eval[c][0], r->per_eval[c][1],
                    r->per_eval[c][2], r->per_eval[c][3], r->per_eval[c][4], r->setup);
    }
    fclose(csv);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc > 4) {
        fprintf(stderr, "usage: fricreg-bench-sparse [OUTDIR|-] [MMAX [MMIN]]\n");
        return 2;
    }
    size_t m_max = argc >= 3 ? (size_t)strtod(argv[2], NULL) : 1000000;
    size_t m_min = argc >= 4 ? (size_t)strtod(argv[3], NULL) : 1000;
    static struct result all[NKINDS * NSIZES * 4];
    int n = 0, status = FRICREG_OK;
    for (int kind = 0; kind < NKINDS && status == FRICREG_OK; kind++)
        for (int s = 0; s < NSIZES && status == FRICREG_OK && sizes[s] <= m_max; s++) {
            if (sizes[s] < m_min)
                continue;
            struct problem p;
            status = problem_init(&p, sizes[s], kind);
            if (status == FRICREG_OK)
                status = measure(&p, kind, all, &n);
            problem_free(&p);
            fprintf(stderr, "fricreg-bench-sparse: %s, m = %zu done\n", kind_names[kind], sizes[s]);
        }
    if (status != FRICREG_OK)
        return 1;
    print_table(all, n);
    if (argc >= 2 && strcmp(argv[1], "-") != 0 && write_csv(argv[1], all, n) != 0)
        return 1;
    return 0;
}
