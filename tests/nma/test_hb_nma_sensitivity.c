/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_hb_nma_sensitivity.c — Check suite for the exact parameter sensitivities of a backbone
 * point (fricreg_hb_nma_point_sensitivities, fricreg_hb.h). Where the numbers come from:
 *
 *   - the 1-dof Jenkins oscillator of test_hb_nma.c at H = 1, whose backbone is the describing
 *     function's closed form, differentiated here by hand in kt, mun and a (to 1e-8);
 *   - central differences of whole backbones, each solved again with the parameter moved (the
 *     same amplitude grid, Newton's tolerance 1e-12), at the relative steps h = 1e-5 and 2e-5
 *     combined by Richardson's extrapolation (4 D(h) − D(2h))/3: a plain central difference's
 *     h² term alone reaches 2e-6 of the largest derivative next to an element's onset of slip,
 *     where the backbone's third derivative is large (measured; its error falls as h², so it
 *     is the difference's, not the sensitivity's). Each derivative of ω, ζ and every dof's
 *     |X_1| agrees to 1e-6 of its largest magnitude over the points (plus Newton's tolerance
 *     over the step, for the ones that are 0: a stuck element's slip force); the models:
 *     NLvib's 3-dof Jenkins chain (tests/support/hb_chain.h) with the matrix C, Rayleigh's and
 *     the modal damping;
 *     the 60-dof chain of test_hb_monodromy.c with 10 Jenkins elements (shared kt and mun);
 *     the 3-D contact element of test_hb_contact_3d.c (kt, mu, kn, n0); Iwan sliders (per
 *     slider) and the Jenkins and Iwan elements with lift-off of test_hb_liftoff.c; the
 *     marched types jenkins_2d, iwan_2d and dahl (by one central difference at h: a sampled
 *     AFT's backbone has kinks that 2h may reach); the sparse path against the dense one;
 *   - identities: the Jenkins-only model scales, F(λq; k, λφ) = λ F(q; k, φ), so
 *     a dω/da + Σ_e mun_e dω/dmun_e = 0 (the same for ζ) and a d|X|/da + Σ_e mun_e d|X|/dmun_e
 *     = |X|; a shared parameter is the sum of the per-element ones;
 *   - every status, nothing written on failure, the driver's results unchanged by a call.
 *
 * HB_PRINT=1 prints the measured agreements and the cost of a point's sensitivities against one
 * Newton iteration of the 60-dof chain's backbone; HB_PRINT_ALL=1 every comparison. */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "fricreg_element.h"
#include "fricreg_hb.h"
#include "hb_chain.h"

#define SENTINEL (-777.125)
#define MAXP 16  /* points of a backbone */
#define MAXN 60  /* dofs */
#define MAXS 8   /* sensitivities of one call */
#define MAXPAR 6 /* a model's parameters moved together */

static const double pi = 3.14159265358979323846;

enum {
    ELEMENT = FRICREG_HB_NMA_PARAM_ELEMENT,
    DAMPING = FRICREG_HB_NMA_PARAM_DAMPING,
    AMPLITUDE = FRICREG_HB_NMA_PARAM_AMPLITUDE,
    MATRIX = FRICREG_HB_NMA_DAMPING_MATRIX,
    MODAL = FRICREG_HB_NMA_DAMPING_MODAL
};

/* ---- The models: each a function of its parameter vector p ------------------------------- */

typedef fricreg_hb *(*builder)(const double *p);

/* The oscillator of test_hb_nma.c: m = 1, k = 1, one Jenkins element p = (kt, mun), H = 1. */
static fricreg_hb *oscillator(const double *p)
{
    fricreg_hb *hb = NULL;
    const double one = 1.0;
    ck_assert_int_eq(fricreg_hb_create(1, 1, 1, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, 1, &one), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 1, &one), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_elements(hb, 1, 1, &one, p, p + 1), FRICREG_OK);
    return hb;
}

/* NLvib's chain (hb_chain.h, jenkins, H = 7) with p = (kt0, mun0, kt1, mun1, s, a0, a1, R):
 * C = s 0.02 K (R = 0) or Rayleigh's a0 M + a1 K (R = 1). */
static const double CHAIN_J[6] = {1, 0, 0, -1, 1, 0};
static fricreg_hb *chain(const double *p)
{
    fricreg_hb *hb = hb_chain(0, 0);
    ck_assert_ptr_nonnull(hb);
    double C[9] = {0.04, -0.02, 0, -0.02, 0.04, -0.02, 0, -0.02, 0.04};
    for (int k = 0; k < 9; k++)
        C[k] *= p[4];
    ck_assert_int_eq(fricreg_hb_clear_elements(hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_add_elements(hb, fricreg_element_lookup("jenkins"), 2, 3, CHAIN_J,
                                             p),
                     FRICREG_OK);
    if (p[7] != 0.0)
        ck_assert_int_eq(fricreg_hb_set_rayleigh(hb, p[5], p[6]), FRICREG_OK);
    else
        ck_assert_int_eq(fricreg_hb_set_damping(hb, 3, C), FRICREG_OK);
    return hb;
}

/* The chain made sparse: its K given again in compressed columns (upper triangle), which turns
 * the driver's model sparse (M and C, or Rayleigh's, converted with it). */
static fricreg_hb *sparse_chain(const double *p)
{
    fricreg_hb *hb = chain(p);
    const int64_t ptr[4] = {0, 1, 3, 5}, ind[5] = {0, 0, 1, 1, 2};
    const double values[5] = {2, -1, 2, -1, 2};
    ck_assert_int_eq(fricreg_hb_set_stiffness_csc(hb, 3, FRICREG_SPARSE_UPPER, ptr, ind, values),
                     FRICREG_OK);
    return hb;
}

/* The chain with two Iwan elements of three sliders each: p = (k[6], phi[6]). */
static fricreg_hb *iwan_chain(const double *p)
{
    fricreg_hb *hb = hb_chain(0, 0);
    ck_assert_ptr_nonnull(hb);
    ck_assert_int_eq(fricreg_hb_set_iwan(hb, 2, 3, CHAIN_J, 3, p, p + 6), FRICREG_OK);
    return hb;
}

/* hb_chain.h's chain at H = 3 (the march's cost grows with H: 0.6 s a backbone at H = 7),
 * marched: jenkins_2d (p = (kt0, mun0, kt1, mun1)) or iwan_2d of two sliders (p = (k[2],
 * phi[2]) of each element), their second components on dofs 4 and 5, as hb_chain(1, 0); or the
 * 3-dof chain with two Dahl elements, p = (sigma0, fc0, sigma1, fc1). */
static const double MARCHED_J[20] = {1, 0, 0, 0, 0, 0, 0, 0, 1, 0, -1, 1, 0, 0, 0, 0, 0, 0, 0, 1};
static fricreg_hb *marched_model(const char *name, size_t ns, const double *p)
{
    size_t n = ns > 0 ? 5 : 3;
    double M[25] = {0}, K[25] = {0}, C[25];
    for (size_t i = 0; i < n; i++) {
        M[i * n + i] = 1.0;
        K[i * n + i] = i < 3 ? 2.0 : 1.0;
        if (i > 0 && i < 3)
            K[i * n + i - 1] = K[(i - 1) * n + i] = -1.0;
    }
    for (size_t i = 0; i < n * n; i++)
        C[i] = 0.02 * K[i];
    const fricreg_element_type *type = fricreg_element_lookup(name);
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(n, 2, 3, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, n, M), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, n, K), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_damping(hb, n, C), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_add_elements(hb, ns > 0 ? fricreg_element_sliders(type, ns) : type,
                                             2, n, ns > 0 ? MARCHED_J : CHAIN_J, p),
                     FRICREG_OK);
    return hb;
}

