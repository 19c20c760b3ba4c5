/* SPDX-License-Identifier: GPL-3.0-or-later */
/* disk_cvode.c — the event-driven CVODE reference of the 2-D oscillator with rotating forcing
 * (problems_cvode.h; the problem p of src/problems/problems.h), classical isotropic Coulomb
 * friction with mun = 1 (the disk |f| <= 1):
 *     x'' = -x + F(t) + f,   F(t) = a sin(omega t) (cos(Omega t), sin(Omega t)),
 *     f_eq(t) = x - F(t),    y = (x[2], v[2], E), E' = -f . v = |v| (the dissipated energy).
 * Two modes:
 *   - stick: v = 0 and x fixed (f = f_eq), while |f_eq(t)| <= 1; root g = 1 - |f_eq(t)|, which
 *     depends on t alone (CVODE's steps there are capped at 0.5, a quarter of the forcing's
 *     timescale 1/omega, so that no excursion of |f_eq| past 1 is stepped over);
 *   - slip: v' = -x + F(t) - e, e the sliding direction (see direction() for its three
 *     cases). The slip ends when the body stops, |v| -> 0, which |v| cannot signal: it does
 *     not change sign. The root function is g = v . e_ref, e_ref the direction of v at the
 *     last accepted step (CVODE in one-step mode, e_ref refreshed after every step): v stays
 *     within 90 degrees of e_ref while it slows down (near the stop its direction converges to
 *     that of -f_eq), and g changes sign at the stop; beyond it the force keeps its direction,
 *     so that the integrand is smooth through the stop and the root on CVODE's interpolant is
 *     as accurate as a step. Near v = 0 (a band |v| <= v_small = rtol^(2/3), at the break-away
 *     and at the stop) the direction of v relaxes to that of -f_eq at the rate |f_eq|/|v|,
 *     stiff, and CVODE's v there is mostly its absolute error: e = -f_eq/|f_eq| in the band
 *     (the direction the exact motion relaxes to; the O(|v|) lag it omits costs
 *     O(v_small^(3/2)) = O(rtol) per event), and g cannot fire before v has left the band
 *     unless |f_eq| < 1 (the body slows down). Without the band, v's noise passed for stops
 *     right after each break-away (event cascades at rtol <= 1e-8); holding e = e_ref in a
 *     band of 10 atol made the RHS chatter at its edge (millions of steps); with this one the
 *     count of events is the same (111) at every rtol from 1e-4 to 1e-12, and Adams and BDF
 *     agree to 2e-11 at 1e-12.
 *     At the stop: v := 0, stick if |f_eq| <= 1, else slip again in direction -f_eq/|f_eq|.
 * Every event restarts CVODE (CVodeReInit). D per forcing cycle = the change of E over the turn
 * after turns_transient turns, divided by cycles_per_turn, with the turn boundaries hit exactly
 * (CVODE's stop time). */
#include <math.h>
#include <stdio.h>

#include "fricreg.h"

#include "cvode_setup.h"
#include "event_driven.h"
#include "problems_cvode.h"

#define MAX_BURST 1000 /* events without progress in time before a run is declared stuck */

struct disk_sys {
    const struct prob_disk *p;
    int slipping;
    double e_ref[2]; /* slip: the direction at the last accepted step with |v| > v_small */
    double v_small;  /* rtol^(2/3): the slow-manifold band about v = 0 (see direction) */
    int launched;    /* slip: an accepted step has had |v| > v_small since the break-away */
};

/* |f_eq(t)| at position x. */
static double feq_norm(const struct prob_disk *p, double t, const double x[2], double feq[2])
{
    double F[2];
    prob_disk_forcing(p, t, F);
    feq[0] = x[0] - F[0];
    feq[1] = x[1] - F[1];
    return hypot(feq[0], feq[1]);
}

/* The sliding direction e (the friction force is -e) at state y, time t:
 *   - |v| <= v_small and not past the stop: e = -f_eq/|f_eq|. Near v = 0 the direction of v
 *     relaxes to that of the net applied force -f_eq at the rate |f_eq|/|v| (v' = -f_eq - e),
 *     so this is where the exact motion's direction is, to O(|v|), at a break-away and at a
 *     stop alike; and below v_small the direction of CVODE's v is its absolute error;
 *   - launched and v . e_ref <= 0, past the stop: e = e_ref, held, so that the integrand is
 *     smooth through the stop and CVODE's step over it as accurate as any;
 *   - otherwise e = v/|v|. */
static void direction(const struct disk_sys *d, double t, const double y[5], double e[2])
{
    double feq[2], n = feq_norm(d->p, t, y, feq), speed = hypot(y[2], y[3]);
    double along = y[2] * d->e_ref[0] + y[3] * d->e_ref[1];
    if (d->launched && along <= 0.0)
        e[0] = d->e_ref[0], e[1] = d->e_ref[1];
    else if (speed <= d->v_small)
        e[0] = -feq[0] / n, e[1] = -feq[1] / n;
    else
        e[0] = y[2] / speed, e[1] = y[3] / speed;
}

