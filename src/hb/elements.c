/* SPDX-License-Identifier: GPL-3.0-or-later */
/* elements.c — the per-kind element setters of the driver (fricreg_hb.h): Jenkins and Iwan
 * elements of one row, with a normal law (lift-off) of two rows, and the 3-D contact element of
 * three, each checking everything before it changes anything, then replacing the elements held
 * by one block of its kind (element_store.c); and the check of J's rows that
 * fricreg_hb_add_elements (element_types.c) shares. */
#include <math.h>

#include "element_store.h"
#include "elements.h"
#include "model.h"
#include "newton_matrix.h"
#include "busy.h"

int fr_hb_check_entries(fricreg_hb *hb, const char *fn, size_t rows, size_t ndof, const double *J,
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
    return fr_hb_check_entries(hb, fn, rows_per_element * m, ndof, J, name);
}

/* The checked block in place of the elements held (what names them in a message). */
static int install(fricreg_hb *hb, const char *fn, const struct fr_hb_block *blk, const char *what)
{
    if (fr_hb_store_add(hb, blk, 1) != FRICREG_OK)
        return fr_fail(hb, FRICREG_ENOMEM, "%s: no memory for %zu %s", fn, blk->me, what);
    (void)fr_hb_newton_matrix_room(hb); /* none: the dense LU serves */
    fr_hb_invalidate(hb);
    return FRICREG_OK;
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
    if (hb == NULL || hb->busy)
        return fr_hb_refuse(hb, fn);
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
    struct fr_hb_block blk = {.kind = FR_HB_SLIDERS,
                              .me = m,
                              .ns = 1,
                              .ra = 1,
                              .Ja = J,
                              .k = kt,
                              .phi = mun,
                              .pstride = 1};
    return install(hb, fn, &blk, "Jenkins elements");
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
    if (hb == NULL || hb->busy)
        return fr_hb_refuse(hb, fn);
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
    struct fr_hb_block blk = {.kind = FR_HB_SLIDERS,
                              .me = m,
                              .ns = ns,
                              .ra = 1,
                              .Ja = J,
                              .k = k,
                              .phi = phi,
                              .pstride = ns};
    return install(hb, fn, &blk, "Iwan elements");
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

/* fricreg_hb_set_jenkins_normal (ns = 1: k = kt) and fricreg_hb_set_iwan_normal, their
 * messages naming fn. */
static int set_normal(fricreg_hb *hb, const char *fn, size_t m, size_t ndof, const double Jt[],
                      const double Jn[], size_t ns, const double k[], const double mu[],
                      const double n0[], const double kn[])
{
    if (hb == NULL || hb->busy)
        return fr_hb_refuse(hb, fn);
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
    struct fr_hb_block blk = {.kind = FR_HB_LIFTOFF,
                              .me = m,
                              .ns = ns,
                              .ra = 1,
                              .Ja = Jt,
                              .Jb = Jn,
                              .k = k,
                              .phi = mu,
                              .pstride = ns,
                              .n0 = n0,
                              .kn = kn,
                              .nstride = 1};
    return install(hb, fn, &blk, "elements with lift-off");
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

int fricreg_hb_set_jenkins_2d_normal(fricreg_hb *hb, size_t m, size_t ndof, const double Je[],
                                     const double Jn[], const double kt[], const double mu[],
                                     const double n0[], const double kn[])
{
    static const char fn[] = "set_jenkins_2d_normal";
    if (hb == NULL || hb->busy)
        return fr_hb_refuse(hb, fn);
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
    struct fr_hb_block blk = {.kind = FR_HB_CONTACT_3D,
                              .me = m,
                              .ns = 1,
                              .ra = 2,
                              .Ja = Je,
                              .Jb = Jn,
                              .k = kt,
                              .phi = mu,
                              .pstride = 1,
                              .n0 = n0,
                              .kn = kn,
                              .nstride = 1};
    return install(hb, fn, &blk, "3-D contact elements");
}
