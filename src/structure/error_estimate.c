/* SPDX-License-Identifier: GPL-3.0-or-later */
/* error_estimate.c — fricreg_structure_set_error_estimate: an a-posteriori estimate of the
 * error of the peak displacements and of each contact's dissipation against the Coulomb
 * problem (eps -> 0) read from companion structures (estimate_companions.c, which also holds
 * the settings) at finer or coarser levels of (eps, dt): the estimates and the warning (the
 * public getters: estimate_read.c).
 *
 * The estimate of each quantity from q, q2 = q(eps / 2), q4 = q(eps / 4) (coarser: q(2 eps),
 * q(4 eps)) is base/companion_estimate.c's, fricreg_sim's too: Richardson's correction with the
 * observed order in range (kind ASYMPTOTIC), a safe bound below it (kind BOUND); one
 * companion (1.6's): 3 |q - q2| (kind ASSUMED). FRICREG_WARN_ERROR_ESTIMATE where half the
 * largest peak's or the summed dissipations' estimate (its central value, fr_estimate_exceeds)
 * exceeds the answer tolerance (fricreg_structure_set_answer_rtol), whatever the kind; the
 * same test decides where FRICREG_COMPANIONS_AUTO's screen doubts (fr_estimate_doubts). */
#include <math.h>
#include <string.h>

#include "base/companion_estimate.h"
#include "ctx/ctx_driver.h"
#include "fricreg_sim.h"
#include "structure_internal.h"

/* The estimate of one quantity from its values on s, its companion and (with two) the
 * second companion (base/companion_estimate.h, shared with fricreg_sim), its kind into *kind. */
static double estimate_of(const fricreg_structure *s, double q, double q2, double q4, int *kind)
{
    if (s->companion_level == FRICREG_COMPANIONS_COARSER)
        return fr_companion_estimate_coarser(s->estimate_on, q, q2, q4, kind);
    return fr_companion_estimate(s->estimate_on, q, q2, q4, kind);
}

/* The three structures along the path (the second companion is the first when there is one
 * companion only; estimate_of then ignores it). */
static const fricreg_structure *second(const fricreg_structure *s)
{
    const fricreg_structure *c = s->companion;
    return c->estimate_state == FR_ESTIMATE_ACTIVE ? c->companion : c;
}

/* Every step's peak takes in the turning points between its ends (peak.c), so a peak
 * converges at an order as a dissipation does, and its kind is read the same way. */
double fr_estimate_peak(const fricreg_structure *s, size_t i, int *kind)
{
    return estimate_of(s, s->peak[i], s->companion->peak[i], second(s)->peak[i], kind);
}

double fr_estimate_dissipation(const fricreg_structure *s, size_t j, int *kind)
{
    return estimate_of(s, s->energy.per_contact[j], s->companion->energy.per_contact[j],
                       second(s)->energy.per_contact[j], kind);
}

/* The estimate of joint element i's dissipation (the elements have no eps: their error is
 * dt's, along the same path). */
double fr_estimate_element_dissipation(const fricreg_structure *s, size_t i, int *kind)
{
    return estimate_of(s, s->el.dissipation[i], s->companion->el.dissipation[i],
                       second(s)->el.dissipation[i], kind);
}

/* One of the warning's two quantities: its value, its estimate, and the kind of the largest
 * estimate in it (the one that weighs most in a sum). */
struct judged {
    double q, err, largest;
    int kind;
};

static void add_estimate(struct judged *sum, double q, double err, int kind)
{
    sum->q += fabs(q);
    sum->err += err;
    if (err > sum->largest || sum->kind == 0)
        sum->largest = err, sum->kind = kind;
}

