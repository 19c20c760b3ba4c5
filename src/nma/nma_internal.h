/* SPDX-License-Identifier: GPL-3.0-or-later */
/* nma_internal.h — the nonlinear modes' state (fricreg_hb_nma, fricreg_hb.h): the linear mode
 * the backbone starts from (nma_linear.c), the extended periodic motion concept's equations and
 * their Newton solve (nma_solve.c), the backbone's points (nma.c), hung on the driver as
 * hb->nma. Included only inside src/nma/. */
#ifndef FRICREG_HB_NMA_INTERNAL_H
#define FRICREG_HB_NMA_INTERNAL_H

#include "hb/hb_internal.h"

struct fr_hb_nma {
    size_t n, nq, nd; /* dofs, the condensed unknowns q, nd = nq + 2 with ω and ξ */
    size_t nc;        /* 2H + 1 coefficients a row of q, the mean first */
    int modal;        /* FRICREG_HB_NMA_DAMPING_MODAL: C replaced by ξ_k M */
    double omega_k;   /* the linearized (elements stuck) mode's circular frequency */
    double xi_k;      /* and φ_k^T C φ_k = 2 ζ_k ω_k */
    double a_stick;   /* below this modal amplitude every element sticks (0: none does) */
    double *phi;      /* [n] φ_k, mass-normalized */
    double *w;        /* [n] M φ_k: the load column of Y_1 while a mode is solved */
    double *zero;     /* [n] zeros: the load's sine part */
    double *dGx;      /* [(H+1) m m] complex: dG_h/dξ */
    double *dgx;      /* [(H+1) m] complex: d(J D_h^-1 M φ)/dξ */
    double *A;        /* [nd nd] Newton's matrix, LU-factored in place */
    int *piv;         /* [nd] its row interchanges (LAPACK's) */
    double *y, *yt, *R, *Rt, *dy, *col; /* [nd] each: iterate, trial, residuals, step, column */
    double *yc, *yo;  /* [nd] each: the march's last solution and the one before (nma.c) */
    double amplitude; /* the amplitude of the solve under way */
    double scale;     /* its displacement scale: the amplitude rows' weight is scale/amplitude */
    double *saved_pc, *saved_ps; /* the driver's excitation, back after the solve */

    /* the backbone: per point a, ω, ξ, then the unknowns q */
    size_t npts, cap, stride;
    double *pts;
    /* the folds of the last continuation (nma_arclength.c): per fold a, ω, ξ and its place,
     * the stored points' index plus the fraction of the stretch (its arclength until the
     * points are resampled), 4 doubles */
    size_t nfolds;
    double *folds;
    size_t mode;           /* the backbone's mode k */
    const double *targets; /* the caller's amplitudes of fricreg_hb_nma_at (npoints), else NULL */
    size_t nlambda;  /* n for a dense model (every stuck mode's ω² known), 0 for a sparse one */
    double *lambda;  /* [n] the stuck structure's ω_r², ascending (nma_linear.c) */
    size_t nspecial; /* the special points, folds and crossings k ω = ω_r (nma_crossings.c) */
    double *special; /* per point FR_HB_NMA_SPECIAL_STRIDE doubles: place, type, k, r, a, ω, ζ */
    double *modes;   /* [n n] the stuck modes φ_r (row r), mass-normalized; NULL until first
                        asked for (nma_energy.c) */
    unsigned long model_serial; /* the driver's when the backbone was begun: it holds while the
                                   model is the same (fr_hb_backbone_holds) */
};

/* Whether a backbone was computed and the model is still its own (no change since). */
static inline int fr_hb_backbone_holds(const fricreg_hb *hb)
{
    return hb->nma != NULL && hb->nma->model_serial == hb->model_serial;
}

/* The linearized structure's mode k (elements stuck: each row of J a spring of its elements'
 * stiffness, fr_hb_nma_row): φ_k mass-normalized into nma->phi, ω_k, ξ_k, a_stick.
 * FRICREG_OK, FRICREG_EINVAL (ω_k² <= 0), FRICREG_ENOTPSD (M), FRICREG_ENONFINITE (overflow),
 * FRICREG_EWORK (a sparse model's iteration did not converge), FRICREG_ENOMEM (message
 * recorded, with fn). */
int fr_hb_nma_linear(fricreg_hb *hb, const char *fn, size_t mode, struct fr_hb_nma *nma);

/* A sparse model's mode k of K_0 φ = λ M φ by shift-invert subspace iteration
 * (nma_sparse_mode.c): φ [n] mass-normalized (its sign not set), λ = ω_k². FRICREG_OK,
 * FRICREG_ENOTPSD (M), FRICREG_EINVAL (K_0 not positive definite), FRICREG_ENONFINITE,
 * FRICREG_EWORK (not converged), FRICREG_ENOMEM (message recorded, with fn). */
