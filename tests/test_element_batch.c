/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_element_batch.c — Check suite for fricreg_element_eval_batch (fricreg_element.h): many
 * points of one type in one call.
 *
 * Where the numbers come from:
 *   - fricreg_element_eval point by point, the function the batch promises to equal bit for
 *     bit, for every type of the table, parameters shared and per point;
 *   - jenkins under u = A sin t at several amplitudes at once: the dissipation per cycle
 *     4 mun (A - mun/kt) (test_element.c derives it; the samples hit the turns, so it holds to
 *     rounding);
 *   - the header's failure promises: the status, the point named, and nothing written. */
#include <check.h>
#include <math.h>
#include <string.h>

#include "fricreg_element.h"
#include "quiet_check.h"

#define SENTINEL (-777.125)
#define NPOINTS 7
#define NS 3
#define MAXP (2 * NS + 3)
#define MAXS (3 * NS)

static double uniform(unsigned long *seed, double lo, double hi)
{
    *seed = *seed * 6364136223846793005UL + 1442695040888963407UL;
    return lo + (hi - lo) * (double)(*seed >> 11) / 9007199254740992.0;
}

/* In-range parameters of type t at point i: stiffnesses near 2, bounds near 0.7 (mu for a
 * normal type), a preload near 1 with kn near 3, no gap. */
static void point_params(const fricreg_element_type *t, unsigned long *seed, double *p)
{
    size_t ns = fricreg_element_nsliders(t), np = fricreg_element_nparams(t);
    if (np == 1) { /* spring */
        p[0] = uniform(seed, 1.0, 3.0);
        return;
    }
    for (size_t s = 0; s < ns; s++) {
        p[s] = uniform(seed, 1.0, 3.0);
        p[ns + s] = uniform(seed, 0.3, 1.0);
    }
    if (np > 2 * ns) {
        p[2 * ns] = uniform(seed, 2.0, 4.0);
        p[2 * ns + 1] = uniform(seed, 0.5, 1.5);
        p[2 * ns + 2] = 0.0;
    }
}

/* Every type of the table (the families with NS sliders), its batch against its points. */
static void check_type_bitwise(const fricreg_element_type *t, int shared)
{
    unsigned long seed = 12345;
    size_t dim = (size_t)fricreg_element_dim(t), np = fricreg_element_nparams(t);
    size_t nst = fricreg_element_nstate(t), stride = shared ? 0 : np;
    double p[NPOINTS * MAXP], w[NPOINTS * MAXS + 1], u[NPOINTS * 3];
    for (size_t i = 0; i < NPOINTS; i++)
        point_params(t, &seed, p + np * i);
    for (size_t k = 0; k < NPOINTS * nst; k++)
        w[k] = uniform(&seed, -0.5, 0.5);
    for (size_t k = 0; k < NPOINTS * dim; k++)
        u[k] = uniform(&seed, -1.0, 1.0);

    double f[NPOINTS * 3], dfdu[NPOINTS * 9], dfdp[NPOINTS * 3 * MAXP], wn[NPOINTS * MAXS + 1];
    QUIET_OK(fricreg_element_eval_batch(t, NPOINTS, p, stride, w, u, f, dfdu, dfdp, wn, NULL));
    for (size_t i = 0; i < NPOINTS; i++) {
        double fi[3], ti[9], qi[3 * MAXP], wi[MAXS + 1];
        QUIET_OK(fricreg_element_eval(t, p + stride * i, w + nst * i, u + dim * i, fi, ti, qi, wi));
        ck_assert_msg(memcmp(fi, f + dim * i, dim * sizeof *fi) == 0, "%s: f at %zu",
                      fricreg_element_name(t), i);
        ck_assert(memcmp(ti, dfdu + dim * dim * i, dim * dim * sizeof *ti) == 0);
        ck_assert(memcmp(qi, dfdp + dim * np * i, dim * np * sizeof *qi) == 0);
        ck_assert(memcmp(wi, wn + nst * i, nst * sizeof *wi) == 0);
    }
    /* The tangents left out, and the state updated in place: the same forces and state. */
    double f2[NPOINTS * 3];
    QUIET_OK(fricreg_element_eval_batch(t, NPOINTS, p, stride, w, u, f2, NULL, NULL, w, NULL));
    ck_assert(memcmp(f2, f, NPOINTS * dim * sizeof *f) == 0);
    ck_assert(memcmp(w, wn, NPOINTS * nst * sizeof *w) == 0);
}

START_TEST(test_every_type_equals_its_points)
{
    for (size_t k = 0; k < fricreg_element_count(); k++) {
        const fricreg_element_type *t = fricreg_element_at(k);
        const fricreg_element_type *many = fricreg_element_sliders(t, NS);
        if (many != NULL)
            t = many;
        check_type_bitwise(t, 1);
        check_type_bitwise(t, 0);
    }
}
END_TEST

