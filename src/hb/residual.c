/* SPDX-License-Identifier: GPL-3.0-or-later */
/* residual.c — the condensed HB residual (R) of fricreg_hb.h in real form, its Jacobian and
 * its Ω derivative, and the real LU solve of Newton's matrix. For harmonic h >= 1, element e,
 * with G = Gr + i Gi and F = fa − i fb (the complex form of fricreg_hb.h):
 *
 *     R_a = a + sum_e' (Gr fa + Gi fb) − Re ql,      R_b = b + sum_e' (Gr fb − Gi fa) + Im ql
 *
 * and R_0 = q0 + sum_e' G_0 f0 − ql_0 (real), e, e' rows of J. The forces and their exact
 * Jacobians come from fricreg_aft_iwan_exact (a Jenkins element is one slider), or with lift-off
 * fricreg_aft_jenkins_normal_exact (two rows: the tangential force f on u, the normal force N on
 * g, one Jacobian block coupling them; an Iwan element's sliders summed on the tangential row),
 * one element at a time; the 3-D contact element's (three rows: x, y, normal) from
 * fricreg_aft_jenkins_2d_normal_sampled. Each element by its own kind: a model may mix them. */
#include <math.h>
#include <string.h>

#include "hb_internal.h"
#include "joint/aft_march.h"
#include "lu.h"
#include "residual.h"

/* out[nq] = G F − load ql in the real form above, from the forces f[nq] and the complex
 * G[(H+1) m m], ql[(H+1) m] (the condensation or its Ω derivative; NULL: no load). */
void fr_hb_apply(const fricreg_hb *hb, const double *G, const double *ql, double load,
                 const double *f, double *out)
{
    size_t m = hb->m, nc = hb->nc;
    for (size_t e = 0; e < m; e++)
        for (int h = 0; h <= hb->H; h++) {
            static const double none[2] = {0.0, 0.0};
            const double *g = G + 2 * ((size_t)h * m * m + e * m),
                         *p = ql ? ql + 2 * ((size_t)h * m + e) : none;
            if (h == 0) {
                double s = -load * p[0];
                for (size_t e2 = 0; e2 < m; e2++)
                    s += g[2 * e2] * f[e2 * nc];
                out[e * nc] = s;
                continue;
            }
            size_t ca = 2 * (size_t)h - 1, cb = ca + 1;
            double ra = -load * p[0], rb = load * p[1];
            for (size_t e2 = 0; e2 < m; e2++) {
                double gr = g[2 * e2], gi = g[2 * e2 + 1], fa = f[e2 * nc + ca],
                       fb = f[e2 * nc + cb];
                ra += gr * fa + gi * fb;
                rb += gr * fb - gi * fa;
            }
            out[e * nc + ca] = ra;
            out[e * nc + cb] = rb;
        }
}

/* Iwan element e with lift-off at its coefficients u[2 nc] (u, then g): its sliders' forces
 * summed into f[nc] and their Jacobians' tangential rows into jac (NULL: none), the normal
 * force (the same for every slider) into f[nc ..] and the normal rows from the first slider,
 * each slider by fricreg_aft_jenkins_normal_exact into the scratch after the sliders. */
static int iwan_normal(fricreg_hb *hb, size_t e, const double *u, double *f, double *jac)
{
    size_t nc = hb->nc, me = hb->me, b = 2 * nc;
    const double *k, *mu;
    size_t ns = fr_hb_sliders(hb, e, &k, &mu);
    double *fs = hb->sk + 2 * hb->nsl, *js = fs + b;
    for (size_t s = 0; s < ns; s++) {
        int status = fricreg_aft_jenkins_normal_exact(hb->aft, k[s], mu[s], hb->nl[2 * me + e],
                                                      hb->nl[3 * me + e], nc, u, u + nc, fs,
                                                      fs + nc, jac ? js : NULL);
        if (status != FRICREG_OK)
            return status;
        size_t rows = s == 0 ? b : nc; /* the normal rows once */
        for (size_t i = 0; i < rows; i++)
            f[i] = s == 0 ? fs[i] : f[i] + fs[i];
        for (size_t i = 0; jac != NULL && i < rows * b; i++)
            jac[i] = s == 0 ? js[i] : jac[i] + js[i];
    }
    return FRICREG_OK;
}

/* Richardson's extrapolation 2 F(N) - F(N/2) of forces f[w] and, with jac, their Jacobian
 * [w x w], in place, from the half-sampled fh, jh. */
