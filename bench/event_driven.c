/* SPDX-License-Identifier: GPL-3.0-or-later */
/* event_driven.c — classical Coulomb friction, event-driven, on SUNDIALS CVODE: the baseline a
 * user picks instead of regularizing.
 *
 * The systems with uncoupled contacts of unit mobility (W = I): every body i has one contact
 * with relative velocity v_i and u_i'' = a_free,i(t, u) + f_i, f_eq,i = -a_free,i:
 *   oscillator, Eq. (5):  a_free = -x + a sin(omega t), mun = 1, D weight 1;
 *   chain, Sec. 3.2:      a_free = -n^2 K u + n G(t) e_1, mun_i = 1, D weight 1/n.
 * Each contact is in one mode: slipping with direction s_i = +1 or -1 (f_i = -s_i mun_i), or
 * stuck (v_i = 0, f_i = f_eq,i, hence u_i'' = 0). Between events CVODE integrates the smooth
 * ODE of the current modes; its root finding watches one switching function per contact:
 *   slipping: g_i = v_i                     (the contact comes to rest),
 *   stuck:    g_i = mun_i - |f_eq,i|        (the force balance reaches the friction bound).
 * At a root: a slipping contact stops (v_i := 0) and sticks if |f_eq,i| <= mun_i, else
 * reverses, s_i = -sgn(f_eq,i); a stuck contact starts to slip in direction -sgn(f_eq,i).
 * Then CVodeReInit restarts the integrator (order 1) from the event. The contacts are
 * uncoupled (f_eq,i depends on the configuration only, not on the other modes), so each event
 * is decided alone: no complementarity problem. The dissipation D is integrated as one more
 * state, D' = weight * sum over slipping contacts of s_i mun_i v_i. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_config.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include "event_driven.h"

#if SUNDIALS_VERSION_MAJOR >= 7
typedef sunrealtype ed_real;
#define ED_COMM_NULL SUN_COMM_NULL
#else
typedef realtype ed_real;
#define ED_COMM_NULL NULL
#endif

#define MAX_BURST 1000 /* events with no progress in time before a run is declared stuck */

/* The system of one run: sizes, parameters, the contacts' modes, scratch. */
struct ed_sys {
    size_t n;  /* bodies = contacts */
    int chain; /* 1 chain, 0 oscillator */
    double a, omega, weight;
    double period; /* the forcing period, as the library reports it */
    int *mode;     /* +1 / -1 slipping with that direction, 0 stuck */
    double *a_free;
};

/* Free accelerations a_free(t, u) (friction excluded), as in src/sim/systems/{oscillator,chain}.c. */
static void free_acc(const struct ed_sys *s, double t, const double u[], double af[])
{
    double G = s->a * sin(s->omega * t);
    size_t n = s->n;
    if (!s->chain) {
        af[0] = -u[0] + G;
        return;
    }
    double n2 = (double)n * (double)n;
    af[0] = -n2 * (u[0] - u[1]) + (double)n * G;
    for (size_t i = 1; i + 1 < n; i++)
        af[i] = -n2 * (-u[i - 1] + 2.0 * u[i] - u[i + 1]);
    af[n - 1] = -n2 * (-u[n - 2] + 2.0 * u[n - 1]);
}

/* y = (u[n], v[n], D). A stuck contact has u' = v' = 0; a slipping one f = -s mun (mun = 1). */
static int rhs(ed_real t, N_Vector yv, N_Vector ydotv, void *user)
{
    struct ed_sys *s = user;
    const double *y = N_VGetArrayPointer(yv);
    double *dy = N_VGetArrayPointer(ydotv);
    size_t n = s->n;
    free_acc(s, t, y, s->a_free);
    double power = 0.0;
    for (size_t i = 0; i < n; i++) {
        double sgn = (double)s->mode[i], v = y[n + i];
        dy[i] = s->mode[i] ? v : 0.0;
        dy[n + i] = s->mode[i] ? s->a_free[i] - sgn : 0.0;
        power += sgn * v;
    }
    dy[2 * n] = s->weight * power;
    return 0;
}

