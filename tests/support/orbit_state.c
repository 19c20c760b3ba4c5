/* SPDX-License-Identifier: GPL-3.0-or-later */
/* orbit_state.c — orbit_state.h's evaluation of the Fourier series and its derivative. */
#include "orbit_state.h"

#include <math.h>

void orbit_state_at(size_t n, int H, const double *x, double omega, double t, double *z)
{
    size_t nc = 2 * (size_t)H + 1;
    for (size_t k = 0; k < n; k++) {
        const double *c = x + k * nc;
        z[k] = c[0], z[n + k] = 0.0;
        for (int h = 1; h <= H; h++) {
            double a = h * omega * t;
            z[k] += c[2 * h - 1] * cos(a) + c[2 * h] * sin(a);
            z[n + k] += h * omega * (c[2 * h] * cos(a) - c[2 * h - 1] * sin(a));
        }
    }
}
