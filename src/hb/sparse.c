/* SPDX-License-Identifier: GPL-3.0-or-later */
/* sparse.c — the harmonic-balance driver's sparse model (fricreg_hb.h): the _csc setters, the
 * pattern of the dynamic stiffness D_h = K − (hΩ)² M + i hΩ C (the union of M's, C's and
 * K's, both triangles, assembled once per pattern with each matrix's values on it), and its
 * factorization by SuiteSparse's KLU, complex (klu_zl_*: D_h is complex symmetric, not
 * Hermitian, and indefinite above the first resonance, so CHOLMOD's Cholesky does not apply):
 * the analysis (AMD) once per pattern, and per harmonic an LU with partial pivoting that is
 * kept and, at the next frequency, refactored on its pivot sequence (klu_zl_refactor), with a
 * fresh factor whenever that sequence's pivot growth is a hundred times the fresh one's. KLU
 * prints nothing; it solves Y_h = D_h^-1 [J^T | P_h] in place in a block held here (no
 * allocation); its analysis and factors allocate through SuiteSparse_config. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/matrix_input.h"
#include "base/sparse_factor.h"
#include "hb_internal.h"
#include "sparse.h"
#include "busy.h"
#include "base/free_all.h"

/* ---- The pattern --------------------------------------------------------------------------- */

struct entry {
    int64_t row;
    int which; /* 0 M, 1 C, 2 K */
    double value;
};

static int by_row(const void *a, const void *b)
{
    const struct entry *x = a, *y = b;
    if (x->row != y->row)
        return x->row < y->row ? -1 : 1;
    return x->which - y->which;
}

/* The new pattern's arrays, built before anything of the driver changes. */
struct pattern {
    int64_t *Dp, *Di;
    size_t dnz;
    double *v;           /* vM, vC, vK [dnz] each, Dv [2 dnz] */
    struct fr_hb_lu *lu; /* [H + 1] */
};

/* One harmonic's LU factor of D_h, and the reciprocal pivot growth (klu_zl_rgrowth) of its
 * last fresh factorization, against which a refactor on the same pivots is judged. */
struct fr_hb_lu {
    klu_l_numeric *numeric; /* NULL: none */
    double fresh_rgrowth;
};

static void pattern_free(struct pattern *p)
{
    FR_FREE_ALL(p->Dp, p->Di, p->v, p->lu);
}

/* The union of X[0..2]'s patterns (upper triangles, stype 1) with both triangles, rows sorted
 * in each column, and each matrix's values on it. FRICREG_OK or FRICREG_ENOMEM. */
