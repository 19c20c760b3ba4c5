/* SPDX-License-Identifier: GPL-3.0-or-later */
/* element_sliders.c — the element types made of Jenkins sliders (fricreg_element.h): jenkins,
 * jenkins_2d, jenkins_3d, jenkins_normal, contact_3d and the Iwan families (iwan, iwan_2d,
 * iwan_3d, iwan_normal), all ns sliders in parallel on the tangential components, each slider
 * slider.h's return mapping, with or without the normal law of lift-off. The sums run over the
 * sliders in order, as fricreg_iwan and the structure's elements sum them, so that their
 * answers agree bit for bit. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "element_kind.h"
#include "slider.h"

static size_t params_plain(size_t ns)
{
    return 2 * ns;
}

static size_t params_normal(size_t ns)
{
    return 2 * ns + 3;
}

static size_t state_1(size_t ns)
{
    return ns;
}

static size_t state_2(size_t ns)
{
    return 2 * ns;
}

static size_t state_3(size_t ns)
{
    return 3 * ns;
}

/* The name of parameter j of the type, into buf[32]: kt, mun (mu), or k[s], phi[s] (mu[s]) of
 * a family, then kn, n0, gap. */
static const char *param_name(const fricreg_element_type *type, size_t j, char buf[32])
{
    static const char *const normal_law[3] = {"kn", "n0", "gap"};
    const struct fr_element_kind *kind = type->kind;
    size_t ns = type->ns;
    if (j >= 2 * ns)
        return normal_law[j - 2 * ns];
    const char *bound = kind->normal ? "mu" : (kind->family ? "phi" : "mun");
    const char *base = j < ns ? (kind->family ? "k" : "kt") : bound;
    if (kind->family)
        snprintf(buf, 32, "%s[%zu]", base, j % ns);
    else
        snprintf(buf, 32, "%s", base);
    return buf;
}

/* The parameters: finite, in range, and sums that stay finite. */
static int check_params(const fricreg_element_type *type, const double *p, char *msg, size_t len)
{
    const struct fr_element_kind *kind = type->kind;
    size_t ns = type->ns, np = kind->nparams(ns);
    char buf[32];
    for (size_t j = 0; j < np; j++)
        if (!isfinite(p[j]))
            return fr_element_say(FRICREG_ENONFINITE, msg, len, "%s: %s = %g (params[%zu])",
                                  kind->name, param_name(type, j, buf), p[j], j);
    double sum_k = 0.0, sum_b = 0.0;
    for (size_t s = 0; s < ns; s++) {
        if (!(p[s] > 0.0))
            return fr_element_say(FRICREG_EINVAL, msg, len, "%s: %s = %g must be > 0 (params[%zu])",
                                  kind->name, param_name(type, s, buf), p[s], s);
        if (!(p[ns + s] >= 0.0))
            return fr_element_say(FRICREG_EINVAL, msg, len,
                                  "%s: %s = %g must be >= 0 (params[%zu])", kind->name,
                                  param_name(type, ns + s, buf), p[ns + s], ns + s);
        sum_k += p[s];
        sum_b += p[ns + s];
    }
    if (!isfinite(sum_k) || !isfinite(sum_b))
        return fr_element_say(FRICREG_ENONFINITE, msg, len,
                              "%s: the sliders' stiffnesses or bounds sum beyond the largest "
                              "double",
                              kind->name);
    if (!kind->normal)
        return FRICREG_OK;
    double kn = p[2 * ns], n0 = p[2 * ns + 1], gap = p[2 * ns + 2];
    if (!(kn >= 0.0))
        return fr_element_say(FRICREG_EINVAL, msg, len, "%s: kn = %g must be >= 0 (params[%zu])",
                              kind->name, kn, 2 * ns);
    if (n0 != 0.0 && gap != 0.0)
        return fr_element_say(FRICREG_EINVAL, msg, len,
                              "%s: n0 = %g (params[%zu]) and gap = %g (params[%zu]) must not both "
                              "be nonzero: a preload or a gap",
                              kind->name, n0, 2 * ns + 1, gap, 2 * ns + 2);
    if (!isfinite(sum_b * kn))
        return fr_element_say(FRICREG_ENONFINITE, msg, len,
                              "%s: the bounds' slope sum(mu) kn = %g overflows", kind->name,
                              sum_b * kn);
    return FRICREG_OK;
}

