/* SPDX-License-Identifier: GPL-3.0-or-later */
/* iwan.c — n Iwan elements of ns parallel Jenkins sliders each, 1-D or 2-D (fricreg_iwan.h):
 * the sum of the sliders' return mappings (slider.h, shared with the Jenkins elements), their
 * trial/commit, Segalman's four-parameter model on the moment rule's geometric grid, and the
 * normal load with lift-off (slip forces phi N/N0).
 *
 * Without a normal law an element has N0 = 1, kn = 0: the scale max(0, 1 + 0 g)/1 is 1 to the
 * bit, so fricreg_iwan_trial is fricreg_iwan_trial_normal at g = 0. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "fricreg_iwan.h"
#include "segalman.h"
#include "slider.h"

#define MAX_SLIDERS (SIZE_MAX / 64)

struct fricreg_iwan {
    int dim;
    size_t n, ns;
    double *k, *phi; /* [n ns] each: element e's slider s at [ns e + s] */
    double *n0, *kn; /* [n] each: the slip forces scale by max(0, n0 + kn g)/n0 */
    double *w_c;     /* committed slider positions [n ns dim] */
    double *w_tr;    /* the last trial's [n ns dim]; equal to w_c after commit, reset, setters */
    double *w_new;   /* [n ns dim] a trial's positions until it succeeds (then swapped with w_tr) */
    double *out;     /* [n (2 dim + dim dim)] a trial's sums (f, dfdu, dfdg) until all are finite */
    struct fr_error err;
};

int fricreg_iwan_create(int dim, size_t n, size_t ns, fricreg_iwan **out)
{
    if (out == NULL)
        return FRICREG_ENULL;
    if ((dim != 1 && dim != 2) || n == 0 || ns == 0 || ns > MAX_SLIDERS / n)
        return FRICREG_EINVAL;
    size_t m = n * ns, d = (size_t)dim;
    /* at most 8 m + 10 n <= 18 SIZE_MAX/64 doubles: the count fits, its bytes may not */
    size_t count = (2 + 3 * d) * m + (2 + 2 * d + d * d) * n;
    if (count > SIZE_MAX / sizeof(double))
        return FRICREG_ENOMEM;
    fricreg_iwan *iw = calloc(1, sizeof *iw);
    double *block = malloc(count * sizeof *block);
    if (iw == NULL || block == NULL) {
        free(iw);
        free(block);
        return FRICREG_ENOMEM;
    }
    iw->dim = dim;
    iw->n = n;
    iw->ns = ns;
    iw->k = block;
    iw->phi = block + m;
    iw->w_c = block + 2 * m;
    iw->w_tr = iw->w_c + d * m;
    iw->w_new = iw->w_tr + d * m;
    iw->n0 = iw->w_new + d * m;
    iw->kn = iw->n0 + n;
    iw->out = iw->kn + n;
    for (size_t i = 0; i < m; i++)
        iw->k[i] = iw->phi[i] = 1.0 / (double)ns;
    for (size_t e = 0; e < n; e++) {
        iw->n0[e] = 1.0;
        iw->kn[e] = 0.0;
    }
    memset(iw->w_c, 0, 2 * (size_t)dim * m * sizeof *block);
    *out = iw;
    return FRICREG_OK;
}

void fricreg_iwan_free(fricreg_iwan *iw)
{
    if (iw == NULL)
        return;
    free(iw->k);
    free(iw);
}

size_t fricreg_iwan_size(const fricreg_iwan *iw)
{
    return iw ? iw->n : 0;
}

size_t fricreg_iwan_sliders(const fricreg_iwan *iw)
{
    return iw ? iw->ns : 0;
}

int fricreg_iwan_dim(const fricreg_iwan *iw)
{
    return iw ? iw->dim : 0;
}

/* The element count check of every array call; ns too where given (ns_given). */
static int check_n(fricreg_iwan *iw, const char *fn, size_t n, int ns_given, size_t ns)
{
    if (n != iw->n)
        return fr_fail(iw, FRICREG_ESIZE, "%s: n = %zu, the object has %zu elements", fn, n, iw->n);
    if (ns_given && ns != iw->ns)
        return fr_fail(iw, FRICREG_ESIZE, "%s: ns = %zu, the object has %zu sliders an element", fn,
                       ns, iw->ns);
    return FRICREG_OK;
}

/* A pending trial is discarded: the trial positions are the committed ones. */
static void discard_trial(fricreg_iwan *iw)
{
    memcpy(iw->w_tr, iw->w_c, (size_t)iw->dim * iw->n * iw->ns * sizeof *iw->w_c);
}

