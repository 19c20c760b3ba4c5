/* SPDX-License-Identifier: GPL-3.0-or-later */
/* law_name.c — the one table of the friction laws' names (enum fricreg_law). The CLI, the
 * Fortran layer and the benchmarks ask here instead of keeping their own copies. */
#include <string.h>

#include "law.h"

/* Indexed by enum fricreg_law; lowercase, as fricreg-sim's --law takes them. */
static const char *const law_names[] = {
    [FRICREG_LAW_COULOMB] = "coulomb", [FRICREG_LAW_FORCE_BALANCE] = "force-balance",
    [FRICREG_LAW_KARNOPP] = "karnopp", [FRICREG_LAW_VELOCITY_LIMITED] = "velocity-limited",
    [FRICREG_LAW_TANH] = "tanh",       [FRICREG_LAW_QUINN] = "quinn",
};

const char *fricreg_law_name(int law)
{
    return fr_law_known(law) ? law_names[law] : NULL;
}

int fricreg_law_from_name(const char *name)
{
    if (name == NULL)
        return 0;
    for (int law = FRICREG_LAW_COULOMB; fr_law_known(law); law++)
        if (strcmp(law_names[law], name) == 0)
            return law;
    return 0;
}