static int build_pattern(size_t n, int H, cholmod_sparse *const X[3], struct pattern *p)
{
    *p = (struct pattern){0};
    size_t total = 0;
    int64_t *start = calloc(n + 1, sizeof *start);
    if (start == NULL)
        return FRICREG_ENOMEM;
    for (int x = 0; x < 3; x++) {
        const SuiteSparse_long *Ap = X[x]->p, *Ai = X[x]->i, *Anz = X[x]->nz;
        for (size_t j = 0; j < n; j++) {
            SuiteSparse_long end = X[x]->packed ? Ap[j + 1] : Ap[j] + Anz[j];
            for (SuiteSparse_long q = Ap[j]; q < end; q++) {
                start[j + 1]++;
                total++;
                if ((size_t)Ai[q] != j) {
                    start[Ai[q] + 1]++;
                    total++;
                }
            }
        }
    }
    for (size_t j = 0; j < n; j++)
        start[j + 1] += start[j];
    struct entry *e = malloc((total ? total : 1) * sizeof *e);
    int64_t *fill = malloc((n ? n : 1) * sizeof *fill);
    if (e == NULL || fill == NULL) {
        FR_FREE_ALL(start, e, fill);
        return FRICREG_ENOMEM;
    }
    memcpy(fill, start, n * sizeof *fill);
    for (int x = 0; x < 3; x++) {
        const SuiteSparse_long *Ap = X[x]->p, *Ai = X[x]->i, *Anz = X[x]->nz;
        const double *Ax = X[x]->x;
        for (size_t j = 0; j < n; j++) {
            SuiteSparse_long end = X[x]->packed ? Ap[j + 1] : Ap[j] + Anz[j];
            for (SuiteSparse_long q = Ap[j]; q < end; q++) {
                size_t i = (size_t)Ai[q];
                e[fill[j]++] = (struct entry){(int64_t)i, x, Ax[q]};
                if (i != j)
                    e[fill[i]++] = (struct entry){(int64_t)j, x, Ax[q]};
            }
        }
    }
    free(fill);
    size_t dnz = 0;
    for (size_t j = 0; j < n; j++) {
        qsort(e + start[j], (size_t)(start[j + 1] - start[j]), sizeof *e, by_row);
        for (int64_t q = start[j]; q < start[j + 1]; q++)
            dnz += q == start[j] || e[q].row != e[q - 1].row;
    }
    p->dnz = dnz;
    p->Dp = malloc((n + 1) * sizeof *p->Dp);
    p->Di = malloc((dnz ? dnz : 1) * sizeof *p->Di);
    p->v = calloc(5 * (dnz ? dnz : 1), sizeof *p->v);
    p->lu = calloc((size_t)H + 1, sizeof *p->lu);
    if (!p->Dp || !p->Di || !p->v || !p->lu) {
        free(start);
        free(e);
        pattern_free(p);
        return FRICREG_ENOMEM;
    }
    size_t k = 0;
    for (size_t j = 0; j < n; j++) {
        p->Dp[j] = (int64_t)k;
        for (int64_t q = start[j]; q < start[j + 1]; q++) {
            if (q == start[j] || e[q].row != e[q - 1].row)
                p->Di[k++] = e[q].row;
            p->v[(size_t)e[q].which * dnz + k - 1] = e[q].value;
        }
    }
    p->Dp[n] = (int64_t)k;
    free(start);
    free(e);
    return FRICREG_OK;
}

/* Frees the pattern, its analysis and the factors on it. */
static void free_factors(fricreg_hb *hb)
{
    if (hb->lu != NULL)
        for (int h = 0; h <= hb->H; h++)
            klu_zl_free_numeric(&hb->lu[h].numeric, &hb->klu);
    klu_l_free_symbolic(&hb->symbolic, &hb->klu);
    FR_FREE_ALL(hb->Dp, hb->Di, hb->vM, hb->lu);
    hb->Dp = hb->Di = NULL;
    hb->vM = hb->vC = hb->vK = hb->Dv = NULL;
    hb->lu = NULL;
}

/* Installs the matrices X[0..2] (M, C, K; each either the driver's own or new) with their
 * pattern: the driver's old matrices not kept are freed. On failure the new ones are freed
 * and nothing changes. */
static int install(fricreg_hb *hb, const char *fn, cholmod_sparse *X[3])
{
    cholmod_sparse **own[3] = {&hb->Ms, &hb->Cs, &hb->Ks};
    struct pattern p;
    int status = build_pattern(hb->n, hb->H, X, &p);
    if (status != FRICREG_OK) {
        for (int x = 0; x < 3; x++)
            if (X[x] != *own[x])
                cholmod_l_free_sparse(&X[x], &hb->cc);
        return fr_fail(hb, FRICREG_ENOMEM, "%s: no memory for the dynamic stiffness's pattern", fn);
    }
    for (int x = 0; x < 3; x++)
        if (X[x] != *own[x]) {
            cholmod_l_free_sparse(own[x], &hb->cc);
            *own[x] = X[x];
        }
    if (!hb->sparse) { /* for good: the dense model's memory is not needed again */
        FR_FREE_ALL(hb->M, hb->D, hb->piv);
        hb->M = hb->C = hb->K = hb->D = NULL;
        hb->piv = NULL;
        klu_l_defaults(&hb->klu);
        hb->sparse = 1;
    }
    free_factors(hb);
    hb->Dp = p.Dp;
    hb->Di = p.Di;
    hb->dnz = p.dnz;
    size_t d = p.dnz ? p.dnz : 1;
    hb->vM = p.v;
    hb->vC = p.v + d;
    hb->vK = p.v + 2 * d;
    hb->Dv = p.v + 3 * d;
    hb->lu = p.lu;
    hb->factored_omega = NAN;
    hb->have_solution = 0;
    hb->model_serial++;
    return FRICREG_OK;
}

