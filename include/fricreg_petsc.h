/* SPDX-License-Identifier: GPL-3.0-or-later */
/**
 * \file
 * fricreg_petsc.h — friction contacts inside a PETSc time stepper, one MPI rank's share of them
 * at a time (the optional library libfricreg_petsc).
 *
 * A rank's contacts are evaluated by a fricreg context (fricreg_ctx, law (4) of Quinn 2004 by
 * default) inside the user's TS callbacks: the right-hand side of an explicit stepper (TSRK:
 * fricreg_petsc_rhs_add), the residual and its exact Jacobian for an implicit one (TSALPHA2
 * through TSSetI2Function/TSSetI2Jacobian, or TSSetIFunction/TSSetIJacobian:
 * fricreg_petsc_residual_add, fricreg_petsc_jacobian_add). docs/distributed.md shows the calls
 * from a DMDA and a DMPlex code.
 *
 * The model. The unknowns are a PETSc Vec whose entries are degrees of freedom of a structure
 * with a lumped (diagonal) mass matrix M, m_i > 0 at every contact node. Contact k acts
 * along one degree of freedom a = node[k] and, when other[k] >= 0, against a second one
 * b = other[k]: its relative velocity is zdot_k = v_a - v_b (v_a alone against the ground),
 * and its friction force f_k acts on a and, reversed, on b. The ground is at rest: ground
 * motion is modelled in relative coordinates (an effective force -M r a_g, as fricreg_structure
 * does). Hence W = J M^-1 J^T (the paper's R, Sec. 3.3) is W_kk = 1/m_a + 1/m_b, and two
 * contacts that share a degree of freedom d (coupled contacts: the rows of an interface whose
 * nodes carry several contacts) are coupled by W_kl = +-1/m_d (+ where d is on the same side of
 * both). Such a W goes to the context in compressed rows and its near-stick solve couples
 * them (the consistent law of fricreg.h); without a shared degree of freedom W is diagonal, as
 * before.
 *
 * What is supported across ranks. Both degrees of freedom of a contact must be owned by the
 * calling rank (in its ownership range of the Vec: not a ghost, not another rank's), so W is
 * block-local: each rank evaluates its contacts with no communication at all, and f_eq needs
 * no solve across ranks, coupled contacts included (they are coupled through their shared,
 * owned degrees of freedom only). A contact that touches a degree of freedom of another rank
 * is refused at creation with FRICREG_PETSC_EREMOTE, on every rank at once (creation is
 * collective), and never reaches an evaluation. Partition the mesh so that a contact pair, and
 * a group of coupled contacts, stays on one rank (DMPlex: a contact's two sides in one cell
 * closure, or PetscPartitioner weights); contacts to the ground never cross ranks.
 *
 * Conventions: those of fricreg.h. Every function returns FRICREG_OK or a status, the object
 * keeps its last error and a message (fricreg_petsc_errmsg); the library never prints, exits
 * or aborts: a PETSc error inside one of its calls is returned as FRICREG_PETSC_EPETSC with
 * PETSc's text in the message, not printed (PetscReturnErrorHandler is pushed for the call).
 * Units are the caller's, consistent: the mass Vec in mass units, velocities, forces
 * (mun, f) and accelerations as fricreg.h says. One object per TS; like PETSc objects, not to
 * be used from two threads at once.
 *
 * Options and profiling. fricreg_petsc_set_from_options reads -fricreg_law, -fricreg_eps and
 * -fricreg_mun from the options database. The entry points that evaluate the contacts are log
 * events, FricregRhsAdd, FricregResidAdd and FricregJacAdd, registered by the first
 * fricreg_petsc_create: -log_view shows friction's share of a run beside PETSc's own events.
 *
 * This header includes PETSc's (petscmat.h: Vec, Mat, PetscInt, PetscReal): it is a PETSc
 * adapter, called from code that holds those objects. fricreg's own headers include no PETSc.
 */
#ifndef FRICREG_PETSC_H
#define FRICREG_PETSC_H

#include <petscmat.h>

#include "fricreg.h"

