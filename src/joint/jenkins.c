/* SPDX-License-Identifier: GPL-3.0-or-later */
/* jenkins.c — n Jenkins elements (spring kt in series with a Coulomb slider of bound mun), 1-D
 * or 2-D: the elastic predictor, the return onto |f| <= mun and its consistent tangent
 * (fricreg_jenkins.h; Simo & Hughes 1998, Ch. 1 and 3), with trial/commit of the sliders.
 *
 * The return works on d = u - w_c, not on f_tr = kt d: |d| and the direction d/|d| stay finite
 * whenever d does, so a stiff spring (kt d beyond 1e308) still slides to f = mun n, and the
 * sliding tangent kt (mun/|f_tr|) is computed as mun/|d|. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "fricreg_jenkins.h"

#define MAX_ELEMENTS (SIZE_MAX / 64)

struct fricreg_jenkins {
    int dim;
    size_t n;
    double *kt, *mun; /* [n] each, one block */
    double *w_c;      /* committed slider positions [n dim] */
    double *w_tr;     /* the last trial's [n dim]; equal to w_c after commit, reset, set_params */
    struct fr_error err;
};

int fricreg_jenkins_create(int dim, size_t n, fricreg_jenkins **out)
{
    if (out == NULL)
        return FRICREG_ENULL;
    if ((dim != 1 && dim != 2) || n == 0 || n > MAX_ELEMENTS)
        return FRICREG_EINVAL;
    fricreg_jenkins *j = calloc(1, sizeof *j);
    double *block = malloc((2 + 2 * (size_t)dim) * n * sizeof *block);
    if (j == NULL || block == NULL) {
        free(j);
        free(block);
        return FRICREG_ENOMEM;
    }
    j->dim = dim;
    j->n = n;
    j->kt = block;
    j->mun = block + n;
    j->w_c = block + 2 * n;
    j->w_tr = j->w_c + (size_t)dim * n;
    for (size_t i = 0; i < n; i++)
        j->kt[i] = j->mun[i] = 1.0;
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
        if (!(kt[i] > 0.0) || !(mun[i] >= 0.0))
            return fr_fail(j, FRICREG_EINVAL,
                           "set_params: kt[%zu] = %g must be > 0, mun[%zu] = %g >= 0", i, kt[i], i,
                           mun[i]);
    }
    memcpy(j->kt, kt, n * sizeof *kt);
    memcpy(j->mun, mun, n * sizeof *mun);
    memcpy(j->w_tr, j->w_c, (size_t)j->dim * n * sizeof *j->w_c);
    return FRICREG_OK;
}

/* |d| of one element's d = u - w_c, dim 1 or 2. */
static double norm(const double *d, int dim)
{
    return dim == 1 ? fabs(d[0]) : hypot(d[0], d[1]);
}

/* One element: the return mapping from its committed slider wc[dim] at u[dim], with
 * d = u - wc finite and |d| finite (checked by the caller). Writes f[dim], the slider's trial
 * position w[dim] (wc itself in a stick), and the tangent t[dim dim] if t is not NULL. f may
 * alias u: u is read before f is written. */
static void element(double kt, double mun, int dim, const double *u, const double *wc, double *f,
                    double *w, double *t)
{
    double d[2] = {u[0] - wc[0], dim == 2 ? u[1] - wc[1] : 0.0},
           ui[2] = {u[0], dim == 2 ? u[1] : 0.0};
    double r = norm(d, dim);
    if (kt * r <= mun) { /* stick: f = kt d, tangent kt I */
        for (int a = 0; a < dim; a++) {
            f[a] = kt * d[a];
            w[a] = wc[a];
        }
        if (t != NULL)
            for (int a = 0; a < dim * dim; a++)
                t[a] = (a % (dim + 1) == 0) ? kt : 0.0;
        return;
    }
    double nrm[2] = {d[0] / r, d[1] / r}, s = mun / r;
    for (int a = 0; a < dim; a++) {
        f[a] = mun * nrm[a];
        w[a] = ui[a] - f[a] / kt;
    }
    if (t != NULL) /* kt (mun/|f_tr|)(I - n n^T) = (mun/|d|)(I - n n^T); 0 in 1-D */
        for (int a = 0; a < dim; a++)
            for (int b = 0; b < dim; b++)
                t[dim * a + b] = dim == 1 ? 0.0 : s * ((a == b) - nrm[a] * nrm[b]);
}

/* Whether element i's u is finite and |u - w_c| too; writes the message if not. */
static int check_u(fricreg_jenkins *j, size_t i, const double *u)
{
    int dim = j->dim;
    const double *wc = &j->w_c[(size_t)dim * i];
    double d[2] = {0.0, 0.0};
    for (int a = 0; a < dim; a++) {
        size_t k = (size_t)dim * i + (size_t)a;
        if (!isfinite(u[a]))
            return fr_fail(j, FRICREG_ENONFINITE, "trial: u[%zu] = %g", k, u[a]);
        d[a] = u[a] - wc[a];
    }
    if (!isfinite(norm(d, dim)))
        return fr_fail(j, FRICREG_ENONFINITE,
                       "trial: element %zu's u - w overflows (u[%zu] = %g, w = %g)", i,
                       (size_t)dim * i, u[0], wc[0]);
    return FRICREG_OK;
}

int fricreg_jenkins_trial(fricreg_jenkins *j, size_t n, const double u[], double f[], double dfdu[])
{
    if (j == NULL)
        return FRICREG_ENULL;
    if (u == NULL || f == NULL)
        return fr_fail(j, FRICREG_ENULL, "trial: %s is NULL", u == NULL ? "u" : "f");
    if (check_n(j, "trial", n) != FRICREG_OK)
        return FRICREG_ESIZE;
    size_t dim = (size_t)j->dim;
    for (size_t i = 0; i < n; i++)
        if (check_u(j, i, &u[dim * i]) != FRICREG_OK)
            return j->err.code;
    for (size_t i = 0; i < n; i++)
        element(j->kt[i], j->mun[i], j->dim, &u[dim * i], &j->w_c[dim * i], &f[dim * i],
                &j->w_tr[dim * i], dfdu ? &dfdu[dim * dim * i] : NULL);
    return FRICREG_OK;
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

int fricreg_jenkins_errcode(const fricreg_jenkins *j)
{
    return j ? j->err.code : FRICREG_OK;
}

const char *fricreg_jenkins_errmsg(const fricreg_jenkins *j)
{
    return j ? j->err.msg : "NULL Jenkins elements";
}

size_t fricreg_jenkins_errmsg_copy(const fricreg_jenkins *j, char *buf, size_t len)
{
    return fr_error_copy(fricreg_jenkins_errmsg(j), buf, len);
}
