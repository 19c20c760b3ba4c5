/* SPDX-License-Identifier: GPL-3.0-or-later */
/* newton_loop.c — the one Newton iteration of the library's implicit problems (newton_loop.h). */
#include <math.h>

#include "fricreg.h"
#include "newton_loop.h"

/* Converged: after an iteration, by the caller's test or rinf not above tol (a NaN measure
 * ends the iteration too: the caller judges it); before any, only (a structure's step) from an
 * exact 0. */
static int converged(const struct fr_newton_loop *nl, double rinf, int done)
{
    if (done == 0)
        return rinf == 0.0 && !nl->at_least_one;
    return nl->converged != NULL ? nl->converged(nl->user) : !(rinf > nl->tol);
}

int fr_newton_loop_run(const struct fr_newton_loop *nl, double *phi, double *rinf, int *iters)
{
    for (int done = 0; !converged(nl, *rinf, done) && isfinite(*phi); done++) {
        int status = nl->progress != NULL ? nl->progress(nl->user, *rinf) : FRICREG_OK;
        if (status != FRICREG_OK || *iters >= nl->max_iter)
            return status;
        if ((status = nl->direction(nl->user)) != FRICREG_OK)
            return status; /* the iteration ends on this iterate: a failure the caller counts */
        ++*iters;
        int accepted = 0;
        if ((status = nl->search(nl->user, phi, rinf, &accepted)) != FRICREG_OK)
            return status;
        if (!accepted) {
            if (nl->restore != NULL)
                nl->restore(nl->user, phi, rinf); /* back to the iterate: the best point */
            break;
        }
    }
    return FRICREG_OK;
}
