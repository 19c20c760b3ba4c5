/* SPDX-License-Identifier: GPL-3.0-or-later */
/* disk_coupled.c — a coupled W's state in a 2-D context: its blocks, the reduced Hessian's
 * factor, the work arrays of the sweeps and of Newton's method (disk_ctx_internal.h). */
#include <stdlib.h>
#include <string.h>

#include "disk_ctx_internal.h"

void fr_disk_coupled_free(struct fr_disk_coupled *cpl)
{
    if (cpl == NULL)
        return;
    fr_disk_factor_free(&cpl->F);
    fr_disk_coupling_free(&cpl->w);
    free(cpl->acc), free(cpl->grad), free(cpl->fl), free(cpl->laml), free(cpl->onl);
    free(cpl->nkind), free(cpl->nrm), free(cpl->step), free(cpl->trial), free(cpl->wd);
    free(cpl);
}

struct fr_disk_coupled *fr_disk_coupled_new(size_t m)
{
    struct fr_disk_coupled *cpl = calloc(1, sizeof *cpl);
    if (cpl == NULL)
        return NULL;
    size_t v = 2 * m * sizeof(double);
    cpl->acc = malloc(v), cpl->grad = malloc(v), cpl->fl = malloc(v);
    cpl->nrm = malloc(v), cpl->step = malloc(v), cpl->trial = malloc(v), cpl->wd = malloc(v);
    cpl->laml = malloc(m * sizeof *cpl->laml);
    cpl->onl = malloc(m), cpl->nkind = malloc(m);
    if (!cpl->acc || !cpl->grad || !cpl->fl || !cpl->nrm || !cpl->step || !cpl->trial || !cpl->wd ||
        !cpl->laml || !cpl->onl || !cpl->nkind) {
        fr_disk_coupled_free(cpl);
        return NULL;
    }
    return cpl;
}
