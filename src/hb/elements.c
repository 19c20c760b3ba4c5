/* SPDX-License-Identifier: GPL-3.0-or-later */
/* elements.c — the element setters of the driver (fricreg_hb.h): Jenkins and Iwan elements of
 * one row, with a normal law (lift-off) of two rows, and the 3-D contact element of three,
 * each checking everything before it changes anything; the buffers grow once for the rows
 * (rows.c), and the 3-D element gets the sampled AFT. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "elements.h"
#include "model.h"
#include "rows.h"

/* samples of the 3-D contact element's AFT per coefficient (fr_hb_contact_samples) */
#define CONTACT_SAMPLES 64

/* J's rows[ndof]: finite, none zero, named name. */
static int check_entries(fricreg_hb *hb, const char *fn, size_t rows, size_t ndof, const double *J,
                         const char *name)
{
    for (size_t i = 0; i < rows; i++) {
        double norm = 0.0;
        for (size_t k = 0; k < ndof; k++) {
            if (!isfinite(J[i * ndof + k]))
                return fr_fail(hb, FRICREG_ENONFINITE, "%s: %s(%zu, %zu) = %g", fn, name, i, k,
                               J[i * ndof + k]);
            norm += fabs(J[i * ndof + k]);
        }
        if (norm == 0.0)
            return fr_fail(hb, FRICREG_EINVAL, "%s: row %zu of %s is zero", fn, i, name);
    }
    return FRICREG_OK;
}

/* The checks the element setters share: the sizes and J (rows_per_element m rows), named
 * name. */
static int check_rows(fricreg_hb *hb, const char *fn, size_t m, size_t rows_per_element,
                      size_t ndof, const double *J, const char *name)
{
    if (m != hb->me)
        return fr_fail(hb, FRICREG_ESIZE, "%s: m = %zu, the driver has %zu", fn, m, hb->me);
    if (fr_hb_check_ndof(hb, fn, ndof) != FRICREG_OK)
        return FRICREG_ESIZE;
    return check_entries(hb, fn, rows_per_element * m, ndof, J, name);
}

/* Jenkins or Iwan elements: one row each, the normal elements' parameters dropped. */
static void one_row_elements(fricreg_hb *hb)
{
    free(hb->nl);
    hb->nl = NULL;
    fr_hb_rows_set(hb, 1);
}

/* The sliders' parameters: finite, stiffness > 0, slip force >= 0. */
static int check_sliders(fricreg_hb *hb, const char *fn, size_t count, const double *k,
                         const double *phi, const char *kname, const char *pname)
{
    for (size_t i = 0; i < count; i++) {
        if (!isfinite(k[i]) || !isfinite(phi[i]))
            return fr_fail(hb, FRICREG_ENONFINITE, "%s: %s[%zu] = %g, %s[%zu] = %g", fn, kname, i,
                           k[i], pname, i, phi[i]);
        if (!(k[i] > 0.0) || !(phi[i] >= 0.0))
            return fr_fail(hb, FRICREG_EINVAL, "%s: %s[%zu] = %g must be > 0, %s[%zu] = %g >= 0",
                           fn, kname, i, k[i], pname, i, phi[i]);
    }
    return FRICREG_OK;
}

/* fricreg_hb_set_jenkins, its messages naming fn. */
static int set_jenkins(fricreg_hb *hb, const char *fn, size_t m, size_t ndof, const double J[],
                       const double kt[], const double mun[])
{
    if (hb == NULL)
        return FRICREG_ENULL;
    if (hb->busy)
        return fr_hb_busy(hb, fn);
    if (J == NULL || kt == NULL || mun == NULL)
        return fr_fail(hb, FRICREG_ENULL, "%s: %s is NULL", fn,
                       J == NULL    ? "J"
                       : kt == NULL ? "kt"
                                    : "mun");
    int status = check_rows(hb, fn, m, 1, ndof, J, "J");
    if (status == FRICREG_OK)
        status = check_sliders(hb, fn, m, kt, mun, "kt", "mun");
    if (status != FRICREG_OK)
        return status;
    memcpy(hb->J, J, m * ndof * sizeof *J);
    memcpy(hb->kt, kt, m * sizeof *kt);
    memcpy(hb->mun, mun, m * sizeof *mun);
    free(hb->sk); /* Jenkins elements: one slider each, kt and mun */
    hb->sk = NULL;
    hb->ns = 1;
    one_row_elements(hb);
    hb->have_elements = 1;
    fr_hb_invalidate(hb);
    return FRICREG_OK;
}

