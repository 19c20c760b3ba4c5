/* SPDX-License-Identifier: GPL-3.0-or-later */
/* qsma_path.c — the static loading path of quasi-static modal analysis (qsma_internal.h):
 * K x + J^T F(J x) = λ M φ_k from rest, λ increasing. Every slider is a spring of stiffness
 * k_s in series with a Coulomb slider of slip force φ_s, its force k_s (J_r x − z_s) while it
 * sticks (z_s its slip so far), σ_s φ_s while it slips; so the path is piecewise linear: on a
 * piece the pattern of stuck and slipping sliders is fixed, x moves as dx/dλ = v = K_t^-1 M φ_k
 * (K_t = K + Σ_stuck k_s J_r^T J_r), the modal amplitude q = φ_k^T M x as dq/dλ = b^T v, and
 * the piece ends where the next stuck slider's force reaches its slip force (an event, stepped
 * to exactly). So λ(q) is piecewise linear and its integral is exact by the trapezoid rule on
 * each piece. A slider slipping whose row then moves back (J_r v against its slip) sticks again
 * at its bound (z_s = J_r x − σ_s φ_s/k_s), the pattern solved anew until none does: then the
 * loop by Masing's rule on the modal curve is QSMA's assumption, no longer each slider's own
 * loop. With sensitivities, λ's derivative at fixed q (qsma_dlambda.c) is affine in q on a
 * piece, so its integral is the trapezoid's too; the events' own motion adds nothing, λ being
 * continuous across them (Leibniz). A slider stuck again has a slip z_s that moves with the
 * parameters through its event (qsma_dlambda.c's fr_qsma_devent). */
#include <math.h>
#include <string.h>

#include "qsma_internal.h"

/* out_r = J_r y for every row. */
static void rows_of(const fricreg_hb *hb, const double *y, double *out)
{
    size_t n = hb->n;
    for (size_t r = 0; r < hb->m; r++) {
        double t = 0.0;
        for (size_t i = 0; i < n; i++)
            t += hb->J[r * n + i] * y[i];
        out[r] = t;
    }
}

static double dot(const double *a, const double *b, size_t n)
{
    double t = 0.0;
    for (size_t i = 0; i < n; i++)
        t += a[i] * b[i];
    return t;
}

/* The λ step to the next stuck slider's slip force (infinite: none loads), that slider into
 * *t. */
static double next_event(const struct fr_qsma *s, size_t *t)
{
    double step = INFINITY;
    for (size_t j = 0; j < s->nsl; j++) {
        double df = s->ks[j] * s->vr[s->row[j]];
        if (s->sigma[j] == 0 && df != 0.0) {
            double f = s->ks[j] * (s->ur[s->row[j]] - s->z[j]);
            double d = fmax(0.0, (copysign(s->fs[j], df) - f) / df);
            if (d < step) {
                step = d;
                *t = j;
            }
        }
    }
    return step;
}

/* The sliders at their slip force after the event slip; the rows' stuck stiffnesses anew. */
static void slip_at_event(struct fr_qsma *s)
{
    memset(s->kr, 0, s->m * sizeof *s->kr);
    for (size_t j = 0; j < s->nsl; j++) {
        size_t r = s->row[j];
        double df = s->ks[j] * s->vr[r], f = s->ks[j] * (s->ur[r] - s->z[j]);
        /* sliders reaching their bound at the same λ (to rounding) slip together */
        if (s->sigma[j] == 0 && df != 0.0 && copysign(1.0, df) * f >= s->fs[j] * (1.0 - 1e-12))
            s->sigma[j] = df > 0.0 ? 1 : -1;
        if (s->sigma[j] == 0)
            s->kr[r] += s->ks[j];
    }
}

/* The slipping sliders whose rows move against their slip on the new piece stick again at
 * their bound, z_s = J_r x* − σ_s φ_s/k_s (with p its derivative, from the event's J dx*);
 * how many. */
static size_t restick(struct fr_qsma *s, const struct fr_qsma_sens *p)
{
    double vmax = 0.0;
    size_t count = 0;
    for (size_t j = 0; j < s->nsl; j++)
        vmax = fmax(vmax, fabs(s->vr[s->row[j]]));
    for (size_t j = 0; j < s->nsl; j++) {
        size_t r = s->row[j];
        if (s->sigma[j] != 0 && s->sigma[j] * s->vr[r] < -1e-10 * vmax) {
            s->z[j] = s->ur[r] - s->sigma[j] * s->fs[j] / s->ks[j];
            for (size_t k = 0; p != NULL && k < p->np; k++) {
                signed char role = p->role[k * s->nsl + j];
                p->dz[k * s->nsl + j] = p->dur[k * s->m + r] -
                                        s->sigma[j] * (role == 2) / s->ks[j] +
                                        s->sigma[j] * s->fs[j] * (role == 1) /
                                            (s->ks[j] * s->ks[j]);
            }
            s->sigma[j] = 0;
            s->kr[r] += s->ks[j];
            count++;
        }
    }
    return count;
}

