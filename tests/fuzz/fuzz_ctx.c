/* SPDX-License-Identifier: GPL-3.0-or-later */
/* fuzz_ctx.c — fuzz target: the context's whole life (include/fricreg.h). The input is a
 * program of operations on one context of m <= 6 contacts: set law and eps, bounds, a diagonal
 * or dense W (random symmetric, hence often indefinite; B B^T of low rank, hence singular;
 * non-symmetric; scaled to huge or subnormal entries; NaN/Inf entries), either partition,
 * eval, tangent, stick stiffness, counters and messages, each now and then with a wrong size
 * or a NULL. Every call is held to its docstring: status in the documented set, outputs and
 * the context's state untouched on failure (sentinels), a message on each recorded failure;
 * on success f finite with |f_i| <= mun_i, each f_i the law at (zdot_i, f_eq,i) on the
 * near-stick set (the force balance f = clamp(f_eq, ±mun) at zdot_i = 0), the slip contacts
 * at the law with no f_eq, and f_eq = -a_free/w exactly for a diagonal W. */

#include "fuzz_condition.h"
#include "fuzz_input.h"

#include "fricreg.h"

enum { MAX_M = 6 };

/* What the context holds, as the calls that succeeded set it. */
struct model {
    size_t m;
    int law;
    double eps;
    double mun[MAX_M];
    int dense;
    double W[MAX_M * MAX_M]; /* the diagonal holds w when !dense */
    int evaluated;           /* an eval succeeded since the last setter */
    int partition;
};

#define CODE(c) (1u << (c))

static void require_status(fricreg_ctx *ctx, int status, unsigned allowed, const char *call)
{
    FUZZ_REQUIRE(status == FRICREG_OK || (status > 0 && status < 32 && (allowed >> status & 1u)),
                 "%s: status %d (%s) not documented (mask %#x)", call, status,
                 fricreg_strerror(status), allowed);
    if (status != FRICREG_OK && ctx != NULL) {
        FUZZ_REQUIRE(fricreg_ctx_errcode(ctx) == status, "%s: errcode %d, returned %d", call,
                     fricreg_ctx_errcode(ctx), status);
        FUZZ_REQUIRE(fricreg_ctx_errmsg(ctx)[0] != '\0', "%s: failure %d with no message", call,
                     status);
    }
}

/* A size: the context's, or one off, or an absurd one. */
static size_t fuzz_size(struct fuzz_input *in, size_t m)
{
    switch (fuzz_byte(in) % 16) {
    case 0: return m + 1;
    case 1: return m - 1;
    case 2: return SIZE_MAX;
    case 3: return (size_t)1 << 33;
    default: return m;
    }
}

static int law_uses_feq(int law)
{
    return law == FRICREG_LAW_FORCE_BALANCE || law == FRICREG_LAW_KARNOPP ||
           law == FRICREG_LAW_QUINN;
}

static int near_stick(const struct model *md, double zdot)
{
    switch (md->law) {
    case FRICREG_LAW_FORCE_BALANCE: return zdot == 0.0;
    case FRICREG_LAW_KARNOPP:
    case FRICREG_LAW_QUINN: return fabs(zdot) < md->eps;
    default: return 0;
    }
}

static void op_set_law(struct fuzz_input *in, fricreg_ctx *ctx, struct model *md)
{
    int law = fuzz_int(in, 0, 8);
    double eps = fuzz_double(in);
    int status = fricreg_ctx_set_law(ctx, law, eps);
    require_status(ctx, status, CODE(FRICREG_EINVAL) | CODE(FRICREG_ENONFINITE), "set_law");
    if (status == FRICREG_OK) {
        FUZZ_REQUIRE(fricreg_law_name(law) != NULL && isfinite(eps) && eps >= DBL_MIN,
                     "set_law took law %d eps %g", law, eps);
        md->law = law;
        md->eps = eps;
        md->evaluated = 0;
    }
}

