/* SPDX-License-Identifier: GPL-3.0-or-later */
/* aft_march_jacobian.c — the exact Jacobian of the march of a law with state (aft_march.h),
 * for the sampled march (aft_march.c).
 *
 * Exact for the sampled march: a law without state has f(theta_n) = f(u(theta_n)),
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
 * approximate, by how far it moved.) A law whose state is not sliders' (dahl) gives its own
 * tangents of f and the state in u and the state (element_kind.h's state_tangents), and the
 * same chain runs on its whole state: S' = G_u Phi_n + G_s S, d f_n / d u = F_u Phi_n + F_s S,
 * started at (I - Psi)^-1 R, Psi the product of the G_s over the period. */
#include <math.h>
#include <string.h>

#include "aft_march_internal.h"
#include "base/lapack.h"

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

/* One sample's step of a law whose state is not sliders' (element_kind.h's state_tangents):
 * d f_n / d u = F_u Phi_n + F_s S into g[dim b], S' = G_u Phi_n + G_s S, and in the first
 * pass Psi' = G_s Psi: the sliders' chain with the law's own tangents. */
static void state_step(struct fr_aft_march *w, const fricreg_element_type *type,
                       const double *params, const double *u, size_t nc, int first, double *g)
{
    enum { MS = FR_STATE_TANGENTS_MAX };
    size_t dim = (size_t)w->dim, ns = fricreg_element_nstate(type), b = dim * nc;
    double fu[MAX_DIM * MAX_DIM], fs[MAX_DIM * MS], su[MS * MAX_DIM], ss[MS * MS];
    type->kind->state_tangents(type, params, w->state, u, fu, fs, su, ss, w->state);
    for (size_t r = 0; r < dim + ns; r++) { /* the force's rows, then the state's */
        const double *du = r < dim ? fu + dim * r : su + dim * (r - dim);
        const double *ds = r < dim ? fs + ns * r : ss + ns * (r - dim);
        double *out = r < dim ? g + b * r : w->snext + b * (r - dim);
        for (size_t col = 0; col < b; col++) {
            double v = du[col / nc] * w->phi[col % nc];
            for (size_t j = 0; j < ns; j++)
                v += ds[j] * w->sens[b * j + col];
            out[col] = v;
        }
    }
    memcpy(w->sens, w->snext, ns * b * sizeof *w->sens);
    if (!first)
        return;
    double next[MS * MS] = {0.0};
    for (size_t r = 0; r < ns; r++)
        for (size_t c = 0; c < ns; c++)
            for (size_t j = 0; j < ns; j++)
                next[ns * r + c] += ss[ns * r + j] * w->psis[ns * j + c];
    memcpy(w->psis, next, ns * ns * sizeof *next);
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

/* One step of the march to u with the basis there in w->phi, by the law's own kind of
 * tangents: d f / d u into g, the sensitivities moved on. The state becomes eval's, whose
 * checks the march's period passed at these points. */
static void sample_step(struct fr_aft_march *w, const fricreg_element_type *type,
                        const double *params, const double *u, size_t nc, int first, double *g)
{
    size_t td = (size_t)w->dim, ns = fricreg_element_nstate(type) / td;
    if (type->kind->state_tangents != NULL) {
        state_step(w, type, params, u, nc, first, g);
        return;
    }
    type->kind->slider_tangents(type, params, w->state, u, w->tsl, w->twl, w->state);
    sensitivity_step(w, td, ns, nc, first, g);
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
    memcpy(w->state, w->start, fricreg_element_nstate(type) * sizeof *w->state);
    for (size_t n = 0; n < N; n++) {
        double u[MAX_DIM];
        if (!isnan(w->tturn[n])) { /* through the turn first, its forces' rows overwritten */
            fr_aft_march_basis_at(a, w->tturn[n], w->phi);
            sample_step(w, type, params, &w->uturn[n], nc, first, w->g + k * td * b);
        }
        for (size_t d = 0; d < td; d++)
            u[d] = w->us[d * N + n];
        for (size_t j = 0; j < nc; j++)
            w->phi[j] = fr_aft_sample_basis(a, j, n);
        sample_step(w, type, params, u, nc, first, w->g + k * td * b);
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

/* A state law's periodic start: S = (I - Psi)^-1 R from the first pass's R (in w->sens); where
 * I - Psi is singular (a law that forgets nothing over the period: at rest), S = R. */
static void state_periodic_start(struct fr_aft_march *w, size_t ns, size_t b)
{
    int n = (int)ns, nb = (int)b, info;
    double A[FR_STATE_TANGENTS_MAX * FR_STATE_TANGENTS_MAX];
    for (size_t r = 0; r < ns; r++) /* by columns, as dgesv takes them */
        for (size_t c = 0; c < ns; c++)
            A[c * ns + r] = (r == c) - w->psis[r * ns + c];
    for (size_t r = 0; r < ns; r++)
        for (size_t col = 0; col < b; col++)
            w->snext[col * ns + r] = w->sens[r * b + col];
    dgesv_(&n, &nb, A, &n, w->piv, w->snext, &n, &info);
    for (size_t r = 0; r < ns && info == 0; r++)
        for (size_t col = 0; col < b; col++)
            w->sens[r * b + col] = w->snext[col * ns + r];
}

/* The exact Jacobian of a law with state (the file's comment) into jac. */
void fr_aft_march_sensitivities(const fricreg_aft *a, struct fr_aft_march *w,
                                const fricreg_element_type *type, const double *params, double *jac)
{
    size_t td = (size_t)w->dim, b = td * a->nc, nstate = fricreg_element_nstate(type);
    size_t ns = nstate / td;
    memset(w->sens, 0, nstate * b * sizeof *w->sens);
    if (type->kind->state_tangents != NULL) {
        for (size_t i = 0; i < nstate * nstate; i++)
            w->psis[i] = i % (nstate + 1) == 0;
        sensitive_period(a, w, type, params, 1, NULL);
        state_periodic_start(w, nstate, b);
        memset(jac, 0, b * b * sizeof *jac);
        sensitive_period(a, w, type, params, 0, jac);
        return;
    }
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
