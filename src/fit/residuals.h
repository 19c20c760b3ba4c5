/* SPDX-License-Identifier: GPL-3.0-or-later */
/* residuals.h — a fit's weighted residuals and their exact Jacobian in the transformed free
 * parameters theta (fricreg_fit.h, "The fit"), as GSL's least squares and the statistics
 * read them. */
#ifndef FRICREG_FIT_RESIDUALS_H
#define FRICREG_FIT_RESIDUALS_H

#include <gsl/gsl_matrix.h>
#include <gsl/gsl_vector.h>

#include "model.h"

/* The free parameters of a run: which they are and their bounds, from the fit's settings; and
 * the model at the levels at the last theta evaluated. GSL asks the residuals and then the
 * Jacobian at one point, and one evaluation of a backbone model gives both: the second is read
 * from this cache (keyed by theta's bits). */
struct fr_fit_problem {
    fricreg_fit *fit;
    int idx[FR_FIT_MAXP]; /* the k-th free parameter is idx[k] */
    size_t nfree;
    size_t bad_level; /* the last level out of reach, where unreachable */
    int unreachable;
    struct fr_fit_levels lv; /* the cache: the model at the levels at theta */
    double theta[FR_FIT_MAXP];
    int cached;    /* lv holds the model at theta */
    double *block; /* lv's memory and guess[n] */
    double *guess; /* the levels' modal amplitudes of the last evaluation (NaN: none) */
    size_t nmodel; /* the model's evaluations (the cache's misses) */
};

/* The free parameters of fit, in the model's order, and the cache (empty). Returns
 * FRICREG_OK or FRICREG_ENOMEM (recorded in the fit). */
int fr_fit_problem_init(struct fr_fit_problem *pb, fricreg_fit *fit);

/* Releases the cache's memory. */
void fr_fit_problem_free(struct fr_fit_problem *pb);

/* Every parameter p[np] at theta[nfree] (the fixed as fixed), and dp/dtheta[nfree]. */
void fr_fit_params_at(const struct fr_fit_problem *pb, const double theta[], double p[],
                      double dp_dtheta[]);

/* The residuals r[2n] (the frequencies' n, then the damping ratios') and, where J is not NULL,
 * J[2n x nfree] = dr/dtheta, at theta. Returns 0, or -1 where the model cannot be evaluated
 * (a parameter out of range, a residual or derivative not finite, or a level out of reach:
 * pb->unreachable, pb->bad_level). */
int fr_fit_residuals(struct fr_fit_problem *pb, const double theta[], gsl_vector *r, gsl_matrix *J);

#endif
