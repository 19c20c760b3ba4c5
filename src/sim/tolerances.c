/* SPDX-License-Identifier: GPL-3.0-or-later */
/* tolerances.c — the absolute tolerances of an adaptive run of fricreg_sim (tolerances.h):
 * atol in every component, the caller's per component, or fricreg's rule from eps; what they
 * ask of the dissipation D (the error estimate's level); fricreg_sim_get_abs_tolerances. */
#include <math.h>

#include "settings.h"
#include "sim_internal.h"
#include "tolerances.h"

/* The rule from eps (fricreg_sim_set_integrator, FRICREG_ATOL_FROM_EPS), measured in
 * docs/integrators.md ("Absolute tolerances from eps"): a velocity is held absolutely to
 * min(FR_SIM_ATOL_V_PER_EPS eps, rtol x 1 velocity unit), with no relative part, since the contact
 * velocity that law (4) reads is a difference of body velocities that are O(1) while it is
 * within its band |zdot| < eps. On the two blocks at eps = 1e-6 (msbdf, rtol 1e-6), D on
 * cycle 4 was 3e-3 off with 1e-1 eps, 1.2e-4 with 1e-2 eps, and within 7e-6 with 1e-3 eps
 * from rtol 1e-4 to 1e-8. Positions and D keep GSL's standard level rtol (1 + |y_i|) of the
 * nondimensional systems. */

double fr_sim_rule_atol_v(const fricreg_sim *sim, double eps)
{
    return fmin(FR_SIM_ATOL_V_PER_EPS * eps * sim->rule_scale, sim->rtol);
}

/* Component i of the rule from eps at eps for y = (x, v, D): fr_sim_rule_atol_v on the
 * velocities, rtol on the positions and on D. */
static double rule_tolerance(const fricreg_sim *sim, double eps, size_t i)
{
    size_t n = fricreg_sim_ndof(sim);
    return i >= n && i < 2 * n ? fr_sim_rule_atol_v(sim, eps) : sim->rtol;
}

void fr_sim_rule_tolerances(const fricreg_sim *sim, double eps, double atol[], double w[])
{
    size_t n = fricreg_sim_ndof(sim);
    for (size_t i = 0; i < 2 * n + 1; i++)
        atol[i] = rule_tolerance(sim, eps, i);
    for (size_t i = 0; w != NULL && i < 2 * n + 1; i++)
        w[i] = i >= n && i < 2 * n ? 0.0 : 1.0;
}

/* Component i of the absolute tolerances of an adaptive run at eps, y = (x, v, D): the
 * caller's, atol in every component, or the rule from eps. */
static double abs_tolerance(const fricreg_sim *sim, double eps, size_t i)
{
    if (sim->atol_vec != NULL)
        return sim->atol_vec[i];
    return sim->atol_from_eps ? rule_tolerance(sim, eps, i) : sim->atol;
}

double fr_sim_dissipation_tolerance(const fricreg_sim *sim, double D)
{
    size_t i = 2 * fricreg_sim_ndof(sim); /* D, the last component of y */
    return abs_tolerance(sim, fr_sim_eps_in_use(sim), i) + sim->rtol * fabs(D);
}

int fricreg_sim_get_abs_tolerances(const fricreg_sim *sim, size_t n, double atol[])
{
    if (sim == NULL || atol == NULL)
        return FRICREG_ENULL;
    if (n != 2 * fricreg_sim_ndof(sim) + 1 || (sim->atol_vec != NULL && sim->atol_n != n))
        return FRICREG_ESIZE;
    double eps = fr_sim_eps_in_use(sim); /* fixed steps: no tolerances, zeros */
    for (size_t i = 0; i < n; i++)
        atol[i] = fr_sim_adaptive(sim) ? abs_tolerance(sim, eps, i) : 0.0;
    return FRICREG_OK;
}
