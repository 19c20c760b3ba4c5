/* SPDX-License-Identifier: GPL-3.0-or-later */
/* coupling.c — contacts that share a degree of freedom on one rank: W = J M^-1 J^T with its
 * off-diagonal entries, and the contacts' coupled groups, whose blocks the tangent fills.
 *
 * Contact k's row of J is e_a - e_b (b the ground: e_a), so with a lumped M
 *   W_kl = sum over the degrees of freedom d that k and l both touch of s_k(d) s_l(d) / m_d,
 * s_k(d) = +1 at a, -1 at b: W_kk = 1/m_a + 1/m_b, and two contacts meeting at d are coupled
 * by +-1/m_d. W goes to the context in compressed rows (fricreg_ctx_set_coupling_csr), and the
 * consistent law's near-stick solve couples exactly the contacts W connects: the tangent
 * df/dzdot, df/da_free is block diagonal over the connected groups of W's graph. Its blocks
 * are read by probing (Curtis, Powell & Reid 1974): direction c holds a 1 at the c-th contact
 * of every group, and the product's entry at contact k is its group's column c. Two products
 * per column of the largest group, O(g_max (m + nnz(L))) per Jacobian, and sum |G|^2 doubles
 * per block kept. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "petsc_internal.h"

void fr_petsc_coupling_free(struct fr_petsc_coupling *c)
{
    free(c->group), free(c->place), free(c->members), free(c->first), free(c->block);
    free(c->tz), free(c->ta), free(c->probe), free(c->df);
    memset(c, 0, sizeof *c);
}

/* The contacts at each owned degree of freedom: at[from[d] .. from[d + 1]) with signs sign[],
 * a counting sort of the 2 m incidences. NULL arrays when out of memory. */
struct incidence {
    size_t *from, *at;
    signed char *sign;
};

static int incidences(const fricreg_petsc *fp, struct incidence *in)
{
    size_t n = (size_t)fp->nlocal;
    in->from = calloc(n + 1, sizeof *in->from);
    in->at = malloc(2 * fp->m * sizeof *in->at);
    in->sign = malloc(2 * fp->m * sizeof *in->sign);
    if (in->from == NULL || in->at == NULL || in->sign == NULL)
        return FRICREG_ENOMEM;
    for (size_t k = 0; k < fp->m; k++) {
        in->from[fp->a[k] + 1]++;
        if (fp->b[k] >= 0)
            in->from[fp->b[k] + 1]++;
    }
    for (size_t d = 0; d < n; d++)
        in->from[d + 1] += in->from[d];
    size_t *next = malloc((n > 0 ? n : 1) * sizeof *next);
    if (next == NULL)
        return FRICREG_ENOMEM;
    memcpy(next, in->from, n * sizeof *next);
    for (size_t k = 0; k < fp->m; k++) {
        in->at[next[fp->a[k]]] = k;
        in->sign[next[fp->a[k]]++] = 1;
        if (fp->b[k] >= 0) {
            in->at[next[fp->b[k]]] = k;
            in->sign[next[fp->b[k]]++] = -1;
        }
    }
    free(next);
    return FRICREG_OK;
}

static void incidence_free(struct incidence *in)
{
    free(in->from), free(in->at), free(in->sign);
}

/* Whether some degree of freedom is in two contacts. */
static int shared(const fricreg_petsc *fp, const struct incidence *in)
{
    for (PetscInt d = 0; d < fp->nlocal; d++)
        if (in->from[d + 1] - in->from[d] > 1)
            return 1;
    return 0;
}

/* Contact k's degrees of freedom (one or two), their signs and inverse masses. */
static size_t dofs_of(const fricreg_petsc *fp, size_t k, PetscInt d[2], double inv_m[2])
{
    d[0] = fp->a[k], inv_m[0] = fp->inv_ma[k];
    d[1] = fp->b[k], inv_m[1] = fp->inv_mb[k];
    return fp->b[k] >= 0 ? 2 : 1;
}

/* W's rows in CSR (whole, contact order): row k sums s_k s_l / m_d over its degrees of
 * freedom d and the contacts l there, duplicates merged through pos[] (-1: not in row k). */
static int assemble_w(fricreg_petsc *fp, const struct incidence *in, int64_t **rowptr,
                      int64_t **colind, double **values)
{
    size_t m = fp->m, cap = 0;
    for (size_t k = 0; k < m; k++) {
        PetscInt d[2];
        double inv_m[2];
        for (size_t j = 0; j < dofs_of(fp, k, d, inv_m); j++)
            cap += in->from[d[j] + 1] - in->from[d[j]];
    }
    int64_t *pos = malloc(m * sizeof *pos);
    *rowptr = malloc((m + 1) * sizeof **rowptr);
    *colind = malloc(cap * sizeof **colind);
    *values = malloc(cap * sizeof **values);
    if (pos == NULL || *rowptr == NULL || *colind == NULL || *values == NULL) {
        free(pos);
        return FRICREG_ENOMEM;
    }
    for (size_t k = 0; k < m; k++)
        pos[k] = -1;
    int64_t nnz = 0;
    for (size_t k = 0; k < m; k++) {
        (*rowptr)[k] = nnz;
        PetscInt d[2];
        double inv_m[2];
        size_t nd = dofs_of(fp, k, d, inv_m);
        for (size_t j = 0; j < nd; j++) {
            double sk = j == 0 ? 1.0 : -1.0;
            for (size_t p = in->from[d[j]]; p < in->from[d[j] + 1]; p++) {
                size_t l = in->at[p];
                if (pos[l] < 0) {
                    pos[l] = nnz;
                    (*colind)[nnz] = (int64_t)l;
                    (*values)[nnz++] = 0.0;
                }
                (*values)[pos[l]] += sk * in->sign[p] * inv_m[j];
            }
        }
        for (int64_t p = (*rowptr)[k]; p < nnz; p++)
            pos[(*colind)[p]] = -1;
    }
    (*rowptr)[m] = nnz;
    free(pos);
    return FRICREG_OK;
}

