/* SPDX-License-Identifier: GPL-3.0-or-later */
/* aft_exact.c — the exact AFT of 1-D Jenkins sliders (fricreg_aft.h): the march of each slider
 * over the stabilized period between the switch points (aft_roots.c), the force integrated
 * piece by piece in closed form; and the march's slip intervals (aft_slips.h).
 *
 * The march starts at the global maximum with the slider at max u − r, r = mun/kt (the play
 * operator's wiping-out property: the state every history reaches there once the range
 * exceeds 2r), so one period is the stabilized one. Between two reversals u is monotone with
 * direction s: the slider sticks, f = kt (u − w), until kt (u − w) = s mun, the root of
 * u(θ) − (w + s r) inside the interval (unique and bracketed there: GSL's Brent, not another
 * companion solve, which cost five times as much at H = 7), then slips, f = s mun, to the next
 * reversal, where it stops at w = u − s r.
 *
 * Integrals. On a piece [α, β] with centre μ and half-width δ,
 *     ∫ cos mθ = 2 cos(mμ) sin(mδ)/m,   ∫ sin mθ = 2 sin(mμ) sin(mδ)/m
 * (no cancellation on a short piece), and the products of the basis by the sum-to-product
 * rules: the piece's Gram matrix G_ij = ∫ φ_i φ_j. A stick piece adds kt G (u − w e_0) to the
 * coefficients and kt (G_ij − φ_j(θ_w) G_i0) to the Jacobian (θ_w the reversal where the
 * slider stopped, u'(θ_w) = 0, so ∂w/∂u_j = φ_j(θ_w)); a slip piece adds s mun G_i0. */
#include <math.h>
#include <string.h>

#include "aft_internal.h"
#include "aft_roots.h"
#include "aft_slips.h"
#include "base/fr_math.h"

/* The Gram matrix of the basis over [al, be] into a->gram, and the integrals of cos, sin. */
void fr_aft_gram(fricreg_aft *a, double al, double be)
{
    int H = a->H, M = 2 * H;
    size_t w = a->nc;
    double mu = 0.5 * (al + be), de = 0.5 * (be - al), *cm = a->cm, *sm = a->sm, *G = a->gram;
    cm[0] = be - al;
    sm[0] = 0.0;
    for (int m = 1; m <= M; m++) {
        double q = 2.0 * sin(m * de) / m;
        cm[m] = cos(m * mu) * q;
        sm[m] = sin(m * mu) * q;
    }
    G[0] = cm[0];
    for (int h = 1; h <= H; h++) {
        G[2 * h - 1] = G[w * (size_t)(2 * h - 1)] = cm[h];
        G[2 * h] = G[w * (size_t)(2 * h)] = sm[h];
        for (int k = 1; k <= H; k++) {
            int dd = h > k ? h - k : k - h;
            double sgn = h > k ? 1.0 : (h < k ? -1.0 : 0.0);
            size_t ck = (size_t)(2 * k - 1), sk = (size_t)(2 * k);
            size_t ch = (size_t)(2 * h - 1), shh = (size_t)(2 * h);
            G[w * ck + ch] = 0.5 * (cm[dd] + cm[h + k]);        /* cos k cos h */
            G[w * sk + shh] = 0.5 * (cm[dd] - cm[h + k]);       /* sin k sin h */
            G[w * ck + shh] = 0.5 * (sm[h + k] + sgn * sm[dd]); /* cos k sin h */
            G[w * sk + ch] = 0.5 * (sm[h + k] - sgn * sm[dd]);  /* sin k cos h */
        }
    }
}

/* Weight of coefficient i: 1/(2 pi) for the mean, 1/pi for the harmonics. */
double fr_aft_weight(size_t i)
{
    return i == 0 ? 1.0 / FR_TWO_PI : 2.0 / FR_TWO_PI;
}

