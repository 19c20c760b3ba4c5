/* SPDX-License-Identifier: GPL-3.0-or-later */
/* start.c — the start without a guess of fricreg_hb_solve and fricreg_hb_continue: the
 * solution at Ω followed in the excitation level from the linear regime (where the stuck guess
 * holds) up to λ = 1, or the plain guesses, or a branch in Ω from a nearby frequency (with
 * stability on, the first of them whose solution is not unstable). Its own
 * file because it is a client of the continuation loop (arclength.c), not a part of it: its
 * continuations store no points. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "solve_at.h"
#include "arclength.h"
#include "start.h"
#include "hb/dynamic.h"
#include "hb/residual.h"
#include "floquet/stability_method.h"

/* The excitation level where fricreg_hb_solve's start begins: small enough for every element
 * to stay in the regime of the stuck guess (a Jenkins element slips once kt |q| > mu N, its
 * q proportional to λ there), not so small that the first point's tolerance, relative to
 * the response, reaches rounding. */
#define LEVEL_START 1e-3

/* Whether the old start's solution q1 at λ = 1 lies on the branch from the linear regime:
 * with q0 the solution at λ = 0 (every element in its regime of no load: stuck, or closed
 * under a preload, or open across a gap), the line q0 + λ (q1 − q0) solves (R) at λ = 1e-3 to
 * Newton's tolerance, so the elements are in that same regime at both ends; a regime is a set
 * of linear inequalities in λ along the line (|kt (u − w)| <= mu N for some w, N0 + kn g >= 0
 * or <= 0), so it holds between them, and the line is the branch. Scratch: tan, tn. */
static int on_linear_branch(fricreg_hb *hb, const char *fn, double omega, int *yes)
{
    size_t nq = hb->nq;
    struct fr_hb_vectors v = fr_hb_vectors(hb);
    double *q0 = v.tan, *q1 = v.tn, s0, s1;
    *yes = 0;
    hb->level = 0.0;
    int status = fr_hb_solve_at(hb, fn, omega, NULL, 0);
    if (status != FRICREG_OK)
        return status;
    memcpy(q0, hb->qw, nq * sizeof(double));
    s0 = fr_hb_scale(hb, q0);
    hb->level = 1.0;
    if ((status = fr_hb_solve_at(hb, fn, omega, NULL, 0)) != FRICREG_OK)
        return status;
    memcpy(q1, hb->qw, nq * sizeof(double));
    s1 = fr_hb_scale(hb, q1);
    hb->level = LEVEL_START;
    for (size_t j = 0; j < nq; j++)
        hb->qt[j] = q0[j] + LEVEL_START * (q1[j] - q0[j]);
    if ((status = fr_hb_residual(hb, fn, hb->qt, hb->R, 0)) != FRICREG_OK)
        return status;
    /* (R) there is (1 − λ) R(q0) + λ R(q1) when the forces are affine along the line */
    double r = 0.0, bound = hb->tol *
                            ((1.0 - LEVEL_START) * s0 + LEVEL_START * s1 + fr_hb_scale(hb, hb->qt));
    for (size_t j = 0; j < nq; j++)
        r = fmax(r, fabs(hb->R[j]));
    *yes = r <= bound;
    return FRICREG_OK;
}

/* The branch in the excitation level at omega from the linear regime to λ = 1, the solution
 * kept as fr_hb_solve_at's (fricreg_hb_solve's docstring). */
static int level_start(fricreg_hb *hb, const char *fn, double omega)
{
    /* the old start, when its solution is the branch's: its Newton once more to keep it */
    int linear = 0, status = on_linear_branch(hb, fn, omega, &linear);
    hb->level = 1.0;
    if (status == FRICREG_OK && linear)
        return fr_hb_solve_at(hb, fn, omega, fr_hb_vectors(hb).tn, 1);
    if (status == FRICREG_ENOMEM || hb->stopped)
        return status;
    /* its end alone is wanted: where it crawls, the plain guesses at λ = 1 answer */
    struct fr_hb_branch b = {.level = 1, .omega = omega, .par = "level", .end_only = 1};
    status = fr_hb_arclength(hb, fn, &b, LEVEL_START, 1.0, NULL);
    hb->level = 1.0;
    return status;
}

