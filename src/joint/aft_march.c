/* SPDX-License-Identifier: GPL-3.0-or-later */
/* aft_march.c — the sampled AFT of any element type (aft_march.h): u at N equidistant samples
 * of the period, the type's fricreg_element_eval marched over them from the centred state at
 * theta = 0 until the state at a period's end equals its start (to 2^-46 of the largest u or
 * state), and the last period's forces to coefficients
 * by GSL's real radix-2 FFT (aft_sampled.c's fr_aft_sample_coefficients), as NLvib's AFT
 * marches a hysteretic law (Krack & Gross, Harmonic Balance for Nonlinear Vibration Problems,
 * 2019, Sec. 3.3; it marches two periods). A state still moving after PLAIN periods is a slow
 * contraction (a 2-D slider barely past slip): with at most MAX_NEWTON_STATES states, Newton's
 * method on the fixed point s = P(s) of the period map P, its derivative by forward
 * differences and LAPACK's dgesv, finds it (as aft_2d.c does with its own chain); otherwise,
 * or if Newton fails, the march goes on to MAX_PERIODS periods and gives its last.
 *
 * The centred state: a slider stuck all period has a periodic state wherever it sits, so the
 * march chooses by where it starts. It starts every slider at the middle of the orbit (the
 * table's laws hold their sliders' positions as state, element_kind.h): for two tangential
 * components the centre of the orbit's smallest enclosing circle (enclosing_circle.h), the one
 * place from which a slider that can stick never slips, and the 3-D contact's choice
 * (aft_2d.c); for one, its (max + min) / 2, the exact 1-D AFT's choice (aft_exact.c); for
 * three, each component's (max + min) / 2. It then equals those AFTs where the slider sticks.
 * A slider that slips leaves the middle for its own periodic state, which is unique; one that
 * barely slips sits near it, so the forces are continuous in u through the onset of stick.
 *
 * The Jacobian, exact for the sampled march: a law without state has f(theta_n) = f(u(theta_n)),
 * so column j of component d2 is the transform of df/du_d2 (theta_n) phi_j(theta_n). A law with
 * state is Jenkins sliders (element_kind.h), whose force f_s depends on u - w_s alone: from each
 * sample's slider tangents t_s = d f_s / d u and T_s = d w_s' / d w_s (the kind's
 * slider_tangents), the sensitivity S_s = d w_s / d u of every slider's position to u's
 * coefficients goes forward with the march, V = Phi_n - S_s, d f_n / d u = sum_s t_s V,
 * S_s' = Phi_n - T_s V, and the forces' derivatives are transformed as they come. The
 * settled period's start is periodic: a first pass from S = 0 gives S_s(N) = R_s and the
 * period's map Psi_s = prod T_s, and a slider that slipped (Psi_s a contraction) starts the
 * second pass from S_s = (I - Psi_s)^-1 R_s, the implicit function theorem on s = P(s, u); a
 * slider stuck all period sits at the centred state, whose derivative is the middle's: the
 * circle's centre moved with its support samples, or (phi(theta_max) + phi(theta_min)) / 2. (A
 * 3-D slider that settles stuck after slipping in the march's first periods, on an orbit whose
 * middle is not a stuck state, is given the middle's derivative too: then the derivative is
 * approximate, by how far it moved.) */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "aft_internal.h"
#include "aft_march.h"
#include "base/lapack.h"
#include "element_kind.h"
#include "enclosing_circle.h"

#define MAX_PERIODS 64
#define PLAIN 4
#define MAX_NEWTON_STATES 64
#define MAX_NEWTON 20
#define MAX_DIM 3
#define BLOCK 64 /* samples whose derivatives are transformed by one dgemm */

