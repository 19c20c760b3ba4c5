/* SPDX-License-Identifier: GPL-3.0-or-later */
/* sparse_factor.c — CHOLMOD set up as fricreg needs it (sparse_factor.h). */
#include <string.h>

#include "fricreg.h"
#include "sparse_factor.h"

int fr_cholmod_start(cholmod_common *c)
{
    memset(c, 0, sizeof *c);
    if (!cholmod_l_start(c))
        return FRICREG_ENOMEM;
    c->print = 0;            /* CHOLMOD prints nothing (its default, 3, prints errors) */
    c->error_handler = NULL; /* failures come back in c->status */
    c->try_catch = 0;
    c->final_ll = 1; /* L L^T: a matrix that is not positive definite is reported as such
                      * (CHOLMOD_NOT_POSDEF), where an L D L^T factor takes it silently */
    return FRICREG_OK;
}

void fr_cholmod_finish(cholmod_common *c)
{
    cholmod_l_finish(c); /* a zeroed workspace fails CHOLMOD's own check: nothing freed */
    memset(c, 0, sizeof *c);
}

int fr_cholmod_status(int cholmod_status)
{
    switch (cholmod_status) {
    case CHOLMOD_NOT_POSDEF: return FRICREG_ENOTPSD;
    case CHOLMOD_OUT_OF_MEMORY:
    case CHOLMOD_TOO_LARGE: return FRICREG_ENOMEM;
    default: return cholmod_status >= CHOLMOD_OK ? FRICREG_OK : FRICREG_EINVAL;
    }
}

void fr_cholmod_keep_workspace(cholmod_dense *Y)
{
    if (Y != NULL && Y->nzmax >= 4 * Y->ncol && Y->nrow < 4) {
        Y->nrow = 4;
        Y->d = 4;
    }
}

void fr_cholmod_ordering(cholmod_common *c, int ordering, int simplicial)
{
    c->nmethods = 1;
    c->method[0].ordering = ordering;
    c->postorder = ordering != CHOLMOD_NATURAL;
    c->supernodal = simplicial ? CHOLMOD_SIMPLICIAL : CHOLMOD_AUTO;
}
