/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_guard_structure.c — the step guard's sweep on structures: no fixed explicit step that
 * the guard (src/ode/step_guard.c, the one guard of fricreg_sim and fricreg_structure) accepts
 * puts energy in or leaves a stick.
 *
 * Two structures under harmonic ground motion (an oscillator, and three storeys with Rayleigh
 * damping and coupled contacts between them) x every law x the structure's central difference
 * and GSL's explicit steppers through fricreg_structure_run_ode, at 0.5x to 1x the largest dt
 * the guard accepts (bisection on FRICREG_ESTEP, which is refused before any step). Each run is
 * judged against a fine reference of the same law and eps (average-acceleration Newmark at
 * DT_REF, energy-consistent: Krenk, CMAME 195 (2006)):
 *   energy: the energy the contacts put in, E - E0 - W_in + W_visc (E the kinetic plus strain
 *     energy, W_in the ground motion's work, W_visc the damping's), at its largest over the run
 *     is at most the reference's (a law may push near a stick: Karnopp, (4)), or 0, plus
 *     tol = 1% of the reference's scale E0 + max E + W_visc + D. For central differences E is
 *     the scheme's invariant E - (dt^2/8) (Ku)' M^-1 (Ku) (velocity Verlet's): E itself swings
 *     by (dt omega)^2/4 within each oscillation at no gain.
 *   stick: per contact, the near-stick fraction (|J v| < eps after a step) of the last forcing
 *     cycle is at most 0.05 below the reference's, for the laws that do not jump (those chatter
 *     at a stick at every fixed step, the paper's reason to regularize).
 * A failure of an accepted run is a false accept; the test fails, naming it. */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg_sim.h"
#include "fricreg_structure.h"
#include "structure/structure_internal.h"
#include "quiet_check.h"

#define NMAX 3
#define DT_REF 5e-4
#define PI 3.14159265358979323846

struct model {
    const char *name;
    size_t n, m;
    double M[NMAX], K[NMAX * NMAX], J[NMAX * NMAX], mun[NMAX];
    double a0, a1;          /* Rayleigh damping */
    double eps, amp, omega; /* the law's eps; ground motion amp sin(omega t) */
    double u0[NMAX];        /* initial displacements (at rest) */
    int cycles;             /* forcing cycles run; the last is judged for sticks */
};

/* The paper's oscillator (Eq. (5), a = 2, omega = 0.5, x0 = 2.75) as a structure. */
static const struct model oscillator = {"oscillator", 1,   1,    {1.0}, {1.0}, {1.0},  {1.0},
                                        0.0,          0.0, 0.05, 2.0,   0.5,   {2.75}, 2};

/* Three storeys: masses 1, 1.2, 0.8; storey stiffnesses 40, 30, 20; Rayleigh 0.05 M + 0.01 K;
 * a damper between the ground and storey 1 and between neighbouring storeys (W dense). */
static const struct model storeys = {"three storeys",
                                     3,
                                     3,
                                     {1.0, 1.2, 0.8},
                                     {70.0, -30.0, 0.0, -30.0, 50.0, -20.0, 0.0, -20.0, 20.0},
                                     {1.0, 0.0, 0.0, -1.0, 1.0, 0.0, 0.0, -1.0, 1.0},
                                     {2.0, 1.2, 0.6},
                                     0.05,
                                     0.01,
                                     0.02,
                                     1.5,
                                     2.0,
                                     {0.0, 0.0, 0.0},
                                     2};

static const int steppers[] = {0 /* the structure's central difference */,
                               FRICREG_INT_RK2,
                               FRICREG_INT_RK4,
                               FRICREG_INT_RKF45,
                               FRICREG_INT_RKCK,
                               FRICREG_INT_RK8PD};
#define NSTEPPERS (sizeof steppers / sizeof steppers[0])
#define NEWMARK (-1) /* the reference's scheme */

static void ok(const fricreg_structure *s, int status)
{
    QUIET_ASSERT(status == FRICREG_OK, "status %d: %s", status, fricreg_structure_errmsg(s));
}

static fricreg_structure *make(const struct model *mo, int law)
{
    fricreg_structure *s = NULL;
    size_t n = mo->n;
    ck_assert_int_eq(fricreg_structure_create(n, mo->m, &s), FRICREG_OK);
    double M[NMAX * NMAX] = {0.0}, r[NMAX], v0[NMAX] = {0.0};
    for (size_t i = 0; i < n; i++) {
        M[i * n + i] = mo->M[i];
        r[i] = 1.0;
    }
    ok(s, fricreg_structure_set_mass(s, n, M));
    ok(s, fricreg_structure_set_stiffness(s, n, mo->K));
    if (mo->a0 > 0.0 || mo->a1 > 0.0)
        ok(s, fricreg_structure_set_rayleigh(s, mo->a0, mo->a1));
    ok(s, fricreg_structure_set_contacts(s, mo->m, n, mo->J));
    ok(s, fricreg_structure_set_bounds(s, mo->m, mo->mun));
    ok(s, fricreg_structure_set_law(s, law, mo->eps));
    ok(s, fricreg_structure_set_influence(s, n, r));
    /* a_g = -amp sin(omega t), sampled every 1e-3 over the run and a step beyond */
    double T = 2.0 * PI / mo->omega, t_end = mo->cycles * T + 1.0;
    size_t samples = (size_t)(t_end / 1e-3) + 2;
    double *ag = malloc(samples * sizeof *ag);
    ck_assert_ptr_nonnull(ag);
    for (size_t k = 0; k < samples; k++)
        ag[k] = -mo->amp * sin(mo->omega * 1e-3 * (double)k);
    ok(s, fricreg_structure_set_ground_accel(s, 0.0, 1e-3, samples, ag));
    free(ag);
    ok(s, fricreg_structure_set_initial(s, n, mo->u0, v0));
    return s;
}

/* One step of the stepper (0: central difference, NEWMARK, else a GSL stepper) from the
 * structure's time; its status. */
static int step(fricreg_structure *s, int stepper, double dt)
{
    if (stepper > 0) {
        double t = 0.0;
        fricreg_structure_get_value(s, FRICREG_SVALUE_TIME, &t);
        return fricreg_structure_run_ode(s, stepper, dt, 0.0, 0.0, t + dt);
    }
    return fricreg_structure_step(s, dt);
}

static fricreg_structure *make_for(const struct model *mo, int law, int stepper)
{
    fricreg_structure *s = make(mo, law);
    if (stepper == 0)
        ok(s, fricreg_structure_set_central_difference(s));
    return s;
}

/* The largest dt the guard accepts, to 1e-6 relative (the check runs before any step). */
static double guard_bound(const struct model *mo, int law, int stepper)
{
    double lo = 1e-7, hi = 10.0;
    while (hi > lo * (1.0 + 1e-6)) {
        double mid = sqrt(lo * hi);
        fricreg_structure *s = make_for(mo, law, stepper);
        int status = step(s, stepper, mid);
        fricreg_structure_free(s);
        ck_assert_msg(status == FRICREG_OK || status == FRICREG_ESTEP, "status %d", status);
        if (status == FRICREG_ESTEP)
            hi = mid;
        else
            lo = mid;
    }
    return lo;
}

struct outcome {
    int status;
    double gain, scale, stick[NMAX];
};

/* E, with the central-difference invariant's correction when dt_shadow > 0. */
static double energy(const struct model *mo, const double u[], const double v[], double dt_shadow)
{
    size_t n = mo->n;
    double E = 0.0;
    for (size_t i = 0; i < n; i++) {
        double Ku = 0.0;
        for (size_t j = 0; j < n; j++)
            Ku += mo->K[i * n + j] * u[j];
        E += 0.5 * mo->M[i] * v[i] * v[i] + 0.5 * u[i] * Ku;
        E -= dt_shadow * dt_shadow / 8.0 * Ku * Ku / mo->M[i];
    }
    return E;
}

static double value(const fricreg_structure *s, int which)
{
    double x = 0.0;
    ok(s, fricreg_structure_get_value(s, which, &x));
    return x;
}

static struct outcome run(const struct model *mo, int law, int stepper, double dt)
{
    fricreg_structure *s = stepper == NEWMARK ? make(mo, law) : make_for(mo, law, stepper);
    size_t n = mo->n, m = mo->m;
    double T = 2.0 * PI / mo->omega, t_end = mo->cycles * T, t = 0.0;
    double shadow = stepper == 0 ? dt : 0.0, u[NMAX], v[NMAX];
    ok(s, fricreg_structure_get_state(s, n, u, v, NULL));
    double E0 = energy(mo, u, v, shadow), E_max = E0;
    struct outcome o = {.status = FRICREG_OK, .gain = 0.0};
    double near[NMAX] = {0.0};
    while (t < t_end && o.status == FRICREG_OK) {
        double h = fmin(dt, t_end - t);
        o.status = step(s, stepper, h);
        if (o.status != FRICREG_OK)
            break;
        t = value(s, FRICREG_SVALUE_TIME);
        ok(s, fricreg_structure_get_state(s, n, u, v, NULL));
        double E = energy(mo, u, v, shadow);
        E_max = fmax(E_max, E);
        double gain = E - E0 - value(s, FRICREG_SVALUE_INPUT) + value(s, FRICREG_SVALUE_VISCOUS);
        o.gain = fmax(o.gain, gain);
        for (size_t i = 0; t > t_end - T && i < m; i++) {
            double zdot = 0.0;
            for (size_t j = 0; j < n; j++)
                zdot += mo->J[i * n + j] * v[j];
            near[i] += fabs(zdot) < mo->eps ? h : 0.0;
        }
    }
    for (size_t i = 0; i < m; i++)
        o.stick[i] = near[i] / T;
    o.scale = E0 + E_max + value(s, FRICREG_SVALUE_VISCOUS) + value(s, FRICREG_SVALUE_FRICTION);
    fricreg_structure_free(s);
    return o;
}

static int law_jumps(int law)
{
    return law == FRICREG_LAW_COULOMB || law == FRICREG_LAW_FORCE_BALANCE ||
           law == FRICREG_LAW_KARNOPP;
}

/* Why a run fails against its reference, or NULL. */
static const char *judge(const struct model *mo, int law, const struct outcome *o,
                         const struct outcome *ref)
{
    if (o->status != FRICREG_OK)
        return "the run failed";
    if (o->gain > fmax(ref->gain, 0.0) + 0.01 * ref->scale)
        return "energy gained";
    for (size_t i = 0; !law_jumps(law) && i < mo->m; i++)
        if (o->stick[i] < ref->stick[i] - 0.05)
            return "left a stick";
    return NULL;
}

static const char *stepper_name(int stepper)
{
    return stepper == 0 ? "central difference" : fricreg_integrator_name(stepper);
}

START_TEST(no_false_accept_on_structures)
{
    static const double mult[] = {0.5, 0.75, 0.9, 1.0};
    const struct model *models[] = {&oscillator, &storeys};
    int accepted = 0, false_accepts = 0;
    for (size_t mi = 0; mi < sizeof models / sizeof models[0]; mi++) {
        const struct model *mo = models[mi];
        for (int law = FRICREG_LAW_COULOMB; law <= FRICREG_LAW_QUINN; law++) {
            struct outcome ref = run(mo, law, NEWMARK, DT_REF);
            ck_assert_msg(ref.status == FRICREG_OK, "%s, %s: the reference failed", mo->name,
                          fricreg_law_name(law));
            for (size_t si = 0; si < NSTEPPERS; si++) {
                double bound = guard_bound(mo, law, steppers[si]);
                ck_assert_msg(bound > 1e-6, "%s, %s, %s: the guard refuses every dt", mo->name,
                              fricreg_law_name(law), stepper_name(steppers[si]));
                for (size_t k = 0; k < sizeof mult / sizeof mult[0]; k++) {
                    struct outcome o = run(mo, law, steppers[si], mult[k] * bound);
                    const char *why = judge(mo, law, &o, &ref);
                    accepted++;
                    if (why != NULL) {
                        false_accepts++;
                        fprintf(stderr,
                                "false accept: %s, %s, %s, dt = %.4g (%.2fx): %s (gain %.3g, "
                                "reference %.3g, scale %.3g)\n",
                                mo->name, fricreg_law_name(law), stepper_name(steppers[si]),
                                mult[k] * bound, mult[k], why, o.gain, ref.gain, ref.scale);
                    }
                }
            }
        }
    }
    printf("structure guard sweep: %d accepted runs, %d false accepts\n", accepted, false_accepts);
    ck_assert_int_eq(false_accepts, 0);
}
END_TEST

/* What the structure's old guard accepted (dt omega_max < 2 and dt lambda < 1 apart, viscous
 * damping ignored) and the one guard refuses: the oscillator without friction, damped by
 * Rayleigh a0 = 1.2 (c = 1.2, omega = 1), at dt = 1.9. Central differences see the damping at
 * the predictor v*, so dt c counts like dt lambda: (dt omega/2)^2 + dt c = 3.18 > 1, and the
 * motion grows (run unguarded, the static library's test flag). At dt = 0.6 (0.09 + 0.72 < 0.9)
 * it decays as e^(-0.6 t). */
START_TEST(damping_counts_in_the_guard)
{
    const double one = 1.0, zero = 0.0, x0 = 1.0;
    for (int guarded = 1; guarded >= 0; guarded--) {
        fricreg_structure *s = NULL;
        ck_assert_int_eq(fricreg_structure_create(1, 1, &s), FRICREG_OK);
        ok(s, fricreg_structure_set_mass(s, 1, &one));
        ok(s, fricreg_structure_set_stiffness(s, 1, &one));
        ok(s, fricreg_structure_set_rayleigh(s, 1.2, 0.0));
        ok(s, fricreg_structure_set_contacts(s, 1, 1, &one));
        ok(s, fricreg_structure_set_bounds(s, 1, &zero));
        ok(s, fricreg_structure_set_central_difference(s));
        ok(s, fricreg_structure_set_initial(s, 1, &x0, &zero));
        s->unguarded = !guarded;
        int status = fricreg_structure_run(s, 1.9, 19.0);
        double u = 0.0;
        ok(s, fricreg_structure_get_state(s, 1, &u, NULL, NULL));
        if (guarded) {
            ck_assert_int_eq(status, FRICREG_ESTEP);
            ck_assert_ptr_nonnull(strstr(fricreg_structure_errmsg(s), "damping"));
            ck_assert_double_eq(u, x0); /* refused before any step */
            ok(s, fricreg_structure_run(s, 0.6, 70.0));
            ok(s, fricreg_structure_get_state(s, 1, &u, NULL, NULL));
            ck_assert_double_lt(fabs(u), 1e-3);
        } else {
            ck_assert_int_eq(status, FRICREG_OK);
            ck_assert_double_gt(fabs(u), 100.0 * x0); /* 10 steps: grown, not decayed */
        }
        fricreg_structure_free(s);
    }
}
END_TEST

int main(void)
{
    Suite *su = suite_create("guard_structure");
    TCase *tc = tcase_create("damping");
    tcase_add_test(tc, damping_counts_in_the_guard);
    suite_add_tcase(su, tc);
    /* ~300 runs beside fine references (5 s): the release tier's (guard_structure_release); the
     * quick tier sweeps the same guard (src/ode/step_guard.c) on the reference systems
     * (test_guard.c) */
    TCase *sweep = tcase_create("sweep");
    tcase_set_tags(sweep, "release");
    tcase_add_test(sweep, no_false_accept_on_structures);
    suite_add_tcase(su, sweep);
    SRunner *sr = srunner_create(su);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
