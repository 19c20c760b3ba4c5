/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Checks on a fricreg_disk_ctx shared by the disk-context tests (disk_ctx_checks.h). */
#include "disk_ctx_checks.h"
#include "quiet_check.h"

#include <check.h>
#include <math.h>
#include <string.h>

void eval_ok(fricreg_disk_ctx *ctx, size_t m, const double zdot[], const double a_free[],
             double f[])
{
    int status = fricreg_disk_ctx_eval(ctx, m, zdot, a_free, f);
    QUIET_ASSERT(status == FRICREG_OK, "eval: %d %s", status, fricreg_disk_ctx_errmsg(ctx));
}

double max_abs(const double x[], size_t n)
{
    double s = 0.0;
    for (size_t k = 0; k < n; k++)
        s = fmax(s, fabs(x[k]));
    return s;
}

double disk_ctx_sweep(fricreg_disk_ctx *ctx, size_t m, double zdot[], const double a_free[],
                      const double dir[2], double s0, double h, int steps)
{
    ck_assert_uint_le(2 * m, DISK_CHECK_MAXN);
    double f[DISK_CHECK_MAXN], prev[DISK_CHECK_MAXN], jump = 0.0;
    for (int k = -steps; k <= steps; k++) {
        zdot[0] = (s0 + k * h) * dir[0];
        zdot[1] = (s0 + k * h) * dir[1];
        eval_ok(ctx, m, zdot, a_free, f);
        if (k > -steps)
            for (size_t q = 0; q < 2 * m; q++)
                jump = fmax(jump, fabs(f[q] - prev[q]));
        memcpy(prev, f, sizeof(double) * 2 * m);
    }
    return jump;
}

/* Central differences of eval in zdot (which = 0) or a_free (which = 1), step h: J (2m x 2m,
 * row-major). */
static void central(fricreg_disk_ctx *ctx, size_t m, const double zdot[], const double a_free[],
                    int which, double h, double J[])
{
    size_t n = 2 * m;
    double z[DISK_CHECK_MAXN], a[DISK_CHECK_MAXN], fp[DISK_CHECK_MAXN], fm[DISK_CHECK_MAXN];
    for (size_t c = 0; c < n; c++) {
        memcpy(z, zdot, n * sizeof *z);
        memcpy(a, a_free, n * sizeof *a);
        double *x = which ? a : z;
        x[c] += h;
        eval_ok(ctx, m, z, a, fp);
        x[c] -= 2.0 * h;
        eval_ok(ctx, m, z, a, fm);
        for (size_t r = 0; r < n; r++)
            J[r * n + c] = (fp[r] - fm[r]) / (2.0 * h);
    }
}

int disk_ctx_check_tangent(fricreg_disk_ctx *ctx, size_t m, const double zdot[],
                           const double a_free[], double eps)
{
    enum { NN = DISK_CHECK_MAXN * DISK_CHECK_MAXN };
    ck_assert_uint_le(2 * m, DISK_CHECK_MAXN);
    size_t n = 2 * m, nn = n * n;
    double f[DISK_CHECK_MAXN], T[2][NN], D1[NN], D2[NN];
    eval_ok(ctx, m, zdot, a_free, f);
    int status = fricreg_disk_ctx_tangent(ctx, m, T[0], T[1]);
    ck_assert_msg(status == FRICREG_OK, "tangent: %s", fricreg_disk_ctx_errmsg(ctx));
    for (int which = 0; which < 2; which++) {
        double h = which ? 1e-6 : 1e-6 * eps;
        central(ctx, m, zdot, a_free, which, h, D1);
        central(ctx, m, zdot, a_free, which, 0.5 * h, D2);
        double scale = fmax(max_abs(D1, nn), 1e-3);
        double kink = 0.0, err = 0.0;
        for (size_t k = 0; k < nn; k++) {
            kink = fmax(kink, fabs(D1[k] - D2[k]));
            err = fmax(err, fabs(T[which][k] - D2[k]));
        }
        if (kink > 1e-7 * scale)
            return 0;
        ck_assert_msg(err <= 1e-6 * scale,
                      "tangent (%s) differs from central differences: %g of %g",
                      which ? "a_free" : "zdot", err, scale);
    }
    return 1;
}
