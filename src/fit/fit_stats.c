/* SPDX-License-Identifier: GPL-3.0-or-later */
/* fit_stats.c — what a fit reports at its solution (fit_stats.h): the covariance from the
 * singular value decomposition of the Jacobian in theta, J = U S V^T (LAPACK's dgesvd, its
 * workspace on fricreg's memory: GSL's SV_decomp allocates unchecked inside), as V S^-2 V^T
 * (scaled by the residual variance without deviations), mapped to the parameters by
 * dp/dtheta; the 95 % intervals in theta mapped back; the identifiability as S and V. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include <gsl/gsl_blas.h>
#include <gsl/gsl_cdf.h>

#include "base/gsl_mem.h"
#include "base/lapack.h"
#include "fit_stats.h"
#include "params.h"

#define RANK_RTOL 1e-12    /* smallest over largest singular value: rank deficient below */
#define AT_BOUND_RTOL 1e-6 /* a bound this much closer than from the first start: reached */

/* FRICREG_EINVAL if a free parameter ended at one of its bounds: its distance to the bound
 * shrank below AT_BOUND_RTOL of the first start's (the data push it past the bound). */
static int check_bounds(struct fr_fit_problem *pb, const double p[], const double p0[])
{
    for (size_t k = 0; k < pb->nfree; k++) {
        int j = pb->idx[k];
        const struct fr_fit_param *q = &pb->fit->par[j];
        int low = isfinite(q->lo) && p[j] - q->lo <= AT_BOUND_RTOL * (p0[j] - q->lo);
        int high = isfinite(q->hi) && q->hi - p[j] <= AT_BOUND_RTOL * (q->hi - p0[j]);
        if (low || high)
            return fr_fail(pb->fit, FRICREG_EINVAL,
                           "run: %s ended at its %s bound %g: the levels push it beyond; fix "
                           "it there or widen the bound (no fit is reported)",
                           pb->fit->model->name(pb->fit, j), low ? "lower" : "upper",
                           low ? q->lo : q->hi);
    }
    return FRICREG_OK;
}

/* The message of a rank-deficient Jacobian: the combination of its last singular vector. */
static int rank_deficient(struct fr_fit_problem *pb, const double V[], double ratio)
{
    size_t m = pb->nfree, last = m - 1;
    char combo[160] = "";
    size_t used = 0;
    for (size_t k = 0; k < m && used < sizeof combo - 24; k++) {
        double c = V[last * m + k];
        if (fabs(c) >= 0.1)
            used += (size_t)snprintf(combo + used, sizeof combo - used, " %+.2f %s", c,
                                     pb->fit->model->name(pb->fit, pb->idx[k]));
    }
    return fr_fail(pb->fit, FRICREG_ESINGULAR,
                   "run: the levels do not determine the parameters (singular value ratio "
                   "%.1e): the combination%s of their thetas is free; fix one of them",
                   ratio, combo);
}

/* The singular values S[m] of J (rows x m, row major), largest first, and its right singular
 * vectors, V[k m + a] the a-th entry of the k-th: LAPACK's SVD of J^T (column major, m x rows,
 * the same memory), whose left vectors are J's right ones. J is overwritten. Returns 0, or -1
 * out of memory, or LAPACK's info. */
static int svd(gsl_matrix *J, double S[], double V[])
{
    int m = (int)J->size2, rows = (int)J->size1, one = 1, query = -1, info = 0;
    double best = 0.0, vt;
    dgesvd_("A", "N", &m, &rows, J->data, &m, S, V, &m, &vt, &one, &best, &query, &info, 1, 1);
    int lwork = info == 0 ? (int)best : 5 * (m + rows);
    double *work = malloc((size_t)lwork * sizeof *work);
    if (work == NULL)
        return -1;
    dgesvd_("A", "N", &m, &rows, J->data, &m, S, V, &m, &vt, &one, work, &lwork, &info, 1, 1);
    free(work);
    return info;
}

