/* SPDX-License-Identifier: GPL-3.0-or-later */
/* mex_fit.h — the gateway's commands on a fit (fricreg_fit.h), held in the handle table.
 * Each takes the arguments after the command string. */
#ifndef FRICREG_MEX_FIT_H
#define FRICREG_MEX_FIT_H

#include "mex.h"

/** The signature of every gateway command: the arguments after the command string. */
typedef void mex_command(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[]);

mex_command mexfit_create, mexfit_set_sensor, mexfit_set_levels, mexfit_set_deviations,
    mexfit_set_free, mexfit_set_fixed, mexfit_set_starts, mexfit_run, mexfit_params,
    mexfit_covariance, mexfit_identifiability, mexfit_residuals, mexfit_value, mexfit_quantile,
    mexfit_eval;

#endif
