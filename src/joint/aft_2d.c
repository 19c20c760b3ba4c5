/* SPDX-License-Identifier: GPL-3.0-or-later */
/* aft_2d.c — the sampled AFT of the 3-D contact element (fricreg_aft_jenkins_2d_normal_sampled):
 * a 2-D Jenkins element in the tangential plane (isotropic Coulomb disk, radial return; slider.h)
 * under the normal law N = max(0, N0 + kn g) with lift-off, the tangential displacement (ux, uy)
 * and the normal one g at N equidistant samples, the element marched to its periodic state, and
 * the coefficients of fx, fy and N by GSL's real radix-2 FFT (aft_sampled.c's).
 *
 * The periodic state. The radial return is the projection of the slider onto the disk of
 * radius mu N_n / kt about u_n, so a period is a cycle of projections onto convex sets: where
 * the disks have a common point the march ends in a stick throughout (any common point is a
 * periodic state), otherwise in a unique periodic slip.
 *   - The contact opens in the period: the slider follows u while open, so one period from the
 *     last open sample is periodic (as aft_normal.c), the contact closing between samples.
 *   - Closed throughout: the march starts from the centre of the smallest circle enclosing the
 *     sampled orbit of u (the stuck state of every sample at the threshold of slip, and in 1-D
 *     the centred slider of aft_normal.c, so that the force is continuous across that
 *     threshold) and marches up to PLAIN periods. A period without slip ends it (stuck). A
 *     slip that has not repeated to the bit by then is a slow contraction (a slip barely past
 *     the threshold), and Newton's method on the slider at the period's start, w = Phi(w)
 *     with Phi's 2 x 2 derivative from the chain below, finds it.
 *
 * The Jacobian by the chain rule through the samples, carrying dw, the slider's derivative
 * along one input column (a coefficient of ux, uy or g): open, dw = du, df = 0; stick,
 * df = kt (du - dw); slip, with d = u - w, e = d/|d| and T = (mu N/|d|)(I - e e^T) (slider.h),
 * df = T (du - dw) + mu kn dg e and dw = du - df/kt; dN = kn dg where closed. At a periodic
 * slip, dw at the start solves (I - Psi) dw = Phi_u (Psi = dPhi/dw, the product of the slips'
 * T/kt, a contraction); a march opened in the period starts at du of the last open sample; a
 * stick from the circle's centre at that centre's derivative, carried through the slips of the
 * periods before it where there were some (the march is run again for each column); a stick
 * that Newton's steps reached holds its slider (dw = 0). One-sided at the samples' switches,
 * as aft_normal.c's. */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "aft_internal.h"
#include "enclosing_circle.h"
#include "slider.h"

#define PLAIN 4       /* periods marched from the enclosing circle's centre before Newton */
#define MAX_NEWTON 40 /* Newton steps on the periodic slider */

enum { STICK, SLIP, OPEN };

/* The samples of one call, in the workspace's buffers (aft.c: 8 N beside the 1-D ones). */
struct samples {
    const double *ux, *uy, *gap, *load; /* u, N0 + kn g, N */
    double *fx, *fy;                    /* the forces of the last period marched */
    double *ex, *ey, *sl;               /* a slip's direction e and mu N/|d| */
    double *kind;                       /* STICK, SLIP or OPEN */
    size_t N;
};

struct law {
    double kt, mu, kn;
};

static struct samples views(const fricreg_aft *a)
{
    double *b = a->s2;
    size_t N = a->N;
    return (struct samples){.ux = a->us,
                            .uy = b,
                            .gap = b + N,
                            .load = b + 2 * N,
                            .fx = a->fs,
                            .fy = b + 3 * N,
                            .ex = b + 4 * N,
                            .ey = b + 5 * N,
                            .sl = b + 6 * N,
                            .kind = b + 7 * N,
                            .N = N};
}

/* The contact closes between the open sample m and the closed sample n at the fraction
 * tau = gap_m / (gap_m − gap_n) of the interval (N0 + kn g linear on it), the slider there
 * where u is: w = u_m + tau (u_n − u_m). At the sample after the opening instead, the slider
 * would snap to u_m, and the forces' dependence on the inputs would change its slope each
 * time the last open sample moves (test_aft_2d.c's smooth_between_events). */
static double closing(const struct samples *s, size_t m, size_t n, double w[2])
{
    double tau = s->gap[m] / (s->gap[m] - s->gap[n]);
    w[0] = s->ux[m] + tau * (s->ux[n] - s->ux[m]);
    w[1] = s->uy[m] + tau * (s->uy[n] - s->uy[m]);
    return tau;
}

