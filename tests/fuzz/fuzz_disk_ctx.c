/* SPDX-License-Identifier: GPL-3.0-or-later */
/* fuzz_disk_ctx.c — fuzz target: the 2-D context's whole life (include/fricreg_disk_ctx.h,
 * fricreg_disk_ctx_set_stribeck of include/fricreg_stribeck.h). The input is a program of
 * operations on one context of m <= 4 contacts (W of order 2m <= 8): set law and eps, bounds,
 * Stribeck parameters, block-diagonal W (isotropic w I, symmetric, non-symmetric, indefinite
 * blocks) or dense W (random symmetric, B B^T of low rank, non-symmetric, scaled to huge or
 * subnormal entries), eval, tangent and messages, each now and then with a wrong size or a
 * NULL. Every call is held to its docstring: status in the documented set, recorded with a
 * message; outputs and the context's state untouched on failure (sentinels); valid setter
 * arguments accepted. On a successful eval: f finite; |f_i| <= the contact's bound (mun_i, or
 * under Stribeck B_i(|zdot_i|) in the band and k_i(|zdot_i|) outside it); sliding contacts
 * (|zdot_i| >= eps; FORCE_BALANCE: zdot_i != 0) at the sliding law; with isotropic blocks
 * w_i I each f_i is fricreg_disk_eval's (or fricreg_stribeck_disk_eval's) law at
 * f_eq,i = -a_free,i/w_i to rounding; otherwise f_i lies in K_i and satisfies the QP's
 * optimality conditions (stationarity, a multiplier >= 0 on the circle) to the accuracy the
 * header states, cond(W_SS) DBL_EPSILON. A successful tangent is finite and written in full. */

#include "fuzz_condition.h"
#include "fuzz_input.h"

#include "fricreg_disk_ctx.h"
#include "fricreg_stribeck.h"

enum { MAX_M = 4, MAX_N = 2 * MAX_M };
#define DISK_MAX 1e250                        /* the numbers' limit of fricreg_disk.h */
#define SUBNORMAL_MIN 4.9406564584124654e-324 /* the spacing of the subnormal doubles */

/* What the context holds, as the calls that succeeded set it. */
struct model {
    size_t m;
    int law;
    double eps;
    double mun[MAX_M];
    int stribeck;
    double fs[MAX_M], fk[MAX_M], vs[MAX_M], delta[MAX_M];
    int dense;
    double W[MAX_N * MAX_N]; /* the full W, its off-diagonal blocks 0 when !dense */
    int evaluated;           /* an eval succeeded since the last setter */
    /* The last successful tangent's df_dzdot (bit 0 of kept) and df_dafree (bit 1) since that
     * eval, and whether an eval failed since it was kept (rebuilt[w]: the context then
     * rebuilds its state from the last successful eval's inputs, to rounding). */
    int kept, rebuilt[2];
    double T[2][MAX_N * MAX_N];
};

/* The last failure's status, which the context keeps: a successful call does not clear it. */
static int last_error;

#define CODE(c) (1u << (c))

static void require_status(fricreg_disk_ctx *ctx, int status, unsigned allowed, const char *call)
{
    FUZZ_REQUIRE(status == FRICREG_OK || (status > 0 && status < 32 && (allowed >> status & 1u)),
                 "%s: status %d (%s) not documented (mask %#x)", call, status,
                 fricreg_strerror(status), allowed);
    if (status != FRICREG_OK && ctx != NULL) {
        FUZZ_REQUIRE(fricreg_disk_ctx_errcode(ctx) == status, "%s: errcode %d, returned %d", call,
                     fricreg_disk_ctx_errcode(ctx), status);
        FUZZ_REQUIRE(fricreg_disk_ctx_errmsg(ctx)[0] != '\0', "%s: failure %d with no message",
                     call, status);
        last_error = status;
    }
    FUZZ_REQUIRE(ctx == NULL || fricreg_disk_ctx_errcode(ctx) == last_error,
                 "%s: status %d, errcode %d, the last failure %d", call, status,
                 fricreg_disk_ctx_errcode(ctx), last_error);
}

/* A size: the context's, or one off, or an absurd one. */
static size_t fuzz_size(struct fuzz_input *in, size_t m)
{
    switch (fuzz_byte(in) % 16) {
    case 0: return m + 1;
    case 1: return m - 1;
    case 2: return SIZE_MAX;
    case 3: return (size_t)1 << 62;
    default: return m;
    }
}

