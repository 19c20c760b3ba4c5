/* SPDX-License-Identifier: GPL-3.0-or-later */
/* residuals.c — a fit's weighted residuals and their exact Jacobian in theta (residuals.h), on
 * the model's levels (model.h), cached by theta. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "params.h"
#include "residuals.h"

int fr_fit_problem_init(struct fr_fit_problem *pb, fricreg_fit *fit)
{
    pb->fit = fit;
    pb->nfree = 0;
    pb->unreachable = 0;
    pb->bad_level = 0;
    pb->cached = 0;
    pb->nmodel = 0;
    for (size_t j = 0; j < fit->np; j++)
        if (fit->par[j].free)
            pb->idx[pb->nfree++] = (int)j;
    size_t n = fit->n > 0 ? fit->n : 1;
    pb->block = fr_fit_levels_alloc(n, fit->np, &pb->lv, &pb->guess);
    if (pb->block == NULL)
        return fr_fail(fit, FRICREG_ENOMEM, "run: out of memory for the model at %zu levels", n);
    return FRICREG_OK;
}

void fr_fit_problem_free(struct fr_fit_problem *pb)
{
    free(pb->block);
    pb->block = NULL;
}

void fr_fit_params_at(const struct fr_fit_problem *pb, const double theta[], double p[],
                      double dp_dtheta[])
{
    for (size_t j = 0; j < pb->fit->np; j++)
        p[j] = pb->fit->par[j].value;
    for (size_t k = 0; k < pb->nfree; k++) {
        const struct fr_fit_param *q = &pb->fit->par[pb->idx[k]];
        p[pb->idx[k]] = fr_fit_from_theta(theta[k], q->lo, q->hi, &dp_dtheta[k]);
    }
}

/* The model at the levels at p into pb->lv, unless it holds theta's already: 0, or -1. */
static int model_at(struct fr_fit_problem *pb, const double theta[], const double p[])
{
    fricreg_fit *fit = pb->fit;
    size_t bytes = pb->nfree * sizeof *theta;
    if (pb->cached && memcmp(pb->theta, theta, bytes) == 0)
        return 0;
    pb->cached = 0;
    for (size_t j = 0; j < fit->np; j++)
        if (!fit->model->in_range((int)j, p[j]))
            return -1;
    pb->nmodel++;
    size_t bad = FR_FIT_REACHED;
    int st = fit->model->eval(fit, p, fit->kind, fit->n, fit->amp, pb->guess, &pb->lv, &bad);
    if (st != FRICREG_OK) {
        if (bad != FR_FIT_REACHED) {
            pb->unreachable = 1;
            pb->bad_level = bad;
        }
        return -1;
    }
    memcpy(pb->theta, theta, bytes);
    pb->cached = 1;
    return 0;
}

int fr_fit_residuals(struct fr_fit_problem *pb, const double theta[], gsl_vector *r, gsl_matrix *J)
{
    const fricreg_fit *fit = pb->fit;
    double p[FR_FIT_MAXP], dp[FR_FIT_MAXP];
    fr_fit_params_at(pb, theta, p, dp);
    if (model_at(pb, theta, p) != 0)
        return -1;
    size_t n = fit->n, np = fit->np;
    const struct fr_fit_levels *m = &pb->lv;
    for (size_t i = 0; i < n; i++) {
        double sf = fit->has_sd ? fit->sd_freq[i] : fit->freq[i];
        double sz = fit->has_sd ? fit->sd_zeta[i] : fit->zeta[i];
        double rf = (m->freq_hz[i] - fit->freq[i]) / sf, rz = (m->zeta[i] - fit->zeta[i]) / sz;
        if (!isfinite(rf) || !isfinite(rz)) /* parameters beyond what doubles hold */
            return -1;
        gsl_vector_set(r, i, rf);
        gsl_vector_set(r, n + i, rz);
        for (size_t k = 0; J != NULL && k < pb->nfree; k++) {
            size_t at = i * np + (size_t)pb->idx[k];
            double jf = m->dfreq[at] * dp[k] / sf, jz = m->dzeta[at] * dp[k] / sz;
            if (!isfinite(jf) || !isfinite(jz))
                return -1;
            gsl_matrix_set(J, i, k, jf);
            gsl_matrix_set(J, n + i, k, jz);
        }
    }
    return 0;
}
