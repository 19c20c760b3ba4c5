/* SPDX-License-Identifier: GPL-3.0-or-later */
/* sim_jacobian.c — the Jacobian of the drivers' ODE, for GSL's implicit steppers.
 *
 * The state is y = (x, v, D) (sim.c) and each system is linear in x, v and f (system.h):
 *   zdot = Zv v + zdot_0(t),  a_free = Ax x + a_0(t),
 *   x' = v,  v' = Cx x + Cf f + c_0(t),  D' = -w zdot . f,
 * with f = f(zdot, a_free) from the context. By the chain rule through the context's tangent
 * Tz = df/dzdot, Ta = df/da_free (fricreg_ctx_tangent, exact almost everywhere):
 *   dv'/dx = Cx + Cf Ta Ax,              dv'/dv = Cf Tz Zv,
 *   dD'/dx = -w zdot^T Ta Ax,            dD'/dv = -w (f^T Zv + zdot^T Tz Zv),
 *   dv'/dt = c_0' + Cf g,                dD'/dt = -w (zdot_0' . f + zdot . g),
 * where g = Tz zdot_0' + Ta a_0' is how f moves with t at a fixed state. Nothing depends on D.
 *
 * Differences cannot see the stick zone well: its slope 2 mun/eps is resolved only by a step
 * below eps, and a step that crosses |zdot| = eps or a saturation edge mixes two pieces. The
 * tangent has neither problem, and costs one evaluation instead of 2n + 2.
 *
 * The products skip the zeros of their left factor, so a diagonal tangent (W = I, the chain)
 * costs O(m n) per product, not O(m^2 n): the Jacobian is O(n^2) to write anyway. The system's
 * constant maps are formed once, at the first call of a run (only implicit steppers ask). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_math.h>

#include "ode/fd_jacobian.h"
#include "sim_internal.h"
#include "base/free_all.h"

struct fr_jacobian {
    size_t n, m;
    double *Zv, *Ax;              /* [m x n] the contacts' maps */
    double *Cx, *Cf;              /* [n x n], [n x m] the bodies' maps */
    double *Tz, *Ta;              /* [m x m] the context's tangent */
    double *TaAx, *TzZv;          /* [m x n] products */
    double *zdot_t, *afree_t, *g; /* [m] forcing rates; g = Tz zdot_t + Ta afree_t */
    double *acc_t;                /* [n] */
    double *dydt;                 /* [2n + 1] the right-hand side, discarded */
};

void fr_jacobian_free(struct fr_jacobian *J)
{
    if (J == NULL)
        return;
    FR_FREE_ALL(J->Zv, J->Ax, J->Cx, J->Cf, J->Tz, J->Ta, J->TaAx, J->TzZv, J->zdot_t, J->afree_t,
                J->g, J->acc_t, J->dydt, J);
}

/* The maps of `sys` and scratch for n bodies and m contacts; NULL if out of memory. */
static struct fr_jacobian *jacobian_alloc(const struct fr_system *sys, size_t n, size_t m)
{
    struct fr_jacobian *J = calloc(1, sizeof *J);
    if (J == NULL)
        return NULL;
    J->n = n;
    J->m = m;
    J->Zv = malloc(m * n * sizeof *J->Zv);
    J->Ax = malloc(m * n * sizeof *J->Ax);
    J->Cx = malloc(n * n * sizeof *J->Cx);
    J->Cf = malloc(n * m * sizeof *J->Cf);
    J->Tz = malloc(m * m * sizeof *J->Tz);
    J->Ta = malloc(m * m * sizeof *J->Ta);
    J->TaAx = malloc(m * n * sizeof *J->TaAx);
    J->TzZv = malloc(m * n * sizeof *J->TzZv);
    J->zdot_t = malloc(m * sizeof *J->zdot_t);
    J->afree_t = malloc(m * sizeof *J->afree_t);
    J->g = malloc(m * sizeof *J->g);
    J->acc_t = malloc(n * sizeof *J->acc_t);
    J->dydt = malloc((2 * n + 1) * sizeof *J->dydt);
    if (!J->Zv || !J->Ax || !J->Cx || !J->Cf || !J->Tz || !J->Ta || !J->TaAx || !J->TzZv ||
        !J->zdot_t || !J->afree_t || !J->g || !J->acc_t || !J->dydt) {
        fr_jacobian_free(J);
        return NULL;
    }
    sys->type->contact_maps(sys, J->Zv, J->Ax);
    sys->type->body_maps(sys, J->Cx, J->Cf);
    return J;
}

/* C[r x c] (row stride ldc) = L[r x k] R[k x c], skipping the zeros of L. */
static void multiply(size_t r, size_t k, size_t c, const double L[], const double R[], double C[],
                     size_t ldc)
{
    for (size_t i = 0; i < r; i++) {
        double *row = C + i * ldc;
        memset(row, 0, c * sizeof *row);
        for (size_t j = 0; j < k; j++) {
            double l = L[i * k + j];
            if (l == 0.0)
                continue;
            const double *rj = R + j * c;
            for (size_t col = 0; col < c; col++)
                row[col] += l * rj[col];
        }
    }
}