static int in_range(double x)
{
    return isfinite(x) && fabs(x) <= DISK_MAX;
}

static void op_set_law(struct fuzz_input *in, fricreg_disk_ctx *ctx, struct model *md)
{
    int law = fuzz_int(in, 0, 7);
    double eps = fuzz_double(in);
    int status = fricreg_disk_ctx_set_law(ctx, law, eps);
    require_status(ctx, status, CODE(FRICREG_EINVAL) | CODE(FRICREG_ENONFINITE), "set_law");
    int supported = law == FRICREG_DISK_QUINN || law == FRICREG_DISK_FORCE_BALANCE;
    int valid = supported && isfinite(eps) && eps >= DBL_MIN && eps <= DISK_MAX;
    FUZZ_REQUIRE((status == FRICREG_OK) == valid, "set_law(%d, %g): status %d", law, eps, status);
    FUZZ_REQUIRE(status != FRICREG_ENONFINITE || !isfinite(eps), "set_law: ENONFINITE, eps %g",
                 eps);
    if (status == FRICREG_OK) {
        md->law = law;
        md->eps = eps;
        if (law == FRICREG_DISK_FORCE_BALANCE)
            md->stribeck = 0;
        md->evaluated = 0, md->kept = 0;
    }
}

static void op_set_bounds(struct fuzz_input *in, fricreg_disk_ctx *ctx, struct model *md)
{
    size_t m = fuzz_size(in, md->m);
    double mun[MAX_M];
    for (size_t i = 0; i < MAX_M; i++)
        mun[i] = fabs(fuzz_double(in)) * (fuzz_byte(in) == 9 ? -1.0 : 1.0);
    int null = fuzz_byte(in) == 1;
    int status = fricreg_disk_ctx_set_bounds(ctx, m, null ? NULL : mun);
    require_status(ctx, status,
                   CODE(FRICREG_ENULL) | CODE(FRICREG_ESIZE) | CODE(FRICREG_EINVAL) |
                       CODE(FRICREG_ENONFINITE),
                   "set_bounds");
    int valid = m == md->m && !null;
    for (size_t i = 0; valid && i < m; i++)
        valid = in_range(mun[i]) && mun[i] >= 0.0;
    FUZZ_REQUIRE((status == FRICREG_OK) == valid, "set_bounds: status %d, valid %d", status, valid);
    if (status == FRICREG_OK) {
        memcpy(md->mun, mun, m * sizeof *mun);
        md->stribeck = 0;
        md->evaluated = 0, md->kept = 0;
    }
}

static void op_set_stribeck(struct fuzz_input *in, fricreg_disk_ctx *ctx, struct model *md)
{
    size_t m = fuzz_byte(in) % 8 == 0 ? 0 : fuzz_size(in, md->m);
    double fs[MAX_M], fk[MAX_M], vs[MAX_M], delta[MAX_M];
    for (size_t i = 0; i < MAX_M; i++) {
        fs[i] = fuzz_double(in);
        uint8_t ratio = fuzz_byte(in); /* mostly fk <= fs: the ratio fk/fs */
        fk[i] = ratio < 200 ? fs[i] * (double)(ratio % 101) / 100.0 : fuzz_double(in);
        vs[i] = fuzz_double(in);
        delta[i] = fuzz_byte(in) < 128 ? 1.0 + (double)(fuzz_byte(in) % 3) : fuzz_double(in);
    }
    int null = fuzz_byte(in) == 1;
    int status = fricreg_disk_ctx_set_stribeck(ctx, m, null ? NULL : fs, fk, vs, delta);
    require_status(ctx, status,
                   CODE(FRICREG_ENULL) | CODE(FRICREG_ESIZE) | CODE(FRICREG_EINVAL) |
                       CODE(FRICREG_ENONFINITE) | CODE(FRICREG_ENOMEM),
                   "set_stribeck");
    int valid = m == 0 || (m == md->m && !null);
    for (size_t i = 0; valid && m > 0 && i < m; i++)
        valid = isfinite(fs[i]) && isfinite(fk[i]) && isfinite(vs[i]) && isfinite(delta[i]) &&
                fk[i] >= 0.0 && fk[i] <= fs[i] && fs[i] <= DISK_MAX && vs[i] > 0.0 &&
                delta[i] > 0.0;
    FUZZ_REQUIRE((status == FRICREG_OK) == valid, "set_stribeck(m %zu): status %d, valid %d", m,
                 status, valid);
    if (status != FRICREG_OK)
        return;
    md->evaluated = 0, md->kept = 0;
    md->stribeck = m > 0;
    if (m == 0)
        return;
    md->law = FRICREG_DISK_QUINN;
    memcpy(md->fs, fs, m * sizeof *fs);
    memcpy(md->fk, fk, m * sizeof *fk);
    memcpy(md->vs, vs, m * sizeof *vs);
    memcpy(md->delta, delta, m * sizeof *delta);
}