/* A stick piece [al, be], f = kt u − kw (kw = kt w), the slider stopped at thw. */
void fr_aft_add_stick(fricreg_aft *a, double kt, const double *u, double kw, double thw, double al,
                      double be, int want_jac)
{
    size_t w = a->nc;
    fr_aft_gram(a, al, be);
    const double *G = a->gram;
    for (size_t i = 0; i < w; i++) {
        double s = 0.0;
        for (size_t j = 0; j < w; j++)
            s += G[w * i + j] * u[j];
        a->fout[i] += fr_aft_weight(i) * (kt * s - G[w * i] * kw);
    }
    if (!want_jac)
        return;
    fr_aft_basis(a->H, thw, a->phw);
    for (size_t i = 0; i < w; i++)
        for (size_t j = 0; j < w; j++)
            a->jout[w * i + j] += fr_aft_weight(i) * kt * (G[w * i + j] - a->phw[j] * G[w * i]);
}

/* A slip piece [al, be], f = fs constant. */
static void add_slip(fricreg_aft *a, double fs, double al, double be)
{
    fr_aft_gram(a, al, be);
    for (size_t i = 0; i < a->nc; i++)
        a->fout[i] += fr_aft_weight(i) * fs * a->gram[a->nc * i];
}

/* Where one slider's march puts its pieces: into the force and, with want_jac, the Jacobian
 * (slips NULL), or as slip intervals into slips (fr_aft_exact_slips). */
struct march_sink {
    int want_jac;
    struct fr_aft_slips *slips;
};

/* The reversals of u's global maximum (imax) and minimum (imin). */
static void extreme_reversals(fricreg_aft *a, const double *u, int m, int *imax, int *imin)
{
    double d;
    *imax = *imin = 0;
    for (int i = 1; i < m; i++) {
        if (fr_aft_trig_eval(a->H, u, a->rev[i], &d) > fr_aft_trig_eval(a->H, u, a->rev[*imax], &d))
            *imax = i;
        if (fr_aft_trig_eval(a->H, u, a->rev[i], &d) < fr_aft_trig_eval(a->H, u, a->rev[*imin], &d))
            *imin = i;
    }
}

/* A slip piece [th, be] recorded, its angles reduced to [0, 2 pi). */
static void record_slip(struct fr_aft_slips *slips, double th, double be)
{
    slips->on[slips->count] = th >= FR_TWO_PI ? th - FR_TWO_PI : th;
    slips->off[slips->count] = be >= FR_TWO_PI ? be - FR_TWO_PI : be;
    slips->count++;
}

/* The stabilized march of one slider (kt, mun > 0 resolved, not stuck: kt (umax − umin) >
 * 2 mun) over the m reversals from the global maximum imax. */
static void slider_march(fricreg_aft *a, const double *u, int m, int imax, double kt, double mun,
                         struct march_sink sink)
{
    double d, r = mun / kt, thw = a->rev[imax], wv = fr_aft_trig_eval(a->H, u, thw, &d) - r;
    for (int i = 0; i < m; i++) {
        int ia = (imax + i) % m, ib = (ia + 1) % m, dir = a->rdir[ia];
        double al = a->rev[ia], be = a->rev[ib];
        if (be <= al)
            be += FR_TWO_PI;
        double target = wv + dir * r, ub = fr_aft_trig_eval(a->H, u, be, &d), th = be;
        int slips = dir * (ub - target) > 0.0; /* else sticks to the next reversal */
        if (slips)
            th = fr_aft_slip_onset(a, u, target, dir, al, be);
        if (sink.slips == NULL)
            fr_aft_add_stick(a, kt, u, kt * wv, thw, al, th, sink.want_jac);
        if (!slips)
            continue;
        if (sink.slips != NULL)
            record_slip(sink.slips, th, be);
        else
            add_slip(a, dir * mun, th, be);
        wv = ub - dir * r;
        thw = be;
    }
}

/* The sliders that stick in the rounding of u (UNRESOLVED_STICK): they slip throughout. */
static int unresolved(const double *u, size_t nc, double kt, double mun)
{
    double usum = 0.0;
    for (size_t j = 0; j < nc; j++)
        usum += fabs(u[j]);
    return mun <= UNRESOLVED_STICK * (kt * usum);
}

