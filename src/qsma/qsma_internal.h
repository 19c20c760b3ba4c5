/* SPDX-License-Identifier: GPL-3.0-or-later */
/* qsma_internal.h — quasi-static modal analysis (fricreg_hb_qsma.h): the model of the driver
 * densified with its sliders (qsma_model.c), the stuck mode and its derivative in the
 * stiffnesses (qsma_mode.c), the event-driven loading path (qsma_path.c) and a point's λ
 * differentiated in the parameters (qsma_dlambda.c). Included only inside src/qsma/. */
#ifndef FRICREG_QSMA_INTERNAL_H
#define FRICREG_QSMA_INTERNAL_H

#include "hb/hb_internal.h"

/* Dense models up to this size: every event refactors the tangent, O(n³). */
#define FR_QSMA_MAX_DOFS 4096

/* The model and the path's state. A slider is one of an element's sliders of positive slip
 * force (a slider of slip force 0 carries nothing), on row row[s] of J. */
struct fr_qsma {
    size_t n, m, nsl;         /* dofs, rows of J, sliders */
    double *K, *C, *M;        /* [n n] each, row-major: the model's K (no elements), C, M */
    double *Kt;               /* [n n]: the tangent, Cholesky-factored in place */
    double *phi, *b, *c;      /* [n]: φ_k, b = M φ_k (the load), C φ_k */
    double *x, *v;            /* [n]: the displacement and dx/dλ on the current piece */
    double *ur, *vr, *kr;     /* [m]: J x, J v, each row's stuck stiffness */
    size_t *row, *elem, *loc; /* [nsl]: its row, element and place among the element's sliders */
    size_t ncon, *con;        /* the elements with a normal law (3-D contacts, Jenkins with
                                 lift-off): how many, [ncon] their elements */
    size_t nst;               /* the marched path's states: a slider's one, a contact's dim */
    double *ks, *fs;          /* [nsl]: its stiffness and slip force */
    double *z;                /* [nsl]: its slip (0 until it slips; set when it sticks again) */
    int *sigma;               /* [nsl]: 0 stuck, ±1 slipping in that direction */
    double omega_k, zeta_k;   /* the stuck mode's ω_k and ζ_k = φ^T C φ / (2 ω_k) */
    double phik;              /* φ_k^T K φ_k (Rayleigh's a1 derivative) */
};

/* The sensitivities' inputs (qsma_dlambda.c): np parameters, role[np nsl] what each is to
 * each slider (0 none, 1 its stiffness, 2 its slip force) and crole[np ncon] to each 3-D
 * contact (enum fr_qsma_role), w[np n] M dφ_k/dp (0 if p does not
 * move φ_k); and their state along the path: dz[np nsl] each slider's slip's derivative (0 but
 * for a slider stuck again), dur[np m] the last event's J x* differentiated, dx[np n]
 * scratch. */
struct fr_qsma_sens {
    size_t np;
    const signed char *role, *crole;
    const double *w;
    double *dz, *dur, *dx;
};

/* The path's results at each target amplitude (qsma_path.c): λ, ∫_0^a λ ds, dλ/dq on the
 * piece there, d∫/da (λ where the integral is exact; the marched path's trapezoid moves with
 * its last point), and with sensitivities dλ/dp [np] and d∫/dp [np] per target. */
struct fr_qsma_out {
    double *lambda, *integral, *slope, *dint_da; /* [na] each */
    double *dlambda, *dintegral;                 /* [na np] each, or NULL */
};

/* The model of the driver (every element jenkins, iwan, jenkins_normal or contact_3d, at most
 * FR_QSMA_MAX_DOFS dofs) into a new s, with each row's stuck stiffness in kr (a contact closed
 * at rest, n0 > 0: kt on its tangential rows where mu > 0, kn on its normal one; as
 * fricreg_hb_nma's linear mode). FRICREG_OK, FRICREG_EINVAL (an element of another type, too
 * many dofs, no slider nor contact), FRICREG_ENOMEM (message recorded, with fn).
 * fr_qsma_free(NULL) is a no-op. */
int fr_qsma_create(fricreg_hb *hb, const char *fn, struct fr_qsma **out);
void fr_qsma_free(struct fr_qsma *s);

/* K + J^T diag(kr) J into A [n n] (fr_qsma_assemble); fr_qsma_tangent: that into Kt,
 * Cholesky-factored (LAPACK's dpotrf), then v = Kt^-1 b; FRICREG_OK, or FRICREG_ESINGULAR when
 * a pivot squared is not above 1e-14 of the largest diagonal entry. */
void fr_qsma_assemble(const struct fr_qsma *s, const double *J, double *A);
int fr_qsma_tangent(struct fr_qsma *s, const double *J);

/* LAPACK's LU (dgetrf) of A, order N, column-major, in place: FRICREG_OK, or FRICREG_ESINGULAR
 * at a pivot not above 1e-14 of A's largest entry (or an entry not finite). */
