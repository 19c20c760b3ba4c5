/* SPDX-License-Identifier: GPL-3.0-or-later */
/* qsma_sensitivity.c — the exact derivatives of quasi-static modal analysis's ω and ζ
 * (fricreg_hb_qsma_sensitivities, fricreg_hb_qsma.h). The parameters are described as
 * fricreg_hb_nma_point_sensitivities's; each is what it is to each slider (its stiffness, its
 * slip force, nothing), and a stiffness also moves K_0 and so φ_k, ω_k and ζ_k (qsma_mode.c).
 * The path gives dλ/dp and d∫λ/dp at every amplitude (qsma_path.c, qsma_dlambda.c); here they
 * become, at fixed a, dω = dλ/(2 ω a), dD = 8 d∫ − 4 a dλ and dζ = dζ_k + dD/(2π λ a) −
 * ζ_f dλ/λ (ζ_f = ζ − ζ_k); the amplitude's along the piece at a, λ' = dλ/dq, dD/da = 4 λ −
 * 4 a λ'; the damping's on ζ_k = (a0 + a1 φ_k^T K φ_k)/(2 ω_k) alone. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/fr_math.h"
#include "fricreg_hb_qsma.h"
#include "hb/busy.h"
#include "qsma_internal.h"

struct params {
    size_t np;
    const int *kind;
    const size_t *first, *count, *index;
};

static int check_element(fricreg_hb *hb, const char *fn, const struct params *P, size_t k)
{
    size_t e0 = P->first[k], ne = P->count[k], j = P->index[k];
    if (ne == 0 || e0 >= hb->count || ne > hb->count - e0)
        return fr_fail(hb, FRICREG_EINVAL,
                       "%s: parameter %zu: elements first = %zu, count = %zu, the driver holds %zu",
                       fn, k, e0, ne, hb->count);
    for (size_t e = e0; e < e0 + ne; e++) {
        const double *ks, *phi;
        size_t ns = fr_hb_sliders(hb, e, &ks, &phi);
        if (fr_qsma_has_normal(hb, e)) { /* kt, mu, kn, n0 (HB's normal law: no gap) */
            if (j > 3)
                return fr_fail(hb, FRICREG_EINVAL,
                               "%s: parameter %zu: index %zu, element %zu with a normal law has "
                               "kt, mu, kn, n0 (0 to 3)",
                               fn, k, j, e);
            continue;
        }
        if (j >= 2 * ns)
            return fr_fail(hb, FRICREG_EINVAL,
                           "%s: parameter %zu: index %zu, element %zu has %zu parameters", fn, k, j,
                           e, 2 * ns);
        if (!(phi[j % ns] > 0.0))
            return fr_fail(hb, FRICREG_EINVAL,
                           "%s: parameter %zu: slider %zu of element %zu has slip force 0 (it "
                           "carries nothing)",
                           fn, k, j % ns, e);
    }
    return FRICREG_OK;
}

static int check_param(fricreg_hb *hb, const char *fn, const struct params *P, size_t k)
{
    size_t j = P->index[k];
    switch (P->kind[k]) {
    case FRICREG_HB_NMA_PARAM_AMPLITUDE: return FRICREG_OK;
    case FRICREG_HB_NMA_PARAM_DAMPING:
        if (j > 2)
            return fr_fail(hb, FRICREG_EINVAL,
                           "%s: parameter %zu: damping index %zu (0 zeta_k, 1 a0, 2 a1)", fn, k, j);
        if (j > 0 && !hb->rayleigh)
            return fr_fail(hb, FRICREG_EINVAL,
                           "%s: parameter %zu: %s is Rayleigh's, and the model's damping is a "
                           "matrix (fricreg_hb_set_rayleigh)",
                           fn, k, j == 1 ? "a0" : "a1");
        return FRICREG_OK;
    case FRICREG_HB_NMA_PARAM_ELEMENT: return check_element(hb, fn, P, k);
    default:
        return fr_fail(hb, FRICREG_EINVAL,
                       "%s: parameter %zu: kind = %d is not one of enum fricreg_hb_nma_param", fn,
                       k, P->kind[k]);
    }
}

