/* SPDX-License-Identifier: GPL-3.0-or-later */
/* joint_storage.c — the joint step's dense storage (struct fr_joint, joint_step.c's Newton
 * over the contacts' and the elements' forces): allocated for m contacts and nc element
 * coordinates at the first such step after a model change (jenkins.c), and the compliances
 * W_eff and W made dense from the factors. */
#include <stdlib.h>
#include <string.h>

#include "structure_internal.h"

void fr_joint_free(struct fr_joint *j)
{
    double *arrays[] = {j->Weff, j->W,  j->C,   j->T,    j->Fz, j->Fa,  j->tau, j->norm,
                        j->rhs,  j->z,  j->zt,  j->d,    j->gc, j->gct, j->ge,  j->get,
                        j->wf,   j->mf, j->dzc, j->coef, j->fz, j->wg,  j->fe0, j->dfe};
    for (size_t k = 0; k < sizeof arrays / sizeof *arrays; k++)
        free(arrays[k]);
    free(j->perm);
    free(j->implicit);
    *j = (struct fr_joint){0};
}

int fr_joint_allocate(struct fr_joint *j, size_t m, size_t nc)
{
    if (j->T != NULL && j->m == m && j->nc == nc)
        return 1;
    fr_joint_free(j);
    size_t dim = m + nc;
    j->m = m;
    j->nc = nc;
    j->dim = dim;
    struct {
        double **p;
        size_t n;
    } arrays[] = {{&j->Weff, m * m}, {&j->W, m * m},  {&j->C, m * nc}, {&j->T, dim * dim},
                  {&j->Fz, m * m},   {&j->Fa, m * m}, {&j->tau, dim},  {&j->norm, dim},
                  {&j->rhs, dim},    {&j->z, dim},    {&j->zt, dim},   {&j->d, dim},
                  {&j->gc, m},       {&j->gct, m},    {&j->ge, nc},    {&j->get, nc},
                  {&j->wf, m},       {&j->mf, m},     {&j->dzc, m},    {&j->coef, m},
                  {&j->fz, m},       {&j->wg, m},     {&j->fe0, nc},   {&j->dfe, nc}};
    int ok = 1;
    for (size_t k = 0; k < sizeof arrays / sizeof *arrays; k++)
        ok &= (*arrays[k].p = calloc(arrays[k].n, sizeof(double))) != NULL;
    j->perm = calloc(dim, sizeof *j->perm);
    j->implicit = calloc(m, 1);
    if (ok && j->perm != NULL && j->implicit != NULL)
        return 1;
    fr_joint_free(j);
    return 0;
}

/* The upper triangle S (m x m, CSC) into the dense symmetric D (row-major). */
static void expand(const cholmod_sparse *S, double D[])
{
    size_t m = S->ncol;
    const SuiteSparse_long *Sp = S->p, *Si = S->i;
    const double *Sx = S->x;
    memset(D, 0, m * m * sizeof *D);
    for (size_t c = 0; c < m; c++)
        for (SuiteSparse_long p = Sp[c]; p < Sp[c + 1]; p++) {
            size_t r = (size_t)Si[p];
            D[r * m + c] = Sx[p];
            D[c * m + r] = Sx[p];
        }
}

void fr_joint_compliances(fricreg_structure *s)
{
    expand(s->step.D, s->el.joint.Weff);
    expand(s->mass.D, s->el.joint.W);
    s->el.joint.valid = 1;
}