static void op_set_bounds(struct fuzz_input *in, fricreg_ctx *ctx, struct model *md)
{
    size_t m = fuzz_size(in, md->m);
    double mun[MAX_M];
    for (size_t i = 0; i < MAX_M; i++)
        mun[i] = fabs(fuzz_double(in)) * (fuzz_byte(in) == 9 ? -1.0 : 1.0);
    int status = fricreg_ctx_set_bounds(ctx, m, fuzz_byte(in) == 1 ? NULL : mun);
    require_status(ctx, status,
                   CODE(FRICREG_ENULL) | CODE(FRICREG_ESIZE) | CODE(FRICREG_EINVAL) |
                       CODE(FRICREG_ENONFINITE),
                   "set_bounds");
    if (status == FRICREG_OK) {
        FUZZ_REQUIRE(m == md->m, "set_bounds took m = %zu", m);
        for (size_t i = 0; i < m; i++)
            FUZZ_REQUIRE(isfinite(mun[i]) && mun[i] >= 0.0, "set_bounds took mun %g", mun[i]);
        memcpy(md->mun, mun, m * sizeof *mun);
        md->evaluated = 0;
    }
}

static void op_set_diagonal(struct fuzz_input *in, fricreg_ctx *ctx, struct model *md)
{
    size_t m = fuzz_size(in, md->m);
    double w[MAX_M];
    for (size_t i = 0; i < MAX_M; i++)
        w[i] = fuzz_double(in);
    int status = fricreg_ctx_set_coupling_diagonal(ctx, m, fuzz_byte(in) == 1 ? NULL : w);
    require_status(ctx, status,
                   CODE(FRICREG_ENULL) | CODE(FRICREG_ESIZE) | CODE(FRICREG_EINVAL) |
                       CODE(FRICREG_ENONFINITE),
                   "set_coupling_diagonal");
    if (status == FRICREG_OK) {
        FUZZ_REQUIRE(m == md->m, "set_coupling_diagonal took m = %zu", m);
        md->dense = 0;
        for (size_t i = 0; i < m; i++) {
            FUZZ_REQUIRE(isfinite(w[i]) && w[i] > 0.0, "set_coupling_diagonal took w %g", w[i]);
            md->W[i * m + i] = w[i];
        }
        md->evaluated = 0;
    }
}

static void op_set_dense(struct fuzz_input *in, fricreg_ctx *ctx, struct model *md)
{
    size_t m = fuzz_size(in, md->m);
    double W[MAX_M * MAX_M], scratch[MAX_M * MAX_M];
    fuzz_matrix(in, md->m, W, scratch);
    double W0[MAX_M * MAX_M];
    memcpy(W0, W, sizeof W);
    int status = fricreg_ctx_set_coupling_dense(ctx, m, fuzz_byte(in) == 1 ? NULL : W);
    require_status(ctx, status,
                   CODE(FRICREG_ENULL) | CODE(FRICREG_ESIZE) | CODE(FRICREG_ENONFINITE) |
                       CODE(FRICREG_ENOTSYM) | CODE(FRICREG_ENOTPSD) | CODE(FRICREG_ENOMEM),
                   "set_coupling_dense");
    FUZZ_REQUIRE(memcmp(W, W0, sizeof W) == 0, "set_coupling_dense changed the caller's W");
    if (status == FRICREG_OK) {
        FUZZ_REQUIRE(m == md->m, "set_coupling_dense took m = %zu", m);
        for (size_t i = 0; i < m; i++)
            FUZZ_REQUIRE(isfinite(W[i * m + i]) && W[i * m + i] > 0.0,
                         "set_coupling_dense took W_%zu%zu = %g", i, i, W[i * m + i]);
        md->dense = 1;
        memcpy(md->W, W, m * m * sizeof *W);
        md->evaluated = 0;
    }
}

static void op_set_partition(struct fuzz_input *in, fricreg_ctx *ctx, struct model *md)
{
    int partition = fuzz_int(in, 0, 4);
    int status = fricreg_ctx_set_partition(ctx, partition);
    require_status(ctx, status, CODE(FRICREG_EINVAL), "set_partition");
    FUZZ_REQUIRE(status != FRICREG_OK || partition == FRICREG_PARTITION_CONSISTENT ||
                     partition == FRICREG_PARTITION_PAPER,
                 "set_partition took %d", partition);
    if (status == FRICREG_OK) {
        md->evaluated = 0;
        md->partition = partition;
    }
}

/* FUZZ_TRACE=1 in the environment: print each successful eval (to read a finding). */
static void trace_eval(const struct model *md, const double zdot[], const double a_free[],
                       const double f[], const double f_eq[])
{
    if (getenv("FUZZ_TRACE") == NULL)
        return;
    size_t m = md->m;
    fprintf(stderr, "eval: m %zu law %d eps %.17g partition %d dense %d\n", m, md->law, md->eps,
            md->partition, md->dense);
    for (size_t i = 0; i < m; i++) {
        fprintf(stderr, "  W[%zu] =", i);
        for (size_t j = 0; j < m; j++)
            fprintf(stderr, " %.17g", md->dense || i == j ? md->W[i * m + j] : 0.0);
        fprintf(stderr, "\n  mun %.17g zdot %.17g a_free %.17g -> f %.17g f_eq %.17g\n", md->mun[i],
                zdot[i], a_free[i], f[i], f_eq[i]);
    }
}

