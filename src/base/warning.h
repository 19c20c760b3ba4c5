/* SPDX-License-Identifier: GPL-3.0-or-later */
/* warning.h — an object's list of warnings (enum fricreg_warning of fricreg.h): at most one
 * entry per code, each with its message, recorded by the object's checks and never printed. */
#ifndef FRICREG_WARNING_H
#define FRICREG_WARNING_H

#include <stddef.h>

/* Room for every code of enum fricreg_warning (FRICREG_WARN_NOT_ASYMPTOTIC = 14) and those to
 * come. */
#define FR_WARN_MAX 16

/* The handler's type (fricreg_warning_handler of fricreg.h), spelled here so that this floor-0
 * header includes no public one. */
typedef void (*fr_warning_handler)(int code, const char *message, void *user_data);

struct fr_warnings {
    size_t n;
    struct {
        int code;
        char msg[256];
    } w[FR_WARN_MAX];
    fr_warning_handler handler; /* NULL: the list is only read back (the default) */
    void *handler_data;
    unsigned delivered; /* bit c: code c went to the handler since the last forget */
};

/* Empties the list (the handler and what it was given are kept). */
void fr_warnings_clear(struct fr_warnings *list);

/* Installs fn (NULL: none) with its data; the new handler is owed every warning. */
void fr_warnings_set_handler(struct fr_warnings *list, fr_warning_handler fn, void *data);

/* Owes the handler every warning again: a fresh run's are news even where an earlier run
 * raised the same code. */
void fr_warnings_forget_delivered(struct fr_warnings *list);

/* Calls the handler once for each listed warning it has not been given since the last forget,
 * in the list's order. Nothing without a handler. The object marks itself busy around the call
 * (its `running` flag), so that the handler's calls into it are refused or judge nothing. */
void fr_warnings_deliver(struct fr_warnings *list);

/* Appends code with a printf-style message, unless the list holds code already (a warning is
 * recorded once) or is full. */
void fr_warn(struct fr_warnings *list, int code, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* Entry k of the list: its code into *code and its message into buf[len], NUL-terminated and
 * truncated to fit (nothing written if buf is NULL or len is 0). FRICREG_OK; FRICREG_ENULL if
 * code is NULL; FRICREG_EINVAL if k is not below the count (nothing written). */
int fr_warnings_get(const struct fr_warnings *list, size_t k, int *code, char *buf, size_t len);

/* Entry k's message, or "" if k is not below the count. */
const char *fr_warnings_message(const struct fr_warnings *list, size_t k);

#endif
