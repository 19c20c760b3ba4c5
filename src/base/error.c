/* SPDX-License-Identifier: GPL-3.0-or-later */
/* error.c — fr_error_set: the one place where a failure's message is formatted. */
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "error.h"

int fr_error_set(struct fr_error *err, int code, const char *fmt, ...)
{
    va_list ap;
    err->code = code;
    va_start(ap, fmt);
    vsnprintf(err->msg, sizeof err->msg, fmt, ap);
    va_end(ap);
    return code;
}

size_t fr_error_copy(const char *msg, char *buf, size_t len)
{
    if (buf == NULL || len == 0)
        return 0;
    snprintf(buf, len, "%s", msg);
    return strlen(msg);
}
