/* SPDX-License-Identifier: GPL-3.0-or-later */
/* law.c — the public scalar and batched entry points of the friction laws (law.h). */
#include <math.h>
#include <stdint.h>

#if defined(__GNUC__) && defined(__x86_64__) && defined(__SSE2__)
#define FR_STREAM_STORES 1 /* fricreg_law_eval_batch's non-temporal stores (below) */
#include <emmintrin.h>
#endif

#include "base/dispatch.h"
#include "law.h"
#include "plausible.h"

static int bad_law_params(int law, double eps)
{
    if (!isfinite(eps))
        return FRICREG_ENONFINITE;
    if (!fr_law_known(law) || !fr_eps_valid(eps))
        return FRICREG_EINVAL;
    return FRICREG_OK;
}

int fricreg_law_eval(int law, double v, double f_eq, double mun, double eps, double *f)
{
    if (f == NULL)
        return FRICREG_ENULL;
    int status = bad_law_params(law, eps);
    if (status != FRICREG_OK)
        return status;
    if (!isfinite(v) || !isfinite(f_eq) || !isfinite(mun))
        return FRICREG_ENONFINITE;
    if (mun < 0.0)
        return FRICREG_EINVAL;
    *f = fr_law(law, v, f_eq, mun, eps);
    return FRICREG_OK;
}

/* The exact check of a batch: its first failure decides, non-finite before negative. */
static int bad_batch_inputs(size_t m, const double v[], const double f_eq[], const double mun[])
{
    int nonfinite = 0, negative = 0;
    for (size_t i = 0; i < m; i++) {
        double feq = f_eq ? f_eq[i] : 0.0;
        nonfinite |= !isfinite(v[i]) | !isfinite(feq) | !isfinite(mun[i]);
        negative |= mun[i] < 0.0;
    }
    if (nonfinite)
        return FRICREG_ENONFINITE;
    return negative ? FRICREG_EINVAL : FRICREG_OK;
}

/* One loop per law: the switch stays outside, so each loop is a straight-line kernel of
 * selects that the vectorizer takes. */
FR_KERNEL_BODY void law_batch_loops(int law, double eps, size_t m, const double v[],
                                    const double f_eq[], const double mun[], double f[])
{
    FR_LAWS_LISTED(6);
    switch ((enum fricreg_law)law) {
    case FRICREG_LAW_COULOMB:
        for (size_t i = 0; i < m; i++)
            f[i] = fr_coulomb(v[i], mun[i]);
        break;
    case FRICREG_LAW_FORCE_BALANCE:
        for (size_t i = 0; i < m; i++)
            f[i] = fr_force_balance(v[i], f_eq[i], mun[i]);
        break;
    case FRICREG_LAW_KARNOPP:
        for (size_t i = 0; i < m; i++)
            f[i] = fr_karnopp(v[i], f_eq[i], mun[i], eps);
        break;
    case FRICREG_LAW_VELOCITY_LIMITED:
        for (size_t i = 0; i < m; i++)
            f[i] = fr_velocity_limited(v[i], mun[i], eps);
        break;
    case FRICREG_LAW_TANH:
        for (size_t i = 0; i < m; i++)
            f[i] = fr_tanh(v[i], mun[i], eps);
        break;
    case FRICREG_LAW_QUINN:
        for (size_t i = 0; i < m; i++)
            f[i] = fr_quinn(v[i], f_eq[i], mun[i], eps);
        break;
    }
}

#ifdef FRICREG_AVX2_DISPATCH
FR_AVX2 static void law_batch_avx2(int law, double eps, size_t m, const double v[],
                                   const double f_eq[], const double mun[], double f[])
{
    law_batch_loops(law, eps, m, v, f_eq, mun, f);
}
#endif

/* The loops in AVX2 where the CPU has it (dispatch.h). */
void fr_law_batch(int law, double eps, size_t m, const double v[], const double f_eq[],
                  const double mun[], double f[])
{
#ifdef FRICREG_AVX2_DISPATCH
    if (fr_have_avx2()) {
        law_batch_avx2(law, eps, m, v, f_eq, mun, f);
        return;
    }
#endif
    law_batch_loops(law, eps, m, v, f_eq, mun, f);
}

#ifdef FR_STREAM_STORES
/* From 2^19 contacts the batch's four arrays (16 MB) outgrow the caches a call can count on,
 * and f is written with non-temporal stores: out of cache (m = 10^6) the batch went from
 * 1.46-1.49 to 1.37-1.42 times the minimal loop (bench/kernels.c), its reads of f for
 * ownership saved. f is then not left in cache, which a caller reading it next at this size
 * would miss anyway. */
enum { STREAM_FROM = 1 << 19, STREAM_CHUNK = 512 };

/* fr_law_batch chunk by chunk into a buffer in L1, then streamed to f: the same bits. f may
 * alias v or f_eq: a chunk is read whole before it is written. */
static void law_batch_streamed(int law, double eps, size_t m, const double v[], const double f_eq[],
                               const double mun[], double f[])
{
    double buf[STREAM_CHUNK];
    size_t i = 0;
    for (; i < m && ((uintptr_t)(f + i) & 15) != 0; i++) /* to f's first 16-byte boundary */
        fr_law_batch(law, eps, 1, v + i, f_eq ? f_eq + i : NULL, mun + i, f + i);
    while (i < m) {
        size_t n = m - i < STREAM_CHUNK ? m - i : STREAM_CHUNK, k = 0;
        fr_law_batch(law, eps, n, v + i, f_eq ? f_eq + i : NULL, mun + i, buf);
        for (; k + 2 <= n; k += 2)
            _mm_stream_pd(f + i + k, _mm_loadu_pd(buf + k));
        for (; k < n; k++)
            f[i + k] = buf[k];
        i += n;
    }
    _mm_sfence();
}
#endif

int fricreg_law_eval_batch(int law, double eps, size_t m, const double v[], const double f_eq[],
                           const double mun[], double f[])
{
    int status = bad_law_params(law, eps);
    if (status != FRICREG_OK || m == 0)
        return status;
    if (v == NULL || mun == NULL || f == NULL || (f_eq == NULL && fr_law_uses_feq(law)))
        return FRICREG_ENULL;
    /* Validated before anything is written, f_eq whenever given; the exact check runs only
     * to name the failure. */
    if (!fr_plausible(m, v, f_eq, mun)) {
        status = bad_batch_inputs(m, v, f_eq, mun);
        if (status != FRICREG_OK)
            return status;
    }
#ifdef FR_STREAM_STORES
    if (m >= STREAM_FROM) {
        law_batch_streamed(law, eps, m, v, f_eq, mun, f);
        return FRICREG_OK;
    }
#endif
    fr_law_batch(law, eps, m, v, f_eq, mun, f);
    return FRICREG_OK;
}