void fr_hb_sparse_free(fricreg_hb *hb)
{
    cholmod_l_free_sparse(&hb->Ms, &hb->cc);
    cholmod_l_free_sparse(&hb->Cs, &hb->cc);
    cholmod_l_free_sparse(&hb->Ks, &hb->cc);
    free_factors(hb);
}

/* A zero n x n upper triangle, or the identity. */
static cholmod_sparse *simple(fricreg_hb *hb, int identity)
{
    cholmod_sparse *S = identity ? cholmod_l_speye(hb->n, hb->n, CHOLMOD_REAL, &hb->cc)
                                 : cholmod_l_spzeros(hb->n, hb->n, 0, CHOLMOD_REAL, &hb->cc);
    if (S != NULL)
        S->stype = 1;
    return S;
}

int fr_hb_sparse_defaults(fricreg_hb *hb)
{
    cholmod_sparse *X[3] = {simple(hb, 1), simple(hb, 0), simple(hb, 0)};
    if (!X[0] || !X[1] || !X[2]) {
        for (int x = 0; x < 3; x++)
            cholmod_l_free_sparse(&X[x], &hb->cc);
        return FRICREG_ENOMEM;
    }
    return install(hb, "create", X);
}

int fr_hb_sparse_copy(fricreg_hb *dst, const fricreg_hb *src)
{
    cholmod_sparse *X[3] = {cholmod_l_copy_sparse(src->Ms, &dst->cc),
                            cholmod_l_copy_sparse(src->Cs, &dst->cc),
                            cholmod_l_copy_sparse(src->Ks, &dst->cc)};
    if (!X[0] || !X[1] || !X[2]) {
        for (int x = 0; x < 3; x++)
            cholmod_l_free_sparse(&X[x], &dst->cc);
        return FRICREG_ENOMEM;
    }
    return install(dst, "truncation_error", X);
}

/* The dense driver's matrix which (checked when it was set) as an upper triangle. */
static int from_dense(fricreg_hb *hb, const char *fn, int which, cholmod_sparse **out)
{
    const double *A = which == 0 ? hb->M : which == 1 ? hb->C : hb->K;
    return fr_dense_to_cholmod(hb->n, hb->n, A, 1, &hb->cc, out, &hb->err, fn);
}

/* S becomes matrix which; a dense driver's other two are converted first. */
static int replace(fricreg_hb *hb, const char *fn, int which, cholmod_sparse *S)
{
    cholmod_sparse *X[3] = {hb->Ms, hb->Cs, hb->Ks};
    X[which] = S;
    if (!hb->sparse)
        for (int x = 0; x < 3; x++) {
            if (x == which)
                continue;
            X[x] = NULL;
            if (from_dense(hb, fn, x, &X[x]) != FRICREG_OK) {
                for (int y = 0; y < 3; y++)
                    cholmod_l_free_sparse(&X[y], &hb->cc);
                return fr_fail(hb, FRICREG_ENOMEM, "%s: no memory for the sparse model", fn);
            }
        }
    return install(hb, fn, X);
}

int fr_hb_sparse_set_dense(fricreg_hb *hb, const char *fn, int which, const double *A)
{
    cholmod_sparse *S = NULL;
    int status = fr_dense_to_cholmod(hb->n, hb->n, A, 1, &hb->cc, &S, &hb->err, fn);
    return status != FRICREG_OK ? status : replace(hb, fn, which, S);
}

int fr_hb_set_compressed(fricreg_hb *hb, const char *fn, int which, size_t ndof, int by_columns,
                         int flags, const int64_t ptr[], const int64_t ind[], const double values[])
{
    if (hb == NULL || hb->busy)
        return fr_hb_refuse(hb, fn);
    if (ndof != hb->n)
        return fr_fail(hb, FRICREG_ESIZE, "%s: ndof = %zu, the driver has %zu", fn, ndof, hb->n);
    struct fr_compressed a = {ndof, ndof, by_columns, flags, ptr, ind, values};
    int status = fr_compressed_check(&a, 1, &hb->err, fn);
    cholmod_sparse *S = NULL;
    if (status == FRICREG_OK)
        status = fr_compressed_to_cholmod(&a, 1, &hb->cc, &S, &hb->err, fn);
    if (status == FRICREG_OK)
        status = replace(hb, fn, which, S);
    if (status == FRICREG_OK && which == 1)
        hb->rayleigh = 0; /* C replaces Rayleigh's */
    return status;
}

