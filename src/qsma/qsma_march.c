/* SPDX-License-Identifier: GPL-3.0-or-later */
/* qsma_march.c — quasi-static modal analysis's loading path for a model with 3-D contacts or
 * Jenkins elements with lift-off (qsma_internal.h). A contact's tangential force turns as it slides and its bound μ N moves
 * with the normal displacement, so the path is no longer piecewise linear (qsma_path.c's exact
 * stepping): it is marched in the modal amplitude instead, each point the bordered static
 * equilibrium
 *
 *     K x + J^T F(J x; w_old) = λ M φ_k,      φ_k^T M (x − x_0) = q,
 *
 * solved by Newton's method on its consistent tangent (LAPACK's dgetrf: the contacts' tangent is
 * not symmetric), F each element's return mapping from its state at the point before (backward
 * Euler: qsma_units.c). The march starts at the rest state x_0 under the contacts' preloads
 * (K + Σ kn J_n^T J_n) x_0 = −Σ n0 J_n^T, each slider centred on it (no tangential force, as
 * harmonic balance's stuck contact), steps h = 2^⌊log2(a_max/256)⌋ in q (a power of 2: a
 * parameter or a target moved a little leaves the grid as it is), and reaches each target by a
 * step of its own from the grid point below, so that no target moves another's path. A step
 * whose Newton fails is halved, up to 12 times. ∫ λ dq is the trapezoid's over the points.
 *
 * The sensitivities are the discrete path's, exact (forward differentiation through the
 * states): at a converged point, for each parameter, the bordered matrix (already factored)
 * solves [K_t, −b; b^T, 0] (dx, dλ) = (λ db − J^T ∂F/∂p − J^T ∂F/∂w_old dw_old,
 * −db^T (x − x_0) + b^T dx_0), and the states move by the return mapping's derivatives
 * (qsma_units.c); x_0 by (K + Σ kn J_n^T J_n) dx_0 = −Σ J_n^T (dn0 + g_0 dkn). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/free_all.h"
#include "base/lapack.h"
#include "qsma_internal.h"

#define GRID_STEPS 256   /* at least this many steps up to the largest target */
#define MAX_NEWTON 50    /* iterations of one point */
#define MAX_HALVINGS 12  /* of a step whose Newton fails */
#define NEWTON_TOL 1e-12 /* Newton's last step, relative */

/* A point of the path: q, λ, ∫ λ dq so far, x [n], the elements' states W [nst]; with
 * sensitivities dλ/dp, d∫/dp [np] and dW/dp [np nst]. */
struct point {
    double q, lambda, I;
    double *x, *W, *dl, *dI, *dW;
};

struct march {
    fricreg_hb *hb;
    const char *fn;
    struct fr_qsma *s;
    const struct fr_qsma_sens *p;
    size_t n, m, nu, nst, np;
    struct fr_qsma_unit *units;
    struct fr_qsma_record *rec; /* [nu] of the last evaluation */
    double *x0, *dx0;           /* [n], [np n]: the rest state and its derivatives */
    double *A, *r, *rhs;        /* [n²] the rest state's, [n + 1], [(n + 1) max(np, 1)] */
    double *Ed;                 /* [m m]: the elements' tangents by rows (row-major) */
    struct fr_qsma_cap *cap;    /* the bordered tangent's solver (qsma_capacitance.c) */
    double *ur, *f, *D, *Wn;    /* [m], [m], [9 nu], [nst] */
    int *piv;                   /* [n + 1] */
    double phimax, bmax;        /* |φ_k|∞: x's scale per unit of q; |M φ_k|∞ */
    double fscale;              /* the largest of K x and λ b at the last linearization */
    double prev_q, prev_lambda; /* the point before the last step */
    struct point pt[3];         /* the grid's, a step's trial, a target's */
};

static double *take(double **cursor, size_t count)
{
    double *v = *cursor;
    *cursor += count;
    return v;
}

