/* SPDX-License-Identifier: GPL-3.0-or-later */
/* line_search.c — the backtracking line search (line_search.h). */
#include "line_search.h"

#include "fricreg.h"

int fr_line_search(const struct fr_line_search *ls, double alpha0, fr_line_trial trial, void *user,
                   int *accepted)
{
    double alpha = alpha0;
    *accepted = 0;
    for (int k = 0; k <= ls->max_halvings; k++) {
        int status = trial(user, alpha, accepted);
        if (status != FRICREG_OK || *accepted)
            return status;
        if (ls->rejected != NULL)
            ++*ls->rejected;
        alpha *= 0.5;
    }
    return FRICREG_OK;
}

int fr_armijo_decrease(const struct fr_line_search *ls, double phi0, double phi_t, double alpha)
{
    return phi_t <= (1.0 - ls->armijo * alpha) * phi0;
}

int fr_armijo_holds(const struct fr_line_search *ls, double change, double slope)
{
    return slope < 0.0 && change <= ls->armijo * slope;
}
