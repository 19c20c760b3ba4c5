/* SPDX-License-Identifier: GPL-3.0-or-later */
/* rows.c — the buffers of the driver whose sizes follow the rows of J: allocated all or none,
 * installed in place of the old ones, and cut into the views the kernels use (hb_internal.h's
 * layout). A file below the life cycle (hb.c) and the element setters (elements.c), which
 * both size them. */
#include <limits.h>
#include <stdint.h>
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

/* a b into *out; 0 when it overflows size_t */
static int mul(size_t a, size_t b, size_t *out)
{
    if (b != 0 && a > SIZE_MAX / b)
        return 0;
    *out = a * b;
    return 1;
}

/* a + b into *out; 0 when it overflows size_t */
static int add(size_t a, size_t b, size_t *out)
{
    if (a > SIZE_MAX - b)
        return 0;
    *out = a + b;
    return 1;
}

/* The doubles of J's, Y's, Z's, G's and fq's blocks (rows_alloc's) for cap rows and sq units of
 * nc², each also countable in bytes; 0 when one overflows size_t or Newton's order nq + 1
 * overflows LAPACK's int (lu.c): no memory could hold them. No fixed bound on the rows: the
 * memory is the limit (docs/hb_size.md). */
static int block_sizes(const fricreg_hb *hb, size_t cap, size_t sq, size_t count[5])
{
    size_t n = hb->n, H1 = (size_t)hb->H + 1, nc = hb->nc, nq, nq1, t, u;
    int ok = mul(cap, nc, &nq) && add(nq, 1, &nq1) && nq1 <= INT_MAX;
    /* J: cap n + 2 n */
    ok = ok && mul(cap, n, &t) && add(t, 2 * n, &count[0]);
    /* Y: 2 H1 n (cap + 1); Z: 2 n (cap + 2) (at least the 2 n complex of dynamic.c's
     * derivatives) + 2 n */
    ok = ok && add(cap, 1, &u) && mul(2 * H1 * n, u, &count[1]);
    ok = ok && add(cap, 3, &t) && mul(2 * n, t, &count[2]);
    /* G: 2 H1 cap² + 4 H1 cap (G, ql, dql) */
    ok = ok && mul(cap, cap, &t) && add(t, 2 * cap, &t) && mul(2 * H1, t, &count[3]);
    /* fq, jq, A, eleven of Newton's vectors (R .. refine), the continuation's room, qsol,
     * qjac: nq + sq nc² + (nq + 1)² + (11 + FR_HB_CONT_VECTORS) (nq + 1) + 2 nq */
    ok = ok && mul(sq, nc * nc, &t) && add(t, 3 * nq, &t) && mul(nq1, nq1, &u) && add(t, u, &t) &&
         mul(11 + FR_HB_CONT_VECTORS, nq1, &u) && add(t, u, &count[4]);
    for (int b = 0; ok && b < 5; b++)
        ok = mul(count[b] ? count[b] : 1, sizeof(double), &t);
    return ok && mul(nq1, sizeof(int), &t);
}

int fr_hb_rows_alloc(const fricreg_hb *hb, size_t cap, size_t sq, struct fr_hb_rows *b)
{
    size_t count[5];
    *b = (struct fr_hb_rows){0};
    if (!block_sizes(hb, cap, sq, count))
        return FRICREG_ENOMEM;
    b->J = alloc_doubles(count[0]);
    b->Y = alloc_doubles(count[1]);
    b->Z = alloc_doubles(count[2]);
    b->G = alloc_doubles(count[3]);
    b->fq = alloc_doubles(count[4]);
    b->piv2 = malloc((cap * hb->nc + 1) * sizeof *b->piv2);
    if (!b->J || !b->Y || !b->Z || !b->G || !b->fq || !b->piv2) {
        fr_hb_rows_free(b);
        return FRICREG_ENOMEM;
    }
    memset(b->J, 0, count[0] * sizeof(double));
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
    hb->colw = hb->Z + 2 * n * (m + 2);
    hb->ql = hb->G + 2 * H1 * m * m;
    hb->dql = hb->ql + 2 * H1 * m;
    hb->jq = hb->fq + nq;
    hb->A = hb->jq + hb->ejq[hb->count] * nc * nc;
    hb->held_nd = 0; /* A moved, or the model changed under its factor */
    hb->R = hb->A + (nq + 1) * (nq + 1);
    hb->rw = hb->R + (nq + 1);
    hb->dy = hb->rw + (nq + 1);
    hb->qw = hb->dy + (nq + 1);
    hb->qt = hb->qw + (nq + 1);
    hb->bcol = hb->qt + (nq + 1);
    hb->brow = hb->bcol + (nq + 1);
    hb->refine = hb->brow + (nq + 1);
    hb->cont = hb->refine + 4 * (nq + 1);
    hb->qsol = hb->cont + FR_HB_CONT_VECTORS * (nq + 1);
    hb->qjac = hb->qsol + nq;
}