/* The displacement and its intermediates: u finite, each u_t - w_s, the normal force and the
 * scaled bounds finite. */
static int check_u(const fricreg_element_type *type, const double *p, const double *w,
                   const double *u, char *msg, size_t len)
{
    const struct fr_element_kind *kind = type->kind;
    int dim = kind->dim, td = dim - kind->normal;
    size_t ns = type->ns;
    for (int a = 0; a < dim; a++)
        if (!isfinite(u[a]))
            return fr_element_say(FRICREG_ENONFINITE, msg, len, "%s: u[%d] = %g", kind->name, a,
                                  u[a]);
    for (size_t s = 0; s < ns; s++) {
        double d[3];
        for (int a = 0; a < td; a++)
            d[a] = u[a] - w[(size_t)td * s + (size_t)a];
        if (!isfinite(fr_slider_norm(d, td)))
            return fr_element_say(FRICREG_ENONFINITE, msg, len,
                                  "%s: u - w of slider %zu overflows (u[0] = %g, w = %g)",
                                  kind->name, s, u[0], w[(size_t)td * s]);
    }
    if (!kind->normal)
        return FRICREG_OK;
    double kn = p[2 * ns], n0 = p[2 * ns + 1], gap = p[2 * ns + 2], gg = u[td] - gap;
    double nc = n0 + kn * gg, sum_b = 0.0;
    for (size_t s = 0; s < ns; s++)
        sum_b += p[ns + s];
    if (!isfinite(gg) || !isfinite(nc) || !isfinite(sum_b * fmax(0.0, nc)) ||
        !isfinite(sum_b * fabs(gg)))
        return fr_element_say(FRICREG_ENONFINITE, msg, len,
                              "%s: the normal force n0 + kn (g - gap) = %g (g = %g) or the "
                              "bounds mu N overflow",
                              kind->name, nc, u[td]);
    return FRICREG_OK;
}

static int check(const fricreg_element_type *type, const double *params, const double *state,
                 const double *u, char *msg, size_t len)
{
    int status = check_params(type, params, msg, len);
    if (status != FRICREG_OK || state == NULL)
        return status;
    size_t nstate = type->kind->nstate(type->ns);
    for (size_t i = 0; i < nstate; i++)
        if (!isfinite(state[i]))
            return fr_element_say(FRICREG_ENONFINITE, msg, len, "%s: state[%zu] = %g",
                                  type->kind->name, i, state[i]);
    return u == NULL ? FRICREG_OK : check_u(type, params, state, u, msg, len);
}

/* The normal law's columns of dfdp (kn, n0, gap) from sum_n = sum over slipping sliders of
 * mu_s n_s, while closed. */
static void normal_columns(const double *p, size_t ns, int td, double gg, const double *sum_n,
                           double *dfdp)
{
    size_t np = 2 * ns + 3, j = 2 * ns;
    double kn = p[j];
    for (int a = 0; a <= td; a++) {
        double dn0 = a < td ? sum_n[a] : 1.0;
        dfdp[np * (size_t)a + j] = gg * dn0;
        dfdp[np * (size_t)a + j + 1] = dn0;
        dfdp[np * (size_t)a + j + 2] = -kn * dn0;
    }
}

#if defined(__GNUC__)
#define FR_ALWAYS_INLINE static inline __attribute__((always_inline))
#define FR_NOINLINE __attribute__((noinline))
#else
#define FR_ALWAYS_INLINE static inline
#define FR_NOINLINE
#endif

