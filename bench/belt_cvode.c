/* SPDX-License-Identifier: GPL-3.0-or-later */
/* belt_cvode.c — the event-driven CVODE reference of the belt-driven stick-slip oscillator with
 * Stribeck friction (problems_cvode.h; the problem p of src/problems/problems.h), classical
 * set-valued friction with static bound fs:
 *   - stick (x' = V, |f_eq| = |x| <= fs): exact, x = x0 + V (t - t0), until x = fs, the
 *     break-away (x only grows while stuck, so the bound is reached at +fs);
 *   - slip with direction s = sgn(u), u = x' - V the relative velocity: CVODE integrates
 *         x' = u + V,   u' = -x - s k(|u|)
 *     in (x, u), so that the slip starts at u = 0 exactly (u' = -x + fs = 0 there too: u leaves
 *     0 as -V t^2/2, and CVODE keeps the root function inactive until it is nonzero). Two root
 *     functions: g0 = u, the end of the slip (u back to 0), and g1 = u + V = x', an extremum of
 *     x (x_max, x_min of the amplitude). At the end of the slip the stick test: stick if
 *     |x| <= fs, else slip on the other way, s = -sgn(x) (not met with these parameters).
 * The slip from break-away is the same every cycle (it starts at x = fs, u = 0), so every cycle
 * after the first is the limit cycle; the period is the time between two break-aways. */
#include <math.h>
#include <stdio.h>

#include "fricreg.h"

#include "cvode_setup.h"
#include "event_driven.h"
#include "problems_cvode.h"

struct belt_sys {
    const struct prob_belt *p;
    double s; /* slip direction, sgn(x' - V) */
};

/* y = (x, u): the slip dynamics with the direction held. */
static int slip_rhs(cv_real t, N_Vector yv, N_Vector dyv, void *user)
{
    const struct belt_sys *b = user;
    const double *y = N_VGetArrayPointer(yv);
    double *dy = N_VGetArrayPointer(dyv);
    (void)t;
    dy[0] = y[1] + b->p->v_belt;
    dy[1] = -y[0] - b->s * prob_belt_kinetic(b->p, fabs(y[1]));
    return 0;
}

static int slip_roots(cv_real t, N_Vector yv, cv_real *g, void *user)
{
    const struct belt_sys *b = user;
    const double *y = N_VGetArrayPointer(yv);
    (void)t;
    g[0] = y[1];                /* end of slip: u = 0 */
    g[1] = y[1] + b->p->v_belt; /* x' = 0: an extremum of x */
    return 0;
}

/* One slip phase from (t, x) at u = 0 to its end; updates t, x and the extrema. Returns
 * FRICREG_OK or FRICREG_EINTEGRATOR. */
static int slip(struct cv_handle *h, double *t, double *x, double *xmax, double *xmin,
                struct belt_cycle *out, char *msg, size_t msg_len)
{
    double *y = N_VGetArrayPointer(h->y), t_end = *t + 1e3; /* a slip lasts a few units */
    y[0] = *x, y[1] = 0.0;
    CVodeReInit(h->mem, *t, h->y);
    CVodeSetStopTime(h->mem, t_end);
    for (;;) {
        cv_real tr;
        int flag = CVode(h->mem, t_end, h->y, &tr, CV_NORMAL);
        if (flag != CV_ROOT_RETURN) {
            snprintf(msg, msg_len, "belt: CVODE %s at t = %.17g",
                     flag < 0 ? "failed" : "reached the end without the slip ending", (double)tr);
            return FRICREG_EINTEGRATOR;
        }
        int found[2] = {0, 0};
        CVodeGetRootInfo(h->mem, found);
        if (found[1]) { /* x' = 0 */
            *xmax = fmax(*xmax, y[0]);
            *xmin = fmin(*xmin, y[0]);
        }
        if (found[0]) { /* u = 0: the slip ends here */
            out->steps += cv_steps(h->mem);
            *t = tr;
            *x = y[0];
            return FRICREG_OK;
        }
    }
}

int belt_cvode_run(const struct prob_belt *p, int method, double rtol, struct belt_cycle *out,
                   char *msg, size_t msg_len)
{
    struct belt_sys b = {p, -1.0};
    struct cv_handle h;
    *out = (struct belt_cycle){NAN, NAN, 0.0, 0.0};
    if (cv_open(&h, method, 2, slip_rhs, 2, slip_roots, &b, rtol) != 0) {
        snprintf(msg, msg_len, "belt: CVODE set-up failed");
        return FRICREG_ENOMEM;
    }
    double t = 0.0, x = 0.0, last_break = NAN;
    int status = FRICREG_OK;
    for (int c = 0; c < p->cycles && status == FRICREG_OK; c++) {
        t += (p->fs - x) / p->v_belt; /* stick until x = fs, exactly */
        x = p->fs;
        out->period = t - last_break;
        last_break = t;
        double xmax = x, xmin = x;
        b.s = -1.0; /* f_eq = fs > 0 pushes x back: x' - V < 0 */
        for (;;) {
            status = slip(&h, &t, &x, &xmax, &xmin, out, msg, msg_len);
            out->events += 1.0;
            if (status != FRICREG_OK || fabs(x) <= p->fs)
                break;                  /* the stick test */
            b.s = x > 0.0 ? -1.0 : 1.0; /* slips on the other way */
        }
        out->amplitude = 0.5 * (xmax - xmin);
        out->events += 1.0; /* the break-away */
    }
    cv_close(&h);
    return status;
}
