/* SPDX-License-Identifier: GPL-3.0-or-later */
/* law_disk.c — the public scalar and batched entry points of the 2-D laws (fricreg_disk.h). */
#include <math.h>

#include "law.h"
#include "law_disk.h"

/* Status of the numbers of one contact: non-finite first, then out of range. */
static int disk_numbers_status(const double v[2], const double g[2], double mun)
{
    double gx = g ? g[0] : 0.0, gy = g ? g[1] : 0.0;
    if (!isfinite(v[0]) || !isfinite(v[1]) || !isfinite(gx) || !isfinite(gy) || !isfinite(mun))
        return FRICREG_ENONFINITE;
    if (mun < 0.0 || !fr_disk_in_range(v[0]) || !fr_disk_in_range(v[1]) || !fr_disk_in_range(gx) ||
        !fr_disk_in_range(gy) || !fr_disk_in_range(mun))
        return FRICREG_EINVAL;
    return FRICREG_OK;
}

static int disk_params_status(int law, double eps)
{
    if (!isfinite(eps))
        return FRICREG_ENONFINITE;
    if (!fr_disk_law_known(law) || !fr_eps_valid(eps))
        return FRICREG_EINVAL;
    return FRICREG_OK;
}

int fricreg_disk_eval(int law, const double v[], const double f_eq[], double mun, double eps,
                      double f[])
{
    if (v == NULL || f == NULL || (f_eq == NULL && fr_disk_law_uses_feq(law)))
        return FRICREG_ENULL;
    int status = disk_params_status(law, eps);
    if (status == FRICREG_OK)
        status = disk_numbers_status(v, f_eq, mun);
    if (status != FRICREG_OK)
        return status;
    double out[2];
    fr_disk_law(law, v, f_eq, mun, eps, out);
    f[0] = out[0];
    f[1] = out[1];
    return FRICREG_OK;
}

/* The first failure of a batch decides its status, non-finite anywhere before out of range. */
static int disk_batch_status(size_t m, const double v[], const double f_eq[], const double mun[])
{
    int status = FRICREG_OK;
    for (size_t i = 0; i < m && status != FRICREG_ENONFINITE; i++) {
        int s = disk_numbers_status(v + 2 * i, f_eq ? f_eq + 2 * i : NULL, mun[i]);
        if (s == FRICREG_ENONFINITE || status == FRICREG_OK)
            status = s;
    }
    return status;
}

int fricreg_disk_eval_batch(int law, double eps, size_t m, const double v[], const double f_eq[],
                            const double mun[], double f[])
{
    int status = disk_params_status(law, eps);
    if (status != FRICREG_OK || m == 0)
        return status;
    if (v == NULL || mun == NULL || f == NULL || (f_eq == NULL && fr_disk_law_uses_feq(law)))
        return FRICREG_ENULL;
    status = disk_batch_status(m, v, f_eq, mun);
    if (status != FRICREG_OK)
        return status;
    for (size_t i = 0; i < m; i++)
        fr_disk_law(law, v + 2 * i, f_eq ? f_eq + 2 * i : NULL, mun[i], eps, f + 2 * i);
    return FRICREG_OK;
}
