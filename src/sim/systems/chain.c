/* SPDX-License-Identifier: GPL-3.0-or-later */
/* chain.c — the chain of Sec. 3.2: n blocks of mass 1/n joined by springs of stiffness n,
 * block n tied to a wall, block 1 driven by a sin(omega t), every block on its own contact
 * with mun = 1 and W = I. In the paper's scaling u_i'' = a_free_i + f_i with
 * a_free = -n^2 K u + n G(t) e_1, K the tridiagonal (-1, 2, -1) stiffness with a free end at
 * block 1, and the friction entering the energy as f_i/n. */
#include <math.h>

#include "base/fr_math.h"
#include "sim/system.h"

enum { N, A, OMEGA, NPARAMS };
FR_CHECK_NPARAMS(NPARAMS);

#define MAX_BLOCKS 1e7

/* n: an integer from 2 to 10^7. */
static int valid_size(double value)
{
    return value >= 2.0 && value <= MAX_BLOCKS && value == floor(value);
}

/* The paper's values (spec: reference system 2, Sec. 3.2). */
static const struct fr_param_spec params[NPARAMS] = {
    [N] = {FRICREG_PARAM_N, "n", 32.0, valid_size, "must be an integer from 2 to 10^7"},
    [A] = {FRICREG_PARAM_A, "a", 0.25, NULL, NULL},
    [OMEGA] = {FRICREG_PARAM_OMEGA, "omega", 0.5, fr_param_positive, "must be > 0"},
};

static size_t blocks(const struct fr_system *sys)
{
    return (size_t)sys->p[N];
}

static double period(const struct fr_system *sys)
{
    return FR_TWO_PI / sys->p[OMEGA];
}

/* n^2 K has its eigenvalues below 4 n^2: frequencies below 2n. */
static double max_frequency(const struct fr_system *sys)
{
    return 2.0 * sys->p[N];
}

/* eps = 10 omega dt (Sec. 3.2). */
static double paper_eps(const struct fr_system *sys, double dt)
{
    return 10.0 * sys->p[OMEGA] * dt;
}

/* D = -(1/n) sum_i ∫ u_i' f_i dt (Sec. 3.2). */
static double weight(const struct fr_system *sys)
{
    return 1.0 / sys->p[N];
}

/* The context's defaults are the chain's: mun_i = 1 and W = I. */
static int configure(const struct fr_system *sys, fricreg_ctx *ctx)
{
    (void)sys, (void)ctx;
    return FRICREG_OK;
}

static void initial(const struct fr_system *sys, double x[], double v[])
{
    for (size_t i = 0; i < blocks(sys); i++)
        x[i] = v[i] = 0.0;
}

/* The contacts are the blocks: zdot = v, no copy. a_free is the spring stencil. */
static const double *contacts(struct fr_system *sys, double t, const double u[], const double v[],
                              double zdot_buf[], double a_free[])
{
    (void)zdot_buf;
    size_t n = blocks(sys);
    double n2 = (double)n * (double)n;
    if (a_free == NULL)
        return v;
    double G = sys->p[A] * fr_system_sin(sys, sys->p[OMEGA] * t);
    a_free[0] = -n2 * (u[0] - u[1]) + (double)n * G;
    for (size_t i = 1; i + 1 < n; i++)
        a_free[i] = -n2 * (-u[i - 1] + 2.0 * u[i] - u[i + 1]);
    a_free[n - 1] = -n2 * (-u[n - 2] + 2.0 * u[n - 1]);
    return v;
}

/* Partial sums of the power: a single running sum would be one dependent add per block,
 * the pass's bottleneck (4 cycles each); POWER_LANES of them the vectorizer keeps in
 * registers side by side. */
enum { POWER_LANES = 8 };

/* Contacts at the bodies: u' = v, u'' = a_free + f, and the power v . f, in one pass. The
 * arrays are distinct (dydt is GSL's, the others the stage's state and the drivers' own):
 * restrict spares the vectorizer overlap checks between five arrays, more than it versions. */
static double bodies(const struct fr_system *sys, double t, const double u[],
                     const double *restrict v, const double zdot[], const double *restrict a_free,
                     const double *restrict f, double *restrict dydt)
{
    (void)t, (void)u, (void)zdot;
    size_t n = blocks(sys), i = 0;
    double *restrict du = dydt, *restrict dv = dydt + n, s[POWER_LANES] = {0.0};
    for (; i + POWER_LANES <= n; i += POWER_LANES)
        for (size_t l = 0; l < POWER_LANES; l++) {
            du[i + l] = v[i + l];
            dv[i + l] = a_free[i + l] + f[i + l];
            s[l] += v[i + l] * f[i + l];
        }
    for (; i < n; i++) { /* the tail */
        du[i] = v[i];
        dv[i] = a_free[i] + f[i];
        s[0] += v[i] * f[i];
    }
    double power = 0.0;
    for (size_t l = 0; l < POWER_LANES; l++)
        power += s[l];
    return power;
}

/* Row-major n x n: value on the diagonal, zero elsewhere. */
static void fill_diagonal(size_t n, double value, double M[])
{
    for (size_t k = 0; k < n * n; k++)
        M[k] = 0.0;
    for (size_t i = 0; i < n; i++)
        M[i * n + i] = value;
}

/* -n^2 K into S[n x n], row-major: the springs of contacts() as a matrix. */
static void spring_matrix(size_t n, double S[])
{
    double n2 = (double)n * (double)n;
    fill_diagonal(n, -2.0 * n2, S);
    S[0] = -n2; /* block 1's free end: one spring */
    for (size_t i = 0; i + 1 < n; i++)
        S[i * n + i + 1] = S[(i + 1) * n + i] = n2;
}

/* zdot = v, a_free = -n^2 K u + n G(t) e_1, acc = a_free + f. */
static void contact_maps(const struct fr_system *sys, double dzdot_dv[], double dafree_dx[])
{
    fill_diagonal(blocks(sys), 1.0, dzdot_dv);
    spring_matrix(blocks(sys), dafree_dx);
}

static void body_maps(const struct fr_system *sys, double dacc_dx[], double dacc_df[])
{
    spring_matrix(blocks(sys), dacc_dx);
    fill_diagonal(blocks(sys), 1.0, dacc_df);
}

/* Only block 1 is driven: d(n G)/dt = n a omega cos(omega t). */
static void time_rates(const struct fr_system *sys, double t, double dzdot_dt[], double dafree_dt[],
                       double dacc_dt[])
{
    size_t n = blocks(sys);
    for (size_t i = 0; i < n; i++)
        dzdot_dt[i] = dafree_dt[i] = dacc_dt[i] = 0.0;
    dafree_dt[0] = dacc_dt[0] = (double)n * sys->p[A] * sys->p[OMEGA] * cos(sys->p[OMEGA] * t);
}

const struct fr_system_type fr_chain_type = {
    .id = FRICREG_SYSTEM_CHAIN,
    .name = "chain",
    .params = params,
    .nparams = NPARAMS,
    .ndof = blocks,
    .ncontacts = blocks,
    .period = period,
    .max_frequency = max_frequency,
    .paper_eps = paper_eps,
    .dissipation_weight = weight,
    .configure = configure,
    .initial = initial,
    .contacts = contacts,
    .contacts_are_bodies = 1,
    .bodies = bodies,
    .contact_maps = contact_maps,
    .body_maps = body_maps,
    .time_rates = time_rates,
};
