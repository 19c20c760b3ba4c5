/* SPDX-License-Identifier: GPL-3.0-or-later */
/* floquet_internal.h — what the stability of a periodic solution (floquet/) shares inside its
 * folder and with the forced response above it: the verdict's tolerance, Hill's method's
 * workspace and entry points, LAPACK's eigenvalues. The driver's layout is hb/hb_internal.h. */
#ifndef FRICREG_FLOQUET_INTERNAL_H
#define FRICREG_FLOQUET_INTERNAL_H

#include <gsl/gsl_matrix.h>

#include "hb/hb_internal.h"

/* Re λ T above which a solution is unstable (log |μ|, Hill's and the monodromy's alike): the
 * multipliers' rounding, far below the damping of any model worth a stability verdict. */
#define FR_HB_STABLE_TOL 1e-6

struct fr_hb_hill;      /* below: Hill's matrices */
struct fr_hb_mono;      /* monodromy.c: the exact monodromy's workspace */
struct fr_hb_reduction; /* reduction.c: the condensed stability's reduced model */

/* The stability's state, hung on the driver as hb->stability while stability is on
 * (stability_method.c, fricreg_hb_set_stability) with its release: the workspace of each
 * method, made at the first solution that needs it (the method in force's at
 * fricreg_hb_set_stability), and the records [XW] of the last solution and of a trial point
 * (the bifurcations' bisection), their stability from x[2] on (fr_hb_stability_record). */
struct fr_hb_stability {
    struct fr_hb_hill *hill;           /* Hill's matrices, NULL: none yet */
    struct fr_hb_mono *mono;           /* grown at the first solution that needs more */
    struct fr_hb_reduction *reduction; /* the condensed method's, built for model_serial */
    double *xsol;                      /* [XW] the last solution's */
    double *trial;                     /* [XW] a trial point's */
};

/* Hill's method's workspace (hill.c): N = n nc Fourier coefficients of x; the companion matrix
 * A of the quadratic eigenproblem [2N 2N], its eigenvalues eval [2N] complex, LAPACK's
 * workspace work [lwork + 4N]; M's LU mlu [n n] with pivots piv [n], a column col [n]. */
struct fr_hb_hill {
    gsl_matrix *A;
    double *eval;
    double *work;
    size_t lwork;
    double *mlu, *col;
    int *piv;
};

/* Hill's method at the solution whose element Jacobians jq are in hb (the last residual's, with
 * jac) at omega: into out[2n + 2] stable (1.0/0.0), the largest |Floquet multiplier| and the 2n
 * exponents (re, im); its matrices made at the first call. FRICREG_OK, FRICREG_EINVAL (ndof
 * (2H + 1) > FRICREG_HB_MAX_HILL), FRICREG_ENOMEM, FRICREG_ESINGULAR (M), FRICREG_ENONFINITE,
 * FRICREG_EINTEGRATOR (LAPACK's QR), messages recorded with fn. */
int fr_hb_hill(fricreg_hb *hb, const char *fn, double omega, double *out);

/* Whether some exponent of exps[4n] (re, im) at omega of kind which (0 real, 1 at ±Ω/2, 2
 * complex; −1 any) is unstable; the kind of the exponent of largest real part. */
int fr_hb_hill_unstable(const fricreg_hb *hb, double omega, const double *exps, int which);
int fr_hb_hill_crossing(const fricreg_hb *hb, double omega, const double *exps);

/* Hill's matrices made (if not yet): FRICREG_OK or FRICREG_ENOMEM (message recorded, with fn;
 * nothing allocated then); freed (a second call does nothing). */
int fr_hb_hill_reserve(fricreg_hb *hb, const char *fn);
void fr_hb_hill_free(fricreg_hb *hb);

/* The eigenvalues of a dense real matrix (eigenvalues.c, LAPACK's dgeev): A[n n] row-major,
 * destroyed; the real and imaginary parts into wr[n] and wi[n] (a complex pair together, the
 * positive imaginary part first); work[lwork] with lwork = fr_hb_eigenvalues_work(n) (at least
 * 3n, LAPACK's optimum where it says). Returns dgeev's INFO: 0, or > 0 when the QR iteration
 * did not converge (wr, wi then hold only the eigenvalues from INFO on); n < 2^31. */
size_t fr_hb_eigenvalues_work(size_t n);
int fr_hb_eigenvalues(double *A, size_t n, double *wr, double *wi, double *work, size_t lwork);

#endif