/* The fast check: a word whose bit 63 is clear where check surely accepts these parameters of
 * ns sliders, with the normal law or not, and these inputs (set: check decides, and says why).
 * It is check's tests without their messages, each slider's independent of the others', with
 * bounds that imply check's: k_s and b_s below 2^1012 in place of their sums finite (ns <= 2^10
 * terms), |u_a - w_a| < 2^1022 for each component in place of |u_t - w_s| finite (the norm is
 * then below sqrt(3) 2^1022, and u_a and w_a are finite), and the normal law's products
 * bounded through ns max b_s, which bounds sum b_s (rounding aside: the bounds keep a factor
 * 2^3 in hand). The range tests compare a double's bits as an integer, so that loops or-ing
 * them vectorize (floating comparisons that honour NaN do not): a nonnegative double orders as
 * its bits, below +inf's and NaN's, and a negative one, -0 included, has bit 63 set. */
static inline uint64_t bits_of(double x)
{
    uint64_t bits;
    memcpy(&bits, &x, sizeof bits);
    return bits;
}

#define FR_SIGN_BIT (UINT64_C(1) << 63)
#define FR_BITS_2_1012 (UINT64_C(2035) << 52) /* bits_of(0x1p1012) */
#define FR_BITS_2_1022 (UINT64_C(2045) << 52) /* bits_of(0x1p1022) */

/* Bit 63 set unless 0 <= x < c, c a positive double's bits (x = -0 and NaN set it). */
static inline uint64_t doubt_nonneg_below(double x, uint64_t c)
{
    uint64_t b = bits_of(x);
    return b | (b + (FR_SIGN_BIT - c));
}

/* Bit 63 set unless 0 < x < c. */
static inline uint64_t doubt_positive_below(double x, uint64_t c)
{
    uint64_t b = bits_of(x);
    return b | (b - 1) | (b + (FR_SIGN_BIT - c));
}

/* Bit 63 set unless |x| < c. */
static inline uint64_t doubt_abs_below(double x, uint64_t c)
{
    return (bits_of(x) & ~FR_SIGN_BIT) + (FR_SIGN_BIT - c);
}

/* The parameters' part, once for parameters that points share; with the normal law, *bound
 * is ns max b_s, which the displacements' part needs (left alone without it). */
FR_ALWAYS_INLINE uint64_t fast_params_doubt(size_t ns, int normal, const double *p, double *bound)
{
    uint64_t doubt = 0;
    for (size_t s = 0; s < ns; s++)
        doubt |= doubt_positive_below(p[s], FR_BITS_2_1012) |
                 doubt_nonneg_below(p[ns + s], FR_BITS_2_1012);
    if (!normal)
        return doubt;
    double max_b = 0.0;
    for (size_t s = 0; s < ns; s++)
        max_b = p[ns + s] > max_b ? p[ns + s] : max_b;
    *bound = (double)ns * max_b; /* >= sum b_s to rounding */
    double kn = p[2 * ns], n0 = p[2 * ns + 1], gap = p[2 * ns + 2];
    int ok = (kn >= 0.0) & (*bound * kn < 0x1p1020) & ((n0 == 0.0) | (gap == 0.0));
    return doubt | (uint64_t)!ok << 63;
}

/* The displacements' part at the parameters' bound. bound |g - gap| and bound |n0 + kn (g -
 * gap)| below 2^1020 also say that g, gap, n0 and the normal force are finite (an infinite or
 * NaN factor makes the product infinite or NaN, 0 times it too). */
FR_ALWAYS_INLINE uint64_t fast_u_doubt(size_t ns, int td, int normal, const double *p, double bound,
                                       const double *w, const double *u)
{
    uint64_t doubt = 0;
    for (size_t s = 0; s < ns; s++)
        for (int a = 0; a < td; a++)
            doubt |= doubt_abs_below(u[a] - w[(size_t)td * s + (size_t)a], FR_BITS_2_1022);
    if (!normal)
        return doubt;
    double kn = p[2 * ns], n0 = p[2 * ns + 1], gg = u[td] - p[2 * ns + 2], nc = n0 + kn * gg;
    int ok = (bound * fabs(gg) < 0x1p1020) & (bound * fabs(nc) < 0x1p1020);
    return doubt | (uint64_t)!ok << 63;
}

