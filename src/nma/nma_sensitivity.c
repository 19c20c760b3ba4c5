/* SPDX-License-Identifier: GPL-3.0-or-later */
/* nma_sensitivity.c — the exact parameter sensitivities of a backbone point
 * (fricreg_hb_nma_point_sensitivities, fricreg_hb.h). The point solves the extended periodic
 * motion concept's equations R(y, p) = 0 of nma_solve.c, y = (q, ω, ξ), at its fixed modal
 * amplitude a; by the implicit function theorem
 *
 *     dy/dp = −(∂R/∂y)^-1 ∂R/∂p,
 *
 * ∂R/∂y Newton's matrix at the point (one evaluation with the Jacobians and one real LU of
 * order nq + 2: a Newton iteration's work), every parameter's ∂R/∂p one right-hand side of one
 * solve. ∂R/∂p of an element parameter is G ∂F/∂p on (R) and −g^T ∂F_1/∂p on the amplitude and
 * phase rows, ∂F/∂p exact from the forces and Jacobians already there (hb/element_params.c);
 * a stiffness of the stuck structure also moves the mode shape φ of the amplitude condition
 * (and ξ_k = φ^T C φ of the modal damping): nma_sensitivity_terms.c. The damping enters D_h
 * through ξ less a shift (ξ_k with modal damping, Rayleigh's a0 with the matrix C), so ζ_k and
 * a0 move ξ by their shift's derivative and nothing else; Rayleigh's a1 enters D_h as i hω a1 K
 * (dG_h/da1 = −Y_h^T (i hω K) Y_h). The amplitude's right-hand side is the amplitude row's −c.
 * The driver's state that the getters read is restored: the evaluation is the one
 * fricreg_hb_nma_point with x makes. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "nma_internal.h"
#include "hb/busy.h"
#include "hb/element_params.h"
#include "hb/lu.h"
#include "hb/residual.h"
#include "hb/sparse.h"

/* The caller's parameters: np of them in parallel arrays. */
struct params {
    size_t np;
    const int *kind;
    const size_t *first, *count, *index;
};

/* One call's workspace. */
struct sens {
    double *rhs;   /* [np nd]: ∂R/∂p, then dy/dp (its ξ without the shift) */
    double *df;    /* [np nq]: ∂F/∂p (0 but for element parameters) */
    double *dk;    /* [np m]: d k_r/dp of the stuck rows */
    double *shift; /* [np]: the derivative of the shift ξ_k or a0 that D_h's ξ is taken from */
    double *da1;   /* [np]: 1 where Rayleigh's a1 is in D_h (matrix damping) */
    double *t;     /* [3 np]: the shape's terms (nma_sensitivity_terms.c) */
    double *X1;    /* [2 n]: the first harmonic of the displacements */
    double *out;   /* [np (2 + n)]: dω, dζ, then d|X_1| */
    double *work;  /* the AFT's and the amplitudes' scratch */
    int shape;     /* some parameter moves φ */
};

static int check_element(fricreg_hb *hb, const char *fn, const char *what, size_t e0, size_t ne,
                         size_t j, int *shape)
{
    if (ne == 0 || e0 >= hb->count || ne > hb->count - e0)
        return fr_fail(hb, FRICREG_EINVAL,
                       "%s: %s: elements first = %zu, count = %zu, the driver holds %zu", fn, what,
                       e0, ne, hb->count);
    int moves = 0;
    for (size_t e = e0; e < e0 + ne; e++) {
        int status = fr_hb_element_param_check(hb, fn, what, e, j);
        if (status != FRICREG_OK)
            return status;
        for (size_t sr = 0; sr < fr_hb_rows_of(hb, e); sr++)
            moves |= fr_hb_nma_row_dk(hb, e, j, sr) != 0.0;
    }
    if (moves && hb->n > FR_HB_NMA_SPARSE_ALL_MODES)
        return fr_fail(hb, FRICREG_EINVAL,
                       "%s: %s: a stiffness of the stuck structure moves the mode shape, whose "
                       "derivative (a dense bordered solve) is taken up to %d dofs; the model "
                       "has %zu",
                       fn, what, FR_HB_NMA_SPARSE_ALL_MODES, hb->n);
    *shape |= moves;
    return FRICREG_OK;
}