int fr_hb_nma_sparse_mode(fricreg_hb *hb, const char *fn, size_t mode, double *phi, double *lambda);

/* The dense generalized symmetric eigenproblem K φ = λ M φ (nma_eigen.c), n x n row-major.
 * fr_hb_nma_cholesky: M = L L^T in place (the lower triangle, the upper zeroed); FRICREG_OK, or
 * FRICREG_ENOTPSD when a pivot is not above 1e-14 of M's largest diagonal entry.
 * fr_hb_nma_reduce: K <- L^-1 K L^-T in place. fr_hb_nma_symmv: the eigenvalues of the reduced
 * A (destroyed) ascending into work[0..n) (work: 5 n), the eigenvectors v as V's columns;
 * FRICREG_OK, FRICREG_ENONFINITE (*bad: A's first entry that is not finite) or FRICREG_EINVAL.
 * fr_hb_nma_back: φ = L^-T v of V's column c (φ^T M φ = 1). */
int fr_hb_nma_cholesky(double *M, size_t n);
void fr_hb_nma_reduce(const double *L, double *K, size_t n);
int fr_hb_nma_symmv(double *A, double *V, double *work, size_t n, size_t *bad);
void fr_hb_nma_back(const double *L, const double *V, size_t n, size_t c, double *phi);

/* A sparse model's every stuck mode is found (densified, as a dense model's) up to this many
 * dofs: for the crossings (nma_crossings.c) and the modal participation (nma_energy.c). Its
 * cost, GSL's dense symmetric eigensolve, O(n³), measured at 256 dofs: 0.11 s, beside 0.08 s
 * for a 40-point backbone of a 256-mass chain with one element (the cheapest backbone of that
 * size; a dense model of any size pays it too, its linear mode is that solve). Above it a
 * sparse model has neither. */
#define FR_HB_NMA_SPARSE_ALL_MODES 256

/* Every mode of a dense (or small sparse) model's stuck structure (as fr_hb_nma_linear's mode
 * k): φ_r mass-normalized into Phi's row r (n x n, row-major), ascending in ω_r. FRICREG_OK,
 * FRICREG_ENOTPSD, FRICREG_ENONFINITE, FRICREG_EINVAL, FRICREG_ENOMEM (message recorded, with
 * fn). */
int fr_hb_nma_modes(fricreg_hb *hb, const char *fn, double *Phi);

/* The special points into s->special in the branch's order (nma_crossings.c): the crossings
 * k ω = ω_r (k = 2..H, r every stuck mode but the backbone's; none for a sparse model,
 * s->nlambda 0) between the backbone's consecutive points, merged with the folds of
 * s->folds. FRICREG_OK, FRICREG_ENOMEM (no message: the caller records it). */
#define FR_HB_NMA_SPECIAL_STRIDE 7
int fr_hb_nma_find_special(struct fr_hb_nma *s);

/* Row r of J's stiffness with its elements stuck and its amplitude of first slip (or opening):
 * *k (0: the row carries no force at rest), *limit (infinite: none). */
void fr_hb_nma_row(const fricreg_hb *hb, size_t r, double *k, double *limit);

/* d k_r / d p for row erow[e] + sr of J (fr_hb_nma_row's k) and parameter j of element e in
 * fricreg_element.h's layout of its type (element_params.h): 1 for a slider's stiffness of
 * positive slip force (a normal law's kt or k_s, and kn on the normal row, while N0 > 0 closes
 * it), else 0; a marched element's the derivative of its elastic stiffness (linear in its
 * parameters: its value at the unit vector e_j). */
double fr_hb_nma_row_dk(const fricreg_hb *hb, size_t e, size_t j, size_t sr);

/* The model's M, the stuck structure's K_0 = K + J^T diag(k_r) J and the damping C (or
 * Rayleigh's a0 M + a1 K) as n x n row-major, densified (nma_linear.c). */
void fr_hb_nma_stuck_model(const fricreg_hb *hb, double *M, double *K0, double *C);

/* Sets up the driver for a mode's solves (the damping C − ξ M, the load column M φ) and back. */
void fr_hb_nma_enter(fricreg_hb *hb, struct fr_hb_nma *nma);
void fr_hb_nma_leave(fricreg_hb *hb, struct fr_hb_nma *nma);

/* Newton's method on the extended periodic motion concept's equations at the amplitude a from
 * nma->y (q, ω, ξ; the solution there). FRICREG_OK, FRICREG_EWORK, FRICREG_ESINGULAR,
 * FRICREG_EINTEGRATOR, FRICREG_ENONFINITE, FRICREG_ENOMEM (message recorded, with fn). */
int fr_hb_nma_newton(fricreg_hb *hb, const char *fn, struct fr_hb_nma *nma, double a);

