/* SPDX-License-Identifier: GPL-3.0-or-later */
/* chain_explicit.c — a prototype: the chain of Sec. 3.2 stepped by explicit central
 * differences, one friction evaluation a step, O(n).
 *
 *   u1 = u + dt v + dt^2/2 a,  v* = v + dt a,  a1 = a_free(t1, u1) + f(v*, -a_free),
 *   v1 = v + dt (a + a1)/2
 * (the library's structure integrator, src/structure/central_difference.c, on dense matrices). Why: RK4
 * pays four right-hand sides a step and is held by the step guard to dt * 2n <= 1/sqrt 2;
 * this scheme pays one, and is stable to dt * 2n < 2 (springs) and dt * 2/eps < 1 (law (4)'s
 * stick zone, src/structure/central_difference.c). Second order: the velocity update is Heun's. D is
 * integrated by the trapezoidal rule on the power -(1/n) sum v* f. Not part of the library:
 * bench/bigchain.c measures it at the guard's step (0.35/n) and beyond it (0.9/n). */
#include <math.h>
#include <stdlib.h>

#include "chain_explicit.h"

/* a_free = -n^2 K u + n G e_1 (src/sim/systems/chain.c). */
static void free_acc(size_t n, double G, const double u[], double af[])
{
    double n2 = (double)n * (double)n;
    af[0] = -n2 * (u[0] - u[1]) + (double)n * G;
    for (size_t i = 1; i + 1 < n; i++)
        af[i] = -n2 * (-u[i - 1] + 2.0 * u[i] - u[i + 1]);
    af[n - 1] = -n2 * (-u[n - 2] + 2.0 * u[n - 1]);
}

/* a = a_free + f at (t, u, vs), f_eq = -a_free; *power = -(1/n) sum vs f. */
static int accelerations(const struct chain_explicit_opts *o, double t, const double u[],
                         const double vs[], double *w[3], double a[], double *power)
{
    double *af = w[0], *f = w[1], *mun = w[2];
    size_t n = o->n;
    free_acc(n, o->a * sin(o->omega * t), u, af);
    for (size_t i = 0; i < n; i++)
        a[i] = -af[i]; /* f_eq, overwritten below */
    int status = fricreg_law_eval_batch(FRICREG_LAW_QUINN, o->eps, n, vs, a, mun, f);
    double p = 0.0;
    for (size_t i = 0; i < n; i++) {
        a[i] = af[i] + f[i];
        p -= vs[i] * f[i];
    }
    *power = p / (double)n;
    return status;
}

int chain_explicit_run(const struct chain_explicit_opts *o, struct bench_run *out)
{
    size_t n = o->n;
    double *u = calloc(n, sizeof *u), *v = calloc(n, sizeof *v), *a = calloc(n, sizeof *a);
    double *vs = calloc(n, sizeof *vs), *w[3];
    for (int k = 0; k < 3; k++)
        w[k] = calloc(n, sizeof(double));
    *out = (struct bench_run){0};
    out->status = u && v && a && vs && w[0] && w[1] && w[2] ? FRICREG_OK : FRICREG_ENOMEM;
    for (size_t i = 0; out->status == FRICREG_OK && i < n; i++)
        w[2][i] = 1.0; /* mun */
    size_t steps = (size_t)ceil(o->period / o->dt - 1e-9);
    double dt = o->period / (double)steps, D = 0.0, p0 = 0.0, p1 = 0.0;
    if (out->status == FRICREG_OK)
        out->status = accelerations(o, 0.0, u, v, w, a, &p0); /* from rest */
    for (size_t k = 0; out->status == FRICREG_OK && k < steps; k++) {
        for (size_t i = 0; i < n; i++) {
            u[i] += dt * v[i] + 0.5 * dt * dt * a[i];
            vs[i] = v[i] + dt * a[i];
            v[i] += 0.5 * dt * a[i]; /* the first half of (a + a1) dt/2 */
        }
        out->status = accelerations(o, (double)(k + 1) * dt, u, vs, w, a, &p1);
        for (size_t i = 0; i < n; i++)
            v[i] += 0.5 * dt * a[i];
        D += 0.5 * dt * (p0 + p1);
        p0 = p1;
    }
    out->D = out->status == FRICREG_OK ? D : NAN;
    out->steps = (double)steps;
    out->rhs_evals = (double)steps + 1.0;
    free(u);
    free(v);
    free(a);
    free(vs);
    for (int k = 0; k < 3; k++)
        free(w[k]);
    return out->status;
}
