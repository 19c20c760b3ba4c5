/* SPDX-License-Identifier: GPL-3.0-or-later */
/* mex_structure.h — the gateway's commands on a structure stepped in time (fricreg_structure.h),
 * held in the handle table (mex_handles.h) with the sizes the commands need beside it
 * (mex_structure.c: the model, contacts, excitation, elements and settings;
 * mex_structure_run.c: a run, its time series and results, its accuracy warnings). Each
 * command takes the arguments after the command string; fricreg_structure.m and
 * fricreg_structure_*.m put them together. */
#ifndef FRICREG_MEX_STRUCTURE_H
#define FRICREG_MEX_STRUCTURE_H

#include <stddef.h>

#include "mex.h"
#include "mex_fit.h" /* mex_command */
#include "fricreg_structure.h"

/** The most element sets one structure's record keeps sizes of (the results' element_forces). */
#define MEXST_MAX_SETS 64

/** What the table holds for a structure: the structure and its sizes. */
typedef struct {
    fricreg_structure *s;
    size_t ndof;
    size_t m;     /* the contacts shown: 0 where the library holds one of bound 0 */
    size_t nsets; /* element sets added, and each one's count and dimension */
    size_t set_me[MEXST_MAX_SETS], set_dim[MEXST_MAX_SETS];
    unsigned long warned; /* the warning codes raised as fricreg:accuracy since the last reset */
    int scheme;           /* the integrator in force: 0 newmark (the default), 1 hht, 2 central */
    double alpha;         /* HHT's alpha in force */
} mexst;

/** The structure of the handle in a (fricreg:handle if it is none). */
mexst *mexst_of(const mxArray *a, const char *cmd);

/** Raise fricreg:<NAME> with the structure's message where status is not FRICREG_OK. */
void mexst_check(const mexst *d, int status, const char *cmd);

/** Free a structure and its record (the handle table's free function for MEXH_STRUCTURE). */
void mexst_free(void *object);

mex_command mexst_create, mexst_set_matrix, mexst_set_rayleigh, mexst_set_bounds, mexst_set_law,
    mexst_set_influence, mexst_set_ground_accel, mexst_set_load, mexst_add_elements,
    mexst_set_initial, mexst_set_newton, mexst_set_error_estimate, mexst_run;

#endif
