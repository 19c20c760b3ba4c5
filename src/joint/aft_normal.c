/* SPDX-License-Identifier: GPL-3.0-or-later */
/* aft_normal.c — the sampled AFT of a 1-D Jenkins element under normal load with lift-off
 * (fricreg_aft_jenkins_normal_sampled): the tangential displacement u and the normal one g at
 * N equidistant samples, the element's return mapping with the bound mu N, N = max(0, N0 +
 * kn g) (fricreg_jenkins.h, slider.h), marched to its periodic state, and the coefficients of
 * f and N by GSL's real radix-2 FFT (aft_sampled.c's).
 *
 * The periodic state. Where the contact opens in the period (N0 + kn g < 0 at some sample) the
 * slider follows u there (memory reset), so a march of one period from the last open sample
 * is periodic. Otherwise the bound moves with g and the play operator's wiping-out need not
 * hold at the maximum of u: the march starts there as if slipping (w = u_max − mu N/kt), and
 * periods are marched until the slider at the start repeats to the bit (a period that slips
 * in both directions forgets its start; MAX_PERIODS bounds the march). A period with no slip
 * and no opening sticks throughout (or slips one way only, which at the periodic state has no
 * length), and its state is not unique: the centred slider
 * w = (max u + min u)/2 is taken where it holds (as fricreg_aft_jenkins_sampled does, which
 * this function equals to the bit when kn = 0), else the stuck slider nearest it (the march's
 * least one, or the greatest, min_n u_n + mu N_n/kt), continuous as the centre leaves them.
 *
 * The Jacobian by the chain rule through the samples, with φ_j the basis at a sample: in a
 * stick anchored at the sample m where the slider last moved, f_n = kt (u_n − u_m) + f_m, with
 * f_m = s mu N_m after a slip (∂f_n/∂g_j = s mu kn φ_j(m)) and f_m = 0 after an opening; in a
 * slip f_n = s mu N_n (∂/∂u = 0, ∂f_n/∂g_j = s mu kn φ_j(n)); open, 0. ∂N_n/∂g_j = kn φ_j(n)
 * on the closed side (N0 + kn g_n >= 0), else 0. Each column goes through the FFT. */
#include <math.h>
#include <string.h>

#include "aft_internal.h"
#include "slider.h"

#define MAX_PERIODS 16 /* periods marched in search of the periodic state without opening */
#define OPEN (-1.0)    /* a sample's tangent mark when the contact is open */

void fr_aft_sample_values(const fricreg_aft *a, const double *c, double *x)
{
    for (size_t n = 0; n < a->N; n++) {
        double v = c[0];
        for (int h = 1; h <= a->H; h++) {
            size_t idx = ((size_t)h * n) & (a->N - 1); /* N is a power of two */
            v += c[2 * h - 1] * a->ctab[idx] + c[2 * h] * a->stab[idx];
        }
        x[n] = v;
    }
}

/* The fraction of the interval from the open sample m to the closed sample n where the
 * contact closes (N0 + kn g linear on it crosses 0): there the slider is where u is, as in
 * aft_2d.c, rather than at u of the last open sample, whose moves would change the forces'
 * slope in the inputs (test_aft_2d.c, smooth_between_events). */
static double closing_fraction(const double *gap, size_t m, size_t n)
{
    return gap[m] / (gap[m] - gap[n]);
}

/* One step of the march at sample n from the slider w: the force into a->fs[n], the tangent
 * mark into a->ts[n] (kt stick, 0 slip, OPEN), and the anchor into a->anchor[n] (n where the
 * slider moved, else *m). Returns the new slider. */
static double step(fricreg_aft *a, double kt, double mu, const double *gap, const double *load,
                   size_t n, double w, size_t *m)
{
    double f, wn, t;
    if (gap[n] < 0.0) { /* open: the slider follows u, the memory reset */
        fr_slider_separated(1, &a->us[n], &f, &wn, &t, NULL);
        t = OPEN;
        *m = n;
    } else {
        size_t before = (n + a->N - 1) % a->N;
        if (gap[before] < 0.0) /* closed again after it */
            w = a->us[before] + closing_fraction(gap, before, n) * (a->us[n] - a->us[before]);
        fr_slider_return(kt, mu * load[n], 0.0, 1, &a->us[n], &w, &f, &wn, &t, NULL);
        if (t == 0.0)
            *m = n;
    }
    a->fs[n] = f;
    a->ts[n] = t;
    a->anchor[n] = *m;
    return wn;
}