int fricreg_hb_set_mass_csc(fricreg_hb *hb, size_t ndof, int flags, const int64_t colptr[],
                            const int64_t rowind[], const double values[])
{
    return fr_hb_set_compressed(hb, "set_mass_csc", 0, ndof, 1, flags, colptr, rowind, values);
}

int fricreg_hb_set_damping_csc(fricreg_hb *hb, size_t ndof, int flags, const int64_t colptr[],
                               const int64_t rowind[], const double values[])
{
    return fr_hb_set_compressed(hb, "set_damping_csc", 1, ndof, 1, flags, colptr, rowind, values);
}

int fricreg_hb_set_stiffness_csc(fricreg_hb *hb, size_t ndof, int flags, const int64_t colptr[],
                                 const int64_t rowind[], const double values[])
{
    return fr_hb_set_compressed(hb, "set_stiffness_csc", 2, ndof, 1, flags, colptr, rowind, values);
}

/* ---- The factor and the solves ------------------------------------------------------------- */

void fr_hb_sparse_release(fricreg_hb *hb)
{
    if (hb->lu != NULL)
        for (int h = 0; h <= hb->H; h++)
            klu_zl_free_numeric(&hb->lu[h].numeric, &hb->klu);
}

/* The damping in force, less the nonlinear modes' xi M, as dynamic.c's. */
static double damping(const fricreg_hb *hb, size_t p)
{
    double c = hb->no_c ? 0.0 : hb->rayleigh ? hb->a0 * hb->vM[p] + hb->a1 * hb->vK[p] : hb->vC[p];
    return c - hb->xi * hb->vM[p];
}

/* A refactor on the last fresh factor's pivots is kept while its reciprocal pivot growth is at
 * least this fraction of the fresh one's (at most a hundredfold more growth, so the backward
 * error stays near a fresh factor's; below it the pivots are chosen afresh). */
#define REFACTOR_RGROWTH_MIN 1e-2
/* The factors of all H + 1 harmonics are kept from one frequency to the next (within a call:
 * fr_hb_sparse_release at its end) while they hold at most
 * this many entries in all (2^24 complex entries: 256 MiB of values, about three harmonics'
 * factors of a 9·10^4-dof 2-D grid); a larger model frees each after its solves, so one factor
 * lives at a time and every frequency factors afresh. */
#define KEPT_LU_ENTRIES_MAX 16777216.0

static int klu_failed(fricreg_hb *hb, const char *fn, const char *what)
{
    if (hb->klu.status == KLU_OUT_OF_MEMORY)
        return fr_fail(hb, FRICREG_ENOMEM, "%s: no memory for KLU's %s of D_h", fn, what);
    return fr_fail(hb, FRICREG_EINVAL, "%s: KLU's %s of D_h failed (status %ld)", fn, what,
                   (long)hb->klu.status);
}

/* A fresh LU factor of D_h (hb->Dv), partial pivoting: FRICREG_OK, or FRICREG_ENOMEM /
 * FRICREG_EINVAL as klu_failed. A singular D_h gives FRICREG_OK with no factor (KLU stops at
 * its first zero pivot: status KLU_SINGULAR). */
static int factor_fresh(fricreg_hb *hb, const char *fn, struct fr_hb_lu *lu)
{
    SuiteSparse_long *Dp = (SuiteSparse_long *)hb->Dp, *Di = (SuiteSparse_long *)hb->Di;
    klu_zl_free_numeric(&lu->numeric, &hb->klu);
    lu->numeric = klu_zl_factor(Dp, Di, hb->Dv, hb->symbolic, &hb->klu);
    if (lu->numeric == NULL)
        return hb->klu.status == KLU_SINGULAR ? FRICREG_OK : klu_failed(hb, fn, "LU factor");
    if (!klu_zl_rgrowth(Dp, Di, hb->Dv, hb->symbolic, lu->numeric, &hb->klu))
        return klu_failed(hb, fn, "pivot growth");
    lu->fresh_rgrowth = hb->klu.rgrowth;
    return FRICREG_OK;
}