/* One sample of the march from the slider w (updated): forces and the record of sample n. */
static int step(const struct samples *s, const struct law *p, size_t n, double *w)
{
    double u[2] = {s->ux[n], s->uy[n]}, f[2], wn[2];
    if (s->gap[n] < 0.0) { /* open: the slider follows u, the memory reset */
        fr_slider_separated(2, u, f, wn, NULL, NULL);
        s->kind[n] = OPEN;
    } else {
        size_t m = (n + s->N - 1) & (s->N - 1); /* the sample before */
        if (s->gap[m] < 0.0) /* closed again after m: the slider where the contact closed */
            closing(s, m, n, w);
        double b = p->mu * s->load[n], d[2] = {u[0] - w[0], u[1] - w[1]};
        double r = fr_slider_norm(d, 2);
        fr_slider_return(p->kt, b, 0.0, 2, u, w, f, wn, NULL, NULL);
        s->kind[n] = p->kt * r <= b ? STICK : SLIP; /* slider.h's test */
        if (s->kind[n] == SLIP) {
            s->ex[n] = d[0] / r;
            s->ey[n] = d[1] / r;
            s->sl[n] = b / r;
        }
    }
    s->fx[n] = f[0];
    s->fy[n] = f[1];
    w[0] = wn[0];
    w[1] = wn[1];
    return (int)s->kind[n];
}

/* March one period from sample start (exclusive) around to it (inclusive); returns whether the
 * slider slipped. */
static int period(const fricreg_aft *a, const struct samples *s, const struct law *p, size_t start,
                  double *w)
{
    int slipped = 0;
    for (size_t i = 1; i <= a->N; i++)
        slipped |= step(s, p, (start + i) & (a->N - 1), w) == SLIP;
    return slipped;
}

/* One input column: the derivatives of u and g at sample n along column j of the 3 nc inputs
 * (ux, uy, g); j = SIZE_MAX: none (the slider's own sensitivity). */
static void input(const fricreg_aft *a, size_t j, size_t n, double du[2], double *dg)
{
    size_t nc = a->nc;
    double phi = j == SIZE_MAX ? 0.0 : fr_aft_sample_basis(a, j % nc, n);
    du[0] = j < nc ? phi : 0.0;
    du[1] = j >= nc && j < 2 * nc ? phi : 0.0;
    *dg = j >= 2 * nc && j != SIZE_MAX ? phi : 0.0;
}

/* The derivative at sample n along column j on its record: dw updated, df (fx, fy, N) out. */
static void chain_sample(const fricreg_aft *a, const struct samples *s, const struct law *p,
                         size_t n, size_t j, double *dw, double df[3])
{
    double du[2], dg;
    input(a, j, n, du, &dg);
    df[0] = df[1] = 0.0;
    df[2] = s->kind[n] == OPEN ? 0.0 : p->kn * dg;
    size_t m = (n + a->N - 1) & (a->N - 1);
    if (s->kind[n] != OPEN && s->gap[m] < 0.0) { /* closed in the interval: closing()'s w */
        double dum[2], dgm, w[2], gm = s->gap[m], gn = s->gap[n];
        input(a, j, m, dum, &dgm);
        double tau = closing(s, m, n, w), q = gm - gn;
        double dtau = p->kn * (gm * dg - gn * dgm) / (q * q);
        dw[0] = dum[0] + tau * (du[0] - dum[0]) + (s->ux[n] - s->ux[m]) * dtau;
        dw[1] = dum[1] + tau * (du[1] - dum[1]) + (s->uy[n] - s->uy[m]) * dtau;
    }
    if (s->kind[n] == OPEN) {
        dw[0] = du[0];
        dw[1] = du[1];
    } else if (s->kind[n] == STICK) {
        df[0] = p->kt * (du[0] - dw[0]);
        df[1] = p->kt * (du[1] - dw[1]);
    } else {
        double e[2] = {s->ex[n], s->ey[n]}, v[2] = {du[0] - dw[0], du[1] - dw[1]};
        double ev = e[0] * v[0] + e[1] * v[1], dmu = p->mu * p->kn * dg;
        for (int c = 0; c < 2; c++) {
            df[c] = s->sl[n] * (v[c] - e[c] * ev) + dmu * e[c];
            dw[c] = du[c] - df[c] / p->kt;
        }
    }
}

static void put(size_t N, size_t n, const double df[3], double *out)
{
    out[n] = df[0];
    out[N + n] = df[1];
    out[2 * N + n] = df[2];
}

/* The derivative of one period along column j from dw (updated) at sample start, on the
 * record of the last period marched; with out, dfx, dfy, dN into out[0, N, 2N]. */
static void chain(const fricreg_aft *a, const struct samples *s, const struct law *p, size_t start,
                  size_t j, double *dw, double *out)
{
    size_t N = a->N;
    for (size_t i = 1; i <= N; i++) {
        size_t n = (start + i) & (N - 1); /* N is a power of two */
        double df[3];
        chain_sample(a, s, p, n, j, dw, df);
        if (out != NULL)
            put(N, n, df, out);
    }
}

