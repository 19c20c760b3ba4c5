/* SPDX-License-Identifier: GPL-3.0-or-later */
/* hb.c — the harmonic-balance driver (fricreg_hb.h): create and free, the model, element,
 * excitation and solver setters, each checking everything before it changes anything, and the
 * error record. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "base/matrix_input.h"
#include "base/sparse_factor.h"
#include "hb_internal.h"

#define MAX_DENSE_DOFS 4096
#define MAX_DOFS ((size_t)1 << 24)
#define MAX_ELEMENTS 256
/* samples of the 3-D contact element's AFT per coefficient (fr_hb_contact_samples) */
#define CONTACT_SAMPLES 64

static void *alloc_doubles(size_t count)
{
    return malloc((count ? count : 1) * sizeof(double));
}

/* The buffers sized by the rows of J, for cap rows of me elements (at most cap/me rows each):
 * J's block (J [cap n], kt, mun [me], pc, ps [n]), Y, Z (with colw), G (with ql, dG, dql),
 * fq's block (fq, jq, A, R, rw, dy, qw, qt, tan, yp (two), yo, tn, dir, yl, qsol) and piv2,
 * Newton's LU pivots. All or none. */
struct rows_buffers {
    double *J, *Y, *Z, *G, *fq;
    size_t *piv2;
};

/* Frees b and empties it (a second call does nothing). */
static void free_rows(struct rows_buffers *b)
{
    free(b->J);
    free(b->Y);
    free(b->Z);
    free(b->G);
    free(b->fq);
    free(b->piv2);
    *b = (struct rows_buffers){0};
}

static int alloc_rows(const fricreg_hb *hb, size_t cap, struct rows_buffers *b)
{
    size_t n = hb->n, me = hb->me, H1 = (size_t)hb->H + 1, nc = hb->nc, nq = cap * nc;
    *b = (struct rows_buffers){0};
    b->J = alloc_doubles(cap * n + 2 * me + 2 * n);
    b->Y = alloc_doubles(2 * H1 * n * (cap + 1));
    b->Z = alloc_doubles(2 * n * (cap + 1) + 2 * n);
    b->G = alloc_doubles(4 * H1 * cap * cap + 4 * H1 * cap);
    b->fq = alloc_doubles(nq + cap * (cap / me) * nc * nc + (nq + 1) * (nq + 1) + 12 * (nq + 1) +
                          nq);
    b->piv2 = malloc((nq + 1) * sizeof *b->piv2);
    if (!b->J || !b->Y || !b->Z || !b->G || !b->fq || !b->piv2) {
        free_rows(b);
        return FRICREG_ENOMEM;
    }
    memset(b->J, 0, (cap * n + 2 * me + 2 * n) * sizeof(double));
    return FRICREG_OK;
}

/* Installs b (room for cap rows), the excitation and the Jenkins parameters carried over from
 * the buffers it replaces, if any. */
static void install_rows(fricreg_hb *hb, size_t cap, struct rows_buffers *b)
{
    size_t n = hb->n, me = hb->me;
    if (hb->J != NULL)
        memcpy(b->J + cap * n, hb->kt, (2 * me + 2 * n) * sizeof(double));
    free(hb->J);
    free(hb->Y);
    free(hb->Z);
    free(hb->G);
    free(hb->fq);
    free(hb->piv2);
    hb->J = b->J;
    hb->Y = b->Y;
    hb->Z = b->Z;
    hb->G = b->G;
    hb->fq = b->fq;
    hb->piv2 = b->piv2;
    hb->rows_cap = cap;
    hb->kt = hb->J + cap * n;
    hb->mun = hb->kt + me;
    hb->pc = hb->mun + me;
    hb->ps = hb->pc + n;
}

