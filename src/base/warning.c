/* SPDX-License-Identifier: GPL-3.0-or-later */
/* warning.c — the warning codes' names, and an object's list of warnings (warning.h). */
#include <stdarg.h>
#include <stdio.h>

#include "error.h"
#include "fricreg.h"
#include "warning.h"

const char *fricreg_warning_name(int code)
{
    static const char *const names[] = {
        [FRICREG_WARN_NONE] = "none",
        [FRICREG_WARN_EPS_LARGE] = "eps_large",
        [FRICREG_WARN_EPS_SMALL] = "eps_small",
        [FRICREG_WARN_EPS_SPEED] = "eps_speed",
        [FRICREG_WARN_GROUND_PEAK] = "ground_peak",
        [FRICREG_WARN_BOUND_SCALE] = "bound_scale",
        [FRICREG_WARN_DT_COARSE] = "dt_coarse",
        [FRICREG_WARN_NEWTON_FAILURES] = "newton_failures",
        [FRICREG_WARN_NEWTON_SLOW] = "newton_slow",
        [FRICREG_WARN_ENERGY] = "energy",
        [FRICREG_WARN_TOL_LOOSE] = "tol_loose",
        [FRICREG_WARN_STRIBECK_EPS] = "stribeck_eps",
        [FRICREG_WARN_ERROR_ESTIMATE] = "error_estimate",
        [FRICREG_WARN_RECORD_SHORT] = "record_short",
        [FRICREG_WARN_NOT_ASYMPTOTIC] = "not_asymptotic",
    };
    if (code < 0 || (size_t)code >= sizeof names / sizeof names[0] || names[code] == NULL)
        return "unknown";
    return names[code];
}

void fr_warnings_clear(struct fr_warnings *list)
{
    list->n = 0;
}

void fr_warnings_set_handler(struct fr_warnings *list, fr_warning_handler fn, void *data)
{
    list->handler = fn;
    list->handler_data = data;
    list->delivered = 0;
}

void fr_warnings_forget_delivered(struct fr_warnings *list)
{
    list->delivered = 0;
}

void fr_warnings_deliver(struct fr_warnings *list)
{
    if (list->handler == NULL)
        return;
    for (size_t k = 0; k < list->n; k++) {
        int code = list->w[k].code; /* enum fricreg_warning: 0 .. FR_WARN_MAX - 1 */
        unsigned bit = code >= 0 && code < 32 ? 1u << code : 0u;
        if (list->delivered & bit)
            continue;
        list->delivered |= bit;
        list->handler(code, list->w[k].msg, list->handler_data);
    }
}

void fr_warn(struct fr_warnings *list, int code, const char *fmt, ...)
{
    for (size_t k = 0; k < list->n; k++)
        if (list->w[k].code == code)
            return;
    if (list->n == FR_WARN_MAX)
        return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(list->w[list->n].msg, sizeof list->w[list->n].msg, fmt, ap);
    va_end(ap);
    list->w[list->n++].code = code;
}

int fr_warnings_get(const struct fr_warnings *list, size_t k, int *code, char *buf, size_t len)
{
    if (code == NULL)
        return FRICREG_ENULL;
    if (k >= list->n)
        return FRICREG_EINVAL;
    *code = list->w[k].code;
    fr_error_copy(list->w[k].msg, buf, len);
    return FRICREG_OK;
}

const char *fr_warnings_message(const struct fr_warnings *list, size_t k)
{
    return k < list->n ? list->w[k].msg : "";
}