/* The centred slider stuck over the whole period: f = kt (u − (umax + umin)/2). */
static void add_stuck(fricreg_aft *a, double kt, const double *u, double thmax, double thmin,
                      double umax, double umin, int want_jac)
{
    size_t w = a->nc;
    a->fout[0] += kt * (u[0] - 0.5 * (umax + umin));
    for (size_t j = 1; j < w; j++)
        a->fout[j] += kt * u[j];
    if (!want_jac)
        return;
    fr_aft_basis(a->H, thmax, a->phw);
    for (size_t j = 1; j < w; j++)
        a->jout[j] -= 0.5 * kt * a->phw[j];
    fr_aft_basis(a->H, thmin, a->phw);
    for (size_t j = 1; j < w; j++) {
        a->jout[j] -= 0.5 * kt * a->phw[j];
        a->jout[w * j + j] += kt;
    }
}

int fr_aft_exact(fricreg_aft *a, const char *fn, size_t ns, const double *k, const double *phi,
                 const double *u, int want_jac)
{
    size_t w = a->nc;
    memset(a->fout, 0, w * sizeof *a->fout);
    memset(a->jout, 0, w * w * sizeof *a->jout);
    int m, status = fr_aft_reversals(a, fn, u, &m);
    if (status != FRICREG_OK)
        return status;
    if (m == 0) { /* constant u: f = 0, the stick tangent on the harmonics */
        for (size_t s = 0; s < ns; s++)
            if (phi[s] > 0.0)
                for (size_t j = 1; j < w; j++)
                    a->jout[w * j + j] += k[s];
        return FRICREG_OK;
    }
    int imax, imin;
    extreme_reversals(a, u, m, &imax, &imin);
    double d, thmax = a->rev[imax], thmin = a->rev[imin];
    double umax = fr_aft_trig_eval(a->H, u, thmax, &d), umin = fr_aft_trig_eval(a->H, u, thmin, &d);
    for (size_t s = 0; s < ns; s++) {
        double kt = k[s], mun = phi[s];
        if (mun == 0.0)
            continue;
        if (unresolved(u, w, kt, mun)) { /* sticks in the rounding of u: none */
            for (int i = 0; i < m; i++) {
                double al = a->rev[i], be = a->rev[(i + 1) % m];
                add_slip(a, a->rdir[i] * mun, al, be <= al ? be + FR_TWO_PI : be);
            }
        } else if (kt * (umax - umin) <= 2.0 * mun) {
            add_stuck(a, kt, u, thmax, thmin, umax, umin, want_jac);
        } else {
            slider_march(a, u, m, imax, kt, mun, (struct march_sink){want_jac, NULL});
        }
    }
    return FRICREG_OK;
}

int fr_aft_exact_slips(fricreg_aft *a, const char *fn, double kt, double mun, const double *u,
                       struct fr_aft_slips *slips)
{
    int m, status = fr_aft_reversals(a, fn, u, &m);
    if (status != FRICREG_OK)
        return status;
    slips->count = 0;
    if (mun == 0.0 || (m > 0 && unresolved(u, a->nc, kt, mun))) {
        slips->kind = FR_AFT_SLIDES;
        return FRICREG_OK;
    }
    slips->kind = FR_AFT_STUCK;
    if (m == 0)
        return FRICREG_OK;
    int imax, imin;
    extreme_reversals(a, u, m, &imax, &imin);
    double d, umax = fr_aft_trig_eval(a->H, u, a->rev[imax], &d);
    if (kt * (umax - fr_aft_trig_eval(a->H, u, a->rev[imin], &d)) <= 2.0 * mun)
        return FRICREG_OK;
    slider_march(a, u, m, imax, kt, mun, (struct march_sink){0, slips});
    slips->kind = slips->count > 0 ? FR_AFT_SLIPS : FR_AFT_STUCK;
    return FRICREG_OK;
}
