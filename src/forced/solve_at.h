/* SPDX-License-Identifier: GPL-3.0-or-later */
/* solve_at.h — one forced response at one frequency (solve_at.c). */
#ifndef FRICREG_FORCED_SOLVE_AT_H
#define FRICREG_FORCED_SOLVE_AT_H

#include "hb/hb_internal.h"

/* The checks of omega, nq and q0 that fricreg_hb_solve and fricreg_hb_continue share. */
int fr_hb_check_start(fricreg_hb *hb, const char *fn, const char *name, double omega, size_t nq,
                      const double *q0);

/* Factors at omega and solves (R) from q0, or from the stuck guess and then the slipping one:
 * the solution in qw (R, fq, jq at it), with keep its stability computed (when on) and kept as
 * the driver's last solution (at the level in force). */
int fr_hb_solve_at(fricreg_hb *hb, const char *fn, double omega, const double *q0, int keep);

#endif
