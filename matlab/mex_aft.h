/* SPDX-License-Identifier: GPL-3.0-or-later */
/* mex_aft.h — the gateway's command aft (mex_aft.c): the AFT of one element, fricreg_aft.h,
 * its workspace kept between calls of one H and N (mex_aft.c). */
#ifndef FRICREG_MEX_AFT_H
#define FRICREG_MEX_AFT_H

#include "mex.h"
#include "mex_fit.h" /* mex_command */

mex_command mexaft_eval;

/** Free the workspace kept between calls (at exit, with the handle table's objects; also the
 *  command free_all). */
void mexaft_release(void);

#endif