static fricreg_hb *marched_chain(const double *p)
{
    return marched_model("jenkins_2d", 1, p);
}

static fricreg_hb *marched_iwan(const double *p)
{
    return marched_model("iwan_2d", 2, p);
}

static fricreg_hb *dahl_chain(const double *p)
{
    return marched_model("dahl", 0, p);
}

/* The 60-dof chain of test_hb_monodromy.c (unit masses and springs, C = 0.002 (K + M), 10
 * Jenkins elements grounding dofs 3, 9, ..., 57; H = 3), every element's p = (kt, mun). */
#define LONG_N 60
#define LONG_M 10
static fricreg_hb *long_chain(const double *p)
{
    static double M[LONG_N * LONG_N], K[LONG_N * LONG_N], C[LONG_N * LONG_N], J[LONG_M * LONG_N];
    const size_t n = LONG_N;
    memset(M, 0, sizeof M);
    memset(K, 0, sizeof K);
    memset(J, 0, sizeof J);
    for (size_t i = 0; i < n; i++) {
        M[i * n + i] = 1.0;
        K[i * n + i] = i + 1 < n ? 2.0 : 1.0;
        if (i > 0)
            K[i * n + i - 1] = K[(i - 1) * n + i] = -1.0;
    }
    for (size_t i = 0; i < n * n; i++)
        C[i] = 0.002 * (K[i] + M[i]);
    double kt[LONG_M], mun[LONG_M];
    for (size_t e = 0; e < LONG_M; e++) {
        J[e * n + 6 * e + 3] = 1.0;
        kt[e] = p[0];
        mun[e] = p[1];
    }
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(n, LONG_M, 3, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, n, M), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, n, K), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_damping(hb, n, C), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_elements(hb, LONG_M, n, J, kt, mun), FRICREG_OK);
    return hb;
}

/* test_hb_contact_3d.c's inclined plane: a 2-dof mass on a 3-D contact element (its per-kind
 * setter), p = (kt, mu, n0, kn), H = 5. */
static fricreg_hb *contact(const double *p)
{
    const double M[4] = {1.0, 0.0, 0.0, 1.2}, K[4] = {2.0, -0.3, -0.3, 1.5};
    const double C[4] = {0.06, 0.0, 0.0, 0.05}, Je[4] = {1.0, 0.0, 0.0, 1.0}, Jn[2] = {0.4, -0.3};
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(2, 1, 5, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, 2, M), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 2, K), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_damping(hb, 2, C), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_jenkins_2d_normal(hb, 1, 2, Je, Jn, p, p + 1, p + 2, p + 3),
                     FRICREG_OK);
    return hb;
}

/* test_hb_liftoff.c's contact: dof 0 slides, dof 1 presses (g = −x_1), H = 9; p = (kt, mu,
 * n0, kn) of one Jenkins element with lift-off, or (k[3], mu[3], n0, kn) of an Iwan one. */
static fricreg_hb *liftoff_model(const double *p, size_t ns)
{
    const double M[4] = {1.3, 0, 0, 0.9}, K[4] = {2.385, -0.3, -0.3, 1.5}, C[4] = {0.12, 0, 0, 0.1};
    const double Jt[2] = {1.0, 0.0}, Jn[2] = {0.0, -1.0};
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(2, 1, 9, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, 2, M), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 2, K), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_damping(hb, 2, C), FRICREG_OK);
    if (ns == 1)
        ck_assert_int_eq(fricreg_hb_set_normal_elements(hb, 1, 2, Jt, Jn, p, p + 1, p + 2, p + 3),
                         FRICREG_OK);
    else
        ck_assert_int_eq(fricreg_hb_set_iwan_normal(hb, 1, 2, Jt, Jn, ns, p, p + ns, p + 2 * ns,
                                                    p + 2 * ns + 1),
                         FRICREG_OK);
    return hb;
}

static fricreg_hb *liftoff(const double *p)
{
    return liftoff_model(p, 1);
}

static fricreg_hb *iwan_liftoff(const double *p)
{
    return liftoff_model(p, 3);
}

/* ---- The backbones and their finite differences ------------------------------------------ */

struct model {
    builder make;
    const double *p0;
    size_t npar;
    int H;
    size_t mode;
    int damping;
    double a0, a1;
    size_t npts, ndof;
    int plain; /* one central difference at h (a marched model: below), not Richardson's */
};

/* One sensitivity asked and its difference: the model's parameters fd[0..nfd) moved together
 * by h p0[fd[0]] (a parameter shared by them; by h unit if unit > 0), or none with kind
 * AMPLITUDE (the grid scaled by 1 ± h). zeta_k: fd moves the scale of C, whose derivative is ζ_k
 * (the backbone's first point, stuck) times the one in ζ_k. */
struct sens {
    int kind;
    size_t first, count, index;
    size_t nfd;
    size_t fd[MAXPAR];
    int zeta_k;
    double unit;
};

static const double h = 1e-5; /* the differences' relative step */

/* Sensitivity s's step of the difference (of a parameter, or of a[0] for the grid's scale). */
static double step_of(const struct model *md, const struct sens *s, const double *a)
{
    return s->nfd == 0 ? h * a[0] : s->unit > 0.0 ? h * s->unit : h * md->p0[s->fd[0]];
}

/* A backbone's ω, ζ and every dof's |X_1| at its points: [MAXP], [MAXP], [MAXP MAXN]. */
struct backbone {
    double w[MAXP], z[MAXP], x[MAXP * MAXN];
};

static void solve(const struct model *md, const double *p, double grid, struct backbone *b)
{
    fricreg_hb *hb = md->make(p);
    size_t nc = 2 * (size_t)md->H + 1, n = md->ndof;
    double *x = malloc(n * nc * sizeof *x);
    ck_assert_ptr_nonnull(x);
    ck_assert_int_eq(fricreg_hb_set_newton(hb, 1e-12, 50), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_nma(hb, md->mode, md->damping, md->a0 * grid, md->a1 * grid,
                                    md->npts),
                     FRICREG_OK);
    for (size_t i = 0; i < md->npts; i++) {
        double a;
        ck_assert_int_eq(fricreg_hb_nma_point(hb, i, &a, &b->w[i], &b->z[i], n, nc, x), FRICREG_OK);
        for (size_t j = 0; j < n; j++)
            b->x[i * MAXN + j] = hypot(x[j * nc + 1], x[j * nc + 2]);
    }
    free(x);
    fricreg_hb_free(hb);
}

/* The base backbone and its sensitivities: out[k] (ω, ζ and |X_1|'s derivatives, as a
 * backbone's arrays), and the amplitudes a[MAXP]. */
