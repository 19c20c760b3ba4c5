/* SPDX-License-Identifier: GPL-3.0-or-later */
/* peak.c — fricreg_hb_peak: a dof's largest RMS on the continued branch, located between the
 * stored points by Brent's minimization along the chord of the three points around the
 * largest stored one, each trial solved by the corrector (corrector.c) on the hyperplane
 * normal to the chord. Apart from the continuation: it reads a branch already stored. */
#include <math.h>
#include <string.h>

#include "corrector.h"
#include "hb/monitor.h"
#include "hb/busy.h"
#include "hb/recover.h"

static int brent_peak(fricreg_hb *hb, struct fr_hb_branch *b, size_t k, const double *y3[3],
                      double sb, double fb, double *omega, double *rms);

int fricreg_hb_peak(fricreg_hb *hb, size_t dof, double *omega, double *rms)
{
    if (hb == NULL)
        return FRICREG_ENULL;
    if (omega == NULL || rms == NULL)
        return fr_fail(hb, FRICREG_ENULL, "peak: %s is NULL", omega == NULL ? "omega" : "rms");
    if (hb->busy)
        return fr_hb_refuse(hb, "peak");
    if (dof >= hb->n)
        return fr_fail(hb, FRICREG_EINVAL, "peak: dof = %zu, the driver has %zu", dof, hb->n);
    if (!fr_hb_branch_holds(hb))
        return fr_fail(hb, FRICREG_EINVAL,
                       "peak: no branch (no fricreg_hb_continue yet, or the model changed since)");
    const struct fr_hb_forced *fs = hb->forced;
    if (fs->branch_level)
        return fr_fail(hb, FRICREG_EINVAL,
                       "peak: the branch is in the excitation level (fricreg_hb_continue_level), "
                       "not in Omega");
    size_t w = 1 + hb->n, ld = hb->nq + 1, best = 0;
    for (size_t k = 1; k < fs->npts; k++)
        if (fs->pts[k * w + 1 + dof] > fs->pts[best * w + 1 + dof])
            best = k;
    double om = fs->pts[best * w], f = fs->pts[best * w + 1 + dof];
    if (best > 0 && best + 1 < fs->npts) {
        /* the three points around it, scaled */
        struct fr_hb_branch b = {.qs = fs->branch_qs, .ws = fs->branch_ws};
        struct fr_hb_vectors v = fr_hb_vectors(hb);
        double *y[3] = {v.yp, v.yp + ld, v.tan};
        for (int i = 0; i < 3; i++)
            for (size_t j = 0; j < ld; j++)
                y[i][j] = fs->qpts[(best - 1 + (size_t)i) * ld + j] / (j + 1 < ld ? b.qs : b.ws);
        const double *y3[3] = {y[0], y[1], y[2]};
        double len = fr_hb_dist(y[2], y[0], ld), sb = 0.0;
        for (size_t j = 0; j < ld; j++)
            sb += (y[1][j] - y[0][j]) * (y[2][j] - y[0][j]) / (len * len);
        /* the middle point projects inside the chord (the tangent turns by less than 90° a
         * step): otherwise the sampled point stands */
        if (sb > 0.0 && sb < 1.0) {
            struct fr_error before = hb->err;
            fr_hb_begin(hb, 1);
            int status = fr_hb_end(hb, brent_peak(hb, &b, dof, y3, sb, f, &om, &f));
            if (status != FRICREG_OK)
                return status;
            hb->err = before;
        }
    }
    *omega = om;
    *rms = f;
    return FRICREG_OK;
}

/* Dof k's RMS at the branch's point on the hyperplane border^T (y − anchor) = 0, from start
 * (scaled, b's scales); Ω into *omega. */
static int rms_on_plane(fricreg_hb *hb, struct fr_hb_branch *b, size_t k, const double *start,
                        const double *anchor, const double *border, double *omega, double *f)
{
    int its = 0, status = fr_hb_corrector(hb, "peak", b, start, anchor, border, &its);
    if (status != FRICREG_OK)
        return status;
    *omega = hb->qw[hb->nq] * b->ws;
    *f = fr_hb_rms_dof(hb, k); /* fr_hb_bordered() left the factors and forces at qw */
    return FRICREG_OK;
}

