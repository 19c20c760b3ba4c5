/* SPDX-License-Identifier: GPL-3.0-or-later */
/* aft_march.h — the sampled AFT of any element type of fricreg_element.h, by its eval alone:
 * the law a harmonic-balance model (src/hb/) runs when no AFT of its own knows it, so that a
 * new law is one file and one table line there too (aft_march.c says how). */
#ifndef FRICREG_JOINT_AFT_MARCH_H
#define FRICREG_JOINT_AFT_MARCH_H

#include <stddef.h>

#include "fricreg_aft.h"
#include "fricreg_element.h"

/* The march's workspace: the samples of u, f and the tangent of elements of up to 3
 * components and nstate states at N samples and nc coefficients. */
struct fr_aft_march;

/* A workspace for N samples (a power of two), nc = 2H + 1 coefficients and elements of up to
 * nstate states, into *out; FRICREG_ENOMEM (*out NULL) if it cannot be allocated. */
int fr_aft_march_create(size_t N, size_t nc, size_t nstate, struct fr_aft_march **out);

void fr_aft_march_free(struct fr_aft_march *w);

/* The coefficients f[dim nc] (component d's at d nc, the layout of fricreg_aft.h) of the
 * element of the given type and params (checked by fricreg_element_explain) under the
 * displacement of coefficients u[dim nc], on aft's N samples (a 1-D law with state also at
 * the turns of u between them) (fricreg_aft_create with N at
 * most the workspace's); with jac, their Jacobian [dim nc x dim nc] row-major, d f / d u,
 * exact for the samples. w's N and nc cover aft's. FRICREG_OK, a status of the law's check at
 * a sample (u beyond its range), or FRICREG_EINVAL for a law with state but neither slider
 * nor state tangents (element_kind.h: none in the table), with nothing written. */
int fr_aft_march(const fricreg_aft *aft, struct fr_aft_march *w, const fricreg_element_type *type,
                 const double *params, const double *u, double *f, double *jac);

/* 1 where the march's forces lag the law's by a term in 1/N (a law with state of more than one
 * component: a return mapping from sample to sample, whose turns it does not step through), so
 * that Richardson's extrapolation over N and N/2 removes it; 0 where the march is exact at
 * the samples (no state, or one component: it steps through each turn). */
int fr_aft_march_lags(const fricreg_element_type *type);

#endif
