/* SPDX-License-Identifier: GPL-3.0-or-later */
/* qsma_capacitance.c — the marched path's bordered tangent solved on the stuck structure's
 * factor (qsma_internal.h). Its tangent is K_t = K_0 + J^T E J: K_0 = K + J^T diag(k_r) J the
 * structure with every element stuck (SPD, factored once by LAPACK's Cholesky), E = D − diag(k_r)
 * the elements' tangents less their stuck stiffnesses, nonzero only on the rows of elements not
 * stuck (slipping, open). So by Woodbury's identity on those a active rows,
 *
 *     K_t^-1 c = y − Y_A C^-1 E_AA J_A y,    y = K_0^-1 c,  Y = K_0^-1 J^T,  C = I + E_AA G_AA,
 *
 * G = J K_0^-1 J^T (computed once), C of order a factored by LAPACK's LU at each linearization:
 * an iteration costs O(a³ + n² + n a) where the dense bordered LU cost O(n³), and nothing where
 * every element sticks. The border: [K_t, −b; b^T, 0] (z, μ) = (c, d) gives z = K_t^-1 c +
 * μ K_t^-1 b, μ = (d − b^T K_t^-1 c)/(b^T K_t^-1 b). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/free_all.h"
#include "base/lapack.h"
#include "qsma_internal.h"

void fr_qsma_cap_free(struct fr_qsma_cap *c)
{
    if (c == NULL)
        return;
    FR_FREE_ALL(c->L, c->act, c->piv);
    free(c);
}

int fr_qsma_cap_create(const struct fr_qsma *s, const double *J, struct fr_qsma_cap **out)
{
    size_t n = s->n, m = s->m;
    struct fr_qsma_cap *c = calloc(1, sizeof *c);
    if (c == NULL)
        return FRICREG_ENOMEM;
    c->n = n;
    c->m = m;
    c->L = malloc((n * n + n * m + 3 * m * m + n + 2 * m + 1) * sizeof *c->L);
    c->act = malloc((m + 1) * sizeof *c->act);
    c->piv = malloc((m + 1) * sizeof *c->piv);
    if (c->L == NULL || c->act == NULL || c->piv == NULL) {
        fr_qsma_cap_free(c);
        return FRICREG_ENOMEM;
    }
    c->Y = c->L + n * n;
    c->G = c->Y + n * m;
    c->E = c->G + m * m;
    c->C = c->E + m * m;
    c->zb = c->C + m * m;
    c->t = c->zb + n;
    c->u = c->t + m;
    fr_qsma_assemble(s, J, c->L); /* K_0, symmetric: either order */
    int nn = (int)n, mm = (int)m, info = 0;
    dpotrf_("L", &nn, c->L, &nn, &info, 1);
    for (size_t i = 0; i < n && info == 0; i++)
        if (!(c->L[i * n + i] > 0.0))
            info = 1;
    if (info != 0) {
        fr_qsma_cap_free(c);
        return FRICREG_ESINGULAR;
    }
    for (size_t r = 0; r < m; r++) /* Y = K_0^-1 J^T, column r = row r of J */
        memcpy(c->Y + r * n, J + r * n, n * sizeof *c->Y);
    if (m > 0)
        dpotrs_("L", &nn, &mm, c->L, &nn, c->Y, &nn, &info, 1);
    for (size_t r = 0; r < m; r++)
        for (size_t q = 0; q < m; q++) {
            double g = 0.0;
            for (size_t i = 0; i < n; i++)
                g += J[r * n + i] * c->Y[q * n + i];
            c->G[r * m + q] = g;
        }
    *out = c;
    return FRICREG_OK;
}

/* K_t^-1 c in place (c[n]), on the factor of C. */
static void tangent_solve(struct fr_qsma_cap *c, const double *J, double *x)
{
    size_t n = c->n, a = c->na;
    int nn = (int)n, one = 1, info = 0, aa = (int)a;
    dpotrs_("L", &nn, &one, c->L, &nn, x, &nn, &info, 1);
    if (a == 0)
        return;
    for (size_t p = 0; p < a; p++) { /* t = J_A y */
        const double *Jr = J + c->act[p] * n;
        double t = 0.0;
        for (size_t i = 0; i < n; i++)
            t += Jr[i] * x[i];
        c->t[p] = t;
    }
    for (size_t p = 0; p < a; p++) { /* u = E_AA t */
        double u = 0.0;
        for (size_t q = 0; q < a; q++)
            u += c->E[p * a + q] * c->t[q];
        c->u[p] = u;
    }
    dgetrs_("N", &aa, &one, c->C, &aa, c->piv, c->u, &aa, &info, 1);
    for (size_t p = 0; p < a; p++) /* x −= Y_A u */
        for (size_t i = 0; i < n && c->u[p] != 0.0; i++)
            x[i] -= c->Y[c->act[p] * n + i] * c->u[p];
}

int fr_qsma_cap_factor(struct fr_qsma_cap *c, const double *Ed, const double *kr, const double *J,
                       const double *b)
{
    size_t m = c->m, n = c->n, a = 0;
    for (size_t r = 0; r < m; r++) { /* the rows where E = D − diag(k_r) is not 0 */
        int on = Ed[r * m + r] != kr[r];
        for (size_t q = 0; q < m && !on; q++)
            on = q != r && (Ed[r * m + q] != 0.0 || Ed[q * m + r] != 0.0);
        if (on)
            c->act[a++] = r;
    }
    c->na = a;
    for (size_t p = 0; p < a; p++)
        for (size_t q = 0; q < a; q++)
            c->E[p * a + q] = Ed[c->act[p] * m + c->act[q]] - (p == q ? kr[c->act[p]] : 0.0);
    for (size_t p = 0; p < a; p++) /* C = I + E_AA G_AA, column-major for LAPACK */
        for (size_t q = 0; q < a; q++) {
            double v = p == q ? 1.0 : 0.0;
            for (size_t k = 0; k < a; k++)
                v += c->E[p * a + k] * c->G[c->act[k] * m + c->act[q]];
            c->C[q * a + p] = v;
        }
    if (a > 0 && fr_qsma_lu(c->C, a, c->piv) != FRICREG_OK)
        return FRICREG_ESINGULAR;
    memcpy(c->zb, b, n * sizeof *c->zb);
    tangent_solve(c, J, c->zb);
    c->bzb = 0.0;
    for (size_t i = 0; i < n; i++)
        c->bzb += b[i] * c->zb[i];
    return c->bzb != 0.0 && isfinite(c->bzb) ? FRICREG_OK : FRICREG_ESINGULAR;
}

void fr_qsma_cap_solve(struct fr_qsma_cap *c, const double *J, const double *b, size_t nrhs,
                       double *B)
{
    size_t n = c->n, N = n + 1;
    for (size_t k = 0; k < nrhs; k++) {
        double *z = B + k * N, bz = 0.0;
        tangent_solve(c, J, z);
        for (size_t i = 0; i < n; i++)
            bz += b[i] * z[i];
        double mu = (z[n] - bz) / c->bzb;
        for (size_t i = 0; i < n; i++)
            z[i] += mu * c->zb[i];
        z[n] = mu;
    }
}
