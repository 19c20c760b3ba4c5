/* SPDX-License-Identifier: GPL-3.0-or-later */
/* start.h — the start without a guess of fricreg_hb_solve and fricreg_hb_continue (start.c). */
#ifndef FRICREG_HB_START_H
#define FRICREG_HB_START_H

#include "hb/hb_internal.h"

/* The level start; should it fail, the plain guesses at omega; then the branch in Ω from a
 * nearby frequency where those converge. With stability on, an unstable solution is held
 * while the later routes are tried: the first stable one, else the held one. The solution kept
 * as fr_hb_solve_at's; on failure the plain guesses' error. */
int fr_hb_default_start(fricreg_hb *hb, const char *fn, double omega);

#endif
