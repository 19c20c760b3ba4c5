/* SPDX-License-Identifier: GPL-3.0-or-later */
/* ctx_driver.h — internal: what the drivers above the context (fricreg_sim, fricreg_structure)
 * may use of it beyond the public API: its evaluation without the finiteness pass, read access
 * to eps, the bounds and W's diagonal, and the step guard's stiffness. Everything else of the
 * context's layout stays in ctx_internal.h, included only inside src/ctx/. */
#ifndef FRICREG_CTX_DRIVER_H
#define FRICREG_CTX_DRIVER_H

#include "fricreg.h"

/* fricreg_ctx_eval of m = fricreg_ctx_size(ctx) contacts without the finiteness pass, for a
 * caller that checks what it makes of f instead (fricreg_sim's fixed explicit steps, whose
 * state is checked after every step: a non-finite input carries into it through a_free or
 * zdot). With a diagonal W or a law that does not read f_eq and without Stribeck friction;
 * otherwise (the dense solve's range checks need finite inputs) fricreg_ctx_eval itself. The
 * status of fricreg_ctx_eval; FRICREG_OK on the unchecked path (partition.c). */
int fr_ctx_eval_unchecked(fricreg_ctx *ctx, const double zdot[], const double a_free[], double f[]);

/* The context's last error, for a driver's public function on the context that records its
 * own failures there (fricreg_ctx_errmsg then reads them). */
struct fr_error *fr_ctx_error(fricreg_ctx *ctx);

/* The law (enum fricreg_law) and its eps (fricreg_ctx_set_law). */
int fr_ctx_law(const fricreg_ctx *ctx);
double fr_ctx_eps(const fricreg_ctx *ctx);

/* The bounds mun [m] of fricreg_ctx_set_bounds, and W's diagonal [m] (all of W when it is
 * diagonal); owned by the context, valid until its next setter call. */
const double *fr_ctx_bounds(const fricreg_ctx *ctx);
const double *fr_ctx_coupling_diagonal(const fricreg_ctx *ctx);

/* The tangent of the last successful evaluation (fricreg_ctx_tangent) as one row per contact,
 * for a driver that solves with it without the m x m matrix (tangent_rows.c): implicit[i] = 0,
 * df_i = coef_i dzdot_i; implicit[i] = 1, [W df]_i + coef_i dzdot_i + dafree_i = 0 (the
 * consistent law's free contacts; a diagonal W's near-stick ones). implicit[m], coef[m] out.
 * FRICREG_OK; FRICREG_EINVAL where the tangent has no such rows (the paper's partition with a
 * coupled W and a near-stick set; not recorded) or where fricreg_ctx_tangent would refuse it
 * (recorded). */
int fr_ctx_tangent_rows(fricreg_ctx *ctx, unsigned char implicit[], double coef[]);

/* 1 when fr_ctx_tangent_rows can leave a driver the dense tangent instead (its refusal, or a
 * row of a falling bound, coef > 0 or 1 + c coef <= 0): Stribeck friction, or the paper's
 * partition on a coupled W with a law that reads f_eq; 0 when its rows always serve. A driver
 * that must not allocate in a step reserves its dense storage up front when this is 1. */
int fr_ctx_tangent_may_be_dense(const fricreg_ctx *ctx);

/* lambda * eps, finite where lambda = mun/eps overflows, so that the step guard can still name
 * the eps that passes (eps >= dt lambda eps / bound). chord = 0: the stick-zone stiffness of
 * fricreg_ctx_stick_stiffness. chord = 1: the chord stiffness of (1), (2) and Karnopp, their
 * jump 2 mun_i across the band 2 eps seen as the slope mun_i/eps of law (3), with (3)'s
 * coupling (the largest eigenvalue of D^1/2 W D^1/2 for a dense W). A fricreg status
 * (FRICREG_ENOMEM, recorded in ctx; stiffness.c). */
int fr_stiffness_times_eps(fricreg_ctx *ctx, int chord, double *rate);

/* A workspace a driver keeps in the context between its calls (fricreg_ctx_solve_step's
 * solver, contact_step_solver.c), so that a run of calls allocates and analyses once. The context
 * holds one: fr_ctx_workspace returns it (NULL: none); fr_ctx_keep_workspace hands one over
 * with the function that frees it (the one held before, if any, freed first);
 * fr_ctx_drop_workspace frees it. The context drops it itself in fricreg_ctx_free and in the
 * setters that change the law or the coupling (a new scene: the memory goes back). */
void *fr_ctx_workspace(const fricreg_ctx *ctx);
void fr_ctx_keep_workspace(fricreg_ctx *ctx, void *workspace, void (*release)(void *));
void fr_ctx_drop_workspace(fricreg_ctx *ctx);

/* What the context carries from one evaluation to the next that a later evaluation's rounding
 * depends on (ctx_carried.c), for a driver's checkpoint: the warm start, and with factor set the
 * cached factor of a dense W (the coupling in force is the driver's model's). Its size in bytes
 * (0 with factor and a sparse W, whose cached factor is not carried: no checkpoint), a copy
 * into out[size], and its restore from in[len] into a context of the same coupling kind and size
 * (FRICREG_OK; FRICREG_EINVAL, nothing changed, if len or an entry does not fit: not recorded). */
size_t fr_ctx_carried_size(const fricreg_ctx *ctx, int factor);
void fr_ctx_carried_save(const fricreg_ctx *ctx, int factor, unsigned char out[]);
int fr_ctx_carried_restore(fricreg_ctx *ctx, const unsigned char in[], size_t len, int factor);

#endif
