/* SPDX-License-Identifier: GPL-3.0-or-later */
/* richardson.h — internal: Richardson extrapolation of a sequence computed at h, h/2, h/4, …
 * (the regularization eps of fricreg_sim_run_extrapolated), its leading order observed from
 * the ratios of successive differences. */
#ifndef FRICREG_RICHARDSON_H
#define FRICREG_RICHARDSON_H

#define FR_RICHARDSON_MAX_LEVELS 8 /* fricreg_sim_run_extrapolated's limit */
#define FR_RICHARDSON_MAX_ORDER 4  /* the highest leading order accepted as observed */

/* One extrapolated value. */
struct fr_richardson {
    double value;    /* the last diagonal entry of the table */
    double error;    /* its estimate: |last diagonal - the entry left of it|, widened when
                      * flagged to at least |v[L-1] - v[L-2]| */
    int order;       /* the leading order the table used (columns: order, order + 1, …) */
    double observed; /* log2 of the last ratio of successive differences; NaN when fewer
                      * than 3 levels or the differences are at rounding level */
    int flagged;     /* 1: the ratio gave no clean integer order in 1 … FR_RICHARDSON_MAX_ORDER,
                      * so the declared order was used and the estimate widened */
};

/* Extrapolates v[levels], v[k] computed at h / 2^k (2 <= levels <= FR_RICHARDSON_MAX_LEVELS),
 * to h -> 0, assuming v(h) = v(0) + c_p h^p + c_(p+1) h^(p+1) + …. The leading order p is the
 * one the last three values show, log2((v[L-2] - v[L-3]) / (v[L-1] - v[L-2])) rounded, when
 * it is within 0.3 of an integer in 1 … FR_RICHARDSON_MAX_ORDER; otherwise (or with two
 * levels) `declared` (1 … FR_RICHARDSON_MAX_ORDER; 0 means 1). Differences at rounding level
 * (all the values agree to 32 ulp) mean converged: the last value, not flagged. */
void fr_richardson(const double v[], int levels, int declared, struct fr_richardson *out);

#endif
