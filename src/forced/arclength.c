/* SPDX-License-Identifier: GPL-3.0-or-later */
/* arclength.c — the continuation loop: from the last point the predictor along the tangent,
 * the corrector (corrector.c), the step accepted or rejected, and the step control after
 * E. L. Allgower and K. Georg, "Numerical Continuation Methods: An Introduction", Springer
 * 1990, Ch. 6 (steplength adaptation by asymptotic estimates): from the corrector's first step
 * δ, its contraction κ = |Δy_2|/|Δy_1|, the angle α between successive tangents, and the
 * corrector's iterations (as NLvib's solve_and_continue, Krack & Gross Ch. 4–5), the next step
 * is ds / f, f = max(κ/κ0, (δ/ds)/δ0, α/α0, its/its0) within [1/2, 2]. A step is rejected (ds
 * halved) when the corrector fails, ends farther than 4 ds from the last point (it jumped
 * along the branch, e.g. across a sharp peak), turns the chord by more than twice the
 * tangent's angle (it joined another part of the branch: the flanks of a sharp peak meet at
 * q = 0 a tiny Ω apart), turns the tangent by more than 20°, or contracts by more than 1/2 in
 * its first steps. The exact AFT's Jacobian is not smooth where an element's stick/slip or
 * contact pattern changes, and there the branch has a kink: the angle and the contraction do
 * not fall with ds. A converged corrector whose tangent turned by less than 90° is accepted
 * there, once halving ds no longer lowered them by a quarter, or when halving would go below
 * ds_min (a converged residual is a solution), as is then one that the jump or the chord
 * refused within NEAR_REACH of the last point (a fold or kink too fine to resolve: the
 * sampled march's, aft_march.c, turns a kink of the exact AFT into a tiny fold where a slider
 * starts to stick). Below ds_min the step is predicted once more
 * along the secant of the last two points before the continuation stops. A branch that runs
 * back along itself (a point near an earlier stretch, heading the same way) stops it: a
 * success onto its first stretches (it came round a closed branch), else a failure. Each
 * point is stored (points.c), and the bifurcations between them located (bifurcations.c). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "solve_at.h"
#include "arclength.h"
#include "bifurcations.h"
#include "points.h"
#include "hb/residual.h"

/* The last step: the point at p1 by Newton at fixed parameter, from the direction's line
 * there; kept as the driver's solution. */
static int final_point(fricreg_hb *hb, const char *fn, const struct fr_hb_branch *b, double p1)
{
    size_t nq = hb->nq;
    const double *dir = fr_hb_vectors(hb).dir;
    double s = (p1 / b->ws - b->yc[nq]) / dir[nq];
    double *guess = hb->rw; /* free here; fr_hb_solve_at copies it before it uses rw */
    for (size_t j = 0; j < nq; j++)
        guess[j] = (b->yc[j] + s * dir[j]) * b->qs;
    if (b->level)
        hb->level = p1;
    int status = fr_hb_solve_at(hb, fn, fr_hb_branch_omega(b, p1), guess, 1);
    if (status == FRICREG_OK)
        memcpy(hb->qt, hb->qw, nq * sizeof(double));
    return status;
}

/* The displacement scale follows the branch up: qs = the largest |q| so far, so that a branch
 * that starts far below a resonance takes steps in proportion to the amplitudes it reaches
 * (the points qw, yo and the tangent converted to the new scale). */
static void rescale(fricreg_hb *hb, struct fr_hb_branch *b)
{
    size_t nq = hb->nq;
    double top = 0.0, *tan = fr_hb_vectors(hb).tan;
    for (size_t j = 0; j < nq; j++)
        top = fmax(top, fabs(hb->qw[j]));
    if (!(top > 1.0))
        return;
    for (size_t j = 0; j < nq; j++) {
        hb->qw[j] /= top;
        b->yo[j] /= top;
        tan[j] /= top;
    }
    double norm = sqrt(fr_hb_dot(tan, tan, nq + 1));
    for (size_t j = 0; j <= nq; j++)
        tan[j] /= norm;
    b->qs *= top;
}

/* The new point y (scaled; yc the last point) runs back along the branch: within a tenth of
 * a step of an earlier stretch [point k − 1, point k], heading the same way (cosine > 1/2),
 * after a way along the branch since that stretch of more than 3 times the straight distance
 * (so not the branch's latest stretches, however it curves). Returns that k, the latest such,
 * or 0 if none. */