/* A 2x2 block of one of several kinds, row-major. */
static void make_block(struct fuzz_input *in, double b[4])
{
    uint8_t kind = fuzz_byte(in) % 4;
    double x = fuzz_double(in);
    switch (kind) {
    case 0: /* isotropic w I: the Euclidean law */
    case 1: b[0] = b[3] = kind == 0 ? x : fabs(x) + 0.5, b[1] = b[2] = 0.0; break;
    case 2: /* symmetric: often positive definite, anisotropic */
        b[0] = x, b[3] = fuzz_double(in), b[1] = b[2] = fuzz_double(in);
        break;
    default: b[0] = x, b[1] = fuzz_double(in), b[2] = fuzz_double(in), b[3] = fuzz_double(in);
    }
}

static void op_set_blocks(struct fuzz_input *in, fricreg_disk_ctx *ctx, struct model *md)
{
    size_t m = fuzz_size(in, md->m);
    double w[4 * MAX_M], w0[4 * MAX_M];
    for (size_t i = 0; i < MAX_M; i++)
        make_block(in, w + 4 * i);
    memcpy(w0, w, sizeof w);
    int null = fuzz_byte(in) == 1;
    int status = fricreg_disk_ctx_set_coupling_blocks(ctx, m, null ? NULL : w);
    require_status(ctx, status,
                   CODE(FRICREG_ENULL) | CODE(FRICREG_ESIZE) | CODE(FRICREG_ENONFINITE) |
                       CODE(FRICREG_EINVAL) | CODE(FRICREG_ENOTSYM) | CODE(FRICREG_ENOTPSD) |
                       CODE(FRICREG_ENOMEM),
                   "set_coupling_blocks");
    FUZZ_REQUIRE(memcmp(w, w0, sizeof w) == 0, "set_coupling_blocks changed the caller's w");
    if (status != FRICREG_OK)
        return;
    FUZZ_REQUIRE(m == md->m && !null, "set_coupling_blocks took m = %zu", m);
    size_t n = 2 * m;
    memset(md->W, 0, sizeof md->W);
    for (size_t i = 0; i < m; i++) {
        const double *b = w + 4 * i;
        double s = fmax(b[0], b[3]); /* scaled: a subnormal block's determinant underflows */
        FUZZ_REQUIRE(fuzz_all_finite(b, 4) && b[0] > 0.0 && b[3] > 0.0 &&
                         (b[0] / s) * (b[3] / s) - (b[1] / s) * (b[2] / s) > 0.0,
                     "set_coupling_blocks took block %zu (%g %g; %g %g)", i, b[0], b[1], b[2],
                     b[3]);
        md->W[2 * i * n + 2 * i] = b[0], md->W[2 * i * n + 2 * i + 1] = b[1];
        md->W[(2 * i + 1) * n + 2 * i] = b[2], md->W[(2 * i + 1) * n + 2 * i + 1] = b[3];
    }
    md->dense = 0;
    md->evaluated = 0, md->kept = 0;
}

