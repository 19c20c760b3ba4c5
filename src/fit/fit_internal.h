/* SPDX-License-Identifier: GPL-3.0-or-later */
/* fit_internal.h — the layout of a fit (fricreg_fit.h): the problem its setters make, and the
 * result of its last successful run. Included only inside fit/. */
#ifndef FRICREG_FIT_INTERNAL_H
#define FRICREG_FIT_INTERNAL_H

#include <stddef.h>

#include <gsl/gsl_roots.h>

#include "fricreg_fit.h"
#include "base/error.h"

#define FR_FIT_NP FRICREG_FIT_NPARAMS

struct fr_fit_param {
    int free;
    double value;  /* a fixed parameter's value, or a free one's start (NaN: from the levels) */
    double lo, hi; /* a free one's bounds */
};

/* What a successful run found; valid while have_fit. */
struct fr_fit_result {
    double p[FR_FIT_NP];
    double cov[FR_FIT_NP * FR_FIT_NP];
    double lower[FR_FIT_NP], upper[FR_FIT_NP];
    double sv[FR_FIT_NP], vectors[FR_FIT_NP * FR_FIT_NP];
    double cost, variance, quantile, condition;
    size_t nfev, njev, iterations, best_start, converged, nfree;
};

struct fricreg_fit {
    struct fr_error err;
    size_t n;                    /* levels */
    int kind;                    /* enum fricreg_fit_amplitude */
    double *amp, *freq, *zeta;   /* the levels, n each, in one block with the next four */
    double *sd_freq, *sd_zeta;   /* their deviations where has_sd */
    double *res_freq, *res_zeta; /* the fit's weighted residuals */
    int has_sd;
    double sensor;
    struct fr_fit_param par[FR_FIT_NP];
    size_t nstarts;
    gsl_root_fsolver *brent;
    int have_fit;
    struct fr_fit_result result;
};

#endif
