/* SPDX-License-Identifier: GPL-3.0-or-later */
/* chain.c — the paper's chain of blocks (Quinn 2004, Sec. 3.2) on a PETSc DMDA across MPI
 * ranks, stepped by TSRK's classical RK4 at a fixed step, friction by libfricreg_petsc.
 *
 * Block i has u_i'' = a_free,i + f_i with a_free = -n^2 K u + n a sin(omega t) e_1 (K the
 * tridiagonal stiffness, block 1 free, block n tied to a wall), mu N = 1, W = I, law (4) with
 * the paper's eps = 10 omega dt, and its dissipation D = -(1/n) sum_i ∫ u_i' f_i dt per forcing
 * cycle. The DMDA holds (u, v, d) per block: d_i' = -(1/n) v_i f_i is block i's dissipation, so
 * D is a sum taken once a cycle and friction adds no communication to a step (the stiffness
 * needs the ghost blocks' u, the DMDA's halo exchange).
 *
 * The steps are fricreg-sim chain's: each call of 2 dt is two classical steps of dt, and a
 * cycle's last, shortened call two halves of what is left (src/ode/rk4_classic.c), so D is that
 * of `fricreg-sim chain` to rounding.
 *
 * Options: -n blocks [32] (up to 10^7), -a [0.25], -omega [0.5], -dt [0.01], -cycles [4];
 * -steps S: S classical steps instead of cycles, D over them (the large chains, where a cycle
 * takes 10^7 steps: dt must stay below 2.8/(2n)); -v0 A: start from v_i = A sin(pi (i + 1/2)/n)
 * (every block moving, so every rank's contacts slide and stick) instead of rest.
 * Prints "D[k] = ..." per cycle (or "D = ..." over the steps), with 17 digits, on rank 0. */
#include <math.h>
#include <stdio.h>

#include <petscdmda.h>
#include <petscts.h>

#include "fricreg_petsc.h"

typedef struct {
    PetscScalar u, v, d;
} Block;

struct chain {
    DM da;
    PetscInt n;
    double a, omega;
    fricreg_petsc *fp;
    double *f; /* [m] the forces of the last evaluation */
    size_t m;
};

/* The right-hand side: (u, v, d)' = (v, a_free + f, -(1/n) v f). */
static PetscErrorCode rhs(TS ts, PetscReal t, Vec X, Vec F, void *ctx)
{
    struct chain *c = ctx;
    Vec Xl;
    const Block *x;
    Block *g;
    PetscInt xs, xm;
    double n2 = (double)c->n * (double)c->n;
    PetscFunctionBeginUser;
    (void)ts;
    PetscCall(DMGetLocalVector(c->da, &Xl));
    PetscCall(DMGlobalToLocal(c->da, X, INSERT_VALUES, Xl)); /* the halo: neighbours' u */
    PetscCall(DMDAGetCorners(c->da, &xs, NULL, NULL, &xm, NULL, NULL));
    PetscCall(DMDAVecGetArrayRead(c->da, Xl, &x));
    PetscCall(DMDAVecGetArray(c->da, F, &g));
    /* The expressions of src/sim/systems/chain.c, term for term. */
    for (PetscInt i = xs; i < xs + xm; i++) {
        double af;
        if (i == 0)
            af = -n2 * (x[0].u - x[1].u) + (double)c->n * (c->a * sin(c->omega * t));
        else if (i == c->n - 1)
            af = -n2 * (-x[i - 1].u + 2.0 * x[i].u);
        else
            af = -n2 * (-x[i - 1].u + 2.0 * x[i].u - x[i + 1].u);
        g[i].u = x[i].v;
        g[i].v = af;
        g[i].d = 0.0;
    }
    PetscCall(DMDAVecRestoreArray(c->da, F, &g));
    PetscCall(DMDAVecRestoreArrayRead(c->da, Xl, &x));
    PetscCall(DMRestoreLocalVector(c->da, &Xl));
    if (fricreg_petsc_rhs_add(c->fp, X, F, NULL) != FRICREG_OK ||
        fricreg_petsc_get_forces(c->fp, c->m, c->f) != FRICREG_OK)
        SETERRQ(PETSC_COMM_SELF, PETSC_ERR_LIB, "fricreg: %s", fricreg_petsc_errmsg(c->fp));
    PetscCall(DMDAVecGetArrayRead(c->da, X, &x));
    PetscCall(DMDAVecGetArray(c->da, F, &g));
    for (PetscInt i = xs; i < xs + xm; i++)
        g[i].d = -x[i].v * c->f[i - xs] / (double)c->n;
    PetscCall(DMDAVecRestoreArray(c->da, F, &g));
    PetscCall(DMDAVecRestoreArrayRead(c->da, X, &x));
    PetscFunctionReturn(0);
}

