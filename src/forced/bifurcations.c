/* SPDX-License-Identifier: GPL-3.0-or-later */
/* bifurcations.c — the bifurcations of a continued branch: the getters of fricreg_hb.h
 * (fricreg_hb_bifurcations, fricreg_hb_bifurcation, fricreg_hb_bifurcation_level), then their
 * location. Between two stored points a test changes sign: the tangent's parameter component
 * (a turning point), the bordered matrix's determinant (a branch point), or with stability on
 * the verdict of Hill's method (period doubling, Neimark–Sacker, or a real exponent); the
 * sign change is bisected on the hyperplanes normal to the points' chord, with the corrector. */
#include <string.h>

#include "bifurcations.h"
#include "floquet/stability_method.h"
#include "hb/recover.h"

size_t fricreg_hb_bifurcations(const fricreg_hb *hb)
{
    return hb ? fr_hb_bifurcations_held(hb) : 0;
}

int fricreg_hb_bifurcation(fricreg_hb *hb, size_t i, int *type, double *omega, size_t *point,
                           size_t ndof, double rms[])
{
    static const char fn[] = "bifurcation";
    if (hb == NULL)
        return FRICREG_ENULL;
    if (type == NULL || omega == NULL || rms == NULL)
        return fr_fail(hb, FRICREG_ENULL, "%s: %s is NULL", fn,
                       type == NULL    ? "type"
                       : omega == NULL ? "omega"
                                       : "rms");
    size_t nbif = fr_hb_bifurcations_held(hb);
    if (i >= nbif)
        return fr_fail(hb, FRICREG_EINVAL, "%s: i = %zu, %zu bifurcations located", fn, i, nbif);
    if (ndof != hb->n)
        return fr_fail(hb, FRICREG_ESIZE, "%s: ndof = %zu, the driver has %zu", fn, ndof, hb->n);
    const double *rec = hb->forced->bifs + i * (4 + hb->n);
    *type = (int)rec[0];
    *omega = rec[1];
    if (point != NULL)
        *point = (size_t)rec[2];
    memcpy(rms, rec + 4, hb->n * sizeof(double));
    return FRICREG_OK;
}

int fricreg_hb_bifurcation_level(fricreg_hb *hb, size_t i, double *level)
{
    if (hb == NULL)
        return FRICREG_ENULL;
    if (level == NULL)
        return fr_fail(hb, FRICREG_ENULL, "bifurcation_level: level is NULL");
    size_t nbif = fr_hb_bifurcations_held(hb);
    if (i >= nbif)
        return fr_fail(hb, FRICREG_EINVAL, "bifurcation_level: i = %zu, %zu bifurcations located",
                       i, nbif);
    *level = hb->forced->bifs[i * (4 + hb->n) + 3];
    return FRICREG_OK;
}

/* A bifurcation's test: its type, and for a change of stability the exponents' kind it follows
 * (fr_hb_hill_unstable). */
struct test {
    int type, kind;
};

/* The test's sign (0 or 1) at a point whose extras are x (xpts's layout) at omega. */
static int test_sign(const fricreg_hb *hb, struct test t, const double *x, double omega)
{
    if (t.kind >= 0)
        return fr_hb_hill_unstable(hb, omega, x + 4, t.kind);
    return x[t.type == FRICREG_HB_TP ? 0 : 1] > 0.0;
}

/* The branch's point on the hyperplane normal to the chord ya → yb (scaled) through
 * ya + s (yb − ya): its test sign, Ω, and the RMS of each dof into rms. */
static int test_at(fricreg_hb *hb, struct fr_hb_branch *b, const double *ya, const double *yb,
                   double s, struct test t, int *sign, double *omega, double *rms)
{
    static const char fn[] = "continue";
    size_t nq = hb->nq, ld = nq + 1;
    struct fr_hb_vectors v = fr_hb_vectors(hb);
    double *normal = v.dir, *anchor = v.yo, len = fr_hb_dist(yb, ya, ld);
    for (size_t j = 0; j < ld; j++) {
        normal[j] = (yb[j] - ya[j]) / len;
        anchor[j] = ya[j] + s * (yb[j] - ya[j]);
    }
    int its = 0, status = fr_hb_corrector(hb, fn, b, anchor, anchor, normal, &its);
    if (status != FRICREG_OK)
        return status;
    *omega = fr_hb_branch_omega(b, hb->qw[nq] * b->ws);
    double tx[2], *x = t.kind >= 0 ? fr_hb_stability_trial(hb) : tx;
    if (t.kind >= 0)
        status = fr_hb_stability(hb, fn, *omega, x + 2);
    else if ((status = fr_hb_tangent(hb, fn, hb->rw)) == FRICREG_OK) {
        x[0] = hb->rw[nq];
        x[1] = fr_hb_det_sign(hb, ld);
    }
    if (status != FRICREG_OK)
        return status;
    *sign = test_sign(hb, t, x, *omega);
    fr_hb_rms(hb, rms); /* fr_hb_bordered() left the factors and forces at qw */
    return FRICREG_OK;
}

