/* SPDX-License-Identifier: GPL-3.0-or-later */
/* stress_disk_chain.c — the 2-D context on stuck chains of 10^4 contacts (10^5 and 10^6 with
 * --full): W = W1 (x) I2, W1 = w tridiag(-1, 2, -1), set by compressed rows, cond(W1) ~
 * 0.4 m^2 (4e7 at 10^4). Block Gauss-Seidel needs about cond(W) sweeps on such a chain; the
 * context's Newton method on a sparse factor takes a few steps.
 *
 * Checks, each against numbers from outside the context:
 *   - all contacts at rest, every target force f* inside its bound, a_free = -W f*: f = f*,
 *     to the chain's rounding (64 cond(W1) DBL_EPSILON mun);
 *   - at rest, a tenth of the targets beyond their bounds (those contacts saturate and the
 *     others' forces move), and again with contacts in the band and sliding: the consistent
 *     law's fixed point, each f_i = fricreg_disk_eval(FRICREG_DISK_QUINN) at its own
 *     f_eq,i = -W_ii^-1 (a_free,i + sum_{j != i} W_ij f_j) (W_ii = 2w I is isotropic, where the
 *     context's law is fricreg_disk_eval's, fricreg_disk_ctx.h), to 1e-12 mun;
 *   - warm-started evaluations of a moving load, the same fixed point;
 *   - the y components of collinear data are 0, to 1e-12 mun (exactly 0 from a collinear
 *     start; here the warm start holds the previous, planar, case's forces).
 * The CPU time per evaluation and contact is printed, not checked (bench/disk_chain.c
 * measures it beside the 1-D context). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include <float.h>

#include "fricreg_disk.h"
#include "fricreg_disk_ctx.h"
#include "stress.h"

#define CHAIN_W 2.385
#define CHAIN_EPS 1e-3

struct chain {
    size_t m;
    int64_t *ptr, *ind;
    double *val, *mun, *zdot, *afree, *f, *feq;
    fricreg_disk_ctx *ctx;
};

static void chain_free(struct chain *c)
{
    free(c->ptr), free(c->ind), free(c->val), free(c->mun), free(c->zdot), free(c->afree);
    free(c->f), free(c->feq);
    fricreg_disk_ctx_free(c->ctx);
}

/* The chain's W by compressed rows, and its context. */
static int chain_new(struct chain *c, size_t m, uint64_t *rng)
{
    size_t n = 2 * m;
    *c = (struct chain){m,
                        malloc((n + 1) * sizeof(int64_t)),
                        malloc(3 * n * sizeof(int64_t)),
                        malloc(3 * n * sizeof(double)),
                        malloc(m * sizeof(double)),
                        calloc(n, sizeof(double)),
                        malloc(n * sizeof(double)),
                        malloc(n * sizeof(double)),
                        malloc(n * sizeof(double)),
                        NULL};
    if (!c->ptr || !c->ind || !c->val || !c->mun || !c->zdot || !c->afree || !c->f || !c->feq)
        return FRICREG_ENOMEM;
    int64_t e = 0;
    for (size_t r = 0; r < n; r++) {
        c->ptr[r] = e;
        if (r >= 2)
            c->ind[e] = (int64_t)(r - 2), c->val[e++] = -CHAIN_W;
        c->ind[e] = (int64_t)r, c->val[e++] = 2.0 * CHAIN_W;
        if (r + 2 < n)
            c->ind[e] = (int64_t)(r + 2), c->val[e++] = -CHAIN_W;
    }
    c->ptr[n] = e;
    for (size_t i = 0; i < m; i++)
        c->mun[i] = stress_uniform(rng, 0.5, 1.5);
    int status = fricreg_disk_ctx_create(m, &c->ctx);
    if (status == FRICREG_OK)
        status = fricreg_disk_ctx_set_law(c->ctx, FRICREG_DISK_QUINN, CHAIN_EPS);
    if (status == FRICREG_OK)
        status = fricreg_disk_ctx_set_bounds(c->ctx, m, c->mun);
    if (status == FRICREG_OK)
        status = fricreg_disk_ctx_set_coupling_csr(c->ctx, m, FRICREG_SPARSE_ZERO_BASED, c->ptr,
                                                   c->ind, c->val);
    return status;
}

