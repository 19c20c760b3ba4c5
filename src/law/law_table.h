/* SPDX-License-Identifier: GPL-3.0-or-later */
/* law_table.h — internal: the one table of the friction laws (law_table.c), a row per law with
 * what the code that is not the law's kernel asks of it. */
#ifndef FRICREG_LAW_TABLE_H
#define FRICREG_LAW_TABLE_H

#include "fricreg.h"

/* The laws are enum fricreg_law's 1 .. FR_LAW_COUNT. */
enum { FR_LAW_COUNT = FRICREG_LAW_QUINN };

/* What the code that is not a law's kernel asks of a law (law_table.c), one row per law. */
struct fr_law_row {
    const char *name;     /* lowercase, as fricreg-sim's --law takes it */
    int reads_feq;        /* reads f_eq for some v: the partition's stick set S (Sec. 3.3) */
    int jumps;            /* the force jumps (by 2 mun at zdot = 0, or at Karnopp's band edge):
                           * a fixed step's guard then takes the chord as the law's stiffness */
    double slope_at_rest; /* -df/dv at v = 0 in units of mun/eps: the step guard's stiffness */
    unsigned kinks;       /* enum fr_law_kinks: where the law is not smooth (switching.c) */
    double feq_half_band; /* the half-width, in units of eps, of the band where it reads f_eq
                           * (FR_KINK_FEQ_BAND laws): f_eq saturates at +-mun on its segments */
};

/* The kinds of kink of a law in the (v, f_eq) plane (fricreg_ctx_switching's components). */
enum fr_law_kinks {
    FR_KINK_BAND = 1,    /* the band's edges |v| = eps */
    FR_KINK_REST = 2,    /* rest, v = 0 */
    FR_KINK_ZONE = 4,    /* the edges of law (4)'s linear zone, v - xi = +-eps/2 */
    FR_KINK_FEQ_BAND = 8 /* f_eq = +-mun inside a band where the law reads f_eq */
};
extern const struct fr_law_row fr_law_table[FR_LAW_COUNT + 1];

/* Whether law is one of enum fricreg_law's (a row of the table). */
static inline int fr_law_known(int law)
{
    return law >= FRICREG_LAW_COULOMB && law <= FR_LAW_COUNT;
}

#endif
