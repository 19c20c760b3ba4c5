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
