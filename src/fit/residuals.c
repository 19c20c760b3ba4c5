/* SPDX-License-Identifier: GPL-3.0-or-later */
/* residuals.c — a fit's weighted residuals and their exact Jacobian in theta (residuals.h). */
#include <math.h>

#include "modal_iwan.h"
#include "params.h"
#include "residuals.h"

void fr_fit_problem_init(struct fr_fit_problem *pb, fricreg_fit *fit)
{
    pb->fit = fit;
    pb->nfree = 0;
    pb->unreachable = 0;
    pb->bad_level = 0;
    for (int j = 0; j < FR_FIT_NP; j++)
        if (fit->par[j].free)
            pb->idx[pb->nfree++] = j;
}

void fr_fit_params_at(const struct fr_fit_problem *pb, const double theta[], double p[],
                      double dp_dtheta[])
{
    for (int j = 0; j < FR_FIT_NP; j++)
        p[j] = pb->fit->par[j].value;
    for (size_t k = 0; k < pb->nfree; k++) {
        const struct fr_fit_param *q = &pb->fit->par[pb->idx[k]];
        p[pb->idx[k]] = fr_fit_from_theta(theta[k], q->lo, q->hi, &dp_dtheta[k]);
    }
}

int fr_fit_residuals(struct fr_fit_problem *pb, const double theta[], gsl_vector *r, gsl_matrix *J)
{
    const fricreg_fit *fit = pb->fit;
    double p[FR_FIT_NP], dp[FR_FIT_NP];
    int bad;
    fr_fit_params_at(pb, theta, p, dp);
    if (!fr_fit_params_in_range(p, &bad))
        return -1;
    size_t n = fit->n;
    for (size_t i = 0; i < n; i++) {
        struct fr_level_model m;
        if (fr_modal_iwan_level(p, fit->kind, fit->sensor, fit->amp[i], fit->brent, &m) != 0) {
            pb->unreachable = 1;
            pb->bad_level = i;
            return -1;
        }
        double sf = fit->has_sd ? fit->sd_freq[i] : fit->freq[i];
        double sz = fit->has_sd ? fit->sd_zeta[i] : fit->zeta[i];
        double rf = (m.freq_hz - fit->freq[i]) / sf, rz = (m.zeta - fit->zeta[i]) / sz;
        if (!isfinite(rf) || !isfinite(rz)) /* parameters beyond what doubles hold */
            return -1;
        gsl_vector_set(r, i, rf);
        gsl_vector_set(r, n + i, rz);
        for (size_t k = 0; J != NULL && k < pb->nfree; k++) {
            double jf = m.dfreq[pb->idx[k]] * dp[k] / sf, jz = m.dzeta[pb->idx[k]] * dp[k] / sz;
            if (!isfinite(jf) || !isfinite(jz))
                return -1;
            gsl_matrix_set(J, i, k, jf);
            gsl_matrix_set(J, n + i, k, jz);
        }
    }
    return 0;
}
