/* SPDX-License-Identifier: GPL-3.0-or-later */
/* disk_laws.c — the 2-D laws compared (docs/laws2d.md): the energy dissipated per forcing cycle
 * by a 2-D oscillator driven along a rotating direction,
 *     x'' + x = f + a sin(omega t) (cos(Omega t), sin(Omega t)),   mu N = 1,
 *     f_eq = x - a sin(omega t) (cos(Omega t), sin(Omega t)),
 * so that the sliding direction turns continuously and the contact sticks part of each cycle.
 * Fixed-step classical RK4 from rest at the origin, eps = 2 dt (the paper's rule); D is the mean
 * of -integral f . x' dt per forcing cycle over one turn of the direction (7 forcing cycles,
 * Omega = omega/7) after 3 turns of transient. The reference is the same problem at eps = 2e-5,
 * dt = 1e-5 with each regularized law: they agree (the set-valued limit) to the digits printed.
 *
 *   fricreg-bench-disk [law ...]   (default: quinn quinn-lens quinn-nested)
 * prints one line per law and dt: law, dt, eps, D, relative error against the reference, and
 * the fraction of steps in the band |v| < eps; and the largest continuity ratio found. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "fricreg_disk.h"

enum { TURNS_TRANSIENT = 3, CYCLES_PER_TURN = 7 };
static const double A = 2.0, OMEGA = 0.5, PI = 3.14159265358979323846;

struct run {
    double dissipation; /* per forcing cycle, over the measured turn */
    double band;        /* fraction of the measured turn's steps with |v| < eps */
};

static void forcing(double t, double F[2])
{
    double s = A * sin(OMEGA * t), phi = OMEGA / CYCLES_PER_TURN * t;
    F[0] = s * cos(phi);
    F[1] = s * sin(phi);
}

/* y = (x0, x1, v0, v1); dy = (v, -x + f + F); *power = -f . v. */
static void rhs(int law, double eps, double t, const double y[4], double dy[4], double *power)
{
    double F[2], feq[2], f[2];
    forcing(t, F);
    feq[0] = y[0] - F[0];
    feq[1] = y[1] - F[1];
    if (fricreg_disk_eval(law, y + 2, feq, 1.0, eps, f) != FRICREG_OK)
        abort();
    dy[0] = y[2];
    dy[1] = y[3];
    dy[2] = -y[0] + f[0] + F[0];
    dy[3] = -y[1] + f[1] + F[1];
    *power = -(f[0] * y[2] + f[1] * y[3]);
}

static struct run simulate(int law, double dt, double eps)
{
    double turn = 2.0 * PI * CYCLES_PER_TURN / OMEGA;
    long n_transient = lround(TURNS_TRANSIENT * turn / dt), n_measured = lround(turn / dt);
    double y[4] = {0.0, 0.0, 0.0, 0.0}, k[4][4], p[4], tmp[4], energy = 0.0;
    long in_band = 0;
    for (long step = 0; step < n_transient + n_measured; step++) {
        double t = step * dt;
        rhs(law, eps, t, y, k[0], &p[0]);
        for (int i = 0; i < 4; i++)
            tmp[i] = y[i] + 0.5 * dt * k[0][i];
        rhs(law, eps, t + 0.5 * dt, tmp, k[1], &p[1]);
        for (int i = 0; i < 4; i++)
            tmp[i] = y[i] + 0.5 * dt * k[1][i];
        rhs(law, eps, t + 0.5 * dt, tmp, k[2], &p[2]);
        for (int i = 0; i < 4; i++)
            tmp[i] = y[i] + dt * k[2][i];
        rhs(law, eps, t + dt, tmp, k[3], &p[3]);
        for (int i = 0; i < 4; i++)
            y[i] += dt / 6.0 * (k[0][i] + 2.0 * k[1][i] + 2.0 * k[2][i] + k[3][i]);
        if (step >= n_transient) { /* the dissipated energy by the same RK4 weights */
            energy += dt / 6.0 * (p[0] + 2.0 * p[1] + 2.0 * p[2] + p[3]);
            in_band += hypot(y[2], y[3]) < eps;
        }
    }
    return (struct run){energy / CYCLES_PER_TURN, (double)in_band / (double)n_measured};
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
        struct run ref = simulate(law, 1e-5, 2e-5);
        printf("%-16s %-8g %-8g %-18.12f %-10s %.4f\n", names[l], 1e-5, 2e-5, ref.dissipation,
               "(ref)", ref.band);
        for (double dt = 0.04; dt >= 0.0024; dt /= 2.0) {
            struct run r = simulate(law, dt, 2.0 * dt);
            printf("%-16s %-8g %-8g %-18.12f %-10.3e %.4f\n", names[l], dt, 2.0 * dt, r.dissipation,
                   fabs(r.dissipation / ref.dissipation - 1.0), r.band);
        }
        fflush(stdout);
    }
    return 0;
}
