/* SPDX-License-Identifier: GPL-3.0-or-later */
/* error.h — the last error of a context or a simulation: a status code and its message. */
#ifndef FRICREG_ERROR_H
#define FRICREG_ERROR_H

#include <stddef.h>

struct fr_error {
    int code;
    char msg[256];
};

/* Records code and a printf-style message in err, and returns code. */
int fr_error_set(struct fr_error *err, int code, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* Copies msg into buf[len], truncated and NUL-terminated; returns strlen(msg), or 0 and
 * writes nothing if buf is NULL or len is 0 (the errmsg_copy functions). */
size_t fr_error_copy(const char *msg, char *buf, size_t len);

/* Records a failure (code and printf-style message) as the last error of obj, any object
 * with a `struct fr_error err` member (a context, a 2-D context, a simulation, a structure),
 * and returns the code: `return fr_fail(ctx, FRICREG_EINVAL, "set_law: unknown law %d", law);` */
#define fr_fail(obj, ...) fr_error_set(&(obj)->err, __VA_ARGS__)

/* The three error getters of an object of the API (its header documents them): its last
 * error's code and message, null_message for a NULL object, and the message copied. One
 * definition for every object, whose type has a `struct fr_error err` member (FRICREG_OK from
 * fricreg.h): FR_ERROR_GETTERS(fricreg_hb, "NULL HB driver") defines fricreg_hb_errcode,
 * fricreg_hb_errmsg and fricreg_hb_errmsg_copy. */
#define FR_ERROR_GETTERS(type, null_message)                          \
    int type##_errcode(const type *obj)                               \
    {                                                                 \
        return obj ? obj->err.code : FRICREG_OK;                      \
    }                                                                 \
    const char *type##_errmsg(const type *obj)                        \
    {                                                                 \
        return obj ? obj->err.msg : null_message;                     \
    }                                                                 \
    size_t type##_errmsg_copy(const type *obj, char *buf, size_t len) \
    {                                                                 \
        return fr_error_copy(type##_errmsg(obj), buf, len);           \
    }

#endif