static void op_set_dense(struct fuzz_input *in, fricreg_disk_ctx *ctx, struct model *md)
{
    size_t m = fuzz_size(in, md->m), n = 2 * md->m;
    double W[MAX_N * MAX_N], W0[MAX_N * MAX_N], scratch[MAX_N * MAX_N];
    fuzz_matrix(in, n, W, scratch);
    memcpy(W0, W, sizeof W);
    int null = fuzz_byte(in) == 1;
    int status = fricreg_disk_ctx_set_coupling_dense(ctx, m, null ? NULL : W);
    require_status(ctx, status,
                   CODE(FRICREG_ENULL) | CODE(FRICREG_ESIZE) | CODE(FRICREG_ENONFINITE) |
                       CODE(FRICREG_EINVAL) | CODE(FRICREG_ENOTSYM) | CODE(FRICREG_ENOTPSD) |
                       CODE(FRICREG_ENOMEM),
                   "set_coupling_dense");
    FUZZ_REQUIRE(memcmp(W, W0, sizeof W) == 0, "set_coupling_dense changed the caller's W");
    if (status != FRICREG_OK)
        return;
    FUZZ_REQUIRE(m == md->m && !null, "set_coupling_dense took m = %zu", m);
    FUZZ_REQUIRE(fuzz_all_finite(W, n * n), "set_coupling_dense took a non-finite W");
    for (size_t i = 0; i < n; i++)
        FUZZ_REQUIRE(W[i * n + i] > 0.0, "set_coupling_dense took W_%zu%zu = %g", i, i,
                     W[i * n + i]);
    memcpy(md->W, W, n * n * sizeof *W);
    md->dense = 1;
    md->evaluated = 0, md->kept = 0;
}

static double norm2(const double v[2])
{
    return hypot(v[0], v[1]);
}

/* The Stribeck curve k(r) of contact i (fricreg_stribeck.h). */
static double kinetic(const struct model *md, size_t i, double r)
{
    return md->fk[i] + (md->fs[i] - md->fk[i]) * exp(-pow(r / md->vs[i], md->delta[i]));
}

/* The contact's bound at speed r: mun_i, or Stribeck's B_i(r) in the band and k_i(r) outside. */
static double bound_at(const struct model *md, size_t i, double r)
{
    if (!md->stribeck)
        return md->mun[i];
    if (r >= md->eps)
        return kinetic(md, i, r);
    return md->fs[i] + (kinetic(md, i, md->eps) - md->fs[i]) * (r / md->eps);
}

static int sliding(const struct model *md, const double zdot[2])
{
    double r = norm2(zdot);
    return md->law == FRICREG_DISK_FORCE_BALANCE ? r != 0.0 : r >= md->eps;
}

/* The contact's own law, as the 1-contact functions compute it, at (zdot_i, f_eq). */
static void law_at(const struct model *md, size_t i, const double zdot[2], const double f_eq[2],
                   double f[2])
{
    int status = md->stribeck ? fricreg_stribeck_disk_eval(zdot, f_eq, md->fs[i], md->fk[i],
                                                           md->vs[i], md->delta[i], md->eps, f)
                              : fricreg_disk_eval(md->law, zdot, f_eq, md->mun[i], md->eps, f);
    FUZZ_REQUIRE(status == FRICREG_OK, "law at contact %zu (%g, %g), f_eq (%g, %g): %d", i, zdot[0],
                 zdot[1], f_eq[0], f_eq[1], status);
}

/* FUZZ_TRACE=1 in the environment: print each successful eval (to read a finding). */
static void trace_eval(const struct model *md, const double zdot[], const double a_free[],
                       const double f[])
{
    if (getenv("FUZZ_TRACE") == NULL)
        return;
    size_t m = md->m, n = 2 * m;
    fprintf(stderr, "eval: m %zu law %d eps %.17g dense %d stribeck %d\n", m, md->law, md->eps,
            md->dense, md->stribeck);
    for (size_t k = 0; k < n; k++) {
        fprintf(stderr, "  W[%zu] =", k);
        for (size_t j = 0; j < n; j++)
            fprintf(stderr, " %.17g", md->W[k * n + j]);
        fputc('\n', stderr);
    }
    for (size_t i = 0; i < m; i++)
        fprintf(stderr,
                "  %zu: mun %.17g zdot (%.17g, %.17g) a_free (%.17g, %.17g) -> f (%.17g, %.17g)\n",
                i, md->mun[i], zdot[2 * i], zdot[2 * i + 1], a_free[2 * i], a_free[2 * i + 1],
                f[2 * i], f[2 * i + 1]);
}

/* The condition number of the Jacobi-scaled W_SS (unit diagonal), S the components of the
 * near-stick contacts: the forces are the QP's solution to about cond(W_SS) DBL_EPSILON
 * (fricreg_disk_ctx.h). GSL's symmetric eigensolver on a copy; +Inf if W_SS is singular. */