/* The nearby frequencies of the frequency start, omega (1 + d) then omega / (1 + d) for each
 * d, nearest first: far enough apart that a resonance's width (ζ of a few per cent) is left. */
static const double START_OFFSETS[] = {0.05, 0.1, 0.2, 0.4, 0.8};
#define START_TRIALS (2 * sizeof START_OFFSETS / sizeof START_OFFSETS[0])

/* The branch in Ω to omega from the nearest frequency of START_OFFSETS where the plain guesses
 * converge: for a response homogeneous in the forcing (a unilateral spring without gap or
 * preload) the level's branch is a ray, its every point as hard to reach as its end. One
 * continuation at most, its points not stored. */
static int frequency_start(fricreg_hb *hb, const char *fn, double omega)
{
    int status = FRICREG_EWORK;
    for (size_t i = 0; i < START_TRIALS; i++) {
        double d = START_OFFSETS[i / 2], from = i % 2 ? omega / (1.0 + d) : omega * (1.0 + d);
        status = fr_hb_solve_at(hb, fn, from, NULL, 0);
        if (status == FRICREG_ENOMEM || hb->stopped)
            return status;
        if (status == FRICREG_OK) {
            struct fr_hb_branch b = {.par = "Omega"};
            return fr_hb_arclength(hb, fn, &b, from, omega, NULL);
        }
    }
    return status;
}

/* The start's routes, in the order tried: the level's branch, the plain guesses, the branch
 * in Ω from a nearby frequency; each keeps its solution as fr_hb_solve_at's. */
static int plain_start(fricreg_hb *hb, const char *fn, double omega)
{
    return fr_hb_solve_at(hb, fn, omega, NULL, 1);
}

typedef int (*start_route)(fricreg_hb *hb, const char *fn, double omega);
static const start_route START_ROUTES[] = {level_start, plain_start, frequency_start};
#define START_ROUTE_COUNT (sizeof START_ROUTES / sizeof START_ROUTES[0])

/* Whether the kept solution is unstable by the stability in force (none: not unstable). */
static int kept_unstable(const fricreg_hb *hb)
{
    return fr_hb_stability_on(hb) && fr_hb_stability_record(hb)[2] == 0.0;
}

/* The routes in turn until one reaches a solution that is not unstable: a route can land on
 * another branch at omega than the one the others and a sweep follow (a closed branch,
 * unstable there, that a continuation would go round), so an unstable solution is held (the
 * first, in q_held) while the later routes are tried; none stable: the held one, solved once
 * more to be kept. On failure of all, the plain guesses' error. A singular D_h at omega fails
 * first. */
int fr_hb_default_start(fricreg_hb *hb, const char *fn, double omega)
{
    size_t nq = hb->nq;
    double *q_held = NULL;
    struct fr_error plain = hb->err;
    /* every route ends in a solve at omega: a singular D_h there fails now, not after a
     * frequency route has crept up on an undamped resonance */
    int status = fr_hb_factor(hb, fn, omega, 0), plain_status = FRICREG_EWORK;
    if (status == FRICREG_ESINGULAR || status == FRICREG_ENONFINITE)
        return status;
    for (size_t r = 0; r < START_ROUTE_COUNT; r++) {
        status = START_ROUTES[r](hb, fn, omega);
        if (status == FRICREG_ENOMEM || hb->stopped)
            break;
        if (START_ROUTES[r] == plain_start && status != FRICREG_OK) {
            plain = hb->err; /* the failure reported should all fail */
            plain_status = status;
        }
        if (status != FRICREG_OK)
            continue;
        if (!kept_unstable(hb))
            break;
        if (q_held == NULL) { /* the first unstable solution, kept should no route be stable */
            if ((q_held = malloc(nq * sizeof(double))) == NULL) {
                status = fr_fail(hb, FRICREG_ENOMEM, "%s: out of memory", fn);
                break;
            }
            memcpy(q_held, hb->qsol, nq * sizeof(double));
        }
        status = FRICREG_EWORK; /* not this one: the next route */
    }
    if (status != FRICREG_OK && status != FRICREG_ENOMEM && !hb->stopped) {
        if (q_held != NULL) {
            hb->level = 1.0;
            status = fr_hb_solve_at(hb, fn, omega, q_held, 1);
        } else {
            hb->err = plain;
            status = plain_status;
        }
    }
    free(q_held);
    return status;
}