/* Six jenkins elements of different amplitudes, one call per time sample: each dissipates
 * 4 mun (A - mun/kt) a cycle after its first quarter. */
START_TEST(test_jenkins_loops_at_once)
{
    const fricreg_element_type *t = fricreg_element_lookup("jenkins");
    const double kt = 2.0, mun = 0.5, p[2] = {kt, mun};
    enum { N = 6, STEPS = 4000 };
    double amp[N], w[N] = {0}, f[N], u[N], w0[N], diss[N] = {0};
    for (int i = 0; i < N; i++)
        amp[i] = 0.3 + 0.2 * i; /* mun/kt = 0.25: every one slides */
    /* the first quarter, then one whole cycle, sampled so that the turns are hit */
    for (int s = 0; s <= STEPS + STEPS / 4; s++) {
        double ts = 2.0 * 3.14159265358979323846 * s / STEPS;
        for (int i = 0; i < N; i++)
            u[i] = amp[i] * sin(ts);
        memcpy(w0, w, sizeof w);
        QUIET_OK(fricreg_element_eval_batch(t, N, p, 0, w, u, f, NULL, NULL, w, NULL));
        if (s > 0)
            for (int i = 0; i < N; i++)
                diss[i] += f[i] * (w[i] - w0[i]); /* f = +-mun wherever w moves */
        if (s == STEPS / 4)                       /* at the first turn */
            memset(diss, 0, sizeof diss);
    }
    for (int i = 0; i < N; i++) {
        double exact = 4.0 * mun * (amp[i] - mun / kt);
        ck_assert_msg(fabs(diss[i] - exact) <= 1e-12 * exact, "A = %g: %.17g against %.17g", amp[i],
                      diss[i], exact);
    }
}
END_TEST

/* The header's failures: status, bad_point and no output written. */
START_TEST(test_failures_write_nothing)
{
    const fricreg_element_type *t = fricreg_element_lookup("jenkins");
    double p[2 * 4] = {2.0, 0.5, 2.0, 0.5, 2.0, 0.5, 2.0, 0.5};
    double w[4] = {0}, u[4] = {0.1, 0.2, 0.3, 0.4}, f[4], wn[4];
    size_t bad = 99;
    for (int k = 0; k < 4; k++)
        f[k] = wn[k] = SENTINEL;

    ck_assert_int_eq(fricreg_element_eval_batch(NULL, 4, p, 0, w, u, f, NULL, NULL, wn, &bad),
                     FRICREG_ENULL);
    ck_assert_uint_eq(bad, 4);
    bad = 99;
    ck_assert_int_eq(fricreg_element_eval_batch(t, 4, p, 0, w, NULL, f, NULL, NULL, wn, &bad),
                     FRICREG_ENULL);
    ck_assert_uint_eq(bad, 4);
    bad = 99;
    ck_assert_int_eq(fricreg_element_eval_batch(t, 4, p, 1, w, u, f, NULL, NULL, wn, &bad),
                     FRICREG_EINVAL); /* a stride below nparams = 2 */
    ck_assert_uint_eq(bad, 4);

    u[2] = NAN;
    ck_assert_int_eq(fricreg_element_eval_batch(t, 4, p, 0, w, u, f, NULL, NULL, wn, &bad),
                     FRICREG_ENONFINITE);
    ck_assert_uint_eq(bad, 2);
    u[2] = 0.3;
    p[2 * 3] = -1.0; /* point 3's kt, per point */
    ck_assert_int_eq(fricreg_element_eval_batch(t, 4, p, 2, w, u, f, NULL, NULL, wn, &bad),
                     FRICREG_EINVAL);
    ck_assert_uint_eq(bad, 3);
    char msg[128];
    ck_assert_int_eq(fricreg_element_explain(t, p + 2 * 3, w + 3, u + 3, msg, sizeof msg),
                     FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(msg, "kt = -1"));
    for (int k = 0; k < 4; k++) {
        ck_assert(f[k] == SENTINEL);
        ck_assert(wn[k] == SENTINEL);
    }
    /* the same point's parameters shared: point 0 already fails */
    ck_assert_int_eq(fricreg_element_eval_batch(t, 4, p + 6, 0, w, u, f, NULL, NULL, wn, &bad),
                     FRICREG_EINVAL);
    ck_assert_uint_eq(bad, 0);

    bad = 99;
    QUIET_OK(
        fricreg_element_eval_batch(NULL, 0, NULL, 0, NULL, NULL, NULL, NULL, NULL, NULL, &bad));
    ck_assert_uint_eq(bad, 99);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("element_batch");
    TCase *tc = tcase_create("core");
    tcase_add_test(tc, test_every_type_equals_its_points);
    tcase_add_test(tc, test_jenkins_loops_at_once);
    tcase_add_test(tc, test_failures_write_nothing);
    suite_add_tcase(s, tc);
    SRunner *sr = srunner_create(s);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? 0 : 1;
}