/* The law at one contact, with the context's law, eps and bound. */
static double law_at(const struct model *md, size_t i, double zdot, double f_eq)
{
    double f = NAN;
    int status = fricreg_law_eval(md->law, zdot, f_eq, md->mun[i], md->eps, &f);
    FUZZ_REQUIRE(status == FRICREG_OK, "law_eval(%d, %g, %g, %g, %g): %d", md->law, zdot, f_eq,
                 md->mun[i], md->eps, status);
    return f;
}

/* The condition number of the Jacobi-scaled W_SS (unit diagonal), S the contacts in_s marks:
 * fricreg_ctx_eval's forces are accurate to the rounding of their sums times it (fricreg.h).
 * GSL's symmetric eigensolver on a copy; +Inf if W_SS is singular to it. */
static double scaled_condition(const struct model *md, const int in_s[])
{
    size_t m = md->m, s = 0, pos[MAX_M];
    for (size_t i = 0; i < m; i++)
        if (in_s[i])
            pos[s++] = i;
    return fuzz_scaled_condition(md->W, m, pos, s);
}

static void check_forces(const struct model *md, const double zdot[], const double a_free[],
                         const double f[], const double f_eq[])
{
    size_t m = md->m;
    double largest_scaled = 0.0; /* max_j sqrt(W_jj) |f_j|, the forces in Jacobi-scaled units */
    for (size_t j = 0; md->dense && j < m; j++)
        largest_scaled = fmax(largest_scaled, sqrt(md->W[j * m + j]) * fabs(f[j]));
    int near[MAX_M];
    for (size_t j = 0; j < m; j++)
        near[j] = near_stick(md, zdot[j]) && law_uses_feq(md->law);
    /* relative accuracy of a dense solve: 1e-6, or 64 m eps times the scaled condition */
    double rtol = md->dense
                      ? fmax(1e-6, 64.0 * (double)m * DBL_EPSILON * scaled_condition(md, near))
                      : 0.0;
    for (size_t i = 0; i < m; i++) {
        FUZZ_REQUIRE(isfinite(f[i]) && fabs(f[i]) <= md->mun[i],
                     "eval: f[%zu] = %g, mun %g (law %d eps %g dense %d)", i, f[i], md->mun[i],
                     md->law, md->eps, md->dense);
        int in_s = near_stick(md, zdot[i]) && law_uses_feq(md->law);
        FUZZ_REQUIRE(in_s != isnan(f_eq[i]), "eval: contact %zu zdot %g: f_eq %g (law %d)", i,
                     zdot[i], f_eq[i], md->law);
        if (!in_s) {
            FUZZ_REQUIRE(f[i] == law_at(md, i, zdot[i], 0.0), "eval: slip contact %zu f %.17g", i,
                         f[i]);
            continue;
        }
        /* an f_eq that overflowed is beyond every bound: the law sees it as +-DBL_MAX */
        double feq = isinf(f_eq[i]) ? copysign(DBL_MAX, f_eq[i]) : f_eq[i];
        if (!md->dense) { /* contact by contact, exactly the scalar law */
            FUZZ_REQUIRE(f_eq[i] == -a_free[i] / md->W[i * m + i], "eval: f_eq[%zu] %.17g", i,
                         f_eq[i]);
            FUZZ_REQUIRE(f[i] == law_at(md, i, zdot[i], feq), "eval: f[%zu] %.17g, law %.17g", i,
                         f[i], law_at(md, i, zdot[i], feq));
            continue;
        }
        /* Dense: f_i is the law at (zdot_i, f_eq,i) to what fricreg_ctx_eval promises: the
         * rounding of the sums forming f_eq times the scaled condition number of W_SS (rtol:
         * 64 m eps cond, at least 1e-6), or, the solve being backward stable in the
         * Jacobi-scaled norm, 1e-6 of the largest scaled force max_j sqrt(W_jj) |f_j| over
         * sqrt(W_ii) (a contact beside one whose scaled force is 1e52 times its own lost its
         * digits to an updated factor: fuzz finding); and the underflow floor, 1e-292 in
         * acceleration units, 1e-292/W_ii in force units (and 1e-292 in force units). */
        double scale = fabs(a_free[i]), w_ii = md->W[i * m + i];
        for (size_t j = 0; j < m; j++)
            scale += fabs(md->W[i * m + j] * f[j]);
        scale = scale / w_ii + md->mun[i] + largest_scaled / sqrt(w_ii);
        double underflow = DBL_MIN / DBL_EPSILON * fmax(1.0, 1.0 / w_ii);
        double expected = law_at(md, i, zdot[i], feq);
        double tolerance = scale > 0.0 ? rtol * scale : 0.0; /* cond may be +Inf: W_SS singular */
        FUZZ_REQUIRE(fabs(f[i] - expected) <= tolerance + underflow,
                     "eval dense: f[%zu] %.17g, law at f_eq %.17g gives %.17g (scale %g)", i, f[i],
                     f_eq[i], expected, scale);
    }
}

