/* SPDX-License-Identifier: GPL-3.0-or-later */
/* dual.h — forward differentiation of the modal backbone's closed forms: a number with its
 * derivatives along the model's parameters and the modal amplitude (FR_DUAL_N directions), so
 * that every sensitivity is exact and written once, by the formula it differentiates. */
#ifndef FRICREG_FIT_DUAL_H
#define FRICREG_FIT_DUAL_H

#include <math.h>

#include "fricreg_fit.h"

/* The directions: the parameters (enum fricreg_fit_param), then the modal amplitude a. */
#define FR_DUAL_A FRICREG_FIT_NPARAMS
#define FR_DUAL_N (FRICREG_FIT_NPARAMS + 1)

typedef struct {
    double v;
    double d[FR_DUAL_N];
} fr_dual;

static inline fr_dual fr_dual_const(double v)
{
    fr_dual x = {v, {0}};
    return x;
}

/* The variable of direction i, at v. */
static inline fr_dual fr_dual_var(double v, int i)
{
    fr_dual x = fr_dual_const(v);
    x.d[i] = 1.0;
    return x;
}

/* a x + b y, the one linear combination the rest build on. */
static inline fr_dual fr_dual_lin(double a, fr_dual x, double b, fr_dual y)
{
    fr_dual z;
    z.v = a * x.v + b * y.v;
    for (int i = 0; i < FR_DUAL_N; i++)
        z.d[i] = a * x.d[i] + b * y.d[i];
    return z;
}

static inline fr_dual fr_dual_add(fr_dual x, fr_dual y)
{
    return fr_dual_lin(1.0, x, 1.0, y);
}
static inline fr_dual fr_dual_sub(fr_dual x, fr_dual y)
{
    return fr_dual_lin(1.0, x, -1.0, y);
}

static inline fr_dual fr_dual_add_c(fr_dual x, double c)
{
    x.v += c;
    return x;
}

static inline fr_dual fr_dual_scale(double c, fr_dual x)
{
    return fr_dual_lin(c, x, 0.0, x);
}

static inline fr_dual fr_dual_mul(fr_dual x, fr_dual y)
{
    fr_dual z = fr_dual_lin(y.v, x, x.v, y);
    z.v = x.v * y.v;
    return z;
}

static inline fr_dual fr_dual_div(fr_dual x, fr_dual y)
{
    double q = x.v / y.v;
    fr_dual z = fr_dual_lin(1.0 / y.v, x, -q / y.v, y);
    z.v = q;
    return z;
}

/* f(x) by the chain rule, given f(x.v) and f'(x.v). */
static inline fr_dual fr_dual_chain(fr_dual x, double f, double df)
{
    fr_dual z = fr_dual_scale(df, x);
    z.v = f;
    return z;
}

static inline fr_dual fr_dual_log(fr_dual x)
{
    return fr_dual_chain(x, log(x.v), 1.0 / x.v);
}

static inline fr_dual fr_dual_sqrt(fr_dual x)
{
    double s = sqrt(x.v);
    return fr_dual_chain(x, s, 0.5 / s);
}

/* x^y for x > 0, both differentiated: d(x^y) = x^y d(y log x). */
static inline fr_dual fr_dual_pow(fr_dual x, fr_dual y)
{
    double p = pow(x.v, y.v);
    return fr_dual_chain(fr_dual_mul(y, fr_dual_log(x)), p, p);
}

#endif
