/* SPDX-License-Identifier: GPL-3.0-or-later */
/* cvode_twoblock.c — the paper's two blocks on a belt, Eqs. (7), integrated by the caller's own
 * SUNDIALS CVODE (BDF, dense Newton) with fricreg's context for the friction:
 *
 *   - the forces: fricreg_ctx_eval on the contacts' (zdot, a_free), W = [[1, -1], [-1, 2]];
 *   - the Jacobian: fricreg_ctx_tangent chained through the blocks' linear kinematics into a
 *     dense SUNMatrix (CVodeSetJacFn);
 *   - the kinks of law (4): fricreg_ctx_switching as CVODE's root functions (CVodeRootInit),
 *     and CVodeReInit at each root, so that BDF restarts on the new smooth piece;
 *   - the tolerances: the rule from eps of fricreg_sim (FRICREG_ATOL_FROM_EPS), read from
 *     fricreg_sim_get_abs_tolerances for the same state (x1, x2, v1, v2, D) and applied as an
 *     error-weight function (CVodeEwtFn): CVODE's CVodeSVtolerances would add rtol |v_i| to
 *     each velocity, and that relative part is what leaves a stick's contact velocity, a
 *     difference of O(1) body velocities inside the band |zdot| < eps, uncontrolled.
 *
 * Run: cvode_twoblock [rtol] (default 1e-6), eps = 1e-6, four belt cycles. It prints D on each
 * cycle and exits with 0 when D on cycle 4 is within 1e-4 of 1.7355132, the converged value of
 * tests/sim/test_kink_location.c (RK4 extrapolated in eps; rkf45, rk8pd and msbdf at rtol 1e-8 …
 * 1e-11), else 1; 2 when something failed to set up. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_types.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include "fricreg.h"
#include "fricreg_sim.h"

#if SUNDIALS_VERSION_MAJOR >= 7
#define COMM_NULL SUN_COMM_NULL
#else
#define COMM_NULL NULL
/* CVODE 6 prints its warnings; the one it gives after a restart on a kink, where a switching
 * function is 0 at the new start (and so inactive until it leaves 0), is expected here. */
static void quiet_warnings(int code, const char *module, const char *function, char *msg,
                           void *user)
{
    (void)user;
    if (code != CV_WARNING)
        fprintf(stderr, "[%s] %s: %s\n", module, function, msg);
}
#endif

#define D_REFERENCE 1.7355132 /* tests/sim/test_kink_location.c, eps = 1e-6 */
#define EPS 1e-6
#define M 2   /* contacts */
#define DIM 5 /* x1, x2, v1, v2, D */

/* The blocks' parameters (the paper's defaults: fricreg_sim.h, FRICREG_SYSTEM_TWOBLOCK). */
struct model {
    double k, belt_amp, belt_omega;
    fricreg_ctx *ctx;
    double atol[DIM], rtol, rel[DIM]; /* the rule: rel[i] 1 or 0 (velocities) */
    double zdot[M], a_free[M], f[M];
};

/* The contacts z1 = x1 - u(t), z2 = x2 - x1 on the belt u = b sin(w t), and the friction. */
static int forces(struct model *p, double t, const double y[])
{
    double w = p->belt_omega, b = p->belt_amp;
    p->zdot[0] = y[2] - b * w * cos(w * t);
    p->zdot[1] = y[3] - y[2];
    p->a_free[0] = b * w * w * sin(w * t) - y[0]; /* -u'' - x1 */
    p->a_free[1] = y[0] - p->k * y[1];
    return fricreg_ctx_eval(p->ctx, M, p->zdot, p->a_free, p->f, NULL) == FRICREG_OK ? 0 : -1;
}

/* Eqs. (7): x1'' = -x1 + f1 - f2, x2'' = -k x2 + f2, and D' = -(zdot . f). */
static int rhs(sunrealtype t, N_Vector yv, N_Vector ydot, void *user)
{
    struct model *p = user;
    const double *y = N_VGetArrayPointer(yv);
    double *dy = N_VGetArrayPointer(ydot);
    if (forces(p, t, y) != 0)
        return -1;
    dy[0] = y[2];
    dy[1] = y[3];
    dy[2] = -y[0] + p->f[0] - p->f[1];
    dy[3] = -p->k * y[1] + p->f[1];
    dy[4] = -(p->zdot[0] * p->f[0] + p->zdot[1] * p->f[1]);
    return 0;
}

/* The exact Jacobian: df/dx = (df/da_free) Ax and df/dv = (df/dzdot) Zv with the constant maps
 * Ax = da_free/dx = [[-1, 0], [1, -k]] and Zv = dzdot/dv = [[1, 0], [-1, 1]]. */
