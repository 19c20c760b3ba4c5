/* SPDX-License-Identifier: GPL-3.0-or-later */
/* prepare.c — the set-up of a structure's model at its first step after a change: the damping
 * in force, M's factor with the contacts seen through it (contact_factor.h: W = J M^-1 J^T),
 * W handed to the context (diagonal or dense), and M r. */
#include <float.h>
#include <math.h>
#include <stdlib.h>

#include "base/sparse_ops.h"
#include "ctx/ctx_driver.h"
#include "structure_internal.h"

cholmod_sparse *fr_structure_combine(fricreg_structure *s, double am, double ac, double ak)
{
    double one[2] = {1.0, 0.0}, cm[2] = {am, 0.0}, cc[2] = {ac, 0.0}, ck[2] = {ak, 0.0};
    cholmod_sparse *MC = cholmod_l_add(s->M, s->Cd, cm, cc, 1, 1, &s->cc);
    if (MC == NULL)
        return NULL;
    cholmod_sparse *A = cholmod_l_add(MC, s->K, one, ck, 1, 1, &s->cc);
    cholmod_l_free_sparse(&MC, &s->cc);
    return A;
}

/* The damping in force: a copy of C, or Rayleigh's a0 M + a1 K. */
static int damping(fricreg_structure *s)
{
    cholmod_l_free_sparse(&s->Cd, &s->cc);
    if (s->rayleigh) {
        double a0[2] = {s->a0, 0.0}, a1[2] = {s->a1, 0.0};
        s->Cd = cholmod_l_add(s->M, s->K, a0, a1, 1, 1, &s->cc);
    } else {
        s->Cd = cholmod_l_copy_sparse(s->C, &s->cc);
    }
    return s->Cd == NULL ? fr_fail(s, FRICREG_ENOMEM, "step: no memory for the damping matrix")
                         : FRICREG_OK;
}

/* J and M of scales too far apart: W beyond the double range (M = 1e-310 beside J = 1), or a
 * W_ii below the normal doubles (J = 1e-200 beside M = 1), which the context refuses with the
 * code of its own argument (ENONFINITE, EINVAL or ENOTPSD); one code here, named after the
 * contact. */
static int check_range(fricreg_structure *s, const cholmod_sparse *W)
{
    const SuiteSparse_long *Wp = W->p, *Wi = W->i;
    const double *Wx = W->x;
    for (size_t j = 0; j < s->m; j++) {
        double wjj = 0.0;
        int finite = 1;
        for (SuiteSparse_long p = Wp[j]; p < Wp[j + 1]; p++) {
            finite = finite && isfinite(Wx[p]);
            if ((size_t)Wi[p] == j)
                wjj = Wx[p];
        }
        if (!finite || !(wjj >= DBL_MIN))
            return fr_fail(s, FRICREG_EINVAL,
                           "W = J M^-1 J^T: contact %zu's W_ii = %g is %s: J and M are of scales "
                           "too far apart",
                           j, wjj, finite ? "below DBL_MIN" : "beyond the double range");
    }
    return FRICREG_OK;
}

static int off_diagonal(const cholmod_sparse *W)
{
    const SuiteSparse_long *Wp = W->p, *Wi = W->i;
    const double *Wx = W->x;
    for (size_t j = 0; j < W->ncol; j++)
        for (SuiteSparse_long p = Wp[j]; p < Wp[j + 1]; p++)
            if ((size_t)Wi[p] != j && Wx[p] != 0.0)
                return 1;
    return 0;
}

/* Up to this many contacts a coupled W goes to the context dense (the path of every small
 * model's numbers, and its exact eigenvalue for the step guard); beyond, sparse, where nothing
 * the context does with it is O(m^2). */
#define DENSE_COUPLING_MAX 64

/* The context's setter's status, its failure recorded by the structure. */
static int from_ctx(fricreg_structure *s, int status)
{
    if (status != FRICREG_OK)
        return fr_fail(s, status, "W = J M^-1 J^T: %s", fricreg_ctx_errmsg(s->ctx));
    return FRICREG_OK;
}