static double scaled_condition(const struct model *md, const int near[])
{
    size_t n = 2 * md->m, s = 0, pos[MAX_N];
    for (size_t k = 0; k < n; k++)
        if (near[k / 2])
            pos[s++] = k;
    return fuzz_scaled_condition(md->W, n, pos, s);
}

/* Contact i's optimality in the QP of fricreg_disk_ctx.h: with g_i = (W f)_i + a_free,i +
 * W_ii c_i B_i (c_i = 2 zdot_i/eps), f_i in K_i (centre -a_i u_i, radius B_i - a_i), and
 * g_i = -lambda (f_i - centre) with lambda >= 0 (lambda = 0 inside K_i). Tolerances: rtol of
 * the scale of each quantity, plus the underflow floor. */
static void check_optimality(const struct model *md, size_t i, const double zdot[],
                             const double a_free[], const double f[], double rtol)
{
    if (!(rtol < 0.01))
        return; /* W_SS singular or nearly: no digits promised, only |f_i| <= bound */
    size_t n = 2 * md->m;
    const double *z = zdot + 2 * i, *fi = f + 2 * i;
    double r = norm2(z), B = bound_at(md, i, r);
    double a = md->law == FRICREG_DISK_QUINN ? B * (r / md->eps) : 0.0;
    double u[2] = {r > 0.0 ? z[0] / r : 0.0, r > 0.0 ? z[1] / r : 0.0};
    double c[2] = {md->law == FRICREG_DISK_QUINN ? 2.0 * z[0] / md->eps : 0.0,
                   md->law == FRICREG_DISK_QUINN ? 2.0 * z[1] / md->eps : 0.0};
    double centre[2] = {-a * u[0], -a * u[1]}, radius = B - a;
    double d[2] = {fi[0] - centre[0], fi[1] - centre[1]}, dist = norm2(d);
    double ftol = rtol * (B + a) + 1e-300;
    FUZZ_REQUIRE(dist <= radius + ftol, "eval: f_%zu (%.17g, %.17g) outside K_%zu by %g", i, fi[0],
                 fi[1], i, dist - radius);
    double g[2], gscale[2];
    for (int k = 0; k < 2; k++) {
        size_t row = 2 * i + (size_t)k;
        double wc = md->W[row * n + 2 * i] * c[0] + md->W[row * n + 2 * i + 1] * c[1];
        g[k] = a_free[row] + wc * B;
        gscale[k] = fabs(a_free[row]) + fabs(wc * B);
        for (size_t j = 0; j < n; j++) {
            double bj = bound_at(md, j / 2, norm2(zdot + 2 * (j / 2)));
            g[k] += md->W[row * n + j] * f[j];
            gscale[k] += fabs(md->W[row * n + j]) * (fabs(f[j]) + bj + 4.0 * SUBNORMAL_MIN);
        }
    }
    double gtol = rtol * norm2(gscale) + DBL_MIN / DBL_EPSILON;
    if (dist < radius - ftol || radius <= 0.0 || dist == 0.0) { /* inside K_i: stationary */
        FUZZ_REQUIRE(radius <= 0.0 || norm2(g) <= gtol,
                     "eval: f_%zu inside K_%zu but g = (%g, %g), tolerance %g", i, i, g[0], g[1],
                     gtol);
        return;
    }
    /* on the circle: g = -lambda d, lambda >= 0; with d's direction e (no squares: a bound
     * near 1e-303 would underflow them), t = lambda |d| = -g.e and g + t e = 0 */
    double e[2] = {d[0] / dist, d[1] / dist}, t = -(g[0] * e[0] + g[1] * e[1]);
    double res[2] = {g[0] + t * e[0], g[1] + t * e[1]};
    /* a force of a few subnormal quanta has its direction quantized (mun = 4.9e-324: only the
     * axes): the residual may be |g| times the quantum over |d| */
    double quantized = norm2(g) * (4.0 * SUBNORMAL_MIN / dist);
    FUZZ_REQUIRE(
        t >= -gtol && norm2(res) <= gtol + quantized,
        "eval: f_%zu on its circle, g = (%g, %g): lambda |d| %g, residual %g, tolerance %g", i,
        g[0], g[1], t, norm2(res), gtol);
}

