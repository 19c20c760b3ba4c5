/* SPDX-License-Identifier: GPL-3.0-or-later */
/* qsma_levels.c — a harmonic-balance driver's quasi-static modal analysis as the fit's model
 * (model.h, fricreg_fit_set_model_qsma): hb_model.c's parameters on the driver, and the backbone
 * at the measured levels by fricreg_hb_qsma_sensitivities (exact for jenkins and iwan models,
 * the marched path's own for contact_3d ones).
 *
 * A level measures g(a, p) = |s| a omega(a, p)^kind = A (modal amplitudes times the sensor's
 * mode shape value s). A displacement gives a = A/|s| at once; a velocity or an acceleration is
 * solved by Newton's method on log a, every level at once (one QSMA call an iteration, its
 * amplitude derivative beside omega), from the linear mode's omega_k. Then, with G_a = d log
 * g/da = 1/a + kind omega_a/omega and G_p = kind omega_p/omega,
 *
 *     da/dp = -G_p/G_a,    d omega/dp = omega_p + omega_a da/dp,    dzeta/dp likewise,
 *
 * G_a <= 0 a fold of the measured amplitude in a (its level out of reach), as hb_levels.c. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/fr_math.h"
#include "fricreg_hb_qsma.h"
#include "qsma_levels.h"

#define NEWTON_TOL 1e-12 /* |log g - log A|: each level's amplitude to 1e-12 relative */
#define NEWTON_MAX 40    /* iterations of the levels' Newton */
#define MAX_LOG_STEP 1.0 /* a Newton step moves log a by at most 1 */
#define PROBE 1e-9       /* the linear probe's modal amplitude over the smallest level's */
#define SAME 1e-12       /* modal amplitudes this close (relative) share one point */

/* The levels' modal amplitudes a[n], sorted into u distinct points ua[u] (pt[i] level i's); ω,
 * ζ and their derivatives in np1 = np + 1 parameters (the amplitude last) at each point. */
struct work {
    size_t n, u, np1;
    double *a, *ua, *dw, *dz;
    size_t *pt, *order;
};

/* Levels ordered by a (insertion sort: a fit's levels are few), then merged into points. */
static void points(struct work *wk)
{
    for (size_t i = 0; i < wk->n; i++) {
        size_t j = i, v = i;
        for (; j > 0 && wk->a[wk->order[j - 1]] > wk->a[v]; j--)
            wk->order[j] = wk->order[j - 1];
        wk->order[j] = v;
    }
    wk->u = 0;
    for (size_t r = 0; r < wk->n; r++) {
        size_t i = wk->order[r];
        if (wk->u == 0 || wk->a[i] > wk->ua[wk->u - 1] * (1.0 + SAME))
            wk->ua[wk->u++] = wk->a[i];
        wk->pt[i] = wk->u - 1;
    }
}

/* QSMA at the points with the parameters and the amplitude (nd of them: np + 1, or the
 * amplitude alone): ω, ζ into w[u], z[u], derivatives into dw, dz [u nd]. A driver's failure:
 * where a point is beyond reach (macroslip, Newton's march), the first such level into *bad. */
static int qsma(fricreg_fit *fit, struct work *wk, size_t nd, double *w, double *z, size_t *bad)
{
    const struct fr_fit_hb *m = fit->hb;
    size_t off = fit->np + 1 - nd;
    fit->marches++;
    int st = fricreg_hb_qsma_at(m->hb, m->mode, wk->u, wk->ua, w, z);
    if (st == FRICREG_OK)
        st = fricreg_hb_qsma_sensitivities(m->hb, m->mode, wk->u, wk->ua, nd, m->kind + off,
                                           m->first + off, m->count + off, m->index + off, wk->dw,
                                           wk->dz);
    if (st == FRICREG_OK)
        return FRICREG_OK;
    int short_of = st == FRICREG_ESINGULAR || st == FRICREG_EWORK;
    snprintf(fit->reason, sizeof fit->reason, "%s%s",
             short_of ? "the static path stops before it: " : "the driver: ",
             fricreg_hb_errmsg(m->hb));
    if (!short_of)
        return st;
    double wk1, zk1;
    for (size_t r = 0; r < wk->n; r++) { /* the first level the path does not reach */
        size_t i = wk->order[r];
        if (fricreg_hb_qsma_at(m->hb, m->mode, 1, &wk->a[i], &wk1, &zk1) != FRICREG_OK) {
            *bad = i;
            break;
        }
    }
    return FRICREG_EINVAL;
}

