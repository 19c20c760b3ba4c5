/* SPDX-License-Identifier: GPL-3.0-or-later */
/* quickstart.c — a first complete program: one law, then two coupled contacts through a context.
 * Build: cc quickstart.c $(pkg-config --cflags --libs fricreg) or with CMake (fricreg::fricreg). */
#include <stdio.h>

#include "fricreg.h"

int main(void)
{
    /* Quinn's law (4) at rest: the force balances f_eq = 0.3 exactly, within mun = 0.5. */
    double f = 0.0;
    int status = fricreg_law_eval(FRICREG_LAW_QUINN, 0.0, 0.3, 0.5, 0.02, &f);
    if (status != FRICREG_OK) {
        fprintf(stderr, "%s\n", fricreg_strerror(status));
        return 1;
    }
    printf("law (4) at v = 0, f_eq = 0.3: f = %g\n", f);

    /* Two coupled contacts, z'' = a_free + W f, with the paper's Sec. 3.3 Delassus matrix. */
    const double W[4] = {1.0, -1.0, -1.0, 2.0}; /* row-major 2 x 2 */
    const double mun[2] = {0.5, 0.25};
    const double zdot[2] = {0.0, 0.0}; /* both contacts at rest: near-stick */
    const double a_free[2] = {-0.1, 0.05};
    double force[2], f_eq[2];
    fricreg_ctx *ctx = NULL;
    status = fricreg_ctx_create(2, &ctx);
    if (status == FRICREG_OK)
        status = fricreg_ctx_set_law(ctx, FRICREG_LAW_QUINN, 0.02);
    if (status == FRICREG_OK)
        status = fricreg_ctx_set_bounds(ctx, 2, mun);
    if (status == FRICREG_OK)
        status = fricreg_ctx_set_coupling_dense(ctx, 2, W);
    if (status == FRICREG_OK)
        status = fricreg_ctx_eval(ctx, 2, zdot, a_free, force, f_eq);
    if (status != FRICREG_OK) {
        fprintf(stderr, "fricreg: %s\n", ctx ? fricreg_ctx_errmsg(ctx) : fricreg_strerror(status));
        fricreg_ctx_free(ctx);
        return 1;
    }
    /* W f_eq = -a_free: f_eq = W^-1 (0.1, -0.05) = (0.15, 0.05), inside both bounds. */
    printf("f_eq = (%g, %g), f = (%g, %g)\n", f_eq[0], f_eq[1], force[0], force[1]);
    fricreg_ctx_free(ctx);
    return 0;
}