/* Psi = dPhi/dw of the last period marched, row-major 2 x 2. */
static void monodromy(const fricreg_aft *a, const struct samples *s, const struct law *p,
                      size_t start, double psi[4])
{
    for (int c = 0; c < 2; c++) {
        double dw[2] = {c == 0, c == 1};
        chain(a, s, p, start, SIZE_MAX, dw, NULL);
        psi[c] = dw[0];
        psi[2 + c] = dw[1];
    }
}

/* x = (I - psi)^-1 r. psi is a contraction wherever the period slips, but a slip along a
 * line leaves the direction across it neutral (each slip's T/kt is 1 there to rounding when
 * |d| sits at the bound): I - psi then has rank one to rounding, and x is the pseudo-inverse's
 * solution (A^T r / |A|_F^2 for a rank-one A), the neutral component left out. */
static void solve_periodic(const double psi[4], const double r[2], double x[2])
{
    double a = 1.0 - psi[0], b = -psi[1], c = -psi[2], d = 1.0 - psi[3];
    double det = a * d - b * c, fro2 = a * a + b * b + c * c + d * d;
    if (fabs(det) > 1e-9 * fro2) {
        x[0] = (d * r[0] - b * r[1]) / det;
        x[1] = (a * r[1] - c * r[0]) / det;
    } else if (fro2 > 0.0) {
        x[0] = (a * r[0] + c * r[1]) / fro2;
        x[1] = (b * r[0] + d * r[1]) / fro2;
    } else {
        x[0] = x[1] = 0.0;
    }
}

/* The enclosing circle's centre's derivative along column j (enclosing_circle.h): its support
 * points move with u. */
static void circle_derivative(const fricreg_aft *a, const struct samples *s,
                              const struct fr_circle *k, size_t j, double dc[2])
{
    double dp[3][2], dg;
    for (int i = 0; i < k->nsup; i++)
        input(a, j, k->sup[i], dp[i], &dg);
    fr_circle_centre_derivative(k, s->ux, s->uy, (const double(*)[2])dp, dc);
}

/* ---- the periodic march ------------------------------------------------------------------ */

enum start_kind { FROM_OPENING, STUCK_FROM_CIRCLE, STUCK_ELSEWHERE, PERIODIC_SLIP };

struct periodic {
    enum start_kind kind;
    size_t start; /* the sample the recorded period starts after */
    int periods;  /* STUCK_FROM_CIRCLE: periods marched from the centre */
    struct fr_circle circle;
};

/* Newton's method on the slider at the start of a period, from w (the PLAIN periods' end),
 * left in w; the last period marched from it is recorded. */
static enum start_kind newton(const fricreg_aft *a, const struct samples *s, const struct law *p,
                              double scale, double w[2])
{
    double last = INFINITY;
    for (int it = 0; it < MAX_NEWTON; it++) {
        double w0[2] = {w[0], w[1]}, psi[4], dx[2];
        if (!period(a, s, p, a->N - 1, w))
            return STUCK_ELSEWHERE;
        double r[2] = {w[0] - w0[0], w[1] - w0[1]}, norm = fmax(fabs(r[0]), fabs(r[1]));
        if (norm <= 4.0 * DBL_EPSILON * scale)
            break;
        if (norm < last) { /* Newton's step; where it did not help, the period's own (w = Phi) */
            monodromy(a, s, p, a->N - 1, psi);
            solve_periodic(psi, r, dx);
            w[0] = w0[0] + dx[0];
            w[1] = w0[1] + dx[1];
        }
        last = norm;
    }
    double w0[2] = {w[0], w[1]}; /* the recorded period from the slider found */
    int slipped = period(a, s, p, a->N - 1, w);
    w[0] = w0[0];
    w[1] = w0[1];
    return slipped ? PERIODIC_SLIP : STUCK_ELSEWHERE;
}

static struct periodic march(const fricreg_aft *a, const struct samples *s, const struct law *p)
{
    size_t N = a->N, open = N;
    double scale = 0.0;
    for (size_t n = 0; n < N; n++) {
        if (s->gap[n] < 0.0)
            open = n;
        scale = fmax(scale, fabs(s->ux[n]) + fabs(s->uy[n]) + p->mu * s->load[n] / p->kt);
    }
    struct periodic out = {.start = open};
    if (open < N) {
        out.kind = FROM_OPENING;
        double w[2] = {s->ux[open], s->uy[open]};
        period(a, s, p, open, w);
        return out;
    }
    out.start = N - 1;
    out.circle = fr_enclosing_circle(s->ux, s->uy, a->N);
    double w[2] = {out.circle.c[0], out.circle.c[1]};
    for (out.periods = 1; out.periods <= PLAIN; out.periods++) {
        double w0[2] = {w[0], w[1]};
        if (!period(a, s, p, N - 1, w)) {
            out.kind = STUCK_FROM_CIRCLE;
            return out;
        }
        if (w[0] == w0[0] && w[1] == w0[1]) { /* repeated to the bit */
            out.kind = PERIODIC_SLIP;
            return out;
        }
    }
    out.kind = newton(a, s, p, scale, w);
    return out;
}

