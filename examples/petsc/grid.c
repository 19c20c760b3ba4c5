/* SPDX-License-Identifier: GPL-3.0-or-later */
/* grid.c — a 2-D grid of masses and springs with friction contacts to the ground on a subset
 * of its nodes, under harmonic ground motion, on a 2-D DMDA across MPI ranks: TSALPHA2
 * (generalized-alpha for second-order systems) with libfricreg_petsc's residual and exact
 * Jacobian, Newton by SNES.
 *
 * Each node moves along one direction: u_ij relative to the ground, unit mass, springs of
 * stiffness k to its four neighbours and k0 to the ground (a column), damping c M. In the
 * ground's frame (relative coordinates, as fricreg_structure's M u'' + C u' + K u = -M r a_g
 * + J^T f) the ground motion x_g = A sin(omega t) is the force -M a_g, and the contacts at
 * the nodes with i and j multiples of 3 hold each node to the ground with mu N = 0.3 m A
 * omega^2: the grid slides on them and sticks. Law (4), eps = 1e-3 of the peak ground velocity
 * A omega by default.
 *
 * Options: -nx, -ny nodes [64] (1000 x 1000: 10^6 dof), -cycles ground cycles [2],
 * -steps_per_cycle [50], -eps_ratio eps/(A omega) [1e-3], the adapter's -fricreg_law,
 * -fricreg_eps (eps itself, over -eps_ratio) and -fricreg_mun (fricreg_petsc_set_from_options,
 * read after the settings above, so they override them), and every TS/SNES/KSP option.
 * Prints, on rank 0, the steps, the Newton iterations per step, the failed steps, the seconds
 * and the rank count. */
#include <math.h>

#include <petscdmda.h>
#include <petscts.h>

#include "fricreg_petsc.h"

#define SPRING 100.0  /* k between neighbours */
#define COLUMN 10.0   /* k0 to the ground */
#define DAMPING 0.05  /* c: C = c M */
#define GROUND_A 0.01 /* ground displacement amplitude A */
#define MU_G 0.3      /* mu N = MU_G m A omega^2 */

struct grid {
    DM da;
    PetscInt nx, ny;
    double omega;
    fricreg_petsc *fp;
};

/* F_free = -K U - C V - M a_g(t), a_g = -A omega^2 sin(omega t), unit masses. */
static PetscErrorCode free_force(struct grid *g, PetscReal t, Vec U, Vec V, Vec F)
{
    Vec Ul;
    const PetscScalar **u, **v;
    PetscScalar **f;
    PetscInt xs, ys, xm, ym;
    double ag = -GROUND_A * g->omega * g->omega * sin(g->omega * t);
    PetscFunctionBeginUser;
    PetscCall(DMGetLocalVector(g->da, &Ul));
    PetscCall(DMGlobalToLocal(g->da, U, INSERT_VALUES, Ul)); /* the halo: neighbours' u */
    PetscCall(DMDAGetCorners(g->da, &xs, &ys, NULL, &xm, &ym, NULL));
    PetscCall(DMDAVecGetArrayRead(g->da, Ul, &u));
    PetscCall(DMDAVecGetArrayRead(g->da, V, &v));
    PetscCall(DMDAVecGetArray(g->da, F, &f));
    for (PetscInt j = ys; j < ys + ym; j++)
        for (PetscInt i = xs; i < xs + xm; i++) {
            double s = COLUMN * u[j][i];
            if (i > 0)
                s += SPRING * (u[j][i] - u[j][i - 1]);
            if (i < g->nx - 1)
                s += SPRING * (u[j][i] - u[j][i + 1]);
            if (j > 0)
                s += SPRING * (u[j][i] - u[j - 1][i]);
            if (j < g->ny - 1)
                s += SPRING * (u[j][i] - u[j + 1][i]);
            f[j][i] = -s - DAMPING * v[j][i] - ag;
        }
    PetscCall(DMDAVecRestoreArray(g->da, F, &f));
    PetscCall(DMDAVecRestoreArrayRead(g->da, V, &v));
    PetscCall(DMDAVecRestoreArrayRead(g->da, Ul, &u));
    PetscCall(DMRestoreLocalVector(g->da, &Ul));
    PetscFunctionReturn(0);
}

