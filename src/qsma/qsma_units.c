/* SPDX-License-Identifier: GPL-3.0-or-later */
/* qsma_units.c — the elements as the marched loading path steps them (qsma_internal.h): a
 * slider (jenkins, or one of an iwan element's) or a 3-D contact, each one backward-Euler step
 * of its return mapping from its state before the step (joint/slider.h; a Jenkins element with
 * lift-off is a 1-D one under the same normal law), with the consistent
 * tangent Newton needs and the forward derivatives that carry the parameters' sensitivities
 * from step to step. With d = u − w_old, n = d/|d| and the bound b (φ_s, or μ N with N = n0 + kn g
 * while the contact is closed):
 *   stick: f = kt d, w = w_old;   slip: f = b n, w = u − f/kt;   open (N <= 0): f = 0, w = u;
 * so df = t (du − dw_old) + d dkt (stick) or t (du − dw_old) + n db (slip), t the slider's tangent
 * (kt I, or (b/|d|)(I − n n^T)), db = μ dN + N dμ, dN = kn dg + dn0 + g dkn; and in slip
 * dw = du − df/kt + f dkt/kt², in stick dw = dw_old, open dw = du. */
#include <string.h>

#include "joint/slider.h"
#include "qsma_internal.h"

void fr_qsma_unit_step(const struct fr_qsma_unit *un, const double *u, const double *wold,
                       double *f, double *D, double *w, struct fr_qsma_record *rec)
{
    int dim = un->dim;
    size_t rows = fr_qsma_unit_rows(un);
    memset(D, 0, rows * rows * sizeof *D);
    for (int a = 0; a < dim; a++)
        rec->d[a] = u[a] - wold[a];
    rec->g = un->normal ? u[dim] : 0.0;
    rec->N = un->normal ? un->n0 + un->kn * rec->g : 1.0;
    if (!(rec->N > 0.0)) { /* open: the slider follows u */
        fr_slider_separated(dim, u, f, w, NULL, NULL);
        f[dim] = 0.0;
        rec->mode = FR_QSMA_OPEN;
        return;
    }
    double b = un->normal ? un->mu * rec->N : un->phi, t[4], dfdg[2];
    int slip = fr_slider_return(un->kt, b, un->normal ? un->mu * un->kn : 0.0, dim, u, wold, f, w,
                                t, dfdg);
    rec->mode = slip ? FR_QSMA_SLIP : FR_QSMA_STICK;
    double r = fr_slider_norm(rec->d, dim);
    for (int a = 0; a < dim; a++) {
        rec->n[a] = r > 0.0 ? rec->d[a] / r : 0.0;
        rec->f[a] = f[a];
        for (int c = 0; c < dim; c++)
            D[a * rows + c] = t[a * dim + c];
    }
    memcpy(rec->t, t, (size_t)(dim * dim) * sizeof *t);
    if (un->normal) { /* the bound's dependence on g, and the normal law */
        for (int a = 0; a < dim; a++)
            D[a * rows + (size_t)dim] = dfdg[a];
        D[(size_t)dim * rows + (size_t)dim] = un->kn;
        f[dim] = rec->N;
    }
}

/* The bound's and N's derivatives in parameter role (and dg): db, dN. */
static void bound_terms(const struct fr_qsma_unit *un, const struct fr_qsma_record *rec, int role,
                        double dg, double *db, double *dN)
{
    if (!un->normal) {
        *dN = 0.0;
        *db = role == FR_QSMA_ROLE_BOUND ? 1.0 : 0.0;
        return;
    }
    *dN = un->kn * dg + (role == FR_QSMA_ROLE_N0) + (role == FR_QSMA_ROLE_KN) * rec->g;
    *db = un->mu * *dN + (role == FR_QSMA_ROLE_BOUND) * rec->N;
}

void fr_qsma_unit_dforce(const struct fr_qsma_unit *un, const struct fr_qsma_record *rec, int role,
                         const double *dwold, double *df)
{
    int dim = un->dim;
    memset(df, 0, fr_qsma_unit_rows(un) * sizeof *df);
    if (rec->mode == FR_QSMA_OPEN)
        return;
    double db, dN, dkt = role == FR_QSMA_ROLE_KT;
    bound_terms(un, rec, role, 0.0, &db, &dN);
    for (int a = 0; a < dim; a++) {
        for (int c = 0; c < dim; c++)
            df[a] -= rec->t[a * dim + c] * dwold[c];
        df[a] += rec->mode == FR_QSMA_STICK ? rec->d[a] * dkt : rec->n[a] * db;
    }
    if (un->normal)
        df[dim] = dN;
}

void fr_qsma_unit_dstate(const struct fr_qsma_unit *un, const struct fr_qsma_record *rec, int role,
                         const double *du, const double *dwold, double *dw)
{
    int dim = un->dim;
    if (rec->mode == FR_QSMA_OPEN) {
        memcpy(dw, du, (size_t)dim * sizeof *dw);
        return;
    }
    if (rec->mode == FR_QSMA_STICK) {
        memcpy(dw, dwold, (size_t)dim * sizeof *dw);
        return;
    }
    double db, dN, dkt = role == FR_QSMA_ROLE_KT;
    bound_terms(un, rec, role, un->normal ? du[dim] : 0.0, &db, &dN);
    for (int a = 0; a < dim; a++) {
        double df = rec->n[a] * db;
        for (int c = 0; c < dim; c++)
            df += rec->t[a * dim + c] * (du[c] - dwold[c]);
        dw[a] = du[a] - df / un->kt + rec->f[a] * dkt / (un->kt * un->kt);
    }
}
