/* SPDX-License-Identifier: GPL-3.0-or-later */
/* nma_energy.c — what a backbone point is made of (fricreg_hb.h): the share of each harmonic
 * in the mode's kinetic energy (fricreg_hb_nma_harmonic_energy) and the share of each linear
 * mode of the stuck structure in a harmonic of the displacement
 * (fricreg_hb_nma_modal_participation). Both from the point's displacement coefficients X_h
 * (fricreg_hb_nma_point) and M; the harmonics are orthogonal over a period and the modes
 * M-orthonormal, so both shares add up to 1 without cross terms (Parseval; the energy of each
 * harmonic along a backbone as Krack & Gross 2019 plot it for internal resonances). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "nma_internal.h"

/* y = M v, M the model's (dense row-major, or on the sparse pattern of D_h). */
static void mass_times(const fricreg_hb *hb, const double *v, double *y)
{
    size_t n = hb->n;
    memset(y, 0, n * sizeof *y);
    if (hb->sparse) {
        for (size_t j = 0; j < n; j++)
            for (int64_t p = hb->Dp[j]; p < hb->Dp[j + 1]; p++)
                y[hb->Di[p]] += hb->vM[p] * v[j];
        return;
    }
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++)
            y[i] += hb->M[i * n + j] * v[j];
}

static double dot(const double *u, const double *v, size_t n)
{
    double s = 0.0;
    for (size_t k = 0; k < n; k++)
        s += u[k] * v[k];
    return s;
}

/* Coefficient c (0: the mean, 2h − 1 and 2h: harmonic h's cosine and sine) of every dof of x
 * (ndof x nc, as fricreg_hb_nma_point's) into v [n]. */
static void gather(const fricreg_hb *hb, const double *x, size_t c, double *v)
{
    for (size_t k = 0; k < hb->n; k++)
        v[k] = x[k * hb->nc + c];
}

/* The arguments' common checks and the point's displacements into a buffer of
 * n nc + 3 n doubles the caller frees (*x: X, then three n-vectors of scratch). */
static int point_displacements(fricreg_hb *hb, const char *fn, size_t i, const void *out,
                               double **x)
{
    if (hb == NULL)
        return FRICREG_ENULL;
    if (out == NULL)
        return fr_fail(hb, FRICREG_ENULL, "%s: fraction is NULL", fn);
    size_t npts = fricreg_hb_nma_points(hb);
    if (i >= npts)
        return fr_fail(hb, FRICREG_EINVAL, "%s: i = %zu, %zu points stored", fn, i, npts);
    if (!fr_hb_backbone_holds(hb) || hb->nma->nq != hb->nq)
        return fr_fail(hb, FRICREG_EINVAL, "%s: the model changed since the backbone", fn);
    size_t n = hb->n, nc = hb->nc;
    if ((*x = malloc((n * nc + 3 * n) * sizeof **x)) == NULL)
        return fr_fail(hb, FRICREG_ENOMEM, "%s: no memory for %zu dofs' coefficients", fn, n);
    double a, omega, zeta;
    int status = fricreg_hb_nma_point(hb, i, &a, &omega, &zeta, n, nc, *x);
    if (status != FRICREG_OK) {
        free(*x);
        *x = NULL;
    }
    return status;
}

int fricreg_hb_nma_harmonic_energy(fricreg_hb *hb, size_t i, size_t nh, double fraction[])
{
    static const char fn[] = "nma_harmonic_energy";
    if (hb != NULL && fraction != NULL && nh != (size_t)hb->H + 1)
        return fr_fail(hb, FRICREG_ESIZE, "%s: nh = %zu, the driver has H + 1 = %d", fn, nh,
                       hb->H + 1);
    double *x = NULL;
    int status = point_displacements(hb, fn, i, fraction, &x);
    if (status != FRICREG_OK)
        return status;
    size_t n = hb->n;
    double *v = x + n * hb->nc, *Mv = v + n, total = 0.0;
    /* T_h = (hω)²/4 (a_h^T M a_h + b_h^T M b_h); ω² cancels in the shares */
    double share[FRICREG_HB_MAX_HARMONICS + 1];
    share[0] = 0.0;
    for (size_t h = 1; h < nh; h++) {
        double s = 0.0;
        for (size_t c = 2 * h - 1; c <= 2 * h; c++) {
            gather(hb, x, c, v);
            mass_times(hb, v, Mv);
            s += dot(v, Mv, n);
        }
        share[h] = (double)(h * h) * s;
        total += share[h];
    }
    free(x);
    if (!(total > 0.0) || !isfinite(total))
        return fr_fail(hb, FRICREG_ENONFINITE, "%s: the kinetic energy at point %zu is %g", fn, i,
                       total);
    for (size_t h = 0; h < nh; h++)
        fraction[h] = share[h] / total;
    return FRICREG_OK;
}

int fricreg_hb_nma_modal_participation(fricreg_hb *hb, size_t i, int harmonic, size_t nmodes,
                                       double fraction[])
{
    static const char fn[] = "nma_modal_participation";
    if (hb != NULL && fraction != NULL) {
        if (harmonic < 0 || harmonic > hb->H)
            return fr_fail(hb, FRICREG_EINVAL, "%s: harmonic = %d, the driver has 0 to H = %d", fn,
                           harmonic, hb->H);
        if (nmodes != hb->n)
            return fr_fail(hb, FRICREG_ESIZE, "%s: nmodes = %zu, the driver has %zu dofs", fn,
                           nmodes, hb->n);
        if (hb->sparse && hb->n > FR_HB_NMA_SPARSE_ALL_MODES)
            return fr_fail(hb, FRICREG_EINVAL,
                           "%s: a sparse model's linear modes are found only up to %d dofs, "
                           "it has %zu",
                           fn, FR_HB_NMA_SPARSE_ALL_MODES, hb->n);
    }
    double *x = NULL;
    int status = point_displacements(hb, fn, i, fraction, &x);
    if (status != FRICREG_OK)
        return status;
    struct fr_hb_nma *s = hb->nma;
    size_t n = hb->n;
    if (s->modes == NULL) { /* once per backbone: the stuck structure's every mode */
        double *Phi = malloc(n * n * sizeof *Phi);
        if (Phi == NULL)
            status = fr_fail(hb, FRICREG_ENOMEM, "%s: no memory for %zu modes", fn, n);
        else if ((status = fr_hb_nma_modes(hb, fn, Phi)) != FRICREG_OK)
            free(Phi);
        else
            s->modes = Phi;
    }
    if (status != FRICREG_OK) {
        free(x);
        return status;
    }
    /* p_r = (φ_r^T M a_h)² + (φ_r^T M b_h)² (the mean: (φ_r^T M x_0)²), over their sum */
    double *v = x + n * hb->nc, *Mv = v + n, total = 0.0;
    size_t h = (size_t)harmonic, c0 = h ? 2 * h - 1 : 0, c1 = h ? 2 * h : 0;
    double *p = Mv + n;
    memset(p, 0, n * sizeof *p);
    for (size_t c = c0; c <= c1; c++) {
        gather(hb, x, c, v);
        mass_times(hb, v, Mv);
        for (size_t r = 0; r < n; r++) {
            double q = dot(s->modes + r * n, Mv, n);
            p[r] += q * q;
        }
    }
    for (size_t r = 0; r < n; r++)
        total += p[r];
    for (size_t r = 0; r < n; r++)
        fraction[r] = total > 0.0 ? p[r] / total : 0.0;
    free(x);
    return FRICREG_OK;
}