static void op_eval(struct fuzz_input *in, fricreg_ctx *ctx, struct model *md)
{
    size_t m = fuzz_size(in, md->m);
    double zdot[MAX_M], a_free[MAX_M], f[MAX_M + 1], f_eq[MAX_M + 1];
    for (size_t i = 0; i < MAX_M; i++) {
        zdot[i] = fuzz_byte(in) < 96 ? 0.0 : fuzz_double(in); /* often exactly at rest */
        a_free[i] = fuzz_double(in);
    }
    uint8_t nulls = fuzz_byte(in);
    fuzz_fill(f, sizeof f);
    fuzz_fill(f_eq, sizeof f_eq);
    int with_feq = nulls != 2;
    int status = fricreg_ctx_eval(ctx, m, nulls == 3 ? NULL : zdot, nulls == 4 ? NULL : a_free,
                                  nulls == 5 ? NULL : f, with_feq ? f_eq : NULL);
    require_status(ctx, status,
                   CODE(FRICREG_ENULL) | CODE(FRICREG_ESIZE) | CODE(FRICREG_ENONFINITE) |
                       CODE(FRICREG_ESINGULAR),
                   "eval");
    if (status != FRICREG_OK) {
        FUZZ_REQUIRE(fuzz_untouched(f, sizeof f) && fuzz_untouched(f_eq, sizeof f_eq),
                     "eval wrote on failure %d", status);
        FUZZ_REQUIRE(status != FRICREG_ESINGULAR || md->dense, "ESINGULAR with a diagonal W");
        return; /* the tangent stays that of the last successful eval */
    }
    FUZZ_REQUIRE(m == md->m && nulls != 3 && nulls != 4 && nulls != 5, "eval took a bad call");
    FUZZ_REQUIRE(fuzz_untouched(f + m, sizeof *f) && fuzz_untouched(f_eq + m, sizeof *f_eq),
                 "eval wrote past m");
    FUZZ_REQUIRE(fuzz_all_finite(zdot, m) && fuzz_all_finite(a_free, m),
                 "eval took a non-finite input");
    md->evaluated = 1;
    if (with_feq)
        trace_eval(md, zdot, a_free, f, f_eq);
    if (with_feq)
        check_forces(md, zdot, a_free, f, f_eq);
}

static void op_tangent(struct fuzz_input *in, fricreg_ctx *ctx, struct model *md)
{
    size_t m = fuzz_size(in, md->m);
    double dz[MAX_M * MAX_M + 1], da[MAX_M * MAX_M + 1];
    fuzz_fill(dz, sizeof dz);
    fuzz_fill(da, sizeof da);
    uint8_t which = fuzz_byte(in) % 4; /* bit 0: df_dzdot, bit 1: df_dafree */
    int status = fricreg_ctx_tangent(ctx, m, which & 1 ? dz : NULL, which & 2 ? da : NULL);
    require_status(ctx, status,
                   CODE(FRICREG_ENULL) | CODE(FRICREG_ESIZE) | CODE(FRICREG_EINVAL) |
                       CODE(FRICREG_ESINGULAR),
                   "tangent");
    if (status != FRICREG_OK) {
        FUZZ_REQUIRE(fuzz_untouched(dz, sizeof dz) && fuzz_untouched(da, sizeof da),
                     "tangent wrote on failure %d", status);
        FUZZ_REQUIRE(status != FRICREG_ESINGULAR, "tangent: ESINGULAR with the same W");
        FUZZ_REQUIRE(status != FRICREG_EINVAL || !md->evaluated,
                     "tangent: EINVAL after a successful eval");
        return;
    }
    FUZZ_REQUIRE(which != 0 && m == md->m && md->evaluated, "tangent took a bad call");
    size_t n = m * m;
    for (size_t k = 0; k < n; k++)
        FUZZ_REQUIRE(!(which & 1) || !isnan(dz[k]), "tangent: df_dzdot[%zu] NaN", k);
    for (size_t k = 0; k < n; k++)
        FUZZ_REQUIRE(!(which & 2) || !isnan(da[k]), "tangent: df_dafree[%zu] NaN", k);
    FUZZ_REQUIRE((!(which & 1) || fuzz_untouched(dz + n, sizeof *dz)) &&
                     (!(which & 2) || fuzz_untouched(da + n, sizeof *da)),
                 "tangent wrote past m*m");
}