static int rhs(cv_real t, N_Vector yv, N_Vector dyv, void *user)
{
    const struct disk_sys *d = user;
    const double *y = N_VGetArrayPointer(yv);
    double *dy = N_VGetArrayPointer(dyv);
    for (int i = 0; i < 5; i++)
        dy[i] = 0.0;
    if (!d->slipping)
        return 0;
    double F[2], e[2];
    prob_disk_forcing(d->p, t, F);
    direction(d, t, y, e);
    dy[0] = y[2];
    dy[1] = y[3];
    dy[2] = -y[0] + F[0] - e[0];
    dy[3] = -y[1] + F[1] - e[1];
    dy[4] = e[0] * y[2] + e[1] * y[3]; /* -f . v = |v| before the stop */
    return 0;
}

/* Stuck: g = 1 - |f_eq|. Slipping: g = v . e_ref once launched; before (|v| has not yet
 * exceeded v_small at an accepted step), v's direction is noise, so g = v . e with e the
 * direction above while the body decelerates (|f_eq| < 1), else 1: it cannot stop while it
 * speeds up, and the jump between 1 and a positive v . e is no sign change. */
static int roots(cv_real t, N_Vector yv, cv_real *g, void *user)
{
    const struct disk_sys *d = user;
    const double *y = N_VGetArrayPointer(yv);
    double feq[2], n = feq_norm(d->p, t, y, feq), e[2];
    if (!d->slipping)
        g[0] = 1.0 - n;
    else if (d->launched)
        g[0] = y[2] * d->e_ref[0] + y[3] * d->e_ref[1];
    else if (n < 1.0)
        direction(d, t, y, e), g[0] = y[2] * e[0] + y[3] * e[1];
    else
        g[0] = 1.0;
    return 0;
}

/* The mode at rest at time t: stuck if |f_eq| <= 1 (unless break_away: the stuck root found
 * |f_eq| = 1, to the root's tolerance), else slipping along -f_eq/|f_eq|. */
static void set_mode_at_rest(struct disk_sys *d, double t, double y[5], int break_away)
{
    double feq[2], n = feq_norm(d->p, t, y, feq);
    y[2] = y[3] = 0.0;
    d->launched = 0;
    d->slipping = break_away || n > 1.0;
    if (d->slipping)
        d->e_ref[0] = -feq[0] / n, d->e_ref[1] = -feq[1] / n;
}

/* Restarts CVODE at t in the current mode; stuck steps are capped (see the top). */
static void restart(struct cv_handle *h, const struct disk_sys *d, double t)
{
    CVodeReInit(h->mem, t, h->y);
    CVodeSetMaxStep(h->mem, d->slipping ? 0.0 : 0.5);
}

int disk_cvode_run(const struct prob_disk *p, int method, double rtol, struct disk_result *out,
                   char *msg, size_t msg_len)
{
    struct disk_sys d = {p, 0, {1.0, 0.0}, pow(rtol, 2.0 / 3.0), 0};
    struct cv_handle h;
    *out = (struct disk_result){NAN, 0.0, 0.0};
    if (cv_open(&h, method, 5, rhs, 1, roots, &d, rtol) != 0) {
        snprintf(msg, msg_len, "disk: CVODE set-up failed");
        return FRICREG_ENOMEM;
    }
    double *y = N_VGetArrayPointer(h.y), turn = prob_disk_turn(p);
    double E_start = 0.0, t_burst = 0.0;
    long burst = 0;
    cv_real t = 0.0;
    int status = FRICREG_OK;
    set_mode_at_rest(&d, 0.0, y, 0); /* from rest at the origin */
    restart(&h, &d, 0.0);
    for (int k = 1; k <= p->turns_transient + 1 && status == FRICREG_OK; k++) {
        double boundary = k * turn;
        CVodeSetStopTime(h.mem, boundary);
        while (t < boundary) {
            int flag = CVode(h.mem, boundary, h.y, &t, CV_ONE_STEP);
            if (flag < 0) {
                snprintf(msg, msg_len, "disk: CVODE failed (%d) at t = %.17g", flag, (double)t);
                status = FRICREG_EINTEGRATOR;
                break;
            }
            if (flag == CV_ROOT_RETURN) {
                burst = t - t_burst < 1e-9 * (1.0 + t) ? burst + 1 : 0;
                t_burst = burst ? t_burst : t;
                if (burst > MAX_BURST) {
                    snprintf(msg, msg_len, "disk: event cascade near t = %.17g", t_burst);
                    status = FRICREG_EINTEGRATOR;
                    break;
                }
                out->steps += cv_steps(h.mem);
                out->events += 1.0;
                /* slipping: the body stopped; stuck: |f_eq| reached the bound */
                set_mode_at_rest(&d, t, y, !d.slipping);
                restart(&h, &d, t);
                CVodeSetStopTime(h.mem, boundary);
            } else if (d.slipping) { /* an accepted step: refresh the reference direction */
                double speed = hypot(y[2], y[3]);
                if (speed > d.v_small && y[2] * d.e_ref[0] + y[3] * d.e_ref[1] > 0.0) {
                    d.e_ref[0] = y[2] / speed, d.e_ref[1] = y[3] / speed;
                    d.launched = 1;
                }
            }
        }
        if (k == p->turns_transient)
            E_start = y[4];
    }
    out->steps += cv_steps(h.mem);
    if (status == FRICREG_OK)
        out->dissipation = (y[4] - E_start) / p->cycles_per_turn;
    cv_close(&h);
    return status;
}
