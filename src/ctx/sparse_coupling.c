/* SPDX-License-Identifier: GPL-3.0-or-later */
/* sparse_coupling.c — a sparse W's storage and products (sparse_coupling.h).
 *
 * The ordering is AMD's, and only AMD's: CHOLMOD's default would try METIS on matrices that
 * AMD fills badly, and METIS (5.1) keeps its random generator in process-wide state (two
 * contexts set up at once in two threads race on it) and aborts the program when it runs out
 * of memory. The price is a tall elimination tree on chain-like couplings, which makes row
 * updates of the factor dear (sparse_block.c says how the update rule accounts for it). */
#include <math.h>
#include <string.h>

#include "fricreg.h"
#include "sparse_coupling.h"
#include "base/sparse_factor.h"

double fr_sparse_row_dot(const struct fr_sparse_coupling *sp, size_t i, const double x[],
                         int skip_diagonal, double *size)
{
    const SuiteSparse_long *Wp = sp->W->p, *Wi = sp->W->i;
    const double *Wx = sp->W->x;
    double sum = 0.0, magnitude = 0.0;
    for (SuiteSparse_long p = Wp[i]; p < Wp[i + 1]; p++) {
        if (skip_diagonal && (size_t)Wi[p] == i)
            continue;
        double term = Wx[p] * x[Wi[p]];
        sum += term;
        magnitude += fabs(term);
    }
    if (size != NULL)
        *size = magnitude;
    return sum;
}

double fr_sparse_row_abs_dot(const struct fr_sparse_coupling *sp, size_t i, const double x[])
{
    const SuiteSparse_long *Wp = sp->W->p, *Wi = sp->W->i;
    const double *Wx = sp->W->x;
    double sum = 0.0;
    for (SuiteSparse_long p = Wp[i]; p < Wp[i + 1]; p++)
        sum += fabs(Wx[p]) * x[Wi[p]];
    return sum;
}

void fr_sparse_column_gather(struct fr_sparse_coupling *sp, size_t k, const size_t set[], size_t n,
                             double out[])
{
    const SuiteSparse_long *Wp = sp->W->p, *Wi = sp->W->i;
    const double *Wx = sp->W->x;
    for (SuiteSparse_long p = Wp[k]; p < Wp[k + 1]; p++)
        sp->column[Wi[p]] = Wx[p];
    for (size_t a = 0; a < n; a++)
        out[a] = sp->column[set[a]];
    for (SuiteSparse_long p = Wp[k]; p < Wp[k + 1]; p++)
        sp->column[Wi[p]] = 0.0;
}

double fr_sparse_gershgorin(const struct fr_sparse_coupling *sp, const double s[], double s_max,
                            double w_max)
{
    const SuiteSparse_long *Wp = sp->W->p, *Wi = sp->W->i;
    const double *Wx = sp->W->x;
    double radius = 0.0;
    for (size_t i = 0; i < sp->m; i++) {
        double row = 0.0, si = sqrt(s[i] / s_max);
        for (SuiteSparse_long p = Wp[i]; p < Wp[i + 1]; p++)
            row += si * (fabs(Wx[p]) / w_max) * sqrt(s[Wi[p]] / s_max);
        radius = fmax(radius, row);
    }
    return radius;
}

double fr_sparse_max_abs(const struct fr_sparse_coupling *sp)
{
    const double *Wx = sp->W->x;
    size_t nnz = (size_t)((SuiteSparse_long *)sp->W->p)[sp->m];
    double largest = 0.0;
    for (size_t p = 0; p < nnz; p++)
        largest = fmax(largest, fabs(Wx[p]));
    return largest;
}

/* AMD's ordering of W's pattern, postordered (CHOLMOD's analysis of the upper triangle), into
 * sp->perm and sp->pinv. */
static int order(struct fr_sparse_coupling *sp)
{
    cholmod_common *c = &sp->c;
    cholmod_sparse *U = cholmod_l_copy(sp->W, 1, 0, c); /* pattern of the upper triangle */
    cholmod_factor *symbolic = NULL;
    c->nmethods = 1;
    c->method[0].ordering = CHOLMOD_AMD;
    c->postorder = 1;
    if (U != NULL)
        symbolic = cholmod_l_analyze(U, c);
    int status = symbolic != NULL ? FRICREG_OK : FRICREG_ENOMEM;
    if (status == FRICREG_OK) {
        const SuiteSparse_long *P = symbolic->Perm;
        for (size_t p = 0; p < sp->m; p++) {
            sp->perm[p] = P[p];
            sp->pinv[P[p]] = (SuiteSparse_long)p;
        }
    }
    cholmod_l_free_factor(&symbolic, c);
    cholmod_l_free_sparse(&U, c);
    return status;
}

/* C = upper triangle of P W P^T, sorted. */
static int permute(struct fr_sparse_coupling *sp)
{
    cholmod_common *c = &sp->c;
    cholmod_sparse *PWP = cholmod_l_submatrix(sp->W, sp->perm, (SuiteSparse_long)sp->m, sp->perm,
                                              (SuiteSparse_long)sp->m, 1, 1, c);
    if (PWP != NULL)
        sp->C = cholmod_l_copy(PWP, 1, 1, c);
    cholmod_l_free_sparse(&PWP, c);
    return sp->C != NULL ? FRICREG_OK : FRICREG_ENOMEM;
}

int fr_sparse_coupling_build(struct fr_sparse_coupling *sp, cholmod_sparse *W)
{
    cholmod_common *c = &sp->c;
    size_t m = W->nrow;
    sp->W = W;
    sp->m = m;
    sp->perm = cholmod_l_malloc(m, sizeof *sp->perm, c);
    sp->pinv = cholmod_l_malloc(m, sizeof *sp->pinv, c);
    sp->by_contact = cholmod_l_calloc(m, sizeof *sp->by_contact, c);
    sp->column = cholmod_l_calloc(m, sizeof *sp->column, c);
    if (!sp->perm || !sp->pinv || !sp->by_contact || !sp->column)
        return FRICREG_ENOMEM;
    int status = order(sp);
    if (status == FRICREG_OK)
        status = permute(sp);
    return status;
}

void fr_sparse_coupling_free(struct fr_sparse_coupling *sp)
{
    cholmod_common *c = &sp->c;
    size_t m = sp->m > 0 ? sp->m : 1;
    cholmod_l_free_sparse(&sp->W, c);
    cholmod_l_free_sparse(&sp->C, c);
    sp->perm = cholmod_l_free(m, sizeof *sp->perm, sp->perm, c);
    sp->pinv = cholmod_l_free(m, sizeof *sp->pinv, sp->pinv, c);
    sp->by_contact = cholmod_l_free(m, sizeof *sp->by_contact, sp->by_contact, c);
    sp->column = cholmod_l_free(m, sizeof *sp->column, sp->column, c);
    fr_cholmod_finish(c);
}