static int jacobian(sunrealtype t, N_Vector yv, N_Vector fy, SUNMatrix J, void *user, N_Vector t1,
                    N_Vector t2, N_Vector t3)
{
    (void)fy, (void)t1, (void)t2, (void)t3;
    struct model *p = user;
    const double *y = N_VGetArrayPointer(yv);
    double df_dz[M * M], df_da[M * M], Fx[M][M], Fv[M][M];
    const double Ax[M][M] = {{-1.0, 0.0}, {1.0, -p->k}}, Zv[M][M] = {{1.0, 0.0}, {-1.0, 1.0}};
    if (forces(p, t, y) != 0 || fricreg_ctx_tangent(p->ctx, M, df_dz, df_da) != FRICREG_OK)
        return -1;
    for (int i = 0; i < M; i++)
        for (int j = 0; j < M; j++) {
            Fx[i][j] = df_da[i * M] * Ax[0][j] + df_da[i * M + 1] * Ax[1][j];
            Fv[i][j] = df_dz[i * M] * Zv[0][j] + df_dz[i * M + 1] * Zv[1][j];
        }
    SUNMatZero(J);
    SM_ELEMENT_D(J, 0, 2) = 1.0;
    SM_ELEMENT_D(J, 1, 3) = 1.0;
    for (int j = 0; j < M; j++) {
        SM_ELEMENT_D(J, 2, j) = (j == 0 ? -1.0 : 0.0) + Fx[0][j] - Fx[1][j];
        SM_ELEMENT_D(J, 2, 2 + j) = Fv[0][j] - Fv[1][j];
        SM_ELEMENT_D(J, 3, j) = (j == 1 ? -p->k : 0.0) + Fx[1][j];
        SM_ELEMENT_D(J, 3, 2 + j) = Fv[1][j];
        SM_ELEMENT_D(J, 4, j) = -(p->zdot[0] * Fx[0][j] + p->zdot[1] * Fx[1][j]);
        SM_ELEMENT_D(J, 4, 2 + j) = -(Zv[0][j] * p->f[0] + Zv[1][j] * p->f[1] +
                                      p->zdot[0] * Fv[0][j] + p->zdot[1] * Fv[1][j]);
    }
    return 0;
}

/* The signed distances to the next kinks (7 per contact), at the state CVODE gives. */
static int roots(sunrealtype t, N_Vector yv, sunrealtype *g, void *user)
{
    struct model *p = user;
    if (forces(p, t, N_VGetArrayPointer(yv)) != 0)
        return -1;
    return fricreg_ctx_switching(p->ctx, M, p->zdot, p->a_free, p->f, g,
                                 fricreg_ctx_switching_count(p->ctx)) == FRICREG_OK
               ? 0
               : -1;
}

/* CVODE's error weights 1 / (atol_i + rel_i rtol |y_i|): fricreg_sim's rule from eps. */
static int weights(N_Vector yv, N_Vector ewt, void *user)
{
    const struct model *p = user;
    const double *y = N_VGetArrayPointer(yv);
    double *w = N_VGetArrayPointer(ewt);
    for (int i = 0; i < DIM; i++)
        w[i] = 1.0 / (p->atol[i] + p->rel[i] * p->rtol * fabs(y[i]));
    return 0;
}

static int quiet(void *mem)
{
#if SUNDIALS_VERSION_MAJOR >= 7
    (void)mem;
    return CV_SUCCESS;
#else
    return CVodeSetErrHandlerFn(mem, quiet_warnings, NULL);
#endif
}

/* The rule's absolute tolerances for this state, from a fricreg_sim of the same system. */
static int rule_tolerances(struct model *p)
{
    fricreg_sim *sim = NULL;
    int status = fricreg_sim_create(FRICREG_SYSTEM_TWOBLOCK, &sim);
    if (status == FRICREG_OK)
        status = fricreg_sim_set_law(sim, FRICREG_LAW_QUINN, EPS);
    if (status == FRICREG_OK)
        status = fricreg_sim_set_integrator(sim, FRICREG_INT_MSBDF, 0.01, p->rtol,
                                            FRICREG_ATOL_FROM_EPS);
    if (status == FRICREG_OK)
        status = fricreg_sim_get_abs_tolerances(sim, DIM, p->atol);
    fricreg_sim_free(sim);
    for (int i = 0; i < DIM; i++) /* the rule holds velocities absolutely */
        p->rel[i] = i == 2 || i == 3 ? 0.0 : 1.0;
    return status;
}

