/* systems.c — the equations of motion of the paper's three reference systems.
 *
 * Each system is written as contacts zddot = a_free + W f (Sec. 3.3): it supplies the contact
 * velocities zdot and free accelerations a_free from the state, its W and bounds, and the body
 * accelerations once the friction forces f are known. */
#include <math.h>

#include "sim_internal.h"

#define TWO_PI 6.283185307179586

size_t fr_system_ndof(const fricreg_sim *sim)
{
    switch (sim->system) {
    case FRICREG_SYSTEM_CHAIN: return sim->p.n;
    case FRICREG_SYSTEM_TWOBLOCK: return 2;
    default: return 1;
    }
}

double fr_system_period(const fricreg_sim *sim)
{
    double omega = sim->system == FRICREG_SYSTEM_TWOBLOCK ? sim->p.belt_omega : sim->p.omega;
    return TWO_PI / omega;
}

/* An upper bound of the system's highest natural frequency without friction: 1 for Eq. (5);
 * 2n for the chain (the stiffness n^2 tridiag(-1, 2, -1) has eigenvalues below 4 n^2); the
 * larger of the two ground springs for the two blocks (unit masses). */
double fr_system_max_frequency(const fricreg_sim *sim)
{
    switch (sim->system) {
    case FRICREG_SYSTEM_CHAIN: return 2.0 * (double)sim->p.n;
    case FRICREG_SYSTEM_TWOBLOCK: return sqrt(fmax(1.0, sim->p.k));
    default: return 1.0;
    }
}

/* The paper's choices: eps = 2 dt (Sec. 3.1, also used for Sec. 3.3), 10 omega dt (Sec. 3.2). */
double fr_system_paper_eps(const fricreg_sim *sim, double dt)
{
    return sim->system == FRICREG_SYSTEM_CHAIN ? 10.0 * sim->p.omega * dt : 2.0 * dt;
}

/* The chain's friction enters as f_i/n: D = -(1/n) sum_i ∫ u_i' f_i dt (Sec. 3.2). */
double fr_system_dissipation_weight(const fricreg_sim *sim)
{
    return sim->system == FRICREG_SYSTEM_CHAIN ? 1.0 / (double)sim->p.n : 1.0;
}

int fr_system_configure(fricreg_sim *sim)
{
    if (sim->system == FRICREG_SYSTEM_TWOBLOCK) {
        const double W[4] = {1.0, -1.0, -1.0, 2.0}; /* Eqs. (7): z'' = a_free + W f */
        const double mun[2] = {sim->p.mu1, sim->p.mu2};
        int status = fricreg_ctx_set_coupling_dense(sim->ctx, 2, W);
        return status ? status : fricreg_ctx_set_bounds(sim->ctx, 2, mun);
    }
    if (sim->system == FRICREG_SYSTEM_OSCILLATOR)
        return fricreg_ctx_set_bounds(sim->ctx, 1, &sim->p.mun);
    return FRICREG_OK; /* chain: the context's defaults, mun_i = 1 and W = I */
}

void fr_system_initial(const fricreg_sim *sim, double x[], double v[])
{
    size_t n = fr_system_ndof(sim);
    for (size_t i = 0; i < n; i++)
        x[i] = v[i] = 0.0;
    if (sim->system == FRICREG_SYSTEM_OSCILLATOR) {
        x[0] = sim->p.x0;
        v[0] = sim->p.v0;
    }
}

/* Chain, Sec. 3.2: u_i'' = f_i + a_free_i with a_free = -n^2 K u + n G e_1, where K is the
 * tridiagonal (-1, 2, -1) stiffness with a free end at block 1 and a wall at block n. */
static void chain_contacts(const fricreg_sim *sim, double t, const double u[], double a_free[])
{
    size_t n = sim->p.n;
    double n2 = (double)n * (double)n;
    double G = sim->p.a * sin(sim->p.omega * t);
    a_free[0] = -n2 * (u[0] - u[1]) + (double)n * G;
    for (size_t i = 1; i + 1 < n; i++)
        a_free[i] = -n2 * (-u[i - 1] + 2.0 * u[i] - u[i + 1]);
    a_free[n - 1] = -n2 * (-u[n - 2] + 2.0 * u[n - 1]);
}