/* The connected groups of W's graph by a breadth-first walk over the incidences: each
 * contact's group and place in it, the members group by group, and the blocks' offsets. */
static int groups(fricreg_petsc *fp, const struct incidence *in)
{
    struct fr_petsc_coupling *c = &fp->coupling;
    size_t m = fp->m;
    c->group = malloc(m * sizeof *c->group);
    c->place = malloc(m * sizeof *c->place);
    c->members = malloc(m * sizeof *c->members);
    c->first = malloc((m + 1) * sizeof *c->first);
    c->block = malloc((m + 1) * sizeof *c->block);
    c->probe = malloc(m * sizeof *c->probe);
    c->df = malloc(m * sizeof *c->df);
    if (!c->group || !c->place || !c->members || !c->first || !c->block || !c->probe || !c->df)
        return FRICREG_ENOMEM;
    for (size_t k = 0; k < m; k++)
        c->group[k] = SIZE_MAX;
    size_t filled = 0;
    c->ngroups = 0;
    c->largest = 0;
    c->block[0] = 0;
    for (size_t seed = 0; seed < m; seed++) {
        if (c->group[seed] != SIZE_MAX)
            continue;
        size_t g = c->ngroups++, head = filled;
        c->first[g] = filled;
        c->group[seed] = g;
        c->members[filled++] = seed;
        for (; head < filled; head++) { /* the queue is members[first[g] .. filled) */
            size_t k = c->members[head];
            PetscInt d[2];
            double inv_m[2];
            for (size_t j = 0; j < dofs_of(fp, k, d, inv_m); j++)
                for (size_t p = in->from[d[j]]; p < in->from[d[j] + 1]; p++)
                    if (c->group[in->at[p]] == SIZE_MAX) {
                        c->group[in->at[p]] = g;
                        c->members[filled++] = in->at[p];
                    }
        }
        size_t size = filled - c->first[g];
        for (size_t i = c->first[g]; i < filled; i++)
            c->place[c->members[i]] = i - c->first[g];
        c->block[g + 1] = c->block[g] + size * size;
        if (size > c->largest)
            c->largest = size;
    }
    c->first[c->ngroups] = filled;
    c->tz = malloc(c->block[c->ngroups] * sizeof *c->tz);
    c->ta = malloc(c->block[c->ngroups] * sizeof *c->ta);
    return c->tz != NULL && c->ta != NULL ? FRICREG_OK : FRICREG_ENOMEM;
}

int fr_petsc_coupling_setup(fricreg_petsc *fp)
{
    struct incidence in = {NULL, NULL, NULL};
    int64_t *rowptr = NULL, *colind = NULL;
    double *values = NULL;
    int status = fp->m > 0 ? incidences(fp, &in) : FRICREG_OK;
    fp->coupled = status == FRICREG_OK && fp->m > 0 && shared(fp, &in);
    if (status == FRICREG_OK && fp->coupled)
        status = assemble_w(fp, &in, &rowptr, &colind, &values);
    if (status == FRICREG_OK && fp->coupled)
        status = groups(fp, &in);
    if (status != FRICREG_OK)
        status = fr_fail(fp, FRICREG_ENOMEM, "create: out of memory for the coupled contacts");
    else if (fp->coupled &&
             fricreg_ctx_set_coupling_csr(fp->ctx, fp->m, 0, rowptr, colind, values) != FRICREG_OK)
        status = fr_fail(fp, fricreg_ctx_errcode(fp->ctx), "create: %s",
                         fricreg_ctx_errmsg(fp->ctx));
    free(rowptr), free(colind), free(values);
    incidence_free(&in);
    return status;
}

/* One probe: direction c of every group larger than c, through the tangent with respect to
 * zdot (wrt_afree 0) or a_free (1), into the blocks' column c. */
static int probe(fricreg_petsc *fp, size_t col, int wrt_afree)
{
    struct fr_petsc_coupling *c = &fp->coupling;
    size_t m = fp->m;
    memset(c->probe, 0, m * sizeof *c->probe);
    for (size_t g = 0; g < c->ngroups; g++)
        if (c->first[g] + col < c->first[g + 1])
            c->probe[c->members[c->first[g] + col]] = 1.0;
    int status = fricreg_ctx_tangent_apply(fp->ctx, m, wrt_afree ? NULL : c->probe,
                                           wrt_afree ? c->probe : NULL, c->df);
    if (status != FRICREG_OK)
        return status;
    double *T = wrt_afree ? c->ta : c->tz;
    for (size_t k = 0; k < m; k++) {
        size_t g = c->group[k], size = c->first[g + 1] - c->first[g];
        if (col < size) /* row place[k], column col of group g's block */
            T[c->block[g] + c->place[k] * size + col] = c->df[k];
    }
    return FRICREG_OK;
}

int fr_petsc_coupling_tangent(fricreg_petsc *fp)
{
    for (size_t col = 0; col < fp->coupling.largest; col++) {
        int status = probe(fp, col, 0);
        if (status == FRICREG_OK)
            status = probe(fp, col, 1);
        if (status != FRICREG_OK)
            return fr_fail(fp, status, "jacobian_add: %s", fricreg_ctx_errmsg(fp->ctx));
    }
    return FRICREG_OK;
}