struct fr_aft_march {
    size_t N, nc, nstate; /* the room */
    size_t samples;       /* this call's N (aft's) */
    int dim;              /* this call's type's */
    double *us;           /* [3 N] u at the samples, component d's from d N */
    double *fs;           /* [3 N] f at the samples */
    double *ts;           /* [9 N] df/du at the samples, entry (a, c) from (3 a + c) N */
    double *x;            /* [N] one transform's samples */
    double *state;        /* [nstate] the march's state */
    double *start;        /* [nstate] the state at the period's start */
    double *kept;         /* [nstate] the march's state before Newton's, kept if it fails */
    double *fu;           /* [3 nc] the forces at u */
    double *ps, *pd;      /* [nstate] P(s); Newton's step */
    double *A;            /* [nn nn] I - P'(s), nn = min(nstate, MAX_NEWTON_STATES), by columns */
    int *piv;             /* [max(nn, 3)] its pivots, or a slider's */
    double *sens;         /* [nstate 3 nc] S = d state / d u, row-major */
    double *psi;          /* [nstate 3] each slider's Psi_s, its td x td block from td td s */
    double *tsl, *twl;    /* [nstate 3] the sample's slider tangents t_s, T_s, laid out as psi */
    double *v;            /* [3 3 nc] V = Phi_n - S_s, or (I - Psi_s)'s right-hand sides */
    double *g;            /* [BLOCK 3 3 nc] d f_n / d u of a block's samples, one a row */
    double *wb;           /* [nc BLOCK] the transform's weights at those samples, by rows */
    double *phi;          /* [nc] the basis at a sample */
    int *slipped;         /* [nstate] 1 where slider s slipped in the settled period */
    size_t hi[MAX_DIM], lo[MAX_DIM]; /* the samples of u's largest and smallest components */
    struct fr_circle circle;         /* two tangential components: the orbit's enclosing circle */
};

int fr_aft_march_create(size_t N, size_t nc, size_t nstate, struct fr_aft_march **out)
{
    *out = NULL;
    struct fr_aft_march *w = calloc(1, sizeof *w);
    size_t nn = nstate < MAX_NEWTON_STATES ? nstate : MAX_NEWTON_STATES, b = MAX_DIM * nc;
    size_t doubles = (3 + 3 + 9 + 1) * N + 5 * nstate + MAX_DIM * nc + nn * nn + nstate * b +
                     3 * MAX_DIM * nstate + MAX_DIM * b + BLOCK * MAX_DIM * b + nc * BLOCK + nc;
    double *buf = w ? malloc(doubles * sizeof *buf) : NULL;
    int *piv = buf ? malloc((nn + MAX_DIM + nstate) * sizeof *piv) : NULL;
    if (piv == NULL) {
        free(buf);
        free(w);
        return FRICREG_ENOMEM;
    }
    *w = (struct fr_aft_march){.N = N, .nc = nc, .nstate = nstate, .us = buf, .piv = piv};
    w->slipped = piv + nn + MAX_DIM;
    w->fs = w->us + 3 * N;
    w->ts = w->fs + 3 * N;
    w->x = w->ts + 9 * N;
    w->state = w->x + N;
    w->start = w->state + nstate;
    w->kept = w->start + nstate;
    w->ps = w->kept + nstate;
    w->pd = w->ps + nstate;
    w->fu = w->pd + nstate;
    w->A = w->fu + MAX_DIM * nc;
    w->sens = w->A + nn * nn;
    w->psi = w->sens + nstate * b;
    w->tsl = w->psi + MAX_DIM * nstate;
    w->twl = w->tsl + MAX_DIM * nstate;
    w->v = w->twl + MAX_DIM * nstate;
    w->g = w->v + MAX_DIM * b;
    w->wb = w->g + BLOCK * MAX_DIM * b;
    w->phi = w->wb + nc * BLOCK;
    *out = w;
    return FRICREG_OK;
}

void fr_aft_march_free(struct fr_aft_march *w)
{
    if (w != NULL) {
        free(w->us);
        free(w->piv);
    }
    free(w);
}

/* u[dim nc] at the samples, into w->us. */
static void sample(const fricreg_aft *a, struct fr_aft_march *w, const double *u, int dim)
{
    size_t N = a->N, nc = a->nc;
    for (int d = 0; d < dim; d++) {
        const double *ud = u + (size_t)d * nc;
        for (size_t n = 0; n < N; n++) {
            double v = ud[0];
            for (int h = 1; h <= a->H; h++) {
                size_t idx = ((size_t)h * n) & (N - 1); /* N is a power of two */
                v += ud[2 * h - 1] * a->ctab[idx] + ud[2 * h] * a->stab[idx];
            }
            w->us[(size_t)d * N + n] = v;
        }
    }
}