/* One switching function per contact (see the top of the file). */
static int roots(ed_real t, N_Vector yv, ed_real *g, void *user)
{
    struct ed_sys *s = user;
    const double *y = N_VGetArrayPointer(yv);
    free_acc(s, t, y, s->a_free);
    for (size_t i = 0; i < s->n; i++)
        g[i] = s->mode[i] ? y[s->n + i] : 1.0 - fabs(s->a_free[i]); /* f_eq = -a_free */
    return 0;
}

/* The mode of a contact at rest (v = 0): stuck if the force balance holds within the bound,
 * else slipping in the direction of -f_eq. */
static int mode_at_rest(double a_free)
{
    double f_eq = -a_free;
    if (fabs(f_eq) <= 1.0)
        return 0;
    return f_eq > 0.0 ? -1 : 1;
}

/* Switch the modes of the contacts whose roots were found at time t, state y. Returns the
 * number of switches. */
static int switch_modes(struct ed_sys *s, double t, double y[], const int found[])
{
    int switches = 0;
    free_acc(s, t, y, s->a_free);
    for (size_t i = 0; i < s->n; i++) {
        if (!found[i])
            continue;
        if (s->mode[i]) { /* slipping contact came to rest: stick or reverse */
            y[s->n + i] = 0.0;
            s->mode[i] = mode_at_rest(s->a_free[i]);
        } else { /* stuck contact reached the bound: slip against f_eq */
            s->mode[i] = -s->a_free[i] > 0.0 ? -1 : 1;
        }
        switches++;
    }
    return switches;
}

/* CVODE's error messages would go to stderr; keep the last one for the report instead. */
static char last_error[200];
#if SUNDIALS_VERSION_MAJOR < 7
static void quiet_handler(int code, const char *module, const char *function, char *msg, void *user)
{
    (void)user;
    snprintf(last_error, sizeof last_error, "%s %s (%d): %s", module, function, code, msg);
}
#endif

/* CVODE's counters restart at CVodeReInit: add them up before each restart. */
static void add_counts(void *mem, int newton, struct bench_run *out)
{
    long nst = 0, nfe = 0, nfels = 0;
    CVodeGetNumSteps(mem, &nst);
    CVodeGetNumRhsEvals(mem, &nfe);
    if (newton)
        CVodeGetNumLinRhsEvals(mem, &nfels);
    out->steps += (double)nst;
    out->rhs_evals += (double)(nfe + nfels);
}

/* Integrates cycle by cycle to the end of cycle `cycle`, restarting at every event. */
static int integrate(void *mem, N_Vector yv, struct ed_sys *s, int newton, int cycle, int *found,
                     double cpu_cap, struct bench_run *out)
{
    double cpu_start = bench_cpu_seconds();
    double *y = N_VGetArrayPointer(yv), T = s->period, D_start = 0.0;
    double t_burst = 0.0; /* start of the current burst of events */
    long burst = 0;       /* events since t_burst */
    ed_real t = 0.0;
    for (int k = 1; k <= cycle; k++) {
        double boundary = k * T;
        while (t < boundary) {
            if (cpu_cap > 0.0 && bench_cpu_seconds() - cpu_start > cpu_cap) {
                snprintf(out->msg, sizeof out->msg,
                         "stopped at the CPU cap of %g s at t = %.4g of %.4g (%g events)", cpu_cap,
                         (double)t, cycle * T, out->events);
                add_counts(mem, newton, out);
                return FRICREG_EINTEGRATOR;
            }
            CVodeSetStopTime(mem, boundary);
            int flag = CVode(mem, boundary, yv, &t, CV_NORMAL);
            if (flag < 0) {
                snprintf(out->msg, sizeof out->msg, "CVODE failed at t = %.17g: %s", (double)t,
                         last_error);
                return FRICREG_EINTEGRATOR;
            }
            if (flag == CV_ROOT_RETURN) {
                /* At loose tolerances a contact that starts to slip with a tiny net force
                 * can see its integrated velocity cross zero again at once, on error alone,
                 * over and over (a numerical Zeno cascade). Stop it and report. */
                burst = t - t_burst < 1e-9 * (1.0 + t) ? burst + 1 : 0;
                t_burst = burst ? t_burst : t;
                if (burst > MAX_BURST) {
                    snprintf(out->msg, sizeof out->msg,
                             "event cascade: %d mode switches within 1e-9 of t = %.17g", MAX_BURST,
                             t_burst);
                    add_counts(mem, newton, out);
                    return FRICREG_EINTEGRATOR;
                }
                CVodeGetRootInfo(mem, found);
                out->events += switch_modes(s, t, y, found);
                add_counts(mem, newton, out);
                CVodeReInit(mem, t, yv);
            }
        }
        if (k == cycle - 1)
            D_start = y[2 * s->n];
    }
    add_counts(mem, newton, out);
    out->D = y[2 * s->n] - D_start;
    return FRICREG_OK;
}