static size_t doubles_back(const fricreg_hb *hb, const struct fr_hb_branch *b, const double *y)
{
    size_t nq = hb->nq, ld = nq + 1;
    const struct fr_hb_forced *f = hb->forced;
    double cq = 1.0 / b->qs, cw = 1.0 / b->ws, hs = fr_hb_dist(y, b->yc, ld), arc = hs;
    for (size_t k = f->npts - 1; k >= 1; k--) {
        const double *p0 = f->qpts + (k - 1) * ld, *p1 = f->qpts + k * ld;
        double ll = 0.0, along = 0.0, same = 0.0, d0 = 0.0;
        for (size_t j = 0; j < ld; j++) {
            double c = j < nq ? cq : cw, e = (p1[j] - p0[j]) * c, r = y[j] - p0[j] * c;
            ll += e * e;
            along += e * r;
            same += e * (y[j] - b->yc[j]);
            d0 += r * r;
        }
        ll = sqrt(ll);
        arc += ll;
        if (!(ll > 0.0) || same <= 0.5 * ll * hs || arc <= 3.0 * (sqrt(d0) + ll))
            continue;
        double s = fmin(fmax(along / (ll * ll), 0.0), 1.0), d = 0.0;
        for (size_t j = 0; j < ld; j++) {
            double c = j < nq ? cq : cw, e = y[j] - (p0[j] + s * (p1[j] - p0[j])) * c;
            d += e * e;
        }
        if (sqrt(d) <= 0.1 * fmax(ll, hs))
            return k;
    }
    return 0;
}

/* CRAWL_STEPS accepted steps in a row within CRAWL_DS ds_min are a crawl (a corrector that
 * converges only close to the last point, kink after kink of a sampled AFT: an interface
 * ROM's contacts turning to a periodic slip took thousands of such steps, then ds_min), which
 * a branch wanted for its end alone (end_only: the start's) gives up for the start's next
 * route. The starts of the tests that reach their end take none such. */
#define CRAWL_DS 100.0
#define CRAWL_STEPS 50

/* A branch that runs back onto its first stretches has come round to where it began: nothing
 * on it precedes the first point, so it is a closed curve (an isola, or a loop of a branch
 * whose start lay on it), not a jump from one part of an open branch onto another. */
#define CLOSED_STRETCHES 2

/* One step's outcome from yc with ds along dir: 0 accepted (qw the point, tn its tangent,
 * *alpha the angle between the tangents), 1 rejected (the message in b->why), or a status
 * that ends the continuation (FRICREG_ENOMEM). *sev is the converged corrector's severity,
 * max(κ/KAPPA_MAX, α/ALPHA_MAX) (above 1: rejected, unless a kink), 0 if it failed or left
 * the branch; sev_before the last rejected attempt's from the same point at twice the step. */
static int attempt(fricreg_hb *hb, const char *fn, struct fr_hb_branch *b, double ds, int *its,
                   double *alpha, double *sev, double sev_before, int *kink, int *near)
{
    size_t nq = hb->nq, ld = nq + 1;
    struct fr_hb_vectors v = fr_hb_vectors(hb);
    for (size_t j = 0; j < ld; j++)
        b->yp[j] = b->yc[j] + ds * v.dir[j];
    *alpha = *sev = 0.0;
    *kink = *near = 0;
    int status = fr_hb_corrector(hb, fn, b, b->yp, b->yp, v.dir, its);
    if (status == FRICREG_OK)
        status = fr_hb_tangent(hb, fn, v.tn);
    if (status == FRICREG_ENOMEM || hb->stopped)
        return status;
    if (status != FRICREG_OK) {
        snprintf(b->why, sizeof b->why, "%s", hb->err.msg);
        return -1;
    }
    double h = fr_hb_dist(hb->qw, b->yc, ld), deg = 57.29577951308232;
    *alpha = acos(fmax(-1.0, fmin(1.0, fr_hb_dot(v.tn, v.tan, ld))));
    /* on a smooth arc the chord lies half way between the tangents, at a kink between them:
     * a chord that turned by much more than the tangents did joined another part of the
     * branch (two flanks of a sharp peak, nearly parallel, a tiny Ω apart) */
    double chord = acos(
        fmax(-1.0, fmin(1.0, (fr_hb_dot(hb->qw, v.tan, ld) - fr_hb_dot(b->yc, v.tan, ld)) / h)));
    /* this close to the last point, the branch is finer than the continuation resolves */
    *near = h <= NEAR_REACH && chord < KINK_MAX;
    if (h > JUMP * ds) {
        snprintf(b->why, sizeof b->why,
                 "%s: the corrector ended %g from the last point, beyond %g ds = %g", fn, h, JUMP,
                 JUMP * ds);
        return -1;
    }
    if (chord > 2.0 * *alpha + CHORD_SLACK) {
        snprintf(b->why, sizeof b->why,
                 "%s: the chord turned by %.3g degrees from the tangent, which turned by %.3g", fn,
                 chord * deg, *alpha * deg);
        return -1;
    }
    /* a slow corrector (its first steps contract by more than KAPPA_MAX: the predictor was
     * far from where Newton converges fast, or it converged to another part of the branch)
     * or a tangent turned by more than ALPHA_MAX: the step was too long for the branch's
     * curvature. On a smooth branch both fall in proportion to ds; if they did not fall by a
     * quarter when ds was halved, this is a kink of the branch: accepted. */
    *sev = fmax(*alpha / ALPHA_MAX, b->kappa / KAPPA_MAX);
    if (*sev <= 1.0)
        return 0;
    if (sev_before > 0.0 && *sev >= 0.75 * sev_before && *alpha < KINK_MAX) {
        *kink = 1;
        return 0;
    }
    if (*alpha > ALPHA_MAX)
        snprintf(b->why, sizeof b->why, "%s: the tangent turned by %.3g degrees, beyond %.3g", fn,
                 *alpha * deg, ALPHA_MAX * deg);
    else
        snprintf(b->why, sizeof b->why,
                 "%s: the corrector's first steps contracted by %.3g, beyond %.3g", fn, b->kappa,
                 KAPPA_MAX);
    return -1;
}