/* The largest |a - b| over the states, and the scale the march settles to: 2^-46 of the
 * largest u or state. */
static double moved_by(const struct fr_aft_march *w, const double *a, const double *b,
                       size_t nstate, double *tol)
{
    double scale = 0.0, moved = 0.0;
    for (size_t i = 0; i < (size_t)w->dim * w->samples; i++)
        scale = fmax(scale, fabs(w->us[i]));
    for (size_t i = 0; i < nstate; i++) {
        scale = fmax(scale, fabs(a[i]));
        moved = fmax(moved, fabs(a[i] - b[i]));
    }
    *tol = 0x1p-46 * scale;
    return moved;
}

/* The centred state into w->state: state i, a slider's position along tangential component
 * i % td, at the middle of the orbit: the centre of its smallest enclosing circle for two
 * components (w->circle), else each component's middle between its largest and smallest
 * samples (w->hi, w->lo). */
static void centre(const fricreg_element_type *type, struct fr_aft_march *w, size_t nstate)
{
    size_t N = w->samples, td = (size_t)(w->dim - type->kind->normal);
    for (size_t a = 0; a < td; a++) {
        const double *ua = w->us + a * N;
        w->hi[a] = w->lo[a] = 0;
        for (size_t n = 1; n < N; n++) {
            w->lo[a] = ua[n] < ua[w->lo[a]] ? n : w->lo[a];
            w->hi[a] = ua[n] > ua[w->hi[a]] ? n : w->hi[a];
        }
    }
    if (td == 2)
        w->circle = fr_enclosing_circle(w->us, w->us + N, N);
    for (size_t i = 0; i < nstate; i++) {
        const double *ua = w->us + (i % td) * N;
        w->state[i] = td == 2 ? w->circle.c[i % 2]
                              : 0.5 * ua[w->lo[i % td]] + 0.5 * ua[w->hi[i % td]];
    }
}

/* One period over w->us from w->state (left at the period's end): the forces in w->fs and,
 * with tangent, df/du in w->ts. */
static int period(const fricreg_element_type *type, const double *params, struct fr_aft_march *w,
                  int dim, int tangent)
{
    size_t N = w->samples;
    for (size_t n = 0; n < N; n++) {
        double u[MAX_DIM], f[MAX_DIM], t[MAX_DIM * MAX_DIM];
        for (int d = 0; d < dim; d++)
            u[d] = w->us[(size_t)d * N + n];
        int status = fricreg_element_eval(type, params, w->state, u, f, tangent ? t : NULL, NULL,
                                          w->state);
        if (status != FRICREG_OK)
            return status;
        for (int d = 0; d < dim; d++)
            w->fs[(size_t)d * N + n] = f[d];
        for (int a = 0; tangent && a < dim; a++)
            for (int c = 0; c < dim; c++)
                w->ts[(size_t)(MAX_DIM * a + c) * N + n] = t[dim * a + c];
    }
    return FRICREG_OK;
}

/* P(s) of s = w->start into w->ps (the forces of that period in w->fs). */
static int period_map(const fricreg_element_type *type, const double *params,
                      struct fr_aft_march *w, int dim, size_t nstate, int tangent)
{
    memcpy(w->state, w->start, nstate * sizeof *w->state);
    int status = period(type, params, w, dim, tangent);
    memcpy(w->ps, w->state, nstate * sizeof *w->ps);
    return status;
}

/* Newton on s = P(s) from s = w->start: 1 when it converged (w->start the periodic state,
 * w->fs its period's forces), 0 when not (w->start where it stopped), or a failed status
 * of the law as -status. */
