/* SPDX-License-Identifier: GPL-3.0-or-later */
/* gsl_mem.c — GSL objects on memory fricreg allocates (gsl_mem.h): a header and its data in
 * one calloc'ed block, the data right after the header (header + 1 is aligned for the header,
 * whose size_t and pointer fields make that enough for a double or a size_t). */
#include <stdint.h>
#include <stdlib.h>

#include "gsl_mem.h"

/* calloc of a header of `head` bytes followed by n doubles, or NULL (also on overflow). */
static void *block(size_t head, size_t n)
{
    if (n > (SIZE_MAX - head) / sizeof(double))
        return NULL;
    return calloc(1, head + n * sizeof(double));
}

gsl_matrix *fr_gsl_matrix_new(size_t n1, size_t n2)
{
    if (n2 != 0 && n1 > SIZE_MAX / n2)
        return NULL;
    gsl_matrix *a = block(sizeof *a, n1 * n2);
    if (a != NULL)
        *a = (gsl_matrix){.size1 = n1, .size2 = n2, .tda = n2, .data = (double *)(a + 1)};
    return a;
}

gsl_vector *fr_gsl_vector_new(size_t n)
{
    gsl_vector *v = block(sizeof *v, n);
    if (v != NULL)
        *v = (gsl_vector){.size = n, .stride = 1, .data = (double *)(v + 1)};
    return v;
}

gsl_permutation *fr_gsl_permutation_new(size_t n)
{
    if (n > (SIZE_MAX - sizeof(gsl_permutation)) / sizeof(size_t))
        return NULL;
    gsl_permutation *p = calloc(1, sizeof *p + n * sizeof(size_t));
    if (p == NULL)
        return NULL;
    p->size = n;
    p->data = (size_t *)(p + 1);
    for (size_t k = 0; k < n; k++)
        p->data[k] = k;
    return p;
}

gsl_root_fsolver *fr_gsl_brent_new(void)
{
    size_t state = gsl_root_fsolver_brent->size;
    gsl_root_fsolver *s = block(sizeof *s, (state + sizeof(double) - 1) / sizeof(double));
    if (s != NULL)
        *s = (gsl_root_fsolver){.type = gsl_root_fsolver_brent, .state = s + 1};
    return s;
}
