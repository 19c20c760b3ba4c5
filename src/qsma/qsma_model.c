/* SPDX-License-Identifier: GPL-3.0-or-later */
/* qsma_model.c — the driver's model as quasi-static modal analysis takes it (qsma_internal.h):
 * M, K and C dense (a sparse model's spread out), its elements as sliders and 3-D contacts, and
 * the tangent K_t = K + J^T diag(k_r) J of the sliders stuck, factored by LAPACK's Cholesky.
 * Jenkins and iwan elements load piecewise linearly, so that their path is exact (qsma_path.c);
 * 3-D contacts and Jenkins elements with lift-off are marched (qsma_march.c); the others (iwan
 * with lift-off, marched laws) are refused by name. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/free_all.h"
#include "base/lapack.h"
#include "fricreg_element.h"
#include "qsma_internal.h"

void fr_qsma_free(struct fr_qsma *s)
{
    if (s == NULL)
        return;
    FR_FREE_ALL(s->K, s->row, s->sigma, s->con);
    free(s);
}

/* M, K and C (Rayleigh's a0 M + a1 K where set) as n x n row-major. */
static void densify(const fricreg_hb *hb, struct fr_qsma *s)
{
    size_t n = hb->n;
    if (hb->sparse) {
        memset(s->K, 0, 3 * n * n * sizeof *s->K);
        for (size_t j = 0; j < n; j++)
            for (int64_t p = hb->Dp[j]; p < hb->Dp[j + 1]; p++) {
                size_t i = (size_t)hb->Di[p];
                s->M[i * n + j] = hb->vM[p];
                s->K[i * n + j] = hb->vK[p];
                s->C[i * n + j] = hb->rayleigh ? 0.0 : hb->vC[p]; /* Rayleigh's: below */
            }
    } else {
        memcpy(s->M, hb->M, n * n * sizeof *s->M);
        memcpy(s->K, hb->K, n * n * sizeof *s->K);
        memcpy(s->C, hb->C, n * n * sizeof *s->C);
    }
    if (hb->rayleigh)
        for (size_t k = 0; k < n * n; k++)
            s->C[k] = hb->a0 * s->M[k] + hb->a1 * s->K[k];
}

/* Every element jenkins, iwan (one row of J, sliders), jenkins_normal or contact_3d; the first
 * that is not, named. */
static int check_kinds(fricreg_hb *hb, const char *fn)
{
    static const char *const names[] = {"", "jenkins/iwan", "iwan_normal", "contact_3d"};
    for (size_t e = 0; e < hb->count; e++)
        if (hb->kind[e] != FR_HB_SLIDERS && !fr_qsma_has_normal(hb, e))
            return fr_fail(hb, FRICREG_EINVAL,
                           "%s: element %zu is of type %s: quasi-static modal analysis takes "
                           "jenkins, iwan, jenkins_normal and contact_3d elements only "
                           "(fricreg_hb_nma for the others)",
                           fn, e,
                           hb->kind[e] == FR_HB_MARCH ? fricreg_element_name(hb->etype[e])
                                                      : names[hb->kind[e]]);
    return FRICREG_OK;
}

/* The sliders of positive slip force, with their rows, elements and places; the contacts. */
static void list_sliders(const fricreg_hb *hb, struct fr_qsma *s)
{
    size_t k = 0;
    s->ncon = 0;
    s->nst = 0;
    for (size_t e = 0; e < hb->count; e++) {
        const double *ks, *phi;
        if (fr_qsma_has_normal(hb, e)) {
            s->con[s->ncon++] = e;
            s->nst += (size_t)fr_qsma_tangential_rows(hb, e);
            continue;
        }
        size_t ns = fr_hb_sliders(hb, e, &ks, &phi);
        for (size_t j = 0; j < ns; j++)
            if (phi[j] > 0.0) {
                s->row[k] = hb->erow[e];
                s->elem[k] = e;
                s->loc[k] = j;
                s->ks[k] = ks[j];
                s->fs[k] = phi[j];
                s->sigma[k++] = 0;
            }
    }
    s->nsl = k;
    s->nst += k;
}

/* Each row's stiffness with every element stuck (an element with a normal law closed by its
 * preload n0 > 0: kt on its tangential rows where mu > 0, kn on its normal one). */
static void stuck_rows(const fricreg_hb *hb, struct fr_qsma *s)
{
    size_t me = hb->me;
    memset(s->kr, 0, s->m * sizeof *s->kr);
    for (size_t k = 0; k < s->nsl; k++)
        s->kr[s->row[k]] += s->ks[k];
    for (size_t c = 0; c < s->ncon; c++) {
        size_t e = s->con[c], r = hb->erow[e], dim = (size_t)fr_qsma_tangential_rows(hb, e);
        if (!(hb->nl[2 * me + e] > 0.0))
            continue;
        for (size_t a = 0; a < dim && hb->nl[me + e] > 0.0; a++)
            s->kr[r + a] = hb->nl[e];
        s->kr[r + dim] = hb->nl[3 * me + e];
    }
}

