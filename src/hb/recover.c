/* SPDX-License-Identifier: GPL-3.0-or-later */
/* recover.c — the displacements from the elements' forces by (HB) of fricreg_hb.h,
 * X_h = D_h^-1 P_h − (D_h^-1 J^T) F_h, with the solves Y_h of the factored frequency, the RMS
 * per dof (forced/points.c has the getters of the coefficients). */
#include <math.h>
#include <string.h>

#include "hb_internal.h"
#include "recover.h"

/* X_h of dof k (complex, into out[2]) from the forces fq. */
static void coefficient(const fricreg_hb *hb, int h, size_t k, double *out)
{
    size_t m = hb->m, w = m + 1, nc = hb->nc;
    const double *y = hb->Y + 2 * (((size_t)h * hb->n + k) * w);
    /* the load column at the level in force, but in a nonlinear mode (the normalization's M φ
     * there) */
    double load = fr_hb_load(hb), re = load * y[2 * m], im = load * y[2 * m + 1];
    for (size_t e = 0; e < m; e++) {
        double fa = h == 0 ? hb->fq[e * nc] : hb->fq[e * nc + 2 * (size_t)h - 1];
        double fb = h == 0 ? 0.0 : -hb->fq[e * nc + 2 * (size_t)h]; /* F = fa − i fb */
        re -= y[2 * e] * fa - y[2 * e + 1] * fb;
        im -= y[2 * e] * fb + y[2 * e + 1] * fa;
    }
    out[0] = re;
    out[1] = im;
}

void fr_hb_recover(const fricreg_hb *hb, double *x)
{
    size_t nc = hb->nc;
    for (size_t k = 0; k < hb->n; k++)
        for (int h = 0; h <= hb->H; h++) {
            double X[2];
            coefficient(hb, h, k, X);
            if (h == 0) {
                x[k * nc] = X[0];
                continue;
            }
            x[k * nc + 2 * (size_t)h - 1] = X[0];
            x[k * nc + 2 * (size_t)h] = -X[1]; /* X = a − i b */
        }
}

/* Dof k's RMS over the harmonics 0..harmonics; its |X_1| into *amplitude (NULL: not wanted). */
static double rms_upto(const fricreg_hb *hb, size_t k, int harmonics, double *amplitude)
{
    double s = 0.0;
    for (int h = 0; h <= harmonics; h++) {
        double X[2];
        coefficient(hb, h, k, X);
        s += h == 0 ? X[0] * X[0] : 0.5 * (X[0] * X[0] + X[1] * X[1]);
        if (h == 1 && amplitude != NULL)
            *amplitude = hypot(X[0], X[1]);
    }
    return sqrt(s);
}

double fr_hb_rms_dof(const fricreg_hb *hb, size_t k)
{
    return rms_upto(hb, k, hb->H, NULL);
}

void fr_hb_rms_upto(const fricreg_hb *hb, int harmonics, double *rms, double *amplitude)
{
    for (size_t k = 0; k < hb->n; k++)
        rms[k] = rms_upto(hb, k, harmonics, amplitude ? &amplitude[k] : NULL);
}

void fr_hb_rms(const fricreg_hb *hb, double *rms)
{
    fr_hb_rms_upto(hb, hb->H, rms, NULL);
}
