/* SPDX-License-Identifier: GPL-3.0-or-later */
/* fuzz_law.c — fuzz target: fricreg_law_eval and fricreg_law_eval_batch, every law id (and
 * unknown ones), against their contract in include/fricreg.h: the status is the one the
 * docstring names for the inputs given (or one of them, when several are wrong); the output
 * is untouched on failure; on success f is finite, |f| <= mun, Coulomb's f = -mun sgn(v), and
 * at v = 0 the laws with a force balance give f = clamp(f_eq, -mun, mun) (Eq. 2; (4) at v = 0
 * and Karnopp inside its band); the batch equals the scalar law element by element, also when
 * f aliases v or f_eq. */
#include "fuzz_input.h"

#include "fricreg.h"

enum { MAX_BATCH = 16 };

static int known_law(int law)
{
    return fricreg_law_name(law) != NULL;
}

static int uses_feq(int law)
{
    return law == FRICREG_LAW_FORCE_BALANCE || law == FRICREG_LAW_KARNOPP ||
           law == FRICREG_LAW_QUINN;
}

static int eps_invalid(double eps)
{
    return isfinite(eps) && !(eps >= DBL_MIN);
}

/* The codes the docstring allows for these law parameters: a bit per code. */
static unsigned law_param_codes(int law, double eps)
{
    unsigned codes = 0;
    if (!known_law(law) || eps_invalid(eps))
        codes |= 1u << FRICREG_EINVAL;
    if (!isfinite(eps))
        codes |= 1u << FRICREG_ENONFINITE;
    return codes;
}

static void check_force(int law, double v, double f_eq, double mun, double eps, double f)
{
    FUZZ_REQUIRE(isfinite(f), "law %d v %g f_eq %g mun %g eps %g: f %g", law, v, f_eq, mun, eps, f);
    FUZZ_REQUIRE(fabs(f) <= mun, "law %d v %g f_eq %g mun %g eps %g: |f| %g > mun", law, v, f_eq,
                 mun, eps, f);
    if (law == FRICREG_LAW_COULOMB) {
        double expected = v > 0.0 ? -mun : v < 0.0 ? mun : 0.0;
        FUZZ_REQUIRE(f == expected, "Coulomb v %g mun %g: f %g", v, mun, f);
    }
    int at_rest = v == 0.0 && uses_feq(law);
    if (law == FRICREG_LAW_KARNOPP)
        at_rest = fabs(v) < eps;
    if (at_rest) {
        double expected = f_eq > mun ? mun : f_eq < -mun ? -mun : f_eq;
        FUZZ_REQUIRE(f == expected, "law %d at rest v %g f_eq %g mun %g eps %g: f %g, not %g", law,
                     v, f_eq, mun, eps, f, expected);
    }
}

static void fuzz_scalar(struct fuzz_input *in, int law)
{
    double v = fuzz_double(in), f_eq = fuzz_double(in), mun = fuzz_double(in);
    double eps = fuzz_double(in);
    int null_out = fuzz_byte(in) == 7;
    double f;
    fuzz_fill(&f, sizeof f);
    int status = fricreg_law_eval(law, v, f_eq, mun, eps, null_out ? NULL : &f);

    unsigned codes = law_param_codes(law, eps);
    if (null_out)
        codes |= 1u << FRICREG_ENULL;
    if (!isfinite(v) || !isfinite(f_eq) || !isfinite(mun))
        codes |= 1u << FRICREG_ENONFINITE;
    if (mun < 0.0)
        codes |= 1u << FRICREG_EINVAL;
    if (codes == 0) {
        FUZZ_REQUIRE(status == FRICREG_OK, "law %d v %g f_eq %g mun %g eps %g: status %d", law, v,
                     f_eq, mun, eps, status);
        check_force(law, v, f_eq, mun, eps, f);
    } else {
        FUZZ_REQUIRE(status > 0 && status < 32 && (codes >> status & 1u),
                     "law %d v %g f_eq %g mun %g eps %g: status %d, allowed mask %#x", law, v, f_eq,
                     mun, eps, status, codes);
        FUZZ_REQUIRE(fuzz_untouched(&f, sizeof f), "f written on failure (status %d)", status);
    }
}

