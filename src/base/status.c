/* SPDX-License-Identifier: GPL-3.0-or-later */
/* status.c — fixed text for each status code, and the library version. */
#include "fricreg.h"

const char *fricreg_strerror(int status)
{
    switch (status) {
    case FRICREG_OK: return "success";
    case FRICREG_ENULL: return "a required pointer argument is NULL";
    case FRICREG_EINVAL: return "an argument is out of its valid range";
    case FRICREG_ENONFINITE: return "an input number is NaN or infinite";
    case FRICREG_ESIZE: return "array length does not match the context";
    case FRICREG_ENOMEM: return "out of memory";
    case FRICREG_ENOTSYM: return "coupling matrix is not symmetric";
    case FRICREG_ENOTPSD: return "coupling matrix is not positive semidefinite";
    case FRICREG_ESINGULAR: return "near-stick block W_SS is singular: f_eq is not unique";
    case FRICREG_ESTEP: return "step too large for the stability of the explicit stepper";
    case FRICREG_EDIVERGED: return "integrated state diverged (non-finite or beyond 1e100)";
    case FRICREG_EINTEGRATOR: return "ODE integrator failed";
    case FRICREG_EWORK: return "the run reached its bound on steps before its end";
    default: return "unknown fricreg status code";
    }
}

int fricreg_version_number(void)
{
    return FRICREG_VERSION_NUMBER;
}

const char *fricreg_version(void)
{
    return FRICREG_VERSION_STRING;
}
