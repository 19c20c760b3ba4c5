/* SPDX-License-Identifier: GPL-3.0-or-later */
/* nma_crossings.c — the special points of a nonlinear mode's backbone
 * (fricreg_hb_nma_special_points, fricreg_hb.h): its folds (nma_arclength.c finds them) and
 * where a harmonic k ω of the mode crosses another linear mode's frequency ω_r, the place an
 * internal resonance can start (a harmonic of the nonlinear mode meeting a natural frequency of
 * another mode; Krack & Gross 2019, "Harmonic Balance for Nonlinear Vibration Problems"). The
 * frequencies ω_r are those of the structure with its elements stuck, K_0 φ = ω² M φ, which the
 * backbone starts from (nma_linear.c: a dense model's eigensolve gives all of them at no extra
 * cost; a sparse model's subspace iteration only its own mode's, so a sparse model's are found by a
 * dense solve up to FR_HB_NMA_SPARSE_ALL_MODES dofs, and above it has none). Between two
 * consecutive stored points i and i + 1 a crossing of (k, r) is a change of sign of g = k ω − ω_r
 * (g >= 0 at one, g < 0 at the other: a zero counts once); it is placed at the fraction t = g_i /
 * (g_i − g_{i+1}) of the stretch, a, ω and ζ linear in t (the stretch's arclength for
 * fricreg_hb_nma_continue, its log a for fricreg_hb_nma, both to the chord's accuracy). The
 * folds and the crossings are one list, by their place along the stored points (a stretch's
 * index plus the fraction t; a fold's from its arclength), ties a fold first, then by k, then by
 * r: the branch's order, as fricreg_hb_bifurcation's list of the forced response. */
#include <math.h>
#include <stdlib.h>

#include "nma_internal.h"

enum { PLACE, TYPE, K, R, A, W, Z }; /* a special point's doubles */

/* The crossings between points i and i + 1 into out (FR_HB_NMA_SPECIAL_STRIDE doubles each) if
 * not NULL; their number. */
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
                double t = g0 / (g0 - g1), *c = out + FR_HB_NMA_SPECIAL_STRIDE * count;
                double z0 = p[2] / (2.0 * p[1]), z1 = q[2] / (2.0 * q[1]);
                c[PLACE] = (double)i + t;
                c[TYPE] = FRICREG_HB_NMA_CROSSING;
                c[K] = k;
                c[R] = (double)r;
                c[A] = p[0] + t * (q[0] - p[0]);
                c[W] = p[1] + t * (q[1] - p[1]);
                c[Z] = z0 + t * (z1 - z0);
            }
            count++;
        }
    return count;
}

/* The branch's order: the place, then a fold before a crossing, then k, then r. */
static int by_place(const void *x, const void *y)
{
    const double *u = x, *v = y;
    for (int j = PLACE; j <= R; j++)
        if (u[j] != v[j])
            return u[j] < v[j] ? -1 : 1;
    return 0;
}

int fr_hb_nma_find_special(struct fr_hb_nma *s)
{
    int H = (int)(s->nc - 1) / 2;
    size_t count = s->nfolds, st = FR_HB_NMA_SPECIAL_STRIDE;
    free(s->special);
    s->special = NULL;
    s->nspecial = 0;
    for (size_t i = 0; i + 1 < s->npts; i++)
        count += crossings_between(s, H, i, NULL);
    if (count == 0)
        return FRICREG_OK;
    if ((s->special = malloc(st * count * sizeof *s->special)) == NULL)
        return FRICREG_ENOMEM;
    for (size_t f = 0; f < s->nfolds; f++) {
        const double *g = s->folds + 4 * f;
        double *c = s->special + st * s->nspecial++;
        c[PLACE] = g[3];
        c[TYPE] = FRICREG_HB_NMA_FOLD;
        c[K] = 1.0;
        c[R] = (double)s->mode;
        c[A] = g[0];
        c[W] = g[1];
        c[Z] = g[2] / (2.0 * g[1]);
    }
    for (size_t i = 0; i + 1 < s->npts; i++)
        s->nspecial += crossings_between(s, H, i, s->special + st * s->nspecial);
    qsort(s->special, s->nspecial, st * sizeof *s->special, by_place);
    return FRICREG_OK;
}

size_t fricreg_hb_nma_special_points(const fricreg_hb *hb)
{
    return hb && hb->nma ? hb->nma->nspecial : 0;
}

int fricreg_hb_nma_special_point(fricreg_hb *hb, size_t i, int *type, double *amplitude,
                                 double *omega, double *zeta, int *harmonic, size_t *mode)
{
    static const char fn[] = "nma_special_point";
    if (hb == NULL)
        return FRICREG_ENULL;
    if (type == NULL || amplitude == NULL || omega == NULL || zeta == NULL || harmonic == NULL ||
        mode == NULL)
        return fr_fail(hb, FRICREG_ENULL, "%s: %s is NULL", fn,
                       type == NULL        ? "type"
                       : amplitude == NULL ? "amplitude"
                       : omega == NULL     ? "omega"
                       : zeta == NULL      ? "zeta"
                       : harmonic == NULL  ? "harmonic"
                                           : "mode");
    size_t n = fricreg_hb_nma_special_points(hb);
    if (i >= n)
        return fr_fail(hb, FRICREG_EINVAL, "%s: i = %zu, %zu special points stored", fn, i, n);
    const double *c = hb->nma->special + FR_HB_NMA_SPECIAL_STRIDE * i;
    *type = (int)c[TYPE];
    *amplitude = c[A];
    *omega = c[W];
    *zeta = c[Z];
    *harmonic = (int)c[K];
    *mode = (size_t)c[R];
    return FRICREG_OK;
}