static fricreg_hb *sensitivities(const struct model *md, size_t ns, const struct sens *sp,
                                 struct backbone *out, double *a)
{
    fricreg_hb *hb = md->make(md->p0);
    ck_assert_int_eq(fricreg_hb_set_newton(hb, 1e-12, 50), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_nma(hb, md->mode, md->damping, md->a0, md->a1, md->npts),
                     FRICREG_OK);
    ck_assert_uint_eq(fricreg_hb_nma_points(hb), md->npts);
    int kind[MAXS];
    size_t first[MAXS], count[MAXS], index[MAXS];
    for (size_t k = 0; k < ns; k++) {
        kind[k] = sp[k].kind;
        first[k] = sp[k].first;
        count[k] = sp[k].count;
        index[k] = sp[k].index;
    }
    for (size_t i = 0; i < md->npts; i++) {
        double dw[MAXS], dz[MAXS], dx[MAXS * MAXN], w, z;
        ck_assert_int_eq(fricreg_hb_nma_point(hb, i, &a[i], &w, &z, 0, 0, NULL), FRICREG_OK);
        int status = fricreg_hb_nma_point_sensitivities(hb, i, ns, kind, first, count, index, dw,
                                                        dz, md->ndof, dx);
        ck_assert_msg(status == FRICREG_OK, "point %zu: %s", i, fricreg_hb_errmsg(hb));
        for (size_t k = 0; k < ns; k++) {
            out[k].w[i] = dw[k];
            out[k].z[i] = dz[k];
            for (size_t j = 0; j < md->ndof; j++)
                out[k].x[i * MAXN + j] = dx[k * md->ndof + j];
        }
    }
    return hb;
}

/* The largest |fd − an| over the points against tol times the largest |an|, plus the
 * difference's floor: Newton's tolerance 1e-12 times the quantity's scale over the step (for a
 * derivative that is 0: a stuck element's slip force's, Rayleigh's a0's of ω, whose step is
 * 1e-7); the relative error into *worst. */
static void agree(const char *what, size_t np, const double *fd, const double *an, size_t stride,
                  double tol, double floor, double *worst)
{
    double err = 0.0, big = 0.0;
    for (size_t i = 0; i < np; i++) {
        err = fmax(err, fabs(fd[i * stride] - an[i * stride]));
        big = fmax(big, fabs(an[i * stride]));
    }
    if (big > 1e3 * floor)
        *worst = fmax(*worst, err / big);
    if (getenv("HB_PRINT_ALL"))
        fprintf(stderr, "  %s: %.3g of %.3g (floor %.3g)\n", what, err, big, floor);
    for (size_t i = 0; getenv("HB_PRINT_ALL") && i < np; i++)
        fprintf(stderr, "    %.12g %.12g\n", fd[i * stride], an[i * stride]);
    ck_assert_msg(err <= tol * big + floor,
                  "%s: |fd - exact| up to %.3g, the largest |exact| %.3g (floor %.3g)", what, err,
                  big, floor);
}

/* The largest |v| over the points. */
static double largest(size_t np, const double *v, size_t stride)
{
    double big = 0.0;
    for (size_t i = 0; i < np; i++)
        big = fmax(big, fabs(v[i * stride]));
    return big;
}

/* Richardson's central difference of sensitivity s at the relative step h: the backbones at
 * ±h and ±2h; or the plain one at ±h (md->plain: a sampled AFT's backbone is piecewise smooth,
 * its kinks where a sample's stick or slip changes, one of which 2h may reach). */
static void difference(const struct model *md, const struct sens *s, const struct backbone *base,
                       const double *a, struct backbone *fd)
{
    const double steps[4] = {h, -h, 2 * h, -2 * h};
    struct backbone b[4];
    double step = s->nfd > 0 ? step_of(md, s, a) : h;
    for (int k = 0; k < (md->plain ? 2 : 4); k++) {
        double p[16];
        memcpy(p, md->p0, md->npar * sizeof *p);
        for (size_t j = 0; j < s->nfd; j++)
            p[s->fd[j]] += steps[k] / h * step;
        solve(md, p, s->nfd > 0 ? 1.0 : 1.0 + steps[k], &b[k]);
    }
    for (size_t i = 0; i < md->npts; i++) {
        double d = s->nfd > 0 ? step : h * a[i];
        if (s->zeta_k)
            d *= base->z[0] / md->p0[s->fd[0]]; /* per unit of ζ_k = s ζ_k(s = 1) */
        for (size_t q = 0; q <= md->ndof + 1; q++) {
            const double *v[4];
            double *out = q == 0 ? fd->w : q == 1 ? fd->z : fd->x + (q - 2);
            for (int k = 0; k < 4; k++)
                v[k] = q == 0 ? b[k].w : q == 1 ? b[k].z : b[k].x + (q - 2);
            size_t at = q < 2 ? i : i * MAXN;
            double d1 = (v[0][at] - v[1][at]) / (2 * d);
            out[at] = md->plain ? d1 : (4 * d1 - (v[2][at] - v[3][at]) / (4 * d)) / 3;
        }
    }
}

/* Every sensitivity of sp against its difference to tol; the worst relative error returned. */
static double check_differences(const char *name, const struct model *md, size_t ns,
                                const struct sens *sp, double tol)
{
    struct backbone an[MAXS], base, fd;
    double a[MAXP], worst = 0.0;
    fricreg_hb_free(sensitivities(md, ns, sp, an, a));
    solve(md, md->p0, 1.0, &base);
    for (size_t k = 0; k < ns; k++) {
        char what[96];
        size_t n = md->npts;
        double r = 1e-12 / step_of(md, &sp[k], a);
        difference(md, &sp[k], &base, a, &fd);
        snprintf(what, sizeof what, "%s, sensitivity %zu, omega", name, k);
        agree(what, n, fd.w, an[k].w, 1, tol, r * largest(n, base.w, 1), &worst);
        snprintf(what, sizeof what, "%s, sensitivity %zu, zeta", name, k);
        agree(what, n, fd.z, an[k].z, 1, tol, r * largest(n, base.z, 1), &worst);
        for (size_t j = 0; j < md->ndof; j++) {
            snprintf(what, sizeof what, "%s, sensitivity %zu, |X_1| of dof %zu", name, k, j);
            agree(what, n, fd.x + j, an[k].x + j, MAXN, tol, r * largest(n, base.x + j, MAXN),
                  &worst);
        }
    }
    if (getenv("HB_PRINT"))
        fprintf(stderr, "%s: worst |fd - exact| / max |exact| = %.3g\n", name, worst);
    return worst;
}

/* ---- (1) The closed form ----------------------------------------------------------------- */

/* The oscillator's backbone at H = 1 (test_hb_nma.c): slipping for a > δ = mun/kt, cos β =
 * 1 − 2δ/a, ω² = 1 + (kt/π)(β − sin 2β / 2), ζ = 2 mun (a − δ)/(π a² ω²); and its derivatives
 * in kt, mun and a (v[0..2]: ω's, v[3..5]: ζ's), by dβ/dδ = 2/(a sin β), dβ/da = −2δ/(a² sin β),
 * dk_re/dβ = 2 kt sin² β / π. */
static void closed_form(double a, double kt, double mun, double *omega, double *zeta, double *v)
{
    double d = mun / kt, b = acos(1.0 - 2.0 * d / a), sb = sin(b);
    double w2 = 1.0 + kt / pi * (b - 0.5 * sin(2.0 * b)), dk_db = 2.0 * kt * sb * sb / pi;
    double db_dd = 2.0 / (a * sb), db_da = -2.0 * d / (a * a * sb);
    double dd_kt = -mun / (kt * kt), dd_mun = 1.0 / kt;
    double dw2[3] = {(b - 0.5 * sin(2.0 * b)) / pi + dk_db * db_dd * dd_kt, dk_db * db_dd * dd_mun,
                     dk_db * db_da};
    double z = 2.0 * mun * (a - d) / (pi * a * a * w2);
    double dz[3] = {-2.0 * mun * dd_kt / (pi * a * a * w2),
                    (2.0 * (a - d) - 2.0 * mun * dd_mun) / (pi * a * a * w2),
                    2.0 * mun * (1.0 / (a * a) - 2.0 * (a - d) / (a * a * a)) / (pi * w2)};
    *omega = sqrt(w2);
    *zeta = z;
    for (int k = 0; k < 3; k++) {
        v[k] = dw2[k] / (2.0 * *omega);
        v[3 + k] = dz[k] - z / w2 * dw2[k];
    }
}

