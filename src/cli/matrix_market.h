/* SPDX-License-Identifier: GPL-3.0-or-later */
/* matrix_market.h — a Matrix Market file read as compressed sparse columns
 * (matrix_market.c), in one pass and O(entries + columns) memory, for the library's _csc
 * setters. */
#ifndef FRICREG_CLI_MATRIX_MARKET_H
#define FRICREG_CLI_MATRIX_MARKET_H

#include <stddef.h>
#include <stdint.h>

/* The most rows or columns a file may declare: its column pointers then take 0.8 GB, before a
 * structure of that size takes far more. */
#define CLI_MTX_MAX_DIM 100000000L

/* A rows x cols matrix in compressed sparse columns, zero-based (fricreg.h's enum
 * fricreg_sparse_flags): column j's entries are rowind[colptr[j] .. colptr[j+1] - 1], rows
 * ascending, each once, none zero. lower: symmetric storage, which holds the lower triangle
 * only (pass FRICREG_SPARSE_LOWER). */
struct cli_sparse {
    size_t rows, cols;
    int lower;
    int64_t *colptr; /* [cols + 1] */
    int64_t *rowind; /* [colptr[cols]] */
    double *values;  /* [colptr[cols]] */
    long size_line;  /* the file's line that gave rows and cols */
};

/* The file whose size line set the size a later file must have (the mass matrix, whose size
 * line sets n): its option, path and matrix. */
struct cli_mtx_size {
    const char *option, *path;
    const struct cli_sparse *A;
};

/* Reads "%%MatrixMarket matrix coordinate real|integer general|symmetric" from path into *A:
 * the size line "rows columns entries" (1 to CLI_MTX_MAX_DIM rows and
 * columns; a matrix not rows x cols is refused there, 0 meaning any), then exactly that many
 * entries "row column value", 1-based and in range, finite, each at most once, and on or
 * below the diagonal in symmetric storage. Comment and blank lines anywhere, CRLF line ends.
 * Entries of value 0 are left out, as the library's dense setters leave them out. A bad file
 * is one line on stderr naming option, path and the first bad line (or the entry or the
 * count), and CLI_EXIT_USAGE with *A unchanged; else 0, and *A is the caller's to free with
 * cli_sparse_free. */
int cli_read_mtx(const char *option, const char *path, size_t rows, size_t cols,
                 struct cli_sparse *A);

/* cli_read_mtx, with rows and cols (those of 0 excepted) taken from the n x n matrix of
 * from->path (NULL: as cli_read_mtx). A size line that differs from n is that file's fault, as
 * cli_read_mtx reports it, unless each differing size is the extent of from's entries (the
 * largest row or column of a nonzero entry) and that extent is below n: then from's own size
 * line declared more than its entries hold, and the line reported is that one, in from's
 * file. */
int cli_read_mtx_sized(const char *option, const char *path, size_t rows, size_t cols,
                       const struct cli_mtx_size *from, struct cli_sparse *A);

/* Frees A's arrays and zeroes it; a zeroed A is left as it is. */
void cli_sparse_free(struct cli_sparse *A);

#endif
