/* SPDX-License-Identifier: GPL-3.0-or-later */
/* warn_track.c — what the warnings (warnings.c) judge a run by, tracked as it steps: the
 * fastest contact and degree of freedom, the longest step, the steps whose energy balance is
 * not exact, the adaptive calls' tolerance levels. */
#include <math.h>

#include "structure_internal.h"

void fr_warn_track_reset(fricreg_structure *s)
{
    s->peak_speed = 0.0;
    s->max_dt = 0.0;
    s->inexact_steps = 0;
    s->ode_tol_level = 0.0;
    s->ode_rtol_max = 0.0;
    s->peak_dof_speed = 0.0;
}

/* Average-acceleration Newmark: the one scheme whose discrete energy balance is exact. */
static int balance_exact(const fricreg_structure *s)
{
    return s->scheme == FR_SCHEME_NEWMARK && s->alpha == 0.0 && s->beta == 0.25 && s->gamma == 0.5;
}

void fr_warn_track_step(fricreg_structure *s, double dt, int ode)
{
    const SuiteSparse_long *Jp = s->Jt->p, *Ji = s->Jt->i;
    const double *Jx = s->Jt->x, *v = s->v->data;
    for (size_t i = 0; i < s->m; i++) { /* zdot_i = (J v)_i: column i of J^T */
        if (s->mun[i] == 0.0)
            continue; /* no friction there: its speed says nothing of eps */
        double z = 0.0, w = 0.0;
        for (SuiteSparse_long p = Jp[i]; p < Jp[i + 1]; p++) {
            z += Jx[p] * v[Ji[p]];
            w += fabs(Jx[p] * v[Ji[p]]);
        }
        s->peak_speed = fmax(s->peak_speed, fabs(z));
        s->peak_dof_speed = fmax(s->peak_dof_speed, w);
    }
    s->max_dt = fmax(s->max_dt, dt);
    if (ode || !balance_exact(s) || s->el.crossed) /* lift-off: the normal kink within a step */
        s->inexact_steps++;
}

/* The level to which an adaptive run_ode call with (rtol, atol) holds the contacts'
 * velocities: each velocity v_j to atol_j + rtol |v_j| (GSL's control, the per-component atol
 * of set_ode_abs_tolerances or the call's one atol), summed through J, so contact i's to
 * sum_j |J_ij| (atol_j + rtol |v_j|). Kept as the absolute part, max over contacts with
 * mun_i > 0 of sum_j |J_ij| atol_j, and rtol; check_tolerances adds rtol times the run's
 * largest sum_j |J_ij| |v_j| (as include/fricreg_structure.h documents
 * FRICREG_WARN_TOL_LOOSE). The rule from eps holds them to 1e-3 eps and is not judged. */
void fr_warn_track_ode_tolerances(fricreg_structure *s, double rtol, double atol)
{
    if (s->ode_atol == NULL && atol == FRICREG_ATOL_FROM_EPS)
        return;
    const SuiteSparse_long *Jp = s->Jt->p, *Ji = s->Jt->i;
    const double *Jx = s->Jt->x;
    for (size_t i = 0; i < s->m; i++) {
        if (s->mun[i] == 0.0)
            continue; /* no friction there */
        double level = 0.0;
        for (SuiteSparse_long p = Jp[i]; p < Jp[i + 1]; p++) {
            size_t j = s->n + (size_t)Ji[p]; /* v_j's component of y = (u, v, ...) */
            double atol_j = s->ode_atol != NULL ? s->ode_atol[j] * s->tol_scale : atol;
            level += fabs(Jx[p]) * atol_j;
        }
        s->ode_tol_level = fmax(s->ode_tol_level, level);
    }
    s->ode_rtol_max = fmax(s->ode_rtol_max, rtol);
}