/* A coupled W (upper triangle, CSC) into the context: dense, m x m allocated for the call. */
static int couple_dense(fricreg_structure *s, const cholmod_sparse *W)
{
    const SuiteSparse_long *Wp = W->p, *Wi = W->i;
    const double *Wx = W->x;
    size_t m = s->m;
    double *dense = calloc(m * m, sizeof *dense);
    if (dense == NULL)
        return fr_fail(s, FRICREG_ENOMEM, "step: no memory for W = J M^-1 J^T");
    for (size_t j = 0; j < m; j++)
        for (SuiteSparse_long p = Wp[j]; p < Wp[j + 1]; p++)
            dense[(size_t)Wi[p] * m + j] = dense[j * m + (size_t)Wi[p]] = Wx[p];
    int status = fricreg_ctx_set_coupling_dense(s->ctx, m, dense);
    free(dense);
    return from_ctx(s, status);
}

/* W's diagonal (no entry off it) into the context. */
static int couple_diagonal(fricreg_structure *s, const cholmod_sparse *W)
{
    const SuiteSparse_long *Wp = W->p, *Wi = W->i;
    const double *Wx = W->x;
    double *w = calloc(s->m, sizeof *w);
    if (w == NULL)
        return fr_fail(s, FRICREG_ENOMEM, "step: no memory for W = J M^-1 J^T");
    for (size_t j = 0; j < s->m; j++)
        for (SuiteSparse_long p = Wp[j]; p < Wp[j + 1]; p++)
            w[j] = (size_t)Wi[p] == j ? Wx[p] : w[j];
    int status = fricreg_ctx_set_coupling_diagonal(s->ctx, s->m, w);
    free(w);
    return from_ctx(s, status);
}

/* CHOLMOD's long indices are the sparse setters' int64_t (C99 has no static_assert). */
typedef char fr_long_is_int64[sizeof(SuiteSparse_long) == sizeof(int64_t) ? 1 : -1];

/* W into the context: its diagonal when contacts do not couple (separate degrees of freedom
 * under a lumped M), else dense or sparse (DENSE_COUPLING_MAX). */
static int couple(fricreg_structure *s)
{
    const cholmod_sparse *W = s->mass.D;
    s->w_diagonal = !off_diagonal(W);
    if (s->w_diagonal)
        return couple_diagonal(s, W);
    if (s->m <= DENSE_COUPLING_MAX)
        return couple_dense(s, W);
    int flags = FRICREG_SPARSE_ZERO_BASED | FRICREG_SPARSE_UPPER;
    return from_ctx(s, fricreg_ctx_set_coupling_csc(s->ctx, s->m, flags, (const int64_t *)W->p,
                                                    (const int64_t *)W->i, W->x));
}

int fr_structure_prepare(fricreg_structure *s)
{
    if (s->prepared)
        return FRICREG_OK;
    if (!s->contacts_set)
        return fr_fail(s, FRICREG_EINVAL,
                       "step: the contact matrix J was never set "
                       "(fricreg_structure_set_contacts)");
    fr_cfactor_free(&s->mass, &s->cc);
    int status = damping(s);
    if (status == FRICREG_OK)
        status = fr_cfactor_build(&s->mass, s->M, s->Jt, 0.0, &s->cc, &s->err, "step",
                                  "the mass matrix");
    if (status == FRICREG_OK)
        status = check_range(s, s->mass.D);
    if (status == FRICREG_OK)
        status = couple(s);
    if (status != FRICREG_OK) {
        fr_cfactor_free(&s->mass, &s->cc);
        return status;
    }
    fr_sym_mult(s->M, 1.0, s->r->data, 0.0, s->Mr->data);
    s->step_dt = 0.0;
    fr_structure_rates_stale(s);
    s->prepared = 1;
    return FRICREG_OK;
}
