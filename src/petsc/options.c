/* SPDX-License-Identifier: GPL-3.0-or-later */
/* options.c — the adapter's settings from the PETSc options database (-fricreg_law,
 * -fricreg_eps, -fricreg_mun), read with PetscOptionsGetString/Real as a PETSc object's
 * SetFromOptions reads its own, all checked before any is applied. */
#include <float.h>
#include <math.h>

#include "petsc_internal.h"

/* What the database gives: each value and whether it was given. */
struct given {
    char law_name[64];
    PetscReal eps, mun;
    PetscBool has_law, has_eps, has_mun;
};

static PetscErrorCode read_options(PetscOptions options, const char *prefix, struct given *g)
{
    PetscErrorCode ierr = PetscOptionsGetString(options, prefix, "-fricreg_law", g->law_name,
                                                sizeof g->law_name, &g->has_law);
    if (!ierr)
        ierr = PetscOptionsGetReal(options, prefix, "-fricreg_eps", &g->eps, &g->has_eps);
    if (!ierr)
        ierr = PetscOptionsGetReal(options, prefix, "-fricreg_mun", &g->mun, &g->has_mun);
    return ierr;
}

/* The values' own checks (those of fricreg_petsc_set_law and _set_bounds), naming the option. */
static int check_given(fricreg_petsc *fp, const char *prefix, const struct given *g, int *law)
{
    const char *p = prefix != NULL ? prefix : "";
    *law = g->has_law ? fricreg_law_from_name(g->law_name) : fp->law;
    if (*law == 0)
        return fr_fail(fp, FRICREG_EINVAL,
                       "set_from_options: -%sfricreg_law %s names no law (coulomb, "
                       "force-balance, karnopp, velocity-limited, tanh, quinn)",
                       p, g->law_name);
    if (g->has_eps && !isfinite(g->eps))
        return fr_fail(fp, FRICREG_ENONFINITE, "set_from_options: -%sfricreg_eps %g", p, g->eps);
    if (g->has_eps && !(g->eps >= DBL_MIN))
        return fr_fail(fp, FRICREG_EINVAL, "set_from_options: -%sfricreg_eps %g is not > 0", p,
                       g->eps);
    if (g->has_mun && !isfinite(g->mun))
        return fr_fail(fp, FRICREG_ENONFINITE, "set_from_options: -%sfricreg_mun %g", p, g->mun);
    if (g->has_mun && !(g->mun >= 0.0))
        return fr_fail(fp, FRICREG_EINVAL, "set_from_options: -%sfricreg_mun %g is negative", p,
                       g->mun);
    return FRICREG_OK;
}

static int apply(fricreg_petsc *fp, const struct given *g, int law)
{
    int status = FRICREG_OK;
    if (g->has_law || g->has_eps)
        status = fricreg_petsc_set_law(fp, law, g->has_eps ? g->eps : fp->eps);
    if (status == FRICREG_OK && g->has_mun && fp->m > 0) {
        for (size_t k = 0; k < fp->m; k++)
            fp->f[k] = g->mun; /* f is scratch until the next evaluation */
        status = fricreg_petsc_set_bounds(fp, fp->m, fp->f);
    }
    return status;
}

int fricreg_petsc_set_from_options(fricreg_petsc *fp, PetscOptions options, const char *prefix)
{
    if (fp == NULL)
        return FRICREG_ENULL;
    struct given g = {.has_law = PETSC_FALSE};
    PetscPushErrorHandler(PetscReturnErrorHandler, NULL);
    PetscErrorCode ierr = read_options(options, prefix, &g);
    PetscPopErrorHandler();
    if (ierr)
        return fr_petsc_fail(fp, ierr, "set_from_options: reading the options");
    int law = 0, status = check_given(fp, prefix, &g, &law);
    return status == FRICREG_OK ? apply(fp, &g, law) : status;
}
