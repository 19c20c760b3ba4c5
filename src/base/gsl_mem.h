/* SPDX-License-Identifier: GPL-3.0-or-later */
/* gsl_mem.h — GSL objects on memory fricreg allocates, so that running out of memory is
 * reported as FRICREG_ENOMEM instead of through GSL's process-wide error handler (whose
 * default aborts). Each object is one block: release it with free() (or fr_gsl_free), never
 * with GSL's _free functions. */
#ifndef FRICREG_GSL_MEM_H
#define FRICREG_GSL_MEM_H

#include <stddef.h>

#include <gsl/gsl_eigen.h>
#include <gsl/gsl_matrix.h>
#include <gsl/gsl_permutation.h>
#include <gsl/gsl_roots.h>
#include <gsl/gsl_vector.h>

/* A zeroed n1 x n2 matrix, or NULL. */
gsl_matrix *fr_gsl_matrix_new(size_t n1, size_t n2);

/* A zeroed vector of n, or NULL. */
gsl_vector *fr_gsl_vector_new(size_t n);

/* The identity permutation of n, or NULL. */
gsl_permutation *fr_gsl_permutation_new(size_t n);

/* Brent's bracketing root solver (gsl_root_fsolver_brent), or NULL. */
gsl_root_fsolver *fr_gsl_brent_new(void);

#endif
