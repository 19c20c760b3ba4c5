/* SPDX-License-Identifier: GPL-3.0-or-later */
/* peak.c — the peak displacements max_t |u_i(t)| (fricreg_structure_get_peak_displacement):
 * a step's end, and inside a step (fixed or adaptive) the turning point of u_i on the cubic Hermite
 * interpolant of its ends (u, v at both), where v_i changes sign.
 *
 * Why between the samples: a maximum taken at the step ends alone falls short of the
 * trajectory's by up to |u''| dt^2 / 8, of either size from step to step as the turning
 * point's phase against the samples moves, so it converges with that phase and not at the
 * scheme's order, and a companion at dt / 2 cannot tell its error (error_estimate.c). For
 * Newmark's average acceleration (gamma = 1/2, beta = 1/4: u1 = u0 + dt (v0 + v1) / 2) the
 * interpolant is the scheme's own quadratic, u0 + v0 tau + (v1 - v0) tau^2 / (2 dt). */
#include <gsl/gsl_poly.h>
#include <math.h>

#include "structure_internal.h"

/* The largest |u| at the turning points in (0, 1) of the cubic Hermite interpolant
 * p(theta) = u0 + h v0 theta + b theta^2 + c theta^3 with p(1) = u1, p'(1) = h v1. */
static double turning_peak(double u0, double v0, double u1, double v1, double h)
{
    double b = 3.0 * (u1 - u0) - h * (2.0 * v0 + v1);
    double c = 2.0 * (u0 - u1) + h * (v0 + v1);
    double root[2], peak = 0.0;
    int count = gsl_poly_solve_quadratic(3.0 * c, 2.0 * b, h * v0, &root[0], &root[1]);
    for (int k = 0; k < count; k++) {
        double th = root[k];
        if (th > 0.0 && th < 1.0)
            peak = fmax(peak, fabs(u0 + th * (h * v0 + th * (b + th * c))));
    }
    return peak;
}

void fr_peak_step(fricreg_structure *s, const double u1[], const double v1[], double h)
{
    const double *u0 = s->u->data, *v0 = s->v->data;
    for (size_t i = 0; i < s->n; i++) {
        double peak = fmax(s->peak[i], fabs(u1[i]));
        if (v0[i] * v1[i] < 0.0)
            peak = fmax(peak, turning_peak(u0[i], v0[i], u1[i], v1[i], h));
        s->peak[i] = peak;
    }
}
