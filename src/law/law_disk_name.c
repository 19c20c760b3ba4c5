/* SPDX-License-Identifier: GPL-3.0-or-later */
/* law_disk_name.c — the one table of the 2-D friction laws' names (enum fricreg_disk_law). */
#include <string.h>

#include "law_disk.h"

/* Indexed by enum fricreg_disk_law; the 1-D law's name where the law is its 2-D form. */
static const char *const disk_law_names[] = {
    [FRICREG_DISK_COULOMB] = "coulomb",
    [FRICREG_DISK_FORCE_BALANCE] = "force-balance",
    [FRICREG_DISK_QUINN] = "quinn",
    [FRICREG_DISK_QUINN_LENS] = "quinn-lens",
    [FRICREG_DISK_QUINN_NESTED] = "quinn-nested",
};

const char *fricreg_disk_law_name(int law)
{
    return fr_disk_law_known(law) ? disk_law_names[law] : NULL;
}

int fricreg_disk_law_from_name(const char *name)
{
    if (name == NULL)
        return 0;
    for (int law = FRICREG_DISK_COULOMB; fr_disk_law_known(law); law++)
        if (strcmp(disk_law_names[law], name) == 0)
            return law;
    return 0;
}