static void warn_above_tolerance(fricreg_structure *s, const char *what, const struct judged *x)
{
    fr_warn(&s->warnings, FRICREG_WARN_ERROR_ESTIMATE,
            "the error estimate %.3g of %s %.7g (kind %s) exceeds twice the answer tolerance "
            "%.3g of it (the estimate bounds the error at about twice its size): halve eps and "
            "dt, or raise --answer-rtol (set_answer_rtol)",
            x->err, what, x->q, fr_estimate_kind_name(x->kind), s->answer_rtol);
}

/* The warning's two quantities, the largest peak and the summed dissipations, with their
 * estimates; and the floors of fr_estimate_exceeds: what the contacts' band, |zdot| < eps,
 * moves in the run's time, and the work their bounds do over it. */
static void judge(const fricreg_structure *s, struct judged *peak, struct judged *D, double *band,
                  double *work)
{
    /* The peaks: the largest estimate against the largest peak (a building's drift is read at
     * its largest storey); the dissipations, contacts' and joint elements', summed. */
    *peak = (struct judged){0};
    *D = (struct judged){0};
    for (size_t i = 0; i < s->n; i++) {
        int kind;
        double err = fr_estimate_peak(s, i, &kind);
        peak->q = fmax(peak->q, fabs(s->peak[i]));
        if (err > peak->err || peak->kind == 0)
            peak->err = err, peak->kind = kind;
    }
    for (size_t j = 0; j < s->m; j++) {
        int kind;
        double err = fr_estimate_dissipation(s, j, &kind);
        add_estimate(D, s->energy.per_contact[j], err, kind);
    }
    for (size_t i = 0; i < s->el.me; i++) {
        int kind;
        double err = fr_estimate_element_dissipation(s, i, &kind);
        add_estimate(D, s->el.dissipation[i], err, kind);
    }
    *band = fr_ctx_eps(s->ctx) * s->t;
    *work = 0.0;
    for (size_t j = 0; j < s->m; j++)
        *work += s->mun[j] * *band;
}

int fr_estimate_doubts(const fricreg_structure *s, double *peak_err, double *dissipation_err)
{
    struct judged peak, D;
    double band, work;
    judge(s, &peak, &D, &band, &work);
    *peak_err = peak.err;
    *dissipation_err = D.err;
    return fr_estimate_exceeds(peak.err, peak.q, s->answer_rtol, band) ||
           fr_estimate_exceeds(D.err, D.q, s->answer_rtol, work);
}

void fr_estimate_check(fricreg_structure *s)
{
    if (s->estimate_state == FR_ESTIMATE_FAILED) {
        fr_warn(&s->warnings, FRICREG_WARN_ERROR_ESTIMATE,
                "no error estimate could be formed (reported as infinite): %s", s->estimate_msg);
        return;
    }
    if (s->estimate_state != FR_ESTIMATE_ACTIVE)
        return;
    struct judged peak, D;
    double band, work;
    judge(s, &peak, &D, &band, &work);
    if (fr_estimate_exceeds(peak.err, peak.q, s->answer_rtol, band))
        warn_above_tolerance(s, "the largest peak displacement", &peak);
    if (fr_estimate_exceeds(D.err, D.q, s->answer_rtol, work))
        warn_above_tolerance(s, "the summed dissipation", &D);
}

int fricreg_structure_set_answer_rtol(fricreg_structure *s, double rtol)
{
    if (s == NULL)
        return FRICREG_ENULL;
    if (!(rtol > 0.0 && rtol < INFINITY)) /* NaN fails both */
        return fr_fail(s, FRICREG_EINVAL, "set_answer_rtol: rtol = %g must be finite and > 0",
                       rtol);
    s->answer_rtol = rtol;
    return FRICREG_OK;
}

int fricreg_structure_get_peak_displacement(const fricreg_structure *s, size_t ndof, double peak[])
{
    if (s == NULL || peak == NULL)
        return FRICREG_ENULL;
    if (ndof != s->n)
        return FRICREG_ESIZE;
    memcpy(peak, s->peak, ndof * sizeof *peak);
    return FRICREG_OK;
}
