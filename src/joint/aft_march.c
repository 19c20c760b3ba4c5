/* SPDX-License-Identifier: GPL-3.0-or-later */
/* aft_march.c — the sampled AFT of any element type (aft_march.h): u at N equidistant samples
 * of the period, the type's fricreg_element_eval marched over them from the law's initial
 * state (fricreg_element_init's) at theta = 0 until the state at a period's end equals its
 * start (to 2^-46 of the largest u or state), and the last period's forces to coefficients
 * by GSL's real radix-2 FFT (aft_sampled.c's fr_aft_sample_coefficients), as NLvib's AFT
 * marches a hysteretic law (Krack & Gross, Harmonic Balance for Nonlinear Vibration Problems,
 * 2019, Sec. 3.3; it marches two periods). A state still moving after PLAIN periods is a slow
 * contraction (a 2-D slider barely past slip): with at most MAX_NEWTON_STATES states, Newton's
 * method on the fixed point s = P(s) of the period map P, its derivative by forward
 * differences and LAPACK's dgesv, finds it (as aft_2d.c does with its own chain); otherwise,
 * or if Newton fails, the march goes on to MAX_PERIODS periods and gives its last.
 *
 * The Jacobian: a law without state has f(theta_n) = f(u(theta_n)), so column j of component
 * d2 is the transform of df/du_d2 (theta_n) phi_j(theta_n), exact. A law with state has
 * forces that depend on the samples before (a slider's anchor) through its periodic state
 * s = P(s, u): by the implicit function theorem dF/du = G_u + G_s (I - P_s)^-1 P_u, G the
 * forces of one period from s, each derivative by central differences of one period (with at
 * most MAX_NEWTON_STATES states). Where I - P_s is singular (a slider stuck all period: any
 * state is periodic) or the states are more, by central differences of the whole march,
 * u_j ± h, each started from u's settled state, which keeps a stuck slider on u's anchor. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "aft_internal.h"
#include "aft_march.h"

#define MAX_PERIODS 64
#define PLAIN 4
#define MAX_NEWTON_STATES 64
#define MAX_NEWTON 20
#define MAX_DIM 3

/* LAPACK by Fortran's calling convention (lu.c says more). */
void dgesv_(const int *n, const int *nrhs, double *a, const int *lda, int *ipiv, double *b,
            const int *ldb, int *info);

struct fr_aft_march {
    size_t N, nc, nstate; /* the room */
    size_t samples;       /* this call's N (aft's) */
    int dim;              /* this call's type's */
    size_t nstate_now;    /* this call's type's */
    double *us;           /* [3 N] u at the samples, component d's from d N */
    double *fs;           /* [3 N] f at the samples */
    double *ts;           /* [9 N] df/du at the samples, entry (a, c) from (3 a + c) N */
    double *x;            /* [N] one transform's samples */
    double *state;        /* [nstate] the march's state */
    double *start;        /* [nstate] the state at the period's start */
    double *settled;      /* [nstate] u's settled state, where the differences start */
    double *kept;         /* [nstate] the march's state before Newton's, kept if it fails */
    double *up;           /* [3 nc] u moved by h */
    double *fp, *fm;      /* [3 nc] the forces at u + h, u - h */
    double *fu;           /* [3 nc] the forces at u */
    double *ps, *pd;      /* [nstate] P(s); Newton's step */
    double *A;            /* [nn nn] I - P'(s), nn = min(nstate, MAX_NEWTON_STATES), by columns */
    int *piv;             /* [nn] its pivots */
    double *gs;           /* [3 nc nn] dF/ds at the settled state, row-major */
    double *pu;           /* [nn 3 nc] dP/du, by columns (dgesv's right-hand sides) */
};

