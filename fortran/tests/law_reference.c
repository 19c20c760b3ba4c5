/* SPDX-License-Identifier: GPL-3.0-or-later */
/* law_reference.c — test helper: the laws evaluated from C, one fricreg_law_eval call per
 * point, for test_laws.f90 to compare with what module fricreg returns. */
#include <stddef.h>

#include "fricreg.h"

void fricreg_ref_law_grid(int law, double eps, size_t n, const double v[], const double f_eq[],
                          const double mun[], double f[], int status[])
{
    for (size_t i = 0; i < n; i++)
        status[i] = fricreg_law_eval(law, v[i], f_eq[i], mun[i], eps, &f[i]);
}
