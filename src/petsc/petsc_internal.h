/* SPDX-License-Identifier: GPL-3.0-or-later */
/* petsc_internal.h — the layout of a fricreg_petsc: a rank's contacts as offsets into its
 * owned part of the Vecs, their inverse masses, the context and its scratch, the coupled
 * contacts' groups, and the one helper every entry point uses to turn a PETSc error into a
 * status. */
#ifndef FRICREG_PETSC_INTERNAL_H
#define FRICREG_PETSC_INTERNAL_H

#include "fricreg_petsc.h"

#include "base/error.h"

/* Contacts that share degrees of freedom (coupling.c): W's connected groups, and the
 * tangent's block of each, row-major |G| x |G| in the group's member order. */
struct fr_petsc_coupling {
    size_t ngroups, largest; /* groups; the most contacts in one */
    size_t *group, *place;   /* [m] each contact's group and its place in it */
    size_t *members;         /* [m] the contacts group by group, */
    size_t *first;           /* [ngroups + 1] group g's from members[first[g]] */
    size_t *block;           /* [ngroups + 1] group g's block from tz[block[g]] */
    double *tz, *ta;         /* the blocks of df/dzdot and df/da_free */
    double *probe, *df;      /* [m] scratch */
};

struct fricreg_petsc {
    struct fr_error err;
    size_t m;          /* this rank's contacts */
    PetscInt nlocal;   /* the owned length of mass's layout */
    PetscInt rstart;   /* the first owned global index */
    PetscInt *a, *b;   /* [m] offsets in the owned part; b = -1: the ground */
    double *inv_ma;    /* [m] 1/m_a */
    double *inv_mb;    /* [m] 1/m_b, 0 for the ground */
    fricreg_ctx *ctx;  /* NULL when m = 0 */
    double *zdot;      /* [m] scratch: relative velocities */
    double *afree;     /* [m] scratch: free relative accelerations */
    double *f;         /* [m] the last evaluation's forces */
    double *gv, *ga;   /* [m] the tangent's diagonal: df/dzdot, df/da_free */
    double *ones;      /* [m] 1: the direction that reads a diagonal tangent */
    int evaluated;     /* f holds an evaluation */
    PetscInt *cols;    /* the Jacobian's row buffer: columns */
    PetscScalar *vals; /* and values, cap entries each */
    size_t cap;
    int law;     /* the law and eps last set (fricreg_petsc_set_from_options keeps */
    double eps;  /* the one it is not given) */
    int coupled; /* a degree of freedom in two contacts: W not diagonal, coupling's groups */
    struct fr_petsc_coupling coupling;
};

/* The adapter's log events (events.c): -1 until fr_petsc_events_register. */
struct fr_petsc_events {
    PetscLogEvent rhs_add, residual_add, jacobian_add;
};
extern struct fr_petsc_events fr_petsc_events;

/* Finds or registers the log events; called by fricreg_petsc_create. */
PetscErrorCode fr_petsc_events_register(void);

/* Records PETSc's error ierr from the call named `what` as fp's FRICREG_PETSC_EPETSC. */
int fr_petsc_fail(fricreg_petsc *fp, PetscErrorCode ierr, const char *what);

/* Checks that v is a Vec with fp's owned length: FRICREG_ENULL, FRICREG_ESIZE, or the PETSc
 * failure of asking. */
int fr_petsc_check_vec(fricreg_petsc *fp, Vec v, const char *fn, const char *name);

/* Evaluates the context at fp->zdot, fp->afree into fp->f (m = 0: nothing). */
int fr_petsc_eval(fricreg_petsc *fp, const char *fn);

/* Reads zdot_k = V_a - V_b and a_free,k = F_a s_a - F_b s_b, s = 1/m when scale_by_mass, else
 * 1 (F already accelerations), from the owned arrays. */
void fr_petsc_gather(fricreg_petsc *fp, const PetscScalar *v, const PetscScalar *F,
                     int scale_by_mass);

/* sum_k zdot_k f_k. */
double fr_petsc_power(const fricreg_petsc *fp);

/* After the inverse masses: whether contacts share degrees of freedom (fp->coupled), and if
 * so W with its off-diagonal entries to the context and the groups (coupling.c). FRICREG_OK,
 * FRICREG_ENOMEM, or the context's refusal of W; recorded in fp. */
int fr_petsc_coupling_setup(fricreg_petsc *fp);

/* The tangent's blocks at the last evaluation, by probing: FRICREG_OK or the status of
 * fricreg_ctx_tangent_apply, recorded in fp. */
int fr_petsc_coupling_tangent(fricreg_petsc *fp);

void fr_petsc_coupling_free(struct fr_petsc_coupling *c);

#endif