static int newton(const fricreg_element_type *type, const double *params, struct fr_aft_march *w,
                  int dim, size_t nstate, int tangent)
{
    int n = (int)nstate, one = 1, info;
    for (int it = 0; it < MAX_NEWTON; it++) {
        int status = period_map(type, params, w, dim, nstate, tangent);
        double tol, r = moved_by(w, w->ps, w->start, nstate, &tol);
        if (status != FRICREG_OK)
            return -status;
        if (r <= tol)
            return 1;
        for (size_t j = 0; j < nstate; j++) { /* column j of I - P'(s) */
            double sj = w->start[j], delta = 0x1p-26 * fmax(fabs(sj), 0x1p46 * tol);
            memcpy(w->state, w->start, nstate * sizeof *w->state);
            w->state[j] = sj + delta;
            delta = w->state[j] - sj;
            if ((status = period(type, params, w, dim, 0)) != FRICREG_OK)
                return -status;
            for (size_t i = 0; i < nstate; i++)
                w->A[j * nstate + i] = (i == j) - (w->state[i] - w->ps[i]) / delta;
        }
        for (size_t i = 0; i < nstate; i++) /* the step into pd: (I - P') d = P(s) - s */
            w->pd[i] = w->ps[i] - w->start[i];
        dgesv_(&n, &one, w->A, &n, w->piv, w->pd, &n, &info);
        if (info != 0)
            return 0;
        for (size_t i = 0; i < nstate; i++)
            w->start[i] += w->pd[i];
    }
    return 0;
}

/* The march over w->us from w->state until it settles: the last period's forces in w->fs and,
 * with tangent, its df/du in w->ts; the settled period's start in w->start. */
static int march(const fricreg_element_type *type, const double *params, struct fr_aft_march *w,
                 int dim, size_t nstate, int tangent)
{
    for (int p = 0; p < MAX_PERIODS; p++) {
        memcpy(w->start, w->state, nstate * sizeof *w->state);
        int status = period(type, params, w, dim, tangent);
        double tol;
        if (status != FRICREG_OK)
            return status;
        if (nstate == 0 || moved_by(w, w->state, w->start, nstate, &tol) <= tol)
            return FRICREG_OK;
        if (p + 1 == PLAIN && nstate <= MAX_NEWTON_STATES) {
            memcpy(w->start, w->state, nstate * sizeof *w->state);
            memcpy(w->kept, w->state, nstate * sizeof *w->state);
            int found = newton(type, params, w, dim, nstate, tangent);
            if (found != 0)
                return found > 0 ? FRICREG_OK : -found;
            memcpy(w->state, w->kept, nstate * sizeof *w->state);
        }
    }
    return FRICREG_OK;
}

/* The forces' coefficients of the march in w->fs, into f[dim nc]. */
static void coefficients(const fricreg_aft *a, struct fr_aft_march *w, int dim, double *f)
{
    size_t N = a->N;
    for (int d = 0; d < dim; d++) {
        memcpy(w->x, w->fs + (size_t)d * N, N * sizeof *w->x);
        fr_aft_sample_coefficients(a, w->x, f + (size_t)d * a->nc, 1);
    }
}

/* One sample's step of the sensitivities, slider by slider (the file's comment): V = Phi_n -
 * S_s into w->v, t_s V added into g[td td nc], S_s' = Phi_n - T_s V; in the first pass Psi_s' =
 * T_s Psi_s and whether the slider slipped (T_s not I). */
static void sensitivity_step(struct fr_aft_march *w, size_t td, size_t ns, size_t nc, int first,
                             double *g)
{
    size_t b = td * nc, blk = td * td;
    memset(g, 0, td * b * sizeof *g);
    for (size_t s = 0; s < ns; s++) {
        double *S = w->sens + td * s * b;
        const double *t = w->tsl + blk * s, *T = w->twl + blk * s;
        for (size_t r = 0; r < td; r++)
            for (size_t col = 0; col < b; col++)
                w->v[r * b + col] = (col / nc == r ? w->phi[col % nc] : 0.0) - S[r * b + col];
        for (size_t r = 0; r < td; r++)
            for (size_t col = 0; col < b; col++)
                S[r * b + col] = col / nc == r ? w->phi[col % nc] : 0.0;
        for (size_t r = 0; r < td; r++)
            for (size_t c = 0; c < td; c++)
                for (size_t col = 0; col < b; col++) {
                    g[r * b + col] += t[r * td + c] * w->v[c * b + col];
                    S[r * b + col] -= T[r * td + c] * w->v[c * b + col];
                }
        if (!first)
            continue;
        double *P = w->psi + blk * s, next[MAX_DIM * MAX_DIM] = {0.0};
        for (size_t a = 0; a < blk; a++) {
            w->slipped[s] |= T[a] != (double)(a / td == a % td);
            for (size_t c = 0; c < td; c++)
                next[a] += T[(a / td) * td + c] * P[c * td + a % td];
        }
        memcpy(P, next, blk * sizeof *P);
    }
}