int fricreg_hb_set_jenkins(fricreg_hb *hb, size_t m, size_t ndof, const double J[],
                           const double kt[], const double mun[])
{
    return set_jenkins(hb, "set_jenkins", m, ndof, J, kt, mun);
}

int fricreg_hb_set_elements(fricreg_hb *hb, size_t m, size_t ndof, const double J[],
                            const double kt[], const double mun[])
{
    return set_jenkins(hb, "set_elements", m, ndof, J, kt, mun);
}

int fricreg_hb_set_iwan(fricreg_hb *hb, size_t m, size_t ndof, const double J[], size_t ns,
                        const double k[], const double phi[])
{
    static const char fn[] = "set_iwan";
    if (hb == NULL)
        return FRICREG_ENULL;
    if (hb->busy)
        return fr_hb_busy(hb, fn);
    if (J == NULL || k == NULL || phi == NULL)
        return fr_fail(hb, FRICREG_ENULL, "%s: %s is NULL", fn,
                       J == NULL   ? "J"
                       : k == NULL ? "k"
                                   : "phi");
    int status = check_rows(hb, fn, m, 1, ndof, J, "J");
    if (status != FRICREG_OK)
        return status;
    if (ns < 1 || ns > FRICREG_HB_MAX_SLIDERS)
        return fr_fail(hb, FRICREG_EINVAL, "%s: ns = %zu sliders, must be in [1, %d]", fn, ns,
                       FRICREG_HB_MAX_SLIDERS);
    if ((status = check_sliders(hb, fn, m * ns, k, phi, "k", "phi")) != FRICREG_OK)
        return status;
    double *sk = malloc(2 * m * ns * sizeof *sk);
    if (sk == NULL)
        return fr_fail(hb, FRICREG_ENOMEM, "%s: no memory for %zu sliders", fn, m * ns);
    memcpy(sk, k, m * ns * sizeof *sk);
    memcpy(sk + m * ns, phi, m * ns * sizeof *sk);
    memcpy(hb->J, J, m * ndof * sizeof *J);
    free(hb->sk);
    hb->sk = sk;
    hb->ns = ns;
    one_row_elements(hb);
    hb->have_elements = 1;
    fr_hb_invalidate(hb);
    return FRICREG_OK;
}

/* The normal law's n0 finite and kn >= 0, finite, for Iwan elements (the Jenkins elements'
 * one message names kt and mu as well). */
static int check_normal_law(fricreg_hb *hb, const char *fn, size_t m, const double n0[],
                            const double kn[])
{
    for (size_t i = 0; i < m; i++) {
        if (!isfinite(n0[i]) || !isfinite(kn[i]))
            return fr_fail(hb, FRICREG_ENONFINITE, "%s: n0[%zu] = %g, kn[%zu] = %g", fn, i, n0[i],
                           i, kn[i]);
        if (!(kn[i] >= 0.0))
            return fr_fail(hb, FRICREG_EINVAL, "%s: kn[%zu] = %g must be >= 0", fn, i, kn[i]);
    }
    return FRICREG_OK;
}

/* Jenkins elements' (ns = 1) or Iwan elements' (ns sliders) parameters with a normal law. */
static int check_normal_sliders(fricreg_hb *hb, const char *fn, size_t m, size_t ns,
                                const double k[], const double mu[], const double n0[],
                                const double kn[])
{
    if (ns > 1) {
        int status = check_sliders(hb, fn, m * ns, k, mu, "k", "mu");
        return status != FRICREG_OK ? status : check_normal_law(hb, fn, m, n0, kn);
    }
    for (size_t i = 0; i < m; i++) {
        if (!isfinite(k[i]) || !isfinite(mu[i]) || !isfinite(n0[i]) || !isfinite(kn[i]))
            return fr_fail(hb, FRICREG_ENONFINITE,
                           "%s: kt[%zu] = %g, mu[%zu] = %g, n0[%zu] = %g, kn[%zu] = %g", fn, i,
                           k[i], i, mu[i], i, n0[i], i, kn[i]);
        if (!(k[i] > 0.0) || !(mu[i] >= 0.0) || !(kn[i] >= 0.0))
            return fr_fail(hb, FRICREG_EINVAL,
                           "%s: kt[%zu] = %g must be > 0, mu[%zu] = %g >= 0, kn[%zu] = %g >= 0", fn,
                           i, k[i], i, mu[i], i, kn[i]);
    }
    return FRICREG_OK;
}

/* The normal law's [4 m] kt, mu, n0, kn: an Iwan element's kt the sum of its sliders' k (its
 * stuck stiffness) and mu the sum of theirs. */