static int follow(fricreg_hb *hb, const char *fn, struct fr_hb_branch *b, double p1)
{
    size_t nq = hb->nq, ld = nq + 1;
    struct fr_hb_vectors v = fr_hb_vectors(hb);
    struct fr_hb_forced *f = hb->forced; /* the store, when b keeps its points */
    double ds = hb->ds0, dir = p1 > b->yc[nq] * b->ws ? 1.0 : -1.0;
    /* the first tangent, bordered by the direction of p1 */
    memset(v.dir, 0, ld * sizeof(double));
    v.dir[nq] = dir;
    int status = fr_hb_bordered(hb, fn, b, b->yc, v.dir);
    if (status == FRICREG_OK)
        status = fr_hb_tangent(hb, fn, v.tan);
    if (status != FRICREG_OK)
        return status;
    if (b->keep) { /* the first point's tangent and determinant */
        f->xpts[0] = v.tan[nq];
        f->xpts[1] = fr_hb_det_sign(hb, ld);
    }
    int crawling = 0; /* accepted steps in a row below CRAWL_DS ds_min */
    for (;;) {
        if (b->count >= hb->max_points)
            return fr_fail(hb, FRICREG_EWORK, "%s: %zu points stored before %s1 = %g", fn, b->count,
                           b->par, p1);
        /* the step from yc: along the tangent, halved on rejection; below ds_min once more
         * along the secant of the last two points (the tangent of a non-smooth Jacobian may
         * point off the branch), from the last accepted step */
        int its = 0, kink = 0, near = 0, secant = 0, accepted = 0, last = 0;
        double alpha = 0.0, sev = 0.0, sev_before = 0.0, ds_start = ds;
        memcpy(v.dir, v.tan, ld * sizeof(double));
        while (!accepted) {
            for (size_t j = 0; j <= nq; j++)
                b->yp[j] = b->yc[j] + ds * v.dir[j];
            last = dir * (b->yp[nq] * b->ws - p1) >= 0.0;
            if (last) {
                status = final_point(hb, fn, b, p1);
                if (status == FRICREG_OK)
                    break;
                if (status == FRICREG_ENOMEM || hb->stopped)
                    return status;
                snprintf(b->why, sizeof b->why, "%s", hb->err.msg);
                last = 0;
            } else {
                int r = attempt(hb, fn, b, ds, &its, &alpha, &sev, sev_before, &kink, &near);
                if (r > 0)
                    return r;
                if (r == 0) {
                    accepted = 1;
                    break;
                }
                sev_before = sev; /* 0 unless the corrector converged near the branch */
            }
            /* a converged corrector near the last point whose tangent turned (but not
             * back), or one within NEAR_REACH that the chord or the jump refused (a
             * fold or kink too fine to resolve: the march's near the onset of stick,
             * aft_march.c), is a solution: accepted rather than the step halved below
             * ds_min */
            if ((sev > 0.0 || near) && alpha < KINK_MAX && 0.5 * ds < hb->ds_min) {
                kink = accepted = 1;
                break;
            }
            ds *= 0.5;
            if (ds >= hb->ds_min)
                continue;
            if (secant || !b->have_prev)
                return fr_fail(hb, FRICREG_EINTEGRATOR,
                               "%s: the step fell below ds_min = %g at %s = %g (last failure: %s)",
                               fn, hb->ds_min, b->par, b->yc[nq] * b->ws, b->why);
            secant = 1;
            double h = fr_hb_dist(b->yc, b->yo, ld);
            for (size_t j = 0; j < ld; j++)
                v.dir[j] = (b->yc[j] - b->yo[j]) / h;
            ds = ds_start;
            sev_before = 0.0;
        }
        if (last) /* the direction's sign and the last determinant's sign carried on */
            return fr_hb_store_point(hb, fn, b, p1, v.dir[nq],
                                     b->keep ? f->xpts[(f->npts - 1) * f->xpts_stride + 1] : 0.0,
                                     1);
        crawling = ds < CRAWL_DS * hb->ds_min ? crawling + 1 : 0;
        if (b->end_only && crawling >= CRAWL_STEPS)
            return fr_fail(hb, FRICREG_EWORK,
                           "%s: the branch crawls at %s = %g (%d steps in a row below %g ds_min)",
                           fn, b->par, hb->qw[nq] * b->ws, crawling, CRAWL_DS);
        size_t onto = b->keep ? doubles_back(hb, b, hb->qw) : 0;
        if (onto > 0 && onto <= CLOSED_STRETCHES)
            return FRICREG_OK; /* once round: the points stored are the whole branch */
        if (onto > 0)
            return fr_fail(hb, FRICREG_EWORK,
                           "%s: the branch doubles back on itself at %s = %g (after %zu "
                           "points): it would not reach %s1 = %g",
                           fn, b->par, hb->qw[nq] * b->ws, f->npts, b->par, p1);
        /* fr_hb_bordered() left qt, the factors, the forces and the level at qw */
        status = fr_hb_store_point(hb, fn, b, hb->qw[nq] * b->ws, v.tn[nq], fr_hb_det_sign(hb, ld),
                                   0);
        if (status != FRICREG_OK)
            return status;
        memcpy(b->yo, b->yc, ld * sizeof(double));
        b->have_prev = 1;
        memcpy(v.tan, v.tn, ld * sizeof(double));
        rescale(hb, b);
        memcpy(b->yc, hb->qw, ld * sizeof(double));
        /* the next step: Allgower & Georg's factor on the corrector and the angle */
        ds = fr_hb_next_step(hb, ds, b->kappa, b->delta, kink ? 0.0 : alpha, its);
    }
}

