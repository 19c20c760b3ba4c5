/* SPDX-License-Identifier: GPL-3.0-or-later */
/* disk_coupling.c — W by 2x2 blocks, from a dense W or CHOLMOD's upper triangle
 * (disk_coupling.h). */
#include <stdlib.h>
#include <string.h>

#include "disk_coupling.h"
#include "fricreg.h"

void fr_disk_coupling_free(struct fr_disk_coupling *w)
{
    free(w->ptr), free(w->col), free(w->diag), free(w->blk);
    memset(w, 0, sizeof *w);
}

/* The arrays for m block rows and nb blocks, blk zeroed. */
static int allocate(struct fr_disk_coupling *w, size_t m, size_t nb)
{
    memset(w, 0, sizeof *w);
    w->m = m;
    w->ptr = malloc((m + 1) * sizeof *w->ptr);
    w->col = malloc((nb > 0 ? nb : 1) * sizeof *w->col);
    w->diag = malloc(m * sizeof *w->diag);
    w->blk = calloc(nb > 0 ? 4 * nb : 1, sizeof *w->blk);
    if (!w->ptr || !w->col || !w->diag || !w->blk) {
        fr_disk_coupling_free(w);
        return FRICREG_ENOMEM;
    }
    return FRICREG_OK;
}

/* Whether block (i, j) of the dense W has a non-zero entry (the diagonal blocks always). */
static int dense_block_kept(size_t m, const double W[], size_t i, size_t j)
{
    size_t n = 2 * m;
    const double *b = W + 2 * i * n + 2 * j;
    return i == j || b[0] != 0.0 || b[1] != 0.0 || b[n] != 0.0 || b[n + 1] != 0.0;
}

int fr_disk_coupling_from_dense(struct fr_disk_coupling *w, size_t m, const double W[])
{
    size_t nb = 0, n = 2 * m;
    for (size_t i = 0; i < m; i++)
        for (size_t j = 0; j < m; j++)
            nb += (size_t)dense_block_kept(m, W, i, j);
    if (allocate(w, m, nb) != FRICREG_OK)
        return FRICREG_ENOMEM;
    int64_t k = 0;
    for (size_t i = 0; i < m; i++) {
        w->ptr[i] = k;
        for (size_t j = 0; j < m; j++) {
            if (!dense_block_kept(m, W, i, j))
                continue;
            const double *b = W + 2 * i * n + 2 * j;
            double *o = w->blk + 4 * k;
            o[0] = b[0], o[1] = b[1], o[2] = b[n], o[3] = b[n + 1];
            if (i == j)
                w->diag[i] = k;
            w->col[k++] = (int64_t)j;
        }
    }
    w->ptr[m] = k;
    return FRICREG_OK;
}

/* The contacts of the rows 2i, 2i+1 of the full symmetric F (its columns, by symmetry) in
 * ascending order, each once, into out; returns how many. mark[j] == i flags a contact seen. */
static size_t row_contacts(const cholmod_sparse *F, size_t i, int64_t *mark, int64_t *out)
{
    const SuiteSparse_long *Fp = F->p, *Fi = F->i;
    SuiteSparse_long p0 = Fp[2 * i], e0 = Fp[2 * i + 1], p1 = e0, e1 = Fp[2 * i + 2];
    size_t n = 0;
    while (p0 < e0 || p1 < e1) { /* merge the two sorted columns */
        SuiteSparse_long r;
        if (p1 >= e1 || (p0 < e0 && Fi[p0] <= Fi[p1]))
            r = Fi[p0++];
        else
            r = Fi[p1++];
        int64_t j = (int64_t)(r / 2);
        if (mark[j] != (int64_t)i) {
            mark[j] = (int64_t)i;
            out[n++] = j;
        }
    }
    if (mark[i] != (int64_t)i) { /* the diagonal block, even if W's pattern skipped it */
        size_t k = n;
        while (k > 0 && out[k - 1] > (int64_t)i)
            out[k] = out[k - 1], k--;
        out[k] = (int64_t)i;
        mark[i] = (int64_t)i;
        n++;
    }
    return n;
}

/* The blocks of contact i's row from F, the row's contacts already in w->col. */
static void fill_row(struct fr_disk_coupling *w, const cholmod_sparse *F, size_t i, int64_t *slot)
{
    const SuiteSparse_long *Fp = F->p, *Fi = F->i;
    const double *Fx = F->x;
    for (int64_t k = w->ptr[i]; k < w->ptr[i + 1]; k++) {
        slot[w->col[k]] = k;
        if (w->col[k] == (int64_t)i)
            w->diag[i] = k;
    }
    for (int a = 0; a < 2; a++) /* column 2i+a of F is row 2i+a of W */
        for (SuiteSparse_long p = Fp[2 * i + (size_t)a]; p < Fp[2 * i + (size_t)a + 1]; p++)
            w->blk[4 * slot[Fi[p] / 2] + 2 * a + Fi[p] % 2] = Fx[p];
}

/* Block rows from the full symmetric F (sorted columns). */
static int from_full(struct fr_disk_coupling *w, size_t m, const cholmod_sparse *F, int64_t *mark,
                     int64_t *list)
{
    size_t nb = 0;
    for (size_t i = 0; i < m; i++)
        mark[i] = -1;
    for (size_t i = 0; i < m; i++)
        nb += row_contacts(F, i, mark, list);
    if (allocate(w, m, nb) != FRICREG_OK)
        return FRICREG_ENOMEM;
    for (size_t i = 0; i < m; i++)
        mark[i] = -1;
    int64_t k = 0;
    for (size_t i = 0; i < m; i++) {
        w->ptr[i] = k;
        size_t n = row_contacts(F, i, mark, w->col + k);
        k += (int64_t)n;
    }
    w->ptr[m] = k;
    for (size_t i = 0; i < m; i++)
        fill_row(w, F, i, list); /* list as the contact -> block slot map */
    return FRICREG_OK;
}

int fr_disk_coupling_from_upper(struct fr_disk_coupling *w, size_t m, cholmod_sparse *U,
                                cholmod_common *c)
{
    cholmod_sparse *F = cholmod_l_copy(U, 0, 1, c); /* both triangles */
    if (F != NULL && !F->sorted && !cholmod_l_sort(F, c))
        cholmod_l_free_sparse(&F, c);
    int64_t *mark = malloc((m > 0 ? m : 1) * sizeof *mark);
    int64_t *list = malloc((m > 0 ? m : 1) * sizeof *list);
    int status = FRICREG_ENOMEM;
    if (F != NULL && mark != NULL && list != NULL)
        status = from_full(w, m, F, mark, list);
    free(mark), free(list);
    cholmod_l_free_sparse(&F, c);
    return status;
}
