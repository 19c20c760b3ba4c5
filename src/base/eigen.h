/* SPDX-License-Identifier: GPL-3.0-or-later */
/* eigen.h — internal: eigenvalues of a small symmetric matrix by GSL, on fricreg's memory.
 *
 * GSL's own allocators are avoided here on purpose: gsl_matrix_alloc and gsl_eigen_symm_alloc
 * report a failed malloc through GSL's error handler (which aborts by default), and
 * gsl_eigen_symm_alloc leaks its workspace when its second or third malloc fails (GSL 2.7).
 * The matrix, the eigenvalues and GSL's workspace (whose layout gsl_eigen.h publishes) are
 * allocated here, all or nothing. */
#ifndef FRICREG_EIGEN_H
#define FRICREG_EIGEN_H

#include <stddef.h>

#include <gsl/gsl_eigen.h>
#include <gsl/gsl_matrix.h>
#include <gsl/gsl_vector.h>

struct fr_eigen {
    size_t m;
    double *a;    /* [m*m] row-major: the caller fills it; fr_eigen_solve destroys it */
    double *eval; /* [m] the eigenvalues after fr_eigen_solve, unordered */
    double *d;    /* [m] GSL's workspace: diagonal */
    double *sd;   /* [m] GSL's workspace: subdiagonal */
};

/* Allocates for an m x m matrix (m >= 1, m*m not overflowing): FRICREG_OK, or FRICREG_ENOMEM
 * with nothing held. fr_eigen_free releases it and is safe on a zeroed or freed struct. */
int fr_eigen_alloc(struct fr_eigen *e, size_t m);
void fr_eigen_free(struct fr_eigen *e);

/* The eigenvalues of the symmetric matrix in e->a (its lower triangle is read) into e->eval,
 * by GSL's gsl_eigen_symm with GSL's error handler kept out. Returns GSL's status: nonzero
 * only for sizes that do not match, which fr_eigen_alloc rules out. */
int fr_eigen_solve(struct fr_eigen *e);

/* The same on a caller's GSL objects (A square, eval and work of its order; A destroyed):
 * gsl_eigen_symm on A scaled by a power of two to a largest entry in [0.5, 1), entries below
 * DBL_EPSILON^2 of it dropped (eigen.c: GSL's iteration has no cap and can loop among
 * subnormals, or forever on an Inf or NaN). GSL_EDOM, with every eigenvalue NaN, if an entry is
 * NaN or infinite; otherwise GSL's status. */
int fr_eigen_symm(gsl_matrix *A, gsl_vector *eval, gsl_eigen_symm_workspace *work);

/* The same with the eigenvectors (gsl_eigen_symmv: the columns of evec, orthonormal), the
 * eigenvalues in ascending order with them (gsl_eigen_symmv_sort). */
int fr_eigen_symmv(gsl_matrix *A, gsl_vector *eval, gsl_matrix *evec,
                   gsl_eigen_symmv_workspace *work);

#endif
