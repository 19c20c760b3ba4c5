/* SPDX-License-Identifier: GPL-3.0-or-later */
/* mex_args.c — the gateway's argument checks and errors (mex_args.h). */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "mex_args.h"
#include "fricreg.h"

void mexa_error(const char *id, const char *fmt, ...)
{
    char msg[1024];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    /* the message through "%s": a '%' in it (a value, a name) is not a conversion */
    mexErrMsgIdAndTxt(id, "%s", msg);
}

const char *mexa_status_name(int status, char *buf, size_t len)
{
    switch (status) {
    case FRICREG_OK: return "OK";
    case FRICREG_ENULL: return "ENULL";
    case FRICREG_EINVAL: return "EINVAL";
    case FRICREG_ENONFINITE: return "ENONFINITE";
    case FRICREG_ESIZE: return "ESIZE";
    case FRICREG_ENOMEM: return "ENOMEM";
    case FRICREG_ENOTSYM: return "ENOTSYM";
    case FRICREG_ENOTPSD: return "ENOTPSD";
    case FRICREG_ESINGULAR: return "ESINGULAR";
    case FRICREG_ESTEP: return "ESTEP";
    case FRICREG_EDIVERGED: return "EDIVERGED";
    case FRICREG_EINTEGRATOR: return "EINTEGRATOR";
    case FRICREG_EWORK: return "EWORK";
    default: snprintf(buf, len, "E%d", status); return buf;
    }
}

void mexa_status(int status, const char *where, const char *detail)
{
    char name[32], id[48];
    const char *n = mexa_status_name(status, name, sizeof name);
    snprintf(id, sizeof id, "fricreg:%s", n);
    if (detail == NULL || detail[0] == '\0')
        detail = fricreg_strerror(status);
    mexa_error(id, "%s: %s (FRICREG_%s)", where, detail, n);
}

void mexa_append(char *buf, size_t len, const char *text)
{
    size_t used = strlen(buf);
    if (used + 1 < len)
        snprintf(buf + used, len - used, "%s", text);
}

void mexa_nargs(const char *cmd, int nrhs, int min_rhs, int max_rhs, int nlhs, int max_lhs)
{
    if (nrhs < min_rhs || nrhs > max_rhs) {
        if (min_rhs == max_rhs)
            mexa_error("fricreg:nargs", "%s: takes %d arguments after the command, not %d", cmd,
                       min_rhs, nrhs);
        mexa_error("fricreg:nargs", "%s: takes %d to %d arguments after the command, not %d", cmd,
                   min_rhs, max_rhs, nrhs);
    }
    if (nlhs > max_lhs)
        mexa_error("fricreg:nargs", "%s: gives at most %d outputs, not %d", cmd, max_lhs, nlhs);
}

void mexa_real(const mxArray *a, const char *cmd, const char *name)
{
    if (!mxIsDouble(a) || mxIsComplex(a) || mxIsSparse(a))
        mexa_error("fricreg:type", "%s: %s must be a real, full double array, not %s%s%s", cmd,
                   name, mxIsComplex(a) ? "complex " : "", mxIsSparse(a) ? "sparse " : "",
                   mxGetClassName(a));
}

double mexa_scalar(const mxArray *a, const char *cmd, const char *name)
{
    mexa_real(a, cmd, name);
    if (mxGetNumberOfElements(a) != 1)
        mexa_error("fricreg:size", "%s: %s must be a scalar, not %d elements", cmd, name,
                   (int)mxGetNumberOfElements(a));
    return mxGetPr(a)[0];
}

size_t mexa_count(const mxArray *a, const char *cmd, const char *name, size_t lo, size_t hi)
{
    double x = mexa_scalar(a, cmd, name);
    if (!(x >= (double)lo && x <= (double)hi && x == floor(x)))
        mexa_error("fricreg:EINVAL",
                   "%s: %s = %g must be a whole number in %lu..%lu (FRICREG_EINVAL)", cmd, name, x,
                   (unsigned long)lo, (unsigned long)hi);
    return (size_t)x;
}