/* The views into the buffers for rpe rows per element (m = rpe me rows, nq = m nc). */
static void set_rows(fricreg_hb *hb, size_t rpe)
{
    size_t n = hb->n, H1 = (size_t)hb->H + 1, nc = hb->nc;
    size_t m = rpe * hb->me, nq = m * nc;
    hb->rpe = rpe;
    hb->m = m;
    hb->nq = nq;
    hb->colw = hb->Z + 2 * n * (m + 1);
    hb->ql = hb->G + 2 * H1 * m * m;
    hb->dG = hb->ql + 2 * H1 * m;
    hb->dql = hb->dG + 2 * H1 * m * m;
    hb->jq = hb->fq + nq;
    hb->A = hb->jq + m * rpe * nc * nc;
    hb->R = hb->A + (nq + 1) * (nq + 1);
    hb->rw = hb->R + (nq + 1);
    hb->dy = hb->rw + (nq + 1);
    hb->qw = hb->dy + (nq + 1);
    hb->qt = hb->qw + (nq + 1);
    hb->tan = hb->qt + (nq + 1);
    hb->yp = hb->tan + (nq + 1);
    hb->yo = hb->yp + 2 * (nq + 1);
    hb->tn = hb->yo + (nq + 1);
    hb->dir = hb->tn + (nq + 1);
    hb->yl = hb->dir + (nq + 1);
    hb->qsol = hb->yl + (nq + 1);
}

int fricreg_hb_create(size_t ndof, size_t m, int harmonics, fricreg_hb **out)
{
    if (out == NULL)
        return FRICREG_ENULL;
    if (ndof == 0 || ndof > MAX_DOFS || m == 0 || m > MAX_ELEMENTS || harmonics < 1 ||
        harmonics > FRICREG_HB_MAX_HARMONICS)
        return FRICREG_EINVAL;
    fricreg_hb *hb = calloc(1, sizeof *hb);
    if (hb == NULL)
        return FRICREG_ENOMEM;
    size_t n = ndof, nc = 2 * (size_t)harmonics + 1;
    *hb = (fricreg_hb){.n = n,
                       .me = m,
                       .H = harmonics,
                       .nc = nc,
                       .ns = 1,
                       .tol = 1e-10,
                       .max_iter = 50,
                       .ds0 = 0.02,
                       .ds_min = 1e-6,
                       .ds_max = 0.1,
                       .max_points = 2000,
                       .level = 1.0,
                       .level_sol = 1.0,
                       .factored_omega = NAN};
    /* up to 4096 dofs the dense model, as the dense setters leave it; beyond, sparse only */
    int dense = n <= MAX_DENSE_DOFS;
    hb->M = dense ? calloc(3 * n * n, sizeof(double)) : NULL; /* untouched until set */
    hb->D = dense ? alloc_doubles(2 * n * n) : NULL;
    hb->piv = dense ? malloc(n * sizeof *hb->piv) : NULL;
    struct rows_buffers b;
    int rows = alloc_rows(hb, m, &b);
    if (rows == FRICREG_OK)
        install_rows(hb, m, &b);
    int status = fricreg_aft_create(harmonics, 0, &hb->aft);
    int started = fr_cholmod_start(&hb->cc) == FRICREG_OK;
    if ((dense && (!hb->M || !hb->D || !hb->piv)) || rows != FRICREG_OK || status != FRICREG_OK ||
        !started || (!dense && fr_hb_sparse_defaults(hb) != FRICREG_OK)) {
        fricreg_hb_free(hb);
        return FRICREG_ENOMEM;
    }
    if (dense) {
        hb->C = hb->M + n * n;
        hb->K = hb->C + n * n;
        for (size_t k = 0; k < n; k++)
            hb->M[k * n + k] = 1.0;
    }
    set_rows(hb, 1);
    *out = hb;
    return FRICREG_OK;
}

void fricreg_hb_free(fricreg_hb *hb)
{
    if (hb == NULL)
        return;
    free(hb->M);
    free(hb->J);
    free(hb->D);
    free(hb->Y);
    free(hb->Z);
    free(hb->G);
    free(hb->fq);
    free(hb->piv);
    free(hb->piv2);
    free(hb->pts);
    free(hb->qpts);
    free(hb->xpts);
    free(hb->bifs);
    fr_hb_hill_free(hb);
    fricreg_aft_free(hb->aft);
    fricreg_aft_free(hb->aft_half);
    free(hb->half);
    free(hb->sk);
    free(hb->nl);
    fr_hb_nma_free(hb->nma);
    fr_hb_sparse_free(hb);
    fr_cholmod_finish(&hb->cc);
    free(hb);
}