static int check_param(fricreg_hb *hb, const char *fn, const struct params *P, size_t k, int *shape)
{
    char what[48];
    snprintf(what, sizeof what, "parameter %zu", k);
    size_t j = P->index[k];
    switch (P->kind[k]) {
    case FRICREG_HB_NMA_PARAM_AMPLITUDE: return FRICREG_OK;
    case FRICREG_HB_NMA_PARAM_DAMPING:
        if (j > 2)
            return fr_fail(hb, FRICREG_EINVAL, "%s: %s: damping index %zu (0 zeta_k, 1 a0, 2 a1)",
                           fn, what, j);
        if (j == 0 && !hb->nma->modal)
            return fr_fail(hb, FRICREG_EINVAL,
                           "%s: %s: zeta_k is the modal damping's "
                           "(FRICREG_HB_NMA_DAMPING_MODAL); the backbone has the matrix C",
                           fn, what);
        if (j > 0 && !hb->rayleigh)
            return fr_fail(hb, FRICREG_EINVAL,
                           "%s: %s: %s is Rayleigh's, and the model's damping is a matrix "
                           "(fricreg_hb_set_rayleigh)",
                           fn, what, j == 1 ? "a0" : "a1");
        return FRICREG_OK;
    case FRICREG_HB_NMA_PARAM_ELEMENT:
        return check_element(hb, fn, what, P->first[k], P->count[k], j, shape);
    default:
        return fr_fail(hb, FRICREG_EINVAL,
                       "%s: %s: kind = %d is not one of enum fricreg_hb_nma_param", fn, what,
                       P->kind[k]);
    }
}

static int check_args(fricreg_hb *hb, const char *fn, size_t i, const struct params *P,
                      const double *domega, const double *dzeta, size_t ndof, const double *damp,
                      int *shape)
{
    if (hb->busy) /* the evaluation would move the solve's factors */
        return fr_hb_refuse(hb, fn);
    if (domega == NULL || dzeta == NULL)
        return fr_fail(hb, FRICREG_ENULL, "%s: %s is NULL", fn,
                       domega == NULL ? "domega" : "dzeta");
    if (P->np > 0 && (!P->kind || !P->first || !P->count || !P->index))
        return fr_fail(hb, FRICREG_ENULL, "%s: %s is NULL", fn,
                       !P->kind    ? "kind"
                       : !P->first ? "first"
                       : !P->count ? "count"
                                   : "index");
    size_t npts = fricreg_hb_nma_points(hb);
    if (i >= npts)
        return fr_fail(hb, FRICREG_EINVAL, "%s: i = %zu, %zu points stored", fn, i, npts);
    if (damp != NULL && ndof != hb->n)
        return fr_fail(hb, FRICREG_ESIZE, "%s: ndof = %zu, the driver has %zu", fn, ndof, hb->n);
    if (!fr_hb_backbone_holds(hb) || hb->nma->nq != hb->nq)
        return fr_fail(hb, FRICREG_EINVAL, "%s: the model changed since the backbone", fn);
    *shape = 0;
    for (size_t k = 0; k < P->np; k++) {
        int status = check_param(hb, fn, P, k, shape);
        if (status != FRICREG_OK)
            return status;
    }
    return FRICREG_OK;
}

/* The workspace, one allocation (*buf, freed by the caller). */
static int alloc_sens(fricreg_hb *hb, const char *fn, size_t np, struct sens *w, double **buf)
{
    size_t n = hb->n, m = hb->m, nq = hb->nq, nd = nq + 2, nc = hb->nc;
    size_t nwork = 3 * nc + 9 * nc * nc, namp = 10 * n + nq;
    size_t per = nd + nq + m + 7 + n, rest = 2 * n + (nwork > namp ? nwork : namp);
    double *b = np <= (SIZE_MAX / sizeof *b - rest) / per ? calloc(np * per + rest, sizeof *b)
                                                          : NULL;
    if (b == NULL)
        return fr_fail(hb, FRICREG_ENOMEM, "%s: no memory for %zu parameters' sensitivities", fn,
                       np);
    w->rhs = b;
    w->df = w->rhs + np * nd;
    w->dk = w->df + np * nq;
    w->shift = w->dk + np * m;
    w->da1 = w->shift + np;
    w->t = w->da1 + np;
    w->out = w->t + 3 * np;
    w->X1 = w->out + np * (2 + n);
    w->work = w->X1 + 2 * n;
    *buf = b;
    return FRICREG_OK;
}

