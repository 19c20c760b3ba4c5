/* SPDX-License-Identifier: GPL-3.0-or-later */
/* newton_loop.c — the one Newton iteration of a structure's implicit step (newton_loop.h). */
#include <math.h>

#include "fricreg.h"
#include "newton_loop.h"

int fr_newton_loop_run(const struct fr_newton_loop *nl, double *phi, double *rinf, int *iters)
{
    int done = 0;
    while (*rinf != 0.0 && (done == 0 || *rinf > nl->tol) && *iters < nl->max_iter &&
           isfinite(*phi)) {
        int status = nl->direction(nl->user);
        if (status != FRICREG_OK)
            return status; /* the step ends on this iterate: a failure the caller counts */
        ++*iters;
        ++done;
        if (!nl->search(nl->user, phi, rinf)) {
            nl->restore(nl->user, phi, rinf); /* back to the iterate: the best point */
            break;
        }
    }
    return FRICREG_OK;
}