/* out[c] = s * u[r]^T M[r x c] + out, skipping the zeros of u. */
static void add_row_product(size_t r, size_t c, double s, const double u[], const double M[],
                            double out[])
{
    for (size_t i = 0; i < r; i++) {
        if (u[i] == 0.0)
            continue;
        for (size_t col = 0; col < c; col++)
            out[col] += s * u[i] * M[i * c + col];
    }
}

static double dot(size_t len, const double a[], const double b[])
{
    double s = 0.0;
    for (size_t i = 0; i < len; i++)
        s += a[i] * b[i];
    return s;
}

/* dfdy[dim x dim], row-major, from the tangent in J->Tz, J->Ta at sim->zdot, sim->f. */
static void assemble_dfdy(const fricreg_sim *sim, struct fr_jacobian *J, double w, double *dfdy)
{
    size_t n = J->n, m = J->m, dim = 2 * n + 1;
    memset(dfdy, 0, dim * dim * sizeof *dfdy);
    for (size_t i = 0; i < n; i++)
        dfdy[i * dim + n + i] = 1.0; /* x' = v */

    multiply(m, m, n, J->Ta, J->Ax, J->TaAx, n);
    multiply(m, m, n, J->Tz, J->Zv, J->TzZv, n);
    double *vx = dfdy + n * dim, *vv = vx + n; /* rows n..2n-1, row stride dim */
    multiply(n, m, n, J->Cf, J->TaAx, vx, dim);
    multiply(n, m, n, J->Cf, J->TzZv, vv, dim);
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++)
            vx[i * dim + j] += J->Cx[i * n + j];

    double *Dx = dfdy + 2 * n * dim, *Dv = Dx + n; /* the last row */
    add_row_product(m, n, -w, sim->zdot, J->TaAx, Dx);
    add_row_product(m, n, -w, sim->f, J->Zv, Dv);
    add_row_product(m, n, -w, sim->zdot, J->TzZv, Dv);
}

/* dfdt[dim]: how the right-hand side moves with t at a fixed state. */
static void assemble_dfdt(const fricreg_sim *sim, struct fr_jacobian *J, double t, double w,
                          double dfdt[])
{
    size_t n = J->n, m = J->m;
    sim->sys.type->time_rates(&sim->sys, t, J->zdot_t, J->afree_t, J->acc_t);
    for (size_t i = 0; i < m; i++)
        J->g[i] = dot(m, J->Tz + i * m, J->zdot_t) + dot(m, J->Ta + i * m, J->afree_t);
    for (size_t i = 0; i < n; i++) {
        dfdt[i] = 0.0;
        dfdt[n + i] = J->acc_t[i] + dot(m, J->Cf + i * m, J->g);
    }
    dfdt[2 * n] = -w * (dot(m, J->zdot_t, sim->f) + dot(m, sim->zdot, J->g));
}

static int has_linear_maps(const struct fr_system_type *type)
{
    return type->contact_maps && type->body_maps && type->time_rates;
}

int fr_sim_jacobian(double t, const double y[], double *dfdy, double dfdt[], void *params)
{
    fricreg_sim *sim = params;
    if (!has_linear_maps(sim->sys.type))
        return fr_sim_jacobian_fd(t, y, dfdy, dfdt, params);
    if (sim->jac == NULL)
        sim->jac = jacobian_alloc(&sim->sys, sim->ndof, sim->m);
    if (sim->jac == NULL) {
        sim->rhs_status = FRICREG_ENOMEM;
        return GSL_ENOMEM;
    }
    struct fr_jacobian *J = sim->jac;
    /* Off for the run's explicit steppers (sim.c), on once a Jacobian is asked for; cheap, and
     * it cannot fail with a valid context and 1. */
    fricreg_ctx_set_keep_tangent(sim->ctx, 1);
    int status = fr_sim_rhs(t, y, J->dydt, sim); /* the tangent is that of the last eval */
    if (status != GSL_SUCCESS)
        return status;
    status = fricreg_ctx_tangent(sim->ctx, sim->m, J->Tz, J->Ta);
    if (status != FRICREG_OK) {
        sim->rhs_status = status;
        return GSL_EBADFUNC;
    }
    double w = sim->sys.type->dissipation_weight(&sim->sys);
    assemble_dfdy(sim, J, w, dfdy);
    assemble_dfdt(sim, J, t, w, dfdt);
    return GSL_SUCCESS;
}

/* Jacobian by forward differences (fd_jacobian.h), kept for systems without linear maps and
 * for comparison; the D column is zero, as nothing depends on D. */
int fr_sim_jacobian_fd(double t, const double y[], double *dfdy, double dfdt[], void *params)
{
    fricreg_sim *sim = params;
    return fr_fd_jacobian(fr_sim_rhs, sim, 2 * sim->ndof + 1, sim->jac_work, t, y, dfdy, dfdt);
}