/* eval's work for ns sliders on td tangential components, with the normal law or not: the
 * callers pass constants, which specialize it per kind (the sums run in the same order). */
FR_ALWAYS_INLINE void eval_sliders(size_t ns, int td, int normal, const double *p,
                                   const double *state_in, const double *u, double *f, double *dfdu,
                                   double *dfdp, double *state_out, double *slider_forces)
{
    int dim = td + normal;
    size_t np = 2 * ns + (normal ? 3 : 0);
    double N = 1.0, kn = 0.0, gg = 0.0;
    int open = 0;
    if (normal) {
        kn = p[2 * ns];
        gg = u[td] - p[2 * ns + 2];
        double nc = p[2 * ns + 1] + kn * gg;
        open = nc < 0.0;
        N = 0.0 > nc ? 0.0 : nc; /* fmax(0, nc) of a finite nc, inline */
    }
    double ft[3] = {0.0, 0.0, 0.0}, t[9] = {0.0}, tg[3] = {0.0, 0.0, 0.0},
           sum_n[3] = {0.0, 0.0, 0.0};
    if (dfdp != NULL)
        memset(dfdp, 0, (size_t)dim * np * sizeof *dfdp);
    for (size_t s = 0; s < ns; s++) {
        /* slider s's old and new positions: the same place where state_out is state_in, each
         * read before it is written */
        const double *wc = &state_in[(size_t)td * s];
        double *wn = &state_out[(size_t)td * s];
        double fs[3], ts[9], tgs[3];
        if (open) {
            fr_slider_separated(td, u, fs, wn, ts, tgs);
        } else {
            double b = normal ? p[ns + s] * N : p[ns + s];
            double dbdg = normal ? p[ns + s] * kn : 0.0;
            double d[3] = {0.0, 0.0, 0.0};
            for (int a = 0; a < td; a++)
                d[a] = u[a] - wc[a];
            int slip = fr_slider_return(p[s], b, dbdg, td, u, wc, fs, wn, ts, tgs);
            if (dfdp != NULL) {
                double r = fr_slider_norm_inline(d, td);
                for (int a = 0; a < td; a++) {
                    if (slip) {
                        dfdp[np * (size_t)a + ns + s] = normal ? N * (d[a] / r) : d[a] / r;
                        sum_n[a] += p[ns + s] * (d[a] / r);
                    } else {
                        dfdp[np * (size_t)a + s] = d[a];
                    }
                }
            }
        }
        for (int a = 0; a < td; a++) {
            ft[a] += fs[a];
            tg[a] += tgs[a];
        }
        if (slider_forces != NULL)
            memcpy(&slider_forces[(size_t)td * s], fs, (size_t)td * sizeof *fs);
        for (int a = 0; a < td * td; a++)
            t[a] += ts[a];
    }
    if (dfdp != NULL && normal && !open)
        normal_columns(p, ns, td, gg, sum_n, dfdp);
    for (int a = 0; a < td; a++)
        f[a] = ft[a];
    if (normal)
        f[td] = N;
    if (dfdu != NULL) {
        memset(dfdu, 0, (size_t)(dim * dim) * sizeof *dfdu);
        for (int a = 0; a < td; a++) {
            for (int c = 0; c < td; c++)
                dfdu[dim * a + c] = t[td * a + c];
            if (normal)
                dfdu[dim * a + td] = tg[a];
        }
        if (normal)
            dfdu[dim * td + td] = open ? 0.0 : kn;
    }
}

/* 1 where the fast check vouches for every point: one pass without branches (the shared
 * parameters' part once), which the compiler can vectorize. */
