/* SPDX-License-Identifier: GPL-3.0-or-later */
/* central_difference.c — the explicit central-difference step of a fricreg_structure: the
 * scheme of src/ode/central.h, with
 *
 *   M a1 = p~1 - C v* - K u1 + J^T f(J v*, J M^-1 (p~1 - C v* - K u1)),
 *
 * so the friction and the damping see the explicit velocity v* and nothing is solved but M's
 * factor (one forward and one backward solve; O(n) for a lumped M). Each step passes the
 * drivers' one step guard first (src/ode/step_guard.c, the integrator table's central row):
 * (dt omega_max/2)^2 + dt (lambda + c_max) < 0.9, with lambda the stick zone's stiffness and
 * c_max the largest viscous damping rate (guard.c). */
#include "fricreg_sim.h"
#include "ode/central.h"
#include "ode/integrator.h"
#include "structure_internal.h"

int fr_central_solve(fricreg_structure *s, double dt)
{
    int status = fr_structure_guard(s, fr_integrator_find(FRICREG_INT_CENTRAL), dt, "step");
    if (status != FRICREG_OK)
        return status;
    const double *u = s->u->data, *v = s->v->data, *a = s->a->data;
    double *u1 = s->u1->data, *vp = s->vp->data;
    for (size_t k = 0; k < s->n; k++) {
        u1[k] = fr_central_position(dt, u[k], v[k], a[k]);
        vp[k] = fr_central_predicted_velocity(dt, v[k], a[k]);
    }
    fr_structure_net_force(s, s->ptil1, s->u1, s->vp, s->work);
    status = fr_elements_explicit(s, s->u1, s->work, s->t + dt); /* at the known displacement */
    if (status != FRICREG_OK)
        return status;
    status = fr_structure_motion(s, s->work, s->vp, s->f1, s->x); /* f1 and a1 */
    if (status != FRICREG_OK)
        return fr_fail(s, status, "step: friction at t = %g: %s", s->t + dt,
                       fricreg_ctx_errmsg(s->ctx));
    const double *a1 = s->x->data;
    double *v1 = s->v1->data, big = 0.0;
    for (size_t k = 0; k < s->n; k++) {
        v1[k] = fr_central_velocity(dt, v[k], a[k], a1[k]);
        big = fr_max_abs(fr_max_abs(fr_max_abs(big, u1[k]), v1[k]), a1[k]);
    }
    s->end_max = big;
    return FRICREG_OK;
}
