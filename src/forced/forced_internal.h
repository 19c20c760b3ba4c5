/* SPDX-License-Identifier: GPL-3.0-or-later */
/* forced_internal.h — the forced response's own state on the driver: the branch last
 * continued (its points, their unknowns and extras, the bifurcations located on it), hung on
 * the driver as hb->forced with its release, and the layout of the continuation's vectors on
 * the room the driver keeps for them (hb->cont). Included only inside src/forced/
 * (tests/module_layers.sh). */
#ifndef FRICREG_FORCED_INTERNAL_H
#define FRICREG_FORCED_INTERNAL_H

#include <stddef.h>

#include "hb/hb_internal.h"

/* The branch of the last fricreg_hb_continue or fricreg_hb_continue_level: its points [npts
 * (1 + n)], Ω then the n RMS values; each point's unknowns (q, then the parameter) in qpts
 * [npts (nq + 1)], for fricreg_hb_peak and the bisections; each point's extras [cap XW]: the
 * tangent's parameter component, the sign of the bordered matrix's determinant, then
 * (stability on) stable (1/0), the largest |multiplier|, and the 2n Floquet exponents (re,
 * im); and the located bifurcations [cap (4 + n)]: the type (enum
 * fricreg_hb_bifurcation_type), Ω, the point before, λ, the n RMS values. */
struct fr_hb_forced {
    double *pts, *qpts;
    size_t npts, cap, qpts_stride; /* qpts holds cap points of qpts_stride = nq + 1 */
    double *xpts, *bifs;
    size_t xpts_stride, nbif;
    double branch_qs, branch_ws; /* the branch's scales */
    int branch_level; /* the branch is in the level λ at fixed Ω (qpts's last entry is λ) */
    /* the driver's serials when the branch was begun: its unknowns hold while the model's is
     * the same, its points while the extras' is (fr_hb_points_held) */
    unsigned long model_serial, extras_serial;
};

/* The continuation's vectors, each [nq + 1], on the driver's room for them. */
struct fr_hb_vectors {
    double *tan; /* the tangent */
    double *yp;  /* [2 (nq + 1)]: the last point, then the predictor */
    double *yo;  /* the point before the last (the secant) */
    double *tn;  /* the tangent at the corrected point */
    double *dir; /* the predictor's direction and border */
    double *yl;  /* the corrector's line search base */
};

/* The vectors laid out on hb->cont for the elements held now (nq). */
static inline struct fr_hb_vectors fr_hb_vectors(const fricreg_hb *hb)
{
    size_t ld = hb->nq + 1;
    double *v = hb->cont;
    return (struct fr_hb_vectors){v, v + ld, v + 3 * ld, v + 4 * ld, v + 5 * ld, v + 6 * ld};
}

/* The points of the stored branch that still hold: none if none was stored or stability was
 * turned on or off since (their extras have another width). */
static inline size_t fr_hb_points_held(const fricreg_hb *hb)
{
    const struct fr_hb_forced *f = hb->forced;
    return f != NULL && f->extras_serial == hb->extras_serial ? f->npts : 0;
}

/* The bifurcations located on it that still hold, likewise. */
static inline size_t fr_hb_bifurcations_held(const fricreg_hb *hb)
{
    const struct fr_hb_forced *f = hb->forced;
    return f != NULL && f->extras_serial == hb->extras_serial ? f->nbif : 0;
}

/* Whether the stored points' unknowns still solve the model (no change of it since). */
static inline int fr_hb_branch_holds(const fricreg_hb *hb)
{
    return fr_hb_points_held(hb) > 0 && hb->forced->model_serial == hb->model_serial;
}

#endif
