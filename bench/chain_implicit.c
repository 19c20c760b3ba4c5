/* SPDX-License-Identifier: GPL-3.0-or-later */
/* chain_implicit.c — a prototype: the chain of Sec. 3.2 stepped by HHT-alpha (Newmark when
 * alpha = 0) with the friction implicit, each Newton system tridiagonal, O(n) per iteration.
 *
 * Why: the chain is stiff (spring frequencies up to 2n) while the forcing is slow, so an
 * explicit step is bounded by stability (RK4: dt = 0.35/n), not by accuracy. An implicit step
 * can follow the slow motion at a step set by accuracy alone, and here its Newton matrix keeps
 * the chain's structure: with u_i'' = a_free_i + f_i, a_free = -n^2 K u + n G(t) e_1, K
 * tridiagonal, W = I and law (4) per contact, the unknown is the acceleration a1 at the step's
 * end (u1 = u_pred + beta dt^2 a1, v1 = v_pred + gamma dt a1) and
 *   R(a1) = a1 - (1 + alpha) g(t1, u1, v1) + alpha g(t0, u0, v0),  g = a_free + f(v, f_eq),
 *   dR/da1 = I + (1 + alpha) [(I - F_eq) n^2 K beta dt^2 - gamma dt F_v],
 * with f_eq = -a_free (W = I) and F_v, F_eq the diagonal tangent of law (4) (spec Eq. (4): in
 * the band |v - xi| < eps/2, F_v = -2 mun/eps and F_eq = 1 where |f_eq| < mun; else 0). The
 * matrix is tridiagonal: GSL's gsl_linalg_solve_tridiag solves it. The library's structure
 * integrator (newmark.c) forms the same Newton matrix densely (O(n^3) per factorization); this
 * is what a banded path there would cost. The friction itself is fricreg_law_eval_batch.
 *
 * The dissipation D' = -(1/n) sum_i v_i f_i is integrated by the trapezoidal rule, of the
 * scheme's second order. Not part of the library: bench/bigchain.c measures it. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>

#include "chain_implicit.h"

#define NEWTON_MAX 50

struct chain {
    size_t n;
    double a, omega, eps, n2;
    double *u, *v, *acc, *f, *feq, *mun; /* state at t0 and its forces */
    double *up, *vp, *u1, *v1, *a1, *f1, *feq1, *R, *g0, *a_old;
    gsl_vector *diag, *above, *below, *rhs, *dx;
};

/* a_free = -n^2 K u + n G(t) e_1 (src/sim/systems/chain.c). */
static void free_acc(const struct chain *c, double t, const double u[], double af[])
{
    size_t n = c->n;
    af[0] = -c->n2 * (u[0] - u[1]) + (double)n * c->a * sin(c->omega * t);
    for (size_t i = 1; i + 1 < n; i++)
        af[i] = -c->n2 * (-u[i - 1] + 2.0 * u[i] - u[i + 1]);
    af[n - 1] = -c->n2 * (-u[n - 2] + 2.0 * u[n - 1]);
}

/* g = a_free + f at (t, u, v); f_eq = -a_free. Returns a fricreg status. */
static int forces(const struct chain *c, double t, const double u[], const double v[], double g[],
                  double f[], double feq[])
{
    free_acc(c, t, u, g);
    for (size_t i = 0; i < c->n; i++)
        feq[i] = -g[i];
    int status = fricreg_law_eval_batch(FRICREG_LAW_QUINN, c->eps, c->n, v, feq, c->mun, f);
    for (size_t i = 0; status == FRICREG_OK && i < c->n; i++)
        g[i] += f[i];
    return status;
}

static double power(const struct chain *c, const double v[], const double f[])
{
    double p = 0.0;
    for (size_t i = 0; i < c->n; i++)
        p -= v[i] * f[i];
    return p / (double)c->n;
}