/* A driver at harmonics H with src's model (dense or sparse M, C, K, Rayleigh damping),
 * elements (Jenkins, Iwan, lift-off or 3-D contact), excitation, Newton's settings, monitor and
 * bound: the companion of fricreg_hb_truncation_error. Nothing of src changes. */
int fr_hb_clone(const fricreg_hb *src, int harmonics, fricreg_hb **out)
{
    fricreg_hb *hb = NULL;
    size_t n = src->n, me = src->me;
    int status = fricreg_hb_create(n, me, harmonics, &hb);
    if (status != FRICREG_OK)
        return status;
    struct rows_buffers b = {0};
    double *nl = src->nl ? malloc(4 * me * sizeof *nl) : NULL;
    size_t sliders = fr_hb_slider_doubles(me, src->ns, src->nl != NULL, 2 * (size_t)harmonics + 1);
    double *sk = src->sk ? malloc(sliders * sizeof *sk) : NULL;
    if ((src->nl && (!nl || alloc_rows(hb, src->rpe * me, &b) != FRICREG_OK)) || (src->sk && !sk) ||
        (src->rpe == 3 && fr_hb_sampled_aft(hb) != FRICREG_OK) ||
        (src->sparse && fr_hb_sparse_copy(hb, src) != FRICREG_OK)) {
        free(nl);
        free(sk);
        fricreg_hb_free(hb);
        return FRICREG_ENOMEM;
    }
    if (b.J != NULL)
        install_rows(hb, src->rpe * me, &b);
    if (!src->sparse) /* M, C, K: one block */
        memcpy(hb->M, src->M, 3 * n * n * sizeof(double));
    hb->rayleigh = src->rayleigh;
    hb->a0 = src->a0;
    hb->a1 = src->a1;
    memcpy(hb->J, src->J, src->m * n * sizeof(double));
    memcpy(hb->kt, src->kt, (2 * me + 2 * n) * sizeof(double)); /* kt, mun, pc, ps */
    if (nl != NULL)
        memcpy(nl, src->nl, 4 * me * sizeof *nl);
    if (sk != NULL)
        memcpy(sk, src->sk, 2 * me * src->ns * sizeof *sk);
    hb->nl = nl;
    hb->sk = sk;
    hb->ns = src->ns;
    set_rows(hb, src->rpe);
    hb->have_elements = src->have_elements;
    hb->tol = src->tol;
    hb->max_iter = src->max_iter;
    hb->monitor = src->monitor;
    hb->monitor_user = src->monitor_user;
    hb->max_iterations = src->max_iterations;
    *out = hb;
    return FRICREG_OK;
}

/* A model change: the factors, the kept solution and the branch's unknowns no longer hold. */
static void invalidate(fricreg_hb *hb)
{
    hb->factored_omega = NAN;
    hb->have_solution = 0;
    hb->have_branch = 0;
    hb->have_backbone = 0;
}

static int check_ndof(fricreg_hb *hb, const char *fn, size_t ndof)
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
    if (hb == NULL)
        return FRICREG_ENULL;
    if (hb->busy)
        return fr_hb_busy(hb, fn);
    if (A == NULL)
        return fr_fail(hb, FRICREG_ENULL, "%s: the matrix is NULL", fn);
    if (check_ndof(hb, fn, ndof) != FRICREG_OK)
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
    for (size_t i = 0; i < n; i++)
        for (size_t k = 0; k < n; k++)
            dst[i * n + k] = 0.5 * A[i * n + k] + 0.5 * A[k * n + i]; /* no overflow near 1e308 */
    invalidate(hb);
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
    if (hb == NULL)
        return FRICREG_ENULL;
    if (hb->busy)
        return fr_hb_busy(hb, fn);
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
    if (hb == NULL)
        return FRICREG_ENULL;
    if (hb->busy)
        return fr_hb_busy(hb, "set_rayleigh");
    if (!isfinite(a0) || !isfinite(a1))
        return fr_fail(hb, FRICREG_ENONFINITE, "set_rayleigh: a0 = %g, a1 = %g", a0, a1);
    if (a0 < 0.0 || a1 < 0.0)
        return fr_fail(hb, FRICREG_EINVAL, "set_rayleigh: a0 = %g and a1 = %g must be >= 0", a0,
                       a1);
    hb->rayleigh = 1;
    hb->a0 = a0;
    hb->a1 = a1;
    invalidate(hb);
    return FRICREG_OK;
}

