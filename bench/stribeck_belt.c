/* SPDX-License-Identifier: GPL-3.0-or-later */
/* stribeck_belt.c — the belt-driven stick-slip oscillator with Stribeck friction
 * (fricreg_stribeck.h, docs/laws2d.md):
 *     x'' + x = f(x' - V),   f_eq = x,   fs = 1, fk = 0.5, vs = 0.05, delta = 1, V = 0.2,
 * its limit cycle's period and amplitude (x_max - x_min)/2 on the 12th cycle under the
 * regularized law with classical RK4 (GSL's rk4 at 2 dt) at eps = 2 dt, against the
 * event-driven reference (stick exact, slip by RK4 at 1e-5 with its end located by GSL's Brent
 * solver on the Hermite interpolant). The problem and the reference are src/problems/belt.c,
 * which `fricreg-sim belt` runs too. Prints the reference, then per dt: period, amplitude and
 * their relative errors. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "fricreg.h"
#include "problems.h"

static void check(int status, const char *what)
{
    if (status != FRICREG_OK) {
        fprintf(stderr, "fricreg-bench-stribeck-belt: %s: %s\n", what, fricreg_strerror(status));
        exit(1);
    }
}

int main(void)
{
    struct prob_belt p = prob_belt_defaults();
    struct prob_belt_cycle ref, c;
    check(prob_belt_reference(&p, NULL, NULL, &ref), "reference");
    printf("reference (event-driven): period %.12f amplitude %.12f\n", ref.period, ref.amplitude);
    printf("%-10s %-16s %-10s %-16s %-10s\n", "dt", "period", "rel.err", "amplitude", "rel.err");
    for (double dt = 0.02; dt > 1e-4; dt /= 2) {
        p.dt = dt, p.eps = 2 * dt;
        check(prob_belt_regularized(&p, 0.5 * (ref.x_min + ref.x_max), NULL, NULL, &c), "run");
        printf("%-10g %-16.12f %-10.3e %-16.12f %-10.3e\n", dt, c.period,
               fabs(c.period / ref.period - 1), c.amplitude, fabs(c.amplitude / ref.amplitude - 1));
    }
    return 0;
}
