/* SPDX-License-Identifier: GPL-3.0-or-later */
/* orbit.h — the switch instants of the exact periodic orbit nearest a harmonic-balance orbit,
 * where only contacts switch (orbit.c), for the exact monodromy (monodromy.c). */
#ifndef FRICREG_HB_ORBIT_H
#define FRICREG_HB_ORBIT_H

#include <stddef.h>

#include "switches.h"

/* The model between switches, M x'' + C x' + K x + J^T f = p(t), in M^-1's image, with
 * elements under a normal law with lift-off (two rows of J each: tangential 2e, normal 2e + 1):
 * n dofs, column-major [n n] M^-1 K and M^-1 C; MiJ [m][n] M^-1 J_r^T for each row r of the
 * row-major J [m n]; the elements' n0 and kn [me] (a closed contact adds n0 + kn J_n x to the
 * normal row); the S sliders of the state (switches.h's schedule: element, stiffness k, mu kn
 * as c [S]), stuck k (J_t x − w) or slipping d mu (n0 + kn J_n x) on the tangential row while
 * closed; Mip [2][n] M^-1 p_c and M^-1 p_s of the load p_c cos Ωt + p_s sin Ωt (the level in
 * force included); omega, Ω. */
struct fr_hb_orbit_model {
    size_t n, m, me, S;
    const double *MiK, *MiC, *MiJ, *J, *n0, *kn, *Mip;
    const size_t *element;
    const double *k, *c;
    double omega;
};

/* The sizes it refines: larger models and schedules keep the HB's instants (a Newton step
 * costs U + 1 products of count exponentials of order 2n + S + 3, U the switches' unknowns,
 * and a solution 3 to 5 steps: about 10 to 20 times the monodromy's own product). */
#define FR_HB_ORBIT_MAX_N 32
#define FR_HB_ORBIT_MAX_SWITCHES 16
#define FR_HB_ORBIT_MAX_SLIDERS 16
#define FR_HB_ORBIT_MAX_ELEMENTS 16

/* Doubles of fr_hb_orbit_refine's workspace for n dofs and S sliders. */
size_t fr_hb_orbit_work(size_t n, size_t S);

/* Newton on the angles of sc's switches from the HB's, so that the piecewise-affine model's
 * periodic orbit through them (its start solved from the period's affine map; the offsets
 * reset to J_t x at a touchdown and to their bound at a slip onset) meets each switch's
 * surface there: a contact's n0 + kn J_n x = 0, a slip onset's k (J_t x − w) = d mu (n0 +
 * kn J_n x), a stop's offset velocity 0. A slider's touchdown, opening, or onset at the instant
 * its contact closes moves with the contact's switch. Converged (a step below 1e-10 rad), the
 * angles and the touchdowns' ratios u'/g' replace sc's, the switches wrapped into [0, 2π) and
 * sorted, and the states at θ = 0 (sc->closed, mode, dir) follow them: returns 1. Else (sizes
 * past the bounds above, an element without normal stiffness, a switch of another kind, a
 * singular step, no convergence in 12 steps, a switch moving by more than
 * 0.2 rad) sc is left as it was: returns 0. work[fr_hb_orbit_work(n, S)],
 * piv[2n + S + 3 + FR_HB_ORBIT_MAX_SWITCHES]; no allocation. */
int fr_hb_orbit_refine(const struct fr_hb_orbit_model *om, struct fr_hb_schedule *sc, double *work,
                       int *piv);

#endif