/* J's rows[ndof]: finite, none zero, named name. */
static int check_entries(fricreg_hb *hb, const char *fn, size_t rows, size_t ndof, const double *J,
                         const char *name)
{
    for (size_t i = 0; i < rows; i++) {
        double norm = 0.0;
        for (size_t k = 0; k < ndof; k++) {
            if (!isfinite(J[i * ndof + k]))
                return fr_fail(hb, FRICREG_ENONFINITE, "%s: %s(%zu, %zu) = %g", fn, name, i, k,
                               J[i * ndof + k]);
            norm += fabs(J[i * ndof + k]);
        }
        if (norm == 0.0)
            return fr_fail(hb, FRICREG_EINVAL, "%s: row %zu of %s is zero", fn, i, name);
    }
    return FRICREG_OK;
}

/* The checks the element setters share: the sizes and J (rows_per_element m rows), named
 * name. */
static int check_rows(fricreg_hb *hb, const char *fn, size_t m, size_t rows_per_element,
                      size_t ndof, const double *J, const char *name)
{
    if (m != hb->me)
        return fr_fail(hb, FRICREG_ESIZE, "%s: m = %zu, the driver has %zu", fn, m, hb->me);
    if (check_ndof(hb, fn, ndof) != FRICREG_OK)
        return FRICREG_ESIZE;
    return check_entries(hb, fn, rows_per_element * m, ndof, J, name);
}

/* Jenkins or Iwan elements: one row each, the normal elements' parameters dropped. */
static void one_row_elements(fricreg_hb *hb)
{
    free(hb->nl);
    hb->nl = NULL;
    set_rows(hb, 1);
}

/* The sliders' parameters: finite, stiffness > 0, slip force >= 0. */
static int check_sliders(fricreg_hb *hb, const char *fn, size_t count, const double *k,
                         const double *phi, const char *kname, const char *pname)
{
    for (size_t i = 0; i < count; i++) {
        if (!isfinite(k[i]) || !isfinite(phi[i]))
            return fr_fail(hb, FRICREG_ENONFINITE, "%s: %s[%zu] = %g, %s[%zu] = %g", fn, kname, i,
                           k[i], pname, i, phi[i]);
        if (!(k[i] > 0.0) || !(phi[i] >= 0.0))
            return fr_fail(hb, FRICREG_EINVAL, "%s: %s[%zu] = %g must be > 0, %s[%zu] = %g >= 0",
                           fn, kname, i, k[i], pname, i, phi[i]);
    }
    return FRICREG_OK;
}

/* fricreg_hb_set_jenkins, its messages naming fn. */
static int set_jenkins(fricreg_hb *hb, const char *fn, size_t m, size_t ndof, const double J[],
                       const double kt[], const double mun[])
{
    if (hb == NULL)
        return FRICREG_ENULL;
    if (hb->busy)
        return fr_hb_busy(hb, fn);
    if (J == NULL || kt == NULL || mun == NULL)
        return fr_fail(hb, FRICREG_ENULL, "%s: %s is NULL", fn,
                       J == NULL    ? "J"
                       : kt == NULL ? "kt"
                                    : "mun");
    int status = check_rows(hb, fn, m, 1, ndof, J, "J");
    if (status == FRICREG_OK)
        status = check_sliders(hb, fn, m, kt, mun, "kt", "mun");
    if (status != FRICREG_OK)
        return status;
    memcpy(hb->J, J, m * ndof * sizeof *J);
    memcpy(hb->kt, kt, m * sizeof *kt);
    memcpy(hb->mun, mun, m * sizeof *mun);
    free(hb->sk); /* Jenkins elements: one slider each, kt and mun */
    hb->sk = NULL;
    hb->ns = 1;
    one_row_elements(hb);
    hb->have_elements = 1;
    invalidate(hb);
    return FRICREG_OK;
}

int fricreg_hb_set_jenkins(fricreg_hb *hb, size_t m, size_t ndof, const double J[],
                           const double kt[], const double mun[])
{
    return set_jenkins(hb, "set_jenkins", m, ndof, J, kt, mun);
}