/* D_h (hb->Dv) factored in lu: refactored on the kept pivots if their growth stays within
 * REFACTOR_RGROWTH_MIN of the fresh factor's, afresh otherwise. */
static int factor(fricreg_hb *hb, const char *fn, struct fr_hb_lu *lu)
{
    SuiteSparse_long *Dp = (SuiteSparse_long *)hb->Dp, *Di = (SuiteSparse_long *)hb->Di;
    if (lu->numeric != NULL &&
        klu_zl_refactor(Dp, Di, hb->Dv, hb->symbolic, lu->numeric, &hb->klu) &&
        hb->klu.status == KLU_OK &&
        klu_zl_rgrowth(Dp, Di, hb->Dv, hb->symbolic, lu->numeric, &hb->klu) &&
        hb->klu.rgrowth >= REFACTOR_RGROWTH_MIN * lu->fresh_rgrowth)
        return FRICREG_OK;
    return factor_fresh(hb, fn, lu);
}

/* Y_h = D_h^-1 [J^T | P_h] (column m the load, zero but for h = 1) from D_h's factor, the
 * right-hand sides solved in place in the scratch Z. */
static void solve(fricreg_hb *hb, int h, struct fr_hb_lu *lu)
{
    size_t n = hb->n, m = hb->m, w = m + 1, nrhs = h == 1 ? w : m;
    double *Y = hb->Y + 2 * (size_t)h * n * w, *B = hb->Z;
    for (size_t e = 0; e < nrhs; e++)
        for (size_t k = 0; k < n; k++) {
            B[2 * (e * n + k)] = e < m ? hb->J[e * n + k] : hb->pc[k];
            B[2 * (e * n + k) + 1] = e < m ? 0.0 : -hb->ps[k];
        }
    if (nrhs > 0)
        klu_zl_solve(hb->symbolic, lu->numeric, (SuiteSparse_long)n, (SuiteSparse_long)nrhs, B,
                     &hb->klu);
    for (size_t k = 0; k < n; k++)
        for (size_t e = 0; e < w; e++) {
            Y[2 * (k * w + e)] = e < nrhs ? B[2 * (e * n + k)] : 0.0;
            Y[2 * (k * w + e) + 1] = e < nrhs ? B[2 * (e * n + k) + 1] : 0.0;
        }
}

/* D_h(omega)'s values into hb->Dv; returns the largest |K| + w² |M| + w |C| of an entry. */
static double form_values(fricreg_hb *hb, int h, double omega)
{
    double wh = h * omega, dmax = 0.0;
    for (size_t p = 0; p < hb->dnz; p++) {
        double im = wh * damping(hb, p);
        hb->Dv[2 * p] = hb->vK[p] - wh * wh * hb->vM[p];
        hb->Dv[2 * p + 1] = im;
        dmax = fmax(dmax, fabs(hb->vK[p]) + wh * wh * fabs(hb->vM[p]) + fabs(im));
    }
    return dmax;
}

/* The harmonics' factors are freed after their solves once they hold more than this. */
static int too_many_entries(const fricreg_hb *hb, const struct fr_hb_lu *lu)
{
    return (double)(lu->numeric->lnz + lu->numeric->unz) * (hb->H + 1) > KEPT_LU_ENTRIES_MAX;
}

/* D_h(omega) formed and factored in hb->lu[h] (KLU's analysis first if none), its pivots
 * checked: FRICREG_OK, FRICREG_ESINGULAR, FRICREG_ENONFINITE, FRICREG_ENOMEM. */
