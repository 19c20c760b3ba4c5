/* SPDX-License-Identifier: GPL-3.0-or-later */
/* exact_internal.h — the exact solution's layout (fricreg_exact.h): the oscillator as given,
 * the phases of the solution held and its counts. exact.c creates and runs it, phases.c finds
 * its phases, results.c reads them. Included only inside src/exact/. */
#ifndef FRICREG_EXACT_INTERNAL_H
#define FRICREG_EXACT_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include <gsl/gsl_roots.h>

#include "base/error.h"
#include "fricreg_exact.h"

#define FR_EXACT_STATS 3 /* enum fricreg_exact_stat */

struct fr_phase {
    double t0, x0, v0;
    int s; /* 0: stick; +1 or -1: slip in that direction */
};

struct fricreg_exact {
    double a, omega, mun, x0, v0; /* as given to fricreg_exact_create */
    double t_end;                 /* end of the solution held; 0 before the first run */
    struct fr_phase *ph;          /* its phases; ph[0] starts at t = 0 */
    size_t n, cap;
    int64_t stats[FR_EXACT_STATS]; /* enum fricreg_exact_stat, of the solution held */
    gsl_root_fsolver *brent;       /* allocated at create: a run allocates only phases */
    struct fr_error err;
};

#endif