int fricreg_hb_set_elements(fricreg_hb *hb, size_t m, size_t ndof, const double J[],
                            const double kt[], const double mun[])
{
    return set_jenkins(hb, "set_elements", m, ndof, J, kt, mun);
}

int fricreg_hb_set_iwan(fricreg_hb *hb, size_t m, size_t ndof, const double J[], size_t ns,
                        const double k[], const double phi[])
{
    static const char fn[] = "set_iwan";
    if (hb == NULL)
        return FRICREG_ENULL;
    if (hb->busy)
        return fr_hb_busy(hb, fn);
    if (J == NULL || k == NULL || phi == NULL)
        return fr_fail(hb, FRICREG_ENULL, "%s: %s is NULL", fn,
                       J == NULL   ? "J"
                       : k == NULL ? "k"
                                   : "phi");
    int status = check_rows(hb, fn, m, 1, ndof, J, "J");
    if (status != FRICREG_OK)
        return status;
    if (ns < 1 || ns > FRICREG_HB_MAX_SLIDERS)
        return fr_fail(hb, FRICREG_EINVAL, "%s: ns = %zu sliders, must be in [1, %d]", fn, ns,
                       FRICREG_HB_MAX_SLIDERS);
    if ((status = check_sliders(hb, fn, m * ns, k, phi, "k", "phi")) != FRICREG_OK)
        return status;
    double *sk = malloc(2 * m * ns * sizeof *sk);
    if (sk == NULL)
        return fr_fail(hb, FRICREG_ENOMEM, "%s: no memory for %zu sliders", fn, m * ns);
    memcpy(sk, k, m * ns * sizeof *sk);
    memcpy(sk + m * ns, phi, m * ns * sizeof *sk);
    memcpy(hb->J, J, m * ndof * sizeof *J);
    free(hb->sk);
    hb->sk = sk;
    hb->ns = ns;
    one_row_elements(hb);
    hb->have_elements = 1;
    invalidate(hb);
    return FRICREG_OK;
}

/* The normal law's n0 finite and kn >= 0, finite, for Iwan elements (the Jenkins elements'
 * one message names kt and mu as well). */
static int check_normal_law(fricreg_hb *hb, const char *fn, size_t m, const double n0[],
                            const double kn[])
{
    for (size_t i = 0; i < m; i++) {
        if (!isfinite(n0[i]) || !isfinite(kn[i]))
            return fr_fail(hb, FRICREG_ENONFINITE, "%s: n0[%zu] = %g, kn[%zu] = %g", fn, i, n0[i],
                           i, kn[i]);
        if (!(kn[i] >= 0.0))
            return fr_fail(hb, FRICREG_EINVAL, "%s: kn[%zu] = %g must be >= 0", fn, i, kn[i]);
    }
    return FRICREG_OK;
}

/* Jenkins elements' (ns = 1) or Iwan elements' (ns sliders) parameters with a normal law. */
static int check_normal_sliders(fricreg_hb *hb, const char *fn, size_t m, size_t ns,
                                const double k[], const double mu[], const double n0[],
                                const double kn[])
{
    if (ns > 1) {
        int status = check_sliders(hb, fn, m * ns, k, mu, "k", "mu");
        return status != FRICREG_OK ? status : check_normal_law(hb, fn, m, n0, kn);
    }
    for (size_t i = 0; i < m; i++) {
        if (!isfinite(k[i]) || !isfinite(mu[i]) || !isfinite(n0[i]) || !isfinite(kn[i]))
            return fr_fail(hb, FRICREG_ENONFINITE,
                           "%s: kt[%zu] = %g, mu[%zu] = %g, n0[%zu] = %g, kn[%zu] = %g", fn, i,
                           k[i], i, mu[i], i, n0[i], i, kn[i]);
        if (!(k[i] > 0.0) || !(mu[i] >= 0.0) || !(kn[i] >= 0.0))
            return fr_fail(hb, FRICREG_EINVAL,
                           "%s: kt[%zu] = %g must be > 0, mu[%zu] = %g >= 0, kn[%zu] = %g >= 0", fn,
                           i, k[i], i, mu[i], i, kn[i]);
    }
    return FRICREG_OK;
}