static int factor_at(fricreg_hb *hb, const char *fn, int h, double omega)
{
    double dmax = form_values(hb, h, omega);
    if (!isfinite(dmax))
        return fr_fail(hb, FRICREG_ENONFINITE,
                       "%s: the dynamic stiffness D_%d overflows at Omega = %g (|K| + w^2 |M| + w "
                       "|C| beyond the double range)",
                       fn, h, omega);
    if (hb->symbolic == NULL) {
        hb->symbolic = klu_l_analyze((SuiteSparse_long)hb->n, (SuiteSparse_long *)hb->Dp,
                                     (SuiteSparse_long *)hb->Di, &hb->klu);
        if (hb->symbolic == NULL)
            return klu_failed(hb, fn, "analysis");
    }
    struct fr_hb_lu *lu = &hb->lu[h];
    int status = factor(hb, fn, lu);
    if (status != FRICREG_OK)
        return status;
    int singular = lu->numeric == NULL || hb->klu.status == KLU_SINGULAR;
    if (!singular && !klu_zl_rcond(hb->symbolic, lu->numeric, &hb->klu))
        return klu_failed(hb, fn, "pivot ratio");
    double rcond = singular ? 0.0 : hb->klu.rcond;
    if (!(rcond > 1e-14)) {
        klu_zl_free_numeric(&lu->numeric, &hb->klu);
        return fr_fail(hb, FRICREG_ESINGULAR,
                       "%s: %s is singular at Omega = %g (KLU's LU factor: smallest over largest "
                       "pivot %g)",
                       fn, h == 0 ? "K" : "the dynamic stiffness D_h", omega, rcond);
    }
    return FRICREG_OK;
}

int fr_hb_sparse_solve(fricreg_hb *hb, const char *fn, int h, double omega)
{
    int status = factor_at(hb, fn, h, omega);
    if (status != FRICREG_OK)
        return status;
    struct fr_hb_lu *lu = &hb->lu[h];
    solve(hb, h, lu);
    if (too_many_entries(hb, lu))
        klu_zl_free_numeric(&lu->numeric, &hb->klu);
    return FRICREG_OK;
}

int fr_hb_sparse_solve_many(fricreg_hb *hb, const char *fn, int h, double omega, size_t nrhs,
                            double *B)
{
    int status = factor_at(hb, fn, h, omega);
    if (status != FRICREG_OK)
        return status;
    struct fr_hb_lu *lu = &hb->lu[h];
    if (nrhs > 0)
        klu_zl_solve(hb->symbolic, lu->numeric, (SuiteSparse_long)hb->n, (SuiteSparse_long)nrhs, B,
                     &hb->klu);
    if (too_many_entries(hb, lu))
        klu_zl_free_numeric(&lu->numeric, &hb->klu);
    return FRICREG_OK;
}

int fr_hb_sparse_condition(fricreg_hb *hb, const char *fn, int h, double omega, double *kappa)
{
    form_values(hb, h, omega);
    struct fr_hb_lu *lu = &hb->lu[h];
    int status = lu->numeric == NULL ? factor_fresh(hb, fn, lu) : FRICREG_OK;
    if (status != FRICREG_OK)
        return status;
    if (lu->numeric == NULL) /* fr_hb_sparse_solve refused it as singular at omega */
        return fr_fail(hb, FRICREG_ESINGULAR, "%s: D_%d is singular at Omega = %g", fn, h, omega);
    if (!klu_zl_condest((SuiteSparse_long *)hb->Dp, hb->Dv, hb->symbolic, lu->numeric, &hb->klu))
        return klu_failed(hb, fn, "condition estimate");
    *kappa = hb->klu.condest;
    if (too_many_entries(hb, lu))
        klu_zl_free_numeric(&lu->numeric, &hb->klu);
    return FRICREG_OK;
}

void fr_hb_sparse_derivative(fricreg_hb *hb, int h, double omega, const double *y, double *z)
{
    memset(z, 0, 2 * hb->n * sizeof(double));
    for (size_t j = 0; j < hb->n; j++)
        for (int64_t p = hb->Dp[j]; p < hb->Dp[j + 1]; p++) {
            size_t i = (size_t)hb->Di[p];
            double re = -2.0 * h * h * omega * hb->vM[p], im = h * damping(hb, (size_t)p);
            z[2 * i] += re * y[2 * j] - im * y[2 * j + 1];
            z[2 * i + 1] += re * y[2 * j + 1] + im * y[2 * j];
        }
}
