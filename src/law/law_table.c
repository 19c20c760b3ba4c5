/* SPDX-License-Identifier: GPL-3.0-or-later */
/* law_table.c — the one table of the friction laws (enum fricreg_law): a row per law with what
 * the code that is not the law's kernel asks of it. The CLI, the Fortran constants, the
 * benchmarks, the step guard and the partition read it here instead of keeping copies. */
#include <string.h>

#include "law_table.h"

/* Indexed by enum fricreg_law; row 0 is no law. */
const struct fr_law_row fr_law_table[] = {
    /* name, reads f_eq, jumps, slope at rest x eps / mun, kinks, f_eq's half band / eps */
    [FRICREG_LAW_COULOMB] = {"coulomb", 0, 1, 0.0, FR_KINK_REST, 0.0}, /* (1) */
    /* (2): f_eq at v = 0 only */
    [FRICREG_LAW_FORCE_BALANCE] = {"force-balance", 1, 1, 0.0, FR_KINK_REST, 0.0},
    /* Karnopp: f_eq in |v| < eps, a jump at the band's edge */
    [FRICREG_LAW_KARNOPP] = {"karnopp", 1, 1, 0.0, FR_KINK_BAND | FR_KINK_FEQ_BAND, 1.0},
    /* (3): slope mun/eps in the band */
    [FRICREG_LAW_VELOCITY_LIMITED] = {"velocity-limited", 0, 0, 1.0, FR_KINK_BAND, 0.0},
    [FRICREG_LAW_TANH] = {"tanh", 0, 0, 1.0, 0, 0.0}, /* tanh'(0) = 1: mun/eps; smooth */
    /* (4): slope 2 mun/eps at rest (4a), f_eq read in its zone of half-width eps/2 */
    [FRICREG_LAW_QUINN] = {"quinn", 1, 0, 2.0, FR_KINK_ZONE | FR_KINK_FEQ_BAND, 0.5},
};
/* A row for every law (C99 has no static_assert): a law added to the enum and FR_LAW_COUNT
 * without its row, or a row without them, does not compile. */
typedef char fr_law_table_has_a_row_per_law
    [sizeof fr_law_table / sizeof fr_law_table[0] == FR_LAW_COUNT + 1 ? 1 : -1];

const char *fricreg_law_name(int law)
{
    return fr_law_known(law) ? fr_law_table[law].name : NULL;
}

int fricreg_law_from_name(const char *name)
{
    if (name == NULL)
        return 0;
    for (int law = FRICREG_LAW_COULOMB; fr_law_known(law); law++)
        if (strcmp(fr_law_table[law].name, name) == 0)
            return law;
    return 0;
}
