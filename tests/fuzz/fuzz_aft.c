/* SPDX-License-Identifier: GPL-3.0-or-later */
/* fuzz_aft.c — fuzz target: the AFT of the joint elements (include/fricreg_aft.h): the exact
 * and sampled force coefficients of a Jenkins element, an Iwan element of up to four sliders,
 * a Jenkins element under a normal load with lift-off and (sampled) the 3-D contact element,
 * the last chosen by a byte after the coefficients (so that inputs written before it keep
 * their meaning), with and without the Jacobian, at
 * H = 1..6 and N = 0 or a power of two up to 1024, on parameters and coefficients from the
 * input (moderate, special or any bits). Contract: the status is OK or one the docstring names
 * for the inputs (EINVAL, ENONFINITE, EINTEGRATOR; ESIZE cannot arise, n is right), recorded
 * with a message; on failure the outputs are untouched; on success they are finite and the
 * force keeps its bound: |f_0| <= B and |f_h| <= 2 B for the pointwise bound B (mun, the
 * sliders' sum of phi, or mu (|N0| + kn sum |g_j|)), up to 1e-9 B, the rounding of kt u
 * (1e-12 of kt sum |u_j|, and 4 kt n subnormal quanta: fricreg_aft.h) and 64 n^2 subnormal
 * quanta (forces computed in the subnormals); the normal force 0 <= N <= |N0| + kn sum |g_j| likewise; and a constant normal load
 * (kn = 0, N0 >= 0) gives the plain element's coefficients at mun = mu N0, to 1e-6 mu N0 plus
 * that rounding, where u's oscillation is resolved at all (fricreg_aft_jenkins_normal_exact's
 * docstring). */
#include "fuzz_input.h"

#include "fricreg_aft.h"

enum { MAX_H = 6, MAX_NC = 2 * MAX_H + 1, MAX_SLIDERS = 4 };

/* The spacing of the subnormals: a bound that underflows (mu N0 = 1e-265 x 5e-324) leaves
 * forces of a few of them, the rounding of products in that range. */
#define SUBNORMAL_QUANTUM 4.9406564584124654e-324
/* The absolute floor of a force computed in the subnormals: each product kt u_j, G_ij x_j
 * there rounds to a quantum, about n^2 of them per piece (a subnormal kt of 5e-315 beside u of
 * 2e-8 and a bound of 4 quanta gave f_0 of 117 quanta; fricreg_aft.h's rounding) */
#define SUBNORMAL_FLOOR(n) (64.0 * (double)((n) * (n)) * SUBNORMAL_QUANTUM)

enum { JENKINS, IWAN, LIFTOFF, KINDS };

struct call {
    int kind, exact, want_jac, H, planar; /* planar: LIFTOFF as the 3-D contact element */
    size_t n, ns;
    double kt, mu, n0, kn, k[MAX_SLIDERS], phi[MAX_SLIDERS], u[2 * MAX_NC], g[MAX_NC];
};

static double sum_abs(const double *x, size_t n)
{
    double s = 0.0;
    for (size_t j = 0; j < n; j++)
        s += fabs(x[j]);
    return s;
}

static int run(fricreg_aft *a, const struct call *c, double *f, double *nf, double *jac)
{
    double *J = c->want_jac ? jac : NULL;
    switch (c->kind) {
    case JENKINS:
        return c->exact ? fricreg_aft_jenkins_exact(a, c->kt, c->mu, c->n, c->u, f, J)
                        : fricreg_aft_jenkins_sampled(a, c->kt, c->mu, c->n, c->u, f, J);
    case IWAN:
        return c->exact ? fricreg_aft_iwan_exact(a, c->ns, c->k, c->phi, c->n, c->u, f, J)
                        : fricreg_aft_iwan_sampled(a, c->ns, c->k, c->phi, c->n, c->u, f, J);
    default:
        if (c->planar)
            return fricreg_aft_jenkins_2d_normal_sampled(a, c->kt, c->mu, c->n0, c->kn, c->n, c->u,
                                                         c->g, f, nf, J);
        return c->exact ? fricreg_aft_jenkins_normal_exact(a, c->kt, c->mu, c->n0, c->kn, c->n,
                                                           c->u, c->g, f, nf, J)
                        : fricreg_aft_jenkins_normal_sampled(a, c->kt, c->mu, c->n0, c->kn, c->n,
                                                             c->u, c->g, f, nf, J);
    }
}

