/* SPDX-License-Identifier: GPL-3.0-or-later */
/* disk_laws.c — the 2-D laws compared (docs/laws2d.md): the energy dissipated per forcing cycle
 * by a 2-D oscillator driven along a rotating direction,
 *     x'' + x = f + a sin(omega t) (cos(Omega t), sin(Omega t)),   mu N = 1,
 *     f_eq = x - a sin(omega t) (cos(Omega t), sin(Omega t)),
 * so that the sliding direction turns continuously and the contact sticks part of each cycle.
 * The problem is src/problems/disk_oscillator.c (`fricreg-sim disk` runs the same code):
 * classical RK4 (GSL's rk4 at 2 dt) from rest at the origin, eps = 2 dt (the paper's rule); D
 * is the mean of -integral f . x' dt per forcing cycle over one turn of the direction
 * (7 forcing cycles, Omega = omega/7) after 3 turns of transient. The reference is the same
 * problem at eps = 2e-5, dt = 1e-5 with each regularized law: they agree (the set-valued limit)
 * to the digits printed.
 *
 *   fricreg-bench-disk [law ...]   (default: quinn quinn-nested quinn-lens)
 * prints one line per law and dt: law, dt, eps, D, relative error against the reference, and
 * the fraction of GSL steps (2 dt) that end in the band |v| < eps. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "fricreg_disk.h"
#include "problems.h"

static struct prob_disk_result simulate(int law, double dt, double eps)
{
    struct prob_disk p = prob_disk_defaults();
    struct prob_disk_result r;
    p.law = law, p.dt = dt, p.eps = eps;
    int status = prob_disk_run(&p, NULL, NULL, &r);
    if (status != FRICREG_OK) {
        fprintf(stderr, "fricreg-bench-disk: dt %g: %s\n", dt, fricreg_strerror(status));
        exit(1);
    }
    return r;
}

int main(int argc, char **argv)
{
    const char *defaults[] = {"quinn", "quinn-nested", "quinn-lens"};
    int n_laws = argc > 1 ? argc - 1 : 3;
    const char *const *names = argc > 1 ? (const char *const *)argv + 1 : defaults;
    printf("%-16s %-8s %-8s %-18s %-10s %s\n", "law", "dt", "eps", "D/cycle", "rel.err", "band");
    for (int l = 0; l < n_laws; l++) {
        int law = fricreg_disk_law_from_name(names[l]);
        if (law == 0) {
            fprintf(stderr, "unknown 2-D law '%s'\n", names[l]);
            return 2;
        }
        struct prob_disk_result ref = simulate(law, 1e-5, 2e-5);
        printf("%-16s %-8g %-8g %-18.12f %-10s %.4f\n", names[l], 1e-5, 2e-5, ref.dissipation,
               "(ref)", ref.band);
        for (double dt = 0.04; dt >= 0.0024; dt /= 2.0) {
            struct prob_disk_result r = simulate(law, dt, 2.0 * dt);
            printf("%-16s %-8g %-8g %-18.12f %-10.3e %.4f\n", names[l], dt, 2.0 * dt, r.dissipation,
                   fabs(r.dissipation / ref.dissipation - 1.0), r.band);
        }
        fflush(stdout);
    }
    return 0;
}