/* (1) 12 amplitudes from 2 to 200 (every one slipping: δ = 1.5): dω and dζ in kt, mun and a
 * against the closed form's, to 1e-8 of each; φ = 1 and a = |X_1| here, so d|X_1|/da = 1 and
 * the parameters' d|X_1| = 0. */
START_TEST(oscillator_closed_form)
{
    const double p0[2] = {2.0, 3.0};
    const struct model md = {oscillator, p0, 2, 1, 0, MATRIX, 2.0, 200.0, 12, 1};
    const struct sens sp[3] = {{ELEMENT, 0, 1, 0, 0, {0}, 0},
                               {ELEMENT, 0, 1, 1, 0, {0}, 0},
                               {AMPLITUDE, 0, 0, 0, 0, {0}, 0}};
    struct backbone an[3];
    double a[MAXP], worst = 0.0;
    fricreg_hb *hb = sensitivities(&md, 3, sp, an, a);
    for (size_t i = 0; i < md.npts; i++) {
        double omega, zeta, v[6], w, z, x;
        closed_form(a[i], p0[0], p0[1], &omega, &zeta, v);
        ck_assert_int_eq(fricreg_hb_nma_point(hb, i, &x, &w, &z, 0, 0, NULL), FRICREG_OK);
        ck_assert_double_le(fabs(w - omega), 1e-10 * omega);
        for (int k = 0; k < 3; k++) {
            worst = fmax(worst, fabs(an[k].w[i] - v[k]) / fabs(v[k]));
            worst = fmax(worst, fabs(an[k].z[i] - v[3 + k]) / fabs(v[3 + k]));
            ck_assert_msg(fabs(an[k].w[i] - v[k]) <= 1e-8 * fabs(v[k]),
                          "a = %g, sensitivity %d: domega %.15g, closed form %.15g", a[i], k,
                          an[k].w[i], v[k]);
            ck_assert_msg(fabs(an[k].z[i] - v[3 + k]) <= 1e-8 * fabs(v[3 + k]),
                          "a = %g, sensitivity %d: dzeta %.15g, closed form %.15g", a[i], k,
                          an[k].z[i], v[3 + k]);
            ck_assert_double_le(fabs(an[k].x[i * MAXN] - (k == 2 ? 1.0 : 0.0)), 1e-9);
        }
    }
    if (getenv("HB_PRINT"))
        fprintf(stderr, "oscillator: worst relative error against the closed form %.3g\n", worst);
    fricreg_hb_free(hb);
}
END_TEST

/* ---- (2) NLvib's chain ------------------------------------------------------------------- */

/* The chain's base: kt = 20, mun = 1 for both elements, C = 0.02 K (or Rayleigh's a0 = 0.01,
 * a1 = 0.02). Its backbone of mode 0 sticks up to a = 0.88, then element 0 slips, element 1
 * from a = 0.98 (measured), and folds in a at 1.03 (an internal resonance, test_hb_nma_energy:
 * where fricreg_hb_nma stops), so the grid is 8 points from 0.85 to 1 (the modal damping's
 * from 0.85 to 0.97: it folds earlier). */
static const double CHAIN_P[8] = {20, 1, 20, 1, 1, 0, 0, 0},
                    RAYLEIGH_P[8] = {20, 1, 20, 1, 1, 0.01, 0.02, 1};

/* The chain's parameters: each element's kt and mun, the shared mun and kt, a. */
static const struct sens CHAIN_SENS[7] = {{ELEMENT, 0, 1, 0, 1, {0}, 0},
                                          {ELEMENT, 0, 1, 1, 1, {1}, 0},
                                          {ELEMENT, 1, 1, 0, 1, {2}, 0},
                                          {ELEMENT, 1, 1, 1, 1, {3}, 0},
                                          {ELEMENT, 0, 2, 1, 2, {1, 3}, 0},
                                          {ELEMENT, 0, 2, 0, 2, {0, 2}, 0},
                                          {AMPLITUDE, 0, 0, 0, 0, {0}, 0}};

/* (2a) the matrix C: every element parameter, shared ones and a, to 1e-6. */
START_TEST(chain_matrix_damping)
{
    const struct model md = {chain, CHAIN_P, 8, HB_CHAIN_H, 0, MATRIX, 0.85, 1.0, 8, 3};
    check_differences("chain, matrix C", &md, 7, CHAIN_SENS, 1e-6);
}
END_TEST

/* (2b) Rayleigh's damping, matrix and modal: a0 and a1 (their differences' step 1e-5, not
 * relative: a0 = 0.01, a1 = 0.02), and kt, whose mode shape term enters the modal damping's ξ_k,
 * to 1e-6. */
START_TEST(chain_rayleigh)
{
    const struct sens sp[4] = {{DAMPING, 0, 0, 1, 1, {5}, 0, 1.0},
                               {DAMPING, 0, 0, 2, 1, {6}, 0, 1.0},
                               {ELEMENT, 0, 1, 0, 1, {0}, 0},
                               {ELEMENT, 0, 2, 1, 2, {1, 3}, 0}};
    const struct model matrix = {chain, RAYLEIGH_P, 8, HB_CHAIN_H, 0, MATRIX, 0.85, 1.0, 8, 3};
    const struct model modal = {chain, RAYLEIGH_P, 8, HB_CHAIN_H, 0, MODAL, 0.85, 0.97, 8, 3};
    check_differences("chain, Rayleigh, matrix", &matrix, 4, sp, 1e-6);
    check_differences("chain, Rayleigh, modal", &modal, 4, sp, 1e-6);
}
END_TEST

/* (2c) the modal damping: the element parameters (element 1 stays stuck below 0.97: its mun's
 * derivatives are 0), ζ_k (the difference in the scale of C: ξ_k is proportional to it; dω/dζ_k
 * = 0 and dζ/dζ_k = ω_k/ω exactly), to 1e-6. */
START_TEST(chain_modal_damping)
{
    const struct model md = {chain, CHAIN_P, 8, HB_CHAIN_H, 0, MODAL, 0.85, 0.97, 8, 3};
    struct sens sp[8];
    memcpy(sp, CHAIN_SENS, 7 * sizeof *sp);
    sp[7] = (struct sens){DAMPING, 0, 0, 0, 1, {4}, 1};
    check_differences("chain, modal damping", &md, 8, sp, 1e-6);
    struct backbone an[1];
    double a[MAXP];
    fricreg_hb *hb = sensitivities(&md, 1, sp + 7, an, a);
    double omega_k = 0.0;
    for (size_t i = 0; i < md.npts; i++) {
        double x, w, z;
        ck_assert_int_eq(fricreg_hb_nma_point(hb, i, &x, &w, &z, 0, 0, NULL), FRICREG_OK);
        omega_k = i == 0 ? w : omega_k; /* stuck at the first point */
        ck_assert_double_eq(an[0].w[i], 0.0);
        ck_assert_double_le(fabs(an[0].z[i] - omega_k / w), 1e-14);
    }
    fricreg_hb_free(hb);
}
END_TEST

