/* sim_internal.h — the simulation's layout, shared by systems.c (equations) and sim.c (run). */
#ifndef FRICREG_SIM_INTERNAL_H
#define FRICREG_SIM_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include "error.h"
#include "fricreg_sim.h"

struct fr_params {
    double a, omega, mun, x0, v0; /* oscillator; a and omega also the chain's */
    size_t n;                     /* chain */
    double k, mu1, mu2, belt_amp, belt_omega; /* two blocks */
};

struct fricreg_sim {
    int system;
    struct fr_params p;
    int law;
    int partition; /* enum fricreg_partition, passed to the context */
    double eps_set; /* 0: the paper's rule */
    int integrator;
    double dt, rtol, atol;
    fricreg_sim_observer observer;
    void *observer_user;

    /* Working state of a run, sized by fr_system_ndof at its start. */
    size_t ndof, m;
    double eps;
    fricreg_ctx *ctx;
    double *y;              /* [2 ndof + 1]: x, v, D */
    double *zdot, *a_free;  /* [m] contact kinematics */
    double *f, *f_eq;       /* [m] friction */
    double *stick_time;     /* [m] near-stick time in the current cycle */
    double *stick_fraction; /* [m] result */
    double *D;              /* [cycles] dissipation per cycle */
    double *jac_work;       /* [3 (2 ndof + 1)] finite-difference Jacobian scratch */
    size_t cycles;
    double t;
    int64_t steps, rhs_evals;
    int rhs_status;   /* fricreg status raised inside the right-hand side */
    size_t bad_contact; /* with FRICREG_ENONFINITE: the first contact that overflowed */

    struct fr_error err;
};

/* systems.c: the equations of motion of each reference system. */
size_t fr_system_ndof(const fricreg_sim *sim);
double fr_system_period(const fricreg_sim *sim);
double fr_system_max_frequency(const fricreg_sim *sim);
double fr_system_paper_eps(const fricreg_sim *sim, double dt);
double fr_system_dissipation_weight(const fricreg_sim *sim);
int fr_system_configure(fricreg_sim *sim); /* bounds and coupling into sim->ctx */
void fr_system_initial(const fricreg_sim *sim, double x[], double v[]);
void fr_system_contacts(const fricreg_sim *sim, double t, const double x[], const double v[],
                        double zdot[], double a_free[]);
void fr_system_accelerations(const fricreg_sim *sim, double t, const double x[],
                             const double a_free[], const double f[], double acc[]);
int fr_system_set_param(struct fr_params *p, int system, int param, double value,
                        const char **why);

#endif