void fr_system_contacts(const fricreg_sim *sim, double t, const double x[], const double v[],
                        double zdot[], double a_free[])
{
    const struct fr_params *p = &sim->p;
    switch (sim->system) {
    case FRICREG_SYSTEM_OSCILLATOR: /* Eq. (5): f_eq = x - a sin(wt) = -a_free */
        zdot[0] = v[0];
        a_free[0] = -x[0] + p->a * sin(p->omega * t);
        break;
    case FRICREG_SYSTEM_CHAIN:
        for (size_t i = 0; i < p->n; i++)
            zdot[i] = v[i];
        chain_contacts(sim, t, x, a_free);
        break;
    default: { /* Eqs. (7): z1 = x1 - u(t), z2 = x2 - x1 */
        double wt = p->belt_omega * t;
        double belt_v = p->belt_amp * p->belt_omega * cos(wt);
        double belt_a = -p->belt_amp * p->belt_omega * p->belt_omega * sin(wt);
        zdot[0] = v[0] - belt_v;
        zdot[1] = v[1] - v[0];
        a_free[0] = -belt_a - x[0];
        a_free[1] = x[0] - p->k * x[1];
        break;
    }
    }
}

void fr_system_accelerations(const fricreg_sim *sim, double t, const double x[],
                             const double a_free[], const double f[], double acc[])
{
    (void)t;
    if (sim->system == FRICREG_SYSTEM_TWOBLOCK) { /* (7a), (7b) */
        acc[0] = -x[0] + f[0] - f[1];
        acc[1] = -sim->p.k * x[1] + f[1];
        return;
    }
    /* Oscillator and chain have W = I and contacts at the bodies: x'' = a_free + f. */
    size_t n = fr_system_ndof(sim);
    for (size_t i = 0; i < n; i++)
        acc[i] = a_free[i] + f[i];
}

/* Validates and stores one parameter; on failure *why says what is wrong. */
int fr_system_set_param(struct fr_params *p, int system, int param, double value,
                        const char **why)
{
    int osc = system == FRICREG_SYSTEM_OSCILLATOR, chain = system == FRICREG_SYSTEM_CHAIN;
    int two = system == FRICREG_SYSTEM_TWOBLOCK;
    if (!isfinite(value)) {
        *why = "is not finite";
        return FRICREG_ENONFINITE;
    }
    *why = "is not a parameter of this system";
    switch (param) {
    case FRICREG_PARAM_A: if (!(osc || chain)) return FRICREG_EINVAL; p->a = value; break;
    case FRICREG_PARAM_X0: if (!osc) return FRICREG_EINVAL; p->x0 = value; break;
    case FRICREG_PARAM_V0: if (!osc) return FRICREG_EINVAL; p->v0 = value; break;
    case FRICREG_PARAM_BELT_AMP: if (!two) return FRICREG_EINVAL; p->belt_amp = value; break;
    case FRICREG_PARAM_OMEGA:
    case FRICREG_PARAM_K:
    case FRICREG_PARAM_BELT_OMEGA: {
        int has = param == FRICREG_PARAM_OMEGA ? osc || chain : two;
        if (!has) return FRICREG_EINVAL;
        *why = "must be > 0";
        if (!(value > 0.0)) return FRICREG_EINVAL;
        double *slot = param == FRICREG_PARAM_OMEGA ? &p->omega
                       : param == FRICREG_PARAM_K   ? &p->k
                                                    : &p->belt_omega;
        *slot = value;
        break;
    }
    case FRICREG_PARAM_MUN:
    case FRICREG_PARAM_MU1:
    case FRICREG_PARAM_MU2: {
        int has = param == FRICREG_PARAM_MUN ? osc : two;
        if (!has) return FRICREG_EINVAL;
        *why = "must be >= 0";
        if (!(value >= 0.0)) return FRICREG_EINVAL;
        double *slot = param == FRICREG_PARAM_MUN ? &p->mun
                       : param == FRICREG_PARAM_MU1 ? &p->mu1
                                                    : &p->mu2;
        *slot = value;
        break;
    }
    case FRICREG_PARAM_N:
        if (!chain) return FRICREG_EINVAL;
        *why = "must be an integer from 2 to 10^7";
        if (!(value >= 2.0 && value <= 1e7 && value == floor(value))) return FRICREG_EINVAL;
        p->n = (size_t)value;
        break;
    default:
        *why = "is not a known parameter";
        return FRICREG_EINVAL;
    }
    return FRICREG_OK;
}