int fr_qsma_lu(double *A, size_t N, int *piv);

/* The stuck mode k of K_0 = K + J^T diag(kr) J (the sliders' stiffnesses summed per row) with
 * M, by LAPACK's dsygvd: φ_k mass-normalized, its largest entry positive (as fricreg_hb_nma's),
 * ω_k, b, c, ζ_k. FRICREG_OK, FRICREG_EINVAL (ω_k² <= 0), FRICREG_ENOTPSD (M),
 * FRICREG_ENONFINITE, FRICREG_ENOMEM (message recorded, with fn). */
int fr_qsma_mode(fricreg_hb *hb, const char *fn, size_t mode, struct fr_qsma *s);

/* dφ_k/dp of the np parameters whose stiffness rows move K_0 (dk[np m]: d k_r/dp, a row of
 * zeros for the others) as M dφ_k/dp into w[np n], dω_k/dp into domk[np] and dζ_k/dp into
 * dzk[np]: the bordered [K_0 − ω_k² M, M φ_k; φ_k^T M, 0] (dφ, −dω_k²) = (−dK_0 φ_k, 0), one
 * LU (LAPACK's dgetrf). FRICREG_OK, FRICREG_ESINGULAR (a repeated stuck mode), FRICREG_ENOMEM
 * (message recorded, with fn). */
int fr_qsma_shape(fricreg_hb *hb, const char *fn, const struct fr_qsma *s, size_t np,
                  const double *dk, double *w, double *domk, double *dzk);

/* dλ/dp of the np parameters at the point (x, λ) of the current piece (J x in ur, J v in vr):
 * the bordered solve of K_t dx − dλ b = −dK_t x − dg + λ db, b^T dx = −db^T x, with v = K_t^-1 b
 * making it one dot product a parameter. */
void fr_qsma_dlambda(const struct fr_qsma *s, const struct fr_qsma_sens *p, const double *x,
                     const double *ur, double lambda, double *dl);

/* The event at λ where slider t reaches its slip force, moved by the parameters: on the piece's
 * factor (before the pattern changes) dx* = dx|_λ + v dλ_e, dλ_e from t's condition
 * k_t (J_t x − z_t) = ±φ_t; J dx* into p->dur. */
void fr_qsma_devent(const struct fr_qsma *s, const struct fr_qsma_sens *p, const double *J,
                    size_t t, double lambda);

/* The loading path from rest through the na increasing amplitudes amp[] (qsma_path.c), its
 * results into out; with p (or NULL) the sensitivities too; work[4 np + n + m]. FRICREG_OK,
 * FRICREG_ESINGULAR (macroslip: the tangent singular before the last amplitude),
 * FRICREG_EINVAL (no consistent pattern of stuck and slipping sliders at an event),
 * FRICREG_ENONFINITE (message recorded, with fn). */
int fr_qsma_path(fricreg_hb *hb, const char *fn, struct fr_qsma *s, size_t na, const double *amp,
                 const struct fr_qsma_sens *p, double *work, struct fr_qsma_out *out);

/* The elements as the marched path steps them (qsma_units.c): a slider (dim 1: kt = k_s, phi
 * its slip force) or an element with a normal law (normal: its normal row after its dim
 * tangential ones, kt, mu, kn, n0: a 3-D contact, dim 2, or a Jenkins element with lift-off,
 * dim 1), its first row of J and its state's place st; what one step records of it; and
 * what a parameter is to it (a slider's stiffness is KT, its slip force BOUND, a contact's mu
 * BOUND). */
enum fr_qsma_mode { FR_QSMA_STICK, FR_QSMA_SLIP, FR_QSMA_OPEN };
enum fr_qsma_role {
    FR_QSMA_ROLE_NONE,
    FR_QSMA_ROLE_KT,
    FR_QSMA_ROLE_BOUND,
    FR_QSMA_ROLE_KN,
    FR_QSMA_ROLE_N0
};
struct fr_qsma_unit {
    size_t row, st;
    int dim, normal;
    double kt, phi, mu, kn, n0;
};
struct fr_qsma_record {
    int mode;                      /* enum fr_qsma_mode */
    double d[2], n[2], f[2], t[4]; /* u − w_old, its direction, the tangential force, tangent */
    double g, N;                   /* a contact's normal displacement and force */
};

/* Whether element e is stepped as a unit with a normal law (contact_3d, or jenkins_normal: a
 * lift-off element of one slider), and then its tangential rows. */
static inline int fr_qsma_has_normal(const fricreg_hb *hb, size_t e)
{
    const double *k, *phi;
    return hb->kind[e] == FR_HB_CONTACT_3D ||
           (hb->kind[e] == FR_HB_LIFTOFF && fr_hb_sliders(hb, e, &k, &phi) == 1);
}

