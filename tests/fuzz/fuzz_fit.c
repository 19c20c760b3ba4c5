/* SPDX-License-Identifier: GPL-3.0-or-later */
/* fuzz_fit.c — fuzz target: the identification of a modal Iwan joint (include/fricreg_fit.h):
 * 1 to 9 levels of any kind, sensor, amplitudes, frequencies and damping ratios from the input
 * (moderate, special or any bits), deviations or none, some parameters fixed at input values,
 * 1 to 3 starts; and the model's eval at input parameters. Contract: every status is one the
 * header names (the setters' ENULL cannot arise); a run that fails reports nothing (the
 * getters refuse with EINVAL); a run that succeeds gives finite parameters in their ranges,
 * each inside its 95 % interval, a symmetric covariance with a non-negative diagonal, singular
 * values positive and largest first; an eval that fails writes nothing, one that succeeds gives
 * finite frequencies, damping ratios, modal amplitudes and sensitivities. */
#include "fuzz_input.h"

#include "fricreg_fit.h"

#define NP FRICREG_FIT_NPARAMS
#define MAX_LEVELS 9

static int in_range(int j, double v)
{
    if (!isfinite(v))
        return 0;
    if (j == FRICREG_FIT_FS || j == FRICREG_FIT_KT)
        return v > 0.0;
    return j == FRICREG_FIT_CHI ? v > -1.0 : v >= 0.0;
}

static void check_fit(fricreg_fit *fit, int status)
{
    double p[NP], cov[NP * NP], lo[NP], hi[NP], sv[NP];
    FUZZ_REQUIRE(status == FRICREG_OK || status == FRICREG_EINVAL || status == FRICREG_ENONFINITE ||
                     status == FRICREG_ESINGULAR || status == FRICREG_EWORK,
                 "run status %d", status);
    int got = fricreg_fit_get_params(fit, NP, p);
    if (status != FRICREG_OK) {
        FUZZ_REQUIRE(got == FRICREG_EINVAL, "a failed run reports a fit (%d)", got);
        return;
    }
    FUZZ_REQUIRE(got == FRICREG_OK, "get_params after a fit: %d", got);
    FUZZ_REQUIRE(fricreg_fit_get_covariance(fit, NP, cov, lo, hi) == FRICREG_OK, "covariance");
    FUZZ_REQUIRE(fricreg_fit_get_identifiability(fit, NP, sv, NULL) == FRICREG_OK, "sv");
    for (int j = 0; j < NP; j++) {
        FUZZ_REQUIRE(in_range(j, p[j]), "parameter %d = %g", j, p[j]);
        FUZZ_REQUIRE(lo[j] <= p[j] && p[j] <= hi[j], "parameter %d %g outside [%g, %g]", j, p[j],
                     lo[j], hi[j]);
        FUZZ_REQUIRE(cov[j * NP + j] >= 0.0, "variance %d = %g", j, cov[j * NP + j]);
        for (int i = 0; i < NP; i++)
            FUZZ_REQUIRE(cov[j * NP + i] == cov[i * NP + j], "covariance not symmetric");
    }
    double nfree;
    FUZZ_REQUIRE(fricreg_fit_get_value(fit, FRICREG_FIT_NFREE, &nfree) == FRICREG_OK, "nfree");
    for (int k = 0; k < (int)nfree; k++)
        FUZZ_REQUIRE(sv[k] > 0.0 && (k == 0 || sv[k] <= sv[k - 1]), "singular value %d", k);
}

static void check_eval(fricreg_fit *fit, struct fuzz_input *in)
{
    double p[NP], a[2], f[2], z[2], m[2], df[2 * NP], dz[2 * NP], keep[2];
    for (int j = 0; j < NP; j++)
        p[j] = fuzz_double(in);
    a[0] = fuzz_double(in);
    a[1] = fuzz_double(in);
    int kind = fuzz_byte(in) % 4; /* 3: unknown */
    fuzz_fill(f, sizeof f);
    memcpy(keep, f, sizeof keep);
    int st = fricreg_fit_eval(fit, p, kind, 2, a, f, z, m, df, dz);
    FUZZ_REQUIRE(st == FRICREG_OK || st == FRICREG_EINVAL || st == FRICREG_ENONFINITE,
                 "eval status %d", st);
    if (st != FRICREG_OK) {
        FUZZ_REQUIRE(memcmp(f, keep, sizeof f) == 0, "a failed eval wrote");
        return;
    }
    for (int i = 0; i < 2; i++) {
        FUZZ_REQUIRE(isfinite(f[i]) && isfinite(z[i]) && isfinite(m[i]), "eval not finite");
        for (int j = 0; j < NP; j++)
            FUZZ_REQUIRE(isfinite(df[i * NP + j]) && isfinite(dz[i * NP + j]),
                         "sensitivity not finite");
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    struct fuzz_input in = {data, size, 0};
    fricreg_fit *fit = NULL;
    if (fricreg_fit_create(&fit) != FRICREG_OK)
        return 0;
    size_t n = 1 + fuzz_byte(&in) % MAX_LEVELS;
    int kind = fuzz_byte(&in) % 3, with_sd = fuzz_byte(&in) % 2;
    double A[MAX_LEVELS], f[MAX_LEVELS], z[MAX_LEVELS], sf[MAX_LEVELS], sz[MAX_LEVELS];
    for (size_t i = 0; i < n; i++) {
        A[i] = fuzz_double(&in);
        f[i] = fuzz_double(&in);
        z[i] = fuzz_double(&in);
        sf[i] = fuzz_double(&in);
        sz[i] = fuzz_double(&in);
    }
    int st = fricreg_fit_set_sensor(fit, fuzz_double(&in));
    FUZZ_REQUIRE(st == FRICREG_OK || st == FRICREG_EINVAL || st == FRICREG_ENONFINITE, "sensor");
    st = fricreg_fit_set_levels(fit, n, kind, A, f, z);
    FUZZ_REQUIRE(st == FRICREG_OK || st == FRICREG_EINVAL || st == FRICREG_ENONFINITE, "levels");
    if (with_sd) {
        st = fricreg_fit_set_deviations(fit, n, sf, sz);
        FUZZ_REQUIRE(st == FRICREG_OK || st == FRICREG_EINVAL || st == FRICREG_ENONFINITE ||
                         st == FRICREG_ESIZE,
                     "deviations %d", st);
    }
    uint8_t fixed = fuzz_byte(&in);
    for (int j = 0; j < NP; j++)
        if (fixed >> j & 1) {
            st = fricreg_fit_set_fixed(fit, j, fuzz_double(&in));
            FUZZ_REQUIRE(st == FRICREG_OK || st == FRICREG_EINVAL || st == FRICREG_ENONFINITE,
                         "fixed %d", st);
        }
    fricreg_fit_set_starts(fit, 1 + fuzz_byte(&in) % 3);
    check_fit(fit, fricreg_fit_run(fit));
    check_eval(fit, &in);
    fricreg_fit_free(fit);
    return 0;
}