/* Whether contact i's block is w I: then the W_ii-metric projection is the Euclidean one. */
static int isotropic(const struct model *md, size_t i)
{
    size_t n = 2 * md->m, k = 2 * i;
    return md->W[k * n + k + 1] == 0.0 && md->W[(k + 1) * n + k] == 0.0 &&
           md->W[k * n + k] == md->W[(k + 1) * n + k + 1];
}

static void check_forces(const struct model *md, const double zdot[], const double a_free[],
                         const double f[])
{
    size_t m = md->m, n = 2 * m;
    int near[MAX_M];
    for (size_t i = 0; i < m; i++)
        near[i] = !sliding(md, zdot + 2 * i) && bound_at(md, i, norm2(zdot + 2 * i)) > 0.0;
    double rtol = md->dense
                      ? fmax(1e-6, 64.0 * (double)n * DBL_EPSILON * scaled_condition(md, near))
                      : 1e-12;
    for (size_t i = 0; i < m; i++) {
        const double *z = zdot + 2 * i, *fi = f + 2 * i;
        double r = norm2(z), B = bound_at(md, i, r), size = norm2(fi);
        FUZZ_REQUIRE(isfinite(fi[0]) && isfinite(fi[1]), "eval: f_%zu not finite", i);
        /* to rounding: a few ulps of |f_i| (64 under Stribeck: the harness's exp and pow are
         * not the library's), or a few subnormal quanta */
        double ulps = md->stribeck ? 64.0 : 4.0;
        FUZZ_REQUIRE(size <= B * (1.0 + ulps * DBL_EPSILON) + 4.0 * SUBNORMAL_MIN,
                     "eval: |f_%zu| = %.17g above its bound %.17g (stribeck %d)", i, size, B,
                     md->stribeck);
        if (!near[i]) { /* sliding (or no bound): the law with any f_eq */
            double expected[2], zero[2] = {0.0, 0.0};
            law_at(md, i, z, zero, expected);
            double err = hypot(fi[0] - expected[0], fi[1] - expected[1]);
            FUZZ_REQUIRE(err <= 4.0 * DBL_EPSILON * B + 1e-300,
                         "eval: sliding contact %zu f (%.17g, %.17g), law (%.17g, %.17g)", i, fi[0],
                         fi[1], expected[0], expected[1]);
            continue;
        }
        if (!md->dense && isotropic(md, i)) { /* contact by contact, the 1-contact law */
            double w = md->W[2 * i * n + 2 * i];
            double f_eq[2] = {-a_free[2 * i] / w, -a_free[2 * i + 1] / w}, expected[2];
            if (in_range(f_eq[0]) && in_range(f_eq[1])) {
                law_at(md, i, z, f_eq, expected);
                double err = hypot(fi[0] - expected[0], fi[1] - expected[1]);
                FUZZ_REQUIRE(err <= 1e-12 * B + 1e-300,
                             "eval: isotropic contact %zu f (%.17g, %.17g), law (%.17g, %.17g)", i,
                             fi[0], fi[1], expected[0], expected[1]);
                continue;
            }
        }
        check_optimality(md, i, zdot, a_free, f, rtol);
    }
}