int fr_aft_march_create(size_t N, size_t nc, size_t nstate, struct fr_aft_march **out)
{
    *out = NULL;
    struct fr_aft_march *w = calloc(1, sizeof *w);
    size_t nn = nstate < MAX_NEWTON_STATES ? nstate : MAX_NEWTON_STATES;
    size_t doubles = (3 + 3 + 9 + 1) * N + 6 * nstate + 4 * MAX_DIM * nc + nn * nn +
                     2 * MAX_DIM * nc * nn;
    double *buf = w ? malloc(doubles * sizeof *buf) : NULL;
    int *piv = buf ? malloc((nn + 1) * sizeof *piv) : NULL;
    if (piv == NULL) {
        free(buf);
        free(w);
        return FRICREG_ENOMEM;
    }
    *w = (struct fr_aft_march){.N = N, .nc = nc, .nstate = nstate, .us = buf, .piv = piv};
    w->fs = w->us + 3 * N;
    w->ts = w->fs + 3 * N;
    w->x = w->ts + 9 * N;
    w->state = w->x + N;
    w->start = w->state + nstate;
    w->settled = w->start + nstate;
    w->kept = w->settled + nstate;
    w->up = w->kept + nstate;
    w->fp = w->up + MAX_DIM * nc;
    w->fm = w->fp + MAX_DIM * nc;
    w->fu = w->fm + MAX_DIM * nc;
    w->ps = w->fu + MAX_DIM * nc;
    w->pd = w->ps + nstate;
    w->A = w->pd + nstate;
    w->gs = w->A + nn * nn;
    w->pu = w->gs + MAX_DIM * nc * nn;
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

/* The march of u moved by dh in its coefficient col, from the settled state, into f. */
static int moved(const fricreg_aft *a, struct fr_aft_march *w, const fricreg_element_type *type,
                 const double *params, const double *u, size_t col, double dh, double *f)
{
    int dim = fricreg_element_dim(type);
    size_t nstate = fricreg_element_nstate(type);
    memcpy(w->up, u, (size_t)dim * a->nc * sizeof *u);
    w->up[col] += dh;
    sample(a, w, w->up, dim);
    memcpy(w->state, w->settled, nstate * sizeof *w->state);
    int status = march(type, params, w, dim, nstate, 0);
    if (status == FRICREG_OK)
        coefficients(a, w, dim, f);
    return status;
}

/* The Jacobian of a law with state, by central differences of the march. */
static int differences(const fricreg_aft *a, struct fr_aft_march *w,
                       const fricreg_element_type *type, const double *params, const double *u,
                       double h, double *jac)
{
    size_t b = (size_t)fricreg_element_dim(type) * a->nc;
    for (size_t col = 0; col < b; col++) {
        double up = u[col] + h, um = u[col] - h, span = up - um; /* as rounded */
        int status = moved(a, w, type, params, u, col, up - u[col], w->fp);
        if (status == FRICREG_OK)
            status = moved(a, w, type, params, u, col, um - u[col], w->fm);
        if (status != FRICREG_OK)
            return status;
        for (size_t row = 0; row < b; row++)
            jac[row * b + col] = (w->fp[row] - w->fm[row]) / span;
    }
    return FRICREG_OK;
}

/* One period from s = settled + dh e_j (j < nstate) over the samples in w->us: P(s) into
 * w->state, the forces' coefficients into f. */
static int from_state(const fricreg_aft *a, struct fr_aft_march *w,
                      const fricreg_element_type *type, const double *params, size_t j, double dh,
                      double *f)
{
    memcpy(w->state, w->settled, w->nstate_now * sizeof *w->state);
    if (j < w->nstate_now)
        w->state[j] += dh;
    int status = period(type, params, w, w->dim, 0);
    if (status == FRICREG_OK)
        coefficients(a, w, w->dim, f);
    return status;
}

/* The Jacobian of a law with state by the implicit function theorem on the settled state s,
 * s = P(s, u): dF/du = G_u + G_s (I - P_s)^-1 P_u, G the forces of one period from s, each
 * derivative by central differences of one period (aft_2d.c's chain, by differences). 1
 * when I - P_s is singular (a slider stuck all period: its state is any, the march's
 * differences hold it), else a status. */
static int implicit(const fricreg_aft *a, struct fr_aft_march *w, const fricreg_element_type *type,
                    const double *params, const double *u, double h, double *jac)
{
    size_t ns = w->nstate_now, b = (size_t)w->dim * a->nc;
    int n = (int)ns, nrhs = (int)b, info, status;
    sample(a, w, u, w->dim);
    double tol;
    moved_by(w, w->settled, w->settled, ns, &tol);
    for (size_t j = 0; j < ns; j++) { /* G_s and I - P_s, column j */
        double sj = w->settled[j], dh = 0x1p-20 * fmax(fabs(sj), 0x1p46 * tol);
        double span = (sj + dh) - (sj - dh);
        if ((status = from_state(a, w, type, params, j, dh, w->fp)) != FRICREG_OK)
            return status;
        memcpy(w->ps, w->state, ns * sizeof *w->ps);
        if ((status = from_state(a, w, type, params, j, -dh, w->fm)) != FRICREG_OK)
            return status;
        for (size_t i = 0; i < ns; i++)
            w->A[j * ns + i] = (i == j) - (w->ps[i] - w->state[i]) / span;
        for (size_t r = 0; r < b; r++)
            w->gs[r * ns + j] = (w->fp[r] - w->fm[r]) / span;
    }
    for (size_t col = 0; col < b; col++) { /* G_u into jac, P_u into pu, column col */
        double span = (u[col] + h) - (u[col] - h);
        for (int side = 0; side < 2; side++) {
            memcpy(w->up, u, b * sizeof *u);
            w->up[col] += side == 0 ? h : -h;
            sample(a, w, w->up, w->dim);
            if ((status = from_state(a, w, type, params, ns, 0.0, side == 0 ? w->fp : w->fm)) !=
                FRICREG_OK)
                return status;
            memcpy(side == 0 ? w->ps : w->pd, w->state, ns * sizeof *w->ps);
        }
        for (size_t r = 0; r < b; r++)
            jac[r * b + col] = (w->fp[r] - w->fm[r]) / span;
        for (size_t i = 0; i < ns; i++)
            w->pu[col * ns + i] = (w->ps[i] - w->pd[i]) / span;
    }
    dgesv_(&n, &nrhs, w->A, &n, w->piv, w->pu, &n, &info);
    if (info != 0)
        return 1;
    for (size_t r = 0; r < b; r++)
        for (size_t col = 0; col < b; col++)
            for (size_t j = 0; j < ns; j++)
                jac[r * b + col] += w->gs[r * ns + j] * w->pu[col * ns + j];
    return FRICREG_OK;
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
                 const double *params, const double *u, double h, double *f, double *jac)
{
    int dim = fricreg_element_dim(type);
    size_t nstate = fricreg_element_nstate(type), b = (size_t)dim * aft->nc;
    w->samples = aft->N;
    w->dim = dim;
    sample(aft, w, u, dim);
    memset(w->state, 0, nstate * sizeof *w->state);
    int status = march(type, params, w, dim, nstate, jac != NULL && nstate == 0);
    if (status != FRICREG_OK)
        return status;
    coefficients(aft, w, dim, w->fu);
    if (jac != NULL && nstate == 0)
        tangents(aft, w, dim, jac);
    if (jac != NULL && nstate > 0) {
        memcpy(w->settled, w->start, nstate * sizeof *w->start);
        w->nstate_now = nstate;
        status = nstate <= MAX_NEWTON_STATES ? implicit(aft, w, type, params, u, h, jac) : 1;
        if (status == 1)
            status = differences(aft, w, type, params, u, h, jac);
    }
    if (status == FRICREG_OK)
        memcpy(f, w->fu, b * sizeof *f);
    return status;
}
