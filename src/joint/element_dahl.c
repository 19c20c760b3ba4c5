/* SPDX-License-Identifier: GPL-3.0-or-later */
/* element_dahl.c — the element type dahl (fricreg_element.h): Dahl's friction model with
 * exponent 1 (P. R. Dahl, "A solid friction model", Aerospace Corp. TOR-0158(3107-18)-1,
 * 1968), dF/du = sigma (1 - sgn(du) F / fc), a law with state that is not a slider's return
 * mapping: the table's example of one. Along an increment that does not reverse it integrates
 * exactly,
 *
 *     F = s fc - (s fc - F0) exp(-sigma |u - u0| / fc),   s = sgn(u - u0),
 *
 * from the force F0 at the displacement u0 the last call ended at. The state is the bristle's
 * root w, F0 = sigma (u0 - w), and u0: a slider position whose force eval gives, as a
 * structure books energy by (element_kind.h), beside u0, which carries no force. */
#include <math.h>

#include "element_kind.h"

static size_t two(size_t ns)
{
    (void)ns;
    return 2;
}

/* The sign of the increment d; at d = 0 the reversal's (against F0: the stiffer side, 1 + |F0|
 * / fc times sigma), +1 at F0 = 0. */
static double direction(double d, double F0)
{
    if (d != 0.0)
        return d > 0.0 ? 1.0 : -1.0;
    return F0 > 0.0 ? -1.0 : 1.0;
}

static int check(const fricreg_element_type *type, const double *p, const double *state,
                 const double *u, char *msg, size_t len)
{
    (void)type;
    double sigma = p[0], fc = p[1];
    for (int j = 0; j < 2; j++)
        if (!isfinite(p[j]))
            return fr_element_say(FRICREG_ENONFINITE, msg, len, "dahl: %s = %g (params[%d])",
                                  j == 0 ? "sigma" : "fc", p[j], j);
    if (!(sigma > 0.0))
        return fr_element_say(FRICREG_EINVAL, msg, len, "dahl: sigma = %g must be > 0 (params[0])",
                              sigma);
    if (!(fc > 0.0))
        return fr_element_say(FRICREG_EINVAL, msg, len, "dahl: fc = %g must be > 0 (params[1])",
                              fc);
    if (!isfinite(sigma / fc) || !isfinite(fc / sigma))
        return fr_element_say(FRICREG_ENONFINITE, msg, len,
                              "dahl: sigma / fc = %g overflows (sigma = %g, fc = %g)", sigma / fc,
                              sigma, fc);
    if (state == NULL)
        return FRICREG_OK;
    double F0 = sigma * (state[1] - state[0]);
    if (!isfinite(state[0]) || !isfinite(state[1]) || !isfinite(F0) || !isfinite(F0 / fc) ||
        !isfinite(sigma * (1.0 + fabs(F0) / fc)) || !isfinite((fc + fabs(F0)) / sigma))
        return fr_element_say(FRICREG_ENONFINITE, msg, len,
                              "dahl: state = (w %g, u0 %g): its force sigma (u0 - w) = %g or "
                              "its tangent overflows",
                              state[0], state[1], F0);
    if (u == NULL)
        return FRICREG_OK;
    double d = u[0] - state[1];
    if (!isfinite(u[0]) || !isfinite(d) || !isfinite(fabs(u[0]) + (fc + fabs(F0)) / sigma))
        return fr_element_say(FRICREG_ENONFINITE, msg, len,
                              "dahl: u[0] = %g, its increment from u0 = %g overflows", u[0],
                              state[1]);
    return FRICREG_OK;
}

/* One increment from state (w, u0) to u: the force, with E = exp(-sigma |d| / fc) and the
 * tangent T = df/du into *E, *T, the direction into *s (d = u - u0). */
static double increment(const double *p, const double *state, const double *u, double *E, double *T,
                        double *s)
{
    double sigma = p[0], fc = p[1], d = u[0] - state[1], F0 = sigma * (state[1] - state[0]);
    *s = direction(d, F0);
    *E = d != 0.0 ? exp(-(sigma / fc) * fabs(d)) : 1.0;
    *T = sigma * (1.0 - *s * (F0 / fc)) * *E;
    return *s * fc - (*s * fc - F0) * *E;
}

static void eval(const fricreg_element_type *type, const double *p, const double *state_in,
                 const double *u, double *f, double *dfdu, double *dfdp, double *state_out,
                 double *slider_forces)
{
    (void)type;
    double E, T, s, F = increment(p, state_in, u, &E, &T, &s);
    if (dfdu != NULL)
        dfdu[0] = T;
    if (dfdp != NULL) { /* F0 = sigma (u0 - w) moves with sigma too */
        double sigma = p[0], fc = p[1], d = fabs(u[0] - state_in[1]);
        double F0 = sigma * (state_in[1] - state_in[0]);
        dfdp[0] = (s * fc - F0) * E * (d / fc) + E * (state_in[1] - state_in[0]);
        dfdp[1] = s * (1.0 - E) - (s * fc - F0) * E * ((sigma / fc) * d / fc);
    }
    f[0] = F;
    state_out[0] = u[0] - F / p[0];
    state_out[1] = u[0];
    if (slider_forces != NULL) {
        slider_forces[0] = F;
        slider_forces[1] = 0.0;
    }
}

/* The march's tangents (element_kind.h): F depends on u, and on the state through
 * F0 = sigma (u0 - w) and d = u - u0; the state after is (u - F / sigma, u). */
static void state_tangents(const fricreg_element_type *type, const double *p, const double *state,
                           const double *u, double *fu, double *fs, double *su, double *ss,
                           double *state_out)
{
    (void)type;
    double sigma = p[0], E, T, s, F = increment(p, state, u, &E, &T, &s);
    fu[0] = T;
    fs[0] = -sigma * E;    /* d F / d w */
    fs[1] = sigma * E - T; /* d F / d u0 */
    su[0] = 1.0 - T / sigma;
    su[1] = 1.0;
    ss[0] = E; /* d w' / d w = -(d F / d w) / sigma */
    ss[1] = T / sigma - E;
    ss[2] = 0.0;
    ss[3] = 0.0;
    state_out[0] = u[0] - F / sigma;
    state_out[1] = u[0];
}

/* sigma: the stiffness at rest (F = 0); a reversal from F is stiffer, sigma (1 + |F| / fc). */
static void elastic(const fricreg_element_type *type, const double *p, double *k)
{
    (void)type;
    k[0] = p[0];
}

/* |F| <= fc: the force the bristles tend to. */
static void project(const fricreg_element_type *type, const double *p, double *f)
{
    (void)type;
    if (fabs(f[0]) > p[1])
        f[0] = copysign(p[1], f[0]);
}

/* The bristles' F^2 / (2 sigma); no normal spring. */
static double stored(const fricreg_element_type *type, const double *p, const double *fs,
                     const double *f, int normal, double sum)
{
    (void)type;
    (void)f;
    return normal ? sum : sum + 0.5 * fs[0] * (fs[0] / p[0]);
}

/* No sliders: harmonic balance's march chains its own state tangents. */
const struct fr_element_kind fr_element_dahl = {.name = "dahl",
                                                .dim = 1,
                                                .normal = 0,
                                                .family = 0,
                                                .aft = FR_ELEMENT_AFT_MARCH,
                                                .nparams = two,
                                                .nstate = two,
                                                .check = check,
                                                .eval = eval,
                                                .elastic = elastic,
                                                .project = project,
                                                .stored = stored,
                                                .state_tangents = state_tangents};
