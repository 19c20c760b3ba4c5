/* SPDX-License-Identifier: GPL-3.0-or-later */
/* base.h — fricreg.h's version, status codes and matrix storage, in the syntax of cffi's
 * cdef (no macros, no includes; python/build_ffi.py). Every other file may use them. */
enum fricreg_status {
    FRICREG_OK = 0,
    FRICREG_ENULL = 1,
    FRICREG_EINVAL = 2,
    FRICREG_ENONFINITE = 3,
    FRICREG_ESIZE = 4,
    FRICREG_ENOMEM = 5,
    FRICREG_ENOTSYM = 6,
    FRICREG_ENOTPSD = 7,
    FRICREG_ESINGULAR = 8,
    FRICREG_ESTEP = 9,
    FRICREG_EDIVERGED = 10,
    FRICREG_EINTEGRATOR = 11,
    FRICREG_EWORK = 12
};
const char *fricreg_version(void);
const char *fricreg_strerror(int status);

/* fricreg.h: matrices in any storage (the contexts', drivers' and structures' setters) */
enum fricreg_sparse_flags {
    FRICREG_SPARSE_ZERO_BASED = 0,
    FRICREG_SPARSE_ONE_BASED = 1,
    FRICREG_SPARSE_UPPER = 2,
    FRICREG_SPARSE_LOWER = 4
};
enum fricreg_matrix_format {
    FRICREG_MATRIX_DENSE = 0,
    FRICREG_MATRIX_CSR = 8,
    FRICREG_MATRIX_CSC = 16
};
enum fricreg_model_matrix {
    FRICREG_MASS = 1,
    FRICREG_STIFFNESS = 2,
    FRICREG_DAMPING = 3,
    FRICREG_CONTACTS = 4
};