static inline int fr_qsma_tangential_rows(const fricreg_hb *hb, size_t e)
{
    return (int)fr_hb_rows_of(hb, e) - 1;
}

static inline size_t fr_qsma_unit_rows(const struct fr_qsma_unit *un)
{
    return (size_t)(un->dim + un->normal);
}

/* One step of unit un at u[rows] from its state wold[dim]: its forces f[rows], df/du D[rows
 * rows] (row-major, at fixed wold), its state after the step w[dim], and the record the
 * derivatives below need. */
void fr_qsma_unit_step(const struct fr_qsma_unit *un, const double *u, const double *wold,
                       double *f, double *D, double *w, struct fr_qsma_record *rec);

/* The step's force moved by a parameter of role (enum fr_qsma_role) and the state before it by
 * dwold[dim], at fixed u: df[rows]. */
void fr_qsma_unit_dforce(const struct fr_qsma_unit *un, const struct fr_qsma_record *rec, int role,
                         const double *dwold, double *df);

/* The state after the step moved by du[rows], dwold[dim] and a parameter of role: dw[dim]. */
void fr_qsma_unit_dstate(const struct fr_qsma_unit *un, const struct fr_qsma_record *rec, int role,
                         const double *du, const double *dwold, double *dw);

/* The marched path's bordered tangent [K_0 + J^T E J, −b; b^T, 0] solved on K_0's Cholesky
 * factor and a capacitance matrix on the rows of the elements not stuck (qsma_capacitance.c's
 * comment). create: K_0 = K + J^T diag(k_r) J factored, Y = K_0^-1 J^T, G = J Y (FRICREG_OK,
 * FRICREG_ESINGULAR if K_0 is not positive definite, FRICREG_ENOMEM); factor: at the elements'
 * tangents Ed [m m] (row-major, by rows of J) against k_r (FRICREG_OK, FRICREG_ESINGULAR);
 * solve: nrhs columns of order n + 1 in place, (c, d) to (z, μ). fr_qsma_cap_free(NULL) is a
 * no-op. */
struct fr_qsma_cap {
    size_t n, m, na;           /* dofs, rows, active rows */
    double *L, *Y, *G, *E, *C; /* [n n], [m n], [m m], [na na] (room m m) each */
    double *zb, *t, *u, bzb;   /* [n] K_t^-1 b, [m] scratch each; b^T K_t^-1 b */
    size_t *act;               /* [na] the active rows */
    int *piv;
};
int fr_qsma_cap_create(const struct fr_qsma *s, const double *J, struct fr_qsma_cap **out);
int fr_qsma_cap_factor(struct fr_qsma_cap *c, const double *Ed, const double *kr, const double *J,
                       const double *b);
void fr_qsma_cap_solve(struct fr_qsma_cap *c, const double *J, const double *b, size_t nrhs,
                       double *B);
void fr_qsma_cap_free(struct fr_qsma_cap *c);

/* The loading path marched in the modal amplitude (qsma_march.c), for a model with 3-D
 * contacts: from the rest state under the contacts' preloads, steps of h = 2^⌊log2(a_max/256)⌋
 * in q, each a Newton solve of the bordered static equilibrium with the elements' return
 * mappings from the step before (backward Euler), and each target reached by a step of its own
 * from the grid point below it. Results into out as fr_qsma_path's, the integral by the
 * trapezoid over the steps; with p (or NULL) the sensitivities of that discrete path, exact:
 * forward, through the states. FRICREG_OK, FRICREG_EINVAL (the preloads at rest open a contact
 * closed by its n0, or close one that n0 leaves open), FRICREG_ESINGULAR (the rest state's
 * stiffness, or Newton's bordered matrix), FRICREG_EWORK (a step that Newton does not
 * converge in 12 halvings), FRICREG_ENOMEM (message recorded, with fn). */
int fr_qsma_march(fricreg_hb *hb, const char *fn, struct fr_qsma *s, size_t na, const double *amp,
                  const struct fr_qsma_sens *p, struct fr_qsma_out *out);

/* The path for a public call (qsma.c): fr_qsma_march with 3-D contacts, else fr_qsma_path;
 * out->dint_da (where not NULL) set by either. */
int fr_qsma_run(fricreg_hb *hb, const char *fn, struct fr_qsma *s, size_t na, const double *amp,
                const struct fr_qsma_sens *p, double *work, struct fr_qsma_out *out);

/* The model and its mode k for a public call (qsma.c): fr_qsma_create, then fr_qsma_mode. */
int fr_qsma_setup(fricreg_hb *hb, const char *fn, size_t mode, struct fr_qsma **out);

/* A public call's checks of the driver, mode and amplitudes (qsma.c): FRICREG_OK, or the status
 * with its message recorded. */
int fr_qsma_args(fricreg_hb *hb, const char *fn, size_t mode, size_t na, const double *amp);

#endif
