/* SPDX-License-Identifier: GPL-3.0-or-later */
/* qsma_dlambda.c — the load factor λ at a fixed modal amplitude differentiated in the
 * parameters, on one piece of the loading path (qsma_internal.h). With its pattern of stuck
 * and slipping sliders fixed the piece solves, linearly,
 *
 *     K_t x + g = λ b,    b^T x = q,        g = Σ_slipping σ_s φ_s J_r^T,  b = M φ_k,
 *
 * (a stuck slider carries k_s (J_r x − z_s), z_s its slip: 0 until it slips). At fixed q,
 * differentiating gives K_t dx − dλ b = r1 = −dK_t x − dg + λ db and b^T dx = −db^T x; with
 * v = K_t^-1 b (the piece's direction, K_t symmetric) dλ = (−db^T x − v^T r1) / (b^T v): one dot
 * product a parameter. A stuck slider's force moves by dk_s (J_r x − z_s) − k_s dz_s at fixed x,
 * a slipping one's by σ_s dφ_s; db = M dφ_k/dp (qsma_mode.c). A slider stuck again has a slip
 * z_s = J_r x* − σ_s φ_s/k_s set at its event x*, which moves with the parameters: x* = x(λ_e)
 * on the piece before, dx* = dx|_λ + v dλ_e with K_t dx|_λ = r1 (one solve on the piece's
 * factor a parameter) and dλ_e from the condition that put the event there, the slider t that
 * reached its slip force: k_t (J_t x* − z_t) = ±φ_t. */
#include <math.h>

#include "base/lapack.h"
#include "qsma_internal.h"

/* Slider j's force moved by parameter k at fixed x (its row at ur). */
static double dforce(const struct fr_qsma *s, const struct fr_qsma_sens *p, size_t k, size_t j,
                     const double *ur)
{
    signed char role = p->role[k * s->nsl + j];
    if (s->sigma[j] != 0)
        return role == 2 ? s->sigma[j] : 0.0;
    return (role == 1 ? ur[s->row[j]] - s->z[j] : 0.0) - s->ks[j] * p->dz[k * s->nsl + j];
}

void fr_qsma_dlambda(const struct fr_qsma *s, const struct fr_qsma_sens *p, const double *x,
                     const double *ur, double lambda, double *dl)
{
    size_t n = s->n;
    double bv = 0.0;
    for (size_t i = 0; i < n; i++)
        bv += s->b[i] * s->v[i];
    for (size_t k = 0; k < p->np; k++) {
        const double *w = p->w + k * n;
        double num = 0.0;
        for (size_t i = 0; i < n; i++)
            num -= w[i] * (x[i] + lambda * s->v[i]);
        for (size_t j = 0; j < s->nsl; j++)
            num += s->vr[s->row[j]] * dforce(s, p, k, j, ur);
        dl[k] = num / bv;
    }
}

void fr_qsma_devent(const struct fr_qsma *s, const struct fr_qsma_sens *p, const double *J,
                    size_t t, double lambda)
{
    size_t n = s->n, m = s->m, np = p->np, rt = s->row[t];
    for (size_t k = 0; k < np; k++) { /* r1 = λ db − Σ J_r^T dforce */
        double *r = p->dx + k * n;
        for (size_t i = 0; i < n; i++)
            r[i] = lambda * p->w[k * n + i];
        for (size_t j = 0; j < s->nsl; j++) {
            double c = dforce(s, p, k, j, s->ur);
            for (size_t i = 0; i < n && c != 0.0; i++)
                r[i] -= c * J[s->row[j] * n + i];
        }
    }
    int nn = (int)n, nrhs = (int)np, info = 0;
    if (np > 0)
        dpotrs_("L", &nn, &nrhs, s->Kt, &nn, p->dx, &nn, &info, 1);
    for (size_t k = 0; k < np; k++) {
        const double *dx = p->dx + k * n;
        double *du = p->dur + k * m;
        for (size_t r = 0; r < m; r++) {
            du[r] = 0.0;
            for (size_t i = 0; i < n; i++)
                du[r] += J[r * n + i] * dx[i];
        }
        /* t's force at its bound: dforce + k_t J_t dx* = ±dφ_t (its own slip-force term) */
        signed char role = p->role[k * s->nsl + t];
        double dk = role == 1 ? s->ur[rt] - s->z[t] : 0.0;
        double g = dk - s->ks[t] * p->dz[k * s->nsl + t] + s->ks[t] * du[rt] -
                   (role == 2 ? copysign(1.0, s->vr[rt]) : 0.0);
        double dle = -g / (s->ks[t] * s->vr[rt]);
        for (size_t r = 0; r < m; r++)
            du[r] += s->vr[r] * dle;
    }
}