/* The normal law's [4 m] kt, mu, n0, kn: an Iwan element's kt the sum of its sliders' k (its
 * stuck stiffness) and mu the sum of theirs. */
static void normal_parameters(double *nl, size_t m, size_t ns, const double k[], const double mu[],
                              const double n0[], const double kn[])
{
    for (size_t i = 0; i < m; i++) {
        double ksum = 0.0, musum = 0.0;
        for (size_t j = i * ns; j < (i + 1) * ns; j++) {
            ksum += k[j];
            musum += mu[j];
        }
        nl[i] = ksum;
        nl[m + i] = musum;
    }
    memcpy(nl + 2 * m, n0, m * sizeof *nl);
    memcpy(nl + 3 * m, kn, m * sizeof *nl);
}

size_t fr_hb_slider_doubles(size_t me, size_t ns, int normal, size_t nc)
{
    return 2 * me * ns + (normal && ns > 1 ? 2 * nc + 4 * nc * nc : 0);
}

/* fricreg_hb_set_jenkins_normal (ns = 1: k = kt) and fricreg_hb_set_iwan_normal, their
 * messages naming fn. */
static int set_normal(fricreg_hb *hb, const char *fn, size_t m, size_t ndof, const double Jt[],
                      const double Jn[], size_t ns, const double k[], const double mu[],
                      const double n0[], const double kn[])
{
    if (hb == NULL)
        return FRICREG_ENULL;
    if (hb->busy)
        return fr_hb_busy(hb, fn);
    const void *args[6] = {Jt, Jn, k, mu, n0, kn};
    static const char *const names[6] = {"Jt", "Jn", "kt", "mu", "n0", "kn"};
    for (int a = 0; a < 6; a++)
        if (args[a] == NULL)
            return fr_fail(hb, FRICREG_ENULL, "%s: %s is NULL", fn,
                           a == 2 && ns > 1 ? "k" : names[a]);
    int status = check_rows(hb, fn, m, 1, ndof, Jt, "Jt");
    if (status == FRICREG_OK)
        status = check_rows(hb, fn, m, 1, ndof, Jn, "Jn");
    if (status != FRICREG_OK)
        return status;
    if (ns < 1 || ns > FRICREG_HB_MAX_SLIDERS)
        return fr_fail(hb, FRICREG_EINVAL, "%s: ns = %zu sliders, must be in [1, %d]", fn, ns,
                       FRICREG_HB_MAX_SLIDERS);
    if ((status = check_normal_sliders(hb, fn, m, ns, k, mu, n0, kn)) != FRICREG_OK)
        return status;
    /* two rows an element: the buffers sized by the rows grow once (and stay) */
    struct rows_buffers b = {0};
    double *nl = malloc(4 * m * sizeof *nl), *sk = NULL;
    if (ns > 1) /* the sliders, and room for one slider's AFT (residual.c) */
        sk = malloc(fr_hb_slider_doubles(m, ns, 1, hb->nc) * sizeof *sk);
    if (nl == NULL || (ns > 1 && sk == NULL) ||
        (hb->rows_cap < 2 * m && alloc_rows(hb, 2 * m, &b) != FRICREG_OK)) {
        free(nl);
        free(sk);
        return fr_fail(hb, FRICREG_ENOMEM, "%s: no memory for %zu elements with lift-off", fn, m);
    }
    if (b.J != NULL)
        install_rows(hb, 2 * m, &b);
    for (size_t i = 0; i < m; i++) {
        memcpy(hb->J + 2 * i * ndof, Jt + i * ndof, ndof * sizeof *Jt);
        memcpy(hb->J + (2 * i + 1) * ndof, Jn + i * ndof, ndof * sizeof *Jn);
    }
    normal_parameters(nl, m, ns, k, mu, n0, kn);
    if (sk != NULL) {
        memcpy(sk, k, m * ns * sizeof *sk);
        memcpy(sk + m * ns, mu, m * ns * sizeof *sk);
    }
    free(hb->nl);
    hb->nl = nl;
    free(hb->sk);
    hb->sk = sk;
    hb->ns = ns;
    set_rows(hb, 2);
    hb->have_elements = 1;
    invalidate(hb);
    return FRICREG_OK;
}