/* The units: the sliders (their states first), then the contacts (two states each). */
static void build_units(struct march *mk)
{
    const fricreg_hb *hb = mk->hb;
    const struct fr_qsma *s = mk->s;
    size_t me = hb->me;
    for (size_t j = 0; j < s->nsl; j++)
        mk->units[j] = (struct fr_qsma_unit){
            .row = s->row[j], .st = j, .dim = 1, .kt = s->ks[j], .phi = s->fs[j]};
    for (size_t c = 0, st = s->nsl; c < s->ncon; c++) {
        size_t e = s->con[c];
        int dim = fr_qsma_tangential_rows(hb, e);
        mk->units[s->nsl + c] = (struct fr_qsma_unit){.row = hb->erow[e],
                                                      .st = st,
                                                      .dim = dim,
                                                      .normal = 1,
                                                      .kt = hb->nl[e],
                                                      .mu = hb->nl[me + e],
                                                      .n0 = hb->nl[2 * me + e],
                                                      .kn = hb->nl[3 * me + e]};
        st += (size_t)dim;
    }
}

static int role_of(const struct march *mk, size_t k, size_t u)
{
    size_t nsl = mk->s->nsl;
    return u < nsl ? mk->p->role[k * nsl + u] : mk->p->crole[k * mk->s->ncon + (u - nsl)];
}

static void free_march(struct march *mk)
{
    FR_FREE_ALL(mk->units, mk->rec, mk->x0, mk->piv);
    fr_qsma_cap_free(mk->cap);
}

static int alloc_march(struct march *mk)
{
    size_t n = mk->n, N = n + 1, np = mk->np, nst = mk->nst;
    size_t per_point = n + nst + 2 * np + np * nst;
    size_t total = n + np * n + n * n + N + N * (np + 1) + 2 * mk->m + mk->m * mk->m + 9 * mk->nu +
                   nst + 3 * per_point;
    mk->units = malloc((mk->nu + 1) * sizeof *mk->units);
    mk->rec = malloc((mk->nu + 1) * sizeof *mk->rec);
    mk->x0 = calloc(total, sizeof *mk->x0);
    mk->piv = malloc(N * sizeof *mk->piv);
    if (!mk->units || !mk->rec || !mk->x0 || !mk->piv)
        return FRICREG_ENOMEM;
    int st = fr_qsma_cap_create(mk->s, mk->hb->J, &mk->cap);
    if (st != FRICREG_OK)
        return st;
    double *c = mk->x0 + n;
    mk->dx0 = take(&c, np * n);
    mk->A = take(&c, n * n);
    mk->Ed = take(&c, mk->m * mk->m);
    mk->r = take(&c, N);
    mk->rhs = take(&c, N * (np + 1));
    mk->ur = take(&c, mk->m);
    mk->f = take(&c, mk->m);
    mk->D = take(&c, 9 * mk->nu);
    mk->Wn = take(&c, nst);
    for (int k = 0; k < 3; k++) {
        struct point *pt = &mk->pt[k];
        pt->x = take(&c, n);
        pt->W = take(&c, nst);
        pt->dl = take(&c, np);
        pt->dI = take(&c, np);
        pt->dW = take(&c, np * nst);
    }
    return FRICREG_OK;
}

/* y_r = J_r x for every row. */
static void rows_of(const struct march *mk, const double *x, double *y)
{
    const double *J = mk->hb->J;
    for (size_t r = 0; r < mk->m; r++) {
        double t = 0.0;
        for (size_t i = 0; i < mk->n; i++)
            t += J[r * mk->n + i] * x[i];
        y[r] = t;
    }
}

/* out += J_u^T v, v on unit u's rows. */
static void add_rows_t(const struct march *mk, const struct fr_qsma_unit *un, const double *v,
                       double *out)
{
    const double *J = mk->hb->J;
    for (size_t a = 0; a < fr_qsma_unit_rows(un); a++)
        for (size_t i = 0; i < mk->n && v[a] != 0.0; i++)
            out[i] += J[(un->row + a) * mk->n + i] * v[a];
}