int fricreg_iwan_set_params(fricreg_iwan *iw, size_t n, size_t ns, const double k[],
                            const double phi[])
{
    if (iw == NULL)
        return FRICREG_ENULL;
    if (k == NULL || phi == NULL)
        return fr_fail(iw, FRICREG_ENULL, "set_params: %s is NULL", k == NULL ? "k" : "phi");
    if (check_n(iw, "set_params", n, 1, ns) != FRICREG_OK)
        return FRICREG_ESIZE;
    for (size_t i = 0; i < n * ns; i++) {
        if (!isfinite(k[i]) || !isfinite(phi[i]))
            return fr_fail(iw, FRICREG_ENONFINITE, "set_params: k[%zu] = %g, phi[%zu] = %g", i,
                           k[i], i, phi[i]);
        if (!(k[i] > 0.0))
            return fr_fail(iw, FRICREG_EINVAL, "set_params: k[%zu] = %g must be > 0", i, k[i]);
        if (!(phi[i] >= 0.0))
            return fr_fail(iw, FRICREG_EINVAL, "set_params: phi[%zu] = %g must be >= 0", i, phi[i]);
    }
    memcpy(iw->k, k, n * ns * sizeof *k);
    memcpy(iw->phi, phi, n * ns * sizeof *phi);
    discard_trial(iw);
    return FRICREG_OK;
}

int fricreg_iwan_get_params(fricreg_iwan *iw, size_t n, size_t ns, double k[], double phi[])
{
    if (iw == NULL)
        return FRICREG_ENULL;
    if (k == NULL || phi == NULL)
        return fr_fail(iw, FRICREG_ENULL, "get_params: %s is NULL", k == NULL ? "k" : "phi");
    if (check_n(iw, "get_params", n, 1, ns) != FRICREG_OK)
        return FRICREG_ESIZE;
    memcpy(k, iw->k, n * ns * sizeof *k);
    memcpy(phi, iw->phi, n * ns * sizeof *phi);
    return FRICREG_OK;
}

int fricreg_iwan_set_segalman(fricreg_iwan *iw, size_t n, const double fs[], const double kt[],
                              const double chi[], const double beta[], double resolution)
{
    if (iw == NULL)
        return FRICREG_ENULL;
    if (fs == NULL || kt == NULL || chi == NULL || beta == NULL)
        return fr_fail(iw, FRICREG_ENULL, "set_segalman: %s is NULL",
                       fs == NULL    ? "fs"
                       : kt == NULL  ? "kt"
                       : chi == NULL ? "chi"
                                     : "beta");
    if (check_n(iw, "set_segalman", n, 0, 0) != FRICREG_OK)
        return FRICREG_ESIZE;
    size_t ns = iw->ns;
    char why[160];
    if (!isfinite(resolution))
        return fr_fail(iw, FRICREG_ENONFINITE, "set_segalman: resolution = %g", resolution);
    for (size_t e = 0; e < n; e++) {
        int status = fr_segalman_check_params(fs[e], kt[e], chi[e], beta[e], resolution, ns, why,
                                              sizeof why);
        if (status != FRICREG_OK)
            return fr_fail(iw, status, "set_segalman: element %zu: %s", e, why);
    }
    /* the sliders, checked before any is stored (computed twice: set-up, not the trial) */
    for (size_t e = 0; e < n; e++) {
        int status = fr_segalman_check_sliders(fs[e], kt[e], chi[e], beta[e], resolution, ns, why,
                                               sizeof why);
        if (status != FRICREG_OK)
            return fr_fail(iw, status, "set_segalman: element %zu's %s", e, why);
    }
    for (size_t e = 0; e < n; e++)
        for (size_t s = 0; s < ns; s++)
            fr_segalman_slider(fs[e], kt[e], chi[e], beta[e], resolution, ns, s, &iw->k[ns * e + s],
                               &iw->phi[ns * e + s]);
    discard_trial(iw);
    return FRICREG_OK;
}

int fricreg_iwan_set_normal(fricreg_iwan *iw, size_t n, const double n0[], const double kn[])
{
    if (iw == NULL)
        return FRICREG_ENULL;
    if (n0 == NULL || kn == NULL)
        return fr_fail(iw, FRICREG_ENULL, "set_normal: %s is NULL", n0 == NULL ? "n0" : "kn");
    if (check_n(iw, "set_normal", n, 0, 0) != FRICREG_OK)
        return FRICREG_ESIZE;
    for (size_t e = 0; e < n; e++) {
        if (!isfinite(n0[e]) || !isfinite(kn[e]))
            return fr_fail(iw, FRICREG_ENONFINITE, "set_normal: n0[%zu] = %g, kn[%zu] = %g", e,
                           n0[e], e, kn[e]);
        if (!(n0[e] > 0.0))
            return fr_fail(iw, FRICREG_EINVAL, "set_normal: n0[%zu] = %g must be > 0", e, n0[e]);
        if (!(kn[e] >= 0.0))
            return fr_fail(iw, FRICREG_EINVAL, "set_normal: kn[%zu] = %g must be >= 0", e, kn[e]);
        if (!isfinite(kn[e] / n0[e]))
            return fr_fail(iw, FRICREG_ENONFINITE, "set_normal: kn[%zu]/n0[%zu] = %g overflows", e,
                           e, kn[e] / n0[e]);
    }
    memcpy(iw->n0, n0, n * sizeof *n0);
    memcpy(iw->kn, kn, n * sizeof *kn);
    discard_trial(iw);
    return FRICREG_OK;
}

