/* SPDX-License-Identifier: GPL-3.0-or-later */
/* linear_newmark.h — the frictionless baseline of the structure benchmarks: average-
 * acceleration Newmark on a lumped mass m I, a sparse K and Rayleigh C = a1 K, under a
 * uniform ground acceleration (influence vector of ones), written with CHOLMOD alone.
 *
 * K_eff = m I + gamma dt C + beta dt^2 K is factored once with the ordering the structure
 * uses (nested dissection from 4096 dofs, AMD below); a step is u_pred, v_pred, the
 * right-hand side -m a_g - C v_pred - K u_pred and one solve: the physical limit of an
 * implicit step on that factor. */
#ifndef FRICREG_BENCH_LINEAR_NEWMARK_H
#define FRICREG_BENCH_LINEAR_NEWMARK_H

#include <stddef.h>
#include <stdint.h>

#include <cholmod.h>

struct linear_newmark {
    size_t n;
    double mass, dt;
    cholmod_common cc;
    cholmod_sparse *K, *C; /* upper triangles */
    cholmod_factor *L;
    cholmod_dense *X, *Y, *E, *B;
    double *u, *v, *a, *up, *vp, t;
};

/* K (n x n, upper triangle, CSC kp[n+1], ki, kx) copied; state at rest at t = 0. */
void linear_newmark_start(struct linear_newmark *l, size_t n, const int64_t kp[],
                          const int64_t ki[], const double kx[], double mass, double a1, double dt);

/* One step under the ground acceleration ag(t + dt). */
void linear_newmark_step(struct linear_newmark *l, double (*ag)(double t));

/* Mean CPU seconds per step of `steps` steps. */
double linear_newmark_batch(struct linear_newmark *l, double (*ag)(double t), size_t steps);

void linear_newmark_free(struct linear_newmark *l);

#endif
