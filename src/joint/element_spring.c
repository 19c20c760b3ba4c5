/* SPDX-License-Identifier: GPL-3.0-or-later */
/* element_spring.c — the element type spring (fricreg_element.h): a linear spring f = k u on
 * one component, without state, the table's simplest law (a joint's linear stiffness beside
 * its friction elements) and the pattern of a new one: sizes, check, eval and what a
 * structure needs, in one file and one line of element_table.c. */
#include <math.h>

#include "element_kind.h"

static size_t one(size_t ns)
{
    (void)ns;
    return 1;
}

static size_t none(size_t ns)
{
    (void)ns;
    return 0;
}

static int check(const fricreg_element_type *type, const double *p, const double *state,
                 const double *u, char *msg, size_t len)
{
    (void)type;
    (void)state;
    if (!isfinite(p[0]))
        return fr_element_say(FRICREG_ENONFINITE, msg, len, "spring: k = %g (params[0])", p[0]);
    if (!(p[0] > 0.0))
        return fr_element_say(FRICREG_EINVAL, msg, len, "spring: k = %g must be > 0 (params[0])",
                              p[0]);
    if (u != NULL && !(isfinite(u[0]) && isfinite(p[0] * u[0])))
        return fr_element_say(FRICREG_ENONFINITE, msg, len, "spring: u[0] = %g, k u = %g", u[0],
                              p[0] * u[0]);
    return FRICREG_OK;
}

static void eval(const fricreg_element_type *type, const double *p, const double *state_in,
                 const double *u, double *f, double *dfdu, double *dfdp, double *state_out,
                 double *slider_forces)
{
    (void)type;
    (void)state_in;
    (void)state_out;
    (void)slider_forces;
    f[0] = p[0] * u[0];
    if (dfdu != NULL)
        dfdu[0] = p[0];
    if (dfdp != NULL)
        dfdp[0] = u[0];
}

static void elastic(const fricreg_element_type *type, const double *p, double *k)
{
    (void)type;
    k[0] = p[0];
}

/* A spring carries any force. */
static void project(const fricreg_element_type *type, const double *p, double *f)
{
    (void)type;
    (void)p;
    (void)f;
}

/* f^2 / (2 k); no normal spring. */
static double stored(const fricreg_element_type *type, const double *p, const double *fs,
                     const double *f, int normal, double sum)
{
    (void)type;
    (void)fs;
    return normal ? sum : sum + 0.5 * f[0] * (f[0] / p[0]);
}

const struct fr_element_kind fr_element_spring = {.name = "spring",
                                                  .dim = 1,
                                                  .aft = FR_ELEMENT_AFT_MARCH,
                                                  .nparams = one,
                                                  .nstate = none,
                                                  .check = check,
                                                  .eval = eval,
                                                  .elastic = elastic,
                                                  .project = project,
                                                  .stored = stored};
