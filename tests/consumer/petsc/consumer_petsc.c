/* SPDX-License-Identifier: GPL-3.0-or-later */
/* consumer_petsc.c — a user's PETSc program against the installed libfricreg_petsc
 * (tests/install_petsc.sh): one block of mass 2 sliding against the ground at v = 1 under
 * law (4), eps = 1e-3, mun = 0.5. Outside the band the law is Coulomb's: the right-hand side's
 * acceleration is -mun/m = -0.25 (paper Eq. (4), |v| >= eps), and the power -mun v = -0.5.
 * Prints "ok" and exits 0, or names what differs and exits 1. */
#include <math.h>
#include <stdio.h>

#include <petscvec.h>

#include "fricreg_petsc.h"

int main(int argc, char **argv)
{
    Vec mass, X, G;
    fricreg_petsc *fp = NULL;
    const PetscInt node[1] = {1}; /* the contact's entry: the velocity v of the state (u, v) */
    const double mun[1] = {0.5};
    double power = 0.0;
    const PetscScalar *g;
    int ok;
    if (PetscInitialize(&argc, &argv, NULL, NULL))
        return 1;
    VecCreateSeq(PETSC_COMM_SELF, 2, &mass); /* the layout of the state (u, v) */
    VecSet(mass, 2.0);
    VecDuplicate(mass, &X);
    VecSetValue(X, 0, 0.0, INSERT_VALUES);
    VecSetValue(X, 1, 1.0, INSERT_VALUES);
    VecAssemblyBegin(X);
    VecAssemblyEnd(X);
    VecDuplicate(X, &G);
    VecSet(G, 0.0);
    ok = fricreg_petsc_create(mass, 1, node, NULL, &fp) == FRICREG_OK &&
         fricreg_petsc_set_law(fp, FRICREG_LAW_QUINN, 1e-3) == FRICREG_OK &&
         fricreg_petsc_set_bounds(fp, 1, mun) == FRICREG_OK &&
         fricreg_petsc_rhs_add(fp, X, G, &power) == FRICREG_OK;
    if (ok) {
        VecGetArrayRead(G, &g);
        ok = fabs(g[1] + 0.25) < 1e-15 && fabs(power + 0.5) < 1e-15;
        VecRestoreArrayRead(G, &g);
    }
    printf("%s: one sliding block through the installed adapter\n", ok ? "ok" : "FAIL");
    fricreg_petsc_free(fp);
    VecDestroy(&G);
    VecDestroy(&X);
    VecDestroy(&mass);
    PetscFinalize();
    return ok ? 0 : 1;
}
