/* SPDX-License-Identifier: GPL-3.0-or-later */
/* jacobian.c — the exact Jacobian of the friction term of the residual R = M A - F_free - J^T f.
 *
 * f_k = f(zdot_k, a_free,k) with zdot_k = V_a - V_b and a_free,k = F_a/m_a - F_b/m_b, so with
 * g_v, g_a its slopes (the context's tangent, diagonal when W is) and X the Newton unknown,
 *   df_k/dX = g_v s_v (e_a - e_b) + g_a (dF_a/dX / m_a - dF_b/dX / m_b),
 * s_v = dV/dX. The free forces' rows come from the caller's Jacobian P = s_m M - dF/dX in the
 * contact rows (s_m = dA/dX): dF_a/dX = s_m m_a e_a - P_a. Row a of the residual loses df_k/dX,
 * row b gains it. Coupled contacts (a shared degree of freedom) sum the same terms over their
 * group, with the tangent's blocks (coupling.c) for g_v, g_a. Every contact's rows are read
 * into the buffer before any is added, so every read is of the caller's P, even where a row
 * belongs to two contacts. */
#include <math.h>
#include <stdlib.h>

#include "petsc_internal.h"

/* Room for n more entries in the row buffer. */
static int reserve(fricreg_petsc *fp, size_t n)
{
    if (n <= fp->cap)
        return FRICREG_OK;
    PetscInt *c = realloc(fp->cols, n * sizeof *c);
    if (c != NULL)
        fp->cols = c;
    PetscScalar *v = c != NULL ? realloc(fp->vals, n * sizeof *v) : NULL;
    if (v == NULL)
        return fr_fail(fp, FRICREG_ENOMEM, "jacobian_add: out of memory for %zu entries", n);
    fp->vals = v;
    fp->cap = n;
    return FRICREG_OK;
}

/* Appends (g/m) times row `row` of P to the buffer at *len; P's row is read, not changed. */
static int append_row(fricreg_petsc *fp, Mat P, PetscInt row, double scale, size_t *len)
{
    PetscInt ncols;
    const PetscInt *cols;
    const PetscScalar *vals;
    PetscErrorCode ierr = MatGetRow(P, row, &ncols, &cols, &vals);
    if (ierr)
        return fr_petsc_fail(fp, ierr, "jacobian_add: MatGetRow");
    int status = reserve(fp, *len + (size_t)ncols + 2);
    for (PetscInt j = 0; status == FRICREG_OK && j < ncols; j++) {
        if (vals[j] == 0.0) /* an explicit zero adds nothing, and may lie outside row a's pattern */
            continue;
        fp->cols[*len] = cols[j];
        fp->vals[(*len)++] = scale * vals[j];
    }
    MatRestoreRow(P, row, &ncols, &cols, &vals);
    return status;
}

/* Coupled contacts: -df_k/dX = sum over k's group of l of (T^a_kl / m_a) P_a - (T^a_kl / m_b)
 * P_b - (T^z_kl s_v + T^a_kl s_m)(e_a - e_b), a and b contact l's, into the buffer. */
static int coupled_row(fricreg_petsc *fp, Mat P, size_t k, double s_m, double s_v, size_t *len)
{
    const struct fr_petsc_coupling *c = &fp->coupling;
    size_t g = c->group[k], first = c->first[g], size = c->first[g + 1] - first;
    const double *tz = c->tz + c->block[g] + c->place[k] * size,
                 *ta = c->ta + c->block[g] + c->place[k] * size;
    int status = FRICREG_OK;
    for (size_t i = 0; i < size && status == FRICREG_OK; i++) {
        size_t l = c->members[first + i];
        if (ta[i] != 0.0)
            status = append_row(fp, P, fp->rstart + fp->a[l], ta[i] * fp->inv_ma[l], len);
        if (status == FRICREG_OK && ta[i] != 0.0 && fp->b[l] >= 0)
            status = append_row(fp, P, fp->rstart + fp->b[l], -ta[i] * fp->inv_mb[l], len);
    }
    for (size_t i = 0; i < size && status == FRICREG_OK; i++) {
        size_t l = c->members[first + i];
        double diag = tz[i] * s_v + ta[i] * s_m;
        if (diag == 0.0 || (status = reserve(fp, *len + 2)) != FRICREG_OK)
            continue;
        fp->cols[*len] = fp->rstart + fp->a[l];
        fp->vals[(*len)++] = -diag;
        if (fp->b[l] >= 0) {
            fp->cols[*len] = fp->rstart + fp->b[l];
            fp->vals[(*len)++] = diag;
        }
    }
    return status;
}

/* The change of contact k's row a, -df_k/dX, into the buffer from *len (its length added);
 * row b's is its negative. */
static int contact_row(fricreg_petsc *fp, Mat P, size_t k, double s_m, double s_v, size_t *len)
{
    if (fp->coupled)
        return coupled_row(fp, P, k, s_m, s_v, len);
    PetscInt ga = fp->rstart + fp->a[k], gb = fp->rstart + fp->b[k];
    double diag = fp->gv[k] * s_v + fp->ga[k] * s_m;
    int status = append_row(fp, P, ga, fp->ga[k] * fp->inv_ma[k], len);
    if (status == FRICREG_OK && fp->b[k] >= 0)
        status = append_row(fp, P, gb, -fp->ga[k] * fp->inv_mb[k], len);
    if (status == FRICREG_OK)
        status = reserve(fp, *len + 2);
    if (status != FRICREG_OK)
        return status;
    fp->cols[*len] = ga;
    fp->vals[(*len)++] = -diag;
    if (fp->b[k] >= 0) {
        fp->cols[*len] = gb;
        fp->vals[(*len)++] = diag;
    }
    return FRICREG_OK;
}