FR_ALWAYS_INLINE int all_fast_ok(size_t ns, int td, int normal, size_t npoints, const double *p,
                                 size_t p_stride, const double *state_in, const double *u)
{
    size_t dim = (size_t)(td + normal), nstate = (size_t)td * ns;
    double bound = 0.0;
    uint64_t doubt = p_stride == 0 ? fast_params_doubt(ns, normal, p, &bound) : 0;
    for (size_t i = 0; i < npoints; i++) {
        const double *pi = p + p_stride * i;
        if (p_stride != 0)
            doubt |= fast_params_doubt(ns, normal, pi, &bound);
        doubt |= fast_u_doubt(ns, td, normal, pi, bound, state_in + nstate * i, u + dim * i);
    }
    return !(doubt >> 63);
}

/* fricreg_element_eval_batch's work once the arrays and the stride are vetted
 * (element_batch.c): every point checked, the fast check of them all first and check point by
 * point where it doubts, then every point evaluated. On failure *bad is the first bad point. */
FR_ALWAYS_INLINE int batch_sliders(const fricreg_element_type *type, size_t ns, int td, int normal,
                                   size_t npoints, const double *p, size_t p_stride,
                                   const double *state_in, const double *u, double *f, double *dfdu,
                                   double *dfdp, double *state_out, size_t *bad)
{
    size_t dim = (size_t)(td + normal), nstate = (size_t)td * ns;
    size_t np = 2 * ns + (normal ? 3 : 0);
    if (!all_fast_ok(ns, td, normal, npoints, p, p_stride, state_in, u))
        for (size_t i = 0; i < npoints; i++) { /* the first point check refuses, if any */
            const double *pi = p + p_stride * i, *wi = state_in + nstate * i, *ui = u + dim * i;
            int status = check(type, pi, wi, ui, NULL, 0);
            if (status != FRICREG_OK) {
                *bad = i;
                return status;
            }
        }
    if (dfdp == NULL) /* the usual call: its own loop, the derivatives in p compiled out */
        for (size_t i = 0; i < npoints; i++)
            eval_sliders(ns, td, normal, p + p_stride * i, state_in + nstate * i, u + dim * i,
                         f + dim * i, dfdu != NULL ? dfdu + dim * dim * i : NULL, NULL,
                         state_out + nstate * i, NULL);
    else
        for (size_t i = 0; i < npoints; i++)
            eval_sliders(ns, td, normal, p + p_stride * i, state_in + nstate * i, u + dim * i,
                         f + dim * i, dfdu != NULL ? dfdu + dim * dim * i : NULL,
                         dfdp + dim * np * i, state_out + nstate * i, NULL);
    return FRICREG_OK;
}

/* fricreg_element_eval's work once the pointers are vetted (element.c): batch_sliders at one
 * point, without the loops. */
FR_ALWAYS_INLINE int point_sliders(const fricreg_element_type *type, size_t ns, int td, int normal,
                                   const double *p, const double *state_in, const double *u,
                                   double *f, double *dfdu, double *dfdp, double *state_out)
{
    double bound = 0.0;
    uint64_t doubt = fast_params_doubt(ns, normal, p, &bound);
    if ((doubt | fast_u_doubt(ns, td, normal, p, bound, state_in, u)) >> 63)
        return fr_element_check_then_eval(type, p, state_in, u, f, dfdu, dfdp, state_out);
    eval_sliders(ns, td, normal, p, state_in, u, f, dfdu, dfdp, state_out, NULL);
    return FRICREG_OK;
}

/* eval, batch and point of one shape: td tangential components, the normal law or not (the
 * kinds' table below names them by dim and normal); batch and point unrolled for one slider,
 * the point's two forms in functions of their own, so that one slider's call pays for no
 * registers the loop over sliders needs. */