/* The point of the branch at s in [0, 1] along the chord from ya to yc: its hyperplane (normal
 * the chord, through ya + s (yc − ya)) and the quadratic through ya, yb, yc (at 0, sb, 1) as
 * the corrector's start; dof k's RMS there. */
static int rms_at(fricreg_hb *hb, struct fr_hb_branch *b, size_t k, const double *y3[3], double sb,
                  double s, double *omega, double *f)
{
    size_t ld = hb->nq + 1;
    struct fr_hb_vectors v = fr_hb_vectors(hb);
    double *normal = v.dir, *anchor = v.yo, *start = v.tn, len = fr_hb_dist(y3[2], y3[0], ld);
    double la = (s - sb) * (s - 1.0) / sb, lb = s * (s - 1.0) / (sb * (sb - 1.0)),
           lc = s * (s - sb) / (1.0 - sb);
    for (size_t j = 0; j < ld; j++) {
        normal[j] = (y3[2][j] - y3[0][j]) / len;
        anchor[j] = y3[0][j] + s * (y3[2][j] - y3[0][j]);
        start[j] = la * y3[0][j] + lb * y3[1][j] + lc * y3[2][j];
    }
    return rms_on_plane(hb, b, k, start, anchor, normal, omega, f);
}

/* Brent's minimization without derivatives (R. P. Brent, "Algorithms for Minimization without
 * Derivatives", Prentice-Hall 1973, Ch. 5: golden section and successive parabolic
 * interpolation) of −RMS over s in [0, 1], from x = sb where RMS is at least its value at 0 and
 * 1; s to 1e-6 (the RMS to about 1e-12 of itself, below Newton's tolerance). */
static int brent_peak(fricreg_hb *hb, struct fr_hb_branch *b, size_t k, const double *y3[3],
                      double sb, double fb, double *omega, double *rms)
{
    const double golden = 0.3819660112501051, tol1 = 1e-6;
    double a = 0.0, c = 1.0, x = sb, w = sb, v = sb, fx = -fb, fw = fx, fv = fx, d = 0.0, e = 0.0;
    for (int evals = 0; evals < 60; evals++) {
        double xm = 0.5 * (a + c), tol2 = 2.0 * tol1;
        if (fabs(x - xm) <= tol2 - 0.5 * (c - a))
            break;
        int parabolic = 0;
        if (fabs(e) > tol1) {
            double r = (x - w) * (fx - fv), q = (x - v) * (fx - fw), p = (x - v) * q - (x - w) * r;
            q = 2.0 * (q - r);
            if (q > 0.0)
                p = -p;
            q = fabs(q);
            double last = e;
            e = d;
            if (fabs(p) < fabs(0.5 * q * last) && p > q * (a - x) && p < q * (c - x)) {
                d = p / q;
                parabolic = 1;
                double u = x + d;
                if (u - a < tol2 || c - u < tol2)
                    d = xm >= x ? tol1 : -tol1;
            }
        }
        if (!parabolic) {
            e = x >= xm ? a - x : c - x;
            d = golden * e;
        }
        double u = fabs(d) >= tol1 ? x + d : x + (d >= 0.0 ? tol1 : -tol1), om = 0.0, fu = 0.0;
        int status = rms_at(hb, b, k, y3, sb, u, &om, &fu);
        if (status != FRICREG_OK)
            return status;
        fu = -fu;
        if (fu <= fx) {
            if (u >= x)
                a = x;
            else
                c = x;
            v = w, fv = fw, w = x, fw = fx, x = u, fx = fu;
            *omega = om;
        } else {
            if (u < x)
                a = u;
            else
                c = u;
            if (fu <= fw || w == x)
                v = w, fv = fw, w = u, fw = fu;
            else if (fu <= fv || v == x || v == w)
                v = u, fv = fu;
        }
    }
    *rms = -fx;
    return FRICREG_OK;
}