/* Whether element e's u is finite and |u - w_s| too for every slider; writes the message (of
 * function fn) if not. */
static int check_u(fricreg_iwan *iw, const char *fn, size_t e, const double *u)
{
    int dim = iw->dim;
    for (int a = 0; a < dim; a++)
        if (!isfinite(u[a]))
            return fr_fail(iw, FRICREG_ENONFINITE, "%s: u[%zu] = %g", fn,
                           (size_t)dim * e + (size_t)a, u[a]);
    for (size_t s = 0; s < iw->ns; s++) {
        const double *wc = &iw->w_c[(size_t)dim * (iw->ns * e + s)];
        double d[2] = {u[0] - wc[0], dim == 2 ? u[1] - wc[1] : 0.0};
        if (!isfinite(fr_slider_norm(d, dim)))
            return fr_fail(iw, FRICREG_ENONFINITE,
                           "%s: element %zu's u - w of slider %zu overflows (u[%zu] = %g, w = %g)",
                           fn, e, s, (size_t)dim * e, u[0], wc[0]);
    }
    return FRICREG_OK;
}

/* Element e's normal force N0 + kn g (negative: separated), the scale max(0, .)/N0 of its slip
 * forces, and the scaled largest slip force, all finite; writes the message if not. */
static int check_g(fricreg_iwan *iw, size_t e, double g)
{
    if (!isfinite(g))
        return fr_fail(iw, FRICREG_ENONFINITE, "trial_normal: g[%zu] = %g", e, g);
    double nc = iw->n0[e] + iw->kn[e] * g, scale = fmax(0.0, nc) / iw->n0[e];
    double top = 0.0;
    for (size_t s = 0; s < iw->ns; s++)
        top = fmax(top, iw->phi[iw->ns * e + s]);
    if (!isfinite(nc) || !isfinite(scale * top))
        return fr_fail(iw, FRICREG_ENONFINITE,
                       "trial_normal: element %zu's normal force n0 + kn g = %g (g = %g) or its "
                       "slip forces overflow",
                       e, nc, g);
    return FRICREG_OK;
}

/* One element e at u (dim) and normal displacement g: the sums of its sliders into f[dim],
 * t[dim dim] and tg[dim] (the trial's scratch), the sliders' trial positions into w_new. */
static void element(fricreg_iwan *iw, size_t e, const double *u, double g, double *f, double *t,
                    double *tg)
{
    int dim = iw->dim;
    size_t ns = iw->ns, dd = (size_t)(dim * dim);
    double nc = iw->n0[e] + iw->kn[e] * g, scale = fmax(0.0, nc) / iw->n0[e],
           dscale = iw->kn[e] / iw->n0[e];
    double ui[2] = {u[0], dim == 2 ? u[1] : 0.0}, fs[2], ts[4], tgs[2];
    for (int a = 0; a < dim; a++)
        f[a] = tg[a] = 0.0;
    for (size_t a = 0; a < dd; a++)
        t[a] = 0.0;
    for (size_t s = 0; s < ns; s++) {
        size_t i = ns * e + s;
        double *w = &iw->w_new[(size_t)dim * i];
        if (nc < 0.0)
            fr_slider_separated(dim, ui, fs, w, ts, tgs);
        else
            fr_slider_return(iw->k[i], iw->phi[i] * scale, iw->phi[i] * dscale, dim, ui,
                             &iw->w_c[(size_t)dim * i], fs, w, ts, tgs);
        for (int a = 0; a < dim; a++) {
            f[a] += fs[a];
            tg[a] += tgs[a];
        }
        for (size_t a = 0; a < dd; a++)
            t[a] += ts[a];
    }
}

/* Whether x[0..count-1] are finite; the first one that is not into *bad. */
static int all_finite(const double *x, size_t count, double *bad)
{
    for (size_t k = 0; k < count; k++)
        if (!isfinite(x[k])) {
            *bad = x[k];
            return 0;
        }
    return 1;
}

/* The trial of every element, g NULL meaning g = 0 (fricreg_iwan_trial), inputs checked. The
 * sums are formed in the object's scratch and the positions in w_new: each slider's force is
 * finite (|f_s| <= its slip force, checked) but their sum, or the sum of the sticking sliders'
 * stiffnesses or slip-force slopes, can overflow; a sum that did fails the call before any
 * output or the trial state changes. */