/* The codes the docstrings allow for these inputs: a bit per code. */
static unsigned allowed(const struct call *c, size_t N)
{
    unsigned codes = 1u << FRICREG_EINTEGRATOR; /* GSL's root solver (exact paths) */
    if ((!c->exact || c->planar) && N == 0)
        codes |= 1u << FRICREG_EINVAL;
    if (c->planar && (!fuzz_all_finite(c->u + c->n, c->n) ||
                      !isfinite(8.0 * fmax(1.0, fabs(c->kt)) * sum_abs(c->u + c->n, c->n))))
        codes |= 1u << FRICREG_ENONFINITE; /* uy, checked as ux */
    const double *u = c->u;
    size_t n = c->n;
    if (!fuzz_all_finite(u, n))
        codes |= 1u << FRICREG_ENONFINITE;
    if (c->kind == IWAN) {
        double ksum = 0.0;
        for (size_t s = 0; s < c->ns; s++) {
            if (!isfinite(c->k[s]) || !isfinite(c->phi[s]))
                codes |= 1u << FRICREG_ENONFINITE;
            if (!(c->k[s] > 0.0) || !(c->phi[s] >= 0.0))
                codes |= 1u << FRICREG_EINVAL;
            ksum += fabs(c->k[s]);
        }
        if (!isfinite(8.0 * fmax(1.0, ksum) * sum_abs(u, n)))
            codes |= 1u << FRICREG_ENONFINITE;
        return codes;
    }
    if (!isfinite(c->kt) || !isfinite(c->mu) ||
        !isfinite(8.0 * fmax(1.0, fabs(c->kt)) * sum_abs(u, n)))
        codes |= 1u << FRICREG_ENONFINITE;
    if (!(c->kt > 0.0) || !(c->mu >= 0.0))
        codes |= 1u << FRICREG_EINVAL;
    if (c->kind == LIFTOFF) {
        if (!isfinite(c->n0) || !isfinite(c->kn) || !fuzz_all_finite(c->g, n) ||
            !isfinite(8.0 * (1.0 + fabs(c->mu)) *
                      (fabs(c->n0) + fabs(c->kn) * (1.0 + sum_abs(c->g, n)))))
            codes |= 1u << FRICREG_ENONFINITE;
        if (!(c->kn >= 0.0))
            codes |= 1u << FRICREG_EINVAL;
        if ((!c->exact || c->planar) &&
            !isfinite(8.0 * c->mu * (fabs(c->n0) + c->kn * (1.0 + sum_abs(c->g, n))) / c->kt))
            codes |= 1u << FRICREG_ENONFINITE; /* the sampled march's slider excursion */
    }
    return codes;
}

static void check_bound(const struct call *c, const char *what, const double *x, double bound,
                        double slack)
{
    for (size_t j = 0; j < c->n; j++)
        FUZZ_REQUIRE(fabs(x[j]) <= (j == 0 ? 1.0 : 2.0) * bound * (1.0 + 1e-9) + slack +
                                       SUBNORMAL_FLOOR(c->n),
                     "kind %d exact %d H %d: %s[%zu] = %g beyond its bound %g (slack %g; kt %g "
                     "mu %g n0 %g kn %g u0 %g u1 %g)",
                     c->kind, c->exact, c->H, what, j, x[j], bound, slack, c->kt, c->mu, c->n0,
                     c->kn, c->u[0], c->u[1]);
}

