/* SPDX-License-Identifier: GPL-3.0-or-later */
/**
 * \file
 * fricreg_structure_gsl.h — sparse model matrices for a fricreg_structure, as GSL's
 * gsl_spmatrix (the format GSL reads Matrix Market files into, gsl_spmatrix_fscanf).
 *
 * Unlike every other fricreg header, this one exposes a GSL type: a caller must build against
 * the same GSL as the library (its gsl_spmatrix layout is GSL's, and GSL changes its SONAME
 * between releases), and it is not part of the Fortran interface. The functions copy the
 * matrices into the structure's sparse storage (never dense), from any of GSL's storage
 * formats (COO, CSC, CSR); duplicate entries are summed. Entries not stored are zero. The
 * _csr and _csc setters of fricreg_structure.h take the same matrices without GSL. Everything else is fricreg_structure.h: units, validation,
 * messages (named after these functions), and that a failed call changes nothing.
 */
#ifndef FRICREG_STRUCTURE_GSL_H
#define FRICREG_STRUCTURE_GSL_H

#include <gsl/gsl_spmatrix.h>

#include "fricreg_structure.h"

#ifdef __cplusplus
extern "C" {
#endif

/** \addtogroup structure
 *  \{ */

/** Set the mass matrix from a sparse ndof x ndof M (mass units), symmetric (relative
 *  tolerance 1e-12) and positive definite, all of it stored (not one triangle: mirror a
 *  symmetric Matrix Market file first), as fricreg_structure_set_mass.
 *  Returns FRICREG_OK; FRICREG_ENULL if s or M is NULL; FRICREG_ESIZE if M is not
 *  ndof x ndof; FRICREG_EINVAL for a storage type GSL does not have; FRICREG_ENONFINITE;
 *  FRICREG_ENOTSYM; FRICREG_ENOTPSD; FRICREG_ENOMEM. */
FRICREG_API int fricreg_structure_set_mass_sparse(fricreg_structure *s, const gsl_spmatrix *M);

/** Set the stiffness matrix from a sparse ndof x ndof K (force per length), symmetric, as
 *  fricreg_structure_set_stiffness.
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_ESIZE; FRICREG_EINVAL (storage type);
 *  FRICREG_ENONFINITE; FRICREG_ENOTSYM; FRICREG_ENOMEM. */
FRICREG_API int fricreg_structure_set_stiffness_sparse(fricreg_structure *s, const gsl_spmatrix *K);

/** Set the damping matrix from a sparse ndof x ndof C (force per velocity), symmetric, as
 *  fricreg_structure_set_damping (it replaces Rayleigh damping).
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_ESIZE; FRICREG_EINVAL (storage type);
 *  FRICREG_ENONFINITE; FRICREG_ENOTSYM; FRICREG_ENOMEM. */
FRICREG_API int fricreg_structure_set_damping_sparse(fricreg_structure *s, const gsl_spmatrix *C);

/** Set the contact matrix from a sparse m x ndof J, J(i, k) = d zdot_i / d u'_k, as
 *  fricreg_structure_set_contacts (each row non-zero).
 *  Returns FRICREG_OK; FRICREG_ENULL; FRICREG_ESIZE if J is not m x ndof;
 *  FRICREG_ENONFINITE; FRICREG_EINVAL if a row is zero or for a storage type GSL does not
 *  have; FRICREG_ENOMEM. */
FRICREG_API int fricreg_structure_set_contacts_sparse(fricreg_structure *s, const gsl_spmatrix *J);

/** \} */

#ifdef __cplusplus
}
#endif

#endif /* FRICREG_STRUCTURE_GSL_H */
