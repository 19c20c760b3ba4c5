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
 *   - the header's failure promises: the status, the point named, and nothing written;
 *   - fricreg_element_explain, whose full check is the authority on what is refused: eval's and
 *     the batch's faster checks agree with it at every border value of every input. */
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

/* The values at the borders of eval's checks: NaN, the infinities, signed zeros, the
 * smallest subnormal, powers of 2 around the bounds its fast check uses (2^1012, 2^1020,
 * 2^1022) and the largest double. */
static const double BORDER_VALUES[] = {NAN,
                                       INFINITY,
                                       -INFINITY,
                                       0.0,
                                       -0.0,
                                       -1.0,
                                       0x1p-1074,
                                       0x1p1011,
                                       0x1p1012,
                                       0x1p1013,
                                       0x1p1020,
                                       0x1p1021,
                                       0x1p1022,
                                       -0x1p1022,
                                       0x1p1023,
                                       1.7976931348623157e308,
                                       -1.7976931348623157e308};
#define NBORDER (sizeof BORDER_VALUES / sizeof BORDER_VALUES[0])

/* eval, and the batch with the point at index BAD_AT among copies of the good point good
 * (params, state and u in a row), parameters per point and (where shared is set) shared, give
 * explain's status on the same inputs, the batch naming its bad point. */
#define BAD_AT 3
static void agrees_with_explain(const fricreg_element_type *t, const double *good, const double *p,
                                const double *w, const double *u, int shared)
{
    size_t dim = (size_t)fricreg_element_dim(t), np = fricreg_element_nparams(t);
    size_t nst = fricreg_element_nstate(t);
    int status = fricreg_element_explain(t, p, w, u, NULL, 0);
    double f[NPOINTS * 3], wn[NPOINTS * MAXS + 1];
    ck_assert_msg(fricreg_element_eval(t, p, w, u, f, NULL, NULL, wn) == status,
                  "%s: eval's status is not explain's %d", fricreg_element_name(t), status);
    double pp[NPOINTS * MAXP], ww[NPOINTS * MAXS + 1], uu[NPOINTS * 3];
    for (size_t i = 0; i < NPOINTS; i++) {
        int at = i == BAD_AT;
        memcpy(pp + np * i, at ? p : good, np * sizeof *p);
        memcpy(ww + nst * i, at ? w : good + np, nst * sizeof *w);
        memcpy(uu + dim * i, at ? u : good + np + nst, dim * sizeof *u);
    }
    for (int mode = 0; mode < 1 + shared; mode++) {
        size_t bad = 99, stride = mode == 0 ? np : 0;
        int got = fricreg_element_eval_batch(t, NPOINTS, mode == 0 ? pp : p, stride, ww, uu, f,
                                             NULL, NULL, wn, &bad);
        ck_assert_msg(got == status, "%s: the batch's status %d is not explain's %d (stride %zu)",
                      fricreg_element_name(t), got, status, stride);
        if (status != FRICREG_OK)
            ck_assert_uint_eq(bad, mode == 0 ? BAD_AT : 0);
    }
}

/* Every input of every slider type, one at a time, and every slider's stiffness, every
 * slider's bound and every component of u at once, at each border value: the checks eval and the batch run for speed (element_sliders.c's
 * fast check, then check where it doubts) refuse exactly what explain's full check refuses. */
START_TEST(test_checks_agree_with_explain_at_the_borders)
{
    for (size_t k = 0; k < fricreg_element_count(); k++)
        for (size_t ns = 1; ns <= NS; ns += NS - 1) {
            const fricreg_element_type *t = fricreg_element_sliders(fricreg_element_at(k), ns);
            if (t == NULL)
                continue;
            unsigned long seed = 99;
            size_t dim = (size_t)fricreg_element_dim(t), np = fricreg_element_nparams(t);
            size_t nst = fricreg_element_nstate(t), n = np + nst + dim;
            double base[MAXP + MAXS + 3], x[MAXP + MAXS + 3];
            point_params(t, &seed, base);
            for (size_t j = np; j < n; j++)
                base[j] = uniform(&seed, -0.5, 0.5);
            for (size_t v = 0; v < NBORDER; v++) {
                /* j = n, n + 1, n + 2: every k_s, every b_s, every component of u */
                for (size_t j = 0; j <= n + 2; j++) {
                    memcpy(x, base, n * sizeof *x);
                    if (j < n)
                        x[j] = BORDER_VALUES[v];
                    else if (j == n + 2)
                        for (size_t a = 0; a < dim; a++)
                            x[np + nst + a] = BORDER_VALUES[v];
                    else if (np > 1)
                        for (size_t s = 0; s < ns; s++)
                            x[(j - n) * ns + s] = BORDER_VALUES[v];
                    agrees_with_explain(t, base, x, x + np, x + np + nst,
                                        j < np || j == n || j == n + 1);
                }
            }
        }
}
END_TEST

int main(void)
{
    Suite *s = suite_create("element_batch");
    TCase *tc = tcase_create("core");
    tcase_add_test(tc, test_every_type_equals_its_points);
    tcase_add_test(tc, test_jenkins_loops_at_once);
    tcase_add_test(tc, test_failures_write_nothing);
    tcase_add_test(tc, test_checks_agree_with_explain_at_the_borders);
    suite_add_tcase(s, tc);
    SRunner *sr = srunner_create(s);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? 0 : 1;
}
