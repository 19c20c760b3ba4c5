/* SPDX-License-Identifier: GPL-3.0-or-later */
/* disk_coupling.h — internal: the Delassus matrix W of a 2-D context by contacts, as block
 * rows of 2x2 blocks (the BSR layout): block row i lists every contact j that W couples to i,
 * j ascending, the diagonal block included, with W_ij row-major. Both triangles are kept, so
 * that the sweeps and Newton's products read a contact's row in one pass. A dense W keeps its
 * non-zero blocks; a sparse one every block that holds an entry of its pattern. Memory
 * O(blocks): no (2m)^2 array on the sparse path. */
#ifndef FRICREG_DISK_COUPLING_H
#define FRICREG_DISK_COUPLING_H

#include <stddef.h>
#include <stdint.h>

#include <cholmod.h>

struct fr_disk_coupling {
    size_t m;
    int64_t *ptr;  /* [m + 1] block row i is blocks ptr[i] .. ptr[i+1] - 1 */
    int64_t *col;  /* [nb] the contact j of each block */
    int64_t *diag; /* [m] the index of block (i, i) */
    double *blk;   /* [4 nb] W_ij row-major: blk[4k + 2a + b] = W(2i + a, 2j + b) */
};

/* From a dense row-major W of order 2m (checked symmetric): the blocks that are not all zero,
 * and every diagonal block. FRICREG_OK or FRICREG_ENOMEM (nothing held). */
int fr_disk_coupling_from_dense(struct fr_disk_coupling *w, size_t m, const double W[]);

/* From CHOLMOD's upper triangle U (stype 1, sorted, 2m x 2m) of a symmetric W. FRICREG_OK or
 * FRICREG_ENOMEM (nothing held); c is the workspace U belongs to. */
int fr_disk_coupling_from_upper(struct fr_disk_coupling *w, size_t m, cholmod_sparse *U,
                                cholmod_common *c);

/* Releases the arrays; safe on a zeroed or freed struct. */
void fr_disk_coupling_free(struct fr_disk_coupling *w);

#endif
