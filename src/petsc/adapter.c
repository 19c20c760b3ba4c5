/* SPDX-License-Identifier: GPL-3.0-or-later */
/* adapter.c — a rank's contacts on a PETSc Vec layout: creation (collective: every rank learns
 * whether any rank refused a contact), the settings passed on to the context, the errors. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "petsc_internal.h"

/* PetscScalar and PetscReal are doubles below: the context's arrays are read in place. */
#if defined(PETSC_USE_COMPLEX) || !defined(PETSC_USE_REAL_DOUBLE)
#error "fricreg's PETSc adapter needs PETSc built with real double scalars"
#endif

#define MAX_CONTACTS ((size_t)1 << 26) /* fricreg_ctx_create's bound */

const char *fricreg_petsc_strerror(int status)
{
    switch (status) {
    case FRICREG_PETSC_EPETSC: return "a PETSc call failed";
    case FRICREG_PETSC_EREMOTE:
        return "a contact's degree of freedom is not owned by this rank (contacts across ranks "
               "are not supported)";
    default: return fricreg_strerror(status);
    }
}

int fr_petsc_fail(fricreg_petsc *fp, PetscErrorCode ierr, const char *what)
{
    const char *text = NULL;
    PetscErrorMessage(ierr, &text, NULL);
    return fr_fail(fp, FRICREG_PETSC_EPETSC, "%s failed: PETSc error %d (%s)", what, (int)ierr,
                   text != NULL ? text : "no text");
}

void fricreg_petsc_free(fricreg_petsc *fp)
{
    if (fp == NULL)
        return;
    fricreg_ctx_free(fp->ctx);
    free(fp->a), free(fp->b), free(fp->inv_ma), free(fp->inv_mb);
    free(fp->zdot), free(fp->afree), free(fp->f), free(fp->gv), free(fp->ga), free(fp->ones);
    free(fp->cols), free(fp->vals);
    fr_petsc_coupling_free(&fp->coupling);
    free(fp);
}

static int alloc_arrays(fricreg_petsc *fp, size_t m)
{
    size_t n = m > 0 ? m : 1;
    int ok = (fp->a = malloc(n * sizeof *fp->a)) != NULL;
    ok &= (fp->b = malloc(n * sizeof *fp->b)) != NULL;
    double **d[] = {&fp->inv_ma, &fp->inv_mb, &fp->zdot, &fp->afree,
                    &fp->f,      &fp->gv,     &fp->ga,   &fp->ones};
    for (size_t i = 0; i < sizeof d / sizeof d[0]; i++)
        ok &= (*d[i] = malloc(n * sizeof **d[i])) != NULL;
    if (ok && m > 0)
        ok = fricreg_ctx_create(m, &fp->ctx) == FRICREG_OK;
    return ok ? FRICREG_OK : FRICREG_ENOMEM;
}

/* The owned offset of global index g, or -1 when this rank does not own it. */
static PetscInt owned(const fricreg_petsc *fp, PetscInt g)
{
    return g >= fp->rstart && g < fp->rstart + fp->nlocal ? g - fp->rstart : -1;
}

/* The contacts' offsets, checked: owned, a != b (contacts may share degrees of freedom:
 * coupling.c). */
static int place_contacts(fricreg_petsc *fp, const PetscInt node[], const PetscInt other[])
{
    int status = FRICREG_OK;
    for (size_t k = 0; k < fp->m && status == FRICREG_OK; k++) {
        PetscInt gb = other != NULL ? other[k] : -1;
        fp->a[k] = owned(fp, node[k]);
        fp->b[k] = gb < 0 ? -1 : owned(fp, gb);
        if (fp->a[k] < 0 || (gb >= 0 && fp->b[k] < 0))
            status = fr_fail(fp, FRICREG_PETSC_EREMOTE,
                             "create: contact %zu's degree of freedom %lld is not owned by this "
                             "rank (%lld .. %lld): contacts across ranks are not supported",
                             k, (long long)(fp->a[k] < 0 ? node[k] : gb), (long long)fp->rstart,
                             (long long)(fp->rstart + fp->nlocal - 1));
        else if (fp->a[k] == fp->b[k])
            status = fr_fail(fp, FRICREG_EINVAL, "create: contact %zu joins %lld to itself", k,
                             (long long)node[k]);
    }
    return status;
}