static double dlog_g(int kind, double a, double w, double dw_da)
{
    return 1.0 / a + kind * dw_da / w;
}

/* Velocity and acceleration levels: Newton's method on log a from the linear mode's ω. */
static int solve_amplitudes(fricreg_fit *fit, struct work *wk, int kind, const double amp[],
                            const double guess[], double *w, double *z, size_t *bad)
{
    double s = fabs(fit->sensor), lo = INFINITY, wl, zl;
    for (size_t i = 0; i < wk->n; i++)
        lo = fmin(lo, amp[i]);
    wk->u = 1;
    wk->ua[0] = PROBE * lo / s;
    int st = qsma(fit, wk, 1, &wl, &zl, bad);
    if (st != FRICREG_OK)
        return st;
    for (size_t i = 0; i < wk->n; i++)
        wk->a[i] = isfinite(guess[i]) && guess[i] > 0.0 ? guess[i] : amp[i] / (s * pow(wl, kind));
    for (int it = 0; it < NEWTON_MAX; it++) {
        points(wk);
        st = qsma(fit, wk, 1, w, z, bad);
        if (st != FRICREG_OK)
            return st;
        double worst = 0.0;
        for (size_t i = 0; i < wk->n; i++) {
            size_t k = wk->pt[i];
            double a = wk->ua[k], e = log(s * a * pow(w[k], kind)) - log(amp[i]);
            double ga = dlog_g(kind, a, w[k], wk->dw[k]) * a; /* d log g/d log a */
            if (!(ga > 0.0)) {
                *bad = i;
                snprintf(fit->reason, sizeof fit->reason,
                         "the measured amplitude folds in the modal amplitude %g", a);
                return FRICREG_EINVAL;
            }
            double step = fmax(-MAX_LOG_STEP, fmin(MAX_LOG_STEP, -e / ga));
            wk->a[i] = a * exp(step);
            worst = fmax(worst, fabs(e));
        }
        if (worst <= NEWTON_TOL)
            return FRICREG_OK;
    }
    *bad = wk->order[wk->n - 1];
    snprintf(fit->reason, sizeof fit->reason,
             "Newton's method on the modal amplitudes did not converge in %d iterations",
             NEWTON_MAX);
    return FRICREG_EINVAL;
}

int fr_fit_qsma_levels(fricreg_fit *fit, int kind, size_t n, const double amp[], double guess[],
                       const struct fr_fit_levels *out, size_t *bad)
{
    int st = FRICREG_OK;
    size_t np = fit->np, np1 = np + 1;
    double *block = malloc((4 * n + 2 * n * np1) * sizeof *block);
    size_t *idx = malloc(2 * n * sizeof *idx);
    if (block == NULL || idx == NULL) {
        free(block);
        free(idx);
        snprintf(fit->reason, sizeof fit->reason, "out of memory for %zu levels", n);
        return FRICREG_ENOMEM;
    }
    struct work wk = {.n = n, .np1 = np1, .a = block, .ua = block + n, .pt = idx, .order = idx + n};
    double *w = block + 2 * n, *z = w + n;
    wk.dw = z + n;
    wk.dz = wk.dw + n * np1;
    for (size_t i = 0; i < n; i++)
        wk.a[i] = amp[i] / fabs(fit->sensor);
    if (kind != FRICREG_FIT_DISPLACEMENT)
        st = solve_amplitudes(fit, &wk, kind, amp, guess, w, z, bad);
    if (st == FRICREG_OK) {
        points(&wk);
        st = qsma(fit, &wk, np1, w, z, bad);
    }
    for (size_t i = 0; i < n && st == FRICREG_OK; i++) {
        size_t k = wk.pt[i], at = k * np1;
        double a = wk.ua[k], ga = dlog_g(kind, a, w[k], wk.dw[at + np]);
        out->freq_hz[i] = w[k] / FR_TWO_PI;
        out->zeta[i] = z[k];
        out->modal[i] = guess[i] = a;
        for (size_t j = 0; j < np; j++) {
            double da = -kind * wk.dw[at + j] / w[k] / ga;
            out->dfreq[i * np + j] = (wk.dw[at + j] + wk.dw[at + np] * da) / FR_TWO_PI;
            out->dzeta[i * np + j] = wk.dz[at + j] + wk.dz[at + np] * da;
        }
    }
    free(block);
    free(idx);
    return st;
}
