/* SPDX-License-Identifier: GPL-3.0-or-later */
/* events.c — the adapter's PETSc log events, so that -log_view shows friction's share of a run
 * beside PETSc's own stages: FricregRhsAdd, FricregResidAdd and FricregJacAdd, one per entry
 * point that evaluates the contacts. They are registered by the first fricreg_petsc_create after
 * PetscInitialize (looked up by name first, so a second object, or a second initialization of
 * PETSc, finds them rather than adding copies), as PETSc's own packages register theirs. */
#include "petsc_internal.h"

struct fr_petsc_events fr_petsc_events = {-1, -1, -1};

/* The event called name: the one registered before, else a new one. */
static PetscErrorCode find_or_register(const char *name, PetscLogEvent *event)
{
    PetscErrorCode ierr = PetscLogEventGetId(name, event);
    if (!ierr && *event < 0)
        ierr = PetscLogEventRegister(name, PETSC_OBJECT_CLASSID, event);
    return ierr;
}

PetscErrorCode fr_petsc_events_register(void)
{
    PetscErrorCode ierr = find_or_register("FricregRhsAdd", &fr_petsc_events.rhs_add);
    if (!ierr)
        ierr = find_or_register("FricregResidAdd", &fr_petsc_events.residual_add);
    if (!ierr)
        ierr = find_or_register("FricregJacAdd", &fr_petsc_events.jacobian_add);
    return ierr;
}