/* 1/m at the contacts, from the owned entries of mass; W = diag(1/m_a + 1/m_b), or with
 * shared degrees of freedom coupling.c's. */
static int read_masses(fricreg_petsc *fp, Vec mass)
{
    const PetscScalar *mv;
    PetscErrorCode ierr = VecGetArrayRead(mass, &mv);
    if (ierr)
        return fr_petsc_fail(fp, ierr, "create: VecGetArrayRead(mass)");
    int status = FRICREG_OK;
    for (size_t k = 0; k < fp->m && status == FRICREG_OK; k++) {
        double ma = mv[fp->a[k]], mb = fp->b[k] >= 0 ? mv[fp->b[k]] : INFINITY;
        if (isnan(ma) || isnan(mb) || isinf(ma) || (fp->b[k] >= 0 && isinf(mb)))
            status = fr_fail(fp, FRICREG_ENONFINITE, "create: contact %zu's mass is not finite", k);
        else if (!(ma > 0.0 && mb > 0.0))
            status = fr_fail(fp, FRICREG_EINVAL, "create: contact %zu's mass is not > 0", k);
        else {
            fp->inv_ma[k] = 1.0 / ma;
            fp->inv_mb[k] = fp->b[k] >= 0 ? 1.0 / mb : 0.0;
            fp->ones[k] = 1.0;
            fp->zdot[k] = fp->inv_ma[k] + fp->inv_mb[k]; /* W_kk, for the setter below */
        }
    }
    VecRestoreArrayRead(mass, &mv);
    if (status == FRICREG_OK)
        status = fr_petsc_coupling_setup(fp);
    if (status == FRICREG_OK && fp->m > 0 && !fp->coupled &&
        fricreg_ctx_set_coupling_diagonal(fp->ctx, fp->m, fp->zdot) != FRICREG_OK)
        status = fr_fail(fp, fricreg_ctx_errcode(fp->ctx), "create: %s",
                         fricreg_ctx_errmsg(fp->ctx));
    return status;
}

static int setup(fricreg_petsc *fp, Vec mass, const PetscInt node[], const PetscInt other[])
{
    PetscInt rend;
    PetscErrorCode ierr = VecGetOwnershipRange(mass, &fp->rstart, &rend);
    if (ierr)
        return fr_petsc_fail(fp, ierr, "create: VecGetOwnershipRange(mass)");
    fp->nlocal = rend - fp->rstart;
    if (fp->m > MAX_CONTACTS)
        return fr_fail(fp, FRICREG_EINVAL, "create: m = %zu contacts is more than 2^26", fp->m);
    if (fp->m > 0 && node == NULL)
        return fr_fail(fp, FRICREG_ENULL, "create: node is NULL");
    if (alloc_arrays(fp, fp->m) != FRICREG_OK)
        return fr_fail(fp, FRICREG_ENOMEM, "create: out of memory");
    int status = place_contacts(fp, node, other);
    return status == FRICREG_OK ? read_masses(fp, mass) : status;
}