/* The slider's derivative at the recorded period's start along column j; psi the recorded
 * period's monodromy (PERIODIC_SLIP). */
static void start_derivative(const fricreg_aft *a, const struct samples *s, const struct law *p,
                             const struct periodic *pm, const double psi[4], size_t j, double dw[2])
{
    double dg;
    switch (pm->kind) {
    case FROM_OPENING: input(a, j, pm->start, dw, &dg); return;
    case STUCK_ELSEWHERE: /* a stick Newton's steps reached: the slider held */
        dw[0] = dw[1] = 0.0;
        return;
    case STUCK_FROM_CIRCLE: circle_derivative(a, s, &pm->circle, j, dw); return;
    case PERIODIC_SLIP: {
        if (j == 0 || j == a->nc) { /* u's mean moves the whole state with it: dw = du */
            input(a, j, pm->start, dw, &dg);
            return;
        }
        double phi_u[2] = {0.0, 0.0};
        chain(a, s, p, pm->start, j, phi_u, NULL);
        solve_periodic(psi, phi_u, dw);
        return;
    }
    }
}

/* A stick reached after slips of the first periods: the march from the circle's centre run
 * again with the derivative along column j (the slips placed the slider), the last period's
 * derivatives into out. Rewrites each sample's record and forces with the same values. */
static void remarch(const fricreg_aft *a, const struct samples *s, const struct law *p,
                    const struct periodic *pm, size_t j, double *out)
{
    size_t N = a->N;
    double w[2] = {pm->circle.c[0], pm->circle.c[1]}, dw[2], df[3];
    circle_derivative(a, s, &pm->circle, j, dw);
    for (int period = 1; period <= pm->periods; period++)
        for (size_t n = 0; n < N; n++) {
            step(s, p, n, w);
            chain_sample(a, s, p, n, j, dw, df);
            if (period == pm->periods)
                put(N, n, df, out);
        }
}

void fr_aft_sampled_2d_normal(fricreg_aft *a, double kt, double mu, double n0, double kn,
                              const double *u, const double *g, double *f, double *nf, double *jac)
{
    size_t N = a->N, nc = a->nc, w3 = 3 * nc;
    double *uy = a->s2, *gap = a->s2 + N, *load = a->s2 + 2 * N; /* views()'s layout */
    fr_aft_sample_values(a, u, a->us);
    fr_aft_sample_values(a, u + nc, uy);
    fr_aft_sample_values(a, g, gap);
    for (size_t n = 0; n < N; n++) {
        gap[n] = n0 + kn * gap[n];
        load[n] = fmax(0.0, gap[n]);
    }
    struct samples s = views(a);
    struct law p = {.kt = kt, .mu = mu, .kn = kn};
    struct periodic pm = march(a, &s, &p);
    int placed = pm.kind == STUCK_FROM_CIRCLE && pm.periods > 1; /* a stick after slips */
    if (jac != NULL) {
        double *col = a->ds, psi[4] = {0.0}; /* 3 N of the nc N */
        if (pm.kind == PERIODIC_SLIP)
            monodromy(a, &s, &p, pm.start, psi);
        for (size_t j = 0; j < w3; j++) {
            double dw[2];
            if (placed) {
                remarch(a, &s, &p, &pm, j, col);
            } else {
                start_derivative(a, &s, &p, &pm, psi, j, dw);
                chain(a, &s, &p, pm.start, j, dw, col);
            }
            /* N moves with g alone: its rows in the u columns are 0 */
            for (size_t r = 0; r < 3; r++)
                if (r < 2 || j >= 2 * nc)
                    fr_aft_sample_coefficients(a, col + r * N, &jac[r * nc * w3 + j], w3);
                else
                    for (size_t i = 0; i < nc; i++)
                        jac[(r * nc + i) * w3 + j] = 0.0;
        }
    }
    double *col = a->ds;
    memcpy(col, s.load, N * sizeof *col);
    memcpy(col + N, s.fy, N * sizeof *col);
    fr_aft_sample_coefficients(a, col, nf, 1);
    fr_aft_sample_coefficients(a, col + N, f + nc, 1);
    fr_aft_sample_coefficients(a, s.fx, f, 1);
}