/* The rest state's solve, on A's dense LU (order n). */
static void rest_solve(const struct march *mk, size_t nrhs, double *b)
{
    int nn = (int)mk->n, nr = (int)nrhs, info = 0;
    dgetrs_("N", &nn, &nr, mk->A, &nn, mk->piv, b, &nn, &info, 1);
}

/* The bordered tangent's solve at the last linearization: nrhs columns of order n + 1. */
static void solve(const struct march *mk, size_t nrhs, double *B)
{
    fr_qsma_cap_solve(mk->cap, mk->hb->J, mk->s->b, nrhs, B);
}

/* A_rest = K + Σ_closed kn J_n^T J_n, x_0 = A_rest^-1 (−Σ n0 J_n^T) and dx_0 = A_rest^-1
 * (−Σ J_n^T (dn0 + g_0 dkn)), on the contacts closed by their preload (n0 > 0). */
static int rest_state(struct march *mk, struct point *g)
{
    size_t n = mk->n, np = mk->np, nsl = mk->s->nsl;
    const double *J = mk->hb->J;
    memcpy(mk->A, mk->s->K, n * n * sizeof *mk->A); /* symmetric: either order */
    memset(mk->x0, 0, n * sizeof *mk->x0);
    for (size_t u = nsl; u < mk->nu; u++) {
        const struct fr_qsma_unit *un = &mk->units[u];
        const double *Jn = J + (un->row + (size_t)un->dim) * n;
        if (!(un->n0 > 0.0))
            continue;
        for (size_t i = 0; i < n && un->kn != 0.0; i++)
            for (size_t j = 0; j < n && Jn[i] != 0.0; j++)
                mk->A[i * n + j] += un->kn * Jn[i] * Jn[j];
        for (size_t i = 0; i < n; i++)
            mk->x0[i] -= un->n0 * Jn[i];
    }
    if (fr_qsma_lu(mk->A, n, mk->piv) != FRICREG_OK)
        return fr_fail(mk->hb, FRICREG_ESINGULAR,
                       "%s: the structure with its contacts closed, K + sum kn Jn^T Jn, is "
                       "singular: no rest state under the preloads",
                       mk->fn);
    rest_solve(mk, 1, mk->x0);
    rows_of(mk, mk->x0, mk->ur);
    memset(mk->dx0, 0, np * n * sizeof *mk->dx0);
    for (size_t u = nsl; u < mk->nu; u++) {
        const struct fr_qsma_unit *un = &mk->units[u];
        double g0 = mk->ur[un->row + (size_t)un->dim], N0 = un->n0 + un->kn * g0;
        if ((un->n0 > 0.0) != (N0 > 0.0))
            return fr_fail(mk->hb, FRICREG_EINVAL,
                           "%s: contact %zu's normal force at rest is %g (n0 = %g): the preloads "
                           "of the others %s it",
                           mk->fn, u - nsl, N0, un->n0, un->n0 > 0.0 ? "open" : "close");
        for (size_t k = 0; k < np && un->n0 > 0.0; k++) {
            int role = role_of(mk, k, u);
            double c = (role == FR_QSMA_ROLE_N0) + (role == FR_QSMA_ROLE_KN) * g0;
            for (size_t i = 0; i < n && c != 0.0; i++)
                mk->dx0[k * n + i] -= c * J[(un->row + (size_t)un->dim) * n + i];
        }
    }
    if (np > 0)
        rest_solve(mk, np, mk->dx0);
    /* the sliders unloaded, each contact's centred on its rest displacement */
    memcpy(g->x, mk->x0, n * sizeof *g->x);
    memset(g->W, 0, mk->nst * sizeof *g->W);
    memset(g->dW, 0, np * mk->nst * sizeof *g->dW);
    for (size_t u = nsl; u < mk->nu; u++) {
        const struct fr_qsma_unit *un = &mk->units[u];
        for (int a = 0; a < un->dim; a++) {
            g->W[un->st + (size_t)a] = mk->ur[un->row + (size_t)a];
            for (size_t k = 0; k < np; k++) {
                double t = 0.0;
                for (size_t i = 0; i < n; i++)
                    t += J[(un->row + (size_t)a) * n + i] * mk->dx0[k * n + i];
                g->dW[k * mk->nst + un->st + (size_t)a] = t;
            }
        }
    }
    g->q = g->lambda = g->I = 0.0;
    memset(g->dl, 0, np * sizeof *g->dl);
    memset(g->dI, 0, np * sizeof *g->dI);
    return FRICREG_OK;
}

