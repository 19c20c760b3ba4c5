/* SPDX-License-Identifier: GPL-3.0-or-later */
/* model.c — the linear model of the driver (fricreg_hb.h): the mass, damping and stiffness
 * matrices (dense, or through sparse.c compressed), Rayleigh damping, and the excitation of
 * the fundamental; each setter checks everything before it changes anything, and a change
 * invalidates what was solved on the old model. */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "base/matrix_input.h"
#include "model.h"
#include "sparse.h"
#include "busy.h"

/* A model change: the factors and the kept solution no longer hold, nor (model_serial counted)
 * what the modules above made on the old model (the forced response's branch, the backbone,
 * the condensed stability's reduced model). */
void fr_hb_invalidate(fricreg_hb *hb)
{
    hb->factored_omega = NAN;
    hb->have_solution = 0;
    hb->model_serial++;
}

int fr_hb_check_ndof(fricreg_hb *hb, const char *fn, size_t ndof)
{
    if (ndof != hb->n)
        return fr_fail(hb, FRICREG_ESIZE, "%s: ndof = %zu, the driver has %zu", fn, ndof, hb->n);
    return FRICREG_OK;
}

/* The symmetric-matrix setters' one check and copy: finite, symmetric to 1e-12 of the rows'
 * scales, its symmetric part into dst (the dense model), or as matrix which (0 M, 1 C, 2 K)
 * of the sparse one. */
static int set_symmetric(fricreg_hb *hb, const char *fn, size_t ndof, const double *A, int which)
{
    if (hb == NULL || hb->busy)
        return fr_hb_refuse(hb, fn);
    if (A == NULL)
        return fr_fail(hb, FRICREG_ENULL, "%s: the matrix is NULL", fn);
    if (fr_hb_check_ndof(hb, fn, ndof) != FRICREG_OK)
        return FRICREG_ESIZE;
    size_t n = ndof;
    for (size_t k = 0; k < n * n; k++)
        if (!isfinite(A[k]))
            return fr_fail(hb, FRICREG_ENONFINITE, "%s: entry (%zu, %zu) = %g", fn, k / n, k % n,
                           A[k]);
    double *scale = hb->colw; /* scratch [2n]: the rows' largest entries */
    for (size_t i = 0; i < n; i++) {
        scale[i] = 0.0;
        for (size_t k = 0; k < n; k++)
            scale[i] = fmax(scale[i], fabs(A[i * n + k]));
    }
    for (size_t i = 0; i < n; i++)
        for (size_t k = i + 1; k < n; k++)
            if (fabs(A[i * n + k] - A[k * n + i]) > 1e-12 * sqrt(scale[i] * scale[k]))
                return fr_fail(hb, FRICREG_ENOTSYM,
                               "%s: entries (%zu, %zu) = %g and (%zu, %zu) = %g", fn, i, k,
                               A[i * n + k], k, i, A[k * n + i]);
    if (hb->sparse)
        return fr_hb_sparse_set_dense(hb, fn, which, A);
    double *dst = which == 0 ? hb->M : which == 1 ? hb->C : hb->K;
    hb->mk_serial += which != 1; /* the modes of (K, M) no longer hold */
    if (which == 1) {
        hb->c_zero = 1;
        for (size_t k = 0; k < n * n && hb->c_zero; k++)
            hb->c_zero = A[k] == 0.0;
    }
    for (size_t i = 0; i < n; i++)
        for (size_t k = 0; k < n; k++)
            dst[i * n + k] = 0.5 * A[i * n + k] + 0.5 * A[k * n + i]; /* no overflow near 1e308 */
    fr_hb_invalidate(hb);
    return FRICREG_OK;
}

int fricreg_hb_set_mass(fricreg_hb *hb, size_t ndof, const double M[])
{
    return set_symmetric(hb, "set_mass", ndof, M, 0);
}

int fricreg_hb_set_stiffness(fricreg_hb *hb, size_t ndof, const double K[])
{
    return set_symmetric(hb, "set_stiffness", ndof, K, 2);
}

int fricreg_hb_set_damping(fricreg_hb *hb, size_t ndof, const double C[])
{
    int status = set_symmetric(hb, "set_damping", ndof, C, 1);
    if (status == FRICREG_OK)
        hb->rayleigh = 0;
    return status;
}

int fricreg_hb_set_matrix(fricreg_hb *hb, int which, size_t nrows, size_t ncols, int format,
                          const int64_t ptr[], const int64_t ind[], const double values[])
{
    static const char fn[] = "set_matrix";
    if (hb == NULL || hb->busy)
        return fr_hb_refuse(hb, fn);
    if (!(which >= FRICREG_MASS && which <= FRICREG_DAMPING))
        return fr_fail(hb, FRICREG_EINVAL,
                       "%s: which = %d is not a model matrix of the driver (FRICREG_MASS, "
                       "FRICREG_STIFFNESS or FRICREG_DAMPING)",
                       fn, which);
    int slot = which == FRICREG_MASS ? 0 : which == FRICREG_DAMPING ? 1 : 2;
    if (nrows != ncols)
        return fr_fail(hb, FRICREG_ESIZE, "%s: the matrix is %zu x %zu, not square", fn, nrows,
                       ncols);
    int compressed, by_columns, flags; /* a dense matrix's ptr and ind are not read */
    int status = fr_matrix_format(format, &compressed, &by_columns, &flags, &hb->err, fn);
    if (status != FRICREG_OK)
        return status;
    if (compressed)
        return fr_hb_set_compressed(hb, fn, slot, nrows, by_columns, flags, ptr, ind, values);
    status = set_symmetric(hb, fn, nrows, values, slot);
    if (status == FRICREG_OK && slot == 1)
        hb->rayleigh = 0;
    return status;
}

int fricreg_hb_set_rayleigh(fricreg_hb *hb, double a0, double a1)
{
    if (hb == NULL || hb->busy)
        return fr_hb_refuse(hb, "set_rayleigh");
    if (!isfinite(a0) || !isfinite(a1))
        return fr_fail(hb, FRICREG_ENONFINITE, "set_rayleigh: a0 = %g, a1 = %g", a0, a1);
    if (a0 < 0.0 || a1 < 0.0)
        return fr_fail(hb, FRICREG_EINVAL, "set_rayleigh: a0 = %g and a1 = %g must be >= 0", a0,
                       a1);
    hb->rayleigh = 1;
    hb->a0 = a0;
    hb->a1 = a1;
    fr_hb_invalidate(hb);
    return FRICREG_OK;
}

int fricreg_hb_set_excitation(fricreg_hb *hb, size_t ndof, const double pc[], const double ps[])
{
    if (hb == NULL || hb->busy)
        return fr_hb_refuse(hb, "set_excitation");
    if (pc == NULL || ps == NULL)
        return fr_fail(hb, FRICREG_ENULL, "set_excitation: %s is NULL", pc == NULL ? "pc" : "ps");
    if (fr_hb_check_ndof(hb, "set_excitation", ndof) != FRICREG_OK)
        return FRICREG_ESIZE;
    for (size_t k = 0; k < ndof; k++)
        if (!isfinite(pc[k]) || !isfinite(ps[k]))
            return fr_fail(hb, FRICREG_ENONFINITE, "set_excitation: pc[%zu] = %g, ps[%zu] = %g", k,
                           pc[k], k, ps[k]);
    memcpy(hb->pc, pc, ndof * sizeof *pc);
    memcpy(hb->ps, ps, ndof * sizeof *ps);
    fr_hb_invalidate(hb);
    return FRICREG_OK;
}
