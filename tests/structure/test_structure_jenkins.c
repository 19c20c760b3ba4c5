/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_structure_jenkins.c — Check suite for Jenkins elements as joints of a fricreg_structure
 * (fricreg_structure_set_jenkins).
 *
 * Where the numbers come from:
 *   - the hand-written average-acceleration Newmark with the elements' return mapping
 *     (tests/support/jenkins_newmark.h, test_hb's reference) solves the same discrete equations
 *     as the structure's Newmark: the displacement histories agree to rounding (1e-10 of the
 *     amplitude over 100 periods; one dof, and test_hb's chain of three with two elements);
 *   - harmonic balance (fricreg_hb at H = 21, as test_hb): the steady RMS within 1e-3;
 *   - the closed form of a Jenkins element driven with amplitude A: 4 mun (A - mun/kt) per
 *     cycle (the hysteresis loop's area), the element behind a stiff spring to a prescribed
 *     motion;
 *   - a stuck element (mun huge) is the spring kt: the run equals one without the element and
 *     K + kt J_e^T J_e, to 1e-12;
 *   - central difference converges to Newmark's solution at a fine step as dt shrinks (second
 *     order);
 *   - average-acceleration Newmark's discrete energy balance closes with the elements'
 *     dissipation (FRICREG_SVALUE_JENKINS). */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg_hb.h"
#include "fricreg_structure.h"
#include "jenkins_newmark.h"
#include "quiet_check.h"

static const double PI = 3.14159265358979323846;

/* test_hb's oscillator, forced by p_s sin(Omega t) so that the start at rest is the equation
 * of motion's (a(0) = 0, as the reference assumes). */
static struct jenkins_model oscillator(void)
{
    struct jenkins_model s = jenkins_model_oscillator();
    s.ps[0] = s.pc[0];
    s.pc[0] = 0.0;
    return s;
}

/* A structure of the model, one contact of bound 0 (no friction), the elements attached, the
 * load p_c cos + p_s sin sampled at every step of dt for nsteps steps. */
static fricreg_structure *make(const struct jenkins_model *m, int elements, double omega, double dt,
                               int nsteps)
{
    fricreg_structure *s = NULL;
    size_t n = m->n;
    ck_assert_int_eq(fricreg_structure_create(n, 1, &s), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_mass(s, n, m->M), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_stiffness(s, n, m->K), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_damping(s, n, m->C), FRICREG_OK);
    double J[JENKINS_MODEL_MAXN] = {0}, zero = 0.0;
    J[0] = 1.0;
    ck_assert_int_eq(fricreg_structure_set_contacts(s, 1, n, J), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_bounds(s, 1, &zero), FRICREG_OK);
    if (elements)
        ck_assert_int_eq(fricreg_structure_set_jenkins(s, m->m, n, m->J, m->kt, m->mun),
                         FRICREG_OK);
    /* p(t) = p g(t): the model's loads share one time function here */
    double p[JENKINS_MODEL_MAXN];
    int sine = m->pc[0] == 0.0;
    for (size_t k = 0; k < n; k++)
        p[k] = sine ? m->ps[k] : m->pc[k];
    double *g = malloc(((size_t)nsteps + 1) * sizeof *g);
    ck_assert_ptr_nonnull(g);
    for (int k = 0; k <= nsteps; k++)
        g[k] = sine ? sin(omega * k * dt) : cos(omega * k * dt);
    ck_assert_int_eq(fricreg_structure_set_load(s, n, p, 0.0, dt, (size_t)nsteps + 1, g),
                     FRICREG_OK);
    free(g);
    ck_assert_int_eq(fricreg_structure_set_newton(s, 1e-13, 50), FRICREG_OK);
    return s;
}

START_TEST(oscillator_against_reference_and_hb)
{
    struct jenkins_model m = oscillator();
    const int N = 1024, periods = 100, nsteps = N * periods;
    const double omega = 1.5, dt = 2.0 * PI / omega / N;
    double *ref = malloc((size_t)nsteps * sizeof *ref), *got = malloc((size_t)nsteps * sizeof *got);
    ck_assert_ptr_nonnull(ref);
    ck_assert_ptr_nonnull(got);
    double rms_ref, prev_ref;
    int slips = jenkins_newmark_rms(&m, omega, N, periods, &rms_ref, &prev_ref, ref);
    ck_assert(slips);

    fricreg_structure *s = make(&m, 1, omega, dt, nsteps);
    /* run's own clock: step k ends at k dt exactly, as the reference's */
    double amp = 0.0, diff = 0.0;
    for (int k = 1; k <= nsteps; k++) {
        double t1 = k * dt, t0;
        QUIET_OK(fricreg_structure_get_value(s, FRICREG_SVALUE_TIME, &t0));
        QUIET_OK(fricreg_structure_step(s, t1 - t0));
        QUIET_OK(fricreg_structure_get_state(s, 1, &got[k - 1], NULL, NULL));
        amp = fmax(amp, fabs(ref[k - 1]));
        diff = fmax(diff, fabs(got[k - 1] - ref[k - 1]));
    }
    double rms = 0.0;
    for (int k = nsteps - N; k < nsteps; k++)
        rms += got[k] * got[k];
    rms = sqrt(rms / N);
    int64_t iters, steps, imax, fails;
    fricreg_structure_get_stat(s, FRICREG_SSTAT_NEWTON_ITERATIONS, &iters);
    fricreg_structure_get_stat(s, FRICREG_SSTAT_STEPS, &steps);
    fricreg_structure_get_stat(s, FRICREG_SSTAT_NEWTON_MAX, &imax);
    fricreg_structure_get_stat(s, FRICREG_SSTAT_NEWTON_FAILURES, &fails);

    /* HB at H = 21 */
    const int H = 21;
    fricreg_hb *hb = NULL;
    size_t nc = 2 * H + 1;
    double q[2 * 21 + 1], x[2 * 21 + 1];
    ck_assert_int_eq(fricreg_hb_create(1, 1, H, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, 1, m.M), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 1, m.K), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_damping(hb, 1, m.C), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_elements(hb, 1, 1, m.J, m.kt, m.mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_excitation(hb, 1, m.pc, m.ps), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_solve(hb, omega, nc, NULL, q), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_displacement(hb, 1, nc, x), FRICREG_OK);
    double rms_hb = x[0] * x[0];
    for (size_t c = 1; c < nc; c++)
        rms_hb += 0.5 * x[c] * x[c];
    rms_hb = sqrt(rms_hb);
    fricreg_hb_free(hb);
    if (getenv("JENKINS_PRINT"))
        fprintf(stderr,
                "history |x - ref| %.3e of %.6g; RMS structure %.10g reference %.10g HB %.10g "
                "(rel %.2e); Newton %g per step, max %lld, failures %lld\n",
                diff, amp, rms, rms_ref, rms_hb, fabs(rms / rms_hb - 1.0),
                (double)iters / (double)steps, (long long)imax, (long long)fails);
    ck_assert_msg(diff <= 1e-10 * amp, "history differs by %g of %g", diff, amp);
    ck_assert_double_eq_tol(rms, rms_ref, 1e-10 * rms_ref);
    ck_assert_msg(fabs(rms - rms_hb) <= 1e-3 * rms_hb, "RMS %.9g, HB %.9g", rms, rms_hb);
    ck_assert_int_eq(fails, 0);
    ck_assert_int_le(imax, 4);

    /* the balance closes with the elements' dissipation, and the warning agrees */
    double residual, input, jenkins, D;
    fricreg_structure_get_value(s, FRICREG_SVALUE_RESIDUAL, &residual);
    fricreg_structure_get_value(s, FRICREG_SVALUE_INPUT, &input);
    fricreg_structure_get_value(s, FRICREG_SVALUE_JENKINS, &jenkins);
    ck_assert_int_eq(fricreg_structure_get_jenkins_state(s, 1, NULL, NULL, &D), FRICREG_OK);
    ck_assert_double_eq(D, jenkins);
    ck_assert(jenkins > 0.1 * input);
    ck_assert_msg(fabs(residual) <= 1e-9 * fabs(input), "residual %g of input %g", residual, input);
    size_t nw = fricreg_structure_warning_count(s);
    for (size_t k = 0; k < nw; k++) {
        int code;
        ck_assert_int_eq(fricreg_structure_get_warning(s, k, &code, NULL, 0), FRICREG_OK);
        ck_assert_int_ne(code, FRICREG_WARN_ENERGY);
    }
    fricreg_structure_free(s);
    free(ref);
    free(got);
}
END_TEST

/* test_hb's chain (three masses, two elements: one to ground, one between masses 1 and 2, so
 * E = J_e K_eff^-1 J_e^T is full), forced by 0.8 sin(Omega t) on mass 1, HHT's alpha = 0:
 * against the hand-written Newmark to rounding over 60 periods, every dof. */
START_TEST(chain_against_reference)
{
    struct jenkins_model m = jenkins_model_chain();
    m.pc[0] = 0.0, m.ps[0] = 0.8; /* sine forcing only */
    const int N = 512, periods = 60, nsteps = N * periods;
    const double omega = 1.3, dt = 2.0 * PI / omega / N;
    double *ref = malloc(3 * (size_t)nsteps * sizeof *ref), rms[3], prev[3], x[3];
    ck_assert_ptr_nonnull(ref);
    ck_assert(jenkins_newmark_rms(&m, omega, N, periods, rms, prev, ref));
    fricreg_structure *s = make(&m, 1, omega, dt, nsteps);
    double amp = 0.0, diff = 0.0;
    for (int k = 1; k <= nsteps; k++) {
        double t0;
        QUIET_OK(fricreg_structure_get_value(s, FRICREG_SVALUE_TIME, &t0));
        QUIET_OK(fricreg_structure_step(s, k * dt - t0));
        QUIET_OK(fricreg_structure_get_state(s, 3, x, NULL, NULL));
        for (int i = 0; i < 3; i++) {
            amp = fmax(amp, fabs(ref[3 * (size_t)(k - 1) + i]));
            diff = fmax(diff, fabs(x[i] - ref[3 * (size_t)(k - 1) + i]));
        }
    }
    int64_t iters, imax, fails;
    fricreg_structure_get_stat(s, FRICREG_SSTAT_NEWTON_ITERATIONS, &iters);
    fricreg_structure_get_stat(s, FRICREG_SSTAT_NEWTON_MAX, &imax);
    fricreg_structure_get_stat(s, FRICREG_SSTAT_NEWTON_FAILURES, &fails);
    if (getenv("JENKINS_PRINT"))
        fprintf(stderr, "chain: history |x - ref| %.3e of %.4g; Newton %g per step, max %lld\n",
                diff, amp, (double)iters / nsteps, (long long)imax);
    ck_assert_msg(diff <= 1e-10 * amp, "history differs by %g of %g", diff, amp);
    ck_assert_int_eq(fails, 0);
    ck_assert_int_le(imax, 4);
    fricreg_structure_free(s);
    free(ref);
}
END_TEST

/* One cycle's dissipation of an element at q = A sin(omega t): the element (kt, mun) in
 * parallel with a stiff spring kg to ground that a load kg A sin(omega t) drives, so that
 * q = A sin(omega t) - (fe + m q'')/kg, within mun/(kg A) + (omega/omega_n)^2 ~ 1e-6 of A. */
START_TEST(dissipation_closed_form)
{
    const double kg = 1e6, kt = 3.0, mun = 0.5, A = 0.4, omega = 1.0, mass = 1.0;
    const int N = 4000;
    const double T = 2.0 * PI / omega, dt = T / N;
    fricreg_structure *s = NULL;
    double J = 1.0, zero = 0.0, p = kg * A;
    ck_assert_int_eq(fricreg_structure_create(1, 1, &s), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_mass(s, 1, &mass), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_stiffness(s, 1, &kg), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_contacts(s, 1, 1, &J), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_bounds(s, 1, &zero), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_jenkins(s, 1, 1, &J, &kt, &mun), FRICREG_OK);
    const int cycles = 3;
    double *g = malloc(((size_t)cycles * N + 1) * sizeof *g);
    ck_assert_ptr_nonnull(g);
    for (int k = 0; k <= cycles * N; k++)
        g[k] = sin(omega * k * dt);
    ck_assert_int_eq(fricreg_structure_set_load(s, 1, &p, 0.0, dt, (size_t)cycles * N + 1, g),
                     FRICREG_OK);
    free(g);
    double u0 = 0.0, v0 = A * omega; /* on the forced motion: no free vibration of omega_n */
    ck_assert_int_eq(fricreg_structure_set_initial(s, 1, &u0, &v0), FRICREG_OK);
    double D[4] = {0};
    for (int c = 1; c <= cycles; c++) {
        ck_assert_int_eq(fricreg_structure_run(s, dt, c * T), FRICREG_OK);
        ck_assert_int_eq(fricreg_structure_get_jenkins_state(s, 1, NULL, NULL, &D[c]), FRICREG_OK);
    }
    double want = 4.0 * mun * (A - mun / kt);
    for (int c = 2; c <= cycles; c++) {
        double got = D[c] - D[c - 1];
        if (getenv("JENKINS_PRINT"))
            fprintf(stderr, "cycle %d: dissipation %.10g, closed form %.10g (rel %.2e)\n", c, got,
                    want, fabs(got / want - 1.0));
        ck_assert_msg(fabs(got - want) <= 1e-4 * want, "cycle %d: %.10g, closed form %.10g", c, got,
                      want);
    }
    fricreg_structure_free(s);
}
END_TEST

/* Two masses, the element between them stuck (mun = 1e30): the spring kt. */
START_TEST(stuck_element_is_a_spring)
{
    struct jenkins_model m = {.n = 2, .m = 1};
    m.M[0] = 1.1, m.M[3] = 0.8;
    m.K[0] = 3.0, m.K[1] = m.K[2] = -1.0, m.K[3] = 1.5;
    m.C[0] = 0.05, m.C[3] = 0.02;
    m.J[0] = -1.0, m.J[1] = 1.0;
    m.kt[0] = 2.2, m.mun[0] = 1e30;
    m.pc[0] = 0.7, m.pc[1] = 0.3;
    struct jenkins_model lin = m;
    for (int i = 0; i < 2; i++)
        for (int k = 0; k < 2; k++)
            lin.K[2 * i + k] += m.kt[0] * m.J[i] * m.J[k];
    const double omega = 1.3, dt = 0.01;
    const int nsteps = 2000;
    for (int scheme = 0; scheme < 3; scheme++) {
        fricreg_structure *a = make(&m, 1, omega, dt, nsteps),
                          *b = make(&lin, 0, omega, dt, nsteps);
        if (scheme == 1) {
            ck_assert_int_eq(fricreg_structure_set_hht(a, -0.1), FRICREG_OK);
            ck_assert_int_eq(fricreg_structure_set_hht(b, -0.1), FRICREG_OK);
        } else if (scheme == 2) {
            ck_assert_int_eq(fricreg_structure_set_central_difference(a), FRICREG_OK);
            ck_assert_int_eq(fricreg_structure_set_central_difference(b), FRICREG_OK);
        }
        ck_assert_int_eq(fricreg_structure_run(a, dt, nsteps * dt), FRICREG_OK);
        ck_assert_int_eq(fricreg_structure_run(b, dt, nsteps * dt), FRICREG_OK);
        double ua[2], va[2], ub[2], vb[2], f, strain_a, strain_b;
        fricreg_structure_get_state(a, 2, ua, va, NULL);
        fricreg_structure_get_state(b, 2, ub, vb, NULL);
        fricreg_structure_get_jenkins_state(a, 1, &f, NULL, NULL);
        fricreg_structure_get_value(a, FRICREG_SVALUE_STRAIN, &strain_a);
        fricreg_structure_get_value(b, FRICREG_SVALUE_STRAIN, &strain_b);
        double scale = fmax(fabs(ub[0]), fabs(ub[1])), vscale = fmax(fabs(vb[0]), fabs(vb[1]));
        if (getenv("JENKINS_PRINT"))
            fprintf(stderr, "stuck, scheme %d: |du| %.2e |dv| %.2e of %.3g, %.3g\n", scheme,
                    fmax(fabs(ua[0] - ub[0]), fabs(ua[1] - ub[1])),
                    fmax(fabs(va[0] - vb[0]), fabs(va[1] - vb[1])), scale, vscale);
        for (int k = 0; k < 2; k++) {
            ck_assert_double_eq_tol(ua[k], ub[k], 1e-12 * scale);
            ck_assert_double_eq_tol(va[k], vb[k], 1e-12 * vscale);
        }
        ck_assert_double_eq_tol(f, m.kt[0] * (ua[1] - ua[0]), 1e-12 * m.kt[0] * scale);
        ck_assert_double_eq_tol(strain_a, strain_b, 1e-11 * strain_b);
        fricreg_structure_free(a);
        fricreg_structure_free(b);
    }
}
END_TEST

/* Central difference against average-acceleration Newmark at dt0/64 on the oscillator over
 * five periods, the largest difference at the times k dt0/8: second order (measured ratios
 * 0.20, 0.30, 0.23 per halving of dt from 0.02), asserted below 0.4. */
START_TEST(central_converges_to_newmark)
{
    struct jenkins_model m = oscillator();
    const double omega = 1.5, dt0 = 0.02, dts = dt0 / 8;
    const int fine = 8, samples = (int)lround(5.0 * 2.0 * PI / omega / dts);
    double *uref = malloc(((size_t)samples + 1) * sizeof *uref);
    ck_assert_ptr_nonnull(uref);
    fricreg_structure *r = make(&m, 1, omega, dts / fine, samples * fine);
    uref[0] = 0.0;
    for (int j = 1; j <= samples; j++) {
        ck_assert_int_eq(fricreg_structure_run(r, dts / fine, j * dts), FRICREG_OK);
        fricreg_structure_get_state(r, 1, &uref[j], NULL, NULL);
    }
    fricreg_structure_free(r);
    double err[4];
    for (int k = 0; k < 4; k++) {
        int stride = 8 >> k;
        double dt = dts * stride, u;
        fricreg_structure *c = make(&m, 1, omega, dt, samples / stride);
        ck_assert_int_eq(fricreg_structure_set_central_difference(c), FRICREG_OK);
        err[k] = 0.0;
        for (int j = stride; j <= samples; j += stride) {
            ck_assert_int_eq(fricreg_structure_run(c, dt, j * dts), FRICREG_OK);
            fricreg_structure_get_state(c, 1, &u, NULL, NULL);
            err[k] = fmax(err[k], fabs(u - uref[j]));
        }
        if (getenv("JENKINS_PRINT"))
            fprintf(stderr, "central dt %g: max |u - u_newmark| %.3e\n", dt, err[k]);
        fricreg_structure_free(c);
    }
    free(uref);
    ck_assert(err[0] < 1e-2);
    for (int k = 1; k < 4; k++)
        ck_assert_msg(err[k] < 0.4 * err[k - 1], "dt0/%d: %g, dt0/%d: %g", 1 << k, err[k],
                      1 << (k - 1), err[k - 1]);
}
END_TEST

/* run_ode refuses elements (the state stays); elements beside a contact of bound > 0 step
 * together (test_structure_joint.c checks the numbers): here on the same dof, the contact
 * taking its share of the load. */
START_TEST(refusals)
{
    struct jenkins_model m = oscillator();
    fricreg_structure *s = make(&m, 1, 1.5, 0.01, 10);
    double one = 1.0, u, f;
    ck_assert_int_eq(fricreg_structure_set_bounds(s, 1, &one), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_run_ode(s, FRICREG_INT_RK4, 0.01, 0.0, 0.0, 0.1),
                     FRICREG_EINVAL);
    fricreg_structure_get_state(s, 1, &u, NULL, NULL);
    ck_assert_double_eq(u, 0.0);
    ck_assert_int_eq(fricreg_structure_run(s, 0.01, 0.1), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_get_forces(s, 1, &f), FRICREG_OK);
    ck_assert(f != 0.0 && fabs(f) <= 1.0);
    /* me = 0 removes the elements: the step then runs with the contact alone */
    ck_assert_int_eq(fricreg_structure_set_jenkins(s, 0, 1, NULL, NULL, NULL), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_get_jenkins_state(s, 0, NULL, NULL, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_structure_step(s, 0.01), FRICREG_OK);
    fricreg_structure_free(s);
}
END_TEST

/* The CSR setter builds the same elements as the dense one. */
START_TEST(csr_same_as_dense)
{
    struct jenkins_model m = oscillator();
    const double omega = 1.5, dt = 0.01;
    fricreg_structure *a = make(&m, 1, omega, dt, 500), *b = make(&m, 0, omega, dt, 500);
    int64_t rowptr[2] = {1, 2}, colind[1] = {1};
    ck_assert_int_eq(fricreg_structure_set_jenkins_csr(b, 1, 1, FRICREG_SPARSE_ONE_BASED, rowptr,
                                                       colind, m.J, m.kt, m.mun),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_run(a, dt, 5.0), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_run(b, dt, 5.0), FRICREG_OK);
    double fa[1], wa[1], fb[1], wb[1];
    fricreg_structure_get_jenkins_state(a, 1, fa, wa, NULL);
    fricreg_structure_get_jenkins_state(b, 1, fb, wb, NULL);
    ck_assert_double_eq(fa[0], fb[0]);
    ck_assert_double_eq(wa[0], wb[0]);
    ck_assert(fabs(wa[0]) > 0.0); /* the slider moved */
    fricreg_structure_free(a);
    fricreg_structure_free(b);
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("structure_jenkins");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, oscillator_against_reference_and_hb);
    tcase_add_test(tc, chain_against_reference);
    tcase_add_test(tc, dissipation_closed_form);
    tcase_add_test(tc, stuck_element_is_a_spring);
    tcase_add_test(tc, central_converges_to_newmark);
    tcase_add_test(tc, refusals);
    tcase_add_test(tc, csr_same_as_dense);
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
