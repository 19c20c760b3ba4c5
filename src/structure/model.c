/* SPDX-License-Identifier: GPL-3.0-or-later */
/* model.c — a structure's model matrices, M, K, C and J, as the caller gives them: dense
 * row-major, or compressed sparse rows or columns (fricreg.h's enum fricreg_sparse_flags).
 * Every form becomes CHOLMOD's compressed columns (src/base/matrix_input.h) and goes through
 * fr_structure_install, which checks what the matrix must be and takes it. GSL's sparse
 * matrices take the same road from structure_gsl.c. */
#include <math.h>

#include "base/matrix_input.h"
#include "base/sparse_factor.h"
#include "structure_internal.h"

/* M is positive definite: CHOLMOD's Cholesky factor exists (a pivot that is not positive is
 * CHOLMOD_NOT_POSDEF). Analysed and factored here, then released: the first step factors the
 * model it gets. */
static int check_positive_definite(fricreg_structure *s, cholmod_sparse *M, const char *who)
{
    fr_cholmod_ordering(&s->cc, CHOLMOD_AMD, 0);
    cholmod_factor *L = cholmod_l_analyze(M, &s->cc);
    int status = FRICREG_OK;
    if (L == NULL || !cholmod_l_factorize(M, L, &s->cc) || s->cc.status < CHOLMOD_OK)
        status = fr_fail(s, FRICREG_ENOMEM, "%s: no memory to factor the mass matrix", who);
    else if (s->cc.status == CHOLMOD_NOT_POSDEF)
        status = fr_fail(s, FRICREG_ENOTPSD,
                         "%s: the mass matrix is not positive definite (its Cholesky factor has "
                         "no positive pivot at column %ld)",
                         who, (long)L->minor);
    cholmod_l_free_factor(&L, &s->cc);
    return status;
}

/* J (m x n) moves every contact: no row without a nonzero entry. Into *Jt its transpose. */
static int contacts_transposed(fricreg_structure *s, cholmod_sparse *J, cholmod_sparse **Jt,
                               const char *who)
{
    *Jt = cholmod_l_transpose(J, 1, &s->cc);
    if (*Jt == NULL)
        return fr_fail(s, FRICREG_ENOMEM, "%s: no memory for J", who);
    const SuiteSparse_long *p = (*Jt)->p;
    const double *x = (*Jt)->x;
    for (size_t i = 0; i < s->m; i++) {
        int moves = 0;
        for (SuiteSparse_long k = p[i]; k < p[i + 1]; k++)
            moves |= x[k] != 0.0;
        if (!moves) {
            cholmod_l_free_sparse(Jt, &s->cc);
            return fr_fail(s, FRICREG_EINVAL, "%s: row %zu of J is zero: contact %zu does not move",
                           who, i, i);
        }
    }
    return FRICREG_OK;
}

int fr_structure_install(fricreg_structure *s, int which, cholmod_sparse *A, const char *who)
{
    cholmod_sparse **slot[] = {&s->M, &s->K, &s->C, &s->Jt};
    int status = FRICREG_OK;
    if (which == FR_MASS)
        status = check_positive_definite(s, A, who);
    if (which == FR_CONTACTS) {
        cholmod_sparse *Jt = NULL;
        status = contacts_transposed(s, A, &Jt, who);
        cholmod_l_free_sparse(&A, &s->cc);
        A = Jt;
    }
    if (status != FRICREG_OK) {
        cholmod_l_free_sparse(&A, &s->cc);
        return status;
    }
    cholmod_l_free_sparse(slot[which], &s->cc);
    *slot[which] = A;
    if (which == FR_DAMPING)
        s->rayleigh = 0;
    if (which == FR_CONTACTS)
        s->contacts_set = 1;
    fr_structure_changed(s, FR_CHANGED_MODEL);
    return FRICREG_OK;
}

/* ---- The one setter ---------------------------------------------------------------------- */

static int set_dense(fricreg_structure *s, int which, const char *who, size_t nrows, size_t ncols,
                     const double A[])
{
    if (s == NULL || s->running)
        return fr_structure_refuse(s, who);
    int contacts = which == FR_CONTACTS;
    if (A == NULL)
        return fr_fail(s, FRICREG_ENULL, contacts ? "%s: J is NULL" : "%s: the matrix is NULL",
                       who);
    if (contacts && (nrows != s->m || ncols != s->n))
        return fr_fail(s, FRICREG_ESIZE, "%s: J is %zu x %zu, the structure needs %zu x %zu", who,
                       nrows, ncols, s->m, s->n);
    if (!contacts && (nrows != s->n || ncols != s->n))
        return fr_fail(s, FRICREG_ESIZE, "%s: ndof = %zu, the structure has %zu", who,
                       nrows != s->n ? nrows : ncols, s->n);
    cholmod_sparse *S = NULL;
    int status = fr_dense_to_cholmod(nrows, ncols, A, !contacts, &s->cc, &S, &s->err, who);
    return status != FRICREG_OK ? status : fr_structure_install(s, which, S, who);
}

