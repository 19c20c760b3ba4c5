/* SPDX-License-Identifier: GPL-3.0-or-later */
/* points.c — the continuation's points: the getters of fricreg_hb.h (fricreg_hb_points,
 * fricreg_hb_point, fricreg_hb_point_level, the coefficients of a point or of the last
 * solution), then the store they read. Each point keeps its Ω and RMS (pts), its unknowns and
 * parameter (qpts: its coefficients, the peak search and the bisections start from them) and
 * its extras (xpts: the bifurcation tests). A file apart from the loop that fills it, since
 * the getters, the bifurcations and the peak search read it too. */
#include <stdlib.h>
#include <string.h>

#include "points.h"
#include "floquet/stability_method.h"
#include "hb/dynamic.h"
#include "hb/residual.h"
#include "hb/busy.h"
#include "hb/recover.h"
#include "base/free_all.h"

size_t fricreg_hb_points(const fricreg_hb *hb)
{
    return hb ? fr_hb_points_held(hb) : 0;
}

int fricreg_hb_point(fricreg_hb *hb, size_t k, double *omega, size_t ndof, double rms[])
{
    if (hb == NULL)
        return FRICREG_ENULL;
    if (omega == NULL || rms == NULL)
        return fr_fail(hb, FRICREG_ENULL, "point: %s is NULL", omega == NULL ? "omega" : "rms");
    size_t npts = fr_hb_points_held(hb);
    if (k >= npts)
        return fr_fail(hb, FRICREG_EINVAL, "point: k = %zu, %zu points stored", k, npts);
    if (ndof != hb->n)
        return fr_fail(hb, FRICREG_ESIZE, "point: ndof = %zu, the driver has %zu", ndof, hb->n);
    const double *p = hb->forced->pts + k * (1 + hb->n);
    *omega = p[0];
    memcpy(rms, p + 1, hb->n * sizeof(double));
    return FRICREG_OK;
}

int fricreg_hb_point_level(fricreg_hb *hb, size_t k, double *level)
{
    if (hb == NULL)
        return FRICREG_ENULL;
    if (level == NULL)
        return fr_fail(hb, FRICREG_ENULL, "point_level: level is NULL");
    size_t npts = fr_hb_points_held(hb);
    if (k >= npts)
        return fr_fail(hb, FRICREG_EINVAL, "point_level: k = %zu, %zu points stored", k, npts);
    const struct fr_hb_forced *f = hb->forced;
    *level = f->branch_level ? f->qpts[k * f->qpts_stride + f->qpts_stride - 1] : 1.0;
    return FRICREG_OK;
}

/* The last solution (k = FRICREG_HB_SOLUTION) or stored point k: its unknowns q, Ω and
 * excitation level; FRICREG_EINVAL when there is none or the model changed since. */
int fr_hb_stored_solution(fricreg_hb *hb, const char *fn, size_t k, const double **q, double *omega,
                          double *level)
{
    if (k == FRICREG_HB_SOLUTION) {
        if (!hb->have_solution)
            return fr_fail(hb, FRICREG_EINVAL,
                           "%s: no solution (none yet, or the model changed since)", fn);
        *q = hb->qsol;
        *omega = hb->omega_sol;
        *level = hb->level_sol;
        return FRICREG_OK;
    }
    size_t npts = fr_hb_points_held(hb);
    if (k >= npts)
        return fr_fail(hb, FRICREG_EINVAL, "%s: k = %zu, %zu points stored", fn, k, npts);
    if (!fr_hb_branch_holds(hb))
        return fr_fail(hb, FRICREG_EINVAL, "%s: the model or elements changed since the branch",
                       fn);
    const struct fr_hb_forced *f = hb->forced;
    *q = f->qpts + k * f->qpts_stride;
    *omega = f->pts[k * (1 + hb->n)];
    *level = f->branch_level ? (*q)[hb->nq] : 1.0;
    return FRICREG_OK;
}

/* The coefficients x[n nc] of the last solution or stored point k (fr_hb_stored_solution),
 * recomputed from its unknowns: later calls move the driver's factors and forces. */
static int displacement_of(fricreg_hb *hb, const char *fn, size_t k, size_t ndof, size_t nc,
                           double x[])
{
    if (hb == NULL || hb->busy)
        return fr_hb_refuse(hb, fn);
    if (x == NULL)
        return fr_fail(hb, FRICREG_ENULL, "%s: x is NULL", fn);
    if (ndof != hb->n || nc != hb->nc)
        return fr_fail(hb, FRICREG_ESIZE,
                       "%s: ndof = %zu, nc = %zu, the driver has %zu and 2H + 1 = %zu", fn, ndof,
                       nc, hb->n, hb->nc);
    const double *q = NULL;
    double omega = 0.0, level = 1.0;
    int status = fr_hb_stored_solution(hb, fn, k, &q, &omega, &level);
    if (status == FRICREG_OK)
        status = fr_hb_factor(hb, fn, omega, 0);
    hb->level = level;
    if (status == FRICREG_OK)
        status = fr_hb_residual(hb, fn, q, hb->rw, 0);
    if (status == FRICREG_OK)
        fr_hb_recover(hb, x);
    hb->level = 1.0;
    return status;
}