static void richardson(size_t w, const double *fh, const double *jh, double *f, double *jac)
{
    for (size_t i = 0; i < w; i++)
        f[i] = 2.0 * f[i] - fh[i];
    for (size_t i = 0; jac != NULL && i < w * w; i++)
        jac[i] = 2.0 * jac[i] - jh[i];
}

/* 3-D contact element e at its coefficients u[3 nc] (ux, uy, g): forces f[3 nc] and, with jac,
 * their Jacobian [3nc x 3nc] by Richardson's extrapolation of the sampled AFT over N and N/2
 * samples, 2 F(N) - F(N/2): the return mapping at samples lags the continuous element by a
 * first-order term in 1/N where the slip turns (fricreg_aft.h), which this removes. */
static int contact_3d(fricreg_hb *hb, size_t e, const double *u, double *f, double *jac)
{
    size_t nc = hb->nc, me = hb->me, w = 3 * nc;
    const double *p = hb->nl;
    double *fh = hb->half, *jh = hb->half + w;
    int status = fricreg_aft_jenkins_2d_normal_sampled(hb->aft, p[e], p[me + e], p[2 * me + e],
                                                       p[3 * me + e], nc, u, u + 2 * nc, f,
                                                       f + 2 * nc, jac);
    if (status == FRICREG_OK)
        status = fricreg_aft_jenkins_2d_normal_sampled(hb->aft_half, p[e], p[me + e], p[2 * me + e],
                                                       p[3 * me + e], nc, u, u + 2 * nc, fh,
                                                       fh + 2 * nc, jac ? jh : NULL);
    if (status != FRICREG_OK)
        return status;
    richardson(w, fh, jh, f, jac);
    return FRICREG_OK;
}

/* Marched element e (joint/aft_march.h) at its coefficients u[dim nc]: forces f and, with jac,
 * their Jacobian; a law whose march lags (state on more than one component) by Richardson's
 * extrapolation over N and N/2 samples, as contact_3d (its samples lag the continuous law by a
 * term in 1/N); a 1-D one is marched through its turns, exact at the samples. */
static int march(fricreg_hb *hb, size_t e, const double *u, double *f, double *jac)
{
    const fricreg_element_type *type = hb->etype[e];
    const double *p = hb->ep + hb->epo[e];
    size_t w = (size_t)fricreg_element_dim(type) * hb->nc;
    double *fh = hb->half, *jh = hb->half + w;
    int status = fr_aft_march(hb->aft, hb->march, type, p, u, f, jac);
    if (status != FRICREG_OK || !fr_aft_march_lags(type))
        return status;
    if ((status = fr_aft_march(hb->aft_half, hb->march, type, p, u, fh, jac ? jh : NULL)) !=
        FRICREG_OK)
        return status;
    richardson(w, fh, jh, f, jac);
    return FRICREG_OK;
}

/* Element e's forces into fq and, with jac, its Jacobian block, by its kind's AFT. */
static int element(fricreg_hb *hb, size_t e, const double *q, int jac)
{
    size_t nc = hb->nc, me = hb->me, at = hb->erow[e] * nc;
    const double *u = q + at, *p = hb->nl;
    double *f = hb->fq + at, *J = jac ? fr_hb_block_of(hb, e) : NULL;
    if (hb->kind[e] == FR_HB_MARCH)
        return march(hb, e, u, f, J);
    if (hb->kind[e] == FR_HB_CONTACT_3D)
        return contact_3d(hb, e, u, f, J);
    const double *k, *phi;
    size_t ns = fr_hb_sliders(hb, e, &k, &phi);
    if (hb->kind[e] == FR_HB_LIFTOFF && ns > 1)
        return iwan_normal(hb, e, u, f, J);
    if (hb->kind[e] == FR_HB_LIFTOFF)
        return fricreg_aft_jenkins_normal_exact(hb->aft, p[e], p[me + e], p[2 * me + e],
                                                p[3 * me + e], nc, u, u + nc, f, f + nc, J);
    return fricreg_aft_iwan_exact(hb->aft, ns, k, phi, nc, u, f, J);
}

