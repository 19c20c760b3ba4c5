/* SPDX-License-Identifier: GPL-3.0-or-later */
/* fuzz_element.c — fuzz target: the element types of host codes (include/fricreg_element.h):
 * any type of the list with 1 to 8 sliders for the Iwan families, its parameters, state and
 * displacement from the input (moderate, special or any bits), with and without the tangents.
 * Contract: the status is OK or one the docstring names for these inputs (EINVAL,
 * ENONFINITE; ENULL cannot arise), and fricreg_element_explain returns the same with a
 * message naming the type; on failure nothing is written; on success every output is finite,
 * the tangential force keeps its bound |f_t| <= sum_s b_s (times N with a normal law, N >= 0
 * and 0 while open) up to its rounding (tangential_bound), and the same call again (the
 * state given as state_out too) gives the same bits. */
#include "fuzz_input.h"

#include "fricreg_element.h"

enum { MAX_SLIDERS = 8, MAX_PARAMS = 2 * MAX_SLIDERS + 3, MAX_STATE = 3 * MAX_SLIDERS };

#define SUBNORMAL_QUANTUM 4.9406564584124654e-324

/* The bound of the tangential force of a slider type: sum_s b_s, times N with a normal law (f[dim - 1]), plus
 * its rounding (fricreg_element_eval's docstring): 1e-12 of it, and 4 k_s subnormal quanta a
 * slider (|u - w| below DBL_MIN keeps only absolute precision: a stick judged on it may hold
 * k_s |u - w| a few quanta of k_s above b_s, as fricreg_aft.h's rounding of kt u). */
static double tangential_bound(const fricreg_element_type *t, const double *p, const double *f,
                               int normal)
{
    size_t ns = fricreg_element_nsliders(t);
    if (fricreg_element_nstate(t) == 0) /* a law without sliders (spring): no bound */
        return INFINITY;
    double b = 0.0, k = 0.0;
    for (size_t s = 0; s < ns; s++) {
        b += p[ns + s];
        k += p[s];
    }
    if (normal)
        b *= f[fricreg_element_dim(t) - 1];
    return b * (1.0 + 1e-12) + 4.0 * k * SUBNORMAL_QUANTUM + 64.0 * SUBNORMAL_QUANTUM;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    struct fuzz_input in = {data, size, 0};
    const fricreg_element_type *base = fricreg_element_at(fuzz_byte(&in) % fricreg_element_count());
    const fricreg_element_type *t = fricreg_element_sliders(base, 1 + fuzz_byte(&in) % MAX_SLIDERS);
    if (t == NULL) /* a type without sliders in parallel */
        t = base;
    int dim = fricreg_element_dim(t), want = fuzz_byte(&in) % 4;
    size_t np = fricreg_element_nparams(t), nst = fricreg_element_nstate(t);
    int normal = np == 2 * fricreg_element_nsliders(t) + 3;
    double p[MAX_PARAMS], w[MAX_STATE], u[3];
    for (size_t j = 0; j < np; j++)
        p[j] = fuzz_double(&in);
    for (size_t j = 0; j < nst; j++)
        w[j] = fuzz_double(&in);
    for (int a = 0; a < dim; a++)
        u[a] = fuzz_double(&in);

    double f[3], dfdu[9], dfdp[3 * MAX_PARAMS], wo[MAX_STATE];
    fuzz_fill(f, sizeof f);
    fuzz_fill(dfdu, sizeof dfdu);
    fuzz_fill(dfdp, sizeof dfdp);
    fuzz_fill(wo, sizeof wo);
    double *tu = (want & 1) ? dfdu : NULL, *tp = (want & 2) ? dfdp : NULL;
    int status = fricreg_element_eval(t, p, w, u, f, tu, tp, wo);
    char msg[256];
    int said = fricreg_element_explain(t, p, w, u, msg, sizeof msg);
    FUZZ_REQUIRE(said == status, "explain %d, eval %d", said, status);
    if (status != FRICREG_OK) {
        FUZZ_REQUIRE(status == FRICREG_EINVAL || status == FRICREG_ENONFINITE, "status %d", status);
        FUZZ_REQUIRE(strstr(msg, fricreg_element_name(t)) == msg, "message '%s'", msg);
        FUZZ_REQUIRE(fuzz_untouched(f, sizeof f) && fuzz_untouched(dfdu, sizeof dfdu) &&
                         fuzz_untouched(dfdp, sizeof dfdp) && fuzz_untouched(wo, sizeof wo),
                     "%s: written on failure (%d)", fricreg_element_name(t), status);
        return 0;
    }
    FUZZ_REQUIRE(msg[0] == '\0', "a message on success: '%s'", msg);
    FUZZ_REQUIRE(fuzz_all_finite(f, (size_t)dim) && fuzz_all_finite(wo, nst), "not finite");
    FUZZ_REQUIRE(tu == NULL || fuzz_all_finite(dfdu, (size_t)(dim * dim)), "tangent");
    FUZZ_REQUIRE(tp == NULL || fuzz_all_finite(dfdp, (size_t)dim * np), "dfdp");
    double ft = 0.0;
    for (int a = 0; a < dim - normal; a++)
        ft = hypot(ft, f[a]);
    double bound = tangential_bound(t, p, f, normal);
    FUZZ_REQUIRE(!normal || f[dim - 1] >= 0.0, "N = %g", f[dim - 1]);
    FUZZ_REQUIRE(ft <= bound, "%s: |f_t| = %.17g above its bound %.17g", fricreg_element_name(t),
                 ft, bound);
    /* pure: again, in place */
    double f2[3], d2[9], q2[3 * MAX_PARAMS], w2[MAX_STATE];
    memcpy(w2, w, nst * sizeof *w);
    FUZZ_REQUIRE(fricreg_element_eval(t, p, w2, u, f2, tu ? d2 : NULL, tp ? q2 : NULL, w2) ==
                     FRICREG_OK,
                 "the same call failed");
    FUZZ_REQUIRE(fuzz_same_bits(f, f2, (size_t)dim) && fuzz_same_bits(wo, w2, nst) &&
                     (tu == NULL || fuzz_same_bits(dfdu, d2, (size_t)(dim * dim))) &&
                     (tp == NULL || fuzz_same_bits(dfdp, q2, (size_t)dim * np)),
                 "%s: not the same bits again", fricreg_element_name(t));
    return 0;
}
