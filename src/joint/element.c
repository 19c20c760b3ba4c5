/* SPDX-License-Identifier: GPL-3.0-or-later */
/* element.c — the public face of the element types (fricreg_element.h): the sizes, and init,
 * eval and explain, each a check of every input followed by the kind's own work. */
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "element_kind.h"

int fr_element_say(int status, char *msg, size_t len, const char *fmt, ...)
{
    if (msg != NULL && len > 0) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(msg, len, fmt, ap);
        va_end(ap);
    }
    return status;
}

const char *fricreg_element_name(const fricreg_element_type *type)
{
    return type != NULL ? type->kind->name : NULL;
}

int fricreg_element_dim(const fricreg_element_type *type)
{
    return type != NULL ? type->kind->dim : 0;
}

size_t fricreg_element_nparams(const fricreg_element_type *type)
{
    return type != NULL ? type->kind->nparams(type->ns) : 0;
}

size_t fricreg_element_nstate(const fricreg_element_type *type)
{
    return type != NULL ? type->kind->nstate(type->ns) : 0;
}

size_t fricreg_element_nsliders(const fricreg_element_type *type)
{
    return type != NULL ? type->ns : 0;
}

int fricreg_element_init(const fricreg_element_type *type, const double params[], double state[])
{
    if (type == NULL || params == NULL || state == NULL)
        return FRICREG_ENULL;
    int status = type->kind->check(type, params, NULL, NULL, NULL, 0);
    if (status != FRICREG_OK)
        return status;
    size_t nstate = type->kind->nstate(type->ns);
    for (size_t i = 0; i < nstate; i++)
        state[i] = 0.0;
    return FRICREG_OK;
}

int fr_element_check_then_eval(const fricreg_element_type *type, const double params[],
                               const double state_in[], const double u[], double f[], double dfdu[],
                               double dfdp[], double state_out[])
{
    int status = type->kind->check(type, params, state_in, u, NULL, 0);
    if (status == FRICREG_OK)
        type->kind->eval(type, params, state_in, u, f, dfdu, dfdp, state_out, NULL);
    return status;
}

int fricreg_element_eval(const fricreg_element_type *type, const double params[],
                         const double state_in[], const double u[], double f[], double dfdu[],
                         double dfdp[], double state_out[])
{
    if (type == NULL || params == NULL || state_in == NULL || u == NULL || f == NULL ||
        state_out == NULL)
        return FRICREG_ENULL;
    return (type->kind->point != NULL
                ? type->kind->point
                : fr_element_check_then_eval)(type, params, state_in, u, f, dfdu, dfdp, state_out);
}

int fricreg_element_explain(const fricreg_element_type *type, const double params[],
                            const double state_in[], const double u[], char *msg, size_t len)
{
    if (msg != NULL && len > 0)
        msg[0] = '\0';
    if (type == NULL || params == NULL)
        return fr_element_say(FRICREG_ENULL, msg, len, "%s is NULL",
                              type == NULL ? "type" : "params");
    /* One of state_in and u: eval's call, which refuses the missing one before any value. */
    if ((state_in == NULL) != (u == NULL))
        return fr_element_say(FRICREG_ENULL, msg, len,
                              "%s is NULL (eval needs state_in and u; both NULL explain init)",
                              state_in == NULL ? "state_in" : "u");
    return type->kind->check(type, params, state_in, u, msg, len);
}
