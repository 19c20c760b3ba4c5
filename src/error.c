/* error.c — fr_error_set: the one place where a failure's message is formatted. */
#include <stdarg.h>
#include <stdio.h>

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
