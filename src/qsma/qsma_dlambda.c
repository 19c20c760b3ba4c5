/* SPDX-License-Identifier: GPL-3.0-or-later */
/* qsma_dlambda.c — the load factor λ at a fixed modal amplitude differentiated in the
 * parameters, on one piece of the loading path (qsma_internal.h). With its pattern of stuck
 * and slipping sliders fixed the piece solves, linearly,
 *
 *     K_t x + g = λ b,    b^T x = q,        g = Σ_slipping σ_s φ_s J_r^T,  b = M φ_k,
 *
 * (a stuck slider of virgin loading carries k_s J_r x). At fixed q, differentiating gives
 * K_t dx − dλ b = r1 = −dK_t x − dg + λ db and b^T dx = −db^T x; with v = K_t^-1 b (the piece's
 * direction, K_t symmetric) dλ = (−db^T x − v^T r1) / (b^T v): one dot product a parameter. A
 * stiffness k_s of a stuck slider has v^T dK_t x = (J_r v)(J_r x); a slip force φ_s of a
 * slipping one v^T dg = σ_s J_r v; db = M dφ_k/dp (qsma_mode.c). */
#include "qsma_internal.h"

void fr_qsma_dlambda(const struct fr_qsma *s, const struct fr_qsma_sens *p, const double *x,
                     const double *ur, double lambda, double *dl)
{
    size_t n = s->n;
    double bv = 0.0;
    for (size_t i = 0; i < n; i++)
        bv += s->b[i] * s->v[i];
    for (size_t k = 0; k < p->np; k++) {
        const double *w = p->w + k * n;
        const signed char *role = p->role + k * s->nsl;
        double num = 0.0;
        for (size_t i = 0; i < n; i++)
            num -= w[i] * (x[i] + lambda * s->v[i]);
        for (size_t j = 0; j < s->nsl; j++) {
            size_t r = s->row[j];
            if (role[j] == 1 && s->sigma[j] == 0)
                num += s->vr[r] * ur[r];
            else if (role[j] == 2 && s->sigma[j] != 0)
                num += s->sigma[j] * s->vr[r];
        }
        dl[k] = num / bv;
    }
}
