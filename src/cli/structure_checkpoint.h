/* SPDX-License-Identifier: GPL-3.0-or-later */
/* structure_checkpoint.h — the checkpoints of `fricreg-sim structure` (structure_checkpoint.c):
 * a run's state saved at its end by --checkpoint-out and restored by --checkpoint-in, as
 * fricreg_structure_save and _restore's blob. */
#ifndef FRICREG_CLI_STRUCTURE_CHECKPOINT_H
#define FRICREG_CLI_STRUCTURE_CHECKPOINT_H

#include "cli_structure.h"
#include "fricreg_structure.h"

/* --checkpoint-in: the blob read whole and restored into the set-up structure, whose time must
 * then be before --t-end. 0, or a message naming the file and exit 2. */
int cli_checkpoint_in(fricreg_structure *s, const struct structure_options *o);

/* --checkpoint-out: the state at the run's end into the file, replaced only once the new one
 * is complete (cli_replace_file). 0, or a message naming it and exit 2. */
int cli_checkpoint_out(fricreg_structure *s, const char *path);

#endif
