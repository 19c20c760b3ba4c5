/* SPDX-License-Identifier: GPL-3.0-or-later */
/* blocks_carried.h — internal: the near-stick block's factor that a Newmark / HHT-alpha step
 * keeps for the next one, for fricreg_structure_save and _restore (checkpoint.c). The next
 * step's rounding depends on it: the dense path's factor keeps its leading rows and deletes
 * others (masked_factor.h), so that it differs in its last bits from a fresh factor of the same
 * block, and the sparse path's held factor is a chord for other shifts (contact_sparse.h). A
 * restored run that factored afresh would leave the saved run's numbers by rounding. */
#ifndef FRICREG_BLOCKS_CARRIED_H
#define FRICREG_BLOCKS_CARRIED_H

#include <stddef.h>

#include "structure_internal.h"

/* The bytes of s's held block: 1 where none is held or K_eff is not factored (step_dt 0). */
size_t fr_blocks_carried_size(const fricreg_structure *s);

/* The held block into out[fr_blocks_carried_size(s)]. */
void fr_blocks_carried_save(const fricreg_structure *s, unsigned char out[]);

/* The held block of in[len] made s's, after its K_eff was factored at the saved dt (factored
 * says whether it was: a block is carried only then): the dense factor copied, the sparse
 * path's block factored again (the same factor, as its matrix is formed the same way), or none
 * held. FRICREG_OK; FRICREG_EINVAL if in does not fit s's blocks (then nothing changed);
 * FRICREG_ESINGULAR or FRICREG_ENOMEM from the sparse path's factorization (then no block
 * held: the next step factors afresh). */
int fr_blocks_carried_restore(fricreg_structure *s, const unsigned char in[], size_t len,
                              int factored);

#endif
