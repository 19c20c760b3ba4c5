/* SPDX-License-Identifier: GPL-3.0-or-later */
/* rows.c — the buffers of the driver whose sizes follow the rows of J: allocated all or none,
 * installed in place of the old ones, and cut into the views the kernels use (hb_internal.h's
 * layout). A file below the life cycle (hb.c) and the element setters (elements.c), which
 * both size them. */
#include <stdlib.h>
#include <string.h>

#include "rows.h"
#include "base/free_all.h"

static void *alloc_doubles(size_t count)
{
    return malloc((count ? count : 1) * sizeof(double));
}

/* Frees b and empties it (a second call does nothing). */
void fr_hb_rows_free(struct fr_hb_rows *b)
{
    FR_FREE_ALL(b->J, b->Y, b->Z, b->G, b->fq, b->piv2);
    *b = (struct fr_hb_rows){0};
}

int fr_hb_rows_alloc(const fricreg_hb *hb, size_t cap, size_t sq, struct fr_hb_rows *b)
{
    size_t n = hb->n, H1 = (size_t)hb->H + 1, nc = hb->nc, nq = cap * nc;
    *b = (struct fr_hb_rows){0};
    b->J = alloc_doubles(cap * n + 2 * n);
    b->Y = alloc_doubles(2 * H1 * n * (cap + 1));
    b->Z = alloc_doubles(2 * n * (cap + 1) + 2 * n);
    b->G = alloc_doubles(4 * H1 * cap * cap + 4 * H1 * cap);
    /* fq, jq, A, five of Newton's vectors (R .. qt), the continuation's room, qsol, qjac */
    b->fq = alloc_doubles(nq + sq * nc * nc + (nq + 1) * (nq + 1) +
                          (5 + FR_HB_CONT_VECTORS) * (nq + 1) + 2 * nq);
    b->piv2 = malloc((nq + 1) * sizeof *b->piv2);
    if (!b->J || !b->Y || !b->Z || !b->G || !b->fq || !b->piv2) {
        fr_hb_rows_free(b);
        return FRICREG_ENOMEM;
    }
    memset(b->J, 0, (cap * n + 2 * n) * sizeof(double));
    return FRICREG_OK;
}

/* Installs b (room for cap rows, sq units of nc² of Jacobian blocks), J's rows held and the
 * excitation carried over from the buffers it replaces, if any. */
void fr_hb_rows_install(fricreg_hb *hb, size_t cap, size_t sq, struct fr_hb_rows *b)
{
    size_t n = hb->n;
    if (hb->J != NULL) {
        memcpy(b->J, hb->J, hb->m * n * sizeof(double));
        memcpy(b->J + cap * n, hb->pc, 2 * n * sizeof(double));
    }
    FR_FREE_ALL(hb->J, hb->Y, hb->Z, hb->G, hb->fq, hb->piv2);
    hb->J = b->J;
    hb->Y = b->Y;
    hb->Z = b->Z;
    hb->G = b->G;
    hb->fq = b->fq;
    hb->piv2 = b->piv2;
    hb->rows_cap = cap;
    hb->sq_cap = sq;
    hb->pc = hb->J + cap * n;
    hb->ps = hb->pc + n;
}

/* The views into the buffers for the rows of the elements held (m = erow[count], nq = m nc). */
void fr_hb_rows_set(fricreg_hb *hb)
{
    size_t n = hb->n, H1 = (size_t)hb->H + 1, nc = hb->nc;
    size_t m = hb->erow[hb->count], nq = m * nc;
    hb->m = m;
    hb->nq = nq;
    hb->colw = hb->Z + 2 * n * (m + 1);
    hb->ql = hb->G + 2 * H1 * m * m;
    hb->dG = hb->ql + 2 * H1 * m;
    hb->dql = hb->dG + 2 * H1 * m * m;
    hb->jq = hb->fq + nq;
    hb->A = hb->jq + hb->ejq[hb->count] * nc * nc;
    hb->R = hb->A + (nq + 1) * (nq + 1);
    hb->rw = hb->R + (nq + 1);
    hb->dy = hb->rw + (nq + 1);
    hb->qw = hb->dy + (nq + 1);
    hb->qt = hb->qw + (nq + 1);
    hb->cont = hb->qt + (nq + 1);
    hb->qsol = hb->cont + FR_HB_CONT_VECTORS * (nq + 1);
    hb->qjac = hb->qsol + nq;
}
