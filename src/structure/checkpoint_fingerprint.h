/* SPDX-License-Identifier: GPL-3.0-or-later */
/* checkpoint_fingerprint.h — a structure's fingerprint in its checkpoint
 * (checkpoint_fingerprint.c), and the FNV-1a hash that the checkpoint's header uses too. */
#ifndef FRICREG_CHECKPOINT_FINGERPRINT_H
#define FRICREG_CHECKPOINT_FINGERPRINT_H

#include <stdint.h>

#include "structure_internal.h"

#define FNV_START 0xcbf29ce484222325ull
/* FNV-1a of bytes[len] continued from h (FNV_START to begin). */
uint64_t fr_fnv1a(uint64_t h, const void *bytes, size_t len);

#define NCOUNTS 7 /* sizes and kinds */
#define NFLAGS 8  /* settings that are integers */
#define NPARAMS 8 /* settings that are doubles */

struct fingerprint {
    uint64_t count[NCOUNTS];
    int32_t flag[NFLAGS + NFLAGS % 2]; /* an even count: no padding */
    double param[NPARAMS];
    uint64_t model, excitation;
};

/* s's fingerprint into *fp (every byte set, padding none). */
void fr_fingerprint_of(const fricreg_structure *s, struct fingerprint *fp);
/* FRICREG_OK, or FRICREG_EINVAL naming the first difference of s's from blob's (recorded). */
int fr_fingerprint_compare(fricreg_structure *s, const struct fingerprint *blob);

#endif