/* Newton's matrix at the point factored: FRICREG_ESINGULAR as the march's (a fold). */
static int factor_newton(fricreg_hb *hb, const char *fn, struct fr_hb_nma *s, size_t i)
{
    size_t nd = s->nd;
    double amax = 0.0;
    for (size_t k = 0; k < nd * nd; k++)
        amax = fmax(amax, fabs(s->A[k]));
    fr_hb_lu_factor(s->A, nd, s->piv);
    for (size_t k = 0; k < nd; k++) {
        double p = fabs(s->A[k * nd + k]);
        if (!(p > 1e-14 * amax) || !isfinite(p))
            return fr_fail(hb, FRICREG_ESINGULAR,
                           "%s: point %zu (amplitude %g): the nonlinear mode's Newton matrix is "
                           "singular (pivot %zu: %g, largest entry %g): a fold of the backbone in "
                           "the amplitude, where the derivatives at fixed a are infinite",
                           fn, i, s->amplitude, k, p, amax);
    }
    return FRICREG_OK;
}

/* φ^T K φ = ω_k² − Σ_r k_r (J_r φ)²: ξ_k's derivative in Rayleigh's a1 (modal damping). */
static double phi_k_phi(const fricreg_hb *hb, const struct fr_hb_nma *s)
{
    double v = s->omega_k * s->omega_k;
    for (size_t r = 0; r < hb->m; r++) {
        double k, limit, q = 0.0;
        fr_hb_nma_row(hb, r, &k, &limit);
        for (size_t j = 0; j < hb->n; j++)
            q += hb->J[r * hb->n + j] * s->phi[j];
        v -= k * q * q;
    }
    return v;
}

/* Element parameter k's ∂F/∂p (summed over its elements), d k_r/dp and right-hand side r. */
static int element_rhs(fricreg_hb *hb, const char *fn, struct fr_hb_nma *s, const struct params *P,
                       size_t k, struct sens *w, double c, double *r)
{
    size_t nq = hb->nq, m = hb->m, j = P->index[k];
    double *df = w->df + k * nq, sm[2];
    for (size_t e = P->first[k]; e < P->first[k] + P->count[k]; e++) {
        int status = fr_hb_element_dfdp(hb, fn, e, j, s->y, df, w->work);
        if (status != FRICREG_OK)
            return status;
        for (size_t sr = 0; sr < fr_hb_rows_of(hb, e); sr++)
            w->dk[k * m + hb->erow[e] + sr] += fr_hb_nma_row_dk(hb, e, j, sr);
    }
    fr_hb_apply(hb, hb->G, NULL, 0.0, df, r);
    fr_hb_nma_modal(hb, hb->ql + 2 * m, df, sm);
    r[nq] = c * sm[0];
    r[nq + 1] = c * sm[1];
    return FRICREG_OK;
}

/* Every parameter's ∂R/∂p into w->rhs (the shape's terms included), the shifts and a1's. */
static int right_hand_sides(fricreg_hb *hb, const char *fn, struct fr_hb_nma *s,
                            const struct params *P, struct sens *w, double c)
{
    size_t nq = hb->nq, nd = s->nd, m = hb->m;
    int a1 = 0;
    for (size_t k = 0; k < P->np; k++) {
        double *r = w->rhs + k * nd, sm[2];
        size_t j = P->index[k];
        if (P->kind[k] == FRICREG_HB_NMA_PARAM_ELEMENT) {
            int status = element_rhs(hb, fn, s, P, k, w, c, r);
            if (status != FRICREG_OK)
                return status;
        } else if (P->kind[k] == FRICREG_HB_NMA_PARAM_AMPLITUDE) {
            r[nq] = -c;
        } else if (j == 0) { /* ξ_k = 2 ζ_k ω_k */
            w->shift[k] = 2.0 * s->omega_k;
        } else if (j == 1) { /* a0: φ^T M φ = 1 in ξ_k, or a0 − ξ in D_h */
            w->shift[k] = 1.0;
        } else if (s->modal) {
            w->shift[k] = phi_k_phi(hb, s);
        } else { /* a1 in D_h: dG/da1 F and dg/da1 (dGx and dgx are free after the Jacobian) */
            if (!a1)
                fr_hb_nma_damping_derivatives(hb, s, s->y[nq], 1);
            a1 = 1;
            fr_hb_apply(hb, s->dGx, NULL, 0.0, hb->fq, r);
            fr_hb_nma_modal(hb, s->dgx + 2 * m, hb->fq, sm);
            r[nq] = c * sm[0];
            r[nq + 1] = c * sm[1];
            w->da1[k] = 1.0;
        }
    }
    fr_hb_nma_first_harmonic(hb, hb->fq, w->X1);
    if (!w->shape)
        return FRICREG_OK;
    int status = fr_hb_nma_shape_terms(hb, fn, s, w->X1, P->np, w->dk, w->t);
    for (size_t k = 0; k < P->np && status == FRICREG_OK; k++) {
        w->rhs[k * nd + nq] += c * w->t[3 * k];
        w->rhs[k * nd + nq + 1] += c * w->t[3 * k + 1];
        if (s->modal) /* dξ_k = 2 (C φ)^T dφ */
            w->shift[k] += 2.0 * w->t[3 * k + 2];
    }
    return status;
}

