/* SPDX-License-Identifier: GPL-3.0-or-later */
/* solve_step.c — fricreg-bench-solve-step [OUTDIR]: the per-call time of fricreg_ctx_solve_step
 * over a run of steps, with the solver the context keeps between calls ("kept") against the
 * same call with a solver built for it ("built"), which is what every call cost before the
 * context kept one: start CHOLMOD, copy W and W_eff, analyse W_eff's pattern, allocate.
 *
 * Both in the same run, interleaved step by step on two contexts set up alike: the built one
 * has fricreg_ctx_set_law called (untimed) before each call, which drops its kept solver. A new
 * context per call would time its set-up too (set_coupling_dense's eigenvalue check is
 * O(m^3)), and a new context's evaluations can differ from an old one's in the last bit (the
 * consistent law's QP warm start), whereas these two give the same forces, checked bit for bit
 * at every step. Two sizes:
 *   - m = 10, dense W (a 10-storey building's dampers: W = J M^-1 J^T of a shear chain,
 *     tridiagonal, its W_eff dense), RUN_SMALL steps;
 *   - m = 2000, a diagonal W (contacts on separate masses) and a banded W_eff (half-bandwidth
 *     2: neighbours coupled through the stiffness), RUN_LARGE steps.
 * Law (4), eps = 1e-3; the velocities are a travelling wave of amplitude 3 eps, so the stick
 * set changes from step to step; W_eff's values change every step on the large run (a
 * structure whose K_eff changes, the worst case for the kept factor) and are constant on the
 * small one (a linear structure at a fixed dt). Each context's guess is its previous forces.
 * A third context makes the same calls by fricreg_ctx_solve_step_matrix ("sparse", its solver
 * kept too), W and W_eff given by their nonzeros, whole, in CSR: the caller's arrays, built outside
 * the timing (a code that assembles sparse matrices has them), its forces checked bit for bit
 * against the dense call's. The dense call reads 2 m^2 doubles a call, the sparse one
 * O(nnz). Prints the median per-call time of each and their ratios; with OUTDIR, writes
 * solve_step.csv there. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <fricreg_structure.h>

#include "bench.h"

enum { RUN_SMALL = 2000, RUN_LARGE = 40 };
#define STEP_EPS 1e-3
#define PI 3.14159265358979323846

struct size_case {
    const char *name;
    size_t m;
    int steps;
    int diagonal_w;   /* W diagonal, else the shear chain's tridiagonal W */
    size_t band;      /* W_eff's half-bandwidth; m: dense */
    int weff_changes; /* W_eff's values change every step */
};

static const struct size_case cases[] = {
    {"building, m = 10, dense W_eff", 10, RUN_SMALL, 0, 10, 0},
    {"banded, m = 2000, banded W_eff", 2000, RUN_LARGE, 1, 2, 1},
};

/* W: the shear chain's J M^-1 J^T (storey masses 1.3 + 0.1 (i mod 3)): tridiagonal,
 * W_ii = 1/m_i + 1/m_{i-1}, W_i,i-1 = -1/m_{i-1}; or its diagonal alone. */
static void make_w(const struct size_case *sc, double W[])
{
    size_t m = sc->m;
    memset(W, 0, m * m * sizeof *W);
    for (size_t i = 0; i < m; i++) {
        double inv = 1.0 / (1.3 + 0.1 * (double)(i % 3));
        double inv_below = i > 0 ? 1.0 / (1.3 + 0.1 * (double)((i - 1) % 3)) : 0.0;
        W[i * m + i] = inv + inv_below;
        if (i > 0 && !sc->diagonal_w)
            W[i * m + i - 1] = W[(i - 1) * m + i] = -inv_below;
    }
}

/* W_eff at step k: within the band, 0.05 (1 + 0.1 sin k) times a diagonally dominant banded
 * matrix (SPD by Gershgorin); constant in k unless the case changes it. */
static void make_weff(const struct size_case *sc, int k, double Weff[])
{
    size_t m = sc->m, band = sc->band;
    double scale = 0.05 * (sc->weff_changes ? 1.0 + 0.1 * sin((double)k) : 1.0);
    for (size_t i = 0; i < m; i++)
        for (size_t j = 0; j < m; j++) {
            size_t d = i > j ? i - j : j - i;
            Weff[i * m + j] = d > band ? 0.0
                              : d == 0 ? scale * (1.0 + 0.5 * (double)band)
                                       : scale * 0.4 / (double)(d + 1);
        }
}

