/* SPDX-License-Identifier: GPL-3.0-or-later */
/* stream.h — internal: writing a large batch's outputs with non-temporal (streaming) stores.
 *
 * A store to a line that is not in cache first reads it (write-allocate): out of cache the
 * minimal loop of law (4) moves 3 reads + that read + the write per contact, 40 bytes, and a
 * batch that validates before it writes moves 24 more for its second read of the inputs.
 * Streaming stores skip the read of the output line: 56 bytes against 40, 1.4x instead of
 * 1.6x (docs/benchmark.md). In cache they would only push the outputs out to memory, so they
 * are used only where the arrays are far beyond the caches a core can count on. */
#ifndef FRICREG_STREAM_H
#define FRICREG_STREAM_H

#include <stddef.h>

/* Batches of at least this many contacts are written by streaming stores: 2^18 contacts are
 * 2 MB per array, 8 MB for the batch's four, beyond the 1-2 MB of L2 per core of current
 * x86-64 CPUs and a large share of an L3 that is shared with other cores, where an output
 * line is unlikely to be still cached when it is next read. Below it, plain stores. */
#define FR_STREAM_MIN_CONTACTS ((size_t)1 << 18)

/* Contacts per block: the law is formed into a stack buffer of this many (4 KB, in L1), then
 * streamed out. Even, so that a 16-byte aligned output stays aligned block after block. */
enum { FR_STREAM_BLOCK = 512 };

/* dst[0..n) = src[0..n) with streaming stores where dst is 16-byte aligned (an unaligned
 * first element and an odd last one by plain stores); a plain copy without SSE2. dst and src
 * do not overlap. Call fr_stream_fence() once after the last copy of a batch. */
void fr_stream_copy(double *restrict dst, const double *restrict src, size_t n);

/* Orders the streaming stores before any later store (sfence), as a plain store would be. */
void fr_stream_fence(void);

#endif
