/* SPDX-License-Identifier: GPL-3.0-or-later */
/* structure_gsl.c — the sparse setters of fricreg_structure_gsl.h: GSL makes the matrix dense
 * (gsl_spmatrix_sp2d, any storage format) in the structure's Newton scratch, which holds
 * nothing between steps, and the dense setter checks and copies it; its messages are renamed
 * after the sparse function. */
#include <stdio.h>
#include <string.h>

#include <gsl/gsl_errno.h>

#include "fricreg_structure_gsl.h"
#include "structure_internal.h"

/* The dense setter's message "name: ..." as "name_sparse: ...". */
static int renamed(fricreg_structure *s, int status, const char *name)
{
    char rest[sizeof s->err.msg];
    const char *msg = fricreg_structure_errmsg(s);
    size_t len = strlen(name);
    snprintf(rest, sizeof rest, "%s", strncmp(msg, name, len) == 0 ? msg + len : msg);
    return fr_fail(s, status, "%s_sparse%s", name, rest);
}

/* S (rows x cols, as the structure needs) into the scratch A, then the dense setter. */
static int set_sparse(fricreg_structure *s, const char *name, const gsl_spmatrix *S, gsl_matrix *A,
                      int (*set)(fricreg_structure *, gsl_matrix *))
{
    if (S == NULL)
        return fr_fail(s, FRICREG_ENULL, "%s_sparse: the matrix is NULL", name);
    if (S->size1 != A->size1 || S->size2 != A->size2)
        return fr_fail(s, FRICREG_ESIZE,
                       "%s_sparse: the matrix is %zu x %zu, the structure needs %zu x %zu", name,
                       S->size1, S->size2, A->size1, A->size2);
    /* gsl_spmatrix_sp2d reports (through GSL's process-wide handler) only a size mismatch and
     * an unknown storage type: both are refused here first, so it cannot fail. */
    if (S->sptype != GSL_SPMATRIX_COO && S->sptype != GSL_SPMATRIX_CSC &&
        S->sptype != GSL_SPMATRIX_CSR)
        return fr_fail(s, FRICREG_EINVAL,
                       "%s_sparse: unknown storage type %d (GSL has COO, CSC and CSR)", name,
                       S->sptype);
    gsl_spmatrix_sp2d(A, S);
    int status = set(s, A);
    return status == FRICREG_OK ? status : renamed(s, status, name);
}

static int set_mass(fricreg_structure *s, gsl_matrix *A)
{
    return fricreg_structure_set_mass(s, s->n, A->data);
}

static int set_stiffness(fricreg_structure *s, gsl_matrix *A)
{
    return fricreg_structure_set_stiffness(s, s->n, A->data);
}

static int set_damping(fricreg_structure *s, gsl_matrix *A)
{
    return fricreg_structure_set_damping(s, s->n, A->data);
}

static int set_contacts(fricreg_structure *s, gsl_matrix *A)
{
    return fricreg_structure_set_contacts(s, s->m, s->n, A->data);
}

int fricreg_structure_set_mass_sparse(fricreg_structure *s, const gsl_spmatrix *M)
{
    return s == NULL ? FRICREG_ENULL : set_sparse(s, "set_mass", M, s->A, set_mass);
}

int fricreg_structure_set_stiffness_sparse(fricreg_structure *s, const gsl_spmatrix *K)
{
    return s == NULL ? FRICREG_ENULL : set_sparse(s, "set_stiffness", K, s->A, set_stiffness);
}

int fricreg_structure_set_damping_sparse(fricreg_structure *s, const gsl_spmatrix *C)
{
    return s == NULL ? FRICREG_ENULL : set_sparse(s, "set_damping", C, s->A, set_damping);
}

int fricreg_structure_set_contacts_sparse(fricreg_structure *s, const gsl_spmatrix *J)
{
    return s == NULL ? FRICREG_ENULL : set_sparse(s, "set_contacts", J, s->T1, set_contacts);
}