/* by_columns: CSC, else CSR; flags: enum fricreg_sparse_flags. */
static int set_compressed(fricreg_structure *s, int which, const char *who, size_t nrows,
                          size_t ncols, int by_columns, int flags, const int64_t ptr[],
                          const int64_t ind[], const double values[])
{
    if (s == NULL || s->running)
        return fr_structure_refuse(s, who);
    size_t need = which == FR_CONTACTS ? s->m : s->n;
    if (nrows != need || ncols != s->n)
        return fr_fail(s, FRICREG_ESIZE,
                       "%s: the matrix is %zu x %zu, the structure needs %zu x %zu", who, nrows,
                       ncols, need, s->n);
    struct fr_compressed a = {nrows, ncols, by_columns, flags, ptr, ind, values};
    int symmetric = which != FR_CONTACTS;
    int status = fr_compressed_check(&a, symmetric, &s->err, who);
    cholmod_sparse *S = NULL;
    if (status == FRICREG_OK)
        status = fr_compressed_to_cholmod(&a, symmetric, &s->cc, &S, &s->err, who);
    return status != FRICREG_OK ? status : fr_structure_install(s, which, S, who);
}

int fricreg_structure_set_matrix(fricreg_structure *s, int which, size_t nrows, size_t ncols,
                                 int format, const int64_t ptr[], const int64_t ind[],
                                 const double values[])
{
    static const int slot[] = {[FRICREG_MASS] = FR_MASS,
                               [FRICREG_STIFFNESS] = FR_STIFFNESS,
                               [FRICREG_DAMPING] = FR_DAMPING,
                               [FRICREG_CONTACTS] = FR_CONTACTS};
    const char *who = "set_matrix";
    if (s == NULL || s->running)
        return fr_structure_refuse(s, who);
    if (!(which >= FRICREG_MASS && which <= FRICREG_CONTACTS))
        return fr_fail(s, FRICREG_EINVAL,
                       "%s: which = %d is not a model matrix (FRICREG_MASS, FRICREG_STIFFNESS, "
                       "FRICREG_DAMPING or FRICREG_CONTACTS)",
                       who, which);
    int compressed, by_columns, flags; /* a dense matrix's ptr and ind are not read */
    int status = fr_matrix_format(format, &compressed, &by_columns, &flags, &s->err, who);
    if (status != FRICREG_OK)
        return status;
    if (compressed)
        return set_compressed(s, slot[which], who, nrows, ncols, by_columns, flags, ptr, ind,
                              values);
    return set_dense(s, slot[which], who, nrows, ncols, values);
}

/* ---- The setters of one matrix in one storage: cases of fricreg_structure_set_matrix ------ */

int fricreg_structure_set_mass(fricreg_structure *s, size_t ndof, const double M[])
{
    return set_dense(s, FR_MASS, "set_mass", ndof, ndof, M);
}

int fricreg_structure_set_stiffness(fricreg_structure *s, size_t ndof, const double K[])
{
    return set_dense(s, FR_STIFFNESS, "set_stiffness", ndof, ndof, K);
}

int fricreg_structure_set_damping(fricreg_structure *s, size_t ndof, const double C[])
{
    return set_dense(s, FR_DAMPING, "set_damping", ndof, ndof, C);
}

int fricreg_structure_set_contacts(fricreg_structure *s, size_t m, size_t ndof, const double J[])
{
    return set_dense(s, FR_CONTACTS, "set_contacts", m, ndof, J);
}

int fricreg_structure_set_mass_csr(fricreg_structure *s, size_t ndof, int flags,
                                   const int64_t rowptr[], const int64_t colind[],
                                   const double values[])
{
    return set_compressed(s, FR_MASS, "set_mass_csr", ndof, ndof, 0, flags, rowptr, colind, values);
}

int fricreg_structure_set_mass_csc(fricreg_structure *s, size_t ndof, int flags,
                                   const int64_t colptr[], const int64_t rowind[],
                                   const double values[])
{
    return set_compressed(s, FR_MASS, "set_mass_csc", ndof, ndof, 1, flags, colptr, rowind, values);
}

int fricreg_structure_set_stiffness_csr(fricreg_structure *s, size_t ndof, int flags,
                                        const int64_t rowptr[], const int64_t colind[],
                                        const double values[])
{
    return set_compressed(s, FR_STIFFNESS, "set_stiffness_csr", ndof, ndof, 0, flags, rowptr,
                          colind, values);
}

int fricreg_structure_set_stiffness_csc(fricreg_structure *s, size_t ndof, int flags,
                                        const int64_t colptr[], const int64_t rowind[],
                                        const double values[])
{
    return set_compressed(s, FR_STIFFNESS, "set_stiffness_csc", ndof, ndof, 1, flags, colptr,
                          rowind, values);
}

int fricreg_structure_set_damping_csr(fricreg_structure *s, size_t ndof, int flags,
                                      const int64_t rowptr[], const int64_t colind[],
                                      const double values[])
{
    return set_compressed(s, FR_DAMPING, "set_damping_csr", ndof, ndof, 0, flags, rowptr, colind,
                          values);
}

int fricreg_structure_set_damping_csc(fricreg_structure *s, size_t ndof, int flags,
                                      const int64_t colptr[], const int64_t rowind[],
                                      const double values[])
{
    return set_compressed(s, FR_DAMPING, "set_damping_csc", ndof, ndof, 1, flags, colptr, rowind,
                          values);
}

int fricreg_structure_set_contacts_csr(fricreg_structure *s, size_t m, size_t ndof, int flags,
                                       const int64_t rowptr[], const int64_t colind[],
                                       const double values[])
{
    return set_compressed(s, FR_CONTACTS, "set_contacts_csr", m, ndof, 0, flags, rowptr, colind,
                          values);
}

int fricreg_structure_set_contacts_csc(fricreg_structure *s, size_t m, size_t ndof, int flags,
                                       const int64_t colptr[], const int64_t rowind[],
                                       const double values[])
{
    return set_compressed(s, FR_CONTACTS, "set_contacts_csc", m, ndof, 1, flags, colptr, rowind,
                          values);
}