int fricreg_hb_set_jenkins_normal(fricreg_hb *hb, size_t m, size_t ndof, const double Jt[],
                                  const double Jn[], const double kt[], const double mu[],
                                  const double n0[], const double kn[])
{
    return set_normal(hb, "set_jenkins_normal", m, ndof, Jt, Jn, 1, kt, mu, n0, kn);
}

int fricreg_hb_set_normal_elements(fricreg_hb *hb, size_t m, size_t ndof, const double Jt[],
                                   const double Jn[], const double kt[], const double mu[],
                                   const double n0[], const double kn[])
{
    return set_normal(hb, "set_normal_elements", m, ndof, Jt, Jn, 1, kt, mu, n0, kn);
}

int fricreg_hb_set_iwan_normal(fricreg_hb *hb, size_t m, size_t ndof, const double Jt[],
                               const double Jn[], size_t ns, const double k[], const double mu[],
                               const double n0[], const double kn[])
{
    return set_normal(hb, "set_iwan_normal", m, ndof, Jt, Jn, ns, k, mu, n0, kn);
}

size_t fr_hb_contact_samples(int harmonics)
{
    size_t want = CONTACT_SAMPLES * (2 * (size_t)harmonics + 1), N = 1;
    while (N < want)
        N *= 2;
    return N;
}

/* hb's AFT workspace with the 3-D contact element's samples at its harmonics (kept if it has
 * them). FRICREG_OK or FRICREG_ENOMEM, hb unchanged. */
int fr_hb_sampled_aft(fricreg_hb *hb)
{
    size_t N = fr_hb_contact_samples(hb->H), nc = hb->nc;
    if (fricreg_aft_samples(hb->aft) == N && hb->aft_half != NULL)
        return FRICREG_OK;
    fricreg_aft *aft = NULL, *half = NULL;
    double *results = malloc((3 * nc + 9 * nc * nc) * sizeof *results);
    if (results == NULL || fricreg_aft_create(hb->H, N, &aft) != FRICREG_OK ||
        fricreg_aft_create(hb->H, N / 2, &half) != FRICREG_OK) {
        free(results);
        fricreg_aft_free(aft);
        return FRICREG_ENOMEM;
    }
    fricreg_aft_free(hb->aft);
    fricreg_aft_free(hb->aft_half);
    free(hb->half);
    hb->aft = aft;
    hb->aft_half = half;
    hb->half = results;
    return FRICREG_OK;
}

int fricreg_hb_set_jenkins_2d_normal(fricreg_hb *hb, size_t m, size_t ndof, const double Je[],
                                     const double Jn[], const double kt[], const double mu[],
                                     const double n0[], const double kn[])
{
    static const char fn[] = "set_jenkins_2d_normal";
    if (hb == NULL)
        return FRICREG_ENULL;
    if (hb->busy)
        return fr_hb_busy(hb, fn);
    const void *args[6] = {Je, Jn, kt, mu, n0, kn};
    static const char *const names[6] = {"Je", "Jn", "kt", "mu", "n0", "kn"};
    for (int a = 0; a < 6; a++)
        if (args[a] == NULL)
            return fr_fail(hb, FRICREG_ENULL, "%s: %s is NULL", fn, names[a]);
    int status = check_rows(hb, fn, m, 2, ndof, Je, "Je");
    if (status == FRICREG_OK)
        status = check_rows(hb, fn, m, 1, ndof, Jn, "Jn");
    if (status == FRICREG_OK)
        status = check_normal_sliders(hb, fn, m, 1, kt, mu, n0, kn);
    if (status != FRICREG_OK)
        return status;
    /* three rows an element (x, y, n), the sampled AFT: the buffers grow once (and stay) */
    struct rows_buffers b = {0};
    double *nl = malloc(4 * m * sizeof *nl);
    if (nl == NULL || (hb->rows_cap < 3 * m && alloc_rows(hb, 3 * m, &b) != FRICREG_OK) ||
        fr_hb_sampled_aft(hb) != FRICREG_OK) {
        free(nl);
        free_rows(&b);
        return fr_fail(hb, FRICREG_ENOMEM, "%s: no memory for %zu 3-D contact elements", fn, m);
    }
    if (b.J != NULL)
        install_rows(hb, 3 * m, &b);
    for (size_t i = 0; i < m; i++) {
        memcpy(hb->J + 3 * i * ndof, Je + 2 * i * ndof, 2 * ndof * sizeof *Je);
        memcpy(hb->J + (3 * i + 2) * ndof, Jn + i * ndof, ndof * sizeof *Jn);
    }
    normal_parameters(nl, m, 1, kt, mu, n0, kn);
    free(hb->nl);
    hb->nl = nl;
    free(hb->sk);
    hb->sk = NULL;
    hb->ns = 1;
    set_rows(hb, 3);
    hb->have_elements = 1;
    invalidate(hb);
    return FRICREG_OK;
}