static void op_eval(struct fuzz_input *in, fricreg_disk_ctx *ctx, struct model *md)
{
    size_t m = fuzz_size(in, md->m), n = 2 * md->m;
    double zdot[MAX_N], a_free[MAX_N], f[MAX_N + 1];
    for (size_t i = 0; i < MAX_M; i++) {
        uint8_t kind = fuzz_byte(in);
        for (int k = 0; k < 2; k++) {
            /* often exactly at rest, or on one axis, or on the band's edge */
            zdot[2 * i + k] = kind < 96 || (kind < 128 && k == 1) ? 0.0 : fuzz_double(in);
            a_free[2 * i + k] = fuzz_double(in);
        }
        if (kind >= 128 && kind < 144)
            zdot[2 * i] = md->eps, zdot[2 * i + 1] = 0.0;
    }
    uint8_t nulls = fuzz_byte(in);
    fuzz_fill(f, sizeof f);
    int status = fricreg_disk_ctx_eval(ctx, m, nulls == 3 ? NULL : zdot, nulls == 4 ? NULL : a_free,
                                       nulls == 5 ? NULL : f);
    require_status(ctx, status,
                   CODE(FRICREG_ENULL) | CODE(FRICREG_ESIZE) | CODE(FRICREG_ENONFINITE) |
                       CODE(FRICREG_EINVAL) | CODE(FRICREG_ESINGULAR),
                   "eval");
    if (status != FRICREG_OK) {
        if (getenv("FUZZ_TRACE") != NULL && m == md->m && nulls != 3 && nulls != 4) {
            trace_eval(md, zdot, a_free, f); /* f: the sentinels */
            fprintf(stderr, "eval failed: %s\n", fricreg_disk_ctx_errmsg(ctx));
        }
        FUZZ_REQUIRE(fuzz_untouched(f, sizeof f), "eval wrote on failure %d", status);
        FUZZ_REQUIRE(status != FRICREG_ESINGULAR || md->dense, "ESINGULAR with a block W");
        md->rebuilt[0] |= md->kept & 1, md->rebuilt[1] |= md->kept >> 1 & 1;
        return; /* the tangent stays that of the last successful eval */
    }
    FUZZ_REQUIRE(m == md->m && nulls != 3 && nulls != 4 && nulls != 5, "eval took a bad call");
    FUZZ_REQUIRE(fuzz_untouched(f + n, sizeof *f), "eval wrote past 2m");
    for (size_t k = 0; k < n; k++)
        FUZZ_REQUIRE(in_range(zdot[k]) && in_range(a_free[k]), "eval took input %zu: %g, %g", k,
                     zdot[k], a_free[k]);
    md->evaluated = 1, md->kept = 0;
    trace_eval(md, zdot, a_free, f);
    check_forces(md, zdot, a_free, f);
}

static void op_tangent(struct fuzz_input *in, fricreg_disk_ctx *ctx, struct model *md)
{
    size_t m = fuzz_size(in, md->m), nn = 4 * md->m * md->m;
    double dz[MAX_N * MAX_N + 1], da[MAX_N * MAX_N + 1];
    fuzz_fill(dz, sizeof dz);
    fuzz_fill(da, sizeof da);
    uint8_t which = fuzz_byte(in) % 4; /* bit 0: df_dzdot, bit 1: df_dafree */
    int status = fricreg_disk_ctx_tangent(ctx, m, which & 1 ? dz : NULL, which & 2 ? da : NULL);
    require_status(ctx, status,
                   CODE(FRICREG_ENULL) | CODE(FRICREG_ESIZE) | CODE(FRICREG_EINVAL) |
                       CODE(FRICREG_ESINGULAR) | CODE(FRICREG_ENONFINITE),
                   "tangent");
    if (status != FRICREG_OK) {
        FUZZ_REQUIRE(fuzz_untouched(dz, sizeof dz) && fuzz_untouched(da, sizeof da),
                     "tangent wrote on failure %d", status);
        FUZZ_REQUIRE(status != FRICREG_EINVAL || !md->evaluated || m != md->m,
                     "tangent: EINVAL after a successful eval: %s", fricreg_disk_ctx_errmsg(ctx));
        return;
    }
    FUZZ_REQUIRE(which != 0 && m == md->m && md->evaluated, "tangent took a bad call");
    for (size_t k = 0; k < nn; k++) {
        FUZZ_REQUIRE(!(which & 1) || isfinite(dz[k]), "tangent: df_dzdot[%zu] = %g", k, dz[k]);
        FUZZ_REQUIRE(!(which & 2) || isfinite(da[k]), "tangent: df_dafree[%zu] = %g", k, da[k]);
    }
    FUZZ_REQUIRE((!(which & 1) || fuzz_untouched(dz + nn, sizeof *dz)) &&
                     (!(which & 2) || fuzz_untouched(da + nn, sizeof *da)),
                 "tangent wrote past (2m)^2");
    /* The tangent of the last successful eval: the same bits again, and after a failed eval
     * (its state rebuilt by a sweep from the kept forces) the same to 1e-9 of its largest
     * entry, or to the rounding a rebuild meets on an ill-conditioned W: 64 eps times its
     * scaled condition number (a finding: W's diagonal from 17 to 3.9e11, the tangent moved by
     * 1.1e-9); on a W singular to rounding the forces, and so the tangent, are not unique, and
     * a rebuild may find others (a finding: equal rows, moved by 0.3 of its largest entry):
     * not compared. */
    int every[MAX_M];
    for (size_t i = 0; i < md->m; i++)
        every[i] = 1;
    double rebuild_tol = fmax(1e-9, 64.0 * DBL_EPSILON * scaled_condition(md, every));
    for (int w = 0; w < 2; w++) {
        const double *T = w ? da : dz;
        if (!(which >> w & 1))
            continue;
        if (md->kept >> w & 1) {
            double scale = 0.0, diff = 0.0;
            for (size_t k = 0; k < nn; k++) {
                scale = fmax(scale, fabs(md->T[w][k]));
                diff = fmax(diff, fabs(T[k] - md->T[w][k]));
            }
            FUZZ_REQUIRE(md->rebuilt[w]
                             ? !isfinite(rebuild_tol) || diff <= rebuild_tol * scale + 1e-300
                             : fuzz_same_bits(T, md->T[w], nn),
                         "tangent: %s moved by %g (largest entry %g) since the last call%s",
                         w ? "df_dafree" : "df_dzdot", diff, scale,
                         md->rebuilt[w] ? ", an eval failed between" : "");
        }
        memcpy(md->T[w], T, nn * sizeof *T);
        md->rebuilt[w] = 0;
    }
    md->kept |= which;
}