static void op_stiffness(struct fuzz_input *in, fricreg_ctx *ctx)
{
    double lambda;
    fuzz_fill(&lambda, sizeof lambda);
    int null_out = fuzz_byte(in) == 1;
    int status = fricreg_ctx_stick_stiffness(ctx, null_out ? NULL : &lambda);
    require_status(ctx, status, CODE(FRICREG_ENULL) | CODE(FRICREG_ENOMEM), "stick_stiffness");
    if (status != FRICREG_OK)
        FUZZ_REQUIRE(fuzz_untouched(&lambda, sizeof lambda), "stick_stiffness wrote on failure");
    else
        FUZZ_REQUIRE(!null_out && lambda >= 0.0, "stick_stiffness: lambda %g", lambda);
}

static void op_misc(struct fuzz_input *in, fricreg_ctx *ctx)
{
    int which = fuzz_int(in, -1, 7);
    int64_t value;
    fuzz_fill(&value, sizeof value);
    int status = fricreg_ctx_get_stat(ctx, which, &value);
    FUZZ_REQUIRE(status == (which >= 0 && which <= FRICREG_STAT_FACTOR_UPDATES ? FRICREG_OK
                                                                               : FRICREG_EINVAL),
                 "get_stat(%d): %d", which, status);
    FUZZ_REQUIRE(status == FRICREG_OK ? value >= 0 : fuzz_untouched(&value, sizeof value),
                 "get_stat(%d) value", which);
    char buf[8];
    size_t len = fuzz_byte(in) % (sizeof buf + 1);
    fuzz_fill(buf, sizeof buf);
    size_t full = fricreg_ctx_errmsg_copy(ctx, buf, len);
    FUZZ_REQUIRE(full == (len > 0 ? strlen(fricreg_ctx_errmsg(ctx)) : 0), "errmsg_copy length %zu",
                 full); /* len 0: 0 and nothing written */
    if (len > 0)
        FUZZ_REQUIRE(memchr(buf, '\0', len) != NULL, "errmsg_copy: no NUL in %zu", len);
    if (len < sizeof buf)
        FUZZ_REQUIRE(fuzz_untouched(buf + len, sizeof buf - len), "errmsg_copy wrote past len");
    if (fuzz_byte(in) & 1)
        fricreg_ctx_reset_stats(ctx);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    struct fuzz_input in = {data, size, 0};
    size_t m = 1 + fuzz_byte(&in) % MAX_M;
    fricreg_ctx *ctx = NULL;
    if (fricreg_ctx_create(m, &ctx) != FRICREG_OK)
        return 0; /* out of memory: nothing to fuzz */
    struct model md = {.m = m,
                       .law = FRICREG_LAW_QUINN,
                       .eps = 1e-3,
                       .partition = FRICREG_PARTITION_CONSISTENT};
    for (size_t i = 0; i < m; i++) {
        md.mun[i] = 1.0;
        md.W[i * m + i] = 1.0;
    }
    FUZZ_REQUIRE(fricreg_ctx_size(ctx) == m, "ctx_size");
    while (!fuzz_done(&in)) {
        switch (fuzz_byte(&in) % 9) {
        case 0: op_set_law(&in, ctx, &md); break;
        case 1: op_set_bounds(&in, ctx, &md); break;
        case 2: op_set_diagonal(&in, ctx, &md); break;
        case 3: op_set_dense(&in, ctx, &md); break;
        case 4: op_set_partition(&in, ctx, &md); break;
        case 5: op_eval(&in, ctx, &md); break;
        case 6: op_tangent(&in, ctx, &md); break;
        case 7: op_stiffness(&in, ctx); break;
        default: op_misc(&in, ctx);
        }
    }
    fricreg_ctx_free(ctx);
    return 0;
}