static void normal_parameters(double *nl, size_t m, size_t ns, const double k[], const double mu[],
                              const double n0[], const double kn[])
{
    for (size_t i = 0; i < m; i++) {
        double ksum = 0.0, musum = 0.0;
        for (size_t j = i * ns; j < (i + 1) * ns; j++) {
            ksum += k[j];
            musum += mu[j];
        }
        nl[i] = ksum;
        nl[m + i] = musum;
    }
    memcpy(nl + 2 * m, n0, m * sizeof *nl);
    memcpy(nl + 3 * m, kn, m * sizeof *nl);
}

size_t fr_hb_slider_doubles(size_t me, size_t ns, int normal, size_t nc)
{
    return 2 * me * ns + (normal && ns > 1 ? 2 * nc + 4 * nc * nc : 0);
}

/* fricreg_hb_set_jenkins_normal (ns = 1: k = kt) and fricreg_hb_set_iwan_normal, their
 * messages naming fn. */
static int set_normal(fricreg_hb *hb, const char *fn, size_t m, size_t ndof, const double Jt[],
                      const double Jn[], size_t ns, const double k[], const double mu[],
                      const double n0[], const double kn[])
{
    if (hb == NULL)
        return FRICREG_ENULL;
    if (hb->busy)
        return fr_hb_busy(hb, fn);
    const void *args[6] = {Jt, Jn, k, mu, n0, kn};
    static const char *const names[6] = {"Jt", "Jn", "kt", "mu", "n0", "kn"};
    for (int a = 0; a < 6; a++)
        if (args[a] == NULL)
            return fr_fail(hb, FRICREG_ENULL, "%s: %s is NULL", fn,
                           a == 2 && ns > 1 ? "k" : names[a]);
    int status = check_rows(hb, fn, m, 1, ndof, Jt, "Jt");
    if (status == FRICREG_OK)
        status = check_rows(hb, fn, m, 1, ndof, Jn, "Jn");
    if (status != FRICREG_OK)
        return status;
    if (ns < 1 || ns > FRICREG_HB_MAX_SLIDERS)
        return fr_fail(hb, FRICREG_EINVAL, "%s: ns = %zu sliders, must be in [1, %d]", fn, ns,
                       FRICREG_HB_MAX_SLIDERS);
    if ((status = check_normal_sliders(hb, fn, m, ns, k, mu, n0, kn)) != FRICREG_OK)
        return status;
    /* two rows an element: the buffers sized by the rows grow once (and stay) */
    struct fr_hb_rows b = {0};
    double *nl = malloc(4 * m * sizeof *nl), *sk = NULL;
    if (ns > 1) /* the sliders, and room for one slider's AFT (residual.c) */
        sk = malloc(fr_hb_slider_doubles(m, ns, 1, hb->nc) * sizeof *sk);
    if (nl == NULL || (ns > 1 && sk == NULL) ||
        (hb->rows_cap < 2 * m && fr_hb_rows_alloc(hb, 2 * m, &b) != FRICREG_OK)) {
        free(nl);
        free(sk);
        return fr_fail(hb, FRICREG_ENOMEM, "%s: no memory for %zu elements with lift-off", fn, m);
    }
    if (b.J != NULL)
        fr_hb_rows_install(hb, 2 * m, &b);
    for (size_t i = 0; i < m; i++) {
        memcpy(hb->J + 2 * i * ndof, Jt + i * ndof, ndof * sizeof *Jt);
        memcpy(hb->J + (2 * i + 1) * ndof, Jn + i * ndof, ndof * sizeof *Jn);
    }
    normal_parameters(nl, m, ns, k, mu, n0, kn);
    if (sk != NULL) {
        memcpy(sk, k, m * ns * sizeof *sk);
        memcpy(sk + m * ns, mu, m * ns * sizeof *sk);
    }
    free(hb->nl);
    hb->nl = nl;
    free(hb->sk);
    hb->sk = sk;
    hb->ns = ns;
    fr_hb_rows_set(hb, 2);
    hb->have_elements = 1;
    fr_hb_invalidate(hb);
    return FRICREG_OK;
}

int fricreg_hb_set_jenkins_normal(fricreg_hb *hb, size_t m, size_t ndof, const double Jt[],
                                  const double Jn[], const double kt[], const double mu[],
                                  const double n0[], const double kn[])
{
    return set_normal(hb, "set_jenkins_normal", m, ndof, Jt, Jn, 1, kt, mu, n0, kn);
}

