/* SPDX-License-Identifier: GPL-3.0-or-later */
/* stream.c — non-temporal copies of a large batch's outputs (stream.h): SSE2's movntpd, part
 * of the x86-64 baseline; a plain copy elsewhere. */
#include <stdint.h>
#include <string.h>

#include "stream.h"

#if defined(__GNUC__) && defined(__x86_64__) && defined(__SSE2__)
#include <emmintrin.h>

void fr_stream_copy(double *restrict dst, const double *restrict src, size_t n)
{
    size_t i = 0;
    if (n > 0 && (uintptr_t)dst % 16 != 0) /* movntpd needs 16-byte alignment */
        dst[i] = src[i], i++;
    for (; i + 2 <= n; i += 2)
        _mm_stream_pd(dst + i, _mm_loadu_pd(src + i));
    if (i < n)
        dst[i] = src[i];
}

void fr_stream_fence(void)
{
    _mm_sfence();
}
#else
void fr_stream_copy(double *restrict dst, const double *restrict src, size_t n)
{
    memcpy(dst, src, n * sizeof *dst);
}

void fr_stream_fence(void)
{
}
#endif