/* The tangent's diagonal at the current forces: two products with a vector of ones. */
static int tangent_diagonal(fricreg_petsc *fp)
{
    if (fp->m == 0)
        return FRICREG_OK;
    int status = fricreg_ctx_tangent_apply(fp->ctx, fp->m, fp->ones, NULL, fp->gv);
    if (status == FRICREG_OK)
        status = fricreg_ctx_tangent_apply(fp->ctx, fp->m, NULL, fp->ones, fp->ga);
    if (status != FRICREG_OK)
        return fr_fail(fp, status, "jacobian_add: %s", fricreg_ctx_errmsg(fp->ctx));
    return FRICREG_OK;
}

/* Every contact's rows, read then added: contacts' rows are read in one pass into the buffer
 * (offsets in start[]), then added to P. */
static int add_rows(fricreg_petsc *fp, Mat P, double s_m, double s_v)
{
    size_t len = 0, *start = malloc((fp->m + 1) * sizeof *start);
    if (start == NULL)
        return fr_fail(fp, FRICREG_ENOMEM, "jacobian_add: out of memory");
    int status = FRICREG_OK;
    for (size_t k = 0; k < fp->m && status == FRICREG_OK; k++) {
        start[k] = len;
        status = contact_row(fp, P, k, s_m, s_v, &len);
    }
    start[fp->m] = len;
    for (size_t k = 0; k < fp->m && status == FRICREG_OK; k++) {
        PetscInt rows[2] = {fp->rstart + fp->a[k], fp->rstart + fp->b[k]};
        PetscInt n = (PetscInt)(start[k + 1] - start[k]);
        PetscErrorCode ierr = MatSetValues(P, 1, &rows[0], n, fp->cols + start[k],
                                           fp->vals + start[k], ADD_VALUES);
        for (PetscInt j = 0; !ierr && fp->b[k] >= 0 && j < n; j++)
            fp->vals[start[k] + (size_t)j] = -fp->vals[start[k] + (size_t)j];
        if (!ierr && fp->b[k] >= 0)
            ierr = MatSetValues(P, 1, &rows[1], n, fp->cols + start[k], fp->vals + start[k],
                                ADD_VALUES);
        if (ierr)
            status = fr_petsc_fail(fp, ierr, "jacobian_add: MatSetValues");
    }
    free(start);
    return status;
}

static int forces_and_tangent(fricreg_petsc *fp, Vec V, Vec Ffree)
{
    int status = fr_petsc_check_vec(fp, V, "jacobian_add", "V");
    if (status == FRICREG_OK)
        status = fr_petsc_check_vec(fp, Ffree, "jacobian_add", "Ffree");
    if (status != FRICREG_OK)
        return status;
    const PetscScalar *v = NULL, *F = NULL;
    PetscErrorCode ierr = VecGetArrayRead(V, &v);
    if (!ierr)
        ierr = VecGetArrayRead(Ffree, &F);
    if (ierr)
        status = fr_petsc_fail(fp, ierr, "jacobian_add: VecGetArrayRead");
    else {
        fr_petsc_gather(fp, v, F, 1);
        status = fr_petsc_eval(fp, "jacobian_add");
    }
    if (F != NULL)
        VecRestoreArrayRead(Ffree, &F);
    if (v != NULL)
        VecRestoreArrayRead(V, &v);
    if (status != FRICREG_OK)
        return status;
    return fp->coupled ? fr_petsc_coupling_tangent(fp) : tangent_diagonal(fp);
}

int fricreg_petsc_jacobian_add(fricreg_petsc *fp, Vec V, Vec Ffree, PetscReal mass_shift,
                               PetscReal velocity_shift, Mat P)
{
    if (fp == NULL)
        return FRICREG_ENULL;
    if (P == NULL)
        return fr_fail(fp, FRICREG_ENULL, "jacobian_add: P is NULL");
    int status = FRICREG_OK;
    if (!isfinite(mass_shift) || !isfinite(velocity_shift))
        status = fr_fail(fp, FRICREG_ENONFINITE, "jacobian_add: a shift is not finite");
    PetscPushErrorHandler(PetscReturnErrorHandler, NULL);
    (void)PetscLogEventBegin(fr_petsc_events.jacobian_add, 0, 0, 0, 0);
    if (status == FRICREG_OK)
        status = forces_and_tangent(fp, V, Ffree);
    if (status == FRICREG_OK)
        status = add_rows(fp, P, mass_shift, velocity_shift);
    /* Collective: a rank that failed above still takes part in the assembly. */
    PetscErrorCode ierr = MatAssemblyBegin(P, MAT_FINAL_ASSEMBLY);
    if (!ierr)
        ierr = MatAssemblyEnd(P, MAT_FINAL_ASSEMBLY);
    if (ierr && status == FRICREG_OK)
        status = fr_petsc_fail(fp, ierr, "jacobian_add: MatAssembly");
    (void)PetscLogEventEnd(fr_petsc_events.jacobian_add, 0, 0, 0, 0);
    PetscPopErrorHandler();
    return status;
}