int fricreg_hb_set_normal_elements(fricreg_hb *hb, size_t m, size_t ndof, const double Jt[],
                                   const double Jn[], const double kt[], const double mu[],
                                   const double n0[], const double kn[])
{
    return set_normal(hb, "set_normal_elements", m, ndof, Jt, Jn, 1, kt, mu, n0, kn);
}

int fricreg_hb_set_iwan_normal(fricreg_hb *hb, size_t m, size_t ndof, const double Jt[],
                               const double Jn[], size_t ns, const double k[], const double mu[],
                               const double n0[], const double kn[])
{
    return set_normal(hb, "set_iwan_normal", m, ndof, Jt, Jn, ns, k, mu, n0, kn);
}

size_t fr_hb_contact_samples(int harmonics)
{
    size_t want = CONTACT_SAMPLES * (2 * (size_t)harmonics + 1), N = 1;
    while (N < want)
        N *= 2;
    return N;
}

/* hb's AFT workspace with the 3-D contact element's samples at its harmonics (kept if it has
 * them). FRICREG_OK or FRICREG_ENOMEM, hb unchanged. */
int fr_hb_sampled_aft(fricreg_hb *hb)
{
    size_t N = fr_hb_contact_samples(hb->H), nc = hb->nc;
    if (fricreg_aft_samples(hb->aft) == N && hb->aft_half != NULL)
        return FRICREG_OK;
    fricreg_aft *aft = NULL, *half = NULL;
    double *results = malloc((3 * nc + 9 * nc * nc) * sizeof *results);
    if (results == NULL || fricreg_aft_create(hb->H, N, &aft) != FRICREG_OK ||
        fricreg_aft_create(hb->H, N / 2, &half) != FRICREG_OK) {
        free(results);
        fricreg_aft_free(aft);
        return FRICREG_ENOMEM;
    }
    fricreg_aft_free(hb->aft);
    fricreg_aft_free(hb->aft_half);
    free(hb->half);
    hb->aft = aft;
    hb->aft_half = half;
    hb->half = results;
    return FRICREG_OK;
}

int fricreg_hb_set_jenkins_2d_normal(fricreg_hb *hb, size_t m, size_t ndof, const double Je[],
                                     const double Jn[], const double kt[], const double mu[],
                                     const double n0[], const double kn[])
{
    static const char fn[] = "set_jenkins_2d_normal";
    if (hb == NULL)
        return FRICREG_ENULL;
    if (hb->busy)
        return fr_hb_busy(hb, fn);
    const void *args[6] = {Je, Jn, kt, mu, n0, kn};
    static const char *const names[6] = {"Je", "Jn", "kt", "mu", "n0", "kn"};
    for (int a = 0; a < 6; a++)
        if (args[a] == NULL)
            return fr_fail(hb, FRICREG_ENULL, "%s: %s is NULL", fn, names[a]);
    int status = check_rows(hb, fn, m, 2, ndof, Je, "Je");
    if (status == FRICREG_OK)
        status = check_rows(hb, fn, m, 1, ndof, Jn, "Jn");
    if (status == FRICREG_OK)
        status = check_normal_sliders(hb, fn, m, 1, kt, mu, n0, kn);
    if (status != FRICREG_OK)
        return status;
    /* three rows an element (x, y, n), the sampled AFT: the buffers grow once (and stay) */
    struct fr_hb_rows b = {0};
    double *nl = malloc(4 * m * sizeof *nl);
    if (nl == NULL || (hb->rows_cap < 3 * m && fr_hb_rows_alloc(hb, 3 * m, &b) != FRICREG_OK) ||
        fr_hb_sampled_aft(hb) != FRICREG_OK) {
        free(nl);
        fr_hb_rows_free(&b);
        return fr_fail(hb, FRICREG_ENOMEM, "%s: no memory for %zu 3-D contact elements", fn, m);
    }
    if (b.J != NULL)
        fr_hb_rows_install(hb, 3 * m, &b);
    for (size_t i = 0; i < m; i++) {
        memcpy(hb->J + 3 * i * ndof, Je + 2 * i * ndof, 2 * ndof * sizeof *Je);
        memcpy(hb->J + (3 * i + 2) * ndof, Jn + i * ndof, ndof * sizeof *Jn);
    }
    normal_parameters(nl, m, 1, kt, mu, n0, kn);
    free(hb->nl);
    hb->nl = nl;
    free(hb->sk);
    hb->sk = NULL;
    hb->ns = 1;
    fr_hb_rows_set(hb, 3);
    hb->have_elements = 1;
    fr_hb_invalidate(hb);
    return FRICREG_OK;
}