int fricreg_hb_set_excitation(fricreg_hb *hb, size_t ndof, const double pc[], const double ps[])
{
    if (hb == NULL)
        return FRICREG_ENULL;
    if (hb->busy)
        return fr_hb_busy(hb, "set_excitation");
    if (pc == NULL || ps == NULL)
        return fr_fail(hb, FRICREG_ENULL, "set_excitation: %s is NULL", pc == NULL ? "pc" : "ps");
    if (check_ndof(hb, "set_excitation", ndof) != FRICREG_OK)
        return FRICREG_ESIZE;
    for (size_t k = 0; k < ndof; k++)
        if (!isfinite(pc[k]) || !isfinite(ps[k]))
            return fr_fail(hb, FRICREG_ENONFINITE, "set_excitation: pc[%zu] = %g, ps[%zu] = %g", k,
                           pc[k], k, ps[k]);
    memcpy(hb->pc, pc, ndof * sizeof *pc);
    memcpy(hb->ps, ps, ndof * sizeof *ps);
    invalidate(hb);
    return FRICREG_OK;
}

int fricreg_hb_set_newton(fricreg_hb *hb, double tol, int max_iter)
{
    if (hb == NULL)
        return FRICREG_ENULL;
    if (hb->busy)
        return fr_hb_busy(hb, "set_newton");
    if (!isfinite(tol))
        return fr_fail(hb, FRICREG_ENONFINITE, "set_newton: tol = %g", tol);
    if (!(tol > 0.0 && tol < 1.0) || max_iter < 1 || max_iter > 1000)
        return fr_fail(hb, FRICREG_EINVAL,
                       "set_newton: tol = %g must be in (0, 1), max_iter = %d in [1, 1000]", tol,
                       max_iter);
    hb->tol = tol;
    hb->max_iter = max_iter;
    return FRICREG_OK;
}

int fricreg_hb_set_continuation(fricreg_hb *hb, double ds, double ds_min, double ds_max,
                                size_t max_points)
{
    if (hb == NULL)
        return FRICREG_ENULL;
    if (hb->busy)
        return fr_hb_busy(hb, "set_continuation");
    if (!isfinite(ds) || !isfinite(ds_min) || !isfinite(ds_max))
        return fr_fail(hb, FRICREG_ENONFINITE,
                       "set_continuation: ds = %g, ds_min = %g, ds_max = %g", ds, ds_min, ds_max);
    if (!(ds_min > 0.0 && ds_min <= ds && ds <= ds_max && ds_max <= 1.0) || max_points < 2)
        return fr_fail(hb, FRICREG_EINVAL,
                       "set_continuation: need 0 < ds_min = %g <= ds = %g <= ds_max = %g <= 1 and "
                       "max_points = %zu >= 2",
                       ds_min, ds, ds_max, max_points);
    hb->ds0 = ds;
    hb->ds_min = ds_min;
    hb->ds_max = ds_max;
    hb->max_points = max_points;
    return FRICREG_OK;
}

int fricreg_hb_errcode(const fricreg_hb *hb)
{
    return hb ? hb->err.code : FRICREG_OK;
}

const char *fricreg_hb_errmsg(const fricreg_hb *hb)
{
    return hb ? hb->err.msg : "NULL HB driver";
}

size_t fricreg_hb_errmsg_copy(const fricreg_hb *hb, char *buf, size_t len)
{
    return fr_error_copy(fricreg_hb_errmsg(hb), buf, len);
}