/* The elements at x from the states Wold: forces f, tangents D, states Wn, records; then the
 * bordered residual into r and the tangent's solver factored (qsma_capacitance.c). */
static int linearize(struct march *mk, const double *Wold, const struct point *t)
{
    size_t n = mk->n, m = mk->m;
    const double *b = mk->s->b;
    rows_of(mk, t->x, mk->ur);
    memset(mk->Ed, 0, m * m * sizeof *mk->Ed);
    for (size_t u = 0; u < mk->nu; u++) {
        const struct fr_qsma_unit *un = &mk->units[u];
        size_t rows = fr_qsma_unit_rows(un);
        const double *D = mk->D + 9 * u;
        fr_qsma_unit_step(un, mk->ur + un->row, Wold + un->st, mk->f + un->row, mk->D + 9 * u,
                          mk->Wn + un->st, &mk->rec[u]);
        for (size_t a = 0; a < rows; a++)
            for (size_t c = 0; c < rows; c++)
                mk->Ed[(un->row + a) * m + un->row + c] += D[a * rows + c];
    }
    double cq = -t->q;
    mk->fscale = 0.0;
    for (size_t i = 0; i < n; i++) {
        double ri = -t->lambda * b[i], kx = 0.0;
        for (size_t j = 0; j < n; j++)
            kx += mk->s->K[i * n + j] * t->x[j];
        mk->fscale = fmax(mk->fscale, fmax(fabs(kx), fabs(ri)));
        mk->r[i] = ri + kx;
        cq += b[i] * (t->x[i] - mk->x0[i]);
    }
    mk->r[n] = cq;
    for (size_t u = 0; u < mk->nu; u++)
        add_rows_t(mk, &mk->units[u], mk->f + mk->units[u].row, mk->r);
    return fr_qsma_cap_factor(mk->cap, mk->Ed, mk->s->kr, mk->hb->J, b);
}

/* Newton's method for point t (its q set, x and λ its guess) from the states Wold: FRICREG_OK
 * with t's states set and A factored at the solution, else a status (no message). */
static int newton(struct march *mk, const double *Wold, struct point *t)
{
    size_t n = mk->n;
    double last = INFINITY, lastl = INFINITY;
    for (int it = 0; it <= MAX_NEWTON; it++) {
        if (linearize(mk, Wold, t) != FRICREG_OK)
            return FRICREG_ESINGULAR;
        /* relative to x and λ, or to the preloads' scale (x_0 and its forces), whichever is
         * larger: at amplitudes far below the preloads' displacements, rounding in K x_0 is
         * what remains */
        double xinf = mk->phimax * t->q, lscale = fabs(t->lambda) + mk->fscale / mk->bmax;
        for (size_t i = 0; i < n; i++)
            xinf = fmax(xinf, fabs(t->x[i]));
        if (last <= NEWTON_TOL * xinf && lastl <= NEWTON_TOL * lscale) {
            memcpy(t->W, mk->Wn, mk->nst * sizeof *t->W);
            return FRICREG_OK;
        }
        for (size_t i = 0; i <= n; i++)
            mk->r[i] = -mk->r[i];
        solve(mk, 1, mk->r);
        last = 0.0;
        for (size_t i = 0; i < n; i++) {
            t->x[i] += mk->r[i];
            last = fmax(last, fabs(mk->r[i]));
        }
        t->lambda += mk->r[n];
        lastl = fabs(mk->r[n]);
        if (!isfinite(last) || !isfinite(lastl))
            return FRICREG_ENONFINITE;
    }
    return FRICREG_EWORK;
}

