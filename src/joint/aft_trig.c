/* SPDX-License-Identifier: GPL-3.0-or-later */
/* aft_trig.c — the trigonometric polynomials of the AFT's coefficient layout (aft_internal.h):
 * the basis phi_j(theta) = 1, cos theta, sin theta, cos 2 theta, ..., and the half-angle table
 * that turns a polynomial of degree D in theta into an algebraic one in t = tan(theta/2), whose
 * roots the exact paths isolate (aft_roots.c). Below both AFT paths and the workspace. */
#include <math.h>
#include <string.h>

#include "aft_internal.h"

void fr_aft_basis(int H, double theta, double *phi)
{
    phi[0] = 1.0;
    for (int h = 1; h <= H; h++) {
        phi[2 * h - 1] = cos(h * theta);
        phi[2 * h] = sin(h * theta);
    }
}

void fr_aft_half_angle_table(fricreg_aft *a, int H)
{
    size_t w = (size_t)(2 * H + 1);
    double *b1 = a->cm, *b2 = a->sm; /* rows H + h and H - h of Pascal's triangle */
    for (int h = 0; h <= H; h++) {
        double *re = &a->qre[w * (size_t)h], *im = &a->qim[w * (size_t)h];
        memset(re, 0, w * sizeof *re);
        memset(im, 0, w * sizeof *im);
        int m1 = H + h, m2 = H - h;
        for (int k = 0; k <= m2; k++)
            b2[k] = k == 0 ? 1.0 : b2[k - 1] * (double)(m2 - k + 1) / k;
        for (int k = 0; k <= m1; k++) {
            b1[k] = k == 0 ? 1.0 : b1[k - 1] * (double)(m1 - k + 1) / k;
            for (int l = 0; l <= m2; l++) {
                /* the coefficient of t^(k+l): C(m1, k) i^k C(m2, l) (-i)^l, i^(k+l) (-1)^l */
                int p = (k + l) % 4;
                double c = b1[k] * b2[l] * ((l % 2) ? -1.0 : 1.0);
                if (p == 0)
                    re[k + l] += c;
                else if (p == 1)
                    im[k + l] += c;
                else if (p == 2)
                    re[k + l] -= c;
                else
                    im[k + l] -= c;
            }
        }
    }
    a->table_H = H;
}