int fr_hb_residual(fricreg_hb *hb, const char *fn, const double *q, double *R, int jac)
{
    for (size_t e = 0; e < hb->me; e++) {
        int status = element(hb, e, q, jac);
        if (status != FRICREG_OK && hb->kind[e] == FR_HB_MARCH)
            return fr_fail(hb, status,
                           "%s: element %zu (%s) refused its displacement at a sample of the "
                           "period (%s)",
                           fn, e, fricreg_element_name(hb->etype[e]), fricreg_strerror(status));
        if (status != FRICREG_OK)
            return fr_fail(hb, status, "%s: the AFT of element %zu failed: %s", fn, e,
                           fricreg_aft_errmsg(hb->aft));
    }
    if (jac) /* the orbit whose Jacobians these are, for the monodromy */
        memmove(hb->qjac, q, hb->nq * sizeof *q);
    fr_hb_apply(hb, hb->G, hb->ql, fr_hb_load(hb), hb->fq, R);
    for (size_t j = 0; j < hb->nq; j++)
        R[j] += q[j];
    return FRICREG_OK;
}

void fr_hb_dlevel(const fricreg_hb *hb, double *out)
{
    size_t m = hb->m, nc = hb->nc;
    for (size_t e = 0; e < m; e++)
        for (int h = 0; h <= hb->H; h++) { /* −ql in the real form of fr_hb_apply */
            const double *p = hb->ql + 2 * ((size_t)h * m + e);
            if (h == 0) {
                out[e * nc] = -p[0];
                continue;
            }
            out[e * nc + 2 * (size_t)h - 1] = -p[0];
            out[e * nc + 2 * (size_t)h] = p[1];
        }
}

void fr_hb_matrix(fricreg_hb *hb, const double *jac, double *A, size_t ld)
{
    /* row r of J against element e2's block: its rows r2 = erow[e2] + s, its Jacobian's rows
     * (s nc + c) and columns the block's rows nc unknowns, from erow[e2] nc on */
    size_t m = hb->m, nc = hb->nc;
    for (size_t r = 0; r < m; r++)
        for (size_t e2 = 0; e2 < hb->me; e2++) {
            size_t rows = fr_hb_rows_of(hb, e2), b = rows * nc, r2 = hb->erow[e2], at = r2 * nc;
            const double *block = jac + hb->ejq[e2] * nc * nc;
            for (int h = 0; h <= hb->H; h++) {
                size_t ca = h == 0 ? 0 : 2 * (size_t)h - 1, cb = ca + 1;
                double *ra = A + (r * nc + ca) * ld + at, *rb = A + (r * nc + cb) * ld + at;
                for (size_t j = 0; j < b; j++) {
                    double sa = 0.0, sb = 0.0;
                    for (size_t s = 0; s < rows; s++) {
                        const double *g = hb->G + 2 * ((size_t)h * m * m + r * m + r2 + s);
                        const double *J2 = block + s * nc * b;
                        if (h == 0) {
                            sa += g[0] * J2[j];
                            continue;
                        }
                        sa += g[0] * J2[ca * b + j] + g[1] * J2[cb * b + j];
                        sb += g[0] * J2[cb * b + j] - g[1] * J2[ca * b + j];
                    }
                    ra[j] = sa;
                    if (h > 0)
                        rb[j] = sb;
                }
            }
        }
    for (size_t j = 0; j < hb->nq; j++)
        A[j * ld + j] += 1.0;
}

int fr_hb_lu_solve(fricreg_hb *hb, const char *fn, size_t nd, double *rhs, double *sol)
{
    double amax = 0.0;
    for (size_t k = 0; k < nd * nd; k++)
        amax = fmax(amax, fabs(hb->A[k]));
    fr_hb_lu_factor(hb->A, nd, hb->piv2);
    for (size_t k = 0; k < nd; k++) {
        double piv = fabs(hb->A[k * nd + k]);
        if (!(piv > 1e-14 * amax) || !isfinite(piv))
            return fr_fail(hb, FRICREG_ESINGULAR,
                           "%s: Newton's matrix is singular (pivot %zu of its LU factor: %g, "
                           "largest entry %g)",
                           fn, k, piv, amax);
    }
    if (rhs != sol)
        memcpy(sol, rhs, nd * sizeof *sol);
    fr_hb_lu_solve_factored(hb->A, nd, hb->piv2, sol);
    return FRICREG_OK;
}

double fr_hb_scale(const fricreg_hb *hb, const double *q)
{
    double s = 0.0;
    for (size_t j = 0; j < hb->nq; j++)
        s = fmax(s, fabs(q[j]));
    /* the load's response at the level in force (a nonlinear mode's normalization: whole) */
    double load = hb->free_vibration ? 1.0 : fabs(hb->level);
    for (size_t j = 0; j < 2 * ((size_t)hb->H + 1) * hb->m; j++)
        s = fmax(s, load * fabs(hb->ql[j]));
    return s > 0.0 ? s : 1.0;
}