int ed_run(const void *point, struct bench_run *out)
{
    const struct ed_point *pt = point;
    const struct bench_problem *p = pt->problem;
    *out = (struct bench_run){0};
    out->D = NAN;
    if (!p->event_driven)
        return out->status = FRICREG_EINVAL;
    int chain = p->system == FRICREG_SYSTEM_CHAIN, newton = pt->method == ED_BDF;
    struct ed_sys s = {chain ? p->n : 1, chain, p->a, p->omega, chain ? 1.0 / (double)p->n : 1.0,
                       bench_period(p),  NULL,  NULL};
    sunindextype dim = (sunindextype)(2 * s.n + 1);
    SUNContext ctx = NULL;
    N_Vector y = NULL;
    SUNMatrix A = NULL;
    SUNLinearSolver LS = NULL;
    SUNNonlinearSolver NLS = NULL;
    void *mem = NULL;
    s.mode = calloc(s.n, sizeof *s.mode);
    s.a_free = calloc(s.n, sizeof *s.a_free);
    int *found = calloc(s.n, sizeof *found);
    int status = s.mode && s.a_free && found ? FRICREG_OK : FRICREG_ENOMEM;
    if (status == FRICREG_OK && SUNContext_Create(ED_COMM_NULL, &ctx) != 0)
        status = FRICREG_ENOMEM;
    if (status == FRICREG_OK) {
        y = N_VNew_Serial(dim, ctx);
        mem = CVodeCreate(newton ? CV_BDF : CV_ADAMS, ctx);
        status = y && mem ? FRICREG_OK : FRICREG_ENOMEM;
    }
    if (status == FRICREG_OK) {
        /* From rest at the origin; each contact starts stuck or slipping as at an event. */
        N_VConst(0.0, y);
        free_acc(&s, 0.0, N_VGetArrayPointer(y), s.a_free);
        for (size_t i = 0; i < s.n; i++)
            s.mode[i] = mode_at_rest(s.a_free[i]);
        int flag = CVodeInit(mem, rhs, 0.0, y);
#if SUNDIALS_VERSION_MAJOR < 7
        flag |= CVodeSetErrHandlerFn(mem, quiet_handler, NULL);
#endif
        flag |= CVodeSetUserData(mem, &s);
        flag |= CVodeSStolerances(mem, pt->rtol, pt->atol > 0.0 ? pt->atol : pt->rtol);
        flag |= CVodeSetMaxNumSteps(mem, 100000000L);
        flag |= CVodeRootInit(mem, (int)s.n, roots);
        if (newton) { /* BDF with Newton and a dense difference-quotient Jacobian */
            A = SUNDenseMatrix(dim, dim, ctx);
            LS = SUNLinSol_Dense(y, A, ctx);
            flag |= A && LS ? CVodeSetLinearSolver(mem, LS, A) : -1;
        } else { /* Adams with functional (fixed-point) iteration: no Jacobian */
            NLS = SUNNonlinSol_FixedPoint(y, 0, ctx);
            flag |= NLS ? CVodeSetNonlinearSolver(mem, NLS) : -1;
        }
        if (flag != 0) {
            snprintf(out->msg, sizeof out->msg, "CVODE set-up failed: %s", last_error);
            status = FRICREG_EINTEGRATOR;
        }
    }
    if (status == FRICREG_OK)
        status = integrate(mem, y, &s, newton, p->cycle, found, pt->cpu_cap, out);
    CVodeFree(&mem);
    SUNNonlinSolFree(NLS);
    SUNLinSolFree(LS);
    SUNMatDestroy(A);
    N_VDestroy(y);
    SUNContext_Free(&ctx);
    free(found);
    free(s.a_free);
    free(s.mode);
    return out->status = status;
}

const char *ed_version(void)
{
    return "SUNDIALS " SUNDIALS_VERSION;
}
