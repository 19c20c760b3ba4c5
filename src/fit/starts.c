/* SPDX-License-Identifier: GPL-3.0-or-later */
/* starts.c — a fit's starts (starts.h). The first start's parameters the caller did not give
 * come from the model (model.h: the modal Iwan's from the levels, modal_iwan_model.c; the HB
 * model's the driver's values, hb_model.c). A start outside the caller's bounds is moved inside. Where the caller gave starts, the first
 * start is theirs, alone; every other start is about the levels' centre: the least squares has
 * a local minimum wherever a level's amplitude sits on phi_max's kink (the stiffness drops by
 * F_S beta/(c phi_max) there), so the centre in the right regime with many starts about it
 * finds the best far more often than starts about a caller's guess far off (measured: 8
 * starts about two centres missed the best of 64 in 38 of 50 noisy draws; 32 about the
 * levels' in none). The starts after the centre's first move each theta by
 * (2 h - 1) times a span (ln 10 where theta is a log: a factor 10 either way; 2 for a
 * parameter bounded on both sides; 1 + |theta| for none), h the Halton sequence in the k-th
 * prime's base for the k-th free parameter: deterministic, and spread over the box. */
#include <math.h>

#include "fricreg_fit.h"
#include "model.h"
#include "params.h"
#include "starts.h"

static const unsigned primes[FR_FIT_MAXP] = {2,  3,  5,  7,  11, 13, 17, 19,
                                             23, 29, 31, 37, 41, 43, 47, 53};

/* The van der Corput radical inverse of s in base b, in (0, 1) for s >= 1. */
static double halton(size_t s, unsigned b)
{
    double h = 0.0, f = 1.0 / b;
    for (; s > 0; s /= b, f /= b)
        h += f * (double)(s % b);
    return h;
}

/* v moved inside (lo, hi) if it is not. */
static double inside(double v, double lo, double hi)
{
    if (v > lo && v < hi)
        return v;
    if (isfinite(lo) && isfinite(hi))
        return 0.5 * (lo + hi);
    return isfinite(lo) ? lo + 1.0 + fabs(lo) : hi - 1.0 - fabs(hi);
}

/* 1 if the caller gave a start to some free parameter. */
static int caller_started(const struct fr_fit_problem *pb)
{
    for (size_t k = 0; k < pb->nfree; k++)
        if (!isnan(pb->fit->par[pb->idx[k]].value))
            return 1;
    return 0;
}

void fr_fit_start(const struct fr_fit_problem *pb, size_t s, double theta[])
{
    const fricreg_fit *fit = pb->fit;
    double guess[FR_FIT_MAXP];
    fit->model->start(fit, guess);
    /* The caller's start first, where given; every other start about the levels'. */
    int caller = caller_started(pb), levels_centre = !caller || s > 0;
    size_t h = caller && s > 0 ? s - 1 : s;
    for (size_t k = 0; k < pb->nfree; k++) {
        const struct fr_fit_param *q = &fit->par[pb->idx[k]];
        double p = isnan(q->value) || levels_centre ? inside(guess[pb->idx[k]], q->lo, q->hi)
                                                    : q->value;
        double t = fr_fit_to_theta(p, q->lo, q->hi);
        double span = isfinite(q->lo) && isfinite(q->hi)   ? 2.0
                      : isfinite(q->lo) || isfinite(q->hi) ? log(10.0)
                                                           : 1.0 + fabs(t);
        theta[k] = h == 0 ? t : t + span * (2.0 * halton(h, primes[k]) - 1.0);
    }
}