/* Bisection on the test's sign between stored points k and k + 1, to 1e-9 of their chord; the
 * bifurcation recorded at the last bracket's middle (or, should a trial fail, at the bracket's
 * end nearer to the points' side it came from). */
static void bisect(fricreg_hb *hb, struct fr_hb_branch *b, size_t k, struct test t)
{
    struct fr_hb_forced *f = hb->forced;
    size_t ld = hb->nq + 1, n = hb->n, xw = f->xpts_stride;
    double *ya = fr_hb_vectors(hb).yp, *yb = ya + ld, lo = 0.0, hi = 1.0;
    for (size_t j = 0; j < ld; j++) {
        double c = j < hb->nq ? b->qs : b->ws;
        ya[j] = f->qpts[k * ld + j] / c;
        yb[j] = f->qpts[(k + 1) * ld + j] / c;
    }
    /* a change of stability's side at point k is its verdict's (an exponent within the
     * verdict's margin of the unit circle there puts the crossing at k itself) */
    const double *xk = f->xpts + k * xw;
    int sa = t.kind >= 0 ? xk[2] == 0.0 : test_sign(hb, t, xk, f->pts[k * (1 + n)]);
    double *rec = f->bifs + f->nbif * (4 + n);
    rec[0] = t.type;
    rec[2] = (double)k;
    double omega = 0.0;
    int found = 0;
    while (hi - lo > 1e-9) {
        double s = 0.5 * (lo + hi);
        int sign = 0;
        if (test_at(hb, b, ya, yb, s, t, &sign, &omega, rec + 4) != FRICREG_OK) {
            if (hb->stopped) /* no bifurcation recorded: the call ends */
                return;
            break;
        }
        rec[1] = omega;
        rec[3] = hb->level; /* fr_hb_corrector() left the trial's */
        found = 1;
        if (sign == sa)
            lo = s;
        else
            hi = s;
    }
    if (!found) { /* the stored point nearer to the bracket */
        size_t at = lo > 0.0 ? k + 1 : k;
        rec[1] = f->pts[at * (1 + n)];
        rec[3] = b->level ? f->qpts[at * ld + hb->nq] : 1.0;
        memcpy(rec + 4, f->pts + at * (1 + n) + 1, n * sizeof(double));
    }
    f->nbif++;
}

/* Whether the tangent's Ω component or the determinant's sign changes between points i and
 * i + 1 (a turning or branch point there; i may be out of the branch's range: no). */
static int jacobian_test_changes(const fricreg_hb *hb, size_t i)
{
    const struct fr_hb_forced *f = hb->forced;
    if (i + 1 >= f->npts)
        return 0;
    const double *x0 = f->xpts + i * f->xpts_stride, *x1 = x0 + f->xpts_stride;
    return (x0[0] > 0.0) != (x1[0] > 0.0) || x0[1] * x1[1] < 0.0;
}

/* Each pair of successive points: the first test whose sign changed, located. A real multiplier
 * through +1 next to a turning or branch point is that point's: the exact monodromy's multiplier
 * (the orbit's) crosses within the HB's truncation error of the Jacobian's singularity, which
 * may fall in the neighbouring interval (Hill's, from the Jacobian itself, in the same one). */
void fr_hb_locate_bifurcations(fricreg_hb *hb, struct fr_hb_branch *b)
{
    struct fr_hb_forced *f = hb->forced;
    size_t xw = f->xpts_stride, w = 1 + hb->n;
    f->nbif = 0;
    for (size_t k = 0; k + 1 < f->npts && !hb->stopped; k++) {
        const double *x0 = f->xpts + k * xw, *x1 = x0 + xw;
        struct test t = {0, -1};
        if ((x0[0] > 0.0) != (x1[0] > 0.0))
            t.type = FRICREG_HB_TP;
        else if (x0[1] * x1[1] < 0.0)
            t.type = FRICREG_HB_BP;
        else if (fr_hb_stability_on(hb) && x0[2] != x1[2]) {
            /* the exponent that crossed: the largest on the unstable side */
            int up = x1[2] == 0.0;
            const double *xu = up ? x1 : x0;
            t.kind = fr_hb_hill_crossing(hb, f->pts[(k + (size_t)up) * w], xu + 4);
            t.type = t.kind == 1 ? FRICREG_HB_PD : t.kind == 2 ? FRICREG_HB_NS : FRICREG_HB_BP;
            if (t.kind == 0 &&
                ((k > 0 && jacobian_test_changes(hb, k - 1)) || jacobian_test_changes(hb, k + 1)))
                t.type = 0;
        }
        if (t.type != 0)
            bisect(hb, b, k, t);
    }
}