/* The extended periodic motion concept's equations at y (q, ω, ξ) and the amplitude
 * nma->amplitude: (R) into R[nq], the amplitude and phase rows, weighted by
 * nma->scale/nma->amplitude, into R[nq], R[nq + 1]; with jac Newton's matrix (∂/∂(q, ω, ξ))
 * into nma->A, row-major nd x nd. Statuses as fr_hb_nma_evaluate's. */
int fr_hb_nma_system(fricreg_hb *hb, const char *fn, struct fr_hb_nma *nma, const double *y,
                     double *R, int jac);

/* −g^T F_1 (complex, into s[2]) for a first harmonic's column g[m] (complex: the load column's
 * J D_1^-1 M φ, or a derivative of it) and forces f[nq] in (R)'s real form (nma_solve.c): the
 * amplitude and phase conditions' s = φ^T M X_1, or its derivative in f. */
void fr_hb_nma_modal(const fricreg_hb *hb, const double *g, const double *f, double *s);

/* The derivatives of the condensation in the damping at the factored omega into nma->dGx and
 * nma->dgx: in ξ, dD_h/dξ = −i hω M (stiffness 0), or in Rayleigh's a1, dD_h/da1 = i hω K
 * (stiffness 1): dG_h = −Y_h^T dD_h Y_h, the same for the load column. */
void fr_hb_nma_damping_derivatives(fricreg_hb *hb, struct fr_hb_nma *nma, double omega,
                                   int stiffness);

/* The driver's factors, forces and (R) into R[nq] at the unknowns y (q, ω, ξ), with the forces'
 * Jacobians: the displacements (fr_hb_recover) of a stored point follow. */
int fr_hb_nma_evaluate(fricreg_hb *hb, const char *fn, struct fr_hb_nma *nma, const double *y,
                       double *R);

/* The parameter sensitivities' terms beyond Newton's matrix (nma_sensitivity_terms.c).
 * fr_hb_nma_first_harmonic: −Y_1 F_1 (complex, X[2n]) for forces f[nq] in (R)'s real form at
 * the factored ω: the displacements' first harmonic, or its change with f a change of forces.
 * fr_hb_nma_shape_terms: per parameter k of np, from its d k_r/dp dk[np m], the mode shape's
 * derivative against M Re X_1, M Im X_1 and C φ into t[3 k ..] (−Σ_r dk_r (J_r z)(J_r φ), z the
 * bordered solves'); FRICREG_OK, FRICREG_ESINGULAR (a repeated stuck mode), FRICREG_ENOMEM
 * ((n + 1)² + 3 n² doubles). fr_hb_nma_amplitude_terms: d|X_1| of each dof into damp[np n]
 * from X1, each parameter's dy[k nd ..] (dq, dω, and ξ less its shift), ∂F/∂p df[np nq] and
 * Rayleigh a1's flag da1[np]; work: 10 n + nq doubles; FRICREG_OK or D_1's solve's status.
 * Messages recorded with fn. */
void fr_hb_nma_first_harmonic(const fricreg_hb *hb, const double *f, double *X);
int fr_hb_nma_shape_terms(fricreg_hb *hb, const char *fn, const struct fr_hb_nma *nma,
                          const double *X1, size_t np, const double *dk, double *t);
int fr_hb_nma_amplitude_terms(fricreg_hb *hb, const char *fn, double omega, const double *X1,
                              size_t np, const double *dy, size_t nd, const double *df,
                              const double *da1, double *work, double *damp);

/* The march from the linear mode to the amplitude a0 (nma.c): nma->yc the solution there. */
int fr_hb_nma_march_to(fricreg_hb *hb, const char *fn, struct fr_hb_nma *nma, double a0);

/* A backbone's job after the linear mode (the march's in nma.c, the continuation's in
 * nma_arclength.c), and the public calls' common frame around it (nma.c): the arguments'
 * checks, the state (replacing the earlier backbone), the linear mode, then body with the
 * driver set up for the mode, the call's error record kept on success. */
typedef int (*fr_hb_nma_backbone)(fricreg_hb *hb, const char *fn, struct fr_hb_nma *nma, double a0,
                                  double a1, size_t npoints);
int fr_hb_nma_run(fricreg_hb *hb, const char *fn, size_t mode, int damping, double a0, double a1,
                  size_t npoints, fr_hb_nma_backbone body);

/* The getters' shared checks of a stored backbone point (nma.c): amplitude, omega
 * and zeta not NULL (FRICREG_ENULL), i < n, the count of what (FRICREG_EINVAL "i = .., n
 * <what> stored"); messages recorded with fn. FRICREG_OK otherwise. */
int fr_hb_nma_point_args(fricreg_hb *hb, const char *fn, const double *amplitude,
                         const double *omega, const double *zeta, size_t i, size_t n,
                         const char *what);

#endif
