/* SPDX-License-Identifier: GPL-3.0-or-later */
/* jenkins.c — n Jenkins elements (spring kt in series with a Coulomb slider of bound mun), 1-D
 * or 2-D: the elastic predictor, the return onto |f| <= mun and its consistent tangent
 * (fricreg_jenkins.h; Simo & Hughes 1998, Ch. 1 and 3), with trial/commit of the sliders, and
 * the normal load with lift-off: the bound mu max(0, N0 + kn g). The one slider's return
 * mapping is slider.h's, shared with the Iwan elements.
 *
 * A fixed bound mun (set_params) is the normal law mu = 1, N0 = mun, kn = 0: the bound is then
 * 1 * max(0, mun + 0 g) = mun to the bit and never separates, so fricreg_jenkins_trial keeps
 * its results, and it is fricreg_jenkins_trial_normal at g = 0. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "fricreg_jenkins.h"
#include "slider.h"

#define MAX_ELEMENTS (SIZE_MAX / 64)

struct fricreg_jenkins {
    int dim;
    size_t n;
    double *kt, *mu, *n0, *kn; /* [n] each, one block: the bound is mu max(0, n0 + kn g) */
    double *w_c;               /* committed slider positions [n dim] */
    double *w_tr; /* the last trial's [n dim]; equal to w_c after commit, reset, set_params */
    struct fr_error err;
};

int fricreg_jenkins_create(int dim, size_t n, fricreg_jenkins **out)
{
    if (out == NULL)
        return FRICREG_ENULL;
    if ((dim != 1 && dim != 2) || n == 0 || n > MAX_ELEMENTS)
        return FRICREG_EINVAL;
    fricreg_jenkins *j = calloc(1, sizeof *j);
    double *block = malloc((4 + 2 * (size_t)dim) * n * sizeof *block);
    if (j == NULL || block == NULL) {
        free(j);
        free(block);
        return FRICREG_ENOMEM;
    }
    j->dim = dim;
    j->n = n;
    j->kt = block;
    j->mu = block + n;
    j->n0 = block + 2 * n;
    j->kn = block + 3 * n;
    j->w_c = block + 4 * n;
    j->w_tr = j->w_c + (size_t)dim * n;
    for (size_t i = 0; i < n; i++) {
        j->kt[i] = j->mu[i] = j->n0[i] = 1.0;
        j->kn[i] = 0.0;
    }
    memset(j->w_c, 0, 2 * (size_t)dim * n * sizeof *block);
    *out = j;
    return FRICREG_OK;
}

void fricreg_jenkins_free(fricreg_jenkins *j)
{
    if (j == NULL)
        return;
    free(j->kt);
    free(j);
}

size_t fricreg_jenkins_size(const fricreg_jenkins *j)
{
    return j ? j->n : 0;
}

int fricreg_jenkins_dim(const fricreg_jenkins *j)
{
    return j ? j->dim : 0;
}

/* The element count check of every array call. */
static int check_n(fricreg_jenkins *j, const char *fn, size_t n)
{
    if (n != j->n)
        return fr_fail(j, FRICREG_ESIZE, "%s: n = %zu, the object has %zu elements", fn, n, j->n);
    return FRICREG_OK;
}

int fricreg_jenkins_set_params(fricreg_jenkins *j, size_t n, const double kt[], const double mun[])
{
    if (j == NULL)
        return FRICREG_ENULL;
    if (kt == NULL || mun == NULL)
        return fr_fail(j, FRICREG_ENULL, "set_params: %s is NULL", kt == NULL ? "kt" : "mun");
    if (check_n(j, "set_params", n) != FRICREG_OK)
        return FRICREG_ESIZE;
    for (size_t i = 0; i < n; i++) {
        if (!isfinite(kt[i]) || !isfinite(mun[i]))
            return fr_fail(j, FRICREG_ENONFINITE, "set_params: kt[%zu] = %g, mun[%zu] = %g", i,
                           kt[i], i, mun[i]);
        if (!(kt[i] > 0.0))
            return fr_fail(j, FRICREG_EINVAL, "set_params: kt[%zu] = %g must be > 0", i, kt[i]);
        if (!(mun[i] >= 0.0))
            return fr_fail(j, FRICREG_EINVAL, "set_params: mun[%zu] = %g must be >= 0", i, mun[i]);
    }
    memcpy(j->kt, kt, n * sizeof *kt);
    memcpy(j->n0, mun, n * sizeof *mun);
    for (size_t i = 0; i < n; i++) {
        j->mu[i] = 1.0;
        j->kn[i] = 0.0;
    }
    memcpy(j->w_tr, j->w_c, (size_t)j->dim * n * sizeof *j->w_c);
    return FRICREG_OK;
}