/* The transform of the block's k samples' derivatives in w->g, weighted by w->wb, added into
 * jac: for each component a, jac's rows a nc .. by one dgemm (row-major C = W G, as BLAS's
 * column-major C^T = G^T W^T). */
static void transform_block(struct fr_aft_march *w, int td, int nc, int k, double *jac)
{
    int b = td * nc, ldg = td * b, ldw = BLOCK;
    double one = 1.0;
    for (int a = 0; a < td; a++)
        dgemm_("N", "N", &b, &nc, &k, &one, w->g + (size_t)(a * b), &ldg, w->wb, &ldw, &one,
               jac + (size_t)(a * nc * b), &b, 1, 1);
}

/* One period from the settled state w->start over the samples in w->us, the sensitivities
 * w->sens going with it; in the first pass Psi and the slips, in the second the transform of
 * d f_n / d u added into jac (the coefficients' sums, as the FFT's: 1/N for the mean, 2/N for
 * the harmonics). */
static void sensitive_period(const fricreg_aft *a, struct fr_aft_march *w,
                             const fricreg_element_type *type, const double *params, int first,
                             double *jac)
{
    size_t N = a->N, nc = a->nc, td = (size_t)w->dim, b = td * nc, k = 0;
    size_t ns = fricreg_element_nstate(type) / td;
    memcpy(w->state, w->start, ns * td * sizeof *w->state);
    for (size_t n = 0; n < N; n++) {
        double u[MAX_DIM];
        for (size_t d = 0; d < td; d++)
            u[d] = w->us[d * N + n];
        for (size_t j = 0; j < nc; j++)
            w->phi[j] = fr_aft_sample_basis(a, j, n);
        /* the state as eval's, whose checks the march's period passed at these samples */
        type->kind->slider_tangents(type, params, w->state, u, w->tsl, w->twl, w->state);
        sensitivity_step(w, td, ns, nc, first, w->g + k * td * b);
        if (first)
            continue;
        for (size_t j = 0; j < nc; j++)
            w->wb[j * BLOCK + k] = w->phi[j] * (j == 0 ? 1.0 : 2.0) / (double)N;
        if (++k == BLOCK || n + 1 == N) {
            transform_block(w, (int)td, (int)nc, (int)k, jac);
            k = 0;
        }
    }
}

/* d m_r / d u_col of the middle m of the orbit (centre()), component r: for two components the
 * enclosing circle's centre moved with its support samples, else the basis at component r's
 * largest and smallest samples. An orbit that is one point (at rest) moves with its mean
 * alone (a pure harmonic's extremes cancel). */
static double middle_derivative(const fricreg_aft *a, const struct fr_aft_march *w, size_t r,
                                size_t col)
{
    size_t nc = a->nc, j = col % nc, c = col / nc;
    int rest = w->dim == 2 ? w->circle.nsup == 1 : w->hi[r] == w->lo[r];
    if (rest)
        return c == r && j == 0 ? 1.0 : 0.0;
    if (w->dim == 2) {
        double dp[3][2] = {{0.0}}, dc[2];
        for (int i = 0; i < w->circle.nsup; i++)
            dp[i][c] = fr_aft_sample_basis(a, j, w->circle.sup[i]);
        fr_circle_centre_derivative(&w->circle, w->us, w->us + w->samples, (const double(*)[2])dp,
                                    dc);
        return dc[r];
    }
    if (c != r)
        return 0.0;
    return 0.5 * fr_aft_sample_basis(a, j, w->hi[r]) + 0.5 * fr_aft_sample_basis(a, j, w->lo[r]);
}