static void op_misc(struct fuzz_input *in, fricreg_disk_ctx *ctx, const struct model *md)
{
    FUZZ_REQUIRE(fricreg_disk_ctx_size(ctx) == md->m, "ctx_size");
    char buf[8];
    size_t len = fuzz_byte(in) % (sizeof buf + 1);
    fuzz_fill(buf, sizeof buf);
    size_t full = fricreg_disk_ctx_errmsg_copy(ctx, buf, len);
    FUZZ_REQUIRE(full == (len > 0 ? strlen(fricreg_disk_ctx_errmsg(ctx)) : 0),
                 "errmsg_copy length %zu", full); /* len 0: 0 and nothing written */
    if (len > 0)
        FUZZ_REQUIRE(memchr(buf, '\0', len) != NULL, "errmsg_copy: no NUL in %zu", len);
    if (len < sizeof buf)
        FUZZ_REQUIRE(fuzz_untouched(buf + len, sizeof buf - len), "errmsg_copy wrote past len");
}

/* create with a bad size or a NULL out: refused, out untouched. */
static void check_create_refusals(uint8_t sel)
{
    static const size_t sizes[4] = {0, ((size_t)1 << 24) + 1, SIZE_MAX, (size_t)1 << 62};
    fricreg_disk_ctx *ctx;
    fuzz_fill(&ctx, sizeof ctx);
    int status = fricreg_disk_ctx_create(sizes[sel % 4], &ctx);
    FUZZ_REQUIRE(status == FRICREG_EINVAL && fuzz_untouched(&ctx, sizeof ctx),
                 "create(%zu): status %d", sizes[sel % 4], status);
    FUZZ_REQUIRE(fricreg_disk_ctx_create(1, NULL) == FRICREG_ENULL, "create(1, NULL)");
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    struct fuzz_input in = {data, size, 0};
    last_error = FRICREG_OK;
    uint8_t first = fuzz_byte(&in);
    if (first >= 252) {
        check_create_refusals(first);
        return 0;
    }
    size_t m = 1 + first % MAX_M, n = 2 * m;
    fricreg_disk_ctx *ctx = NULL;
    if (fricreg_disk_ctx_create(m, &ctx) != FRICREG_OK)
        return 0; /* out of memory: nothing to fuzz */
    struct model md = {.m = m, .law = FRICREG_DISK_QUINN, .eps = 1e-3};
    for (size_t i = 0; i < m; i++)
        md.mun[i] = 1.0;
    for (size_t k = 0; k < n; k++)
        md.W[k * n + k] = 1.0;
    while (!fuzz_done(&in)) {
        switch (fuzz_byte(&in) % 8) {
        case 0: op_set_law(&in, ctx, &md); break;
        case 1: op_set_bounds(&in, ctx, &md); break;
        case 2: op_set_stribeck(&in, ctx, &md); break;
        case 3: op_set_blocks(&in, ctx, &md); break;
        case 4: op_set_dense(&in, ctx, &md); break;
        case 5: op_eval(&in, ctx, &md); break;
        case 6: op_tangent(&in, ctx, &md); break;
        default: op_misc(&in, ctx, &md);
        }
    }
    fricreg_disk_ctx_free(ctx);
    return 0;
}
