/* SPDX-License-Identifier: GPL-3.0-or-later */
/* aft_sampled.c — the sampled AFT of 1-D Jenkins sliders (fricreg_aft.h): u at N equidistant
 * samples, each slider's return mapping (slider.h, the one the Jenkins and Iwan elements use)
 * marched over one period, the coefficients by GSL's real radix-2 FFT.
 *
 * The march starts at the sampled maximum of u with the slider at u_max − r (r = mun/kt):
 * the return mapping on samples is the play operator on them, whose wiping-out property puts
 * the slider there after any history that has visited the sampled minimum and maximum, when
 * kt (u_max − u_min) > 2 mun; so one period is already the stabilized one (NLvib marches two
 * periods from a relaxed spring and reaches the same state). Otherwise the slider is centred,
 * w = (u_max + u_min)/2, the exact path's rule on the samples.
 *
 * The Jacobian by the chain rule: at sample n a slider in a stick has f = kt (u_n − w) with w
 * set at its last slip sample m (w = u_m − s r), so ∂f_n/∂u_j = kt (φ_j(θ_n) − φ_j(θ_m)); in a
 * slip ∂f_n/∂u_j = 0 (the 1-D tangent of slider.h); centred, φ_j(θ_m) is replaced by the mean
 * of φ_j at the sampled maximum and minimum. Each column, summed over the sliders, goes
 * through the same FFT as f. */
#include <float.h>
#include <math.h>
#include <string.h>

#include <gsl/gsl_fft_real.h>

#include "aft_internal.h"
#include "slider.h"

double fr_aft_sample_basis(const fricreg_aft *a, size_t j, size_t n)
{
    if (j == 0)
        return 1.0;
    size_t h = (j + 1) / 2, idx = (h * n) & (a->N - 1); /* N is a power of two */
    return (j % 2) ? a->ctab[idx] : a->stab[idx];
}

/* Called with N a power of two (checked at create): GSL has nothing to report. The transform's
 * sums are divided by N after it, except where N samples could overflow them (a Jacobian
 * column of kn = 1.8e308 did): then the samples are divided before. Exact either way (a power
 * of two) but in the subnormals, where dividing first would lose the small samples' digits. */
void fr_aft_sample_coefficients(const fricreg_aft *a, double *x, double *out, size_t stride)
{
    size_t N = a->N;
    double big = 0.0, scale = 1.0 / (double)N, after = scale;
    for (size_t n = 0; n < N; n++) /* x is finite: a comparison, not libm's fmax */
        big = fabs(x[n]) > big ? fabs(x[n]) : big;
    if (big > 0.25 * DBL_MAX * scale) {
        for (size_t n = 0; n < N; n++)
            x[n] *= scale;
        after = 1.0;
    }
    gsl_fft_real_radix2_transform(x, 1, N);
    out[0] = x[0] * after;
    for (int h = 1; h <= a->H; h++) {
        out[(size_t)(2 * h - 1) * stride] = 2.0 * x[h] * after;
        out[(size_t)(2 * h) * stride] = -2.0 * x[N - (size_t)h] * after;
    }
}

/* One slider's march: its force added into a->fs, its tangent into a->ts and its anchors
 * into a->anchor (N for the centred stick). */
static void march(fricreg_aft *a, double kt, double mun, size_t nmax, size_t nmin)
{
    size_t N = a->N;
    double *us = a->us, r = mun / kt;
    if (kt * (us[nmax] - us[nmin]) <= 2.0 * mun) {
        double wc = 0.5 * (us[nmax] + us[nmin]);
        for (size_t n = 0; n < N; n++) {
            a->fs[n] += kt * (us[n] - wc);
            a->ts[n] = kt;
            a->anchor[n] = N;
        }
        return;
    }
    double w = us[nmax] - r, f, wn, t;
    size_t m = nmax;
    for (size_t i = 1; i <= N; i++) {
        size_t n = (nmax + i) % N;
        fr_slider_return(kt, mun, 0.0, 1, &us[n], &w, &f, &wn, &t, NULL);
        if (t == 0.0) /* slipped: the slider stops here */
            m = n;
        w = wn;
        a->fs[n] += f;
        a->ts[n] = t;
        a->anchor[n] = m;
    }
}

void fr_aft_sampled(fricreg_aft *a, size_t ns, const double *k, const double *phi, const double *u,
                    int want_jac)
{
    size_t N = a->N, w = a->nc;
    int H = a->H;
    size_t nmax = 0, nmin = 0;
    for (size_t n = 0; n < N; n++) {
        double v = u[0];
        for (int h = 1; h <= H; h++) {
            size_t idx = ((size_t)h * n) % N;
            v += u[2 * h - 1] * a->ctab[idx] + u[2 * h] * a->stab[idx];
        }
        a->us[n] = v;
        if (v > a->us[nmax])
            nmax = n;
        if (v < a->us[nmin])
            nmin = n;
    }
    memset(a->fs, 0, N * sizeof *a->fs);
    if (want_jac)
        memset(a->ds, 0, w * N * sizeof *a->ds);
    for (size_t s = 0; s < ns; s++) {
        if (phi[s] == 0.0)
            continue;
        march(a, k[s], phi[s], nmax, nmin);
        if (!want_jac)
            continue;
        for (size_t j = 1; j < w; j++) {
            double *col = &a->ds[N * j];
            /* a constant u (nmax = nmin): the exact path's tangent, kt on the harmonics */
            double centred = nmax == nmin ? 0.0
                                          : 0.5 * (fr_aft_sample_basis(a, j, nmax) +
                                                   fr_aft_sample_basis(a, j, nmin));
            for (size_t n = 0; n < N; n++) {
                if (a->ts[n] == 0.0)
                    continue;
                double anchor = a->anchor[n] == N ? centred
                                                  : fr_aft_sample_basis(a, j, a->anchor[n]);
                col[n] += a->ts[n] * (fr_aft_sample_basis(a, j, n) - anchor);
            }
        }
    }
    fr_aft_sample_coefficients(a, a->fs, a->fout, 1);
    if (!want_jac)
        return;
    memset(a->jout, 0, w * w * sizeof *a->jout); /* column 0: u0 moves f nowhere */
    for (size_t j = 1; j < w; j++)
        fr_aft_sample_coefficients(a, &a->ds[N * j], &a->jout[j], w);
}
