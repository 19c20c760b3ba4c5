/* SPDX-License-Identifier: GPL-3.0-or-later */
/* system.h — internal: a reference system as a table of function pointers, one file each.
 *
 * As GSL's ode-initval2 has one file per stepper behind gsl_odeiv2_step_type, each system of
 * the drivers is one file in src/sim/systems/ defining one `const struct fr_system_type`, and
 * systems.c maps enum fricreg_system onto them. A system is written as contacts
 * zddot = a_free + W f (Sec. 3.3): it gives the contact velocities zdot and free
 * accelerations a_free from the state, its W and bounds, and the body accelerations once the
 * friction forces f are known. A new system is one new file and one entry in systems.c. */
#ifndef FRICREG_SYSTEM_H
#define FRICREG_SYSTEM_H

#include <math.h>
#include <stddef.h>

#include "fricreg_sim.h"

#define FR_MAX_PARAMS 8 /* parameters of one system (the oscillator has 5) */

/* In each system's file: its table fits struct fr_system (C99 has no static_assert). */
#define FR_CHECK_NPARAMS(n) typedef char fr_nparams_fit[(n) <= FR_MAX_PARAMS ? 1 : -1]

/* One parameter a system reads: its row in the system's parameter table. */
struct fr_param_spec {
    int param;                  /* enum fricreg_param */
    const char *name;           /* the paper's symbol, for messages: "omega" */
    double paper_value;         /* the default: the paper's value (its one home) */
    int (*valid)(double value); /* NULL: any finite value */
    const char *rule;           /* what valid() demands, after "omega = -1": "must be > 0" */
};

struct fr_system;

/* A reference system. Every function reads the parameters from sys->p, in the order of
 * `params`; array lengths are ndof(sys) for bodies and ncontacts(sys) for contacts. */
struct fr_system_type {
    int id;           /* enum fricreg_system */
    const char *name; /* for messages: "oscillator" */
    const struct fr_param_spec *params;
    size_t nparams; /* <= FR_MAX_PARAMS */

    size_t (*ndof)(const struct fr_system *sys);
    size_t (*ncontacts)(const struct fr_system *sys);
    /* The forcing period: cycles of the dissipation record. */
    double (*period)(const struct fr_system *sys);
    /* An upper bound of the highest natural frequency without friction (the step check). */
    double (*max_frequency)(const struct fr_system *sys);
    /* The paper's eps for the step dt. */
    double (*paper_eps)(const struct fr_system *sys, double dt);
    /* w in D = -w sum_i ∫ zdot_i f_i dt. */
    double (*dissipation_weight)(const struct fr_system *sys);
    /* Bounds and coupling W into a context of ncontacts(sys) contacts; a fricreg status. */
    int (*configure)(const struct fr_system *sys, fricreg_ctx *ctx);
    void (*initial)(const struct fr_system *sys, double x[], double v[]);
    /* The contacts' kinematics at (t, x, v): a_free [m] into a_free unless it is NULL (the
     * drivers' after-step check reads zdot only), and the contact velocities zdot [m] as the
     * return value: written into zdot_buf, or v itself where the contacts move with the bodies
     * (oscillator, chain), which saves a copy per right-hand side. sys is not const: its
     * forcing memo (fr_system_sin) may be updated, never its parameters. */
    const double *(*contacts)(struct fr_system *sys, double t, const double x[], const double v[],
                              double zdot_buf[], double a_free[]);
    /* 1 where contacts() returns v itself (zdot = v, m = ndof: the contacts are the bodies)
     * and W is diagonal; FRICREG_INT_CENTRAL_IMEX solves the friction body by body there. */
    int contacts_are_bodies;
    /* The rest of the right-hand side once the friction forces f are known, in one pass
     * where the system allows: x' = v into dydt[0, ndof), the body accelerations into
     * dydt[ndof, 2 ndof), and the friction power sum_i zdot_i f_i as the return value. */
    double (*bodies)(const struct fr_system *sys, double t, const double x[], const double v[],
                     const double zdot[], const double a_free[], const double f[], double dydt[]);

    /* The system is linear in x, v and f (all three are):
     *   zdot = Zv v + zdot_0(t),  a_free = Ax x + a_0(t),  acc = Cx x + Cf f + c_0(t),
     * with acc's dependence through a_free folded into Cx and c_0. The maps below give these
     * pieces for the analytic Jacobian of the drivers' ODE (sim_jacobian.c); a system that
     * leaves any of them NULL gets the forward-difference Jacobian instead. */
    /* Constant maps, dense row-major, every entry written: Zv = dzdot/dv [m x n],
     * Ax = da_free/dx [m x n]. */
    void (*contact_maps)(const struct fr_system *sys, double dzdot_dv[], double dafree_dx[]);
    /* Constant maps, dense row-major, every entry written: Cx = dacc/dx at fixed f [n x n],
     * Cf = dacc/df [n x m]. */
    void (*body_maps)(const struct fr_system *sys, double dacc_dx[], double dacc_df[]);
    /* The forcing's rates at t, at fixed x, v and f: dzdot_0/dt [m], da_0/dt [m],
     * dc_0/dt [n]. */
    void (*time_rates)(const struct fr_system *sys, double t, double dzdot_dt[], double dafree_dt[],
                       double dacc_dt[]);
};

/* One system with its parameter values. */
struct fr_system {
    const struct fr_system_type *type;
    double p[FR_MAX_PARAMS];   /* in the order of type->params */
    double memo_arg, memo_sin; /* fr_system_sin's last argument (NaN: none yet) and its sine */
};

/* sin(arg), from the memo when arg is the last argument, to the bit what sin(arg) is. The
 * forcing's sine was a sixth of a fixed RK4 step's time (oscillator, chain of 32), and RK4's
 * stages repeat their times: t + h/2 twice, and the end of each of a call's two steps is the
 * start of the next (rk4_classic.c), so 3 of every 8 are repeats. The memo is a pure function
 * of arg: a copied system may keep it whatever its parameters. */
static inline double fr_system_sin(struct fr_system *sys, double arg)
{
    if (!(arg == sys->memo_arg)) {
        sys->memo_arg = arg;
        sys->memo_sin = sin(arg);
    }
    return sys->memo_sin;
}

/* systems.c: the table of types and the parameter lookups. */

/* The type of a system id (enum fricreg_system), or NULL if unknown. */
const struct fr_system_type *fr_system_type_find(int id);

/* A system of `type` with the paper's parameter values. */
void fr_system_init(struct fr_system *sys, const struct fr_system_type *type);

/* The row of `param` in the type's table and its index in p[] (*slot), or NULL if the system
 * does not read it. */
const struct fr_param_spec *fr_system_param(const struct fr_system_type *type, int param,
                                            size_t *slot);

/* The paper's symbol of a parameter of any system ("k"), or NULL for an unknown one. */
const char *fr_param_name(int param);

/* Validity rules shared by the systems' tables. */
int fr_param_positive(double value);    /* "must be > 0" */
int fr_param_nonnegative(double value); /* "must be >= 0" */

/* Table entries shared by the systems. */
double fr_paper_eps_two_dt(const struct fr_system *sys, double dt); /* eps = 2 dt */
double fr_unit_weight(const struct fr_system *sys); /* w = 1: D = -sum_i ∫ zdot_i f_i dt */

/* The three reference systems (src/sim/systems/). */
extern const struct fr_system_type fr_oscillator_type;
extern const struct fr_system_type fr_chain_type;
extern const struct fr_system_type fr_twoblock_type;

#endif