/* March one period from sample start (exclusive) around to it (inclusive) with the slider
 * *w and anchor *m; returns the directions slipped (1: positive, 2: negative, 3: both or an
 * opening). */
static int period(fricreg_aft *a, double kt, double mu, const double *gap, const double *load,
                  size_t start, double *w, size_t *m)
{
    int moved = 0;
    for (size_t i = 1; i <= a->N; i++) {
        size_t n = (start + i) % a->N;
        *w = step(a, kt, mu, gap, load, n, *w, m);
        if (a->ts[n] == OPEN)
            moved = 3;
        else if (a->ts[n] == 0.0)
            moved |= a->fs[n] > 0.0 ? 1 : 2;
    }
    return moved;
}

/* The greatest stuck slider, w = u + mu N/kt at sample nhi (the least of those): a stick
 * anchored there as after a negative slip, f = kt (u − w), the sample itself on the bound. */
static void pin_at_greatest(fricreg_aft *a, double kt, double mu, const double *load, size_t nhi)
{
    double w = a->us[nhi] + mu * load[nhi] / kt;
    for (size_t n = 0; n < a->N; n++) {
        a->fs[n] = kt * (a->us[n] - w);
        a->ts[n] = kt;
        a->anchor[n] = nhi;
    }
    a->fs[nhi] = -mu * load[nhi];
    a->ts[nhi] = 0.0;
}

/* The periodic march (header comment); returns the centred slider's extremes in *nmax, *nmin
 * when the centred rule was taken (anchor N), else leaves them. */
static void march(fricreg_aft *a, double kt, double mu, const double *gap, const double *load,
                  size_t *nmax, size_t *nmin)
{
    size_t N = a->N, open = N;
    for (size_t n = 0; n < N; n++) {
        if (gap[n] < 0.0)
            open = n;
        if (a->us[n] > a->us[*nmax])
            *nmax = n;
        if (a->us[n] < a->us[*nmin])
            *nmin = n;
    }
    if (open < N) { /* one period from the last opening is periodic */
        double w = a->us[open];
        size_t m = open;
        period(a, kt, mu, gap, load, open, &w, &m);
        return;
    }
    double w = a->us[*nmax] - mu * load[*nmax] / kt;
    size_t m = *nmax;
    int moved = 1;
    for (int p = 0; p < MAX_PERIODS; p++) {
        double w0 = w;
        moved = period(a, kt, mu, gap, load, *nmax, &w, &m);
        if (w == w0)
            break;
    }
    if (moved == 3)
        return;
    /* stuck, or slipping one way only: at the periodic state such a slip has no length (the
     * slider only touches the bound; a net slip would move it from period to period), and the
     * slider is a leftover of the start: the centred slider where it holds, else the stuck
     * slider nearest it (aft_normal_exact.c: the march's is the least, lo) */
    double wc = 0.5 * (a->us[*nmax] + a->us[*nmin]), top = 0.0;
    size_t nhi = N; /* where the centre lies farthest above u + mu N/kt */
    for (size_t n = 0; n < N; n++) {
        if (!(kt * (a->us[n] - wc) <= mu * load[n]))
            return; /* below the least stuck slider: the march's */
        double over = kt * (wc - a->us[n]) - mu * load[n];
        if (!(over <= top)) {
            top = over;
            nhi = n;
        }
    }
    if (nhi < N) {
        pin_at_greatest(a, kt, mu, load, nhi);
        return;
    }
    for (size_t n = 0; n < N; n++) {
        a->fs[n] = kt * (a->us[n] - wc);
        a->anchor[n] = N;
    }
}

static double sign(double x)
{
    return (double)((x > 0.0) - (x < 0.0));
}