/* R = M A - F_free - J^T f. */
static PetscErrorCode residual(TS ts, PetscReal t, Vec U, Vec V, Vec A, Vec R, void *ctx)
{
    struct grid *g = ctx;
    Vec F;
    PetscFunctionBeginUser;
    (void)ts;
    PetscCall(DMGetGlobalVector(g->da, &F));
    PetscCall(free_force(g, t, U, V, F));
    PetscCall(VecWAXPY(R, -1.0, F, A)); /* unit masses */
    int status = fricreg_petsc_residual_add(g->fp, V, F, R, NULL);
    PetscCall(DMRestoreGlobalVector(g->da, &F));
    PetscCheck(status == FRICREG_OK, PETSC_COMM_SELF, PETSC_ERR_LIB, "fricreg: %s",
               fricreg_petsc_errmsg(g->fp));
    PetscFunctionReturn(0);
}

/* P = a_shift M + v_shift C + K, then the friction's exact derivative. */
static PetscErrorCode jacobian(TS ts, PetscReal t, Vec U, Vec V, Vec A, PetscReal v_shift,
                               PetscReal a_shift, Mat J, Mat P, void *ctx)
{
    struct grid *g = ctx;
    PetscInt xs, ys, xm, ym;
    PetscFunctionBeginUser;
    (void)ts, (void)A;
    PetscCall(DMDAGetCorners(g->da, &xs, &ys, NULL, &xm, &ym, NULL));
    for (PetscInt j = ys; j < ys + ym; j++)
        for (PetscInt i = xs; i < xs + xm; i++) {
            MatStencil row = {.i = i, .j = j}, col[5];
            PetscScalar val[5];
            PetscInt n = 1;
            double diag = a_shift + v_shift * DAMPING + COLUMN;
            const PetscInt di[4] = {-1, 1, 0, 0}, dj[4] = {0, 0, -1, 1};
            for (int e = 0; e < 4; e++) {
                PetscInt ii = i + di[e], jj = j + dj[e];
                if (ii < 0 || ii >= g->nx || jj < 0 || jj >= g->ny)
                    continue;
                col[n].i = ii, col[n].j = jj, val[n++] = -SPRING;
                diag += SPRING;
            }
            col[0] = row, val[0] = diag;
            PetscCall(MatSetValuesStencil(P, 1, &row, n, col, val, INSERT_VALUES));
        }
    PetscCall(MatAssemblyBegin(P, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(P, MAT_FINAL_ASSEMBLY));
    Vec F;
    PetscCall(DMGetGlobalVector(g->da, &F));
    PetscCall(free_force(g, t, U, V, F));
    int status = fricreg_petsc_jacobian_add(g->fp, V, F, a_shift, v_shift, P);
    PetscCall(DMRestoreGlobalVector(g->da, &F));
    PetscCheck(status == FRICREG_OK, PETSC_COMM_SELF, PETSC_ERR_LIB, "fricreg: %s",
               fricreg_petsc_errmsg(g->fp));
    if (J != P) {
        PetscCall(MatAssemblyBegin(J, MAT_FINAL_ASSEMBLY));
        PetscCall(MatAssemblyEnd(J, MAT_FINAL_ASSEMBLY));
    }
    PetscFunctionReturn(0);
}

/* Contacts at the owned nodes with i and j multiples of 3. */
static PetscErrorCode make_contacts(struct grid *g, double eps)
{
    PetscInt xs, ys, xm, ym, rstart, m = 0;
    Vec mass;
    PetscInt *node;
    double *mun;
    PetscFunctionBeginUser;
    PetscCall(DMDAGetCorners(g->da, &xs, &ys, NULL, &xm, &ym, NULL));
    PetscCall(DMCreateGlobalVector(g->da, &mass));
    PetscCall(VecSet(mass, 1.0));
    PetscCall(VecGetOwnershipRange(mass, &rstart, NULL));
    PetscCall(PetscMalloc2(xm * ym + 1, &node, xm * ym + 1, &mun));
    for (PetscInt j = ys; j < ys + ym; j++)
        for (PetscInt i = xs; i < xs + xm; i++)
            if (i % 3 == 0 && j % 3 == 0) {
                node[m] = rstart + (j - ys) * xm + (i - xs); /* a DMDA's global order */
                mun[m++] = MU_G * GROUND_A * g->omega * g->omega;
            }
    int status = fricreg_petsc_create(mass, (size_t)m, node, NULL, &g->fp);
    if (status == FRICREG_OK)
        status = fricreg_petsc_set_law(g->fp, FRICREG_LAW_QUINN, eps);
    if (status == FRICREG_OK)
        status = fricreg_petsc_set_bounds(g->fp, (size_t)m, mun);
    if (status == FRICREG_OK) /* -fricreg_law, -fricreg_eps, -fricreg_mun override */
        status = fricreg_petsc_set_from_options(g->fp, NULL, NULL);
    PetscCall(PetscFree2(node, mun));
    PetscCall(VecDestroy(&mass));
    PetscCheck(status == FRICREG_OK, PETSC_COMM_SELF, PETSC_ERR_LIB, "fricreg: %s",
               g->fp != NULL ? fricreg_petsc_errmsg(g->fp) : fricreg_petsc_strerror(status));
    PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
    struct grid g = {.nx = 64, .ny = 64, .omega = 2.0 * PETSC_PI};
    PetscInt cycles = 2, per_cycle = 50;
    PetscReal eps_ratio = 1e-3;
    TS ts;
    Vec U, V;
    Mat P;
    PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
    PetscCall(PetscOptionsGetInt(NULL, NULL, "-nx", &g.nx, NULL));
    PetscCall(PetscOptionsGetInt(NULL, NULL, "-ny", &g.ny, NULL));
    PetscCall(PetscOptionsGetInt(NULL, NULL, "-cycles", &cycles, NULL));
    PetscCall(PetscOptionsGetInt(NULL, NULL, "-steps_per_cycle", &per_cycle, NULL));
    PetscCall(PetscOptionsGetReal(NULL, NULL, "-eps_ratio", &eps_ratio, NULL));
    PetscCall(DMDACreate2d(PETSC_COMM_WORLD, DM_BOUNDARY_NONE, DM_BOUNDARY_NONE, DMDA_STENCIL_STAR,
                           g.nx, g.ny, PETSC_DECIDE, PETSC_DECIDE, 1, 1, NULL, NULL, &g.da));
    PetscCall(DMSetUp(g.da));
    PetscCall(make_contacts(&g, eps_ratio * GROUND_A * g.omega));
    PetscCall(DMCreateGlobalVector(g.da, &U));
    PetscCall(VecDuplicate(U, &V));
    PetscCall(VecSet(U, 0.0));
    PetscCall(VecSet(V, 0.0));
    PetscCall(DMCreateMatrix(g.da, &P));

    double period = 2.0 * PETSC_PI / g.omega;
    PetscCall(TSCreate(PETSC_COMM_WORLD, &ts));
    PetscCall(TSSetDM(ts, g.da));
    PetscCall(TSSetType(ts, TSALPHA2));
    PetscCall(TSSetI2Function(ts, NULL, residual, &g));
    PetscCall(TSSetI2Jacobian(ts, P, P, jacobian, &g));
    PetscCall(TSSetTimeStep(ts, period / (double)per_cycle));
    PetscCall(TSSetMaxSteps(ts, cycles * per_cycle));
    PetscCall(TSSetMaxTime(ts, 1e300));
    PetscCall(TSSetExactFinalTime(ts, TS_EXACTFINALTIME_MATCHSTEP));
    PetscCall(TSSetMaxSNESFailures(ts, -1)); /* counted, not fatal: the output reports them */
    PetscCall(TS2SetSolution(ts, U, V));
    SNES snes;
    KSP ksp;
    PetscCall(TSGetSNES(ts, &snes));
    PetscCall(SNESGetKSP(snes, &ksp));
    /* Solved to rounding, so that Newton's count is the tangent's, whatever the ranks' block
     * preconditioner (-ksp_rtol overrides). */
    PetscCall(KSPSetTolerances(ksp, 1e-12, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT));
    PetscCall(TSSetFromOptions(ts));
    PetscLogDouble t0, t1;
    PetscCall(PetscTime(&t0));
    PetscCall(TSSolve(ts, NULL));
    PetscCall(PetscTime(&t1));

    PetscInt steps, newton, rejected, failures;
    PetscCall(TSGetStepNumber(ts, &steps));
    PetscCall(TSGetSNESIterations(ts, &newton));
    PetscCall(TSGetStepRejections(ts, &rejected));
    PetscCall(TSGetSNESFailures(ts, &failures));
    PetscMPIInt size;
    PetscCallMPI(MPI_Comm_size(PETSC_COMM_WORLD, &size));
    PetscCall(PetscPrintf(PETSC_COMM_WORLD,
                          "grid %d x %d, ranks = %d, steps = %d, Newton iterations per step = "
                          "%.3f, failed steps = %d, seconds = %.3f\n",
                          (int)g.nx, (int)g.ny, (int)size, (int)steps,
                          (double)newton / (double)steps, (int)(rejected + failures), t1 - t0));
    PetscCall(TSDestroy(&ts));
    PetscCall(MatDestroy(&P));
    PetscCall(VecDestroy(&U));
    PetscCall(VecDestroy(&V));
    fricreg_petsc_free(g.fp);
    PetscCall(DMDestroy(&g.da));
    PetscCall(PetscFinalize());
    return 0;
}
