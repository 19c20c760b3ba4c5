/* SPDX-License-Identifier: GPL-3.0-or-later */
/* stribeck_belt.c — the belt-driven stick-slip oscillator with Stribeck friction
 * (fricreg_stribeck.h, docs/laws2d.md):
 *     x'' + x = f(x' - V),   f_eq = x,   fs = 1, fk = 0.5, vs = 0.05, delta = 1, V = 0.2,
 * its limit cycle's period and amplitude (x_max - x_min)/2 under the regularized law with
 * classical RK4 at eps = 2 dt, against an event-driven reference:
 *   - stick (x' = V): exact, x = x0 + V (t - t0), until x = fs (break-away, exactly);
 *   - slip in direction s = sgn(x' - V) (here -1): x'' = -x - s k(|x' - V|), RK4 at 1e-5 with
 *     the phase's end x' = V located inside the step by bisection on the cubic Hermite
 *     interpolant of (x', x''); then stick if |x| <= fs, else slip on.
 * No CVODE here (not a dependency of the library's bench target): the reference's own error is
 * that of RK4 at 1e-5 (~1e-13 relative on these smooth phases) and of the located events.
 * Prints the reference, then per dt: period, amplitude and their relative errors. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "fricreg_stribeck.h"

static const double FS = 1.0, FK = 0.5, VS = 0.05, DELTA = 1.0, V = 0.2;
enum { CYCLES = 12 };

struct cycle {
    double period, amplitude;
};

static double kinetic(double s)
{
    return FK + (FS - FK) * exp(-pow(s / VS, DELTA));
}

/* Slip dynamics of the reference with the direction s held. */
static void slip_rhs(double s, const double y[2], double dy[2])
{
    dy[0] = y[1];
    dy[1] = -y[0] - s * kinetic(fabs(y[1] - V));
}

static void rk4(void (*rhs)(double, const double *, double *), double s, double h, double y[2])
{
    double k1[2], k2[2], k3[2], k4[2], t[2];
    rhs(s, y, k1);
    t[0] = y[0] + 0.5 * h * k1[0], t[1] = y[1] + 0.5 * h * k1[1];
    rhs(s, t, k2);
    t[0] = y[0] + 0.5 * h * k2[0], t[1] = y[1] + 0.5 * h * k2[1];
    rhs(s, t, k3);
    t[0] = y[0] + h * k3[0], t[1] = y[1] + h * k3[1];
    rhs(s, t, k4);
    y[0] += h / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0]);
    y[1] += h / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1]);
}

/* Cubic Hermite on [0, h] through (p0, d0), (p1, d1), at theta in [0, 1]. */
static double hermite(double p0, double d0, double p1, double d1, double h, double th)
{
    double h00 = (1 + 2 * th) * (1 - th) * (1 - th), h10 = th * (1 - th) * (1 - th);
    double h01 = th * th * (3 - 2 * th), h11 = th * th * (th - 1);
    return h00 * p0 + h10 * h * d0 + h01 * p1 + h11 * h * d1;
}

/* The event-driven reference: x_max, x_min and the break-away times of CYCLES cycles from
 * stick at x = 0; returns the last cycle's period and amplitude. */
static struct cycle reference(void)
{
    const double h = 1e-5;
    double t = 0.0, x = 0.0, last_break = 0.0, period = 0.0, amplitude = 0.0;
    for (int c = 0; c < CYCLES; c++) {
        t += (FS - x) / V; /* stick until x = fs */
        x = FS;
        period = t - last_break;
        last_break = t;
        double y[2] = {x, V}, xmax = x, xmin = x, s = -1.0;
        for (;;) {
            double y0[2] = {y[0], y[1]}, d0[2], d1[2];
            slip_rhs(s, y0, d0);
            rk4(slip_rhs, s, h, y);
            slip_rhs(s, y, d1);
            xmax = fmax(xmax, y[0]);
            xmin = fmin(xmin, y[0]);
            /* the slip ends where x' - V changes sign against s (not at the start) */
            if (y0[1] != V && (y[1] - V) * s <= 0.0) {
                double lo = 0.0, hi = 1.0;
                for (int it = 0; it < 60; it++) {
                    double mid = 0.5 * (lo + hi);
                    double vm = hermite(y0[1], d0[1], y[1], d1[1], h, mid);
                    if ((vm - V) * s > 0.0)
                        lo = mid;
                    else
                        hi = mid;
                }
                t += hi * h;
                x = hermite(y0[0], d0[0], y[0], d1[0], h, hi);
                if (fabs(x) <= FS)
                    break; /* sticks */
                s = -s;    /* slips the other way: not met with these parameters */
                y[0] = x, y[1] = V;
                continue;
            }
            t += h;
        }
        amplitude = 0.5 * (xmax - xmin);
    }
    return (struct cycle){period, amplitude};
}

/* The regularized law under RK4 at step dt, eps = 2 dt: the period between the last two
 * downward crossings of x = 0 (linear interpolation is enough: x' is far from 0 there, and
 * its error is O(dt^2)), the amplitude from the step values over the last cycle. */
static struct cycle regularized(double dt)
{
    double eps = 2 * dt, y[2] = {0.0, V}, t = 0.0, crossings[CYCLES + 2];
    int n_cross = 0;
    double xmax = -INFINITY, xmin = INFINITY;
    while (n_cross < CYCLES + 1) {
        static const double c[4] = {0.0, 0.5, 0.5, 1.0}; /* RK4's stage offsets */
        double k[4][2], y0[2] = {y[0], y[1]};
        for (int st = 0; st < 4; st++) {
            double x = y0[0], xd = y0[1], f;
            if (st > 0) {
                x += c[st] * dt * k[st - 1][0];
                xd += c[st] * dt * k[st - 1][1];
            }
            if (fricreg_stribeck_eval(xd - V, x, FS, FK, VS, DELTA, eps, &f) != FRICREG_OK)
                abort();
            k[st][0] = xd;
            k[st][1] = -x + f;
        }
        for (int i = 0; i < 2; i++)
            y[i] += dt / 6 * (k[0][i] + 2 * k[1][i] + 2 * k[2][i] + k[3][i]);
        t += dt;
        if (y0[0] > 0.0 && y[0] <= 0.0) {
            crossings[n_cross++] = t - dt + dt * y0[0] / (y0[0] - y[0]);
            if (n_cross == CYCLES) /* the last cycle starts */
                xmax = -INFINITY, xmin = INFINITY;
        }
        xmax = fmax(xmax, y[0]);
        xmin = fmin(xmin, y[0]);
    }
    return (struct cycle){crossings[CYCLES] - crossings[CYCLES - 1], 0.5 * (xmax - xmin)};
}

int main(void)
{
    struct cycle ref = reference();
    printf("reference (event-driven): period %.12f amplitude %.12f\n", ref.period, ref.amplitude);
    printf("%-10s %-16s %-10s %-16s %-10s\n", "dt", "period", "rel.err", "amplitude", "rel.err");
    for (double dt = 0.02; dt > 1e-4; dt /= 2) {
        struct cycle c = regularized(dt);
        printf("%-10g %-16.12f %-10.3e %-16.12f %-10.3e\n", dt, c.period,
               fabs(c.period / ref.period - 1), c.amplitude, fabs(c.amplitude / ref.amplitude - 1));
    }
    return 0;
}