static int make_context(struct model *p)
{
    const double W[M * M] = {1.0, -1.0, -1.0, 2.0}, mun[M] = {0.5, 0.25};
    int status = fricreg_ctx_create(M, &p->ctx);
    if (status == FRICREG_OK)
        status = fricreg_ctx_set_law(p->ctx, FRICREG_LAW_QUINN, EPS);
    if (status == FRICREG_OK)
        status = fricreg_ctx_set_coupling_dense(p->ctx, M, W);
    if (status == FRICREG_OK)
        status = fricreg_ctx_set_bounds(p->ctx, M, mun);
    return status;
}

/* Four belt cycles, each ended exactly on its boundary (CVodeSetStopTime), restarting at each
 * kink; D per cycle into D[4]. 0, or -1 when CVODE failed. */
static int integrate(struct model *p, void *mem, N_Vector y, double D[4], long *restarts)
{
    double T = 2.0 * acos(-1.0) / p->belt_omega, t = 0.0, D_start = 0.0;
    for (int c = 1; c <= 4; c++) {
        if (CVodeSetStopTime(mem, c * T) != CV_SUCCESS)
            return -1;
        for (;;) {
            int flag = CVode(mem, c * T, y, &t, CV_NORMAL);
            if (flag == CV_ROOT_RETURN) { /* a kink: start afresh on the new piece */
                if (CVodeReInit(mem, t, y) != CV_SUCCESS ||
                    CVodeSetStopTime(mem, c * T) != CV_SUCCESS)
                    return -1;
                (*restarts)++;
                continue;
            }
            if (flag < 0)
                return -1;
            if (flag == CV_TSTOP_RETURN || t >= c * T)
                break;
        }
        D[c - 1] = N_VGetArrayPointer(y)[4] - D_start;
        D_start = N_VGetArrayPointer(y)[4];
    }
    return 0;
}

int main(int argc, char **argv)
{
    struct model p = {.k = 2.0, .belt_amp = 1.0, .belt_omega = 0.5};
    p.rtol = argc > 1 ? strtod(argv[1], NULL) : 1e-6;
    SUNContext sun = NULL;
    void *mem = NULL;
    N_Vector y = NULL;
    SUNMatrix A = NULL;
    SUNLinearSolver LS = NULL;
    double D[4] = {0};
    long restarts = 0;
    int ok = make_context(&p) == FRICREG_OK && rule_tolerances(&p) == FRICREG_OK &&
             SUNContext_Create(COMM_NULL, &sun) == 0;
    if (ok) {
        y = N_VNew_Serial(DIM, sun);
        mem = CVodeCreate(CV_BDF, sun);
        A = SUNDenseMatrix(DIM, DIM, sun);
        ok = y && mem && A;
    }
    if (ok) {
        N_VConst(0.0, y); /* at rest at the origin */
        LS = SUNLinSol_Dense(y, A, sun);
        ok = LS && CVodeInit(mem, rhs, 0.0, y) == CV_SUCCESS &&
             CVodeSetUserData(mem, &p) == CV_SUCCESS && quiet(mem) == CV_SUCCESS &&
             CVodeSetMaxNumSteps(mem, 1000000L) == CV_SUCCESS &&
             CVodeWFtolerances(mem, weights) == CV_SUCCESS &&
             CVodeSetLinearSolver(mem, LS, A) == CV_SUCCESS &&
             CVodeSetJacFn(mem, jacobian) == CV_SUCCESS &&
             CVodeRootInit(mem, (int)fricreg_ctx_switching_count(p.ctx), roots) == CV_SUCCESS;
    }
    int result = 2;
    if (ok && integrate(&p, mem, y, D, &restarts) == 0) {
        double error = fabs(D[3] - D_REFERENCE) / D_REFERENCE;
        printf("D per cycle: %.10f %.10f %.10f %.10f\n", D[0], D[1], D[2], D[3]);
        printf("rtol %g: D on cycle 4 off by %.2e (relative), %ld restarts at kinks\n", p.rtol,
               error, restarts);
        result = error < 1e-4 ? 0 : 1;
    } else {
        fprintf(stderr, "cvode_twoblock: set-up or integration failed%s%s\n", p.ctx ? ": " : "",
                p.ctx ? fricreg_ctx_errmsg(p.ctx) : "");
    }
    SUNLinSolFree(LS);
    SUNMatDestroy(A);
    if (y != NULL)
        N_VDestroy(y);
    CVodeFree(&mem);
    SUNContext_Free(&sun);
    fricreg_ctx_free(p.ctx);
    return result;
}
