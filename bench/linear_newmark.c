/* SPDX-License-Identifier: GPL-3.0-or-later */
/* linear_newmark.c — the frictionless Newmark baseline (linear_newmark.h). */
#include <stdlib.h>
#include <string.h>

#include "bench.h"
#include "linear_newmark.h"

#define BETA 0.25
#define GAMMA 0.5

static cholmod_sparse *upper(size_t n, const int64_t kp[], const int64_t ki[], const double kx[],
                             double scale, cholmod_common *cc)
{
    cholmod_sparse *A = cholmod_l_allocate_sparse(n, n, (size_t)kp[n], 1, 1, 1, CHOLMOD_REAL, cc);
    memcpy(A->p, kp, (n + 1) * sizeof *kp);
    memcpy(A->i, ki, (size_t)kp[n] * sizeof *ki);
    for (int64_t q = 0; q < kp[n]; q++)
        ((double *)A->x)[q] = scale * kx[q];
    return A;
}

/* y = A x for an upper triangle A. */
static void sym_mult(const cholmod_sparse *A, const double x[], double y[])
{
    const SuiteSparse_long *p = A->p, *i = A->i;
    const double *ax = A->x;
    memset(y, 0, A->ncol * sizeof *y);
    for (size_t j = 0; j < A->ncol; j++)
        for (SuiteSparse_long q = p[j]; q < p[j + 1]; q++) {
            y[j] += ax[q] * x[i[q]];
            if ((size_t)i[q] != j)
                y[i[q]] += ax[q] * x[j];
        }
}

void linear_newmark_start(struct linear_newmark *l, size_t n, const int64_t kp[],
                          const int64_t ki[], const double kx[], double mass, double a1, double dt)
{
    memset(l, 0, sizeof *l);
    l->n = n;
    l->mass = mass;
    l->dt = dt;
    cholmod_l_start(&l->cc);
    l->cc.final_ll = 1;
    l->cc.nmethods = 1;
    l->cc.method[0].ordering = n >= 4096 ? CHOLMOD_NESDIS : CHOLMOD_AMD;
    l->K = upper(n, kp, ki, kx, 1.0, &l->cc);
    l->C = upper(n, kp, ki, kx, a1, &l->cc);
    cholmod_sparse *I = cholmod_l_speye(n, n, CHOLMOD_REAL, &l->cc);
    I->stype = 1;
    double one[2] = {mass, 0}, kc[2] = {GAMMA * dt * a1 + BETA * dt * dt, 0};
    cholmod_sparse *Keff = cholmod_l_add(I, l->K, one, kc, 1, 1, &l->cc);
    l->L = cholmod_l_analyze(Keff, &l->cc);
    cholmod_l_factorize(Keff, l->L, &l->cc);
    cholmod_l_free_sparse(&Keff, &l->cc);
    cholmod_l_free_sparse(&I, &l->cc);
    l->B = cholmod_l_zeros(n, 1, CHOLMOD_REAL, &l->cc);
    l->u = calloc(n, sizeof *l->u);
    l->v = calloc(n, sizeof *l->v);
    l->a = calloc(n, sizeof *l->a);
    l->up = calloc(n, sizeof *l->up);
    l->vp = calloc(n, sizeof *l->vp);
}

void linear_newmark_step(struct linear_newmark *l, double (*ag)(double t))
{
    size_t n = l->n;
    double dt = l->dt, *b = l->B->x;
    for (size_t i = 0; i < n; i++) {
        l->up[i] = l->u[i] + dt * l->v[i] + (0.5 - BETA) * dt * dt * l->a[i];
        l->vp[i] = l->v[i] + (1.0 - GAMMA) * dt * l->a[i];
    }
    l->t += dt;
    double g = ag(l->t);
    sym_mult(l->C, l->vp, b);
    sym_mult(l->K, l->up, l->a); /* a as scratch */
    for (size_t i = 0; i < n; i++)
        b[i] = -l->mass * g - b[i] - l->a[i];
    cholmod_l_solve2(CHOLMOD_A, l->L, l->B, NULL, &l->X, NULL, &l->Y, &l->E, &l->cc);
    const double *x = l->X->x;
    for (size_t i = 0; i < n; i++) {
        l->a[i] = x[i];
        l->u[i] = l->up[i] + BETA * dt * dt * x[i];
        l->v[i] = l->vp[i] + GAMMA * dt * x[i];
    }
}

double linear_newmark_batch(struct linear_newmark *l, double (*ag)(double t), size_t steps)
{
    double t0 = bench_cpu_seconds();
    for (size_t i = 0; i < steps; i++)
        linear_newmark_step(l, ag);
    return (bench_cpu_seconds() - t0) / (double)steps;
}

void linear_newmark_free(struct linear_newmark *l)
{
    cholmod_l_free_sparse(&l->K, &l->cc);
    cholmod_l_free_sparse(&l->C, &l->cc);
    cholmod_l_free_factor(&l->L, &l->cc);
    cholmod_dense **d[] = {&l->X, &l->Y, &l->E, &l->B};
    for (size_t i = 0; i < 4; i++)
        cholmod_l_free_dense(d[i], &l->cc);
    cholmod_l_finish(&l->cc);
    free(l->u);
    free(l->v);
    free(l->a);
    free(l->up);
    free(l->vp);
}
