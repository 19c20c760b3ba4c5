/* SPDX-License-Identifier: GPL-3.0-or-later */
/* mex_args.h — the gateway's argument checks and errors (matlab/fricreg_mex.c).
 *
 * Every check raises a MATLAB error through mexErrMsgIdAndTxt, which does not return: the
 * gateway's temporaries are mxMalloc'd (freed by MATLAB and Octave when the call ends, on an
 * error too), and a library object made during a call is freed before any error is raised.
 *
 * Identifiers: the gateway's own checks raise fricreg:nargs (argument count), fricreg:type (not
 * a real, full double; not a string), fricreg:size (shapes), fricreg:command (unknown command),
 * fricreg:handle (unknown or freed handle); a nonzero fricreg status raises fricreg:<NAME>,
 * NAME the status's enum name without FRICREG_ (fricreg:EINVAL, fricreg:ESINGULAR, ...). */
#ifndef FRICREG_MEX_ARGS_H
#define FRICREG_MEX_ARGS_H

#include <stddef.h>

#include "mex.h"

/** Raise error(id, message), the message formatted as printf's (cut at 1023 characters). */
void mexa_error(const char *id, const char *fmt, ...);

/** The enum name of a status without FRICREG_ ("EINVAL"); "E<n>" for a code this gateway
 *  does not know (a newer library). buf[len] holds the latter. */
const char *mexa_status_name(int status, char *buf, size_t len);

/** Raise the error of a nonzero status: identifier fricreg:<NAME>, message
 *  "where: detail (FRICREG_<NAME>)", or "where: <fricreg_strerror's text> (FRICREG_<NAME>)"
 *  where detail is NULL or empty. */
void mexa_status(int status, const char *where, const char *detail);

/** Append text to the NUL-terminated buf[len], cut where it does not fit (a list of names in a
 *  message). */
void mexa_append(char *buf, size_t len, const char *text);

/** Check the counts of a command's arguments (after the command string) and outputs. */
void mexa_nargs(const char *cmd, int nrhs, int min_rhs, int max_rhs, int nlhs, int max_lhs);

/** Check that a is a real, full (not sparse), non-complex double array: fricreg:type. */
void mexa_real(const mxArray *a, const char *cmd, const char *name);

/** A real double scalar (any value, NaN and Inf too: the library judges them). */
double mexa_scalar(const mxArray *a, const char *cmd, const char *name);

/** A real double scalar holding a whole number in lo..hi (a count, a code). */
size_t mexa_count(const mxArray *a, const char *cmd, const char *name, size_t lo, size_t hi);

/** A real double vector (1 x n, n x 1, or empty when n may be 0) of n elements; n = (size_t)-1
 *  takes any length, returned in *len when len is not NULL. Returns its data (column-major
 *  storage is the vector's order: no copy), or NULL for an empty one. */
const double *mexa_vector(const mxArray *a, const char *cmd, const char *name, size_t n,
                          size_t *len);

/** A character row vector, copied into buf[len] (fricreg:type if not a string, fricreg:size
 *  if it does not fit). */
void mexa_string(const mxArray *a, const char *cmd, const char *name, char *buf, size_t len);

/** A string naming one of names[count]: its index; fricreg:EINVAL naming the list otherwise. */
int mexa_pick(const mxArray *a, const char *cmd, const char *what, const char *const names[],
              int count);

/** Whether a is a 2-D array of rows x cols. */
int mexa_is_size(const mxArray *a, size_t rows, size_t cols);

/** Whether a is a vector (1 x n or n x 1, n >= 1), 2-D. */
int mexa_is_vector(const mxArray *a);

/** A new real double array of rows x cols, zeros. */
mxArray *mexa_matrix(size_t rows, size_t cols);

/** A new real double array of n1 x n2 x n3, zeros (MATLAB drops trailing singleton sizes). */
mxArray *mexa_array3(size_t n1, size_t n2, size_t n3);

/** Hand out[0 .. n-1] to the caller: those it asked for (nlhs, at least one: MATLAB's ans)
 *  into plhs, the others destroyed. plhs has room for max(nlhs, 1) arrays only. */
void mexa_outputs(int nlhs, mxArray *plhs[], mxArray *out[], int n);

/** mxMalloc'd scratch of n doubles (at least one), freed when the call ends. */
double *mexa_scratch(size_t n);

/** Column-major rows x cols (MATLAB's storage) into row-major (C's, point after point):
 *  dst[cols i + c] = src[i + rows c]. The boundary copy of a table of points. */
void mexa_to_rows(const double *src, double *dst, size_t rows, size_t cols);

/** Row-major rows x cols into column-major: dst[i + rows c] = src[cols i + c]. */
void mexa_to_cols(const double *src, double *dst, size_t rows, size_t cols);

#endif
