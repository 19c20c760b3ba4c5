/* SPDX-License-Identifier: GPL-3.0-or-later */
/* own_integrator.c — fricreg inside the caller's own time stepper.
 *
 * The unforced oscillator of the paper's Eq. (5), x'' + x = f, mun = 1, from (2.75, 0), with a
 * plain classical RK4 loop of the caller's (no GSL) and law (4) at dt = 0.01, eps = 2 dt.
 * Quinn reports x -> -0.750090 (Sec. 3.1.1); the exact Coulomb rest point is -0.75. */
#include <stdio.h>

#include "fricreg.h"

/* The caller's right-hand side: (x, v)' = (v, -x + f), friction from the context. */
static int rhs(fricreg_ctx *ctx, const double y[2], double dydt[2])
{
    double a_free = -y[0], f = 0.0; /* free acceleration: f_eq = -a_free = x */
    int status = fricreg_ctx_eval(ctx, 1, &y[1], &a_free, &f, NULL);
    dydt[0] = y[1];
    dydt[1] = a_free + f;
    return status;
}

static int rk4_step(fricreg_ctx *ctx, double y[2], double h)
{
    double k[4][2], tmp[2];
    static const double stage[4] = {0.0, 0.5, 0.5, 1.0};
    int status = FRICREG_OK;
    for (int s = 0; s < 4 && status == FRICREG_OK; s++) {
        for (int i = 0; i < 2; i++)
            tmp[i] = y[i] + (s ? stage[s] * h * k[s - 1][i] : 0.0);
        status = rhs(ctx, tmp, k[s]);
    }
    for (int i = 0; i < 2 && status == FRICREG_OK; i++)
        y[i] += h / 6.0 * (k[0][i] + 2.0 * k[1][i] + 2.0 * k[2][i] + k[3][i]);
    return status;
}

int main(void)
{
    const double dt = 0.01;
    double y[2] = {2.75, 0.0};
    fricreg_ctx *ctx = NULL;
    int status = fricreg_ctx_create(1, &ctx);
    if (status == FRICREG_OK)
        status = fricreg_ctx_set_law(ctx, FRICREG_LAW_QUINN, 2.0 * dt);
    for (int n = 0; n < 2000 && status == FRICREG_OK; n++)
        status = rk4_step(ctx, y, dt);
    if (status != FRICREG_OK) {
        fprintf(stderr, "fricreg: %s\n", ctx ? fricreg_ctx_errmsg(ctx) : fricreg_strerror(status));
        fricreg_ctx_free(ctx);
        return 1;
    }
    printf("rest position x(20) = %.6f (paper: -0.750090, exact Coulomb: -0.75)\n", y[0]);
    fricreg_ctx_free(ctx);
    return 0;
}
