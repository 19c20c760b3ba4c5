/* SPDX-License-Identifier: GPL-3.0-or-later */
/* fit_internal.h — the layout of a fit (fricreg_fit.h): the problem its setters make, and the
 * result of its last successful run. Included only inside fit/. */
#ifndef FRICREG_FIT_INTERNAL_H
#define FRICREG_FIT_INTERNAL_H

#include <stddef.h>

#include <gsl/gsl_roots.h>

#include "fricreg_fit.h"
#include "fricreg_hb.h"
#include "base/error.h"

#define FR_FIT_NP FRICREG_FIT_NPARAMS /* the modal Iwan model's parameters */
#define FR_FIT_MAXP 16                /* any model's parameters at most */

struct fr_fit_model;

/* An HB model's description (fricreg_fit_set_model_hb): which of the driver's values are its
 * parameters, and the sensor. */
#define FR_FIT_NAME 48 /* a parameter's name, its terminating 0 included */

struct fr_fit_hb {
    fricreg_hb *hb; /* borrowed */
    size_t mode;
    int damping;               /* enum fricreg_hb_nma_damping */
    int kind[FR_FIT_MAXP + 1]; /* the parameters', then AMPLITUDE */
    size_t first[FR_FIT_MAXP + 1], count[FR_FIT_MAXP + 1], index[FR_FIT_MAXP + 1];
    double value0[FR_FIT_MAXP]; /* an element's value at the set-up */
    char names[FR_FIT_MAXP][FR_FIT_NAME];
    int has_dof; /* the levels' amplitudes at dof (else modal, times |s|) */
    size_t dof, ndof, nc;
};

struct fr_fit_param {
    int free;
    double value;  /* a fixed parameter's value, or a free one's start (NaN: from the levels) */
    double lo, hi; /* a free one's bounds */
};

/* What a successful run found; valid while have_fit. */
struct fr_fit_result {
    double p[FR_FIT_MAXP];
    double cov[FR_FIT_MAXP * FR_FIT_MAXP]; /* np x np, row major */
    double lower[FR_FIT_MAXP], upper[FR_FIT_MAXP];
    double sv[FR_FIT_MAXP], vectors[FR_FIT_MAXP * FR_FIT_MAXP]; /* np x np */
    double cost, variance, quantile, condition;
    size_t nfev, njev, iterations, best_start, converged, nfree, nmodel, marches;
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
    const struct fr_fit_model *model; /* model.h: the modal Iwan's or hb_model.c's */
    struct fr_fit_hb *hb;             /* the HB model's description (hb_model.h), or NULL */
    size_t np;                        /* the model's parameters, <= FR_FIT_MAXP */
    struct fr_fit_param par[FR_FIT_MAXP];
    size_t nstarts;
    size_t marches;   /* backbone marches (fricreg_hb_nma_at calls) since the count was reset */
    char reason[256]; /* why the model's last evaluation failed */
    gsl_root_fsolver *brent;
    int have_fit;
    struct fr_fit_result result;
};

#endif