#define FR_SLIDER_SHAPE(dim, normal)                                                               \
    static void eval_##dim##_##normal(const fricreg_element_type *type, const double *p,           \
                                      const double *state_in, const double *u, double *f,          \
                                      double *dfdu, double *dfdp, double *state_out,               \
                                      double *slider_forces)                                       \
    {                                                                                              \
        eval_sliders(type->ns, (dim) - (normal), normal, p, state_in, u, f, dfdu, dfdp, state_out, \
                     slider_forces);                                                               \
    }                                                                                              \
    static int batch_##dim##_##normal(const fricreg_element_type *type, size_t npoints,            \
                                      const double *p, size_t p_stride, const double *state_in,    \
                                      const double *u, double *f, double *dfdu, double *dfdp,      \
                                      double *state_out, size_t *bad)                              \
    {                                                                                              \
        if (type->ns == 1)                                                                         \
            return batch_sliders(type, 1, (dim) - (normal), normal, npoints, p, p_stride,          \
                                 state_in, u, f, dfdu, dfdp, state_out, bad);                      \
        return batch_sliders(type, type->ns, (dim) - (normal), normal, npoints, p, p_stride,       \
                             state_in, u, f, dfdu, dfdp, state_out, bad);                          \
    }                                                                                              \
    static FR_NOINLINE int point1_##dim##_##normal(const fricreg_element_type *type,               \
                                                   const double *p, const double *state_in,        \
                                                   const double *u, double *f, double *dfdu,       \
                                                   double *dfdp, double *state_out)                \
    {                                                                                              \
        return point_sliders(type, 1, (dim) - (normal), normal, p, state_in, u, f, dfdu, dfdp,     \
                             state_out);                                                           \
    }                                                                                              \
    static FR_NOINLINE int pointn_##dim##_##normal(const fricreg_element_type *type,               \
                                                   const double *p, const double *state_in,        \
                                                   const double *u, double *f, double *dfdu,       \
                                                   double *dfdp, double *state_out)                \
    {                                                                                              \
        return point_sliders(type, type->ns, (dim) - (normal), normal, p, state_in, u, f, dfdu,    \
                             dfdp, state_out);                                                     \
    }                                                                                              \
    static int point_##dim##_##normal(const fricreg_element_type *type, const double *p,           \
                                      const double *state_in, const double *u, double *f,          \
                                      double *dfdu, double *dfdp, double *state_out)               \
    {                                                                                              \
        return (type->ns == 1                                                                      \
                    ? point1_##dim##_##normal                                                      \
                    : pointn_##dim##_##normal)(type, p, state_in, u, f, dfdu, dfdp, state_out);    \
    }

FR_SLIDER_SHAPE(1, 0)
FR_SLIDER_SHAPE(2, 0)
FR_SLIDER_SHAPE(3, 0)
FR_SLIDER_SHAPE(2, 1)
FR_SLIDER_SHAPE(3, 1)

static void elastic(const fricreg_element_type *type, const double *p, double *k)
{
    size_t ns = type->ns;
    int td = type->kind->dim - type->kind->normal;
    for (int a = 0; a < td; a++) {
        k[a] = 0.0;
        for (size_t s = 0; s < ns; s++)
            k[a] += p[s];
    }
    if (type->kind->normal)
        k[td] = p[2 * ns];
}

/* |f| <= sum_s phi_s N (N = 1 without a normal law, else f's normal force, first raised to 0
 * if below), radially for 2 or 3 components: the return's projection. */
static void project(const fricreg_element_type *type, const double *p, double *f)
{
    size_t ns = type->ns;
    int td = type->kind->dim - type->kind->normal;
    double bound = 0.0;
    for (size_t s = 0; s < ns; s++)
        bound += p[ns + s];
    if (type->kind->normal) {
        if (f[td] < 0.0)
            f[td] = 0.0;
        bound *= f[td];
    }
    if (td == 1 && fabs(f[0]) > bound)
        f[0] = copysign(bound, f[0]);
    double r = td > 1 ? fr_slider_norm(f, td) : 0.0;
    for (int a = 0; a < td && r > bound; a++)
        f[a] *= bound / r;
}

/* Each slider's spring |f_s|^2 / (2 k_s), or the normal spring's N^2 / (2 kn) (kn = 0: a
 * constant normal load n0, no spring to hold energy). */
static double stored(const fricreg_element_type *type, const double *p, const double *fs,
                     const double *f, int normal, double sum)
{
    size_t ns = type->ns, td = (size_t)(type->kind->dim - type->kind->normal);
    if (normal)
        return type->kind->normal && p[2 * ns] > 0.0 ? sum + 0.5 * f[td] * (f[td] / p[2 * ns])
                                                     : sum;
    for (size_t j = 0; j < ns * td; j++)
        sum += 0.5 * fs[j] * (fs[j] / p[j / td]);
    return sum;
}

/* Each slider's return-mapping tangent t_s, t_s / k_s and position after the call, the sliders
 * of a law without a normal law (slider.h: d w_s' / d w_s = t_s / k_s, k_s I in a stick, a
 * contraction in a slip). */
static void slider_tangents(const fricreg_element_type *type, const double *p, const double *state,
                            const double *u, double *ts, double *tw, double *state_out)
{
    int td = type->kind->dim;
    size_t ns = type->ns, block = (size_t)(td * td);
    for (size_t s = 0; s < ns; s++) {
        double f[3], w[3];
        fr_slider_return(p[s], p[ns + s], 0.0, td, u, &state[(size_t)td * s], f, w, &ts[block * s],
                         NULL);
        for (size_t a = 0; a < block; a++)
            tw[block * s + a] = ts[block * s + a] / p[s];
        memcpy(&state_out[(size_t)td * s], w, (size_t)td * sizeof *w);
    }
}

/* One kind per line: name, dim, normal, family, sizes, harmonic balance's AFT, and the slider
 * tangents of the march (MARCH's only); eval, batch and point are its shape's (dim, normal). */
#define FR_SLIDER_KIND(id, dim_, normal_, family_, params, state, aft_, tangents)      \
    const struct fr_element_kind fr_element_##id = {.name = #id,                       \
                                                    .dim = dim_,                       \
                                                    .normal = normal_,                 \
                                                    .family = family_,                 \
                                                    .aft = FR_ELEMENT_AFT_##aft_,      \
                                                    .nparams = params,                 \
                                                    .nstate = state,                   \
                                                    .check = check,                    \
                                                    .eval = eval_##dim_##_##normal_,   \
                                                    .elastic = elastic,                \
                                                    .project = project,                \
                                                    .stored = stored,                  \
                                                    .slider_tangents = tangents,       \
                                                    .batch = batch_##dim_##_##normal_, \
                                                    .point = point_##dim_##_##normal_};

FR_SLIDER_KIND(jenkins, 1, 0, 0, params_plain, state_1, SLIDERS, NULL)
FR_SLIDER_KIND(jenkins_2d, 2, 0, 0, params_plain, state_2, MARCH, slider_tangents)
FR_SLIDER_KIND(jenkins_3d, 3, 0, 0, params_plain, state_3, MARCH, slider_tangents)
FR_SLIDER_KIND(jenkins_normal, 2, 1, 0, params_normal, state_1, LIFTOFF, NULL)
FR_SLIDER_KIND(contact_3d, 3, 1, 0, params_normal, state_2, CONTACT_3D, NULL)
FR_SLIDER_KIND(iwan, 1, 0, 1, params_plain, state_1, SLIDERS, NULL)
FR_SLIDER_KIND(iwan_2d, 2, 0, 1, params_plain, state_2, MARCH, slider_tangents)
FR_SLIDER_KIND(iwan_3d, 3, 0, 1, params_plain, state_3, MARCH, slider_tangents)
FR_SLIDER_KIND(iwan_normal, 2, 1, 1, params_normal, state_1, LIFTOFF, NULL)