static void check_success(fricreg_aft *a, const struct call *c, const double *f, const double *nf,
                          const double *jac)
{
    size_t n = c->n;
    FUZZ_REQUIRE(fuzz_all_finite(f, n), "f not finite");
    double kts = c->kt, B = c->mu;
    if (c->kind == IWAN) {
        kts = B = 0.0;
        for (size_t s = 0; s < c->ns; s++)
            kts += c->k[s], B += c->phi[s];
    }
    /* the rounding of kt u: relative, and absolute in the subnormals (u of 5e-324 in every
     * coefficient gives forces of kt n quanta, whatever the bound; the header's rounding).
     * kt sum |u_j| first: 1e-12 kt underflowed for a subnormal kt (1e-314 against u of 2e19,
     * whose sticks are below the rounding of u: the two exact paths resolve them differently) */
    double slack = 1e-12 * (kts * sum_abs(c->u, n)) + kts * (4.0 * (double)n * SUBNORMAL_QUANTUM);
    if (c->kind == LIFTOFF) {
        double pmax = fmax(0.0, fabs(c->n0) + c->kn * sum_abs(c->g, n));
        FUZZ_REQUIRE(fuzz_all_finite(nf, n), "nf not finite");
        check_bound(c, "nf", nf, pmax, 1e-12 * pmax);
        B = c->mu * pmax;
    }
    check_bound(c, "f", f, B, slack);
    if (c->planar) { /* fy, and the rounding of kt uy */
        double slack_y = slack + 1e-12 * (kts * sum_abs(c->u + n, n));
        FUZZ_REQUIRE(fuzz_all_finite(f + n, n), "fy not finite");
        check_bound(c, "fy", f + n, B, slack_y);
    }
    if (c->want_jac) {
        size_t w = c->kind == LIFTOFF ? (c->planar ? 3 : 2) * n : n;
        FUZZ_REQUIRE(fuzz_all_finite(jac, w * w), "jac not finite");
    }
    if (c->planar)
        return;
    /* u's oscillation below the rounding of u itself (5e-324 beside a mean of 2e-307): no
     * motion is resolved, and the two paths may stick and slip differently within the bound */
    double swing = sum_abs(c->u + 1, n - 1);
    int resolved = swing > 1e-12 * sum_abs(c->u, n) && swing > 64.0 * (double)n * SUBNORMAL_QUANTUM;
    if (c->kind == LIFTOFF && c->kn == 0.0 && c->n0 >= 0.0 && resolved) { /* plain at mu N0 */
        double fj[MAX_NC];
        int status = c->exact
                         ? fricreg_aft_jenkins_exact(a, c->kt, c->mu * c->n0, n, c->u, fj, NULL)
                         : fricreg_aft_jenkins_sampled(a, c->kt, c->mu * c->n0, n, c->u, fj, NULL);
        if (status == FRICREG_OK)
            for (size_t j = 0; j < n; j++)
                FUZZ_REQUIRE(fabs(f[j] - fj[j]) <=
                                 1e-6 * c->mu * c->n0 + slack + SUBNORMAL_FLOOR(n),
                             "f[%zu] = %.17g, the plain element's %.17g", j, f[j], fj[j]);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    struct fuzz_input in = {data, size, 0};
    struct call c = {0};
    c.kind = fuzz_byte(&in) % KINDS;
    c.exact = fuzz_byte(&in) % 2;
    c.want_jac = fuzz_byte(&in) % 2;
    c.H = 1 + fuzz_byte(&in) % MAX_H;
    c.n = 2 * (size_t)c.H + 1;
    size_t N = 0;
    uint8_t sel = fuzz_byte(&in) % 4; /* 0, or 2^k from the smallest the object takes to 1024 */
    if (sel > 0) {
        N = 16;
        while (N < 2 * (size_t)c.H + 2)
            N *= 2;
        N <<= 2 * (sel - 1);
    }
    c.kt = fuzz_double(&in);
    c.mu = fuzz_double(&in);
    c.n0 = fuzz_double(&in);
    c.kn = fuzz_double(&in);
    c.ns = 1 + fuzz_byte(&in) % MAX_SLIDERS;
    for (size_t s = 0; s < c.ns; s++) {
        c.k[s] = fuzz_double(&in);
        c.phi[s] = fuzz_double(&in);
    }
    for (size_t j = 0; j < c.n; j++) {
        c.u[j] = fuzz_double(&in);
        c.g[j] = fuzz_double(&in);
    }
    c.planar = c.kind == LIFTOFF && fuzz_byte(&in) % 2;
    for (size_t j = 0; c.planar && j < c.n; j++)
        c.u[c.n + j] = fuzz_double(&in); /* uy */
    fricreg_aft *a = NULL;
    FUZZ_REQUIRE(fricreg_aft_create(c.H, N, &a) == FRICREG_OK, "create H %d N %zu", c.H, N);
    static double f[2 * MAX_NC], nf[MAX_NC], jac[9 * MAX_NC * MAX_NC];
    fuzz_fill(f, sizeof f);
    fuzz_fill(nf, sizeof nf);
    fuzz_fill(jac, sizeof jac);
    int status = run(a, &c, f, nf, jac);
    if (status == FRICREG_OK) {
        check_success(a, &c, f, nf, jac);
    } else {
        FUZZ_REQUIRE(allowed(&c, N) & (1u << status), "status %d (%s) not allowed for the inputs",
                     status, fricreg_aft_errmsg(a));
        FUZZ_REQUIRE(fricreg_aft_errcode(a) == status && fricreg_aft_errmsg(a)[0] != '\0',
                     "status %d not recorded", status);
        FUZZ_REQUIRE(fuzz_untouched(f, sizeof f) && fuzz_untouched(nf, sizeof nf) &&
                         fuzz_untouched(jac, sizeof jac),
                     "outputs written on failure (status %d)", status);
    }
    fricreg_aft_free(a);
    return 0;
}
