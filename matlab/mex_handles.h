/* SPDX-License-Identifier: GPL-3.0-or-later */
/* mex_handles.h — the gateway's table of library objects (matlab/fricreg_mex.c).
 *
 * MATLAB and Octave hold an object by an integer handle (a double scalar), never a pointer.
 * A handle is never reused within a load of the MEX file, and each load numbers its handles
 * from a base of its own (the clock and its address mixed: mex_handles.c), so a handle kept
 * across `clear fricreg_mex` is unknown, not another object: an unknown or freed handle raises
 * fricreg:handle, and never touches memory. Every object is freed by the command free or, at the
 * latest, by mexh_free_all, which the gateway registers with mexAtExit (the MEX file cleared,
 * MATLAB or Octave leaving). The table itself is malloc'd (it lives across calls). */
#ifndef FRICREG_MEX_HANDLES_H
#define FRICREG_MEX_HANDLES_H

#include <stddef.h>

#include "mex.h"

/** The kinds of objects the table holds. */
enum mexh_kind {
    MEXH_FIT = 1,      /**< a fricreg_fit (fricreg_fit.h) */
    MEXH_HB = 2,       /**< a harmonic-balance driver with its sizes (mex_hb.h) */
    MEXH_STRUCTURE = 3 /**< a structure stepped in time with its sizes (mex_structure.h) */
};

/** Add an object of a kind; returns its new handle. On failure (memory) the object is freed
 *  and fricreg:ENOMEM raised. */
double mexh_add(int kind, void *object);

/** The object of the handle in a (a real double scalar) of that kind; raises fricreg:handle
 *  for an unknown handle or one of another kind. aux, if not NULL, receives the entry's
 *  number the gateway keeps beside it (a fit's level count). */
void *mexh_get(const mxArray *a, int kind, const char *cmd, size_t **aux);

/** Free the handle's object and forget the handle (fricreg:handle if unknown). */
void mexh_free(const mxArray *a, const char *cmd);

/** Free every object and the table (the mexAtExit function; also the command free_all). */
void mexh_free_all(void);

/** The number of live objects. */
size_t mexh_count(void);

#endif