/* out = W x (the chain's rows). */
static void chain_product(const struct chain *c, const double x[], double out[])
{
    for (size_t r = 0; r < 2 * c->m; r++) {
        double s = 0.0;
        for (int64_t e = c->ptr[r]; e < c->ptr[r + 1]; e++)
            s += c->val[e] * x[c->ind[e]];
        out[r] = s;
    }
}

/* Targets f* (a share `beyond` of them past their bounds; collinear: along x) into feq, and
 * a_free = -W f*. */
static void chain_load(struct chain *c, uint64_t *rng, double beyond, int collinear)
{
    for (size_t i = 0; i < c->m; i++) {
        double r = stress_uniform(rng, 0.0, 0.9) * c->mun[i];
        double th = collinear ? (stress_uniform(rng, 0.0, 1.0) < 0.5 ? 0.0 : STRESS_PI)
                              : stress_uniform(rng, 0.0, 2.0 * STRESS_PI);
        if (stress_uniform(rng, 0.0, 1.0) < beyond)
            r = 1.5 * c->mun[i];
        c->feq[2 * i] = r * cos(th), c->feq[2 * i + 1] = collinear ? 0.0 : r * sin(th);
    }
    chain_product(c, c->feq, c->afree);
    for (size_t k = 0; k < 2 * c->m; k++)
        c->afree[k] = -c->afree[k];
}

/* Velocities: at rest, or (moving) a third in the band and a third sliding. */
static void chain_velocities(struct chain *c, uint64_t *rng, int moving, int collinear)
{
    for (size_t i = 0; i < c->m; i++) {
        double u = stress_uniform(rng, 0.0, 1.0), th = stress_uniform(rng, 0.0, 2.0 * STRESS_PI);
        double r = !moving || u < 1.0 / 3 ? 0.0
                   : u < 2.0 / 3          ? CHAIN_EPS * stress_uniform(rng, 0.0, 1.0)
                                          : CHAIN_EPS * stress_uniform(rng, 1.0, 2.0);
        c->zdot[2 * i] = collinear ? (u < 0.5 ? r : -r) : r * cos(th);
        c->zdot[2 * i + 1] = collinear ? 0.0 : r * sin(th);
    }
}

/* The largest |f_i - law(f_eq,i)| / mun_i over the contacts: 0 at the consistent law's
 * solution (fricreg_disk_ctx.h). */
static double fixed_point_residual(struct chain *c)
{
    double worst = 0.0, wii = 2.0 * CHAIN_W;
    chain_product(c, c->f, c->feq); /* W f */
    for (size_t i = 0; i < c->m; i++) {
        double g[2], law[2];
        for (int a = 0; a < 2; a++) /* f_eq,i = -(a_free + W f - W_ii f_i)/W_ii */
            g[a] = -(c->afree[2 * i + a] + c->feq[2 * i + a] - wii * c->f[2 * i + a]) / wii;
        if (fricreg_disk_eval(FRICREG_DISK_QUINN, c->zdot + 2 * i, g, c->mun[i], CHAIN_EPS, law) !=
            FRICREG_OK)
            return INFINITY;
        worst = fmax(worst, hypot(law[0] - c->f[2 * i], law[1] - c->f[2 * i + 1]) / c->mun[i]);
    }
    return worst;
}

static double cpu_seconds(void)
{
    return (double)clock() / CLOCKS_PER_SEC;
}

/* One evaluation, timed; returns its status. */
static int chain_eval(struct chain *c, double *seconds)
{
    double t0 = cpu_seconds();
    int status = fricreg_disk_ctx_eval(c->ctx, c->m, c->zdot, c->afree, c->f);
    *seconds = cpu_seconds() - t0;
    return status;
}