int fricreg_petsc_create(Vec mass, size_t m, const PetscInt node[], const PetscInt other[],
                         fricreg_petsc **out)
{
    if (out == NULL || mass == NULL)
        return FRICREG_ENULL; /* a rank that cannot even reach the reduction: the caller's bug */
    fricreg_petsc *fp = calloc(1, sizeof *fp);
    int status = fp == NULL ? FRICREG_ENOMEM : FRICREG_OK;
    PetscPushErrorHandler(PetscReturnErrorHandler, NULL);
    if (fp != NULL) {
        fp->m = m;
        fp->law = FRICREG_LAW_QUINN, fp->eps = 1e-3; /* the context's defaults */
        status = setup(fp, mass, node, other);
    }
    if (status == FRICREG_OK && fr_petsc_events_register())
        status = fr_fail(fp, FRICREG_PETSC_EPETSC, "create: registering the log events failed");
    /* Every rank agrees: the largest status of any rank. */
    MPI_Comm comm = PetscObjectComm((PetscObject)mass);
    int all = status;
    if (MPI_Allreduce(&status, &all, 1, MPI_INT, MPI_MAX, comm) != MPI_SUCCESS)
        all = FRICREG_PETSC_EPETSC;
    PetscPopErrorHandler();
    if (all != FRICREG_OK) {
        fricreg_petsc_free(fp);
        return all;
    }
    fp->err.code = FRICREG_OK;
    *out = fp;
    return FRICREG_OK;
}

size_t fricreg_petsc_size(const fricreg_petsc *fp)
{
    return fp != NULL ? fp->m : 0;
}

fricreg_ctx *fricreg_petsc_get_ctx(fricreg_petsc *fp)
{
    return fp != NULL ? fp->ctx : NULL;
}

/* A context's failure as fp's, with its message. */
static int pass_on(fricreg_petsc *fp, int status, const char *fn)
{
    if (status == FRICREG_OK)
        return FRICREG_OK;
    return fr_fail(fp, status, "%s: %s", fn, fricreg_ctx_errmsg(fp->ctx));
}

int fricreg_petsc_set_law(fricreg_petsc *fp, int law, double eps)
{
    if (fp == NULL)
        return FRICREG_ENULL;
    if (fp->m == 0) { /* nothing to set, but the same checks as the context's */
        fricreg_ctx *probe = NULL;
        int status = fricreg_ctx_create(1, &probe);
        if (status == FRICREG_OK)
            status = fricreg_ctx_set_law(probe, law, eps);
        fricreg_ctx_free(probe);
        if (status != FRICREG_OK)
            return fr_fail(fp, status, "set_law: %s", fricreg_strerror(status));
        fp->law = law, fp->eps = eps;
        return FRICREG_OK;
    }
    fp->evaluated = 0;
    int status = pass_on(fp, fricreg_ctx_set_law(fp->ctx, law, eps), "set_law");
    if (status == FRICREG_OK)
        fp->law = law, fp->eps = eps;
    return status;
}

int fricreg_petsc_set_bounds(fricreg_petsc *fp, size_t m, const double mun[])
{
    if (fp == NULL)
        return FRICREG_ENULL;
    if (m != fp->m)
        return fr_fail(fp, FRICREG_ESIZE, "set_bounds: m = %zu, the object has %zu", m, fp->m);
    if (m == 0)
        return FRICREG_OK;
    fp->evaluated = 0;
    return pass_on(fp, fricreg_ctx_set_bounds(fp->ctx, m, mun), "set_bounds");
}

int fricreg_petsc_get_forces(const fricreg_petsc *fp, size_t m, double f[])
{
    if (fp == NULL || (f == NULL && m > 0))
        return FRICREG_ENULL;
    if (m != fp->m)
        return FRICREG_ESIZE;
    if (!fp->evaluated && m > 0)
        return FRICREG_EINVAL;
    if (m > 0)
        memcpy(f, fp->f, m * sizeof *f);
    return FRICREG_OK;
}

int fricreg_petsc_errcode(const fricreg_petsc *fp)
{
    return fp != NULL ? fp->err.code : FRICREG_ENULL;
}

const char *fricreg_petsc_errmsg(const fricreg_petsc *fp)
{
    return fp != NULL ? fp->err.msg : "fricreg_petsc_errmsg: fp is NULL";
}