static struct fr_qsma *alloc(size_t n, size_t m, size_t nsl, size_t ncon)
{
    struct fr_qsma *s = calloc(1, sizeof *s);
    if (s == NULL)
        return NULL;
    s->K = malloc((4 * n * n + 5 * n + 3 * m + 3 * nsl + 1) * sizeof *s->K);
    s->row = malloc((3 * nsl + 1) * sizeof *s->row);
    s->sigma = malloc((nsl + 1) * sizeof *s->sigma);
    s->con = malloc((ncon + 1) * sizeof *s->con);
    if (s->K == NULL || s->row == NULL || s->sigma == NULL || s->con == NULL) {
        fr_qsma_free(s);
        return NULL;
    }
    s->n = n;
    s->m = m;
    s->C = s->K + n * n;
    s->M = s->C + n * n;
    s->Kt = s->M + n * n;
    double *v = s->Kt + n * n, **vecs[5] = {&s->phi, &s->b, &s->c, &s->x, &s->v};
    for (int k = 0; k < 5; k++)
        *vecs[k] = v + (size_t)k * n;
    s->ur = v + 5 * n;
    s->vr = s->ur + m;
    s->kr = s->vr + m;
    s->ks = s->kr + m;
    s->fs = s->ks + nsl;
    s->z = s->fs + nsl;
    s->elem = s->row + nsl;
    s->loc = s->elem + nsl;
    return s;
}

int fr_qsma_create(fricreg_hb *hb, const char *fn, struct fr_qsma **out)
{
    int status = check_kinds(hb, fn);
    if (status != FRICREG_OK)
        return status;
    if (hb->n > FR_QSMA_MAX_DOFS)
        return fr_fail(hb, FRICREG_EINVAL,
                       "%s: %zu dofs; quasi-static modal analysis solves the dense tangent, up "
                       "to %d dofs",
                       fn, hb->n, FR_QSMA_MAX_DOFS);
    size_t ncon = 0;
    for (size_t e = 0; e < hb->count; e++)
        ncon += (size_t)fr_qsma_has_normal(hb, e);
    struct fr_qsma *s = alloc(hb->n, hb->m, hb->nsl, ncon);
    if (s == NULL)
        return fr_fail(hb, FRICREG_ENOMEM, "%s: no memory for a model of %zu dofs", fn, hb->n);
    densify(hb, s);
    list_sliders(hb, s);
    if (s->nsl == 0 && s->ncon == 0) {
        fr_qsma_free(s);
        return fr_fail(hb, FRICREG_EINVAL, "%s: no slider of positive slip force", fn);
    }
    stuck_rows(hb, s);
    *out = s;
    return FRICREG_OK;
}

void fr_qsma_assemble(const struct fr_qsma *s, const double *J, double *A)
{
    size_t n = s->n;
    memcpy(A, s->K, n * n * sizeof *A);
    for (size_t r = 0; r < s->m; r++) {
        const double *Jr = J + r * n;
        for (size_t i = 0; i < n && s->kr[r] != 0.0; i++)
            for (size_t j = 0; j < n && Jr[i] != 0.0; j++)
                A[i * n + j] += s->kr[r] * Jr[i] * Jr[j];
    }
}

int fr_qsma_tangent(struct fr_qsma *s, const double *J)
{
    size_t n = s->n;
    fr_qsma_assemble(s, J, s->Kt);
    double dmax = 0.0;
    for (size_t i = 0; i < n; i++)
        dmax = fmax(dmax, s->Kt[i * n + i]);
    int nn = (int)n, info = 0, one = 1;
    dpotrf_("L", &nn, s->Kt, &nn, &info, 1);
    /* an exactly singular tangent may still factor with a pivot at rounding level */
    for (size_t i = 0; i < n && info == 0; i++)
        if (!(s->Kt[i * n + i] * s->Kt[i * n + i] > 1e-14 * dmax))
            info = 1;
    if (info != 0)
        return FRICREG_ESINGULAR;
    memcpy(s->v, s->b, n * sizeof *s->v);
    dpotrs_("L", &nn, &one, s->Kt, &nn, s->v, &nn, &info, 1);
    return FRICREG_OK;
}

int fr_qsma_lu(double *A, size_t N, int *piv)
{
    double amax = 0.0;
    for (size_t k = 0; k < N * N; k++)
        amax = fmax(amax, fabs(A[k]));
    int nn = (int)N, info = 0;
    dgetrf_(&nn, &nn, A, &nn, piv, &info);
    for (size_t i = 0; i < N && info == 0; i++)
        if (!(fabs(A[i * N + i]) > 1e-14 * amax))
            info = 1;
    return info == 0 && isfinite(amax) ? FRICREG_OK : FRICREG_ESINGULAR;
}