/* The sparse path (KLU's D_1, the pattern's products, the densified stuck structure) against
 * the dense one: the chain's sensitivities in the matrix C, Rayleigh's (a1 in D_h) and the
 * modal damping, to 1e-8 of each's largest (the sparse linear mode is an iteration's, to 1e-10:
 * nma_sparse_mode.c). */
START_TEST(sparse_against_dense)
{
    struct sens sp[5] = {CHAIN_SENS[0],
                         CHAIN_SENS[4],
                         CHAIN_SENS[6],
                         {DAMPING, 0, 0, 2, 0, {0}, 0, 0},
                         {DAMPING, 0, 0, 0, 0, {0}, 0, 0}};
    for (int c = 0; c < 3; c++) {
        const double *p0 = c == 1 ? RAYLEIGH_P : CHAIN_P;
        int damping = c == 2 ? FRICREG_HB_NMA_DAMPING_MODAL : FRICREG_HB_NMA_DAMPING_MATRIX;
        size_t ns = c == 0 ? 3 : 4;
        if (c == 2)
            sp[3] = sp[4]; /* zeta_k */
        struct model md = {chain, p0, 8, HB_CHAIN_H, 0, damping, 0.85, c == 2 ? 0.97 : 1.0, 8, 3};
        struct backbone dense[MAXS], sparse[MAXS];
        double a[MAXP];
        fricreg_hb_free(sensitivities(&md, ns, sp, dense, a));
        md.make = sparse_chain;
        fricreg_hb_free(sensitivities(&md, ns, sp, sparse, a));
        for (size_t k = 0; k < ns; k++) {
            double worst = 0.0;
            agree("sparse, omega", md.npts, sparse[k].w, dense[k].w, 1, 1e-8, 1e-14, &worst);
            agree("sparse, zeta", md.npts, sparse[k].z, dense[k].z, 1, 1e-8, 1e-14, &worst);
            for (size_t j = 0; j < 3; j++)
                agree("sparse, |X_1|", md.npts, sparse[k].x + j, dense[k].x + j, MAXN, 1e-8, 1e-14,
                      &worst);
        }
    }
}
END_TEST

/* (5) Jenkins elements only: a dω/da + Σ_e mun_e dω/dmun_e = 0, the same for ζ, and
 * a d|X_1|/da + Σ_e mun_e d|X_1|/dmun_e = |X_1| (the slip forces scale the solution); the
 * shared mun is the sum of the per-element ones; to 1e-9 of the terms. */
START_TEST(scaling_identity)
{
    const struct model md = {chain, CHAIN_P, 8, HB_CHAIN_H, 0, MATRIX, 0.85, 1.0, 8, 3};
    const struct sens sp[4] = {CHAIN_SENS[1], CHAIN_SENS[3], CHAIN_SENS[4], CHAIN_SENS[6]};
    struct backbone an[4], base;
    double a[MAXP];
    fricreg_hb_free(sensitivities(&md, 4, sp, an, a));
    solve(&md, md.p0, 1.0, &base);
    for (size_t i = 0; i < md.npts; i++) {
        double sw = an[0].w[i] + an[1].w[i], sz = an[0].z[i] + an[1].z[i];
        ck_assert_double_le(fabs(a[i] * an[3].w[i] + sw), 1e-9 * fabs(a[i] * an[3].w[i]) + 1e-12);
        ck_assert_double_le(fabs(a[i] * an[3].z[i] + sz), 1e-9 * fabs(a[i] * an[3].z[i]) + 1e-12);
        ck_assert_double_le(fabs(an[2].w[i] - sw), 1e-12 * fabs(sw) + 1e-15);
        ck_assert_double_le(fabs(an[2].z[i] - sz), 1e-12 * fabs(sz) + 1e-15);
        for (size_t j = 0; j < 3; j++) {
            size_t at = i * MAXN + j;
            double x = base.x[at], t = a[i] * an[3].x[at] + an[0].x[at] + an[1].x[at];
            ck_assert_double_le(fabs(t - x), 1e-9 * x);
            ck_assert_double_le(fabs(an[2].x[at] - an[0].x[at] - an[1].x[at]), 1e-12 * x);
        }
    }
}
END_TEST

/* ---- (3) The 60-dof chain ---------------------------------------------------------------- */

static double cpu_seconds(void)
{
    return (double)clock() / CLOCKS_PER_SEC;
}

static int count_iterations(void *user, int64_t iterations, double parameter, double residual)
{
    (void)iterations;
    (void)parameter;
    (void)residual;
    ++*(long *)user;
    return 0;
}

/* (3) Mode 2 (mode 0 folds back right after the first slip, mode 2's backbone is monotone in a:
 * measured) from a = 0.8, every element slipping, to 4: the shared kt and mun of the ten
 * elements and a, to 1e-6. With HB_PRINT: the CPU time of a point's sensitivities in the three
 * against one Newton iteration of the backbone (its time over its iterations, the monitor's
 * count). */
START_TEST(long_chain_shared)
{
    const double p0[2] = {0.2, 0.02};
    const struct model md = {long_chain, p0, 2, 3, 2, MATRIX, 0.8, 4.0, 8, LONG_N};
    const struct sens sp[3] = {{ELEMENT, 0, LONG_M, 1, 1, {1}, 0},
                               {ELEMENT, 0, LONG_M, 0, 1, {0}, 0},
                               {AMPLITUDE, 0, 0, 0, 0, {0}, 0}};
    check_differences("60-dof chain", &md, 3, sp, 1e-6);
    if (!getenv("HB_PRINT"))
        return;
    fricreg_hb *hb = long_chain(p0);
    long iterations = 0;
    ck_assert_int_eq(fricreg_hb_set_monitor(hb, count_iterations, &iterations), FRICREG_OK);
    double t0 = cpu_seconds();
    for (int r = 0; r < 20; r++)
        ck_assert_int_eq(fricreg_hb_nma(hb, 2, FRICREG_HB_NMA_DAMPING_MATRIX, 0.8, 4.0, 8),
                         FRICREG_OK);
    double t1 = cpu_seconds();
    int kind[3] = {ELEMENT, ELEMENT, AMPLITUDE};
    size_t first[3] = {0, 0, 0}, count[3] = {LONG_M, LONG_M, 1}, index[3] = {1, 0, 0};
    double dw[3], dz[3], dx[3 * LONG_N];
    for (int r = 0; r < 20; r++)
        for (size_t i = 0; i < 8; i++)
            ck_assert_int_eq(fricreg_hb_nma_point_sensitivities(hb, i, 3, kind, first, count, index,
                                                                dw, dz, LONG_N, dx),
                             FRICREG_OK);
    double t2 = cpu_seconds();
    for (int r = 0; r < 20; r++)
        for (size_t i = 0; i < 8; i++)
            ck_assert_int_eq(fricreg_hb_nma_point_sensitivities(hb, i, 2, kind, first, count, index,
                                                                dw, dz, 0, NULL),
                             FRICREG_OK);
    double t3 = cpu_seconds();
    fprintf(stderr,
            "60-dof chain: one Newton iteration %.3g ms (%ld in 20 backbones); a point's "
            "sensitivities %.3g ms (kt, mun, a and the 60 amplitudes), %.3g ms (kt and mun)\n",
            (t1 - t0) / iterations * 1e3, iterations, (t2 - t1) / 160 * 1e3, (t3 - t2) / 160 * 1e3);
    fricreg_hb_free(hb);
}
END_TEST

