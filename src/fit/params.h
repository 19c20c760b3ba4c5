/* SPDX-License-Identifier: GPL-3.0-or-later */
/* params.h — the modal Iwan model's parameters: their names and ranges (fricreg_fit.h's enum
 * fricreg_fit_param), and the transformation that keeps a free one inside its bounds. */
#ifndef FRICREG_FIT_PARAMS_H
#define FRICREG_FIT_PARAMS_H

/* The parameter's name as docs and messages write it ("F_S", "chi", ...). */
const char *fr_fit_param_name(int which);

/* The parameter's own lower limit: -1 for chi, else 0. */
double fr_fit_param_floor(int which);

/* 1 if v is a value the model takes for the parameter (F_S, K_T > 0; chi > -1; beta, zeta0,
 * K0 >= 0; finite), else 0. */
int fr_fit_param_in_range(int which, double v);

/* 1 if every one of p[FRICREG_FIT_NPARAMS] is in range, else 0 (*bad: the first that is not). */
int fr_fit_params_in_range(const double p[], int *bad);

/* The parameter of the transformed coordinate theta, inside (lo, hi) (either infinite):
 * lo + exp(theta), hi - exp(theta), lo + (hi - lo)/(1 + exp(-theta)) or theta itself;
 * *dp_dtheta its derivative. */
double fr_fit_from_theta(double theta, double lo, double hi, double *dp_dtheta);

/* theta of p, lo < p < hi. */
double fr_fit_to_theta(double p, double lo, double hi);

#endif
