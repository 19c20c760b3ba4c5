/* SPDX-License-Identifier: GPL-3.0-or-later */
/* sparse_factor.h — internal: CHOLMOD (SuiteSparse), the library's sparse Cholesky, set up as
 * fricreg needs it in every object that holds a cholmod_common: nothing printed (CHOLMOD's
 * default prints its errors and warnings), no error handler called (its failures come back as
 * Common->status), the fill-reducing ordering CHOLMOD chooses. The process-wide
 * SuiteSparse_config (its malloc and printf) is left as the program set it. fricreg uses
 * CHOLMOD's 64-bit-index interface (cholmod_l_*): a factor of 10^6 unknowns can hold more than
 * 2^31 entries. Factors are L L^T (final_ll), so that the factorization itself tells whether
 * a matrix is positive definite. */
#ifndef FRICREG_SPARSE_FACTOR_H
#define FRICREG_SPARSE_FACTOR_H

#include <cholmod.h>

/* cholmod_l_start with fricreg's settings: FRICREG_OK, or FRICREG_ENOMEM if CHOLMOD could not
 * start (it then holds nothing). */
int fr_cholmod_start(cholmod_common *c);

/* cholmod_l_finish; safe on a workspace that did not start (zeroed). */
void fr_cholmod_finish(cholmod_common *c);

/* The fricreg status of a CHOLMOD status: FRICREG_OK for CHOLMOD_OK and its warnings but
 * CHOLMOD_NOT_POSDEF (FRICREG_ENOTPSD), FRICREG_ENOMEM for CHOLMOD_OUT_OF_MEMORY and
 * CHOLMOD_TOO_LARGE, FRICREG_EINVAL for the rest (a misuse that fricreg's checks rule out). */
int fr_cholmod_status(int cholmod_status);

/* The settings of the next cholmod_l_analyze: exactly one ordering (CHOLMOD_AMD,
 * CHOLMOD_NESDIS, or CHOLMOD_NATURAL, which is then not postordered), so that an allocation
 * failing inside it fails the analysis (CHOLMOD's default tries several and silently keeps
 * another when one runs out of memory: the factor would depend on where memory ran out);
 * simplicial asks for a simplicial factor, else CHOLMOD chooses. */
void fr_cholmod_ordering(cholmod_common *c, int ordering, int simplicial);

/* cholmod_l_solve2 with a simplicial factor and one right-hand side: its workspace Y is sized
 * 4 x n (four right-hand sides at a time, real factors), and the solve sets Y->nrow to the one
 * it used, so that the next call's size check fails and reallocates it, every call. Its
 * storage is unchanged: the shape is put back first (tests/alloc: steps do not allocate). */
void fr_cholmod_keep_workspace(cholmod_dense *Y);

#endif