/* Column j of the Jacobian in time: d f/d u_j (wrt_g = 0) or d f/d g_j (wrt_g = 1) into col. */
static void jacobian_column(const fricreg_aft *a, double kt, double mu, double kn, size_t j,
                            int wrt_g, size_t nmax, size_t nmin, double *col)
{
    const double *gap = a->ds; /* fr_aft_sampled_normal's layout */
    size_t N = a->N;
    for (size_t n = 0; n < N; n++) {
        double t = a->ts[n], v = 0.0;
        size_t m = a->anchor[n];
        if (t == OPEN) {
            v = 0.0;
        } else if (t == 0.0) { /* slip: f = s mu N */
            v = wrt_g ? sign(a->fs[n]) * mu * kn * fr_aft_sample_basis(a, j, n) : 0.0;
        } else if (m == N) { /* the centred stick */
            v = wrt_g
                    ? 0.0
                    : kt * (fr_aft_sample_basis(a, j, n) - 0.5 * (fr_aft_sample_basis(a, j, nmax) +
                                                                  fr_aft_sample_basis(a, j, nmin)));
        } else if (a->ts[m] == OPEN) { /* stick after the contact closed in (m, m1) */
            size_t m1 = (m + 1) % N;
            double tau = closing_fraction(gap, m, m1), q = gap[m] - gap[m1];
            double pm = fr_aft_sample_basis(a, j, m), p1 = fr_aft_sample_basis(a, j, m1);
            v = wrt_g ? -kt * (a->us[m1] - a->us[m]) * kn * (gap[m] * p1 - gap[m1] * pm) / (q * q)
                      : kt * (fr_aft_sample_basis(a, j, n) - (1.0 - tau) * pm - tau * p1);
        } else if (wrt_g) { /* stick after a slip at m */
            v = a->ts[m] == 0.0 ? sign(a->fs[m]) * mu * kn * fr_aft_sample_basis(a, j, m) : 0.0;
        } else {
            v = kt * (fr_aft_sample_basis(a, j, n) - fr_aft_sample_basis(a, j, m));
        }
        col[n] = v;
    }
}

void fr_aft_sampled_normal(fricreg_aft *a, double kt, double mu, double n0, double kn,
                           const double *u, const double *g, double *f, double *nf, double *jac)
{
    size_t N = a->N, nc = a->nc;
    /* ds holds nc >= 3 columns of N: the gap N0 + kn g, the normal force, and a column */
    double *gap = a->ds, *load = a->ds + N, *col = a->ds + 2 * N;
    fr_aft_sample_values(a, u, a->us);
    fr_aft_sample_values(a, g, gap);
    for (size_t n = 0; n < N; n++) {
        gap[n] = n0 + kn * gap[n];
        load[n] = fmax(0.0, gap[n]);
    }
    size_t nmax = 0, nmin = 0;
    march(a, kt, mu, gap, load, &nmax, &nmin);
    if (jac != NULL) {
        size_t w = 2 * nc;
        memset(jac, 0, w * w * sizeof *jac);
        for (size_t j = 0; j < nc; j++) {
            jacobian_column(a, kt, mu, kn, j, 0, nmax, nmin, col);
            fr_aft_sample_coefficients(a, col, &jac[j], w);
            jacobian_column(a, kt, mu, kn, j, 1, nmax, nmin, col);
            fr_aft_sample_coefficients(a, col, &jac[nc + j], w);
            for (size_t n = 0; n < N; n++)
                col[n] = gap[n] >= 0.0 ? kn * fr_aft_sample_basis(a, j, n) : 0.0;
            fr_aft_sample_coefficients(a, col, &jac[nc * w + nc + j], w);
        }
    }
    memcpy(col, load, N * sizeof *col);
    fr_aft_sample_coefficients(a, col, a->jout, 1); /* N's coefficients, held in jout */
    fr_aft_sample_coefficients(a, a->fs, a->fout, 1);
    memcpy(f, a->fout, nc * sizeof *f);
    memcpy(nf, a->jout, nc * sizeof *nf);
}
