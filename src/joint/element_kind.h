/* SPDX-License-Identifier: GPL-3.0-or-later */
/* element_kind.h — what an element type is inside (fricreg_element.h): a kind, one law's row
 * of the element table (element_table.c), and the number of sliders of its member. A new law
 * is one file defining its fr_element_kind and one line of the table. */
#ifndef FRICREG_JOINT_ELEMENT_KIND_H
#define FRICREG_JOINT_ELEMENT_KIND_H

#include <stddef.h>

#include "fricreg_element.h"

/* The harmonic-balance AFT a law runs on (src/hb/): its own exact one for 1-D sliders
 * (fricreg_aft_iwan_exact), for sliders with lift-off (fricreg_aft_jenkins_normal_exact), the
 * 3-D contact's sampled one, or, for any other law, the march of its eval (aft_march.h). */
enum fr_element_aft {
    FR_ELEMENT_AFT_MARCH = 0,
    FR_ELEMENT_AFT_SLIDERS,
    FR_ELEMENT_AFT_LIFTOFF,
    FR_ELEMENT_AFT_CONTACT_3D
};

/* One law. check and eval see only arrays of the sizes nparams and nstate give for the type's
 * ns; check has vetted eval's inputs, so eval cannot fail. */
struct fr_element_kind {
    const char *name;
    int dim;    /* components of u and f */
    int normal; /* 1: u's last component is the normal displacement g, f's the force N */
    int family; /* 1: a family of 1..FRICREG_ELEMENT_MAX_SLIDERS sliders in parallel */
    int aft;    /* enum fr_element_aft */
    size_t (*nparams)(size_t ns);
    size_t (*nstate)(size_t ns);
    /* The status of eval on these inputs (state and u NULL: the parameters alone; u NULL: the
     * parameters and state), a message into msg[len] where msg is not NULL. */
    int (*check)(const fricreg_element_type *type, const double *params, const double *state,
                 const double *u, char *msg, size_t len);
    /* f, dfdu (or NULL), dfdp (or NULL), state_out (may be state_in) from checked inputs, and
     * each slider's force (laid out as the state; NULL: not wanted), which a structure books
     * its energy by. */
    void (*eval)(const fricreg_element_type *type, const double *params, const double *state_in,
                 const double *u, double *f, double *dfdu, double *dfdp, double *state_out,
                 double *slider_forces);
    /* What a structure (src/structure/) needs besides eval, on checked parameters. Its state
     * is the positions of sliders whose forces eval gives, so that a step dissipates
     * sum dw . (f_s + f_s1) / 2 (a law without sliders has no state and dissipates nothing).
     * elastic: the stiffness of each of the dim components with every slider sticking and
     * the normal law closed, into k[dim] (the step guard, the fundamental frequency).
     * project: a force f[dim] (a Newton iterate) onto the forces the element can carry at
     * its own normal force f[dim - 1], in place (a slider's bound). stored: sum plus the
     * energy its springs hold at the slider forces fs (laid out as the state) and the force
     * f[dim], its tangential springs (normal = 0) or its normal one (1), added term by term
     * so that a structure's sum runs in one order whatever the elements. */
    void (*elastic)(const fricreg_element_type *type, const double *params, double *k);
    void (*project)(const fricreg_element_type *type, const double *params, double *f);
    double (*stored)(const fricreg_element_type *type, const double *params, const double *fs,
                     const double *f, int normal, double sum);
    /* What the march of harmonic balance (aft_march.c) chains its exact Jacobian with: at
     * checked params, state and u, each slider's d f_s / d u into ts and d w_s' / d w_s (its
     * position after the call by its position before) into tw, td x td blocks (row-major,
     * slider s's from td td s, td = dim - normal), and the state after the call into
     * state_out (eval's, bit for bit; it may be state). A slider's force depends on u - w_s
     * alone, so these two give every derivative of f and the state (d f_s / d w_s = -ts,
     * d w_s' / d u = I - tw). Required of a law of sliders that marches (aft MARCH); NULL
     * otherwise (a law with other state gives state_tangents). */
    void (*slider_tangents)(const fricreg_element_type *type, const double *params,
                            const double *state, const double *u, double *ts, double *tw,
                            double *state_out);
    /* fricreg_element_eval_batch once its arrays and stride are vetted: check's status at the
     * first point it refuses (its index into *bad, nothing else written), else eval at every
     * point, bit for bit; point i's params at params + params_stride i. A law's own loop, eval
     * inlined; NULL: check and eval per point (element_batch.c). */
    int (*batch)(const fricreg_element_type *type, size_t npoints, const double *params,
                 size_t params_stride, const double *state_in, const double *u, double *f,
                 double *dfdu, double *dfdp, double *state_out, size_t *bad);
    /* fricreg_element_eval once its pointers are vetted: check's status, nothing written if it
     * refuses, else eval's results. The law's own check and eval in one call; NULL: check,
     * then eval (element.c). */
    int (*point)(const fricreg_element_type *type, const double *params, const double *state_in,
                 const double *u, double *f, double *dfdu, double *dfdp, double *state_out);
    /* The march's tangents of a law with state that is not sliders' (at most
     * FR_STATE_TANGENTS_MAX states; slider_tangents NULL), at checked params, state and u:
     * d f / d u into fu[dim dim], d f / d state into fs[dim nstate], d state' / d u into
     * su[nstate dim] and d state' / d state into ss[nstate nstate] (row-major), and the state
     * after the call into state_out (eval's, bit for bit; it may be state). NULL otherwise. */
    void (*state_tangents)(const fricreg_element_type *type, const double *params,
                           const double *state, const double *u, double *fu, double *fs, double *su,
                           double *ss, double *state_out);
};

/* The most states of a law with state_tangents. */
#define FR_STATE_TANGENTS_MAX 8

/* A type: its kind, its sliders and, for a family, its first member (the type of 1 slider,
 * whose array holds the members in the order of ns). */
struct fricreg_element_type {
    const struct fr_element_kind *kind;
    size_t ns;
    const struct fricreg_element_type *family;
};

/* fricreg_element_eval's work on vetted pointers for a law without its own point, and the
 * points' way where their fast check doubts: the kind's check, then its eval where it accepts;
 * check's status. Out of line (element.c), so that the points' usual path saves no registers
 * for it and fricreg_element_eval reaches them by a tail call. */
#if defined(__GNUC__)
__attribute__((noinline))
#endif
int fr_element_check_then_eval(const fricreg_element_type *type, const double params[],
                               const double state_in[], const double u[], double f[],
                               double dfdu[], double dfdp[], double state_out[]);

/* Writes the message of a failed check into msg[len] (nothing if msg is NULL or len is 0) and
 * returns status. */
int fr_element_say(int status, char *msg, size_t len, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;

#endif