/* The branch of b's parameter from p0 to p1 (b's kind, Ω and keep set), its first point solved
 * from q0 (NULL: fr_hb_solve_at's guesses); with keep the points stored (the earlier ones
 * dropped) and the bifurcations between them located. The scales: qs the first point's
 * displacement scale (raised along the branch), ws = |p1 − p0|. */
int fr_hb_arclength(fricreg_hb *hb, const char *fn, struct fr_hb_branch *b, double p0, double p1,
                    const double *q0)
{
    size_t nq = hb->nq;
    /* the first 64 points' room before anything changes: a failure here changes nothing */
    int status = b->keep ? fr_hb_points_reserve(hb, 64) : FRICREG_OK;
    if (status != FRICREG_OK)
        return status;
    struct fr_hb_forced *f = hb->forced;
    if (b->keep) { /* a new branch: on the model and with the extras in force now */
        f->npts = 0;
        f->nbif = 0;
        f->model_serial = hb->model_serial;
        f->extras_serial = hb->extras_serial;
        f->branch_level = b->level;
    }
    if (b->level)
        hb->level = p0;
    if ((status = fr_hb_solve_at(hb, fn, fr_hb_branch_omega(b, p0), q0, b->keep)) != FRICREG_OK)
        return status;
    b->ws = fabs(p1 - p0);
    struct fr_hb_vectors v = fr_hb_vectors(hb);
    b->yc = v.yp;
    b->yp = v.yp + nq + 1;
    b->yo = v.yo;
    b->qs = fr_hb_scale(hb, hb->qw);
    memcpy(hb->qt, hb->qw, nq * sizeof(double));
    if ((status = fr_hb_store_point(hb, fn, b, p0, 0.0, 0.0, 1)) != FRICREG_OK)
        return status;
    for (size_t j = 0; j < nq; j++)
        b->yc[j] = hb->qw[j] / b->qs;
    b->yc[nq] = p0 / b->ws;
    struct fr_error before = hb->err; /* a success keeps it: the halved steps' failures are not
                                         the call's */
    status = follow(hb, fn, b, p1);
    if (b->keep) {
        f->branch_qs = b->qs;
        f->branch_ws = b->ws;
        struct fr_error after = hb->err; /* the bisections' failed trials are not the call's */
        fr_hb_locate_bifurcations(hb, b);
        hb->err = after;
    }
    if (status == FRICREG_OK)
        hb->err = before;
    return status;
}