/* The sensitivities of point t reached from point s (A factored at t): t's dl and dW. */
static void sensitivities(struct march *mk, const struct point *s, struct point *t)
{
    size_t n = mk->n, N = n + 1, np = mk->np, nst = mk->nst;
    const double *b = mk->s->b;
    double df[3], du[3];
    for (size_t k = 0; k < np; k++) {
        const double *w = mk->p->w + k * n;
        double *rk = mk->rhs + k * N, c = 0.0;
        for (size_t i = 0; i < n; i++) {
            rk[i] = t->lambda * w[i];
            c += w[i] * (t->x[i] - mk->x0[i]) - b[i] * mk->dx0[k * n + i];
        }
        rk[n] = -c;
        for (size_t u = 0; u < mk->nu; u++) {
            const struct fr_qsma_unit *un = &mk->units[u];
            fr_qsma_unit_dforce(un, &mk->rec[u], role_of(mk, k, u), s->dW + k * nst + un->st, df);
            for (size_t a = 0; a < fr_qsma_unit_rows(un); a++)
                df[a] = -df[a];
            add_rows_t(mk, un, df, rk);
        }
    }
    if (np > 0)
        solve(mk, np, mk->rhs);
    for (size_t k = 0; k < np; k++) {
        const double *dx = mk->rhs + k * N;
        t->dl[k] = dx[n];
        rows_of(mk, dx, mk->ur);
        for (size_t u = 0; u < mk->nu; u++) {
            const struct fr_qsma_unit *un = &mk->units[u];
            for (size_t a = 0; a < fr_qsma_unit_rows(un); a++)
                du[a] = mk->ur[un->row + a];
            fr_qsma_unit_dstate(un, &mk->rec[u], role_of(mk, k, u), du, s->dW + k * nst + un->st,
                                t->dW + k * nst + un->st);
        }
    }
}

static void copy_point(const struct march *mk, const struct point *from, struct point *to)
{
    size_t np = mk->np;
    to->q = from->q;
    to->lambda = from->lambda;
    to->I = from->I;
    memcpy(to->x, from->x, mk->n * sizeof *to->x);
    memcpy(to->W, from->W, mk->nst * sizeof *to->W);
    memcpy(to->dl, from->dl, np * sizeof *to->dl);
    memcpy(to->dI, from->dI, np * sizeof *to->dI);
    memcpy(to->dW, from->dW, np * mk->nst * sizeof *to->dW);
}

/* Point *s marched to q1 > s->q (A then factored at q1), through *t as scratch (the two
 * swap); the step halved where Newton fails. */
static int advance(struct march *mk, struct point *s, double q1, struct point *t)
{
    double step = q1 - s->q;
    int halvings = 0;
    while (s->q < q1) {
        double qt = q1 - s->q <= step * (1.0 + 1e-12) ? q1 : s->q + step;
        t->q = qt;
        t->lambda = s->lambda;
        memcpy(t->x, s->x, mk->n * sizeof *t->x);
        int status = newton(mk, s->W, t);
        if (status != FRICREG_OK) {
            if (++halvings > MAX_HALVINGS)
                return status;
            step *= 0.5;
            continue;
        }
        if (mk->p != NULL)
            sensitivities(mk, s, t);
        double dq = qt - s->q;
        t->I = s->I + 0.5 * dq * (s->lambda + t->lambda);
        for (size_t k = 0; k < mk->np; k++)
            t->dI[k] = s->dI[k] + 0.5 * dq * (s->dl[k] + t->dl[k]);
        mk->prev_q = s->q;
        mk->prev_lambda = s->lambda;
        struct point swap = *s;
        *s = *t;
        *t = swap;
    }
    return FRICREG_OK;
}

