/* SPDX-License-Identifier: GPL-3.0-or-later */
/* reproduce_table.c — a row of `fricreg-sim reproduce`'s comparison table (cli.h): the figure,
 * the quantity, the paper's (or the reference's) value, ours and their difference. Shared by
 * the paper's experiments (reproduce.c) and the problems beyond them (reproduce_beyond.c). */
#include <stdio.h>

#include "cli.h"

void cli_table_row(const char *figure, const char *quantity, const char *paper, double ours,
                   const char *difference)
{
    printf("%-7s %-44s %-16s %-12.6f %s\n", figure, quantity, paper, ours, difference);
}