/* The covariance and intervals from V and S (theta's covariance scaled by `scale`). */
static void covariance(struct fr_fit_problem *pb, const double theta[], const double V[],
                       const double S[], double scale, struct fr_fit_result *res)
{
    size_t m = pb->nfree, np = pb->fit->np;
    double p[FR_FIT_MAXP], dp[FR_FIT_MAXP], ct[FR_FIT_MAXP * FR_FIT_MAXP] = {0};
    fr_fit_params_at(pb, theta, p, dp);
    for (size_t a = 0; a < m; a++)
        for (size_t b = 0; b <= a; b++) { /* one triangle, mirrored: symmetric to the bit */
            for (size_t k = 0; k < m; k++)
                ct[a * m + b] += scale * V[k * m + a] * V[k * m + b] / (S[k] * S[k]);
            ct[b * m + a] = ct[a * m + b];
        }
    for (size_t j = 0; j < np; j++) {
        res->p[j] = res->lower[j] = res->upper[j] = p[j];
        for (size_t i = 0; i < np; i++)
            res->cov[j * np + i] = 0.0;
    }
    for (size_t a = 0; a < m; a++) {
        size_t ja = (size_t)pb->idx[a];
        for (size_t b = 0; b < m; b++)
            res->cov[ja * np + (size_t)pb->idx[b]] = dp[a] * dp[b] * ct[a * m + b];
        const struct fr_fit_param *q = &pb->fit->par[ja];
        double half = res->quantile * sqrt(ct[a * m + a]), d;
        double x = fr_fit_from_theta(theta[a] - half, q->lo, q->hi, &d);
        double y = fr_fit_from_theta(theta[a] + half, q->lo, q->hi, &d);
        res->lower[ja] = fmin(x, y);
        res->upper[ja] = fmax(x, y);
    }
}

static void identifiability(struct fr_fit_problem *pb, const double V[], const double S[],
                            struct fr_fit_result *res)
{
    size_t m = pb->nfree, np = pb->fit->np;
    for (size_t k = 0; k < np; k++) {
        res->sv[k] = k < m ? S[k] : 0.0;
        for (size_t j = 0; j < np; j++)
            res->vectors[k * np + j] = 0.0;
    }
    for (size_t k = 0; k < m; k++)
        for (size_t a = 0; a < m; a++)
            res->vectors[k * np + (size_t)pb->idx[a]] = V[k * m + a];
}

/* Everything past the residuals and the Jacobian (in J, overwritten) at theta. */
static int report(struct fr_fit_problem *pb, const double theta[], const double theta0[],
                  const gsl_vector *r, gsl_matrix *J)
{
    fricreg_fit *fit = pb->fit;
    struct fr_fit_result res = {0};
    double p[FR_FIT_MAXP], p0[FR_FIT_MAXP], dp[FR_FIT_MAXP], S[FR_FIT_MAXP];
    double V[FR_FIT_MAXP * FR_FIT_MAXP];
    fr_fit_params_at(pb, theta, p, dp);
    fr_fit_params_at(pb, theta0, p0, dp);
    int st = check_bounds(pb, p, p0);
    if (st != FRICREG_OK)
        return st;
    size_t m = pb->nfree, dof = 2 * fit->n - m;
    int info = svd(J, S, V);
    if (info < 0)
        return fr_fail(fit, FRICREG_ENOMEM, "run: out of memory for the SVD's workspace");
    double ratio = S[m - 1] / S[0];
    if (info > 0 || !(ratio > RANK_RTOL))
        return rank_deficient(pb, V, ratio);
    gsl_blas_ddot(r, r, &res.cost);
    res.variance = dof > 0 ? res.cost / (double)dof : 0.0;
    res.condition = 1.0 / ratio;
    res.nfree = m;
    res.quantile = fit->has_sd ? gsl_cdf_ugaussian_Pinv(0.975)
                               : gsl_cdf_tdist_Pinv(0.975, (double)dof);
    covariance(pb, theta, V, S, fit->has_sd ? 1.0 : res.variance, &res);
    identifiability(pb, V, S, &res);
    for (size_t i = 0; i < fit->n; i++) {
        fit->res_freq[i] = gsl_vector_get(r, i);
        fit->res_zeta[i] = gsl_vector_get(r, fit->n + i);
    }
    fit->result = res;
    return FRICREG_OK;
}

int fr_fit_finish(struct fr_fit_problem *pb, const double theta[], const double theta0[])
{
    size_t rows = 2 * pb->fit->n, m = pb->nfree;
    gsl_vector *r = fr_gsl_vector_new(rows);
    gsl_matrix *J = fr_gsl_matrix_new(rows, m);
    int st;
    if (!r || !J)
        st = fr_fail(pb->fit, FRICREG_ENOMEM, "run: out of memory for the fit's statistics");
    else if (fr_fit_residuals(pb, theta, r, J) != 0)
        st = fr_fail(pb->fit, FRICREG_EINVAL, "run: the model cannot be evaluated at the fit");
    else
        st = report(pb, theta, theta0, r, J);
    free(r);
    free(J);
    return st;
}
