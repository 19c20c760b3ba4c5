/* SPDX-License-Identifier: GPL-3.0-or-later */
/* truncation.c — the error of truncating the Fourier series at H (fricreg_hb_truncation_error):
 * the same model solved by Galerkin at H' = 2H + 1 harmonics from the H solution padded with
 * zeros (Krack & Gross 2019, Sec. 2.4: the convergence check by more harmonics), in a companion
 * driver made for the call (fr_hb_clone), and each dof's RMS and amplitude of the fundamental
 * compared: the H solution's are the companion's coefficients up to H at the padded start
 * (the exact AFT gives the same force harmonics from the same q(θ)), so the caller's driver is
 * only read. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "points.h"
#include "hb/dynamic.h"
#include "hb/hb.h"
#include "hb/residual.h"
#include "hb/newton.h"
#include "hb/monitor.h"
#include "hb/busy.h"
#include "hb/recover.h"

/* The estimate's safety factor on |rms(2H + 1) − rms(H)| (the header's docstring). */
#define SAFETY 2.0
/* The companion's Newton bound, in the driver's (fricreg_hb_set_newton): from the padded start
 * Newton takes 2 iterations where the series has converged, but where H truncates much (a dahl
 * chain at 3% off, whose kinked force keeps its steps damped) 65 against the default bound 50. */
#define COMPANION_ITER_FACTOR 4

/* The unknowns q[m nc] of h's driver padded with zeros into c's iterate qw[m nc'] (nc' > nc). */
static void pad(const fricreg_hb *hb, fricreg_hb *c, const double *q)
{
    memset(c->qw, 0, c->nq * sizeof(double));
    for (size_t r = 0; r < hb->m; r++)
        memcpy(c->qw + r * c->nc, q + r * hb->nc, hb->nc * sizeof(double));
}

/* The companion c's solve at omega from q padded: the H solution's RMS and |X_1| into
 * w[0..2n), then the 2H + 1 solution's into w[2n..4n). */
static int companion_solve(fricreg_hb *hb, fricreg_hb *c, const char *fn, const double *q,
                           double omega, double *w)
{
    size_t n = hb->n;
    pad(hb, c, q);
    int status = fr_hb_factor(c, fn, omega, 0);
    if (status == FRICREG_OK)
        status = fr_hb_residual(c, fn, c->qw, c->R, 0);
    if (status != FRICREG_OK)
        return status;
    fr_hb_rms_upto(c, hb->H, w, w + n);
    if ((status = fr_hb_newton(c, fn)) == FRICREG_OK)
        fr_hb_rms_upto(c, c->H, w + 2 * n, w + 3 * n);
    return status;
}

int fricreg_hb_truncation_error(fricreg_hb *hb, size_t k, size_t ndof, double rms_error[],
                                double amplitude_error[])
{
    static const char fn[] = "truncation_error";
    if (hb == NULL || hb->busy)
        return fr_hb_refuse(hb, fn);
    if (rms_error == NULL)
        return fr_fail(hb, FRICREG_ENULL, "%s: rms_error is NULL", fn);
    if (ndof != hb->n)
        return fr_fail(hb, FRICREG_ESIZE, "%s: ndof = %zu, the driver has %zu", fn, ndof, hb->n);
    int H2 = 2 * hb->H + 1;
    if (H2 > FRICREG_HB_MAX_HARMONICS)
        return fr_fail(hb, FRICREG_EINVAL,
                       "%s: H = %d: 2H + 1 = %d harmonics exceed FRICREG_HB_MAX_HARMONICS = %d "
                       "(H <= %d)",
                       fn, hb->H, H2, FRICREG_HB_MAX_HARMONICS, (FRICREG_HB_MAX_HARMONICS - 1) / 2);
    const double *q = NULL;
    double omega = 0.0, level = 1.0;
    int status = fr_hb_stored_solution(hb, fn, k, &q, &omega, &level);
    if (status != FRICREG_OK)
        return status;
    size_t n = hb->n;
    fricreg_hb *c = NULL;
    double *w = malloc(4 * n * sizeof *w);
    if (w == NULL || fr_hb_clone(hb, H2, &c) != FRICREG_OK) {
        free(w);
        return fr_fail(hb, FRICREG_ENOMEM, "%s: no memory for the driver at 2H + 1 = %d harmonics",
                       fn, H2);
    }
    c->level = level;
    c->max_iter = COMPANION_ITER_FACTOR * hb->max_iter;
    /* the monitor sees Ω; the caller's driver takes only the getters' calls meanwhile */
    fr_hb_begin(hb, 1);
    fr_hb_begin(c, 1);
    status = fr_hb_end(c, companion_solve(hb, c, fn, q, omega, w));
    fr_hb_end(hb, FRICREG_OK);
    if (status != FRICREG_OK)
        fr_fail(hb, status, "%s (the solve at 2H + 1 = %d harmonics)", c->err.msg, H2);
    else
        for (size_t i = 0; i < n; i++) {
            rms_error[i] = SAFETY * fabs(w[2 * n + i] - w[i]);
            if (amplitude_error != NULL)
                amplitude_error[i] = SAFETY * fabs(w[3 * n + i] - w[n + i]);
        }
    fricreg_hb_free(c);
    free(w);
    return status;
}
