/* SPDX-License-Identifier: GPL-3.0-or-later */
/* contact_check.h — internal: the contexts' one check of their per-contact array arguments
 * (the 1-D context's ctx.c and the 2-D context's disk_ctx.c), so that both refuse alike. */
#ifndef FRICREG_CONTACT_CHECK_H
#define FRICREG_CONTACT_CHECK_H

#include <stddef.h>

#include "base/error.h"

/* An array a[n] given for m contacts (n = m, 2m, 4m, m^2 or (2m)^2 numbers) of a context of
 * ctx_m: FRICREG_ESIZE unless m == ctx_m, FRICREG_ENULL if a is NULL, FRICREG_ENONFINITE
 * naming the first element that is not finite, FRICREG_EINVAL naming the first beyond max in
 * magnitude (INFINITY for the 1-D context, FR_DISK_MAX for the 2-D one: its kernels' range),
 * else FRICREG_OK. A failure is recorded in err, led by `what` (the setter's name). */
int fr_check_contact_array(struct fr_error *err, const char *what, size_t m, size_t ctx_m, size_t n,
                           const double a[], double max);

/* The friction bounds mun[m] of a context of ctx_m contacts: fr_check_contact_array's checks,
 * then FRICREG_EINVAL naming the first bound outside [0, max]. The range is the laws':
 * the 1-D laws are division-free clamps (law.h) and take every finite bound (max = DBL_MAX);
 * the 2-D kernels form hypot, products and sums of vector components and take at most
 * FR_DISK_MAX (law_disk.h), below which none of them overflows. */
int fr_check_bounds(struct fr_error *err, size_t m, size_t ctx_m, const double mun[], double max);

/* The Stribeck parameters of m contacts for a context of ctx_m: FRICREG_ESIZE unless
 * m == ctx_m, then fr_stribeck_check's statuses (law_stribeck.h), fs at most cap (the bounds'
 * range: INFINITY in 1-D, FR_DISK_MAX in 2-D); recorded led by "set_stribeck". */
int fr_check_stribeck(struct fr_error *err, size_t m, size_t ctx_m, const double fs[],
                      const double fk[], const double vs[], const double delta[], double cap);

/* An evaluation's inputs zdot[n] and a_free[n] for m contacts (n = m in 1-D, 2m in 2-D) and
 * its output f: FRICREG_ESIZE unless m == ctx_m, FRICREG_ENULL naming the NULL array,
 * FRICREG_ENONFINITE naming the first component of zdot or a_free that is not finite;
 * recorded led by "eval". One vectorized pass (fr_plausible) when all are finite. */
int fr_check_eval_inputs(struct fr_error *err, size_t m, size_t ctx_m, size_t n,
                         const double zdot[], const double a_free[], const double f[]);

#endif