int mexa_is_size(const mxArray *a, size_t rows, size_t cols)
{
    return mxGetNumberOfDimensions(a) == 2 && (size_t)mxGetM(a) == rows &&
           (size_t)mxGetN(a) == cols;
}

int mexa_is_vector(const mxArray *a)
{
    return mxGetNumberOfDimensions(a) == 2 && mxGetNumberOfElements(a) >= 1 &&
           (mxGetM(a) == 1 || mxGetN(a) == 1);
}

const double *mexa_vector(const mxArray *a, const char *cmd, const char *name, size_t n,
                          size_t *len)
{
    size_t got;
    mexa_real(a, cmd, name);
    got = (size_t)mxGetNumberOfElements(a);
    if (got > 0 && !mexa_is_vector(a))
        mexa_error("fricreg:size", "%s: %s must be a vector, not %dx%d%s", cmd, name,
                   (int)mxGetM(a), (int)mxGetN(a), mxGetNumberOfDimensions(a) > 2 ? "x..." : "");
    if (n != (size_t)-1 && got != n)
        mexa_error("fricreg:size", "%s: %s must have %lu elements, not %lu", cmd, name,
                   (unsigned long)n, (unsigned long)got);
    if (len != NULL)
        *len = got;
    return got > 0 ? mxGetPr(a) : NULL;
}

void mexa_string(const mxArray *a, const char *cmd, const char *name, char *buf, size_t len)
{
    if (!mxIsChar(a) || mxGetNumberOfDimensions(a) != 2 || mxGetM(a) > 1)
        mexa_error("fricreg:type", "%s: %s must be a character row vector (a string), not %s", cmd,
                   name, mxGetClassName(a));
    if ((size_t)mxGetNumberOfElements(a) >= len || mxGetString(a, buf, (mwSize)len) != 0)
        mexa_error("fricreg:size", "%s: %s is longer than %lu characters", cmd, name,
                   (unsigned long)(len - 1));
}

int mexa_pick(const mxArray *a, const char *cmd, const char *what, const char *const names[],
              int count)
{
    char name[32], list[160] = "";
    mexa_string(a, cmd, what, name, sizeof name);
    for (int i = 0; i < count; i++) {
        if (strcmp(name, names[i]) == 0)
            return i;
        mexa_append(list, sizeof list, i ? ", " : "");
        mexa_append(list, sizeof list, names[i]);
    }
    mexa_error("fricreg:EINVAL", "%s: %s '%s' is not one of %s (FRICREG_EINVAL)", cmd, what, name,
               list);
    return -1;
}

mxArray *mexa_matrix(size_t rows, size_t cols)
{
    return mxCreateDoubleMatrix((mwSize)rows, (mwSize)cols, mxREAL);
}

mxArray *mexa_array3(size_t n1, size_t n2, size_t n3)
{
    mwSize dims[3];
    dims[0] = (mwSize)n1;
    dims[1] = (mwSize)n2;
    dims[2] = (mwSize)n3;
    return mxCreateNumericArray(3, dims, mxDOUBLE_CLASS, mxREAL);
}

void mexa_outputs(int nlhs, mxArray *plhs[], mxArray *out[], int n)
{
    for (int k = 0; k < n; k++) {
        if (k < nlhs || k == 0)
            plhs[k] = out[k];
        else
            mxDestroyArray(out[k]);
    }
}

double *mexa_scratch(size_t n)
{
    return mxCalloc(n > 0 ? n : 1, sizeof(double));
}

void mexa_to_rows(const double *src, double *dst, size_t rows, size_t cols)
{
    for (size_t c = 0; c < cols; c++)
        for (size_t i = 0; i < rows; i++)
            dst[cols * i + c] = src[i + rows * c];
}

void mexa_to_cols(const double *src, double *dst, size_t rows, size_t cols)
{
    for (size_t c = 0; c < cols; c++)
        for (size_t i = 0; i < rows; i++)
            dst[i + rows * c] = src[cols * i + c];
}