/* One contact per owned block, on its v; unit masses (W = I). */
static PetscErrorCode make_contacts(struct chain *c, double eps)
{
    PetscInt xs, xm;
    Vec mass;
    PetscFunctionBeginUser;
    PetscCall(DMDAGetCorners(c->da, &xs, NULL, NULL, &xm, NULL, NULL));
    PetscCall(DMCreateGlobalVector(c->da, &mass));
    PetscCall(VecSet(mass, 1.0));
    PetscInt *node;
    PetscCall(PetscMalloc1(xm > 0 ? xm : 1, &node));
    PetscCall(PetscMalloc1(xm > 0 ? xm : 1, &c->f));
    for (PetscInt i = 0; i < xm; i++)
        node[i] = 3 * (xs + i) + 1; /* a 1-D DMDA's global order is the natural one */
    c->m = (size_t)xm;
    int status = fricreg_petsc_create(mass, c->m, node, NULL, &c->fp);
    if (status == FRICREG_OK)
        status = fricreg_petsc_set_law(c->fp, FRICREG_LAW_QUINN, eps);
    PetscCall(PetscFree(node));
    PetscCall(VecDestroy(&mass));
    if (status != FRICREG_OK)
        SETERRQ(PETSC_COMM_SELF, PETSC_ERR_LIB, "fricreg: %s", fricreg_petsc_strerror(status));
    PetscFunctionReturn(0);
}

static PetscErrorCode initial(struct chain *c, Vec X, double v0)
{
    Block *x;
    PetscInt xs, xm;
    PetscFunctionBeginUser;
    PetscCall(DMDAGetCorners(c->da, &xs, NULL, NULL, &xm, NULL, NULL));
    PetscCall(DMDAVecGetArray(c->da, X, &x));
    for (PetscInt i = xs; i < xs + xm; i++) {
        x[i].u = x[i].d = 0.0;
        x[i].v = v0 * sin(PETSC_PI * ((double)i + 0.5) / (double)c->n);
    }
    PetscCall(DMDAVecRestoreArray(c->da, X, &x));
    PetscFunctionReturn(0);
}

/* One classical step of h from t. */
static PetscErrorCode classical_step(TS ts, double t, double h)
{
    PetscFunctionBeginUser;
    PetscCall(TSSetTime(ts, t));
    PetscCall(TSSetTimeStep(ts, h));
    PetscCall(TSStep(ts));
    PetscFunctionReturn(0);
}

/* fricreg-sim's grid from *t to target: calls of 2 dt, each two classical steps, the last one
 * shortened to end on target; *t is then target exactly. */
