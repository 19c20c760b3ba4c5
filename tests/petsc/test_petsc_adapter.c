/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_petsc_adapter.c — libfricreg_petsc on 1 or more ranks (mpiexec -n 1, -n 2):
 *  - jacobian_add is the exact derivative of residual_add: against central differences of the
 *    whole residual R = M A - F_free - J^T f of a spring chain with a lumped mass, TSALPHA2's
 *    shifts, contacts sliding, in law (4)'s zone and against the ground and between two nodes;
 *  - contacts sharing degrees of freedom (on one rank): the forces are a fricreg context's on
 *    the coupled W = J M^-1 J^T (and differ from its diagonal's), the Jacobian still exact;
 *  - a contact on another rank's degree of freedom is refused on every rank with
 *    FRICREG_PETSC_EREMOTE (2 ranks), a contact joining a degree of freedom to itself with
 *    FRICREG_EINVAL;
 *  - set_from_options: -<prefix>fricreg_law, _eps, _mun give the forces of fricreg_law_eval
 *    with those settings; a bad value is refused with its status and changes nothing;
 *  - rhs_add and jacobian_add are counted by their log events (PetscLogDefaultBegin).
 * Prints "ok" lines and exits 0, or names the failure and exits 1. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <petscdmda.h>

#include "fricreg_petsc.h"

#define N 12
#define SPRING 2.385
#define DAMPING 0.137
#define EPS 0.1
#define SHIFT_V 31.7 /* TSALPHA2-like shifts: v_shift ~ 1/(gamma dt)... any finite values */
#define SHIFT_A 913.0

static int fails = 0;

static void check(int ok, const char *what)
{
    int rank;
    MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
    if (!ok)
        fails++;
    if (rank == 0 || !ok)
        printf("%s: %s\n", ok ? "ok" : "FAIL", what);
}

struct model {
    DM da;
    Vec mass, U0, V0, A0;
    fricreg_petsc *fp;
};

/* F_free = p - K U - C V at the owned entries: K the chain of springs (walls at both ends),
 * C = DAMPING M, p a fixed load. */
static void free_force(struct model *md, Vec U, Vec V, Vec F)
{
    Vec Ul;
    PetscScalar *ul, *f;
    const PetscScalar *v, *mv;
    PetscInt xs, xm;
    DMGetLocalVector(md->da, &Ul);
    DMGlobalToLocal(md->da, U, INSERT_VALUES, Ul);
    DMDAGetCorners(md->da, &xs, NULL, NULL, &xm, NULL, NULL);
    DMDAVecGetArray(md->da, Ul, &ul);
    DMDAVecGetArray(md->da, F, &f);
    DMDAVecGetArrayRead(md->da, V, &v);
    DMDAVecGetArrayRead(md->da, md->mass, &mv);
    for (PetscInt i = xs; i < xs + xm; i++) {
        double left = i > 0 ? ul[i - 1] : 0.0, right = i < N - 1 ? ul[i + 1] : 0.0;
        f[i] = 0.7 * sin(1.3 * i) - SPRING * (2.0 * ul[i] - left - right) - DAMPING * mv[i] * v[i];
    }
    DMDAVecRestoreArrayRead(md->da, md->mass, &mv);
    DMDAVecRestoreArrayRead(md->da, V, &v);
    DMDAVecRestoreArray(md->da, F, &f);
    DMDAVecRestoreArray(md->da, Ul, &ul);
    DMRestoreLocalVector(md->da, &Ul);
}

/* R(U) with V = V0 + SHIFT_V (U - U0), A = A0 + SHIFT_A (U - U0). */
static int residual(struct model *md, Vec U, Vec R)
{
    Vec V, A, F, dU;
    VecDuplicate(U, &V), VecDuplicate(U, &A), VecDuplicate(U, &F), VecDuplicate(U, &dU);
    VecWAXPY(dU, -1.0, md->U0, U);
    VecWAXPY(V, SHIFT_V, dU, md->V0);
    VecWAXPY(A, SHIFT_A, dU, md->A0);
    free_force(md, U, V, F);
    VecPointwiseMult(R, md->mass, A);
    VecAXPY(R, -1.0, F);
    int status = fricreg_petsc_residual_add(md->fp, V, F, R, NULL);
    VecDestroy(&V), VecDestroy(&A), VecDestroy(&F), VecDestroy(&dU);
    return status;
}

/* The caller's Jacobian without friction, SHIFT_A M + SHIFT_V C + K, then the adapter's. */
static int jacobian(struct model *md, Mat P)
{
    PetscInt xs, xm;
    const PetscScalar *mv;
    DMDAGetCorners(md->da, &xs, NULL, NULL, &xm, NULL, NULL);
    DMDAVecGetArrayRead(md->da, md->mass, &mv);
    MatZeroEntries(P);
    for (PetscInt i = xs; i < xs + xm; i++) {
        MatSetValue(P, i, i, SHIFT_A * mv[i] + SHIFT_V * DAMPING * mv[i] + 2.0 * SPRING,
                    INSERT_VALUES);
        if (i > 0)
            MatSetValue(P, i, i - 1, -SPRING, INSERT_VALUES);
        if (i < N - 1)
            MatSetValue(P, i, i + 1, -SPRING, INSERT_VALUES);
    }
    DMDAVecRestoreArrayRead(md->da, md->mass, &mv);
    MatAssemblyBegin(P, MAT_FINAL_ASSEMBLY);
    MatAssemblyEnd(P, MAT_FINAL_ASSEMBLY);
    Vec V, F;
    VecDuplicate(md->U0, &V), VecDuplicate(md->U0, &F);
    VecCopy(md->V0, V);
    free_force(md, md->U0, V, F);
    int status = fricreg_petsc_jacobian_add(md->fp, V, F, SHIFT_A, SHIFT_V, P);
    VecDestroy(&V), VecDestroy(&F);
    return status;
}

/* Contacts of this rank: to the ground at every owned node but the pairs, and one pair of
 * neighbours (two owned nodes) per rank with at least 4 nodes. Velocities V0 put them in
 * slip (|zdot| > eps), in law (4)'s zone, and at rest. */
static void contacts(struct model *md, PetscInt node[], PetscInt other[], size_t *m)
{
    PetscInt xs, xm;
    DMDAGetCorners(md->da, &xs, NULL, NULL, &xm, NULL, NULL);
    *m = 0;
    for (PetscInt i = xs; i < xs + xm; i++) {
        int pair = xm >= 4 && i == xs + 1;
        node[*m] = i;
        other[(*m)++] = pair ? i + 1 : -1;
        if (pair)
            i++;
    }
}

static void fill_state(struct model *md)
{
    PetscInt xs, xm;
    PetscScalar *u, *v, *a, *mv;
    DMDAGetCorners(md->da, &xs, NULL, NULL, &xm, NULL, NULL);
    DMDAVecGetArray(md->da, md->U0, &u), DMDAVecGetArray(md->da, md->V0, &v);
    DMDAVecGetArray(md->da, md->A0, &a), DMDAVecGetArray(md->da, md->mass, &mv);
    static const double vel[5] = {0.31, -0.023, 0.0123, 0.061, -0.47};
    for (PetscInt i = xs; i < xs + xm; i++) {
        mv[i] = 1.0 + 0.1 * i;
        u[i] = 0.05 * cos(0.9 * i);
        v[i] = vel[i % 5];
        a[i] = 0.2 * sin(0.4 * i);
    }
    DMDAVecRestoreArray(md->da, md->U0, &u), DMDAVecRestoreArray(md->da, md->V0, &v);
    DMDAVecRestoreArray(md->da, md->A0, &a), DMDAVecRestoreArray(md->da, md->mass, &mv);
}

/* max |P - dR/dU| over max |P|, dR/dU by central differences column by column. */
static double jacobian_error(struct model *md, Mat P)
{
    Vec U, Rp, Rm;
    VecDuplicate(md->U0, &U), VecDuplicate(md->U0, &Rp), VecDuplicate(md->U0, &Rm);
    PetscInt rs, re;
    VecGetOwnershipRange(U, &rs, &re);
    double err = 0.0, scale = 0.0, h = 1e-7;
    for (PetscInt j = 0; j < N; j++) {
        VecCopy(md->U0, U);
        if (j >= rs && j < re) /* the owner alone: each rank's ADD would add */
            VecSetValue(U, j, h, ADD_VALUES);
        VecAssemblyBegin(U), VecAssemblyEnd(U);
        residual(md, U, Rp);
        VecCopy(md->U0, U);
        if (j >= rs && j < re)
            VecSetValue(U, j, -h, ADD_VALUES);
        VecAssemblyBegin(U), VecAssemblyEnd(U);
        residual(md, U, Rm);
        const PetscScalar *rp, *rm;
        VecGetArrayRead(Rp, &rp), VecGetArrayRead(Rm, &rm);
        for (PetscInt i = rs; i < re; i++) {
            PetscScalar pij;
            MatGetValues(P, 1, &i, 1, &j, &pij);
            double fd = (rp[i - rs] - rm[i - rs]) / (2.0 * h);
            err = fmax(err, fabs(pij - fd));
            scale = fmax(scale, fabs(pij));
        }
        VecRestoreArrayRead(Rp, &rp), VecRestoreArrayRead(Rm, &rm);
    }
    VecDestroy(&U), VecDestroy(&Rp), VecDestroy(&Rm);
    double local[2] = {err, scale}, all[2];
    MPI_Allreduce(local, all, 2, MPI_DOUBLE, MPI_MAX, PETSC_COMM_WORLD);
    return all[0] / all[1];
}

static void test_jacobian(void)
{
    struct model md = {0};
    DMDACreate1d(PETSC_COMM_WORLD, DM_BOUNDARY_NONE, N, 1, 2, NULL, &md.da);
    DMSetUp(md.da);
    DMCreateGlobalVector(md.da, &md.mass);
    VecDuplicate(md.mass, &md.U0), VecDuplicate(md.mass, &md.V0), VecDuplicate(md.mass, &md.A0);
    fill_state(&md);
    PetscInt node[N], other[N];
    size_t m;
    contacts(&md, node, other, &m);
    int status = fricreg_petsc_create(md.mass, m, node, other, &md.fp);
    check(status == FRICREG_OK, "create: contacts to the ground and between two owned nodes");
    double mun[N];
    for (size_t k = 0; k < m; k++)
        mun[k] = 0.4 + 0.05 * (double)k;
    fricreg_petsc_set_law(md.fp, FRICREG_LAW_QUINN, EPS);
    fricreg_petsc_set_bounds(md.fp, m, mun);
    Mat P;
    DMCreateMatrix(md.da, &P);
    status = jacobian(&md, P);
    check(status == FRICREG_OK, "jacobian_add");
    double err = jacobian_error(&md, P);
    char what[160];
    snprintf(what, sizeof what, "jacobian_add against central differences: %.2e (< 1e-6)", err);
    check(err < 1e-6, what);
    MatDestroy(&P);
    fricreg_petsc_free(md.fp);
    VecDestroy(&md.mass), VecDestroy(&md.U0), VecDestroy(&md.V0), VecDestroy(&md.A0);
    DMDestroy(&md.da);
}

/* Coupled contacts on each rank: a chain (x_s, ground), (x_s, x_s + 1), (x_s + 1, x_s + 2)
 * sharing x_s and x_s + 1 (three contacts on three nodes: W is definite), the nodes after it
 * each to the ground; velocities that put every contact in law (4)'s zone, where the
 * near-stick solve couples them through W. */
static void coupled_contacts(struct model *md, PetscInt node[], PetscInt other[], size_t *m)
{
    PetscInt xs, xm;
    DMDAGetCorners(md->da, &xs, NULL, NULL, &xm, NULL, NULL);
    *m = 0;
    for (PetscInt i = xs; i < xs + xm; i++) {
        int chain = xm >= 3 && i < xs + 2;
        if (xm < 3 || i == xs || i > xs + 2) {
            node[*m] = i;
            other[(*m)++] = -1;
        }
        if (chain) {
            node[*m] = i;
            other[(*m)++] = i + 1;
        }
    }
    PetscScalar *v;
    DMDAVecGetArray(md->da, md->V0, &v);
    for (PetscInt i = xs; i < xs + xm; i++)
        v[i] = 0.02 + 0.03 * sin(2.1 * (double)i);
    DMDAVecRestoreArray(md->da, md->V0, &v);
}

/* The forces of a context on W (m x m, row-major) at the adapter's zdot and a_free, as the
 * test computes them (V0, F_free at U0), with the adapter's law and bounds. */
static void context_forces(struct model *md, const PetscInt node[], const PetscInt other[],
                           size_t m, const double *W, const double *mun, double *f)
{
    Vec F;
    VecDuplicate(md->U0, &F);
    free_force(md, md->U0, md->V0, F);
    const PetscScalar *v, *Fa, *mv;
    PetscInt rs;
    VecGetOwnershipRange(F, &rs, NULL);
    VecGetArrayRead(md->V0, &v), VecGetArrayRead(F, &Fa), VecGetArrayRead(md->mass, &mv);
    double zdot[N], afree[N];
    for (size_t k = 0; k < m; k++) {
        PetscInt a = node[k] - rs, b = other[k] - rs;
        zdot[k] = other[k] >= 0 ? v[a] - v[b] : v[a];
        afree[k] = other[k] >= 0 ? Fa[a] / mv[a] - Fa[b] / mv[b] : Fa[a] / mv[a];
    }
    VecRestoreArrayRead(md->V0, &v), VecRestoreArrayRead(F, &Fa);
    VecRestoreArrayRead(md->mass, &mv);
    fricreg_ctx *ctx = NULL;
    int ok = fricreg_ctx_create(m, &ctx) == FRICREG_OK &&
             fricreg_ctx_set_coupling_dense(ctx, m, W) == FRICREG_OK &&
             fricreg_ctx_set_law(ctx, FRICREG_LAW_QUINN, EPS) == FRICREG_OK &&
             fricreg_ctx_set_bounds(ctx, m, mun) == FRICREG_OK &&
             fricreg_ctx_eval(ctx, m, zdot, afree, f, NULL) == FRICREG_OK;
    if (!ok)
        printf("%s\n", fricreg_ctx_errmsg(ctx));
    check(ok, "the reference context");
    fricreg_ctx_free(ctx);
    VecDestroy(&F);
}

/* W = J M^-1 J^T of the contacts, dense; with diagonal_only its diagonal alone. */
static void delassus(struct model *md, const PetscInt node[], const PetscInt other[], size_t m,
                     int diagonal_only, double *W)
{
    const PetscScalar *mv;
    PetscInt rs;
    VecGetOwnershipRange(md->mass, &rs, NULL);
    VecGetArrayRead(md->mass, &mv);
    for (size_t k = 0; k < m; k++)
        for (size_t l = 0; l < m; l++) {
            PetscInt dk[2] = {node[k], other[k]}, dl[2] = {node[l], other[l]};
            double w = 0.0;
            for (int i = 0; i < 2; i++)
                for (int j = 0; j < 2; j++)
                    if (dk[i] >= 0 && dk[i] == dl[j])
                        w += (i == 0 ? 1.0 : -1.0) * (j == 0 ? 1.0 : -1.0) / mv[dk[i] - rs];
            W[k * m + l] = diagonal_only && k != l ? 0.0 : w;
        }
    VecRestoreArrayRead(md->mass, &mv);
}

/* Contacts sharing degrees of freedom: residual_add's forces are a context's on W = J M^-1 J^T
 * with its off-diagonal entries (and differ from W's diagonal alone: the coupling matters),
 * and jacobian_add is still the exact derivative (the tangent's off-diagonal blocks: the
 * stencil is widened to 3 so that P's pattern covers a group's rows). */
static void test_coupled(void)
{
    struct model md = {0};
    DMDACreate1d(PETSC_COMM_WORLD, DM_BOUNDARY_NONE, N, 1, 3, NULL, &md.da);
    DMSetUp(md.da);
    DMCreateGlobalVector(md.da, &md.mass);
    VecDuplicate(md.mass, &md.U0), VecDuplicate(md.mass, &md.V0), VecDuplicate(md.mass, &md.A0);
    fill_state(&md);
    PetscInt node[2 * N], other[2 * N];
    size_t m;
    coupled_contacts(&md, node, other, &m);
    check(fricreg_petsc_create(md.mass, m, node, other, &md.fp) == FRICREG_OK,
          "create: contacts sharing degrees of freedom");
    double mun[2 * N], f[2 * N], fc[2 * N], fd[2 * N], W[4 * N * N];
    for (size_t k = 0; k < m; k++)
        mun[k] = 3.0 + 0.05 * (double)k; /* f_eq inside the bounds: coupled */
    fricreg_petsc_set_law(md.fp, FRICREG_LAW_QUINN, EPS);
    fricreg_petsc_set_bounds(md.fp, m, mun);
    Vec R;
    VecDuplicate(md.U0, &R);
    int status = residual(&md, md.U0, R);
    check(status == FRICREG_OK && fricreg_petsc_get_forces(md.fp, m, f) == FRICREG_OK,
          "residual_add with coupled contacts");
    delassus(&md, node, other, m, 0, W);
    context_forces(&md, node, other, m, W, mun, fc);
    delassus(&md, node, other, m, 1, W);
    context_forces(&md, node, other, m, W, mun, fd);
    double dev = 0.0, coupling = 0.0, scale = 0.0;
    for (size_t k = 0; k < m; k++) {
        dev = fmax(dev, fabs(f[k] - fc[k]));
        coupling = fmax(coupling, fabs(fc[k] - fd[k]));
        scale = fmax(scale, fabs(fc[k]));
    }
    char what[200];
    snprintf(what, sizeof what,
             "the forces are a context's on the coupled W: %.2e of %.3g (< 1e-12); W's diagonal "
             "alone gives %.2e (> 1e-3)",
             dev, scale, coupling);
    check(dev <= 1e-12 * scale && coupling > 1e-3 * scale, what);
    Mat P;
    DMCreateMatrix(md.da, &P);
    status = jacobian(&md, P);
    check(status == FRICREG_OK, "jacobian_add with coupled contacts");
    double err = jacobian_error(&md, P);
    snprintf(what, sizeof what,
             "jacobian_add with coupled contacts against central differences: %.2e (< 1e-6)", err);
    check(err < 1e-6, what);
    MatDestroy(&P);
    VecDestroy(&R);
    fricreg_petsc_free(md.fp);
    VecDestroy(&md.mass), VecDestroy(&md.U0), VecDestroy(&md.V0), VecDestroy(&md.A0);
    DMDestroy(&md.da);
}

/* Rank 1 names rank 0's first node: both ranks get FRICREG_PETSC_EREMOTE; a contact joining a
 * degree of freedom to itself: FRICREG_EINVAL. */
static void test_refusals(void)
{
    int rank, size;
    MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
    MPI_Comm_size(PETSC_COMM_WORLD, &size);
    Vec mass;
    VecCreateMPI(PETSC_COMM_WORLD, 4, PETSC_DETERMINE, &mass);
    VecSet(mass, 2.0);
    PetscInt rs, re;
    VecGetOwnershipRange(mass, &rs, &re);
    fricreg_petsc *fp = NULL;
    if (size > 1) {
        PetscInt node[1] = {rank == 1 ? 0 : rs};
        int status = fricreg_petsc_create(mass, 1, node, NULL, &fp);
        check(status == FRICREG_PETSC_EREMOTE && fp == NULL,
              "a contact on another rank's node: FRICREG_PETSC_EREMOTE on every rank");
    }
    PetscInt self[1] = {rs + 1}, pair[1] = {rs + 1};
    int status = fricreg_petsc_create(mass, 1, self, pair, &fp);
    check(status == FRICREG_EINVAL && fp == NULL, "a node joined to itself: FRICREG_EINVAL");
    PetscInt beyond[1] = {re + 100 * (PetscInt)size};
    status = fricreg_petsc_create(mass, 1, beyond, NULL, &fp);
    check(status == FRICREG_PETSC_EREMOTE, "an index beyond the Vec: FRICREG_PETSC_EREMOTE");
    check(strstr(fricreg_petsc_strerror(FRICREG_PETSC_EREMOTE), "across ranks") != NULL,
          "strerror names the restriction");
    VecDestroy(&mass);
}

/* The forces of one contact per owned node against the ground (mass 2, velocity 0.3 + 0.1 k,
 * free acceleration 0) after set_from_options with opts and prefix: its status, and f[0..m). */
static int forces_after_options(fricreg_petsc *fp, Vec X, Vec G, PetscOptions opts,
                                const char *prefix, size_t m, double f[])
{
    int status = fricreg_petsc_set_from_options(fp, opts, prefix);
    VecSet(G, 0.0);
    if (fricreg_petsc_rhs_add(fp, X, G, NULL) != FRICREG_OK ||
        fricreg_petsc_get_forces(fp, m, f) != FRICREG_OK)
        check(0, "rhs_add after set_from_options");
    return status;
}

static void test_options(void)
{
    Vec mass, X, G;
    VecCreateMPI(PETSC_COMM_WORLD, 4, PETSC_DETERMINE, &mass);
    VecSet(mass, 2.0);
    VecDuplicate(mass, &X), VecDuplicate(mass, &G);
    PetscInt rs, re, node[4];
    VecGetOwnershipRange(mass, &rs, &re);
    for (PetscInt k = 0; k < 4; k++) {
        node[k] = rs + k;
        VecSetValue(X, rs + k, 0.3 + 0.1 * (double)k - 0.35, INSERT_VALUES);
    }
    VecAssemblyBegin(X), VecAssemblyEnd(X);
    fricreg_petsc *fp = NULL;
    check(fricreg_petsc_create(mass, 4, node, NULL, &fp) == FRICREG_OK, "create for the options");
    PetscOptions opts;
    PetscOptionsCreate(&opts);
    PetscOptionsSetValue(opts, "-beam_fricreg_law", "tanh");
    PetscOptionsSetValue(opts, "-beam_fricreg_eps", "0.05");
    PetscOptionsSetValue(opts, "-beam_fricreg_mun", "0.7");
    double f[4], want[4], before[4];
    int status = forces_after_options(fp, X, G, opts, "beam_", 4, f);
    check(status == FRICREG_OK, "set_from_options: -beam_fricreg_law tanh, _eps 0.05, _mun 0.7");
    int same = 1;
    for (int k = 0; k < 4; k++) {
        fricreg_law_eval(FRICREG_LAW_TANH, 0.3 + 0.1 * k - 0.35, 0.0, 0.7, 0.05, &want[k]);
        same &= fabs(f[k] - want[k]) <= 1e-15 * 0.7;
    }
    check(same, "the forces are fricreg_law_eval's with the options' law, eps and bound");
    PetscBool used = PETSC_FALSE;
    PetscOptionsUsed(opts, "beam_fricreg_mun", &used); /* names stored without the - */
    check(used == PETSC_TRUE, "the options read are marked used (-options_left)");
    /* -fricreg_eps alone keeps the law; without the prefix nothing is read */
    PetscOptionsSetValue(opts, "-beam_fricreg_eps", "0.2");
    PetscOptionsClearValue(opts, "-beam_fricreg_law");
    forces_after_options(fp, X, G, opts, "beam_", 4, f);
    fricreg_law_eval(FRICREG_LAW_TANH, -0.05, 0.0, 0.7, 0.2, &want[0]);
    check(fabs(f[0] - want[0]) <= 1e-15 * 0.7, "-fricreg_eps alone keeps the law (tanh)");
    memcpy(before, f, sizeof f);
    forces_after_options(fp, X, G, opts, NULL, 4, f);
    check(memcmp(before, f, sizeof f) == 0,
          "without the prefix, the prefixed options are not read");
    /* refusals: the status, and the forces as before */
    const char *bad[6][2] = {{"-beam_fricreg_law", "sliding"}, {"-beam_fricreg_eps", "-1"},
                             {"-beam_fricreg_mun", "-0.5"},    {"-beam_fricreg_eps", "abc"},
                             {"-beam_fricreg_eps", "inf"},     {"-beam_fricreg_mun", "nan"}};
    const int codes[6] = {FRICREG_EINVAL,       FRICREG_EINVAL,     FRICREG_EINVAL,
                          FRICREG_PETSC_EPETSC, FRICREG_ENONFINITE, FRICREG_ENONFINITE};
    for (int b = 0; b < 6; b++) {
        PetscOptions one;
        PetscOptionsCreate(&one);
        PetscOptionsSetValue(one, "-beam_fricreg_mun", "5"); /* valid, must not be applied */
        PetscOptionsSetValue(one, bad[b][0], bad[b][1]);
        status = forces_after_options(fp, X, G, one, "beam_", 4, f);
        char what[160];
        snprintf(what, sizeof what, "%s %s: status %d (want %d), forces unchanged", bad[b][0],
                 bad[b][1], status, codes[b]);
        check(status == codes[b] && memcmp(before, f, sizeof f) == 0, what);
        PetscOptionsDestroy(&one);
    }
    check(fricreg_petsc_set_from_options(NULL, opts, NULL) == FRICREG_ENULL, "NULL: ENULL");
    PetscOptionsDestroy(&opts);
    fricreg_petsc_free(fp);
    VecDestroy(&mass), VecDestroy(&X), VecDestroy(&G);
}

/* The log events count the calls: FricregRhsAdd at least test_options' 9 rhs_add calls,
 * FricregJacAdd test_jacobian's one at least. */
static void test_log_events(void)
{
    const char *names[2] = {"FricregRhsAdd", "FricregJacAdd"};
    const int least[2] = {9, 1};
    for (int e = 0; e < 2; e++) {
        PetscLogEvent ev = -1;
        PetscEventPerfInfo info;
        memset(&info, 0, sizeof info);
        PetscLogEventGetId(names[e], &ev);
        if (ev >= 0)
            PetscLogEventGetPerfInfo(PETSC_DETERMINE, ev, &info);
        char what[120];
        snprintf(what, sizeof what, "log event %s: %d calls (>= %d)", names[e], info.count,
                 least[e]);
        check(ev >= 0 && info.count >= least[e], what);
    }
}

int main(int argc, char **argv)
{
    if (PetscInitialize(&argc, &argv, NULL, NULL))
        return 1;
    PetscLogDefaultBegin();
    test_jacobian();
    test_coupled();
    test_refusals();
    test_options();
    test_log_events();
    int all;
    MPI_Allreduce(&fails, &all, 1, MPI_INT, MPI_SUM, PETSC_COMM_WORLD);
    PetscFinalize();
    return all == 0 ? 0 : 1;
}