/* The diagonal tangent of law (4) at (v, f_eq), mun = 1 (spec Eq. (4)). */
static void tangent(double eps, double v, double feq, double *Fv, double *Feq)
{
    double sat = feq > 1.0 ? 1.0 : feq < -1.0 ? -1.0 : feq;
    if (fabs(v - 0.5 * eps * sat) < 0.5 * eps) {
        *Fv = -2.0 / eps;
        *Feq = fabs(feq) < 1.0 ? 1.0 : 0.0;
    } else {
        *Fv = 0.0;
        *Feq = 0.0;
    }
}

/* R at a1 (u1, v1, f1 updated); returns ||R||_inf, or NAN if the law refused. */
static double residual(struct chain *c, const struct chain_implicit_opts *o, double t1, double b,
                       double gdt)
{
    size_t n = c->n;
    for (size_t i = 0; i < n; i++) {
        c->u1[i] = c->up[i] + b * c->a1[i];
        c->v1[i] = c->vp[i] + gdt * c->a1[i];
    }
    if (forces(c, t1, c->u1, c->v1, c->R, c->f1, c->feq1) != FRICREG_OK)
        return NAN;
    double r = 0.0;
    for (size_t i = 0; i < n; i++) {
        c->R[i] = c->a1[i] - (1.0 + o->alpha) * c->R[i] + o->alpha * c->g0[i];
        r = fmax(r, fabs(c->R[i]));
    }
    return r;
}

/* The tridiagonal dR/da1 at the last residual's point, solved for dx = -(dR/da1)^-1 R. */
static int newton_direction(struct chain *c, const struct chain_implicit_opts *o, double b,
                            double gdt)
{
    size_t n = c->n;
    double w = 1.0 + o->alpha, kb = c->n2 * b;
    for (size_t i = 0; i < n; i++) {
        double Fv, Feq;
        tangent(c->eps, c->v1[i], c->feq1[i], &Fv, &Feq);
        double s = w * (1.0 - Feq) * kb, kii = i == 0 ? 1.0 : 2.0;
        gsl_vector_set(c->diag, i, 1.0 + s * kii - w * gdt * Fv);
        if (i + 1 < n)
            gsl_vector_set(c->above, i, -s);
        if (i > 0)
            gsl_vector_set(c->below, i - 1, -s);
        gsl_vector_set(c->rhs, i, -c->R[i]);
    }
    return gsl_linalg_solve_tridiag(c->diag, c->above, c->below, c->rhs, c->dx) == GSL_SUCCESS
               ? FRICREG_OK
               : FRICREG_ESINGULAR;
}

/* One step from t0 to t0 + dt; *iters counts Newton iterations. */
static int step(struct chain *c, const struct chain_implicit_opts *o, double t0, double dt,
                int64_t *iters)
{
    size_t n = c->n;
    double beta = 0.25 * (1.0 - o->alpha) * (1.0 - o->alpha), gamma = 0.5 - o->alpha;
    double b = beta * dt * dt, gdt = gamma * dt, t1 = t0 + dt;
    for (size_t i = 0; i < n; i++) {
        c->up[i] = c->u[i] + dt * c->v[i] + (0.5 - beta) * dt * dt * c->acc[i];
        c->vp[i] = c->v[i] + (1.0 - gamma) * dt * c->acc[i];
        c->a1[i] = c->acc[i];
    }
    double r = residual(c, o, t1, b, gdt), scale = (double)n * (fabs(c->a) + 1.0);
    for (int k = 0; k < NEWTON_MAX; k++) {
        if (!(r > o->newton_tol * scale) && k > 0)
            return FRICREG_OK;
        if (!isfinite(r) || newton_direction(c, o, b, gdt) != FRICREG_OK)
            return FRICREG_EDIVERGED;
        ++*iters;
        /* Halve along dx until ||R|| decreases: law (4) is piecewise linear, and a full step
         * from one piece can overshoot across the band. */
        memcpy(c->a_old, c->a1, n * sizeof(double));
        double lambda = 1.0, r_new = NAN;
        for (int cut = 0; cut < 30; cut++, lambda *= 0.5) {
            for (size_t i = 0; i < n; i++)
                c->a1[i] = c->a_old[i] + lambda * gsl_vector_get(c->dx, i);
            r_new = residual(c, o, t1, b, gdt);
            if (r_new < r)
                break;
        }
        r = r_new;
    }
    return r <= o->newton_tol * scale ? FRICREG_OK : FRICREG_EDIVERGED;
}

