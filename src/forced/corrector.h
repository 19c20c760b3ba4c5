/* SPDX-License-Identifier: GPL-3.0-or-later */
/* corrector.h — a branch being followed (its parameter, scales and last points) and the
 * bordered Newton corrector on it (corrector.c): what the continuation loop (arclength.c), the
 * bifurcations' bisection (bifurcations.c) and the peak search (peak.c) all solve with. */
#ifndef FRICREG_HB_CORRECTOR_H
#define FRICREG_HB_CORRECTOR_H

#include <stddef.h>

#include "forced_internal.h"
#include "hb/step_control.h"

/* A branch being followed: its parameter and scales, and the points the loop moves along it
 * (views into the continuation's yp and yo); the peak search sets only the scales. */
struct fr_hb_branch {
    int level;       /* the parameter p is the excitation level λ at the fixed Ω omega, else Ω */
    double omega;    /* a level branch's Ω */
    const char *par; /* the parameter's name in messages */
    int keep;        /* the points are stored (a public continuation), else only counted */
    int end_only;    /* only the branch's end is wanted (the start's): slow correctors and a
                        crawl are given up (arclength.c, corrector.c) */
    size_t count;    /* the points reached */
    double qs, ws;   /* the scales: y = (q/qs, p/ws) */
    double *yc;      /* [nq + 1] the last point, scaled */
    double *yp;      /* [nq + 1] the predictor */
    double *yo;      /* [nq + 1] the point before, scaled (have_prev) */
    int have_prev;
    double delta, kappa; /* the last corrector's first step and contraction */
    char why[256];       /* the last failed step's message */
};

/* The Ω of the branch's point of parameter p. */
static inline double fr_hb_branch_omega(const struct fr_hb_branch *b, double p)
{
    return b->level ? b->omega : p;
}

/* The sign of the determinant of the LU factor in A (order ld, pivots piv2). */
double fr_hb_det_sign(const fricreg_hb *hb, size_t ld);

/* The scaled residual at y into R[nq + 1] and the bordered matrix [R_q, R_p ws/qs; row^T] into
 * A (unfactored), the factors, forces and unscaled q (qt) left at y. */
int fr_hb_bordered(fricreg_hb *hb, const char *fn, const struct fr_hb_branch *b, const double *y,
                   const double *row);

/* The unit tangent into t from the bordered matrix in A (factored in place), oriented along
 * its border row. */
int fr_hb_tangent(fricreg_hb *hb, const char *fn, double *t);

/* Newton's method with a line search on (R) bordered by border^T (y − anchor) = 0, from start
 * into qw; *its its iterations, b->delta and b->kappa its first step and contraction. On
 * success A holds the bordered matrix at qw, unfactored (fr_hb_tangent's input). */
int fr_hb_corrector(fricreg_hb *hb, const char *fn, struct fr_hb_branch *b, const double *start,
                    const double *anchor, const double *border, int *its);

#endif