int fricreg_jenkins_set_normal(fricreg_jenkins *j, size_t n, const double mu[], const double n0[],
                               const double kn[])
{
    if (j == NULL)
        return FRICREG_ENULL;
    if (mu == NULL || n0 == NULL || kn == NULL)
        return fr_fail(j, FRICREG_ENULL, "set_normal: %s is NULL",
                       mu == NULL   ? "mu"
                       : n0 == NULL ? "n0"
                                    : "kn");
    if (check_n(j, "set_normal", n) != FRICREG_OK)
        return FRICREG_ESIZE;
    for (size_t i = 0; i < n; i++) {
        if (!isfinite(mu[i]) || !isfinite(n0[i]) || !isfinite(kn[i]))
            return fr_fail(j, FRICREG_ENONFINITE,
                           "set_normal: mu[%zu] = %g, n0[%zu] = %g, kn[%zu] = %g", i, mu[i], i,
                           n0[i], i, kn[i]);
        if (!(mu[i] >= 0.0))
            return fr_fail(j, FRICREG_EINVAL, "set_normal: mu[%zu] = %g must be >= 0", i, mu[i]);
        if (!(kn[i] >= 0.0))
            return fr_fail(j, FRICREG_EINVAL, "set_normal: kn[%zu] = %g must be >= 0", i, kn[i]);
        if (!isfinite(mu[i] * n0[i]) || !isfinite(mu[i] * kn[i]))
            return fr_fail(j, FRICREG_ENONFINITE,
                           "set_normal: mu[%zu] n0[%zu] = %g or mu[%zu] kn[%zu] = %g overflows", i,
                           i, mu[i] * n0[i], i, i, mu[i] * kn[i]);
    }
    memcpy(j->mu, mu, n * sizeof *mu);
    memcpy(j->n0, n0, n * sizeof *n0);
    memcpy(j->kn, kn, n * sizeof *kn);
    memcpy(j->w_tr, j->w_c, (size_t)j->dim * n * sizeof *j->w_c);
    return FRICREG_OK;
}

/* Whether element i's u is finite and |u - w_c| too; writes the message (of function fn) if
 * not. */
static int check_u(fricreg_jenkins *j, const char *fn, size_t i, const double *u)
{
    int dim = j->dim;
    const double *wc = &j->w_c[(size_t)dim * i];
    double d[2] = {0.0, 0.0};
    for (int a = 0; a < dim; a++) {
        size_t k = (size_t)dim * i + (size_t)a;
        if (!isfinite(u[a]))
            return fr_fail(j, FRICREG_ENONFINITE, "%s: u[%zu] = %g", fn, k, u[a]);
        d[a] = u[a] - wc[a];
    }
    if (!isfinite(fr_slider_norm(d, dim)))
        return fr_fail(j, FRICREG_ENONFINITE,
                       "%s: element %zu's u - w overflows (u[%zu] = %g, w = %g)", fn, i,
                       (size_t)dim * i, u[0], wc[0]);
    return FRICREG_OK;
}

/* Element i's normal force N0 + kn g (negative: separated) and its bound mu max(0, .), both
 * finite; writes the message if not. */
