/* SPDX-License-Identifier: GPL-3.0-or-later */
/* estimate_read.c — the error estimate's public getters (fricreg_structure_get_*_error,
 * fricreg_structure_get_error_kind): each settles auto's screen first (estimate_companions.c:
 * where the coarser companions' estimate would warn now, the finer ones step from the start
 * and give it), then reads the estimator's numbers (error_estimate.c). The screen settles at
 * a read, not at each stepping call's end: a run made of many calls (a step at a time, an
 * adaptive run sampled every dt) is judged as a whole, not at its first calls, where the
 * quantities are small and a bound of kind BOUND doubts them. The structure is logically const
 * there: its results are unchanged; only which companions give the estimate is decided. */
#include <math.h>

#include "fricreg_sim.h"
#include "structure_internal.h"

/* FRICREG_OK when the estimate can be read (a run made one, the companion at s's time), auto's
 * screen settled first (fr_estimate_settle: the finer companions stepped where it doubts). */
static int estimate_ready(const fricreg_structure *s, size_t len, size_t expected, const void *out)
{
    if (s == NULL || out == NULL)
        return FRICREG_ENULL;
    if (s->estimate_state == FR_ESTIMATE_NONE || s->fresh || s->running)
        return FRICREG_EINVAL; /* no step since set_initial with the estimate on, or in a run */
    if (len != expected)
        return FRICREG_ESIZE;
    fr_estimate_settle((fricreg_structure *)s); /* logically const: see the header */
    return FRICREG_OK;
}

int fricreg_structure_get_peak_displacement_error(const fricreg_structure *s, size_t ndof,
                                                  double err[])
{
    int status = estimate_ready(s, ndof, s != NULL ? s->n : 0, err);
    if (status != FRICREG_OK)
        return status;
    for (size_t i = 0; i < ndof; i++)
        err[i] = s->estimate_state == FR_ESTIMATE_FAILED ? INFINITY
                                                         : fr_estimate_peak(s, i, &(int){0});
    return FRICREG_OK;
}

int fricreg_structure_get_dissipation_error(const fricreg_structure *s, size_t m, double err[])
{
    int status = estimate_ready(s, m, s != NULL ? s->m : 0, err);
    if (status != FRICREG_OK)
        return status;
    for (size_t j = 0; j < m; j++)
        err[j] = s->estimate_state == FR_ESTIMATE_FAILED ? INFINITY
                                                         : fr_estimate_dissipation(s, j, &(int){0});
    return FRICREG_OK;
}

int fricreg_structure_get_jenkins_dissipation_error(const fricreg_structure *s, size_t me,
                                                    double err[])
{
    int status = estimate_ready(s, me, s != NULL ? s->el.me : 0, err);
    if (status != FRICREG_OK)
        return status;
    for (size_t i = 0; i < me; i++)
        err[i] = s->estimate_state == FR_ESTIMATE_FAILED
                     ? INFINITY
                     : fr_estimate_element_dissipation(s, i, &(int){0});
    return FRICREG_OK;
}

/* The kind of quantity `quantity`'s i-th estimate (enum fricreg_estimated_quantity). */
static int kind_of(const fricreg_structure *s, int quantity, size_t i)
{
    int kind = FRICREG_EST_KIND_BOUND; /* a failed estimate: +infinity, a bound */
    if (s->estimate_state == FR_ESTIMATE_FAILED)
        return kind;
    if (quantity == FRICREG_EST_PEAK_DISPLACEMENT)
        fr_estimate_peak(s, i, &kind);
    else if (quantity == FRICREG_EST_DISSIPATION)
        fr_estimate_dissipation(s, i, &kind);
    else
        fr_estimate_element_dissipation(s, i, &kind);
    return kind;
}

int fricreg_structure_get_error_kind(const fricreg_structure *s, int quantity, size_t n, int kind[])
{
    if (s == NULL || kind == NULL)
        return FRICREG_ENULL; /* before the quantity is read, as the *_error getters */
    size_t expected;
    switch (quantity) {
    case FRICREG_EST_PEAK_DISPLACEMENT: expected = s->n; break;
    case FRICREG_EST_DISSIPATION: expected = s->m; break;
    case FRICREG_EST_ELEMENT_DISSIPATION: expected = s->el.me; break;
    default: return FRICREG_EINVAL;
    }
    int status = estimate_ready(s, n, expected, kind);
    if (status != FRICREG_OK)
        return status;
    for (size_t i = 0; i < n; i++)
        kind[i] = kind_of(s, quantity, i);
    return FRICREG_OK;
}
