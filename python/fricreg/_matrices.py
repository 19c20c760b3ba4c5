# SPDX-License-Identifier: GPL-3.0-or-later
"""Model matrices handed to the C library's one matrix setter (``fricreg_hb_set_matrix``,
``fricreg_structure_set_matrix``: ``which, nrows, ncols, format, ptr, ind, values``): a dense
numpy array as row-major values, a scipy.sparse matrix as compressed sparse rows or columns
with 64-bit indices. scipy itself is never imported: a sparse matrix is known by its methods.
"""
import numpy as np

from ._fricreg import ffi, lib
from ._arrays import as_doubles, pointer

__all__ = []


def is_sparse(matrix):
    """Whether matrix is a scipy.sparse matrix or array (without importing scipy)."""
    return hasattr(matrix, "tocsr") and hasattr(matrix, "nnz")


class MatrixArgs:
    """A matrix as the setter's arguments (format, ptr, ind, values, shape), holding the arrays
    the pointers point into: a sparse matrix in CSR or CSC as it is (``form``, "csr" or "csc",
    converts it to that one), any other sparse format as CSR; a dense one row-major."""

    def __init__(self, matrix, name, form=None):
        if is_sparse(matrix):
            form = form or (matrix.format if matrix.format in ("csr", "csc") else "csr")
            compressed = matrix.asformat(form)
            self.matrix = compressed
            self.shape = compressed.shape
            self.format = lib.FRICREG_MATRIX_CSR if form == "csr" else lib.FRICREG_MATRIX_CSC
            self._ptr = np.ascontiguousarray(compressed.indptr, dtype=np.int64)
            self._ind = np.ascontiguousarray(compressed.indices, dtype=np.int64)
            self._values = as_doubles(compressed.data, name)
            self.ptr = ffi.from_buffer("int64_t[]", self._ptr)
            self.ind = ffi.from_buffer("int64_t[]", self._ind) if self._ind.size else ffi.NULL
            self.values = pointer(self._values) if self._values.size else ffi.NULL
        else:
            self._values = as_doubles(matrix, name, ndim=2)
            self.matrix = self._values
            self.shape = self._values.shape
            self.format = lib.FRICREG_MATRIX_DENSE
            self.ptr = self.ind = ffi.NULL
            self.values = pointer(self._values)
