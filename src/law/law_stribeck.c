/* SPDX-License-Identifier: GPL-3.0-or-later */
/* law_stribeck.c — static > kinetic friction with exact stick, 1-D and 2-D (fricreg_stribeck.h,
 * docs/laws2d.md): law (4), or the default 2-D law (the inscribed disk), with a bound that falls linearly from fs at v = 0
 * to k(eps) at |v| = eps, and the kinetic curve k(|v|) outside. */
#include <math.h>
#include <stdio.h>

#include "fricreg_stribeck.h"
#include "law.h"
#include "law_disk.h"
#include "law_stribeck.h"

/* The band's bound at rho = |v|/eps (law_stribeck.h). */
static double band_bound(const struct fr_stribeck *p, double eps, double rho)
{
    return fr_stribeck_band_bound(p, fr_stribeck_kinetic(p, eps), rho);
}

static double stribeck_1d(const struct fr_stribeck *p, double v, double g, double eps)
{
    double s = fabs(v);
    if (s >= eps)
        return v > 0.0 ? -fr_stribeck_kinetic(p, s) : fr_stribeck_kinetic(p, s);
    /* the scale and the band of law (4) (law.h), so that fs == fk gives its bits */
    return fr_quinn_band(v * fr_band_scale(eps), g, band_bound(p, eps, s / eps));
}

static void stribeck_2d(const struct fr_stribeck *p, const double v[2], const double g[2],
                        double eps, double f[2])
{
    double r = hypot(v[0], v[1]);
    if (r == 0.0)
        fr_disk_hold(g, p->fs, f);
    else if (r >= eps)
        fr_disk_slide(v, fr_stribeck_kinetic(p, r), f);
    else
        fr_disk_inscribed(v, g, band_bound(p, eps, r / eps), r / eps, f);
}

/* Status of one contact's numbers (v and g: n components each): non-finite first, then out
 * of range; `cap` also bounds the magnitudes (the 2-D kernels' FR_DISK_MAX). */
static int stribeck_status(const struct fr_stribeck *p, const double v[], const double g[], int n,
                           double cap)
{
    int finite = isfinite(p->fs) && isfinite(p->fk) && isfinite(p->vs) && isfinite(p->delta);
    int capped = fabs(p->fs) <= cap;
    for (int j = 0; j < n; j++) {
        finite = finite && isfinite(v[j]) && isfinite(g[j]);
        capped = capped && fabs(v[j]) <= cap && fabs(g[j]) <= cap;
    }
    if (!finite)
        return FRICREG_ENONFINITE;
    if (!(p->fk >= 0.0 && p->fk <= p->fs && p->vs > 0.0 && p->delta > 0.0) || !capped)
        return FRICREG_EINVAL;
    return FRICREG_OK;
}

static int eps_status(double eps)
{
    if (!isfinite(eps))
        return FRICREG_ENONFINITE;
    return fr_eps_valid(eps) ? FRICREG_OK : FRICREG_EINVAL;
}

int fricreg_stribeck_eval(double v, double f_eq, double fs, double fk, double vs, double delta,
                          double eps, double *f)
{
    if (f == NULL)
        return FRICREG_ENULL;
    struct fr_stribeck p = {fs, fk, vs, delta};
    int status = eps_status(eps);
    if (status == FRICREG_OK)
        status = stribeck_status(&p, &v, &f_eq, 1, INFINITY);
    if (status != FRICREG_OK)
        return status;
    *f = stribeck_1d(&p, v, f_eq, eps);
    return FRICREG_OK;
}

int fricreg_stribeck_disk_eval(const double v[], const double f_eq[], double fs, double fk,
                               double vs, double delta, double eps, double f[])
{
    if (v == NULL || f_eq == NULL || f == NULL)
        return FRICREG_ENULL;
    struct fr_stribeck p = {fs, fk, vs, delta};
    int status = eps_status(eps);
    if (status == FRICREG_OK)
        status = stribeck_status(&p, v, f_eq, 2, FR_DISK_MAX);
    if (status != FRICREG_OK)
        return status;
    double out[2];
    stribeck_2d(&p, v, f_eq, eps, out);
    f[0] = out[0];
    f[1] = out[1];
    return FRICREG_OK;
}

/* A batch of n-component contacts: validated in full (a non-finite number anywhere decides
 * first), then evaluated; the outputs go through a local, so f may alias v or f_eq. */
static int stribeck_batch(int n, double eps, size_t m, const double v[], const double f_eq[],
                          const double fs[], const double fk[], const double vs[],
                          const double delta[], double f[])
{
    int status = eps_status(eps);
    if (status != FRICREG_OK || m == 0)
        return status;
    if (!v || !f_eq || !fs || !fk || !vs || !delta || !f)
        return FRICREG_ENULL;
    double cap = n == 2 ? FR_DISK_MAX : INFINITY;
    for (size_t i = 0; i < m && status != FRICREG_ENONFINITE; i++) {
        struct fr_stribeck p = {fs[i], fk[i], vs[i], delta[i]};
        int s = stribeck_status(&p, v + n * i, f_eq + n * i, n, cap);
        if (s == FRICREG_ENONFINITE || status == FRICREG_OK)
            status = s;
    }
    if (status != FRICREG_OK)
        return status;
    for (size_t i = 0; i < m; i++) {
        struct fr_stribeck p = {fs[i], fk[i], vs[i], delta[i]};
        if (n == 1)
            f[i] = stribeck_1d(&p, v[i], f_eq[i], eps);
        else
            stribeck_2d(&p, v + 2 * i, f_eq + 2 * i, eps, f + 2 * i);
    }
    return FRICREG_OK;
}

int fricreg_stribeck_eval_batch(double eps, size_t m, const double v[], const double f_eq[],
                                const double fs[], const double fk[], const double vs[],
                                const double delta[], double f[])
{
    return stribeck_batch(1, eps, m, v, f_eq, fs, fk, vs, delta, f);
}

int fricreg_stribeck_disk_eval_batch(double eps, size_t m, const double v[], const double f_eq[],
                                     const double fs[], const double fk[], const double vs[],
                                     const double delta[], double f[])
{
    return stribeck_batch(2, eps, m, v, f_eq, fs, fk, vs, delta, f);
}

int fr_stribeck_check(size_t m, const double fs[], const double fk[], const double vs[],
                      const double delta[], double fs_max, char why[], size_t len)
{
    static const char *const names[4] = {"fs", "fk", "vs", "delta"};
    const double *arrays[4] = {fs, fk, vs, delta};
    for (size_t k = 0; k < 4; k++)
        if (arrays[k] == NULL) {
            snprintf(why, len, "%s is NULL", names[k]);
            return FRICREG_ENULL;
        }
    for (size_t i = 0; i < m; i++)
        if (!isfinite(fs[i]) || !isfinite(fk[i]) || !isfinite(vs[i]) || !isfinite(delta[i])) {
            snprintf(why, len, "contact %zu: a parameter is not finite", i);
            return FRICREG_ENONFINITE;
        }
    for (size_t i = 0; i < m; i++)
        if (!(fk[i] >= 0.0 && fk[i] <= fs[i] && fs[i] <= fs_max && vs[i] > 0.0 && delta[i] > 0.0)) {
            snprintf(why, len,
                     "contact %zu: fs = %g, fk = %g, vs = %g, delta = %g: need 0 <= fk <= fs "
                     "<= %g, vs > 0, delta > 0",
                     i, fs[i], fk[i], vs[i], delta[i], fs_max);
            return FRICREG_EINVAL;
        }
    return FRICREG_OK;
}