/* The march ends each step at its grid amplitude: mode 2's backbone of the 60-dof chain on
 * its grid scaled by 1 + k 1e-5, k = −20 … 20 (the central differences' grids) stays on mode
 * 2, every point's ω within 1e-3 of the unscaled grid's. A march that stopped a rounding short
 * of a0 took a step of 1e-17 more, and the next predictor's secant over it sent the corrector
 * to another mode (ω = 0.92 from 0.18, at 1 − 2e-5). */
START_TEST(scaled_grids_stay_on_the_mode)
{
    const double p0[2] = {0.2, 0.02};
    double base[8];
    for (int k = 0; k <= 41; k++) {
        double g = k == 41 ? 1.0 : 1.0 + (k - 20) * 1e-5, a, w, z;
        fricreg_hb *hb = long_chain(p0);
        ck_assert_int_eq(fricreg_hb_set_newton(hb, 1e-12, 50), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_nma(hb, 2, MATRIX, 0.8 * g, 4.0 * g, 8), FRICREG_OK);
        for (size_t i = 0; i < 8; i++) {
            ck_assert_int_eq(fricreg_hb_nma_point(hb, i, &a, &w, &z, 0, 0, NULL), FRICREG_OK);
            if (k == 0)
                base[i] = w;
            ck_assert_msg(fabs(w - base[i]) <= 1e-3 * base[i], "grid %.5f, point %zu: %g, not %g",
                          g, i, w, base[i]);
        }
        fricreg_hb_free(hb);
    }
}
END_TEST

/* ---- (4) The 3-D contact, Iwan sliders, lift-off ----------------------------------------- */

/* (4) The inclined plane's 3-D contact (kt = 1.5, mu = 0.4, n0 = 0.5, kn = 2; the modal
 * damping): its backbone from a = 0.3 (slipping) to 3 (opening in every period), kt, mu, kn
 * and n0 and a, to 1e-6: the sampled AFT (Richardson's 2 F(N) − F(N/2)) is piecewise smooth in
 * q, the samples' stick–slip switches its kinks, and its identities are exact at the samples,
 * so the sensitivities are the sampled model's, which the differences see. */
START_TEST(contact_3d_parameters)
{
    const double p0[4] = {1.5, 0.4, 0.5, 2.0};
    const struct model md = {contact, p0, 4, 5, 0, MODAL, 0.3, 3.0, 8, 2};
    const struct sens sp[5] = {{ELEMENT, 0, 1, 0, 1, {0}, 0},
                               {ELEMENT, 0, 1, 1, 1, {1}, 0},
                               {ELEMENT, 0, 1, 2, 1, {3}, 0},
                               {ELEMENT, 0, 1, 3, 1, {2}, 0},
                               {AMPLITUDE, 0, 0, 0, 0, {0}, 0}};
    check_differences("contact_3d", &md, 5, sp, 1e-6);
}
END_TEST

/* Iwan elements, per slider (each its own exact AFT): the chain with two elements of three
 * sliders (k = 10, 6, 4, phi = 0.3, 0.4, 0.3 on both), sliders of both kinds and a shared one;
 * the Jenkins and the three-slider Iwan element with lift-off (test_hb_liftoff.c: kt = 1.7,
 * mu = 0.5, n0 = 0.6, kn = 3, the modal damping) from a = 0.08 and 0.05 (slipping) to 1; the
 * Iwan chain from 0.5 (its first slider slips) to 0.9 (before its fold at 0.92). */
START_TEST(iwan_and_liftoff)
{
    const double pi6[12] = {10, 6, 4, 10, 6, 4, 0.3, 0.4, 0.3, 0.3, 0.4, 0.3};
    const struct model iwan = {iwan_chain, pi6, 12, HB_CHAIN_H, 0, MATRIX, 0.5, 0.9, 8, 3};
    const struct sens si[4] = {{ELEMENT, 0, 1, 0, 1, {0}, 0},
                               {ELEMENT, 0, 1, 4, 1, {7}, 0},
                               {ELEMENT, 0, 2, 3, 2, {6, 9}, 0},
                               {ELEMENT, 1, 1, 2, 1, {5}, 0}};
    check_differences("iwan chain", &iwan, 4, si, 1e-6);
    const double pj[4] = {1.7, 0.5, 0.6, 3.0}, pw[8] = {0.9, 0.5, 0.3, 0.1, 0.15, 0.25, 0.6, 3.0};
    const struct model jn = {liftoff, pj, 4, 9, 0, MODAL, 0.08, 1.0, 8, 2};
    const struct model iw = {iwan_liftoff, pw, 8, 9, 0, MODAL, 0.05, 1.0, 8, 2};
    const struct sens sj[4] = {{ELEMENT, 0, 1, 0, 1, {0}, 0},
                               {ELEMENT, 0, 1, 1, 1, {1}, 0},
                               {ELEMENT, 0, 1, 2, 1, {3}, 0},
                               {ELEMENT, 0, 1, 3, 1, {2}, 0}};
    const struct sens sw[4] = {{ELEMENT, 0, 1, 1, 1, {1}, 0},
                               {ELEMENT, 0, 1, 5, 1, {5}, 0},
                               {ELEMENT, 0, 1, 6, 1, {7}, 0},
                               {ELEMENT, 0, 1, 7, 1, {6}, 0}};
    check_differences("jenkins_normal", &jn, 4, sj, 1e-6);
    check_differences("iwan_normal", &iw, 4, sw, 1e-6);
}
END_TEST

/* The marched types (their forces and Jacobian the march's, exact for its samples, with
 * Richardson's extrapolation for the 2-D sliders): jenkins_2d (a = 0.9 to 1), iwan_2d per
 * slider (0.65 to 0.9) and dahl (0.1 to 0.6; it folds at 0.9), 5 points each, to 1e-6, by one
 * central difference at h = 1e-5: the backbone of a sampled AFT has kinks, where a sample's stick
 * or slip changes, and one lies within 2e-5 of kt of the jenkins_2d grid's third point (measured:
 * the difference at 1e-4 is off by 5e-3 there, those at 1e-5 to 1e-8 agree). */
START_TEST(marched_types)
{
    const double pj[4] = {20, 1, 20, 1}, pw[8] = {12, 8, 0.4, 0.6, 12, 8, 0.4, 0.6};
    const struct model jm = {marched_chain, pj, 4, 3, 0, MATRIX, 0.9, 1.0, 5, 5, 1};
    const struct model im = {marched_iwan, pw, 8, 3, 0, MATRIX, 0.65, 0.9, 5, 5, 1};
    const struct model dm = {dahl_chain, pj, 4, 3, 0, MATRIX, 0.1, 0.6, 5, 3, 1};
    const struct sens sj[3] = {{ELEMENT, 0, 1, 1, 1, {1}, 0},
                               {ELEMENT, 0, 2, 0, 2, {0, 2}, 0},
                               {AMPLITUDE, 0, 0, 0, 0, {0}, 0}};
    const struct sens si[2] = {{ELEMENT, 0, 1, 1, 1, {1}, 0}, {ELEMENT, 0, 2, 2, 2, {2, 6}, 0}};
    check_differences("marched jenkins_2d", &jm, 3, sj, 1e-6);
    check_differences("marched iwan_2d", &im, 2, si, 1e-6);
    check_differences("dahl", &dm, 2, sj, 1e-6);
}
END_TEST