int fricreg_hb_displacement(fricreg_hb *hb, size_t ndof, size_t nc, double x[])
{
    return displacement_of(hb, "displacement", FRICREG_HB_SOLUTION, ndof, nc, x);
}

int fricreg_hb_point_displacement(fricreg_hb *hb, size_t k, size_t ndof, size_t nc, double x[])
{
    return displacement_of(hb, "point_displacement", k, ndof, nc, x);
}

static void forced_release(fricreg_hb *hb)
{
    struct fr_hb_forced *f = hb->forced;
    if (f != NULL)
        FR_FREE_ALL(f->pts, f->qpts, f->xpts, f->bifs);
    free(f);
    hb->forced = NULL;
}

/* The forced response's state hung on the driver at its first branch kept. */
static int forced_made(fricreg_hb *hb)
{
    if (hb->forced != NULL)
        return FRICREG_OK;
    if ((hb->forced = calloc(1, sizeof *hb->forced)) == NULL)
        return FRICREG_ENOMEM;
    hb->release[FR_HB_PART_FORCED] = forced_release;
    return FRICREG_OK;
}

/* Room for `want` points (at most max_points), kept on failure: FRICREG_ENOMEM. The unknowns'
 * room follows nq, which the element setters change (1 or 2 rows per element). */
int fr_hb_points_reserve(fricreg_hb *hb, size_t want)
{
    size_t stride = hb->nq + 1, xw = fr_hb_extras_width(hb);
    if (want > hb->max_points)
        want = hb->max_points;
    if (forced_made(hb) != FRICREG_OK)
        return fr_fail(hb, FRICREG_ENOMEM, "continue: no memory for %zu points", want);
    struct fr_hb_forced *f = hb->forced;
    if (want <= f->cap && f->qpts_stride == stride && f->xpts_stride == xw)
        return FRICREG_OK;
    if (want < f->cap)
        want = f->cap;
    double *p = realloc(f->pts, want * (1 + hb->n) * sizeof(double));
    if (p != NULL)
        f->pts = p;
    double *q = p == NULL ? NULL : realloc(f->qpts, want * stride * sizeof(double));
    if (q != NULL)
        f->qpts = q;
    double *x = q == NULL ? NULL : realloc(f->xpts, want * xw * sizeof(double));
    if (x != NULL)
        f->xpts = x;
    double *g = x == NULL ? NULL : realloc(f->bifs, want * (4 + hb->n) * sizeof(double));
    if (g == NULL)
        return fr_fail(hb, FRICREG_ENOMEM, "continue: no memory for %zu points", want);
    f->bifs = g;
    f->qpts_stride = stride;
    f->xpts_stride = xw;
    f->cap = want;
    return FRICREG_OK;
}

/* The point at qt (unscaled q, parameter p; the factors, forces fq and Jacobians jq at it, the
 * level in force) stored, with the tangent's parameter component tw and the bordered matrix's
 * determinant sign det; its stability by Hill's method when on (already in xsol when
 * hill_done: fr_hb_solve_at's). Only counted when the branch keeps no points. */
int fr_hb_store_point(fricreg_hb *hb, const char *fn, struct fr_hb_branch *b, double p, double tw,
                      double det, int hill_done)
{
    size_t w = 1 + hb->n, nq = hb->nq, xw = fr_hb_extras_width(hb);
    double omega = fr_hb_branch_omega(b, p);
    b->count++;
    if (!b->keep)
        return FRICREG_OK;
    struct fr_hb_forced *f = hb->forced;
    int status = f->npts < f->cap ? FRICREG_OK : fr_hb_points_reserve(hb, 2 * f->cap);
    if (status != FRICREG_OK)
        return status;
    int stability = fr_hb_stability_on(hb);
    if (stability && !hill_done &&
        (status = fr_hb_stability(hb, fn, omega, fr_hb_stability_record(hb) + 2)))
        return status;
    double *x = f->xpts + f->npts * xw;
    x[0] = tw;
    x[1] = det;
    if (stability)
        memcpy(x + 2, fr_hb_stability_record(hb) + 2, (xw - 2) * sizeof(double));
    f->pts[f->npts * w] = omega;
    fr_hb_rms(hb, f->pts + f->npts * w + 1);
    memcpy(f->qpts + f->npts * (nq + 1), hb->qt, nq * sizeof(double));
    f->qpts[f->npts * (nq + 1) + nq] = p;
    f->npts++;
    memcpy(hb->qsol, hb->qt, nq * sizeof(double));
    hb->omega_sol = omega;
    hb->level_sol = hb->level;
    hb->have_solution = 1;
    return FRICREG_OK;
}