/* The targets on the current piece (from q, λ, ∫ = I, up to the step): their results. */
static size_t targets(const struct fr_qsma *s, const struct fr_qsma_sens *p, size_t i, size_t na,
                      const double *amp, double q, double lambda, double I, double step,
                      const double *dl0, const double *dI, double *work, struct fr_qsma_out *out)
{
    size_t n = s->n, np = p ? p->np : 0;
    double bv = dot(s->b, s->v, n), *dl = work, *xa = dl + np, *ua = xa + n;
    for (; i < na && (amp[i] - q) / bv <= step; i++) {
        double dq = amp[i] - q, da = dq / bv, la = lambda + da;
        out->lambda[i] = la;
        out->integral[i] = I + 0.5 * dq * (lambda + la);
        out->slope[i] = 1.0 / bv;
        if (p == NULL)
            continue;
        for (size_t k = 0; k < n; k++)
            xa[k] = s->x[k] + da * s->v[k];
        for (size_t r = 0; r < s->m; r++)
            ua[r] = s->ur[r] + da * s->vr[r];
        fr_qsma_dlambda(s, p, xa, ua, la, dl);
        for (size_t k = 0; k < np; k++) {
            out->dlambda[i * np + k] = dl[k];
            out->dintegral[i * np + k] = dI[k] + 0.5 * dq * (dl0[k] + dl[k]);
        }
    }
    return i;
}

/* The pattern after an event: the tangent of the sliders slipping there, then of those that
 * stick again, until none does. FRICREG_OK, FRICREG_ESINGULAR (the tangent), FRICREG_EINVAL
 * (re-sticking does not settle: more rounds than sliders). */
static int settle(fricreg_hb *hb, struct fr_qsma *s, const struct fr_qsma_sens *p)
{
    for (size_t round = 0; round <= s->nsl; round++) {
        if (fr_qsma_tangent(s, hb->J) != FRICREG_OK)
            return FRICREG_ESINGULAR;
        rows_of(hb, s->v, s->vr);
        if (restick(s, p) == 0)
            return FRICREG_OK;
    }
    return FRICREG_EINVAL;
}

int fr_qsma_path(fricreg_hb *hb, const char *fn, struct fr_qsma *s, size_t na, const double *amp,
                 const struct fr_qsma_sens *p, double *work, struct fr_qsma_out *out)
{
    size_t n = s->n, np = p ? p->np : 0, i = 0, idle = 0, t = 0;
    double lambda = 0.0, q = 0.0, I = 0.0, *dl0 = work, *dl1 = dl0 + np, *dI = dl1 + np;
    memset(s->x, 0, n * sizeof *s->x);
    memset(s->z, 0, s->nsl * sizeof *s->z);
    memset(s->sigma, 0, s->nsl * sizeof *s->sigma);
    memset(dI, 0, np * sizeof *dI);
    if (p != NULL)
        memset(p->dz, 0, np * s->nsl * sizeof *p->dz);
    memset(s->ur, 0, s->m * sizeof *s->ur);
    memset(s->vr, 0, s->m * sizeof *s->vr);
    slip_at_event(s); /* at rest: every slider stuck, the rows' stiffnesses summed */
    if (fr_qsma_tangent(s, hb->J) != FRICREG_OK)
        return fr_fail(hb, FRICREG_ESINGULAR, "%s: the stuck structure's K_0 is singular", fn);
    for (;;) {
        rows_of(hb, s->v, s->vr);
        rows_of(hb, s->x, s->ur);
        double bv = dot(s->b, s->v, n), step = next_event(s, &t);
        if (!(bv > 0.0) || !isfinite(bv))
            return fr_fail(hb, FRICREG_ENONFINITE, "%s: dq/dlambda = %g at q = %g", fn, bv, q);
        if (p != NULL)
            fr_qsma_dlambda(s, p, s->x, s->ur, lambda, dl0);
        i = targets(s, p, i, na, amp, q, lambda, I, step, dl0, dI, dl1 + 2 * np, out);
        if (i == na)
            return FRICREG_OK;
        /* a pattern that loads a slider just stuck again past its bound at once cycles */
        if (!(step > 0.0) && ++idle > s->nsl)
            return fr_fail(hb, FRICREG_EINVAL,
                           "%s: no consistent pattern of stuck and slipping sliders at the modal "
                           "amplitude %g",
                           fn, q);
        if (step > 0.0)
            idle = 0;
        for (size_t k = 0; k < n; k++) /* to the event */
            s->x[k] += step * s->v[k];
        for (size_t r = 0; r < s->m; r++)
            s->ur[r] += step * s->vr[r];
        double qn = dot(s->b, s->x, n), ln = lambda + step;
        I += 0.5 * (qn - q) * (lambda + ln);
        if (p != NULL) {
            fr_qsma_dlambda(s, p, s->x, s->ur, ln, dl1);
            for (size_t k = 0; k < np; k++)
                dI[k] += 0.5 * (qn - q) * (dl0[k] + dl1[k]);
        }
        q = qn;
        lambda = ln;
        if (p != NULL) /* on this piece's factor, before the pattern changes */
            fr_qsma_devent(s, p, hb->J, t, lambda);
        slip_at_event(s);
        int status = settle(hb, s, p);
        if (status == FRICREG_ESINGULAR)
            return fr_fail(hb, FRICREG_ESINGULAR,
                           "%s: macroslip at the modal amplitude %g (lambda = %g): the sliders "
                           "slipping leave the structure without stiffness, the amplitude %g is "
                           "beyond reach",
                           fn, q, lambda, amp[i]);
        if (status != FRICREG_OK)
            return fr_fail(hb, FRICREG_EINVAL,
                           "%s: the sliders sticking again at the modal amplitude %g do not settle "
                           "on a pattern",
                           fn, q);
    }
}
