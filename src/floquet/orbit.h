/* SPDX-License-Identifier: GPL-3.0-or-later */
/* orbit.h — the switch instants of the exact periodic orbit nearest a harmonic-balance orbit,
 * where only contacts switch (orbit.c), for the exact monodromy (monodromy.c). */
#ifndef FRICREG_HB_ORBIT_H
#define FRICREG_HB_ORBIT_H

#include <stddef.h>

#include "switches.h"

/* The model between switches, M x'' + C x' + K x + Σ_closed J_n^T (n0 + kn J_n x) = p(t), in
 * M^-1's image: n dofs, column-major [n n] M^-1 K and M^-1 C (n at most FR_HB_ORBIT_MAX_N);
 * MiJ [m][n] M^-1 J_r^T for each row r of the row-major J [m n], the normal row of element e
 * being row 2e + 1; the elements' n0 and kn [me]; Mip [2][n] M^-1 p_c and M^-1 p_s of the load
 * p_c cos Ωt + p_s sin Ωt (the level in force included); omega, Ω. */
struct fr_hb_orbit_model {
    size_t n, m, me;
    const double *MiK, *MiC, *MiJ, *J, *n0, *kn, *Mip;
    double omega;
};

/* The sizes it refines: larger models and schedules keep the HB's instants (a Newton step
 * costs count + 1 products of count exponentials of order 2n + 3, and a solution 3 to 5 steps:
 * about 10 to 20 times the monodromy's own product). */
#define FR_HB_ORBIT_MAX_N 32
#define FR_HB_ORBIT_MAX_SWITCHES 16

/* Doubles of fr_hb_orbit_refine's workspace for n dofs. */
size_t fr_hb_orbit_work(size_t n);

/* Newton on the angles of sc's contact switches (sc->S = 0: no slider in the state), from the
 * HB's, so that the piecewise-affine model's periodic orbit through them (its start solved
 * from the period's affine map) meets each contact's surface n0 + kn J_n x = 0 at its switch.
 * Converged (a step below 1e-12 rad), the angles replace sc's, wrapped into [0, 2π) and sorted, and the
 * state at θ = 0 (sc->closed) follows them: returns 1. Else (sizes past the bounds above, a
 * singular step, no convergence in 8 steps, a switch moving past its neighbour or by more than
 * 0.2 rad) sc is left as it was: returns 0. work[fr_hb_orbit_work(n)],
 * piv[2n + 3 + FR_HB_ORBIT_MAX_SWITCHES]; no allocation. */
int fr_hb_orbit_refine(const struct fr_hb_orbit_model *om, struct fr_hb_schedule *sc, double *work,
                       int *piv);

#endif