#ifdef __cplusplus
extern "C" {
#endif

/** \defgroup petsc PETSc adapter: a rank's contacts inside TS callbacks (fricreg_petsc)
 *  One object per rank and time stepper: the rank's contacts, their masses, a fricreg context,
 *  and the calls that add friction to a right-hand side, a residual or its Jacobian.
 *  \{ */

/** Opaque: a rank's friction contacts on a PETSc Vec layout. Created by fricreg_petsc_create,
 *  released by fricreg_petsc_free. */
typedef struct fricreg_petsc fricreg_petsc;

/** The adapter's own status codes, beyond fricreg.h's enum fricreg_status (whose codes it also
 *  returns). Values are fixed forever. */
enum fricreg_petsc_status {
    FRICREG_PETSC_EPETSC = 64, /**< a PETSc call failed; the message has PETSc's code and text */
    FRICREG_PETSC_EREMOTE = 65 /**< a contact's degree of freedom is not owned by the calling
                                   rank: contacts across ranks are not supported */
};

/** Fixed English text for a status code, the adapter's (enum fricreg_petsc_status) or the
 *  core's (fricreg_strerror). Returns that text, never NULL, not a status. Thread safe. */
FRICREG_API const char *fricreg_petsc_strerror(int status);

/** Create the calling rank's contacts. Collective on the communicator of mass: every rank
 *  calls it (a rank without contacts with m = 0), and every rank gets the same status: a
 *  refused contact on one rank fails the creation on all, so no rank goes on to a TS step the
 *  others never take.
 *
 *  Defaults: law FRICREG_LAW_QUINN (4) with eps = 1e-3, mun_k = 1
 *  (fricreg_petsc_set_law, fricreg_petsc_set_bounds).
 *
 *  mass      the lumped masses m_i (mass units), a Vec with the layout of the unknowns the
 *            contacts' indices address (a DM's global vector); read at the contacts' entries
 *            only, which must be finite and > 0. Not kept: later calls check their Vecs'
 *            local size against its.
 *  m         number of contacts of this rank, 0 <= m <= 2^26.
 *  node[m]   each contact's degree of freedom a, a global index (PETSc ordering) in this
 *            rank's ownership range of mass. May be NULL when m = 0.
 *  other[m]  optional (NULL: every contact against the ground): each contact's second degree
 *            of freedom b, a global index owned by this rank, or -1 for the ground.
 *  out       out: the new object, released with fricreg_petsc_free. Written only on success.
 *
 *  Contacts may share degrees of freedom (the header's coupled contacts): W = J M^-1 J^T then
 *  has its off-diagonal entries, and creation allocates O(nnz(W) + sum |G|^2) for it and for
 *  the tangent's blocks, G the groups of contacts W connects. More contacts in a group than
 *  the degrees of freedom they move make W singular (redundant contacts): accepted here, an
 *  evaluation whose near-stick set is singular fails with FRICREG_ESINGULAR.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if out or mass is NULL, or node while m > 0;
 *  FRICREG_EINVAL if m > 2^26 on some rank, a contact has a = b, or a mass at a contact is not
 *  > 0; FRICREG_ENONFINITE if such a mass is NaN or infinite; the context's refusal of a
 *  coupled W (which J M^-1 J^T, semidefinite, only meets through memory: FRICREG_ENOMEM); FRICREG_PETSC_EREMOTE if an index is outside this rank's
 *  ownership range (another rank's degree of freedom, or none at all);
 *  FRICREG_PETSC_EPETSC; FRICREG_ENOMEM. The failing rank's status wins on the others (the
 *  largest code when several fail); without an object, a failure has no message beyond it. */
FRICREG_API int fricreg_petsc_create(Vec mass, size_t m, const PetscInt node[],
                                     const PetscInt other[], fricreg_petsc **out);

/** Release the object and its context. fricreg_petsc_free(NULL) does nothing. Not
 *  collective. */
FRICREG_API void fricreg_petsc_free(fricreg_petsc *fp);

/** Number of this rank's contacts m; 0 if fp is NULL. Returns that number, not a status. */
FRICREG_API size_t fricreg_petsc_size(const fricreg_petsc *fp);

/** Select the friction law (enum fricreg_law) and eps > 0 (velocity units), as
 *  fricreg_ctx_set_law. Paper: eps = 10 omega dt on the chain (Sec. 3.2), 2 dt on the
 *  oscillator; for a structure a small fraction of the velocities of interest
 *  (docs/structural.md).
 *  Returns FRICREG_OK; FRICREG_ENULL if fp is NULL; FRICREG_EINVAL for an unknown law or
 *  eps < DBL_MIN; FRICREG_ENONFINITE if eps is NaN or infinite. */
FRICREG_API int fricreg_petsc_set_law(fricreg_petsc *fp, int law, double eps);

/** Set the friction bounds mun[m] = mu_k N_k >= 0 (force units), as fricreg_ctx_set_bounds.
 *  Returns FRICREG_OK; FRICREG_ENULL if fp is NULL, or mun while m > 0; FRICREG_ESIZE if m
 *  differs from the object's; FRICREG_EINVAL if some mun[k] < 0; FRICREG_ENONFINITE. */
FRICREG_API int fricreg_petsc_set_bounds(fricreg_petsc *fp, size_t m, const double mun[]);

/** Read the adapter's settings from a PETSc options database, as a PETSc object's
 *  SetFromOptions does (PetscOptionsGetString/Real, so -options_left counts them as used):
 *
 *    -fricreg_law NAME   the friction law by its fricreg_law_name: coulomb, force-balance,
 *                        karnopp, velocity-limited, tanh or quinn (fricreg_petsc_set_law)
 *    -fricreg_eps EPS    the regularization eps > 0 (velocity units)
 *    -fricreg_mun MUN    one bound mu_k N_k >= 0 for every contact of this rank (force units;
 *                        fricreg_petsc_set_bounds)
 *
 *  An option not given keeps the current setting (a law without -fricreg_eps keeps the eps last
 *  set, 1e-3 by default). Every value is checked before any is applied, so a refusal changes
 *  nothing. -help does not list these options (the library never prints): this docstring and
 *  docs/distributed.md do. Not collective.
 *
 *  options  the database; NULL for PETSc's global one.
 *  prefix   prepended to each name after its '-' (e.g. "beam_" reads -beam_fricreg_law), as
 *           PETSc objects' prefixes are; NULL for none.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if fp is NULL; FRICREG_EINVAL if -fricreg_law names no law,
 *  -fricreg_eps is not > 0 or -fricreg_mun is negative; FRICREG_ENONFINITE if a number is NaN
 *  or infinite; FRICREG_PETSC_EPETSC if PETSc fails to read a value (e.g. "-fricreg_eps abc").
 *  Since 1.7 (FRICREG_PETSC_1.1). */
FRICREG_API int fricreg_petsc_set_from_options(fricreg_petsc *fp, PetscOptions options,
                                               const char *prefix);

/** The fricreg context that evaluates the contacts, for the settings this header does not
 *  repeat (Stribeck friction: fricreg_stribeck.h). Owned by fp; NULL when the rank has no
 *  contacts. Its coupling is the adapter's (W = J M^-1 J^T, diagonal unless contacts share
 *  degrees of freedom): do not set another.
 *  Returns the context, not a status; NULL if fp is NULL. */
FRICREG_API fricreg_ctx *fricreg_petsc_get_ctx(fricreg_petsc *fp);

/** Add friction to an explicit right-hand side (TSRK, TSSetRHSFunction): with G holding the
 *  free accelerations (M^-1 times every force but friction) at the contacts' entries, adds
 *  G_a += f_k/m_a and G_b -= f_k/m_b, with f from the context's law at zdot_k = X_a - X_b and
 *  a_free,k = G_a - G_b (Sec. 3.3; law (4) by default). Not collective: no communication.
 *
 *  X      in: the TS state (global Vec, mass's layout) holding the velocities at the contacts'
 *         entries (first-order form u' = v, v' = a: index the v entries).
 *  G      in/out: the right-hand side, same layout; changed at the contacts' entries only.
 *  power  out, optional (NULL to skip): sum_k zdot_k f_k over this rank's contacts (force x
 *         velocity; minus the rate of frictional dissipation), for the caller's own reduction.
 *  Written only on success.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if fp, X or G is NULL; FRICREG_ESIZE if a Vec's local
 *  size is not mass's; the statuses of fricreg_ctx_eval (FRICREG_ENONFINITE for a NaN
 *  velocity or acceleration); FRICREG_PETSC_EPETSC. */
FRICREG_API int fricreg_petsc_rhs_add(fricreg_petsc *fp, Vec X, Vec G, double *power);

/** Add friction to an implicit residual written in force units, R = M A - F_free(t, U, V)
 *  (TSSetI2Function) or its first-order form (TSSetIFunction), where F_free is every force but
 *  friction: R_a -= f_k, R_b += f_k, with f from the context's law at zdot_k = V_a - V_b and
 *  a_free,k = F_free,a/m_a - F_free,b/m_b (Sec. 3.3; the f_eq of law (4) is -a_free,k/W_kk).
 *  Not collective.
 *
 *  V      in: velocities (global Vec, mass's layout): TSALPHA2's V, or the first-order state
 *         U with the contacts indexing its velocity entries.
 *  Ffree  in: the free forces F_free at the contacts' entries, same layout.
 *  R      in/out: the residual, same layout; changed at the contacts' entries only.
 *  power  out, optional (NULL to skip): sum_k zdot_k f_k over this rank's contacts.
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if fp, V, Ffree or R is NULL; FRICREG_EINVAL if R and
 *  Ffree are one Vec; FRICREG_ESIZE; the statuses of fricreg_ctx_eval; FRICREG_PETSC_EPETSC. */
FRICREG_API int fricreg_petsc_residual_add(fricreg_petsc *fp, Vec V, Vec Ffree, Vec R,
                                           double *power);

/** Add the exact derivative of fricreg_petsc_residual_add's term to the Jacobian P of the
 *  residual R = M A - F_free, P = mass_shift M - dF_free/dX in the rows of the contacts, X the
 *  Newton unknown: TSALPHA2 (TSSetI2Jacobian) passes X = U with velocity_shift = v_shift and
 *  mass_shift = a_shift; the first-order form (TSSetIJacobian) X = U with
 *  velocity_shift = 1 and mass_shift = shift. Collective on P (it ends with
 *  MatAssemblyBegin/End(MAT_FINAL_ASSEMBLY)): every rank calls it.
 *
 *  The free forces' derivative is read from P itself: dF_free,a/dX = mass_shift m_a e_a -
 *  (row a of P), so P must hold, assembled, the caller's whole Jacobian without friction (as
 *  it does at the end of the I(2)Jacobian callback). With g_v = df_k/dzdot_k and
 *  g_a = df_k/da_free,k from fricreg_ctx_tangent_apply (the law's exact slopes, one-sided at
 *  its kinks as fricreg_ctx_tangent says), row a gains
 *  -(g_v velocity_shift + g_a mass_shift)(e_a - e_b) + (g_a/m_a) P_a - (g_a/m_b) P_b, row b
 *  its negative: the contact's row stays in its stencil (a contact between a and b needs row
 *  a's pattern to cover row b's columns and back; against the ground nothing new). Coupled
 *  contacts: g_v and g_a become the tangent's blocks over each group G of contacts W connects
 *  (read by 2 |G| probing products with fricreg_ctx_tangent_apply for the largest group), and
 *  row a gains the same terms summed over its group, so the rows of a group's degrees of
 *  freedom must each cover the columns of all of them.
 *  The forces are evaluated afresh at (V, Ffree), whatever was evaluated before.
 *
 *  V, Ffree        in: as fricreg_petsc_residual_add, at the Newton iterate.
 *  mass_shift      d A/d X (TSALPHA2's a_shift; shift of TSSetIJacobian), finite.
 *  velocity_shift  d V/d X (TSALPHA2's v_shift; 1 in the first-order form), finite.
 *  P               in/out: the assembled Jacobian (AIJ, global rows = mass's layout).
 *
 *  Returns FRICREG_OK; FRICREG_ENULL if fp, V, Ffree or P is NULL; FRICREG_ESIZE;
 *  FRICREG_ENONFINITE if a shift is NaN or infinite; the statuses of fricreg_ctx_eval and
 *  fricreg_ctx_tangent_apply; FRICREG_PETSC_EPETSC (also when P's pattern lacks an entry it
 *  must add, or P is not assembled); FRICREG_ENOMEM. A rank that fails still ends the
 *  assembly when it can, so the others do not wait for ever. */
FRICREG_API int fricreg_petsc_jacobian_add(fricreg_petsc *fp, Vec V, Vec Ffree,
                                           PetscReal mass_shift, PetscReal velocity_shift, Mat P);

/** The forces f[m] of the last successful evaluation (rhs_add, residual_add or
 *  jacobian_add), contact order, force units: for per-contact outputs such as each contact's
 *  dissipation.
 *  Returns FRICREG_OK; FRICREG_ENULL if fp is NULL, or f while m > 0; FRICREG_ESIZE if m
 *  differs from the object's; FRICREG_EINVAL if nothing was evaluated yet. */
FRICREG_API int fricreg_petsc_get_forces(const fricreg_petsc *fp, size_t m, double f[]);

/** The status of the last failed call on fp.
 *  Returns that status, FRICREG_OK if none; FRICREG_ENULL if fp is NULL. */
FRICREG_API int fricreg_petsc_errcode(const fricreg_petsc *fp);

/** Message of the last failed call on fp ("" if none), owned by fp, valid until its next call;
 *  never NULL. Returns that text, not a status. */
FRICREG_API const char *fricreg_petsc_errmsg(const fricreg_petsc *fp);

/** \} */

#ifdef __cplusplus
}
#endif

#endif /* FRICREG_PETSC_H */
