/* SPDX-License-Identifier: GPL-3.0-or-later */
/* qsma.c — quasi-static modal analysis's backbone (fricreg_hb_qsma_at, fricreg_hb_qsma.h): the
 * arguments' checks, the model and its mode, the loading path through the amplitudes
 * (qsma_path.c's exact one, or qsma_march.c's where 3-D contacts are), and the secant frequency and Masing's damping from it (Lacayo & Allen, MSSP
 * 118 (2019) 133–157):
 *
 *     ω² = λ(a)/a,   D = 8 ∫_0^a λ ds − 4 a λ(a),   ζ = ζ_k + D / (2π λ(a) a). */
#include <math.h>
#include <stdlib.h>

#include "fricreg_hb_qsma.h"
#include "base/fr_math.h"
#include "hb/busy.h"
#include "qsma_internal.h"

int fr_qsma_args(fricreg_hb *hb, const char *fn, size_t mode, size_t na, const double *amp)
{
    if (!hb->have_elements)
        return fr_fail(hb, FRICREG_EINVAL, "%s: no elements (fricreg_hb_set_elements)", fn);
    if (mode >= hb->n)
        return fr_fail(hb, FRICREG_EINVAL, "%s: mode = %zu, the structure has %zu modes (from 0)",
                       fn, mode, hb->n);
    if (na == 0)
        return fr_fail(hb, FRICREG_EINVAL, "%s: n = 0 amplitudes", fn);
    for (size_t i = 0; i < na; i++) {
        if (!isfinite(amp[i]))
            return fr_fail(hb, FRICREG_ENONFINITE, "%s: amplitude[%zu] = %g", fn, i, amp[i]);
        if (!(amp[i] > (i > 0 ? amp[i - 1] : 0.0)))
            return fr_fail(hb, FRICREG_EINVAL,
                           "%s: amplitude[%zu] = %g: the amplitudes must be > 0 and increase", fn,
                           i, amp[i]);
    }
    return FRICREG_OK;
}

int fr_qsma_setup(fricreg_hb *hb, const char *fn, size_t mode, struct fr_qsma **out)
{
    struct fr_qsma *s = NULL;
    int status = fr_qsma_create(hb, fn, &s);
    if (status == FRICREG_OK && (status = fr_qsma_mode(hb, fn, mode, s)) != FRICREG_OK) {
        fr_qsma_free(s);
        s = NULL;
    }
    *out = s;
    return status;
}

int fr_qsma_run(fricreg_hb *hb, const char *fn, struct fr_qsma *s, size_t na, const double *amp,
                const struct fr_qsma_sens *p, double *work, struct fr_qsma_out *out)
{
    if (s->ncon > 0) {
        int status = fr_qsma_march(hb, fn, s, na, amp, p, out);
        /* a contact's friction can turn the static load back: no secant frequency there */
        for (size_t i = 0; i < na && status == FRICREG_OK; i++)
            if (!(out->lambda[i] > 0.0))
                return fr_fail(hb, FRICREG_EINVAL,
                               "%s: the static path's load factor lambda = %g at the modal "
                               "amplitude %g is not positive: no secant frequency",
                               fn, out->lambda[i], amp[i]);
        return status;
    }
    int status = fr_qsma_path(hb, fn, s, na, amp, p, work, out);
    for (size_t i = 0; i < na && status == FRICREG_OK && out->dint_da != NULL; i++)
        out->dint_da[i] = out->lambda[i]; /* the integral exact */
    return status;
}

int fricreg_hb_qsma_at(fricreg_hb *hb, size_t mode, size_t n, const double amplitude[],
                       double omega[], double zeta[])
{
    static const char fn[] = "fricreg_hb_qsma_at";
    if (hb == NULL || hb->busy)
        return fr_hb_refuse(hb, fn);
    if (amplitude == NULL || omega == NULL || zeta == NULL)
        return fr_fail(hb, FRICREG_ENULL, "%s: %s is NULL", fn,
                       amplitude == NULL ? "amplitude"
                       : omega == NULL   ? "omega"
                                         : "zeta");
    int status = fr_qsma_args(hb, fn, mode, n, amplitude);
    struct fr_qsma *s = NULL;
    if (status == FRICREG_OK)
        status = fr_qsma_setup(hb, fn, mode, &s);
    if (status != FRICREG_OK)
        return status;
    double *buf = malloc((3 * n + s->n + s->m) * sizeof *buf);
    if (buf == NULL) {
        fr_qsma_free(s);
        return fr_fail(hb, FRICREG_ENOMEM, "%s: no memory for %zu amplitudes", fn, n);
    }
    struct fr_qsma_out out = {.lambda = buf, .integral = buf + n, .slope = buf + 2 * n};
    status = fr_qsma_run(hb, fn, s, n, amplitude, NULL, buf + 3 * n, &out);
    for (size_t i = 0; i < n && status == FRICREG_OK; i++) {
        double a = amplitude[i], l = out.lambda[i], D = 8.0 * out.integral[i] - 4.0 * a * l;
        omega[i] = sqrt(l / a);
        zeta[i] = s->zeta_k + D / (FR_TWO_PI * l * a);
    }
    free(buf);
    fr_qsma_free(s);
    return status;
}