static int in_range(const struct params *P, size_t k, size_t e)
{
    return P->kind[k] == FRICREG_HB_NMA_PARAM_ELEMENT && e >= P->first[k] &&
           e - P->first[k] < P->count[k];
}

/* Each element parameter's role to each slider (role[np nsl]) and contact (crole[np ncon],
 * enum fr_qsma_role) and d k_r/dp (dk[np m]); *shape whether a stiffness moves K_0. */
static void roles(const fricreg_hb *hb, const struct fr_qsma *s, const struct params *P,
                  signed char *role, signed char *crole, double *dk, int *shape)
{
    static const signed char contact_role[4] = {FR_QSMA_ROLE_KT, FR_QSMA_ROLE_BOUND,
                                                FR_QSMA_ROLE_KN, FR_QSMA_ROLE_N0};
    for (size_t k = 0; k < P->np; k++) {
        for (size_t j = 0; j < s->nsl; j++) {
            size_t e = s->elem[j], ns = hb->eso[e + 1] - hb->eso[e], i = P->index[k];
            if (!in_range(P, k, e) || i % ns != s->loc[j])
                continue;
            role[k * s->nsl + j] = i < ns ? 1 : 2;
            if (i < ns) { /* every slider of positive slip force is stuck in K_0 */
                dk[k * s->m + s->row[j]] += 1.0;
                *shape = 1;
            }
        }
        for (size_t c = 0; c < s->ncon; c++) {
            size_t e = s->con[c], r = hb->erow[e], i = P->index[k];
            size_t dim = (size_t)fr_qsma_tangential_rows(hb, e);
            if (!in_range(P, k, e))
                continue;
            crole[k * s->ncon + c] = contact_role[i];
            /* K_0's rows: kt where the contact sticks at rest, kn where it is closed */
            for (size_t a = 0; a < dim && i == 0 && s->kr[r] != 0.0; a++) {
                dk[k * s->m + r + a] += 1.0;
                *shape = 1;
            }
            if (i == 2 && hb->nl[2 * hb->me + e] > 0.0) {
                dk[k * s->m + r + dim] += 1.0;
                *shape = 1;
            }
        }
    }
}

/* Point i's derivatives of parameter k into dw, dz. */
static void point(const struct fr_qsma *s, const struct params *P, size_t k, double a,
                  const struct fr_qsma_out *out, size_t i, const double *dzk, double *dw,
                  double *dz)
{
    size_t np = P->np;
    double l = out->lambda[i], D = 8.0 * out->integral[i] - 4.0 * a * l, w = sqrt(l / a),
           zf = D / (FR_TWO_PI * l * a);
    switch (P->kind[k]) {
    case FRICREG_HB_NMA_PARAM_AMPLITUDE: {
        double lp = out->slope[i], dD = 8.0 * out->dint_da[i] - 4.0 * l - 4.0 * a * lp;
        *dw = (lp / a - l / (a * a)) / (2.0 * w);
        *dz = dD / (FR_TWO_PI * l * a) - zf * (lp * a + l) / (l * a);
        return;
    }
    case FRICREG_HB_NMA_PARAM_DAMPING: {
        size_t j = P->index[k];
        *dw = 0.0;
        *dz = j == 0 ? 1.0 : (j == 1 ? 1.0 : s->phik) / (2.0 * s->omega_k);
        return;
    }
    default: {
        double dl = out->dlambda[i * np + k], dD = 8.0 * out->dintegral[i * np + k] - 4.0 * a * dl;
        *dw = dl / (2.0 * w * a);
        *dz = dzk[k] + dD / (FR_TWO_PI * l * a) - zf * dl / l;
    }
    }
}

