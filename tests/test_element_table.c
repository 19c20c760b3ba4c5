/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_element_table.c — white box: the element table's slider tangents (src/joint/
 * element_kind.h), which the march of harmonic balance chains its exact Jacobian with,
 * against the law's own eval: every law with state that marches has them; the state after the
 * call is eval's, bit for bit; summed over the sliders, d f_s / d u is eval's consistent tangent (the same terms in the same order: to the
 * last bit but the sum's rounding, 1e-15 of kt); d w_s' / d w_s agrees with central differences
 * of eval's state_out in state_in to 1e-7 of 1, in a stick (the identity) and in a slip. */
#include <check.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg_element.h"
#include "joint/element_kind.h"

#define NS 3 /* a family's sliders */
#define MAXST (3 * NS)

START_TEST(marched_laws_with_state_have_slider_tangents)
{
    for (size_t i = 0; i < fricreg_element_count(); i++) {
        const fricreg_element_type *T = fricreg_element_at(i);
        int marched = T->kind->aft == FR_ELEMENT_AFT_MARCH;
        ck_assert_msg(!marched || fricreg_element_nstate(T) == 0 ||
                          T->kind->slider_tangents != NULL,
                      "%s marches with state but gives no slider tangents", T->kind->name);
    }
}
END_TEST

/* The type's sliders at kt = 2 + s, bounds 0.3 (0.1 s + 0.3 for a family), at u from the
 * state w: small (every slider sticks) or large (they slip). */
static void check_type(const fricreg_element_type *T, double reach)
{
    int td = fricreg_element_dim(T);
    size_t ns = fricreg_element_nsliders(T), nst = fricreg_element_nstate(T),
           blk = (size_t)(td * td);
    double p[2 * NS], w[MAXST], u[3] = {0.7 * reach, -0.4 * reach, 0.25 * reach};
    double ts[NS * 9], tw[NS * 9], f[3], dfdu[9], ws[MAXST];
    for (size_t s = 0; s < ns; s++) {
        p[s] = 2.0 + (double)s;
        p[ns + s] = 0.3 + 0.1 * (double)s;
    }
    for (size_t j = 0; j < nst; j++)
        w[j] = 0.01 * (double)(j + 1);
    double wt[MAXST];
    T->kind->slider_tangents(T, p, w, u, ts, tw, wt);
    ck_assert_int_eq(fricreg_element_eval(T, p, w, u, f, dfdu, NULL, ws), FRICREG_OK);
    for (size_t j = 0; j < nst; j++) /* the state after the call: eval's, bit for bit */
        ck_assert_msg(wt[j] == ws[j], "%s state %zu: %.17g, eval's %.17g", T->kind->name, j, wt[j],
                      ws[j]);
    for (size_t a = 0; a < blk; a++) {
        double sum = 0.0;
        for (size_t s = 0; s < ns; s++)
            sum += ts[blk * s + a];
        ck_assert_msg(fabs(sum - dfdu[a]) <= 1e-15 * p[0], "%s entry %zu: %g, eval's %g",
                      T->kind->name, a, sum, dfdu[a]);
    }
    const double h = 1e-7;
    for (size_t j = 0; j < nst; j++) { /* column j of d w' / d w, slider j / td's block */
        double wp[MAXST], wm[MAXST], sp[MAXST], sm[MAXST];
        memcpy(wp, w, sizeof w);
        memcpy(wm, w, sizeof w);
        wp[j] += h;
        wm[j] -= h;
        ck_assert_int_eq(fricreg_element_eval(T, p, wp, u, f, NULL, NULL, sp), FRICREG_OK);
        ck_assert_int_eq(fricreg_element_eval(T, p, wm, u, f, NULL, NULL, sm), FRICREG_OK);
        size_t s = j / (size_t)td, c = j % (size_t)td;
        for (size_t i = 0; i < nst; i++) {
            double fd = (sp[i] - sm[i]) / (2.0 * h);
            double want = i / (size_t)td == s ? tw[blk * s + (i % (size_t)td) * (size_t)td + c]
                                              : 0.0;
            ck_assert_msg(fabs(fd - want) <= 1e-7, "%s state %zu by %zu: %g, differences %g",
                          T->kind->name, i, j, want, fd);
        }
    }
}

START_TEST(slider_tangents_are_evals)
{
    for (size_t i = 0; i < fricreg_element_count(); i++) {
        const fricreg_element_type *T = fricreg_element_at(i);
        if (T->kind->slider_tangents == NULL)
            continue;
        if (T->kind->family)
            T = fricreg_element_sliders(T, NS);
        check_type(T, 0.05); /* every slider sticks */
        check_type(T, 2.0);  /* every slider slips */
    }
}
END_TEST

int main(void)
{
    Suite *s = suite_create("element_table");
    TCase *tc = tcase_create("tangents");
    tcase_add_test(tc, marched_laws_with_state_have_slider_tangents);
    tcase_add_test(tc, slider_tangents_are_evals);
    suite_add_tcase(s, tc);
    SRunner *sr = srunner_create(s);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