static void report(struct stress_tally *t, const char *name, size_t m, int status, double figure,
                   double limit, double seconds)
{
    int ok = status == FRICREG_OK && figure <= limit;
    printf("%-46s %8zu %-4s %10.3g %10.3g %9.1f\n", name, m, ok ? "ok" : "FAIL", figure, limit,
           1e9 * seconds / (double)m);
    stress_check(t, ok, "%s, m = %zu: status %d, %g (limit %g)", name, m, status, figure, limit);
}

/* The closed form of a chain stuck inside its bounds. */
static void check_stuck(struct stress_tally *t, struct chain *c, uint64_t *rng)
{
    chain_velocities(c, rng, 0, 0);
    chain_load(c, rng, 0.0, 0);
    double seconds, err = 0.0, c1 = cos(STRESS_PI / (double)(c->m + 1));
    int status = chain_eval(c, &seconds);
    for (size_t k = 0; status == FRICREG_OK && k < 2 * c->m; k++)
        err = fmax(err, fabs(c->f[k] - c->feq[k]) / c->mun[k / 2]);
    report(t, "stuck inside the bounds: f = f*", c->m, status, err,
           64.0 * (1.0 + c1) / (1.0 - c1) * DBL_EPSILON, seconds);
}

/* The fixed point with saturated contacts, at rest or moving, collinear or not, then over
 * warm-started evaluations of a moving load. */
static void check_fixed_point(struct stress_tally *t, struct chain *c, uint64_t *rng, int moving,
                              int collinear)
{
    char name[64];
    chain_velocities(c, rng, moving, collinear);
    chain_load(c, rng, 0.1, collinear);
    double seconds, fy = 0.0;
    int status = chain_eval(c, &seconds);
    for (size_t i = 0; collinear && status == FRICREG_OK && i < c->m; i++)
        fy = fmax(fy, fabs(c->f[2 * i + 1]));
    snprintf(name, sizeof name, "%s, %s, a tenth saturated", moving ? "moving" : "at rest",
             collinear ? "collinear" : "in the plane");
    report(t, name, c->m, status, status == FRICREG_OK ? fixed_point_residual(c) : INFINITY, 1e-12,
           seconds);
    if (collinear)
        report(t, "  and f_y = 0", c->m, status, fy, 1e-12, seconds);
    double worst = 0.0, total = 0.0;
    for (int k = 0; k < 5 && status == FRICREG_OK; k++) {
        for (size_t q = 0; q < 2 * c->m; q++)
            c->afree[q] *= 1.0 + 1e-3 * stress_uniform(rng, -1.0, 1.0);
        status = chain_eval(c, &seconds);
        total += seconds;
        if (status == FRICREG_OK)
            worst = fmax(worst, fixed_point_residual(c));
    }
    report(t, "  then 5 warm-started steps of the load", c->m, status, worst, 1e-12, total / 5.0);
}

int stress_disk_chain(const struct stress_mode *mode)
{
    struct stress_tally t = {0, 0};
    uint64_t rng = mode->seed ^ 0x6469736b636861ULL;
    printf("== the 2-D context on stuck chains (W1 (x) I2 by compressed rows, law QUINN)\n");
    printf("%-46s %8s %-4s %10s %10s %9s\n", "case", "m", "", "figure", "limit", "ns/contact");
    for (double m = 1e4; m <= mode->disk_chain_m; m *= 10.0) {
        struct chain c;
        int status = chain_new(&c, (size_t)m, &rng);
        stress_check(&t, status == FRICREG_OK, "chain of %g: set-up status %d", m, status);
        if (status == FRICREG_OK) {
            check_stuck(&t, &c, &rng);
            check_fixed_point(&t, &c, &rng, 0, 1);
            check_fixed_point(&t, &c, &rng, 1, 1);
            check_fixed_point(&t, &c, &rng, 1, 0);
        }
        chain_free(&c);
    }
    printf("%d checks, %d failed\n\n", t.checks, t.failures);
    return t.failures;
}