/* The point's evaluation, the solve and the outputs into w->out. */
static int sensitivities(fricreg_hb *hb, const char *fn, size_t i, const struct params *P,
                         struct sens *w, int amplitudes)
{
    struct fr_hb_nma *s = hb->nma;
    size_t nq = s->nq, nd = s->nd, np = P->np;
    const double *p = s->pts + i * s->stride;
    memcpy(s->y, p + 3, nq * sizeof(double));
    s->y[nq] = p[1];
    s->y[nq + 1] = p[2];
    s->amplitude = p[0];
    s->scale = 0.0;
    for (size_t j = 0; j < nq; j++)
        s->scale = fmax(s->scale, fabs(s->y[j]));
    if (!(s->scale > 0.0))
        s->scale = p[0];
    double c = s->scale / s->amplitude, omega = p[1], xi = p[2];
    int status = fr_hb_nma_system(hb, fn, s, s->y, s->R, 1);
    if (status == FRICREG_OK)
        status = factor_newton(hb, fn, s, i);
    if (status == FRICREG_OK)
        status = right_hand_sides(hb, fn, s, P, w, c);
    if (status != FRICREG_OK)
        return status;
    fr_hb_lu_solve_many(s->A, nd, s->piv, np, w->rhs);
    for (size_t k = 0; k < np * nd; k++)
        w->rhs[k] = -w->rhs[k];
    for (size_t k = 0; k < np; k++) {
        double dw = w->rhs[k * nd + nq], dxi = w->rhs[k * nd + nq + 1] + w->shift[k];
        w->out[k] = dw;
        w->out[np + k] = dxi / (2.0 * omega) - xi * dw / (2.0 * omega * omega);
    }
    if (!amplitudes)
        return FRICREG_OK;
    return fr_hb_nma_amplitude_terms(hb, fn, omega, w->X1, np, w->rhs, nd, w->df, w->da1, w->work,
                                     w->out + 2 * np);
}

int fricreg_hb_nma_point_sensitivities(fricreg_hb *hb, size_t i, size_t np, const int kind[],
                                       const size_t first[], const size_t count[],
                                       const size_t index[], double domega[], double dzeta[],
                                       size_t ndof, double damp[])
{
    static const char fn[] = "nma_point_sensitivities";
    if (hb == NULL)
        return FRICREG_ENULL;
    struct params P = {np, kind, first, count, index};
    struct sens w = {0};
    int status = check_args(hb, fn, i, &P, domega, dzeta, ndof, damp, &w.shape);
    if (status != FRICREG_OK || np == 0)
        return status;
    double *buf = NULL;
    if ((status = alloc_sens(hb, fn, np, &w, &buf)) != FRICREG_OK)
        return status;
    struct fr_hb_nma *s = hb->nma;
    double amplitude = s->amplitude, scale = s->scale;
    fr_hb_nma_enter(hb, s);
    status = sensitivities(hb, fn, i, &P, &w, damp != NULL);
    fr_hb_nma_leave(hb, s);
    if (hb->sparse) /* the next call factors afresh, as after a solving call */
        fr_hb_sparse_release(hb);
    s->amplitude = amplitude;
    s->scale = scale;
    if (status == FRICREG_OK) {
        memcpy(domega, w.out, np * sizeof *domega);
        memcpy(dzeta, w.out + np, np * sizeof *dzeta);
        if (damp != NULL)
            memcpy(damp, w.out + 2 * np, np * hb->n * sizeof *damp);
    }
    free(buf);
    return status;
}