static int trial(fricreg_iwan *iw, const char *fn, size_t n, const double u[], const double g[],
                 double f[], double nf[], double dfdu[], double dfdg[])
{
    if (check_n(iw, fn, n, 0, 0) != FRICREG_OK)
        return FRICREG_ESIZE;
    size_t dim = (size_t)iw->dim, dd = dim * dim;
    for (size_t e = 0; e < n; e++) {
        if (check_u(iw, fn, e, &u[dim * e]) != FRICREG_OK)
            return iw->err.code;
        if (g != NULL && check_g(iw, e, g[e]) != FRICREG_OK)
            return iw->err.code;
    }
    double *fo = iw->out, *to = fo + dim * n, *tgo = to + dd * n, bad = 0.0;
    for (size_t e = 0; e < n; e++) {
        element(iw, e, &u[dim * e], g ? g[e] : 0.0, &fo[dim * e], &to[dd * e], &tgo[dim * e]);
        const char *what = !all_finite(&fo[dim * e], dim, &bad)                    ? "force"
                           : dfdu != NULL && !all_finite(&to[dd * e], dd, &bad)    ? "tangent"
                           : dfdg != NULL && !all_finite(&tgo[dim * e], dim, &bad) ? "df/dg"
                                                                                   : NULL;
        if (what != NULL)
            return fr_fail(iw, FRICREG_ENONFINITE,
                           "%s: element %zu's sliders sum to a %s of %g: the sum of %zu sliders "
                           "overflows (their stiffnesses or slip forces near the double range)",
                           fn, e, what, bad, iw->ns);
    }
    double *w = iw->w_tr; /* the new trial positions become the trial state */
    iw->w_tr = iw->w_new;
    iw->w_new = w;
    for (size_t e = 0; e < n && nf != NULL; e++)
        nf[e] = fmax(0.0, iw->n0[e] + iw->kn[e] * (g ? g[e] : 0.0));
    memcpy(f, fo, dim * n * sizeof *f); /* u read: f may alias it */
    if (dfdu != NULL)
        memcpy(dfdu, to, dd * n * sizeof *dfdu);
    if (dfdg != NULL)
        memcpy(dfdg, tgo, dim * n * sizeof *dfdg);
    return FRICREG_OK;
}

int fricreg_iwan_trial(fricreg_iwan *iw, size_t n, const double u[], double f[], double dfdu[])
{
    if (iw == NULL)
        return FRICREG_ENULL;
    if (u == NULL || f == NULL)
        return fr_fail(iw, FRICREG_ENULL, "trial: %s is NULL", u == NULL ? "u" : "f");
    return trial(iw, "trial", n, u, NULL, f, NULL, dfdu, NULL);
}

int fricreg_iwan_trial_normal(fricreg_iwan *iw, size_t n, const double u[], const double g[],
                              double f[], double nf[], double dfdu[], double dfdg[])
{
    if (iw == NULL)
        return FRICREG_ENULL;
    if (u == NULL || g == NULL || f == NULL)
        return fr_fail(iw, FRICREG_ENULL, "trial_normal: %s is NULL",
                       u == NULL   ? "u"
                       : g == NULL ? "g"
                                   : "f");
    return trial(iw, "trial_normal", n, u, g, f, nf, dfdu, dfdg);
}

int fricreg_iwan_commit(fricreg_iwan *iw)
{
    if (iw == NULL)
        return FRICREG_ENULL;
    memcpy(iw->w_c, iw->w_tr, (size_t)iw->dim * iw->n * iw->ns * sizeof *iw->w_c);
    return FRICREG_OK;
}

int fricreg_iwan_reset(fricreg_iwan *iw)
{
    if (iw == NULL)
        return FRICREG_ENULL;
    size_t count = (size_t)iw->dim * iw->n * iw->ns;
    memset(iw->w_c, 0, count * sizeof *iw->w_c);
    memset(iw->w_tr, 0, count * sizeof *iw->w_tr);
    return FRICREG_OK;
}

int fricreg_iwan_get_slider(fricreg_iwan *iw, size_t n, size_t ns, double w[])
{
    if (iw == NULL)
        return FRICREG_ENULL;
    if (w == NULL)
        return fr_fail(iw, FRICREG_ENULL, "get_slider: w is NULL");
    if (check_n(iw, "get_slider", n, 1, ns) != FRICREG_OK)
        return FRICREG_ESIZE;
    memcpy(w, iw->w_c, (size_t)iw->dim * n * ns * sizeof *w);
    return FRICREG_OK;
}

FR_ERROR_GETTERS(fricreg_iwan, "NULL Iwan elements")