/* Which array the batch's output is: its own, v's or f_eq's (the header allows both). */
enum batch_out { OUT_OWN, OUT_ALIAS_V, OUT_ALIAS_FEQ };

static void fuzz_batch(struct fuzz_input *in, int law)
{
    double eps = fuzz_double(in);
    size_t m = fuzz_byte(in) % (MAX_BATCH + 1);
    uint8_t mode = fuzz_byte(in);
    int feq_null = mode & 1, v_null = mode == 0xfe, mun_null = mode == 0xfc;
    enum batch_out out = (enum batch_out)((mode >> 1) % 3);
    if (feq_null && out == OUT_ALIAS_FEQ)
        out = OUT_OWN;
    double v[MAX_BATCH], f_eq[MAX_BATCH], mun[MAX_BATCH], own[MAX_BATCH];
    double v0[MAX_BATCH], f_eq0[MAX_BATCH];
    for (size_t i = 0; i < m; i++) {
        v[i] = fuzz_double(in);
        f_eq[i] = fuzz_double(in);
        mun[i] = fabs(fuzz_double(in));
        if (fuzz_byte(in) == 3)
            mun[i] = -mun[i] - 1.0;
    }
    fuzz_fill(own, sizeof own);
    memcpy(v0, v, sizeof v);
    memcpy(f_eq0, f_eq, sizeof f_eq);
    double *f = out == OUT_ALIAS_V ? v : out == OUT_ALIAS_FEQ ? f_eq : own;
    int status = fricreg_law_eval_batch(law, eps, m, v_null ? NULL : v, feq_null ? NULL : f_eq,
                                        mun_null ? NULL : mun, f);

    unsigned codes = law_param_codes(law, eps);
    if (m > 0 && codes == 0) { /* the array checks of the docstring */
        if (v_null || mun_null || (feq_null && uses_feq(law)))
            codes |= 1u << FRICREG_ENULL;
        for (size_t i = 0; i < m && !v_null && !mun_null; i++) {
            if (!isfinite(v0[i]) || (!feq_null && !isfinite(f_eq0[i])) || !isfinite(mun[i]))
                codes |= 1u << FRICREG_ENONFINITE;
            if (mun[i] < 0.0)
                codes |= 1u << FRICREG_EINVAL;
        }
    }
    if (codes != 0) {
        FUZZ_REQUIRE(status > 0 && status < 32 && (codes >> status & 1u),
                     "batch law %d eps %g m %zu: status %d, allowed mask %#x", law, eps, m, status,
                     codes);
        FUZZ_REQUIRE(fuzz_same_bits(v, v0, m) && fuzz_same_bits(f_eq, f_eq0, m) &&
                         fuzz_untouched(own, sizeof own),
                     "batch wrote on failure (status %d)", status);
        return;
    }
    FUZZ_REQUIRE(status == FRICREG_OK, "batch law %d eps %g m %zu: status %d", law, eps, m, status);
    FUZZ_REQUIRE(out != OUT_OWN || fuzz_untouched(own + m, sizeof own - m * sizeof *own),
                 "batch wrote past f[m]");
    for (size_t i = 0; i < m; i++) {
        double scalar;
        int s = fricreg_law_eval(law, v0[i], feq_null ? 0.0 : f_eq0[i], mun[i], eps, &scalar);
        FUZZ_REQUIRE(s == FRICREG_OK, "scalar law refused what the batch took: %d", s);
        /* sat-form and clamp-form may differ by a few roundings of mun (src/law/law.h) */
        FUZZ_REQUIRE(fabs(f[i] - scalar) <= 4.0 * DBL_EPSILON * mun[i],
                     "batch law %d contact %zu: %.17g, scalar %.17g", law, i, f[i], scalar);
        check_force(law, v0[i], feq_null ? 0.0 : f_eq0[i], mun[i], eps, f[i]);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    struct fuzz_input in = {data, size, 0};
    while (!fuzz_done(&in)) {
        int law = fuzz_int(&in, 0, 8); /* 0 and 7: unknown */
        if (fuzz_byte(&in) & 1)
            fuzz_batch(&in, law);
        else
            fuzz_scalar(&in, law);
    }
    return 0;
}