/* ---- (6) Statuses ------------------------------------------------------------------------ */

struct from_monitor {
    fricreg_hb *hb;
    int status;
};

static int call_from_monitor(void *user, int64_t iterations, double parameter, double residual)
{
    struct from_monitor *m = user;
    int kind = AMPLITUDE;
    size_t zero = 0;
    double dw, dz;
    (void)iterations;
    (void)parameter;
    (void)residual;
    m->status = fricreg_hb_nma_point_sensitivities(m->hb, 0, 1, &kind, &zero, &zero, &zero, &dw,
                                                   &dz, 0, NULL);
    return 0;
}

/* The most dofs a model of expect's has (its dx holds one parameter's amplitudes). */
#define EXPECT_MAX_DOFS 512

/* One call's status, every output at SENTINEL after a failure. */
static void expect(fricreg_hb *hb, int status, size_t i, int kind, size_t first, size_t count,
                   size_t index, size_t ndof)
{
    double dw = SENTINEL, dz = SENTINEL, dx[EXPECT_MAX_DOFS];
    for (int k = 0; k < EXPECT_MAX_DOFS; k++)
        dx[k] = SENTINEL;
    ck_assert_uint_le(ndof, EXPECT_MAX_DOFS); /* a wrong ndof is refused, a right one written */
    int got = fricreg_hb_nma_point_sensitivities(hb, i, 1, &kind, &first, &count, &index, &dw, &dz,
                                                 ndof, dx);
    ck_assert_msg(got == status, "kind %d first %zu count %zu index %zu: %d (%s), expected %d",
                  kind, first, count, index, got, hb ? fricreg_hb_errmsg(hb) : "", status);
    if (status == FRICREG_OK)
        return;
    ck_assert(dw == SENTINEL && dz == SENTINEL);
    for (int k = 0; k < EXPECT_MAX_DOFS; k++)
        ck_assert(dx[k] == SENTINEL);
}

/* (6) Every status; nothing written on failure; the backbone's points and the driver's
 * displacements unchanged by a call, and a backbone solved after one the same as without it,
 * bit for bit. */
START_TEST(statuses)
{
    fricreg_hb *hb = chain(CHAIN_P);
    ck_assert_int_eq(fricreg_hb_nma(hb, 0, FRICREG_HB_NMA_DAMPING_MATRIX, 0.85, 1.0, 4),
                     FRICREG_OK);
    int kind = ELEMENT;
    size_t zero = 0, one = 1;
    double dw = SENTINEL, dz = SENTINEL;
    ck_assert_int_eq(fricreg_hb_nma_point_sensitivities(NULL, 0, 1, &kind, &zero, &one, &zero, &dw,
                                                        &dz, 0, NULL),
                     FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_nma_point_sensitivities(hb, 0, 1, &kind, &zero, &one, &zero, NULL,
                                                        &dz, 0, NULL),
                     FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_nma_point_sensitivities(hb, 0, 1, &kind, &zero, &one, &zero, &dw,
                                                        NULL, 0, NULL),
                     FRICREG_ENULL);
    const size_t *null_size = NULL;
    ck_assert_int_eq(fricreg_hb_nma_point_sensitivities(hb, 0, 1, NULL, &zero, &one, &zero, &dw,
                                                        &dz, 0, NULL),
                     FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_nma_point_sensitivities(hb, 0, 1, &kind, null_size, &one, &zero,
                                                        &dw, &dz, 0, NULL),
                     FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_nma_point_sensitivities(hb, 0, 1, &kind, &zero, null_size, &zero,
                                                        &dw, &dz, 0, NULL),
                     FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_nma_point_sensitivities(hb, 0, 1, &kind, &zero, &one, null_size,
                                                        &dw, &dz, 0, NULL),
                     FRICREG_ENULL);
    ck_assert(dw == SENTINEL && dz == SENTINEL);
    ck_assert_int_eq(fricreg_hb_nma_point_sensitivities(hb, 0, 0, NULL, NULL, NULL, NULL, &dw, &dz,
                                                        0, NULL),
                     FRICREG_OK);                                /* np = 0: the arguments checked */
    expect(hb, FRICREG_EINVAL, 4, ELEMENT, 0, 1, 0, 3);          /* i beyond the points */
    expect(hb, FRICREG_ESIZE, 0, ELEMENT, 0, 1, 0, 2);           /* ndof */
    expect(hb, FRICREG_EINVAL, 0, 3, 0, 1, 0, 3);                /* kind */
    expect(hb, FRICREG_EINVAL, 0, -1, 0, 1, 0, 3);               /* kind */
    expect(hb, FRICREG_EINVAL, 0, ELEMENT, 0, 0, 0, 3);          /* an empty range */
    expect(hb, FRICREG_EINVAL, 0, ELEMENT, 1, 2, 0, 3);          /* beyond the elements */
    expect(hb, FRICREG_EINVAL, 0, ELEMENT, 2, 1, 0, 3);          /* beyond the elements */
    expect(hb, FRICREG_EINVAL, 0, ELEMENT, (size_t)-1, 2, 0, 3); /* first + count wraps */
    expect(hb, FRICREG_EINVAL, 0, ELEMENT, 0, 1, 2, 3);          /* jenkins has 2 */
    expect(hb, FRICREG_EINVAL, 0, DAMPING, 0, 0, 0, 3);          /* zeta_k: the matrix C */
    expect(hb, FRICREG_EINVAL, 0, DAMPING, 0, 0, 1, 3);          /* a0: no Rayleigh */
    expect(hb, FRICREG_EINVAL, 0, DAMPING, 0, 0, 2, 3);          /* a1: no Rayleigh */
    expect(hb, FRICREG_EINVAL, 0, DAMPING, 0, 0, 3, 3);          /* no such index */
    expect(hb, FRICREG_OK, 3, AMPLITUDE, 99, 99, 99, 3);         /* the others ignored */
    /* the model's results unchanged by a call, and the next backbone's */
    double x0[3 * 15], x1[3 * 15], a, w0, w1, z0, z1;
    ck_assert_int_eq(fricreg_hb_nma_point(hb, 2, &a, &w0, &z0, 3, 15, x0), FRICREG_OK);
    expect(hb, FRICREG_OK, 2, ELEMENT, 0, 2, 0, 3);
    ck_assert_int_eq(fricreg_hb_nma_point(hb, 2, &a, &w1, &z1, 3, 15, x1), FRICREG_OK);
    ck_assert(w0 == w1 && z0 == z1);
    ck_assert_mem_eq(x0, x1, sizeof x0);
    fricreg_hb *twin = chain(CHAIN_P);
    ck_assert_int_eq(fricreg_hb_nma(hb, 0, FRICREG_HB_NMA_DAMPING_MATRIX, 0.9, 1.0, 3), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_nma(twin, 0, FRICREG_HB_NMA_DAMPING_MATRIX, 0.9, 1.0, 3),
                     FRICREG_OK);
    for (size_t i = 0; i < 3; i++) {
        ck_assert_int_eq(fricreg_hb_nma_point(hb, i, &a, &w0, &z0, 3, 15, x0), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_nma_point(twin, i, &a, &w1, &z1, 3, 15, x1), FRICREG_OK);
        ck_assert(w0 == w1 && z0 == z1);
        ck_assert_mem_eq(x0, x1, sizeof x0);
    }
    fricreg_hb_free(twin);
    /* from the monitor */
    struct from_monitor m = {hb, FRICREG_OK};
    ck_assert_int_eq(fricreg_hb_set_monitor(hb, call_from_monitor, &m), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_nma(hb, 0, FRICREG_HB_NMA_DAMPING_MATRIX, 0.9, 1.0, 2), FRICREG_OK);
    ck_assert_int_eq(m.status, FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_set_monitor(hb, NULL, NULL), FRICREG_OK);
    /* a slip force of 0 (the identity divides by it) */
    const double p0[8] = {20, 0, 20, 1, 1, 0, 0, 0};
    fricreg_hb *zero_mun = chain(p0);
    ck_assert_int_eq(fricreg_hb_nma(zero_mun, 0, FRICREG_HB_NMA_DAMPING_MATRIX, 0.9, 1.0, 2),
                     FRICREG_OK);
    expect(zero_mun, FRICREG_EINVAL, 0, ELEMENT, 0, 2, 1, 3);
    expect(zero_mun, FRICREG_OK, 0, ELEMENT, 1, 1, 1, 3);
    fricreg_hb_free(zero_mun);
    /* the model changed */
    const double K[9] = {2, -1, 0, -1, 2, -1, 0, -1, 2.5};
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 3, K), FRICREG_OK);
    expect(hb, FRICREG_EINVAL, 0, AMPLITUDE, 0, 0, 0, 3);
    fricreg_hb_free(hb);
}
END_TEST

