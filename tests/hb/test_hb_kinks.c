/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_hb_kinks.c — Check suite for harmonic balance's Newton at a kink of the branch
 * (src/hb/newton.c): a seed on one side of the point where an element's stick/slip pattern
 * changes, solved on the other. NLvib's chain (tests/support/hb_chain.h, exact Jenkins
 * elements, H = 7) has such a point at Ω = 1.39377, where its second element starts to stick.
 * Solved without a seed at Ω0, that solution seeds the solve at Ω1 across the kink; the
 * reference is the unseeded solve at Ω1 (the default start), which reaches the same point:
 * the response is single-valued there. Until this release the pair (1.393768 to
 * 1.393778) failed with "Newton's line search found no decrease of |R| = 0.000261708": each
 * Newton step from the seed's side stopped shorter before the crossing (accepted steps 1/8,
 * 1/64, 1/256, 1/1024 of Newton's), then none decreased |R|. The other pairs below failed the
 * same way (of 648 pairs 1e-6 to 1e-3 apart about the kink, 18 failed; 3 now, each 1e-3
 * below, crawling along the kink in 50 iterations, which this suite does not claim). */
#include <check.h>
#include <math.h>
#include <stdlib.h>

#include "fricreg_hb.h"
#include "hb_chain.h"

/* Seed at w0, solved at w1: the pair first, then pairs that failed as it did. */
static const double PAIRS[][2] = {
    {1.393768, 1.393778}, /* the issue's, 1e-5 above */
    {1.393700, 1.393800}, /* 1e-4 above */
    {1.393760, 1.393860}, /* 1e-4 above */
    {1.393720, 1.394720}, /* 1e-3 above */
};
#define NPAIRS (sizeof PAIRS / sizeof PAIRS[0])

START_TEST(seeded_across_kink)
{
    fricreg_hb *hb = hb_chain(0, 0);
    ck_assert_ptr_nonnull(hb);
    size_t nq = hb_chain_nq(0);
    double q0[2 * (2 * HB_CHAIN_H + 1)], q1[2 * (2 * HB_CHAIN_H + 1)],
        ref[2 * (2 * HB_CHAIN_H + 1)];
    double w0 = PAIRS[_i][0], w1 = PAIRS[_i][1];
    ck_assert_int_eq(fricreg_hb_solve(hb, w0, nq, NULL, q0), FRICREG_OK);
    int status = fricreg_hb_solve(hb, w1, nq, q0, q1);
    ck_assert_msg(status == FRICREG_OK, "seeded at %.7f from %.7f: %s", w1, w0,
                  fricreg_hb_errmsg(hb));
    ck_assert_int_eq(fricreg_hb_solve(hb, w1, nq, NULL, ref), FRICREG_OK);
    double d = 0.0, scale = 0.0, moved = 0.0;
    for (size_t j = 0; j < nq; j++) {
        d = fmax(d, fabs(q1[j] - ref[j]));
        scale = fmax(scale, fabs(ref[j]));
        moved = fmax(moved, fabs(q0[j] - ref[j]));
    }
    /* the seed is not the solution (the step crossed the kink) and the solution is the
     * unseeded one to Newton's tolerance (1e-10 of the scale) */
    ck_assert_double_gt(moved, 1e-7 * scale);
    ck_assert_double_le(d, 1e-9 * scale);
    fricreg_hb_free(hb);
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("hb_kinks");
    TCase *tc = tcase_create("core");
    tcase_add_loop_test(tc, seeded_across_kink, 0, NPAIRS);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    SRunner *sr = srunner_create(suite());
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