static void release(struct chain *c)
{
    double *arrays[] = {c->u,  c->v,  c->acc, c->f,  c->feq,  c->mun, c->up, c->vp,
                        c->u1, c->v1, c->a1,  c->f1, c->feq1, c->R,   c->g0, c->a_old};
    for (size_t k = 0; k < sizeof arrays / sizeof arrays[0]; k++)
        free(arrays[k]);
    gsl_vector_free(c->diag);
    gsl_vector_free(c->above);
    gsl_vector_free(c->below);
    gsl_vector_free(c->rhs);
    gsl_vector_free(c->dx);
}

int chain_implicit_run(const struct chain_implicit_opts *o, struct bench_run *out)
{
    struct chain c = {0};
    c.n = o->n;
    c.a = o->a;
    c.omega = o->omega;
    c.eps = o->eps;
    c.n2 = (double)o->n * (double)o->n;
    size_t n = o->n;
    double **arrays[] = {&c.u,  &c.v,  &c.acc, &c.f,  &c.feq,  &c.mun, &c.up, &c.vp,
                         &c.u1, &c.v1, &c.a1,  &c.f1, &c.feq1, &c.R,   &c.g0, &c.a_old};
    *out = (struct bench_run){0};
    int ok = 1;
    for (size_t k = 0; k < sizeof arrays / sizeof arrays[0]; k++)
        ok &= (*arrays[k] = calloc(n, sizeof(double))) != NULL;
    c.diag = gsl_vector_alloc(n);
    c.above = gsl_vector_alloc(n - 1);
    c.below = gsl_vector_alloc(n - 1);
    c.rhs = gsl_vector_alloc(n);
    c.dx = gsl_vector_alloc(n);
    if (!ok || !c.diag || !c.above || !c.below || !c.rhs || !c.dx) {
        release(&c);
        out->status = FRICREG_ENOMEM;
        return out->status;
    }
    for (size_t i = 0; i < n; i++)
        c.mun[i] = 1.0;
    double T = 2.0 * 3.14159265358979323846 / o->omega, D = 0.0;
    size_t steps = (size_t)ceil(T / o->dt - 1e-9);
    double dt = T / (double)steps;
    int64_t iters = 0;
    int status = forces(&c, 0.0, c.u, c.v, c.acc, c.f, c.feq); /* at rest: a = g(0) */
    memcpy(c.g0, c.acc, n * sizeof(double));
    for (size_t k = 0; status == FRICREG_OK && k < steps; k++) {
        double p0 = power(&c, c.v, c.f);
        status = step(&c, o, (double)k * dt, dt, &iters);
        if (status != FRICREG_OK) {
            snprintf(out->msg, sizeof out->msg, "Newton failed at t = %g", (double)k * dt);
            break;
        }
        D += 0.5 * dt * (p0 + power(&c, c.v1, c.f1));
        memcpy(c.u, c.u1, n * sizeof(double));
        memcpy(c.v, c.v1, n * sizeof(double));
        memcpy(c.acc, c.a1, n * sizeof(double));
        memcpy(c.f, c.f1, n * sizeof(double));
        /* g at the new start for HHT's alpha term: a_free + f at (t1, u1, v1). */
        for (size_t i = 0; i < n; i++)
            c.g0[i] = -c.feq1[i] + c.f1[i];
    }
    out->status = status;
    out->D = status == FRICREG_OK ? D : NAN;
    out->steps = (double)steps;
    out->rhs_evals = (double)iters; /* Newton iterations */
    release(&c);
    return status;
}
