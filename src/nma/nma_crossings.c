/* SPDX-License-Identifier: GPL-3.0-or-later */
/* nma_crossings.c — where along a nonlinear mode's backbone a harmonic k ω of the mode crosses
 * another linear mode's frequency ω_r (fricreg_hb_nma_crossings, fricreg_hb.h): the place an
 * internal resonance can start (a harmonic of the nonlinear mode meeting a natural frequency of
 * another mode; Krack & Gross 2019, "Harmonic Balance for Nonlinear Vibration Problems"). The
 * frequencies ω_r are those of the structure with its elements stuck, K_0 φ = ω² M φ, which the
 * backbone starts from (nma_linear.c: a dense model's eigensolve gives all of them at no extra
 * cost; a sparse model's subspace iteration only its own mode's, so a sparse model's are found by a
 * dense solve up to FR_HB_NMA_SPARSE_ALL_MODES dofs, and above it has none). Between two
 * consecutive stored points i and i + 1 a crossing of (k, r) is a change of sign of g = k ω − ω_r
 * (g >= 0 at one, g < 0 at the other: a zero counts once); it is placed at the fraction t = g_i /
 * (g_i − g_{i+1}) of the stretch, a and ω linear in t (the stretch's arclength for
 * fricreg_hb_nma_continue, its log a for fricreg_hb_nma, both to the chord's accuracy). */
#include <math.h>
#include <stdlib.h>

#include "nma_internal.h"

/* The crossings between points i and i + 1 into out (4 doubles each) if not NULL; their
 * number. */
static size_t crossings_between(const struct fr_hb_nma *s, int H, size_t i, double *out)
{
    const double *p = s->pts + i * s->stride, *q = p + s->stride;
    size_t count = 0;
    for (int k = 2; k <= H; k++)
        for (size_t r = 0; r < s->nlambda; r++) {
            double wr = sqrt(fmax(s->lambda[r], 0.0));
            double g0 = k * p[1] - wr, g1 = k * q[1] - wr;
            if (r == s->mode || (g0 >= 0.0) == (g1 >= 0.0))
                continue;
            if (out != NULL) {
                double t = g0 / (g0 - g1), *c = out + 4 * count;
                c[0] = k;
                c[1] = (double)r;
                c[2] = p[0] + t * (q[0] - p[0]);
                c[3] = p[1] + t * (q[1] - p[1]);
            }
            count++;
        }
    return count;
}

int fr_hb_nma_find_crossings(struct fr_hb_nma *s)
{
    int H = (int)(s->nc - 1) / 2;
    size_t count = 0;
    free(s->cross);
    s->cross = NULL;
    s->ncross = 0;
    for (size_t i = 0; i + 1 < s->npts; i++)
        count += crossings_between(s, H, i, NULL);
    if (count == 0)
        return FRICREG_OK;
    if ((s->cross = malloc(4 * count * sizeof *s->cross)) == NULL)
        return FRICREG_ENOMEM;
    for (size_t i = 0; i + 1 < s->npts; i++)
        s->ncross += crossings_between(s, H, i, s->cross + 4 * s->ncross);
    return FRICREG_OK;
}

size_t fricreg_hb_nma_crossings(const fricreg_hb *hb)
{
    return hb && hb->nma ? hb->nma->ncross : 0;
}

int fricreg_hb_nma_crossing(fricreg_hb *hb, size_t i, int *harmonic, size_t *mode,
                            double *amplitude, double *omega)
{
    static const char fn[] = "nma_crossing";
    if (hb == NULL)
        return FRICREG_ENULL;
    if (harmonic == NULL || mode == NULL || amplitude == NULL || omega == NULL)
        return fr_fail(hb, FRICREG_ENULL, "%s: %s is NULL", fn,
                       harmonic == NULL    ? "harmonic"
                       : mode == NULL      ? "mode"
                       : amplitude == NULL ? "amplitude"
                                           : "omega");
    size_t n = fricreg_hb_nma_crossings(hb);
    if (i >= n)
        return fr_fail(hb, FRICREG_EINVAL, "%s: i = %zu, %zu crossings stored", fn, i, n);
    const double *c = hb->nma->cross + 4 * i;
    *harmonic = (int)c[0];
    *mode = (size_t)c[1];
    *amplitude = c[2];
    *omega = c[3];
    return FRICREG_OK;
}
