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
 * The Jacobian: aft_march_jacobian.c. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "aft_internal.h"
#include "aft_march.h"
#include "aft_march_internal.h"
#include "base/lapack.h"
#include "element_kind.h"

#define MAX_PERIODS 64
#define PLAIN 4
#define MAX_NEWTON_STATES 64
#define MAX_NEWTON 20
#define NOISE 64.0 /* Newton's stall, within 2^-40 of the scale: the period's rounding */

int fr_aft_march_create(size_t N, size_t nc, size_t nstate, struct fr_aft_march **out)
{
    *out = NULL;
    struct fr_aft_march *w = calloc(1, sizeof *w);
    size_t nn = nstate < MAX_NEWTON_STATES ? nstate : MAX_NEWTON_STATES, b = MAX_DIM * nc;
    size_t doubles = (3 + 3 + 9 + 1) * N + 5 * nstate + MAX_DIM * nc + nn * nn + nstate * b +
                     3 * MAX_DIM * nstate + MAX_DIM * b + BLOCK * MAX_DIM * b + nc * BLOCK + nc +
                     FR_STATE_TANGENTS_MAX * b + 2 * N;
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
    w->snext = w->phi + nc;
    w->tturn = w->snext + FR_STATE_TANGENTS_MAX * b;
    w->uturn = w->tturn + N;
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
        int status = FRICREG_OK;
        if (!isnan(w->tturn[n])) /* through the turn first: each piece is monotone */
            status = fricreg_element_eval(type, params, w->state, &w->uturn[n], f, NULL, NULL,
                                          w->state);
        for (int d = 0; d < dim; d++)
            u[d] = w->us[(size_t)d * N + n];
        if (status == FRICREG_OK)
            status = fricreg_element_eval(type, params, w->state, u, f, tangent ? t : NULL, NULL,
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
    double last = INFINITY;
    for (int it = 0; it < MAX_NEWTON; it++) {
        int status = period_map(type, params, w, dim, nstate, tangent);
        double tol, r = moved_by(w, w->ps, w->start, nstate, &tol);
        if (status != FRICREG_OK)
            return -status;
        /* converged, or at the period's rounding noise: a state that moves at every sample
         * (dahl's) gathers some ulps a sample, above 2^-46 of the scale at N = 512 */
        if (r <= tol || (r > 0.5 * last && r <= NOISE * tol))
            return 1;
        last = r;
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
    if (nstate > 0 && type->kind->slider_tangents == NULL && type->kind->state_tangents == NULL)
        return FRICREG_EINVAL;
    w->samples = aft->N;
    w->dim = dim;
    sample(aft, w, u, dim);
    fr_aft_march_turns(aft, w, u, dim == 1 && nstate > 0);
    centre(type, w, nstate);
    int status = march(type, params, w, dim, nstate, jac != NULL && nstate == 0);
    if (status != FRICREG_OK)
        return status;
    coefficients(aft, w, dim, w->fu);
    if (jac != NULL && nstate == 0)
        tangents(aft, w, dim, jac);
    if (jac != NULL && nstate > 0)
        fr_aft_march_sensitivities(aft, w, type, params, jac);
    memcpy(f, w->fu, b * sizeof *f);
    return FRICREG_OK;
}

int fr_aft_march_lags(const fricreg_element_type *type)
{
    return fricreg_element_nstate(type) > 0 && fricreg_element_dim(type) > 1;
}