/* The sensitivities with the model s set up, into domega and dzeta. */
static int run(fricreg_hb *hb, const char *fn, struct fr_qsma *s, size_t na, const double *amp,
               const struct params *P, double *domega, double *dzeta)
{
    size_t np = P->np, n = s->n, m = s->m, nsl = s->nsl;
    size_t nbuf = np * (n + m + 2) + 4 * np + n + m + 4 * na + 2 * na * np + 1 +
                  np * (nsl + m + n); /* the path's dz, dur, dx */
    double *buf = calloc(nbuf, sizeof *buf);
    signed char *role = calloc(np * (nsl + s->ncon) + 1, sizeof *role);
    if (buf == NULL || role == NULL) {
        free(buf);
        free(role);
        return fr_fail(hb, FRICREG_ENOMEM, "%s: no memory for %zu parameters", fn, np);
    }
    double *w = buf, *dk = w + np * n, *domk = dk + np * m, *dzk = domk + np, *work = dzk + np,
           *o = work + 4 * np + n + m;
    struct fr_qsma_out out = {.lambda = o,
                              .integral = o + na,
                              .slope = o + 2 * na,
                              .dlambda = o + 3 * na,
                              .dintegral = o + 3 * na + na * np,
                              .dint_da = o + 3 * na + 2 * na * np};
    int shape = 0, status = FRICREG_OK;
    signed char *crole = role + np * nsl;
    roles(hb, s, P, role, crole, dk, &shape);
    if (shape)
        status = fr_qsma_shape(hb, fn, s, np, dk, w, domk, dzk);
    double *dz = o + 4 * na + 2 * na * np;
    struct fr_qsma_sens sens = {.np = np,
                                .role = role,
                                .crole = crole,
                                .w = w,
                                .dz = dz,
                                .dur = dz + np * nsl,
                                .dx = dz + np * (nsl + m)};
    if (status == FRICREG_OK)
        status = fr_qsma_run(hb, fn, s, na, amp, &sens, work, &out);
    for (size_t i = 0; i < na && status == FRICREG_OK; i++)
        for (size_t k = 0; k < np; k++)
            point(s, P, k, amp[i], &out, i, dzk, domega + i * np + k, dzeta + i * np + k);
    free(buf);
    free(role);
    return status;
}

int fricreg_hb_qsma_sensitivities(fricreg_hb *hb, size_t mode, size_t n, const double amplitude[],
                                  size_t np, const int kind[], const size_t first[],
                                  const size_t count[], const size_t index[], double domega[],
                                  double dzeta[])
{
    static const char fn[] = "fricreg_hb_qsma_sensitivities";
    if (hb == NULL || hb->busy)
        return fr_hb_refuse(hb, fn);
    if (amplitude == NULL || domega == NULL || dzeta == NULL)
        return fr_fail(hb, FRICREG_ENULL, "%s: %s is NULL", fn,
                       amplitude == NULL ? "amplitude"
                       : domega == NULL  ? "domega"
                                         : "dzeta");
    if (np > 0 && (!kind || !first || !count || !index))
        return fr_fail(hb, FRICREG_ENULL, "%s: %s is NULL", fn,
                       !kind    ? "kind"
                       : !first ? "first"
                       : !count ? "count"
                                : "index");
    int status = fr_qsma_args(hb, fn, mode, n, amplitude);
    struct fr_qsma *s = NULL;
    if (status == FRICREG_OK)
        status = fr_qsma_setup(hb, fn, mode, &s);
    struct params P = {np, kind, first, count, index};
    for (size_t k = 0; k < np && status == FRICREG_OK; k++)
        status = check_param(hb, fn, &P, k);
    if (status == FRICREG_OK && np > 0)
        status = run(hb, fn, s, n, amplitude, &P, domega, dzeta);
    fr_qsma_free(s);
    return status;
}
