/* SPDX-License-Identifier: GPL-3.0-or-later */
/* warning.h — an object's list of warnings (enum fricreg_warning of fricreg.h): at most one
 * entry per code, each with its message, recorded by the object's checks and never printed. */
#ifndef FRICREG_WARNING_H
#define FRICREG_WARNING_H

#include <stddef.h>

/* Room for every code of enum fricreg_warning (FRICREG_WARN_TOL_LOOSE = 10) and those to come. */
#define FR_WARN_MAX 16

struct fr_warnings {
    size_t n;
    struct {
        int code;
        char msg[256];
    } w[FR_WARN_MAX];
};

/* Empties the list. */
void fr_warnings_clear(struct fr_warnings *list);

/* Appends code with a printf-style message, unless the list holds code already (a warning is
 * recorded once) or is full. */
void fr_warn(struct fr_warnings *list, int code, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

#endif
