/* SPDX-License-Identifier: GPL-3.0-or-later */
/* identify.c — a joint's parameters from a measured-style backbone (docs/identification.md).
 *
 * Makes the levels a stepped-sine test would give, from a known modal Iwan joint (near 170 Hz:
 * F_S 30, K_T 3e5, chi 0.3, beta 0.5, zeta0 0.002, K0 8.4e5; accelerations at a sensor of
 * mass-normalized shape 0.37) with 1 % noise in the damping ratios and 0.05 % in the
 * frequencies, writes them to measured.csv, fits all six parameters from the levels alone
 * (no start given), prints each with its 95 % interval and whether it holds the truth, and
 * writes fitted.csv: the fitted backbone on a fine grid with its 95 % band.
 * Usage: identify [DIR] (default: the current directory). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>

#include "fricreg_fit.h"

#define NP FRICREG_FIT_NPARAMS
#define NL 8
#define NGRID 60
#define SENSOR 0.37

static const char *const names[NP] = {"F_S", "K_T", "chi", "beta", "zeta0", "K0"};

static FILE *open_in(const char *dir, const char *name)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    return fopen(path, "w");
}

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : ".";
    const double truth[NP] = {30.0, 3e5, 0.3, 0.5, 0.002, 8.4e5};
    double A[NL], f[NL], z[NL], sf[NL], sz[NL];
    fricreg_fit *fit = NULL;
    if (fricreg_fit_create(&fit) != FRICREG_OK)
        return 1;
    fricreg_fit_set_sensor(fit, SENSOR);
    for (int i = 0; i < NL; i++) /* 2 to 100 m/s^2: microslip to past macroslip */
        A[i] = 2.0 * pow(50.0, i / 7.0);
    if (fricreg_fit_eval(fit, truth, FRICREG_FIT_ACCELERATION, NL, A, f, z, NULL, NULL, NULL)) {
        fprintf(stderr, "identify: %s\n", fricreg_fit_errmsg(fit));
        return 1;
    }
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937); /* seed 0: the default, reproducible */
    FILE *out = open_in(dir, "measured.csv");
    if (rng == NULL || out == NULL)
        return 1;
    fprintf(out, "accel_m_s2,freq_hz,zeta,sd_freq_hz,sd_zeta\n");
    for (int i = 0; i < NL; i++) {
        sf[i] = 5e-4 * f[i];
        sz[i] = 0.01 * z[i];
        f[i] += gsl_ran_gaussian(rng, sf[i]);
        z[i] += gsl_ran_gaussian(rng, sz[i]);
        fprintf(out, "%.6g,%.8g,%.6g,%.3g,%.3g\n", A[i], f[i], z[i], sf[i], sz[i]);
    }
    fclose(out);
    gsl_rng_free(rng);

    fricreg_fit_set_levels(fit, NL, FRICREG_FIT_ACCELERATION, A, f, z);
    fricreg_fit_set_deviations(fit, NL, sf, sz);
    if (fricreg_fit_run(fit) != FRICREG_OK) {
        fprintf(stderr, "identify: %s\n", fricreg_fit_errmsg(fit));
        return 1;
    }
    double p[NP], lo[NP], hi[NP], sv[NP], cost, q;
    int inside = 0;
    fricreg_fit_get_params(fit, NP, p);
    fricreg_fit_get_covariance(fit, NP, NULL, lo, hi);
    fricreg_fit_get_identifiability(fit, NP, sv, NULL);
    fricreg_fit_get_value(fit, FRICREG_FIT_COST, &cost);
    fricreg_fit_get_quantile(fit, &q);
    printf("fit of %d levels: chi-square %.3g (%d degrees of freedom)\n", NL, cost, 2 * NL - NP);
    for (int j = 0; j < NP; j++) {
        int holds = lo[j] <= truth[j] && truth[j] <= hi[j];
        inside += holds;
        printf("  %-5s = %-11.5g 95 %% [%.5g, %.5g]  truth %g%s\n", names[j], p[j], lo[j], hi[j],
               truth[j], holds ? "" : "  (outside)");
    }
    printf("singular values in log parameters: %.3g ... %.3g\n", sv[0], sv[NP - 1]);
    printf("truth inside the 95 %% intervals: %d of %d\n", inside, NP);

    double grid[NGRID], gf[NGRID], gz[NGRID], bf[NGRID], bz[NGRID];
    for (int k = 0; k < NGRID; k++)
        grid[k] = 1.0 * pow(200.0, k / (NGRID - 1.0));
    if (fricreg_fit_curve(fit, NGRID, grid, gf, gz, bf, bz) != FRICREG_OK ||
        (out = open_in(dir, "fitted.csv")) == NULL)
        return 1;
    fprintf(out, "accel_m_s2,freq_hz,zeta,freq_lo,freq_hi,zeta_lo,zeta_hi\n");
    for (int k = 0; k < NGRID; k++)
        fprintf(out, "%.6g,%.8g,%.6g,%.8g,%.8g,%.6g,%.6g\n", grid[k], gf[k], gz[k],
                gf[k] - q * bf[k], gf[k] + q * bf[k], gz[k] - q * bz[k], gz[k] + q * bz[k]);
    fclose(out);
    fricreg_fit_free(fit);
    return 0;
}
