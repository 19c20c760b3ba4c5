/* SPDX-License-Identifier: GPL-3.0-or-later */
/* eval.c — friction added to an explicit right-hand side and to an implicit residual: each
 * reads its contacts' entries in the rank's owned arrays and asks the context for the forces,
 * with no communication (W is block-local: petsc_internal.h). */
#include "petsc_internal.h"

int fr_petsc_check_vec(fricreg_petsc *fp, Vec v, const char *fn, const char *name)
{
    PetscInt n;
    if (v == NULL)
        return fr_fail(fp, FRICREG_ENULL, "%s: %s is NULL", fn, name);
    PetscErrorCode ierr = VecGetLocalSize(v, &n);
    if (ierr)
        return fr_petsc_fail(fp, ierr, "VecGetLocalSize");
    if (n != fp->nlocal)
        return fr_fail(fp, FRICREG_ESIZE, "%s: %s has %lld entries on this rank, mass had %lld", fn,
                       name, (long long)n, (long long)fp->nlocal);
    return FRICREG_OK;
}

void fr_petsc_gather(fricreg_petsc *fp, const PetscScalar *v, const PetscScalar *F,
                     int scale_by_mass)
{
    for (size_t k = 0; k < fp->m; k++) {
        PetscInt a = fp->a[k], b = fp->b[k];
        double sa = scale_by_mass ? fp->inv_ma[k] : 1.0, sb = scale_by_mass ? fp->inv_mb[k] : 1.0;
        fp->zdot[k] = b >= 0 ? v[a] - v[b] : v[a];
        fp->afree[k] = b >= 0 ? F[a] * sa - F[b] * sb : F[a] * sa;
    }
}

int fr_petsc_eval(fricreg_petsc *fp, const char *fn)
{
    fp->evaluated = 0;
    if (fp->m == 0)
        return FRICREG_OK;
    int status = fricreg_ctx_eval(fp->ctx, fp->m, fp->zdot, fp->afree, fp->f, NULL);
    if (status != FRICREG_OK)
        return fr_fail(fp, status, "%s: %s", fn, fricreg_ctx_errmsg(fp->ctx));
    fp->evaluated = 1;
    return FRICREG_OK;
}

double fr_petsc_power(const fricreg_petsc *fp)
{
    double power = 0.0;
    for (size_t k = 0; k < fp->m; k++)
        power += fp->zdot[k] * fp->f[k];
    return power;
}

/* The common path: check the Vecs, get the arrays, gather, evaluate, scatter the forces with
 * weights (wa, wb) = (1/m_a, -1/m_b) for a right-hand side, (-1, +1) for a residual. */
static int add_forces(fricreg_petsc *fp, const char *fn, Vec V, Vec F, Vec out, int rhs,
                      double *power)
{
    int status = fr_petsc_check_vec(fp, V, fn, "the velocity Vec");
    if (status == FRICREG_OK)
        status = fr_petsc_check_vec(fp, F, fn, "the free-force Vec");
    if (status == FRICREG_OK && out != F)
        status = fr_petsc_check_vec(fp, out, fn, "the output Vec");
    if (status != FRICREG_OK)
        return status;
    const PetscScalar *v = NULL, *Fa = NULL;
    PetscScalar *o = NULL;
    PetscErrorCode ierr = VecGetArrayRead(V, &v);
    if (!ierr && out != F)
        ierr = VecGetArrayRead(F, &Fa);
    if (!ierr)
        ierr = VecGetArray(out, &o);
    if (ierr) {
        status = fr_petsc_fail(fp, ierr, fn);
    } else {
        fr_petsc_gather(fp, v, out != F ? Fa : o, !rhs);
        status = fr_petsc_eval(fp, fn);
    }
    for (size_t k = 0; status == FRICREG_OK && k < fp->m; k++) {
        double fk = fp->f[k];
        o[fp->a[k]] += rhs ? fk * fp->inv_ma[k] : -fk;
        if (fp->b[k] >= 0)
            o[fp->b[k]] -= rhs ? fk * fp->inv_mb[k] : -fk;
    }
    if (o != NULL)
        VecRestoreArray(out, &o);
    if (Fa != NULL)
        VecRestoreArrayRead(F, &Fa);
    if (v != NULL)
        VecRestoreArrayRead(V, &v);
    if (status == FRICREG_OK && power != NULL)
        *power = fr_petsc_power(fp);
    return status;
}

int fricreg_petsc_rhs_add(fricreg_petsc *fp, Vec X, Vec G, double *power)
{
    if (fp == NULL)
        return FRICREG_ENULL;
    PetscPushErrorHandler(PetscReturnErrorHandler, NULL);
    (void)PetscLogEventBegin(fr_petsc_events.rhs_add, 0, 0, 0, 0);
    int status = add_forces(fp, "rhs_add", X, G, G, 1, power);
    (void)PetscLogEventEnd(fr_petsc_events.rhs_add, 0, 0, 0, 0);
    PetscPopErrorHandler();
    return status;
}

int fricreg_petsc_residual_add(fricreg_petsc *fp, Vec V, Vec Ffree, Vec R, double *power)
{
    if (fp == NULL)
        return FRICREG_ENULL;
    if (R == Ffree && R != NULL)
        return fr_fail(fp, FRICREG_EINVAL, "residual_add: R and Ffree are one Vec");
    PetscPushErrorHandler(PetscReturnErrorHandler, NULL);
    (void)PetscLogEventBegin(fr_petsc_events.residual_add, 0, 0, 0, 0);
    int status = add_forces(fp, "residual_add", V, Ffree, R, 0, power);
    (void)PetscLogEventEnd(fr_petsc_events.residual_add, 0, 0, 0, 0);
    PetscPopErrorHandler();
    return status;
}