static int check_g(fricreg_jenkins *j, size_t i, double g, double *nc, double *b)
{
    if (!isfinite(g))
        return fr_fail(j, FRICREG_ENONFINITE, "trial_normal: g[%zu] = %g", i, g);
    *nc = j->n0[i] + j->kn[i] * g;
    *b = j->mu[i] * fmax(0.0, *nc);
    if (!isfinite(*nc) || !isfinite(*b))
        return fr_fail(j, FRICREG_ENONFINITE,
                       "trial_normal: element %zu's normal force n0 + kn g = %g (g = %g) overflows",
                       i, *nc, g);
    return FRICREG_OK;
}

/* The trial of every element, g NULL meaning g = 0 (fricreg_jenkins_trial), inputs checked. */
static int trial(fricreg_jenkins *j, const char *fn, size_t n, const double u[], const double g[],
                 double f[], double nf[], double dfdu[], double dfdg[])
{
    if (check_n(j, fn, n) != FRICREG_OK)
        return FRICREG_ESIZE;
    size_t dim = (size_t)j->dim;
    double nc, b;
    for (size_t i = 0; i < n; i++) {
        if (check_u(j, fn, i, &u[dim * i]) != FRICREG_OK)
            return j->err.code;
        if (g != NULL && check_g(j, i, g[i], &nc, &b) != FRICREG_OK)
            return j->err.code;
    }
    for (size_t i = 0; i < n; i++) {
        nc = j->n0[i] + j->kn[i] * (g ? g[i] : 0.0);
        b = j->mu[i] * fmax(0.0, nc);
        double *t = dfdu ? &dfdu[dim * dim * i] : NULL, *tg = dfdg ? &dfdg[dim * i] : NULL;
        if (nc < 0.0)
            fr_slider_separated(j->dim, &u[dim * i], &f[dim * i], &j->w_tr[dim * i], t, tg);
        else
            fr_slider_return(j->kt[i], b, j->mu[i] * j->kn[i], j->dim, &u[dim * i],
                             &j->w_c[dim * i], &f[dim * i], &j->w_tr[dim * i], t, tg);
        if (nf != NULL)
            nf[i] = fmax(0.0, nc);
    }
    return FRICREG_OK;
}

int fricreg_jenkins_trial(fricreg_jenkins *j, size_t n, const double u[], double f[], double dfdu[])
{
    if (j == NULL)
        return FRICREG_ENULL;
    if (u == NULL || f == NULL)
        return fr_fail(j, FRICREG_ENULL, "trial: %s is NULL", u == NULL ? "u" : "f");
    return trial(j, "trial", n, u, NULL, f, NULL, dfdu, NULL);
}

int fricreg_jenkins_trial_normal(fricreg_jenkins *j, size_t n, const double u[], const double g[],
                                 double f[], double nf[], double dfdu[], double dfdg[])
{
    if (j == NULL)
        return FRICREG_ENULL;
    if (u == NULL || g == NULL || f == NULL)
        return fr_fail(j, FRICREG_ENULL, "trial_normal: %s is NULL",
                       u == NULL   ? "u"
                       : g == NULL ? "g"
                                   : "f");
    return trial(j, "trial_normal", n, u, g, f, nf, dfdu, dfdg);
}

int fricreg_jenkins_commit(fricreg_jenkins *j)
{
    if (j == NULL)
        return FRICREG_ENULL;
    memcpy(j->w_c, j->w_tr, (size_t)j->dim * j->n * sizeof *j->w_c);
    return FRICREG_OK;
}

int fricreg_jenkins_reset(fricreg_jenkins *j)
{
    if (j == NULL)
        return FRICREG_ENULL;
    memset(j->w_c, 0, 2 * (size_t)j->dim * j->n * sizeof *j->w_c);
    return FRICREG_OK;
}

int fricreg_jenkins_get_slider(fricreg_jenkins *j, size_t n, double w[])
{
    if (j == NULL)
        return FRICREG_ENULL;
    if (w == NULL)
        return fr_fail(j, FRICREG_ENULL, "get_slider: w is NULL");
    if (check_n(j, "get_slider", n) != FRICREG_OK)
        return FRICREG_ESIZE;
    memcpy(w, j->w_c, (size_t)j->dim * n * sizeof *w);
    return FRICREG_OK;
}

FR_ERROR_GETTERS(fricreg_jenkins, "NULL Jenkins elements")
