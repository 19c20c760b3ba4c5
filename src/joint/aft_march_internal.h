/* SPDX-License-Identifier: GPL-3.0-or-later */
/* aft_march_internal.h — the march's workspace (aft_march.h), which its march (aft_march.c)
 * and its Jacobian (aft_march_jacobian.c) share. */
#ifndef FRICREG_JOINT_AFT_MARCH_INTERNAL_H
#define FRICREG_JOINT_AFT_MARCH_INTERNAL_H

#include "aft_internal.h"
#include "element_kind.h"
#include "enclosing_circle.h"

#define MAX_DIM 3
#define BLOCK 64 /* samples whose derivatives are transformed by one dgemm */

struct fr_aft_march {
    size_t N, nc, nstate; /* the room */
    size_t samples;       /* this call's N (aft's) */
    int dim;              /* this call's type's */
    double *us;           /* [3 N] u at the samples, component d's from d N */
    double *fs;           /* [3 N] f at the samples */
    double *ts;           /* [9 N] df/du at the samples, entry (a, c) from (3 a + c) N */
    double *x;            /* [N] one transform's samples */
    double *state;        /* [nstate] the march's state */
    double *start;        /* [nstate] the state at the period's start */
    double *kept;         /* [nstate] the march's state before Newton's, kept if it fails */
    double *fu;           /* [3 nc] the forces at u */
    double *ps, *pd;      /* [nstate] P(s); Newton's step */
    double *A;            /* [nn nn] I - P'(s), nn = min(nstate, MAX_NEWTON_STATES), by columns */
    int *piv;             /* [max(nn, 3)] its pivots, or a slider's */
    double *sens;         /* [nstate 3 nc] S = d state / d u, row-major */
    double *psi;          /* [nstate 3] each slider's Psi_s, its td x td block from td td s */
    double *tsl, *twl;    /* [nstate 3] the sample's slider tangents t_s, T_s, laid out as psi */
    double *v;            /* [3 3 nc] V = Phi_n - S_s, or (I - Psi_s)'s right-hand sides */
    double *g;            /* [BLOCK 3 3 nc] d f_n / d u of a block's samples, one a row */
    double *wb;           /* [nc BLOCK] the transform's weights at those samples, by rows */
    double *phi;          /* [nc] the basis at a sample */
    int *slipped;         /* [nstate] 1 where slider s slipped in the settled period */
    double *snext;        /* [FR_STATE_TANGENTS_MAX 3 nc] a state law's S' (element_kind.h) */
    double psis[FR_STATE_TANGENTS_MAX * FR_STATE_TANGENTS_MAX]; /* its period's map, row-major */
    double *tturn, *uturn; /* [N] a 1-D law's turn before sample n: its angle (NaN: none), u */
    size_t hi[MAX_DIM], lo[MAX_DIM]; /* the samples of u's largest and smallest components */
    struct fr_circle circle;         /* two tangential components: the orbit's enclosing circle */
};

/* The turns of a 1-D orbit u[nc] (find = 1; else none): where u' changes sign between
 * samples n - 1 and n (sample -1 the last of the period before), the angle where u' = 0 into
 * w->tturn[n] (by the AFT's Brent solver, GSL's) and u there into w->uturn[n]; NaN where it has none
 * (aft_march_turns.c). */
void fr_aft_march_turns(const fricreg_aft *a, struct fr_aft_march *w, const double *u, int find);

/* The basis phi_j at the angle theta into phi[nc]: 1, cos theta, sin theta, cos 2 theta, ... */
void fr_aft_march_basis_at(const fricreg_aft *a, double theta, double *phi);

/* The exact Jacobian of a law with state, d f / d u [dim nc x dim nc] row-major, into jac, from
 * the settled march in w (its start, samples and turns; aft_march_jacobian.c). */
void fr_aft_march_sensitivities(const fricreg_aft *a, struct fr_aft_march *w,
                                const fricreg_element_type *type, const double *params,
                                double *jac);

#endif
