/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_element_table.c — white box: the element table's slider tangents (src/joint/
 * element_kind.h), which the march of harmonic balance chains its exact Jacobian with,
 * against the law's own eval: every law with state that marches has them, or state tangents
 * of its own (dahl: checked against central differences of eval), and harmonic balance
 * refuses a law with neither when it is added; the state after the
 * call is eval's, bit for bit; summed over the sliders, d f_s / d u is eval's consistent tangent (the same terms in the same order: to the
 * last bit but the sum's rounding, 1e-15 of kt); d w_s' / d w_s agrees with central differences
 * of eval's state_out in state_in to 1e-7 of 1, in a stick (the identity) and in a slip. */
#include <check.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg_element.h"
#include "joint/element_kind.h"
#ifdef FRICREG_TEST_DRIVERS /* harmonic balance, built with the drivers */
#include "fricreg_hb.h"
#endif

#define NS 3 /* a family's sliders */
#define MAXST (3 * NS)

/* Every law with state that harmonic balance marches gives the march its tangents: a slider
 * law its slider tangents, another (dahl) its state tangents. */
START_TEST(marched_laws_with_state_have_tangents)
{
    for (size_t i = 0; i < fricreg_element_count(); i++) {
        const fricreg_element_type *T = fricreg_element_at(i);
        int marched = T->kind->aft == FR_ELEMENT_AFT_MARCH;
        int tangents = (T->kind->slider_tangents != NULL) + (T->kind->state_tangents != NULL);
        ck_assert_msg(!marched || fricreg_element_nstate(T) == 0 || tangents == 1,
                      "%s marches with state but gives %d kinds of tangents", T->kind->name,
                      tangents);
    }
}
END_TEST

#ifdef FRICREG_TEST_DRIVERS
/* A law with state but no tangents for the march (dahl's kind without them, as a law added to
 * the table without its hook would be) is refused by harmonic balance when it is added, with
 * a message that names what it lacks, rather than at the first solve. */
START_TEST(hb_refuses_state_without_tangents)
{
    const fricreg_element_type *dahl = fricreg_element_lookup("dahl");
    struct fr_element_kind kind = *dahl->kind;
    kind.name = "no_tangents";
    kind.state_tangents = NULL;
    const fricreg_element_type T = {&kind, 1, NULL};
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(1, 1, 3, &hb), FRICREG_OK);
    const double J[1] = {1.0}, p[2] = {2.0, 0.5};
    for (size_t me = 0; me < 2; me++) {
        ck_assert_int_eq(fricreg_hb_add_elements(hb, &T, me, 1, J, p), FRICREG_EINVAL);
        ck_assert_ptr_nonnull(strstr(fricreg_hb_errmsg(hb), "no_tangents has state but neither "
                                                            "slider nor state tangents"));
        ck_assert_uint_eq(fricreg_hb_element_count(hb), 0);
    }
    ck_assert_int_eq(fricreg_hb_add_elements(hb, dahl, 1, 1, J, p), FRICREG_OK);
    ck_assert_uint_eq(fricreg_hb_element_count(hb), 1);
    fricreg_hb_free(hb);
}
END_TEST
#endif

/* dahl's state tangents: the state after is eval's bit for bit, and d f / d (u, state), d
 * state' / d (u, state) agree with central differences of eval to 1e-7, loading, reversing
 * and at u = u0. */
START_TEST(state_tangents_are_evals)
{
    const fricreg_element_type *T = fricreg_element_lookup("dahl");
    const double p[2] = {3.0, 0.5}, h = 1e-7;
    const double w[2] = {0.05, 0.1}, us[3] = {0.3, -0.2, 0.1};
    for (int k = 0; k < 3; k++) {
        double x[3] = {us[k], w[0], w[1]}; /* u, then the state */
        double fu[1], fs[2], su[2], ss[4], st[2], f[1], se[2];
        T->kind->state_tangents(T, p, x + 1, x, fu, fs, su, ss, st);
        ck_assert_int_eq(fricreg_element_eval(T, p, x + 1, x, f, NULL, NULL, se), FRICREG_OK);
        ck_assert(st[0] == se[0] && st[1] == se[1]);
        for (int j = 0; j < 3; j++) {
            if (k == 2 && j != 1) /* at u = u0, d f / d u and d f / d u0 are one-sided */
                continue;
            double xp[3] = {x[0], x[1], x[2]}, xm[3] = {x[0], x[1], x[2]}, fp[1], fm[1], sp[2],
                   sm[2];
            xp[j] += h;
            xm[j] -= h;
            ck_assert_int_eq(fricreg_element_eval(T, p, xp + 1, xp, fp, NULL, NULL, sp),
                             FRICREG_OK);
            ck_assert_int_eq(fricreg_element_eval(T, p, xm + 1, xm, fm, NULL, NULL, sm),
                             FRICREG_OK);
            double want_f = j == 0 ? fu[0] : fs[j - 1];
            ck_assert_msg(fabs((fp[0] - fm[0]) / (2 * h) - want_f) <= 1e-7 * p[0],
                          "u %g: d f / d x[%d] %.17g", x[0], j, want_f);
            for (int r = 0; r < 2; r++) {
                double want_s = j == 0 ? su[r] : ss[2 * r + j - 1];
                ck_assert_msg(fabs((sp[r] - sm[r]) / (2 * h) - want_s) <= 1e-7,
                              "u %g: d state[%d] / d x[%d] %.17g", x[0], r, j, want_s);
            }
        }
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
    tcase_add_test(tc, marched_laws_with_state_have_tangents);
#ifdef FRICREG_TEST_DRIVERS
    tcase_add_test(tc, hb_refuses_state_without_tangents);
#endif
    tcase_add_test(tc, state_tangents_are_evals);
    tcase_add_test(tc, slider_tangents_are_evals);
    suite_add_tcase(s, tc);
    SRunner *sr = srunner_create(s);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