/* (6) What is not supported: a marched element's bound of 0, a contact's gap, kn = 0 for kn; a stiffness
 * that moves the mode shape on a model of more than 256 dofs (its other parameters are taken);
 * a repeated stuck mode (the mode shape has no derivative: FRICREG_ESINGULAR). */
START_TEST(unsupported)
{
    const double pm[4] = {20, 0, 20, 1};
    fricreg_hb *marched = marched_chain(pm);
    ck_assert_int_eq(fricreg_hb_nma(marched, 0, FRICREG_HB_NMA_DAMPING_MATRIX, 0.9, 1.0, 2),
                     FRICREG_OK);
    expect(marched, FRICREG_EINVAL, 0, ELEMENT, 0, 1, 1, 5); /* its bound is 0 */
    expect(marched, FRICREG_EINVAL, 0, ELEMENT, 0, 1, 2, 5); /* jenkins_2d has 2 */
    expect(marched, FRICREG_OK, 1, ELEMENT, 1, 1, 1, 5);
    fricreg_hb_free(marched);
    const double pc[4] = {1.5, 0.4, 0.5, 2.0}, pk[4] = {1.5, 0.4, 0.5, 0.0};
    fricreg_hb *hb = contact(pc), *open = contact(pk);
    ck_assert_int_eq(fricreg_hb_nma(hb, 0, FRICREG_HB_NMA_DAMPING_MODAL, 0.3, 1.0, 2), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_nma(open, 0, FRICREG_HB_NMA_DAMPING_MODAL, 0.3, 1.0, 2),
                     FRICREG_OK);
    expect(hb, FRICREG_EINVAL, 0, ELEMENT, 0, 1, 4, 2);   /* gap */
    expect(hb, FRICREG_EINVAL, 0, ELEMENT, 0, 1, 5, 2);   /* beyond the layout */
    expect(hb, FRICREG_OK, 0, DAMPING, 0, 0, 0, 2);       /* zeta_k */
    expect(open, FRICREG_EINVAL, 0, ELEMENT, 0, 1, 2, 2); /* kn = 0 */
    expect(open, FRICREG_OK, 0, ELEMENT, 0, 1, 3, 2);     /* n0 by (F − J (U, G))/n0 */
    fricreg_hb_free(hb);
    fricreg_hb_free(open);
    /* 300 masses on springs, one element: kt refused, mun taken */
    enum { NB = 300 };
    double *M = calloc(NB * NB, sizeof *M), *K = calloc(NB * NB, sizeof *K), J[NB] = {0};
    ck_assert(M != NULL && K != NULL);
    for (size_t i = 0; i < NB; i++) {
        M[i * NB + i] = 1.0;
        K[i * NB + i] = i + 1 < NB ? 2.0 : 1.0;
        if (i > 0)
            K[i * NB + i - 1] = K[(i - 1) * NB + i] = -1.0;
    }
    J[NB - 1] = 1.0;
    const double kt = 0.5, mun = 1e-3;
    fricreg_hb *big = NULL;
    ck_assert_int_eq(fricreg_hb_create(NB, 1, 1, &big), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(big, NB, M), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(big, NB, K), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_elements(big, 1, NB, J, &kt, &mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_nma(big, 0, FRICREG_HB_NMA_DAMPING_MATRIX, 1e-3, 2e-3, 2),
                     FRICREG_OK);
    expect(big, FRICREG_EINVAL, 0, ELEMENT, 0, 1, 0, NB);
    double dw, dz;
    int kind = ELEMENT;
    size_t zero = 0, one = 1;
    ck_assert_int_eq(fricreg_hb_nma_point_sensitivities(big, 1, 1, &kind, &zero, &one, &one, &dw,
                                                        &dz, 0, NULL),
                     FRICREG_OK);
    fricreg_hb_free(big);
    free(M);
    free(K);
    /* two equal uncoupled oscillators, each with its element: K_0's lowest ω² is double */
    const double M2[4] = {1, 0, 0, 1}, K2[4] = {1, 0, 0, 1}, J2[4] = {1, 0, 0, 1};
    const double C2[4] = {0.1, 0, 0, 0.2}; /* unequal: the nonlinear mode is isolated */
    const double kt2[2] = {2, 2}, mun2[2] = {3, 3};
    fricreg_hb *twin = NULL;
    ck_assert_int_eq(fricreg_hb_create(2, 2, 1, &twin), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(twin, 2, M2), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(twin, 2, K2), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_elements(twin, 2, 2, J2, kt2, mun2), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_damping(twin, 2, C2), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_nma(twin, 0, FRICREG_HB_NMA_DAMPING_MATRIX, 2.0, 4.0, 2),
                     FRICREG_OK);
    expect(twin, FRICREG_ESINGULAR, 0, ELEMENT, 0, 1, 0, 2);
    expect(twin, FRICREG_OK, 0, ELEMENT, 0, 1, 1, 2);
    fricreg_hb_free(twin);
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("hb_nma_sensitivity");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, oscillator_closed_form);
    tcase_add_test(tc, chain_matrix_damping);
    tcase_add_test(tc, chain_rayleigh);
    tcase_add_test(tc, chain_modal_damping);
    tcase_add_test(tc, scaling_identity);
    tcase_add_test(tc, sparse_against_dense);
    tcase_add_test(tc, long_chain_shared);
    tcase_add_test(tc, scaled_grids_stay_on_the_mode);
    tcase_add_test(tc, iwan_and_liftoff);
    tcase_add_test(tc, statuses);
    tcase_add_test(tc, unsupported);
    suite_add_tcase(s, tc);
    /* the sampled and marched AFTs' backbones, differenced (6.7 s native: thousands of marched
     * periods) */
    TCase *marched = tcase_create("marched");
    tcase_set_timeout(marched, 120);
    tcase_add_test(marched, contact_3d_parameters);
    tcase_add_test(marched, marched_types);
    suite_add_tcase(s, marched);
    return s;
}

int main(void)
{
    SRunner *sr = srunner_create(suite());
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