/* Target i reached from the grid point g: its results into out. */
static int target(struct march *mk, const struct point *g, double a, size_t i,
                  struct fr_qsma_out *out)
{
    struct point *side = &mk->pt[2], *t = &mk->pt[1];
    copy_point(mk, g, side);
    int status = advance(mk, side, a, t);
    if (status != FRICREG_OK)
        return status;
    size_t N = mk->n + 1, np = mk->np;
    memset(mk->r, 0, N * sizeof *mk->r); /* dλ/dq on the factor at the target */
    mk->r[mk->n] = 1.0;
    solve(mk, 1, mk->r);
    out->lambda[i] = side->lambda;
    out->integral[i] = side->I;
    out->slope[i] = mk->r[mk->n];
    if (out->dint_da != NULL)
        out->dint_da[i] = 0.5 * (mk->prev_lambda + side->lambda) +
                          0.5 * (a - mk->prev_q) * out->slope[i];
    for (size_t k = 0; k < np && out->dlambda != NULL; k++) {
        out->dlambda[i * np + k] = side->dl[k];
        out->dintegral[i * np + k] = side->dI[k];
    }
    /* the side point becomes scratch again: the pointers stay distinct */
    return FRICREG_OK;
}

static int fail_step(struct march *mk, int status, double q)
{
    if (status == FRICREG_ESINGULAR)
        return fr_fail(mk->hb, status,
                       "%s: the static equilibrium's bordered matrix is singular at the modal "
                       "amplitude %g",
                       mk->fn, q);
    return fr_fail(mk->hb, status == FRICREG_ENONFINITE ? status : FRICREG_EWORK,
                   "%s: Newton's method found no static equilibrium at the modal amplitude %g "
                   "(the step halved %d times)",
                   mk->fn, q, MAX_HALVINGS);
}

static int run(struct march *mk, size_t na, const double *amp, struct fr_qsma_out *out)
{
    struct point *g = &mk->pt[0];
    int status = rest_state(mk, g);
    if (status != FRICREG_OK)
        return status;
    double h = ldexp(1.0, (int)floor(log2(amp[na - 1] / GRID_STEPS)));
    for (size_t i = 0, j = 0; i < na; j++) {
        double qn = (double)(j + 1) * h;
        /* a target on a grid point too is reached from the point below: the step's tangent
         * there is the slope from below (from the point itself a zero step would stick) */
        for (; i < na && amp[i] <= qn; i++)
            if ((status = target(mk, g, amp[i], i, out)) != FRICREG_OK)
                return fail_step(mk, status, amp[i]);
        if (i == na)
            break;
        if ((status = advance(mk, g, qn, &mk->pt[1])) != FRICREG_OK)
            return fail_step(mk, status, qn);
    }
    return FRICREG_OK;
}

int fr_qsma_march(fricreg_hb *hb, const char *fn, struct fr_qsma *s, size_t na, const double *amp,
                  const struct fr_qsma_sens *p, struct fr_qsma_out *out)
{
    struct march mk = {.hb = hb,
                       .fn = fn,
                       .s = s,
                       .p = p,
                       .n = s->n,
                       .m = s->m,
                       .nu = s->nsl + s->ncon,
                       .nst = s->nst,
                       .np = p ? p->np : 0};
    int status = alloc_march(&mk);
    if (status != FRICREG_OK) {
        free_march(&mk);
        return status == FRICREG_ESINGULAR
                   ? fr_fail(hb, status, "%s: the stuck structure's K_0 is singular", fn)
                   : fr_fail(hb, FRICREG_ENOMEM, "%s: no memory for the marched path of %zu dofs",
                             fn, s->n);
    }
    for (size_t i = 0; i < s->n; i++) {
        mk.phimax = fmax(mk.phimax, fabs(s->phi[i]));
        mk.bmax = fmax(mk.bmax, fabs(s->b[i]));
    }
    build_units(&mk);
    status = run(&mk, na, amp, out);
    free_march(&mk);
    return status;
}