/* A's nonzeros (and its diagonal), whole, zero-based CSR; val and ind hold nnz(A). */
static void to_csr(size_t m, const double A[], int64_t ptr[], int64_t ind[], double val[])
{
    int64_t p = 0;
    for (size_t i = 0; i < m; i++) {
        ptr[i] = p;
        for (size_t j = 0; j < m; j++)
            if (i == j || A[i * m + j] != 0.0) {
                ind[p] = (int64_t)j;
                val[p++] = A[i * m + j];
            }
    }
    ptr[m] = p;
}

static size_t nonzeros(size_t m, const double A[])
{
    size_t n = 0;
    for (size_t i = 0; i < m; i++)
        for (size_t j = 0; j < m; j++)
            n += i == j || A[i * m + j] != 0.0;
    return n;
}

/* The sparse side's arrays: W's and W_eff's CSR. */
struct csr_pair {
    int64_t *wp, *wi, *ep, *ei;
    double *wv, *ev;
};

static int csr_alloc(struct csr_pair *c, size_t m, size_t nnz_w, size_t nnz_eff)
{
    c->wp = malloc((m + 1) * sizeof *c->wp);
    c->ep = malloc((m + 1) * sizeof *c->ep);
    c->wi = malloc(nnz_w * sizeof *c->wi);
    c->ei = malloc(nnz_eff * sizeof *c->ei);
    c->wv = malloc(nnz_w * sizeof *c->wv);
    c->ev = malloc(nnz_eff * sizeof *c->ev);
    return c->wp && c->ep && c->wi && c->ei && c->wv && c->ev;
}

static void csr_free(struct csr_pair *c)
{
    free(c->wp), free(c->ep), free(c->wi), free(c->ei), free(c->wv), free(c->ev);
}

static fricreg_ctx *context(const struct size_case *sc, const double W[], const double mun[])
{
    size_t m = sc->m;
    fricreg_ctx *ctx = NULL;
    double *w = malloc(m * sizeof *w);
    int ok = w != NULL && fricreg_ctx_create(m, &ctx) == FRICREG_OK;
    if (ok) {
        for (size_t i = 0; i < m; i++)
            w[i] = W[i * m + i];
        ok = fricreg_ctx_set_law(ctx, FRICREG_LAW_QUINN, STEP_EPS) == FRICREG_OK &&
             fricreg_ctx_set_bounds(ctx, m, mun) == FRICREG_OK &&
             (sc->diagonal_w ? fricreg_ctx_set_coupling_diagonal(ctx, m, w)
                             : fricreg_ctx_set_coupling_dense(ctx, m, W)) == FRICREG_OK;
    }
    free(w);
    if (!ok) {
        fricreg_ctx_free(ctx);
        return NULL;
    }
    return ctx;
}

/* One size: the three contexts step by step; medians into *kept, *built, *sparse; the steps
 * whose forces or info differ (built or sparse against kept) into *differ. 0 on success. */
