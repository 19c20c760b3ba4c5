/* SPDX-License-Identifier: GPL-3.0-or-later */
/* gsl_guard.h — keeps GSL's default error handler, which aborts, out of fricreg's calls.
 *
 * Every call into GSL that can report an error is bracketed by fr_gsl_quiet() and
 * fr_gsl_restore(): the caller's handler is put back afterwards. GSL's handler is one
 * process-wide pointer, so a program that calls GSL from other threads at the same time should
 * call gsl_set_error_handler_off() once itself (docs/usage.md, "Errors and threads"). */
#ifndef FRICREG_GSL_GUARD_H
#define FRICREG_GSL_GUARD_H

#include <gsl/gsl_errno.h>

static inline gsl_error_handler_t *fr_gsl_quiet(void)
{
    return gsl_set_error_handler_off();
}

static inline void fr_gsl_restore(gsl_error_handler_t *previous)
{
    gsl_set_error_handler(previous);
}

#endif
