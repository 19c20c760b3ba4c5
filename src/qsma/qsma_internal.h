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
    double *ks, *fs;          /* [nsl]: its stiffness and slip force */
    double *z;                /* [nsl]: its slip (0 until it slips; set when it sticks again) */
    int *sigma;               /* [nsl]: 0 stuck, ±1 slipping in that direction */
    double omega_k, zeta_k;   /* the stuck mode's ω_k and ζ_k = φ^T C φ / (2 ω_k) */
    double phik;              /* φ_k^T K φ_k (Rayleigh's a1 derivative) */
};

/* The sensitivities' inputs (qsma_dlambda.c): np parameters, role[np nsl] what each is to
 * each slider (0 none, 1 its stiffness, 2 its slip force), w[np n] M dφ_k/dp (0 if p does not
 * move φ_k); and their state along the path: dz[np nsl] each slider's slip's derivative (0 but
 * for a slider stuck again), dur[np m] the last event's J x* differentiated, dx[np n]
 * scratch. */
struct fr_qsma_sens {
    size_t np;
    const signed char *role;
    const double *w;
    double *dz, *dur, *dx;
};

/* The path's results at each target amplitude (qsma_path.c): λ, ∫_0^a λ ds, dλ/dq on the
 * piece there, and with sensitivities dλ/dp [np] and d∫/dp [np] per target. */
struct fr_qsma_out {
    double *lambda, *integral, *slope; /* [na] each */
    double *dlambda, *dintegral;       /* [na np] each, or NULL */
};

/* The model of the driver (every element jenkins or iwan, at most FR_QSMA_MAX_DOFS dofs)
 * into a new s. FRICREG_OK, FRICREG_EINVAL (an element of another type, too many dofs, no
 * slider), FRICREG_ENOMEM (message recorded, with fn). fr_qsma_free(NULL) is a no-op. */
int fr_qsma_create(fricreg_hb *hb, const char *fn, struct fr_qsma **out);
void fr_qsma_free(struct fr_qsma *s);

/* K + J^T diag(kr) J into A [n n] (fr_qsma_assemble); fr_qsma_tangent: that into Kt,
 * Cholesky-factored (LAPACK's dpotrf), then v = Kt^-1 b; FRICREG_OK, or FRICREG_ESINGULAR when
 * a pivot squared is not above 1e-14 of the largest diagonal entry. */
void fr_qsma_assemble(const struct fr_qsma *s, const double *J, double *A);
int fr_qsma_tangent(struct fr_qsma *s, const double *J);

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

/* The model and its mode k for a public call (qsma.c): fr_qsma_create, then fr_qsma_mode. */
int fr_qsma_setup(fricreg_hb *hb, const char *fn, size_t mode, struct fr_qsma **out);

/* A public call's checks of the driver, mode and amplitudes (qsma.c): FRICREG_OK, or the status
 * with its message recorded. */
int fr_qsma_args(fricreg_hb *hb, const char *fn, size_t mode, size_t na, const double *amp);

#endif