static PetscErrorCode advance(TS ts, double *t, double target, double dt)
{
    double call = 2.0 * dt;
    PetscFunctionBeginUser;
    while (*t < target) {
        int last = target - *t <= call * (1.0 + 1e-9);
        double h = last ? target - *t : call;
        PetscCall(classical_step(ts, *t, 0.5 * h));
        PetscCall(classical_step(ts, *t + 0.5 * h, 0.5 * h));
        *t = last ? target : *t + h;
    }
    PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
    struct chain c = {.n = 32, .a = 0.25, .omega = 0.5};
    PetscReal dt = 0.01, v0 = 0.0, a = 0.25, omega = 0.5;
    PetscInt cycles = 4, steps = 0;
    TS ts;
    TSAdapt adapt;
    Vec X;
    PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
    PetscCall(PetscOptionsGetInt(NULL, NULL, "-n", &c.n, NULL));
    PetscCall(PetscOptionsGetReal(NULL, NULL, "-a", &a, NULL));
    PetscCall(PetscOptionsGetReal(NULL, NULL, "-omega", &omega, NULL));
    PetscCall(PetscOptionsGetReal(NULL, NULL, "-dt", &dt, NULL));
    PetscCall(PetscOptionsGetReal(NULL, NULL, "-v0", &v0, NULL));
    PetscCall(PetscOptionsGetInt(NULL, NULL, "-cycles", &cycles, NULL));
    PetscCall(PetscOptionsGetInt(NULL, NULL, "-steps", &steps, NULL));
    PetscCheck(c.n >= 2 && c.n <= 10000000, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE,
               "-n must be 2 ... 10^7");
    c.a = a, c.omega = omega;
    PetscCall(DMDACreate1d(PETSC_COMM_WORLD, DM_BOUNDARY_NONE, c.n, 3, 1, NULL, &c.da));
    PetscCall(DMSetUp(c.da));
    PetscCall(make_contacts(&c, 10.0 * omega * dt)); /* the paper's eps (Sec. 3.2) */
    PetscCall(DMCreateGlobalVector(c.da, &X));
    PetscCall(initial(&c, X, v0));

    PetscCall(TSCreate(PETSC_COMM_WORLD, &ts));
    PetscCall(TSSetDM(ts, c.da));
    PetscCall(TSSetType(ts, TSRK));
    PetscCall(TSRKSetType(ts, TSRK4));
    PetscCall(TSSetRHSFunction(ts, NULL, rhs, &c));
    PetscCall(TSGetAdapt(ts, &adapt));
    PetscCall(TSAdaptSetType(adapt, TSADAPTNONE));
    PetscCall(TSSetSolution(ts, X));
    PetscCall(TSSetMaxTime(ts, 1e300)); /* the loop below decides the steps */
    PetscCall(TSSetMaxSteps(ts, PETSC_MAX_INT));
    PetscCall(TSSetFromOptions(ts));
    PetscCall(TSSetUp(ts));

    double t = 0.0, period = 2.0 * PETSC_PI / omega, D_start = 0.0, D_now;
    PetscLogDouble t0, t1;
    PetscCall(PetscTime(&t0));
    for (PetscInt s = 0; s < steps; s++, t += dt)
        PetscCall(classical_step(ts, t, dt));
    for (PetscInt k = 1; steps == 0 && k <= cycles; k++) {
        PetscCall(advance(ts, &t, (double)k * period, dt));
        PetscCall(TSGetSolution(ts, &X));
        PetscCall(VecStrideSum(X, 2, &D_now));
        PetscCall(PetscPrintf(PETSC_COMM_WORLD, "D[%d] = %.17g\n", (int)k, D_now - D_start));
        D_start = D_now;
    }
    PetscCall(PetscTime(&t1));
    if (steps > 0) {
        PetscCall(TSGetSolution(ts, &X));
        PetscCall(VecStrideSum(X, 2, &D_now));
        PetscCall(PetscPrintf(PETSC_COMM_WORLD, "D = %.17g\n", D_now));
    }
    PetscMPIInt size;
    PetscCallMPI(MPI_Comm_size(PETSC_COMM_WORLD, &size));
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "n = %d, ranks = %d, seconds = %.3f\n", (int)c.n,
                          (int)size, t1 - t0));
    PetscCall(TSDestroy(&ts));
    PetscCall(VecDestroy(&X));
    fricreg_petsc_free(c.fp);
    PetscCall(PetscFree(c.f));
    PetscCall(DMDestroy(&c.da));
    PetscCall(PetscFinalize());
    return 0;
}