static int run_case(const struct size_case *sc, double *kept, double *built, double *sparse,
                    int *differ, double *iters)
{
    size_t m = sc->m;
    int steps = sc->steps;
    double *W = malloc(m * m * sizeof *W), *Weff = malloc(m * m * sizeof *Weff);
    double *vec = malloc(7 * m * sizeof *vec);
    double *t_kept = malloc((size_t)steps * sizeof *t_kept);
    double *t_built = malloc((size_t)steps * sizeof *t_built);
    double *t_sparse = malloc((size_t)steps * sizeof *t_sparse);
    struct csr_pair csr = {0};
    if (!W || !Weff || !vec || !t_kept || !t_built || !t_sparse) {
        free(W), free(Weff), free(vec), free(t_kept), free(t_built), free(t_sparse);
        return 1;
    }
    double *mun = vec, *z0 = vec + m, *zp = vec + 2 * m, *ap = vec + 3 * m;
    double *f_kept = vec + 4 * m, *f_built = vec + 5 * m, *f_sparse = vec + 6 * m;
    make_w(sc, W);
    make_weff(sc, 0, Weff); /* its pattern is every step's */
    int status = !csr_alloc(&csr, m, nonzeros(m, W), nonzeros(m, Weff));
    if (status == 0)
        to_csr(m, W, csr.wp, csr.wi, csr.wv);
    for (size_t i = 0; i < m; i++) {
        mun[i] = 0.8 + 0.4 * (double)(i % 5) / 4.0;
        f_kept[i] = f_built[i] = f_sparse[i] = 0.0;
        z0[i] = 0.0;
    }
    fricreg_ctx *a = context(sc, W, mun), *b = context(sc, W, mun), *c = context(sc, W, mun);
    status |= a == NULL || b == NULL || c == NULL;
    *differ = 0;
    long total_iters = 0;
    for (int k = 0; k < steps && status == 0; k++) {
        make_weff(sc, k, Weff);
        for (size_t i = 0; i < m; i++) {
            double phase = 2.0 * PI * (0.013 * k - 0.37 * (double)i);
            zp[i] = 3.0 * STEP_EPS * sin(phase);
            ap[i] = 1.5 * cos(phase + 0.5);
        }
        to_csr(m, Weff, csr.ep, csr.ei, csr.ev);
        int info_a[2], info_b[2], info_c[2];
        double t0 = bench_cpu_seconds();
        int sa = fricreg_ctx_solve_step(a, m, z0, zp, ap, W, Weff, 0.005, 1e-10, 50, 0, f_kept,
                                        info_a);
        double t1 = bench_cpu_seconds();
        fricreg_ctx_set_law(b, FRICREG_LAW_QUINN, STEP_EPS); /* drops b's kept solver */
        double t2 = bench_cpu_seconds();
        int sb = fricreg_ctx_solve_step(b, m, z0, zp, ap, W, Weff, 0.005, 1e-10, 50, 0, f_built,
                                        info_b);
        double t3 = bench_cpu_seconds();
        int sc_ = fricreg_ctx_solve_step_matrix(c, m, z0, zp, ap, FRICREG_MATRIX_CSR, csr.wp,
                                                csr.wi, csr.wv, csr.ep, csr.ei, csr.ev, 0.005,
                                                1e-10, 50, 0, f_sparse, info_c);
        double t4 = bench_cpu_seconds();
        if (sa != FRICREG_OK || sb != FRICREG_OK || sc_ != FRICREG_OK) {
            fprintf(stderr, "fricreg-bench-solve-step: step %d: %s\n", k,
                    fricreg_ctx_errmsg(sa != FRICREG_OK   ? a
                                       : sb != FRICREG_OK ? b
                                                          : c));
            status = 1;
            break;
        }
        t_kept[k] = t1 - t0;
        t_built[k] = t3 - t2;
        t_sparse[k] = t4 - t3;
        total_iters += info_a[0];
        *differ += memcmp(f_kept, f_built, m * sizeof *f_kept) != 0 ||
                   memcmp(info_a, info_b, sizeof info_a) != 0 ||
                   memcmp(f_kept, f_sparse, m * sizeof *f_kept) != 0 ||
                   memcmp(info_a, info_c, sizeof info_a) != 0;
        memcpy(z0, zp, m * sizeof *z0); /* the next step starts where this one ended */
    }
    if (status == 0) {
        *kept = bench_median(t_kept, (size_t)steps);
        *built = bench_median(t_built, (size_t)steps);
        *sparse = bench_median(t_sparse, (size_t)steps);
        *iters = (double)total_iters / steps;
    }
    fricreg_ctx_free(a);
    fricreg_ctx_free(b);
    fricreg_ctx_free(c);
    csr_free(&csr);
    free(W), free(Weff), free(vec), free(t_kept), free(t_built), free(t_sparse);
    return status;
}

int main(int argc, char **argv)
{
    FILE *csv = argc > 1 ? bench_open_out("fricreg-bench-solve-step", argv[1], "solve_step.csv")
                         : NULL;
    if (argc > 1 && csv == NULL)
        return 1;
    if (csv != NULL)
        fprintf(csv, "case,m,steps,kept_us,built_us,ratio,sparse_us,kept_over_sparse,"
                     "newton_iters,steps_differing\n");
    printf("fricreg_ctx_solve_step per call: the solver kept in the context against one built "
           "per call, and fricreg_ctx_solve_step_matrix in CSR (kept) on the same matrices (median "
           "CPU "
           "time)\n");
    printf("%-34s %6s %12s %12s %8s %12s %11s %8s %8s\n", "case", "steps", "kept (us)",
           "built (us)", "built/kept", "sparse (us)", "kept/sparse", "iters", "differ");
    int status = 0;
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        double kept = 0.0, built = 0.0, sparse = 0.0, iters = 0.0;
        int differ = 0;
        if (run_case(&cases[c], &kept, &built, &sparse, &differ, &iters) != 0) {
            status = 1;
            continue;
        }
        printf("%-34s %6d %12.2f %12.2f %8.2f %12.2f %11.2f %8.2f %8d\n", cases[c].name,
               cases[c].steps, 1e6 * kept, 1e6 * built, built / kept, 1e6 * sparse, kept / sparse,
               iters, differ);
        if (csv != NULL)
            fprintf(csv, "\"%s\",%zu,%d,%.4g,%.4g,%.4g,%.4g,%.4g,%.4g,%d\n", cases[c].name,
                    cases[c].m, cases[c].steps, 1e6 * kept, 1e6 * built, built / kept, 1e6 * sparse,
                    kept / sparse, iters, differ);
        status |= differ != 0; /* kept, built and sparse must give the same forces */
    }
    if (csv != NULL)
        fclose(csv);
    return status;
}