/* The periodic start of the sensitivities in w->sens from the first pass's R_s (there) and
 * Psi_s: (I - Psi_s)^-1 R_s for a slider that slipped, else the middle's derivative. */
static void periodic_start(const fricreg_aft *a, struct fr_aft_march *w, size_t ns)
{
    int td = w->dim, nc = (int)a->nc, b = td * nc, info;
    for (size_t s = 0; s < ns; s++) {
        double *S = w->sens + (size_t)(td * b) * s, A[MAX_DIM * MAX_DIM];
        if (!w->slipped[s]) {
            for (int r = 0; r < td; r++)
                for (int col = 0; col < b; col++)
                    S[r * b + col] = middle_derivative(a, w, (size_t)r, (size_t)col);
            continue;
        }
        const double *P = w->psi + (size_t)(td * td) * s;
        for (int r = 0; r < td; r++) /* by columns, as dgesv takes them */
            for (int c = 0; c < td; c++)
                A[c * td + r] = (r == c) - P[r * td + c];
        for (int r = 0; r < td; r++)
            for (int col = 0; col < b; col++)
                w->v[col * td + r] = S[r * b + col];
        dgesv_(&td, &b, A, &td, w->piv, w->v, &td, &info);
        for (int r = 0; r < td; r++) /* info != 0 only where a slip rounded T_s to I: S_s = R_s */
            for (int col = 0; col < b; col++)
                S[r * b + col] = w->v[col * td + r];
    }
}

/* The exact Jacobian of a law with state (the file's comment) into jac. */
static void sensitivities(const fricreg_aft *a, struct fr_aft_march *w,
                          const fricreg_element_type *type, const double *params, double *jac)
{
    size_t td = (size_t)w->dim, b = td * a->nc, ns = fricreg_element_nstate(type) / td;
    memset(w->sens, 0, ns * td * b * sizeof *w->sens);
    memset(w->psi, 0, ns * td * td * sizeof *w->psi);
    for (size_t s = 0; s < ns; s++) {
        w->slipped[s] = 0;
        for (size_t r = 0; r < td; r++)
            w->psi[(td * s + r) * td + r] = 1.0;
    }
    sensitive_period(a, w, type, params, 1, NULL);
    periodic_start(a, w, ns);
    memset(jac, 0, b * b * sizeof *jac);
    sensitive_period(a, w, type, params, 0, jac);
}

/* The Jacobian of a law without state: column j of component c, the transform of
 * df_a/du_c phi_j at the samples. */
static void tangents(const fricreg_aft *a, struct fr_aft_march *w, int dim, double *jac)
{
    size_t N = a->N, nc = a->nc, b = (size_t)dim * nc;
    for (int r = 0; r < dim; r++)
        for (int c = 0; c < dim; c++)
            for (size_t j = 0; j < nc; j++) {
                const double *t = w->ts + (size_t)(MAX_DIM * r + c) * N;
                for (size_t n = 0; n < N; n++)
                    w->x[n] = t[n] * fr_aft_sample_basis(a, j, n);
                fr_aft_sample_coefficients(a, w->x, jac + (size_t)r * nc * b + (size_t)c * nc + j,
                                           b);
            }
}

int fr_aft_march(const fricreg_aft *aft, struct fr_aft_march *w, const fricreg_element_type *type,
                 const double *params, const double *u, double *f, double *jac)
{
    int dim = fricreg_element_dim(type);
    size_t nstate = fricreg_element_nstate(type), b = (size_t)dim * aft->nc;
    if (nstate > 0 && type->kind->slider_tangents == NULL)
        return FRICREG_EINVAL;
    w->samples = aft->N;
    w->dim = dim;
    sample(aft, w, u, dim);
    centre(type, w, nstate);
    int status = march(type, params, w, dim, nstate, jac != NULL && nstate == 0);
    if (status != FRICREG_OK)
        return status;
    coefficients(aft, w, dim, w->fu);
    if (jac != NULL && nstate == 0)
        tangents(aft, w, dim, jac);
    if (jac != NULL && nstate > 0)
        sensitivities(aft, w, type, params, jac);
    memcpy(f, w->fu, b * sizeof *f);
    return FRICREG_OK;
}
