/* SPDX-License-Identifier: GPL-3.0-or-later */
/* mex_hb.h — the gateway's commands on a harmonic-balance driver (fricreg_hb.h), held in the
 * handle table (mex_handles.h) with the sizes the commands need beside it (mex_hb.c: the model,
 * its elements, the settings; mex_hb_results.c: the solves and what they return;
 * mex_hb_estimates.c: a solved point's truncation error and sensitivities). Each command
 * takes the arguments after the command string; the .m files (fricreg_harmonic_balance.m,
 * fricreg_hb_*.m, fricreg_nlvib_frf.m) put them together. */
#ifndef FRICREG_MEX_HB_H
#define FRICREG_MEX_HB_H

#include <stddef.h>

#include "mex.h"
#include "mex_fit.h" /* mex_command */
#include "fricreg_hb.h"

/** What the table holds for a driver: the driver and its sizes. */
typedef struct {
    fricreg_hb *hb;
    size_t ndof, m; /* fricreg_hb_create's */
    size_t rows;    /* the rows of J the elements set so far hold: q has rows (2H + 1) numbers */
    int harmonics;
    int stability; /* fricreg_hb_set_stability's last enable */
} mexhb;

/** The driver of the handle in a (fricreg:handle if it is none). */
mexhb *mexhb_of(const mxArray *a, const char *cmd);

/** Raise fricreg:<NAME> with the driver's message where status is not FRICREG_OK. */
void mexhb_check(const mexhb *d, int status, const char *cmd);

/** Free a driver and its record (the handle table's free function for MEXH_HB). */
void mexhb_free(void *object);

mex_command mexhb_create, mexhb_set_matrix, mexhb_set_rayleigh, mexhb_set_jenkins,
    mexhb_add_elements, mexhb_set_excitation, mexhb_set_newton, mexhb_set_newton_solver,
    mexhb_set_receptance, mexhb_set_continuation, mexhb_set_stability, mexhb_set_max_iterations,
    mexhb_set_element_param, mexhb_get_element_param, mexhb_info, mexhb_solve, mexhb_continue,
    mexhb_continue_level, mexhb_nma, mexhb_peak, mexhb_truncation_error, mexhb_nma_sensitivities,
    mexhb_modal_participation;

#endif
