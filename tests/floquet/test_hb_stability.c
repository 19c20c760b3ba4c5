/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_hb_stability.c — Check suite for the stability of harmonic-balance solutions by the exact
 * monodromy and Hill's method, and the bifurcations located along a branch
 * (fricreg_hb_set_stability, fricreg_hb_set_stability_method, fricreg_hb_point_stability,
 * fricreg_hb_bifurcations, fricreg_hb_bifurcation; fricreg_hb.h).
 *
 * The models:
 *   - the contact pair of test_hb_continuation.c: 2 unit masses, K = [140 −20; −20 180], C =
 *     0.002 K, one lift-off element kt = 40, mu = 0.3, N0 = 2, kn = 100, tangential along dof 1,
 *     normal g = −x_2, p_c = (2, 1), H = 15, Omega = 11.5 .. 12.5 (with these parameters the
 *     branch does not overhang: scaled forcings 0.05 .. 8 were tried, every solution stable).
 *   - the bilinear oscillator (bilinear_oscillator): one dof and a unilateral spring, no
 *     friction, Omega = 2.2 .. 5.
 *   - the coupled bilinear pair (coupled_bilinear_pair): two bilinear oscillators joined by a
 *     spring, forced alike, Omega = 1.5 .. 1.9.
 *   - the Jenkins pair: 2 unit masses, K = [2 −1; −1 2], C = 0.05 K, one Jenkins element kt =
 *     3, mu N = 0.4 on dof 1 against the ground, p_c = (1, 0), H = 15, Omega = 0.6 .. 2.2.
 *
 * Where the numbers come from:
 *   - the monodromy matrix of a time integration, independent of the HB: the state (x, v, w),
 *     w the slider's offset, integrated by classical RK4 with 4000 steps a period, the slider's
 *     return mapping (an elastic trial clipped to mu N) once a step with w held through the
 *     step; the periodic orbit by Newton's shooting from the HB solution, the monodromy by
 *     central differences. Its largest |eigenvalue| against the HB's largest |multiplier|, and
 *     the stable/unstable verdict, at every point of a sweep where |mu_max − 1| > 0.05 (the
 *     non-smooth element's multipliers converge like the step, and the HB's like H^-2). By the
 *     exact monodromy (the automatic choice for every model here): on the contact pair
 *     (contact opening and closing, little slip) mu_max agrees to 9.3e-5 over 80 points,
 *     asserted to 5e-4; on the gap pair (11 to 15.4 rad/s, across an unstable stretch 13.6 ..
 *     14.2, mu_max up to 1.18, that both find) to 9.7e-4, asserted to 2e-3; on the Jenkins pair (stick-slip on every point) to
 *     2.4e-3, asserted to 3e-3, the shooting's own step error (4000/8000/16000 steps give
 *     0.5089/0.5078/0.5081 at Omega = 0.84, the monodromy 0.5076). By Hill's method (forced) on
 *     the Jenkins pair only the verdict: mu_max differs by up to 0.44 (0.148 against 0.589 at
 *     Omega = 0.68), as the stabilized hysteresis's HB Jacobian does not carry the slider's own
 *     (decaying) dynamics; on the contact and gap pairs Hill's agreed to 1.4e-3 and 9.6e-4.
 *   - the turning points of the gap pair against a fine continuation's fold (ds_max 1e-3, the
 *     vertex of the parabola through the extreme point and its neighbours); the stable flag
 *     flips across every located bifurcation.
 *   - the period doublings of the bilinear oscillator and the Neimark–Sacker bifurcations of the
 *     gap pair against a fine sweep (fine_crossing: point solves on a 1e-3 grid in Omega, the
 *     sign change of log mu_max refined by Brent's root finder) and against the shooting's
 *     crossing of |mu| = 1 (the same root finder on the monodromy's largest |eigenvalue|). On
 *     the bilinear oscillator's period-doubled stretch (two real negative multipliers) mu_max
 *     agrees with the shooting's to 6e-4.
 *   - the branch points of the coupled bilinear pair likewise, and the shooting's largest
 *     multiplier between them real and above +1.
 *   - where a slider sticks after a touchdown (the contact pair at mu = 3), an event-driven
 *     shooting that locates every switch (tests/support/liftoff_events.c): the step-resolved
 *     shooting's touchdown errs by a step for the whole stick after it (4.9e-3, 5.9e-3 off).
 *   - orbits on which nothing switches: GSL's eigenvalues of the linear system they follow.
 */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_complex_math.h>
#include <gsl/gsl_eigen.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_roots.h>

#include "fricreg_hb.h"
#include "liftoff_events.h"
#include "quiet_check.h"

#define H 15
#define NC (2 * H + 1)
#define MAXN 2
#define MAXE 2
#define MAXZ (2 * MAXN + MAXE)
#define MAXQ (2 * MAXE * NC)
static const double PI = 3.14159265358979323846;

/* n dofs and ne elements, J and Jn row-major ne x n. */
struct model {
    size_t n, ne;
    int normal;
    int iwan; /* the HB's one Iwan element of ne sliders, which the time domain takes as ne
                 Jenkins elements on J's first row */
    double M[4], C[4], K[4], J[MAXE * MAXN], Jn[MAXE * MAXN], kt[MAXE], mun[MAXE], mu[MAXE],
        n0[MAXE], kn[MAXE], pc[2], ps[2];
    double sweep_tol; /* > 0: the fine sweep's Newton tolerance (fricreg_hb_set_newton) */
    int method;       /* the stability's method (0: FRICREG_HB_STABILITY_AUTO) */
};

/* The HB unknowns' count: (2 if normal) ne (2H + 1). */
static size_t unknowns(const struct model *s)
{
    return (s->normal ? 2 : 1) * (s->iwan ? 1 : s->ne) * NC;
}

static struct model contact_pair(void)
{
    struct model s = {.n = 2, .ne = 1, .normal = 1};
    const double K[4] = {140, -20, -20, 180};
    for (int i = 0; i < 4; i++)
        s.K[i] = K[i], s.C[i] = 0.002 * K[i];
    s.M[0] = s.M[3] = 1.0;
    s.J[0] = 1.0, s.Jn[1] = -1.0;
    s.kt[0] = 40.0, s.mu[0] = 0.3, s.n0[0] = 2.0, s.kn[0] = 100.0;
    s.pc[0] = 2.0, s.pc[1] = 1.0;
    return s;
}

static struct model jenkins_pair(void)
{
    struct model s = {.n = 2, .ne = 1};
    const double K[4] = {2, -1, -1, 2};
    for (int i = 0; i < 4; i++)
        s.K[i] = K[i], s.C[i] = 0.05 * K[i];
    s.M[0] = s.M[3] = 1.0;
    s.J[0] = 1.0;
    s.kt[0] = 3.0, s.mun[0] = 0.4;
    s.pc[0] = 1.0;
    return s;
}

/* The gap pair: the contact pair with the element turned round (tangential along dof 2, normal
 * g = −x_1), a gap −N0/kn = 0.02 (N0 = −10, kn = 500) and mu = 0.01: a unilateral spring that
 * engages at large amplitude, hardening, so that the branch overhangs above 15 rad/s. */
static struct model gap_pair(void)
{
    struct model s = contact_pair();
    s.J[0] = 0.0, s.J[1] = 1.0;
    s.Jn[0] = -1.0, s.Jn[1] = 0.0;
    s.mu[0] = 0.01, s.n0[0] = -10.0, s.kn[0] = 500.0;
    return s;
}

/* The bilinear oscillator: one unit mass, k = 1, c = 0.04 (zeta = 0.02), and a unilateral spring
 * kn = 9 that engages at x < 0 without a gap or preload (the normal element on g = −x, N0 = 0;
 * mu = 0: no friction), so the stiffness is 1 for x > 0 and 10 for x < 0 (Shaw & Holmes's
 * piecewise linear oscillator, J. Sound Vib. 90, 1983); p_c = 1. Being piecewise linear and
 * homogeneous, its response scales with p_c and its multipliers do not depend on it. Its
 * T-periodic orbit loses stability by period doubling near Omega = 2.348: a real multiplier
 * through −1 (the shooting's too), and regains it near 4.908. */
static struct model bilinear_oscillator(void)
{
    struct model s = {.n = 1, .ne = 1, .normal = 1};
    s.M[0] = 1.0, s.K[0] = 1.0, s.C[0] = 0.04;
    s.J[0] = 1.0, s.Jn[0] = -1.0;
    s.kt[0] = 1.0, s.mu[0] = 0.0, s.n0[0] = 0.0, s.kn[0] = 9.0;
    s.pc[0] = 1.0;
    return s;
}

/* The coupled bilinear pair: two bilinear oscillators joined by a spring kc = 0.2, forced
 * alike (p_c = (1, 1)). Its symmetric response x_1 = x_2 is the single oscillator's (the joining
 * spring idle); an antisymmetric perturbation sees the stiffness 1 + 2 kc, and 9 more while the
 * orbit has x < 0: Hill's equation, whose principal tongue lies near the antisymmetric motion's
 * bilinear frequency 2 / (1/sqrt(1.4) + 1/sqrt(10.4)) = 1.731. There a real multiplier passes
 * through +1 at each end of a stretch where the symmetric branch is unstable: two
 * symmetry-breaking pitchforks, branch points of the symmetric branch. */
static struct model coupled_bilinear_pair(void)
{
    struct model s = {.n = 2, .ne = 2, .normal = 1};
    const double kc = 0.2;
    for (size_t i = 0; i < 2; i++) {
        s.M[3 * i] = 1.0, s.C[3 * i] = 0.04, s.K[3 * i] = 1.0 + kc;
        s.J[3 * i] = 1.0, s.Jn[3 * i] = -1.0;
        s.kt[i] = 1.0, s.mu[i] = 0.0, s.n0[i] = 0.0, s.kn[i] = 9.0;
        s.pc[i] = 1.0;
    }
    s.K[1] = s.K[2] = -kc;
    s.sweep_tol = 1e-6;
    return s;
}

static fricreg_hb *make(const struct model *s)
{
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(s->n, s->iwan ? 1 : s->ne, H, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, s->n, s->M), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, s->n, s->K), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_damping(hb, s->n, s->C), FRICREG_OK);
    if (s->normal)
        ck_assert_int_eq(fricreg_hb_set_normal_elements(hb, s->ne, s->n, s->J, s->Jn, s->kt, s->mu,
                                                        s->n0, s->kn),
                         FRICREG_OK);
    else if (s->iwan)
        ck_assert_int_eq(fricreg_hb_set_iwan(hb, 1, s->n, s->J, s->ne, s->kt, s->mun), FRICREG_OK);
    else
        ck_assert_int_eq(fricreg_hb_set_elements(hb, s->ne, s->n, s->J, s->kt, s->mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_excitation(hb, s->n, s->pc, s->ps), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stability_method(hb, s->method), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stability(hb, 1), FRICREG_OK);
    return hb;
}

/* ---- The time-domain reference ------------------------------------------------------------- */

/* Element e's forces at x with its slider's offset w held: the tangential f (the trial
 * kt (q − w) clipped to its bound) and the normal N; whether it slips. */
static int element(const struct model *s, size_t e, const double *x, double w, double *f, double *N,
                   double *q)
{
    const double *J = s->J + e * s->n, *Jn = s->Jn + e * s->n;
    double g = 0.0;
    *q = 0.0;
    for (size_t k = 0; k < s->n; k++)
        *q += J[k] * x[k], g += Jn[k] * x[k];
    double bound = s->mun[e];
    *N = 0.0;
    if (s->normal) {
        *N = fmax(0.0, s->n0[e] + s->kn[e] * g);
        bound = s->mu[e] * *N;
    }
    double trial = s->kt[e] * (*q - w);
    *f = fmax(-bound, fmin(bound, trial));
    return fabs(trial) > bound;
}

/* z' = (v, M^-1 (p − C v − K x − J^T f − Jn^T N)) with the sliders' w held (M diagonal
 * here). */
static void rhs(const struct model *s, double omega, double t, const double *z, const double *w,
                double *dz)
{
    size_t n = s->n;
    double f[MAXE], N[MAXE], q;
    for (size_t e = 0; e < s->ne; e++)
        element(s, e, z, w[e], &f[e], &N[e], &q);
    for (size_t i = 0; i < n; i++) {
        double a = s->pc[i] * cos(omega * t) + s->ps[i] * sin(omega * t);
        for (size_t e = 0; e < s->ne; e++)
            a -= s->J[e * n + i] * f[e] + s->Jn[e * n + i] * N[e];
        for (size_t k = 0; k < n; k++)
            a -= s->C[i * n + k] * z[n + k] + s->K[i * n + k] * z[k];
        dz[i] = z[n + i];
        dz[n + i] = a / s->M[i * n + i];
    }
}

/* One period from z = (x, v, w) by RK4, steps steps, the sliders' return mapping after each. */
static void period(const struct model *s, double omega, int steps, const double *z0, double *z)
{
    size_t n = s->n, d = 2 * n;
    double dt = 2.0 * PI / omega / steps, k1[MAXZ], k2[MAXZ], k3[MAXZ], k4[MAXZ], y[MAXZ];
    memcpy(z, z0, (d + s->ne) * sizeof *z);
    for (int i = 0; i < steps; i++) {
        double t = i * dt, *w = z + d;
        rhs(s, omega, t, z, w, k1);
        for (size_t j = 0; j < d; j++)
            y[j] = z[j] + 0.5 * dt * k1[j];
        rhs(s, omega, t + 0.5 * dt, y, w, k2);
        for (size_t j = 0; j < d; j++)
            y[j] = z[j] + 0.5 * dt * k2[j];
        rhs(s, omega, t + 0.5 * dt, y, w, k3);
        for (size_t j = 0; j < d; j++)
            y[j] = z[j] + dt * k3[j];
        rhs(s, omega, t + dt, y, w, k4);
        for (size_t j = 0; j < d; j++)
            z[j] += dt / 6.0 * (k1[j] + 2.0 * k2[j] + 2.0 * k3[j] + k4[j]);
        for (size_t e = 0; e < s->ne; e++) {
            double f, N, q;
            if (element(s, e, z, w[e], &f, &N, &q))
                w[e] = q - f / s->kt[e];
        }
    }
}

/* The monodromy Phi[dz dz] of the period map at z by central differences. */
static void monodromy(const struct model *s, double omega, int steps, const double *z, double *Phi,
                      double scale)
{
    size_t dz = 2 * s->n + s->ne;
    double zp[MAXZ], zm[MAXZ], fp[MAXZ], fm[MAXZ];
    for (size_t j = 0; j < dz; j++) {
        double h = 1e-6 * scale;
        memcpy(zp, z, dz * sizeof *z);
        memcpy(zm, z, dz * sizeof *z);
        zp[j] += h, zm[j] -= h;
        period(s, omega, steps, zp, fp);
        period(s, omega, steps, zm, fm);
        for (size_t i = 0; i < dz; i++)
            Phi[i * dz + j] = (fp[i] - fm[i]) / (2.0 * h);
    }
}

/* Newton's shooting on z = period(z) from z, in place; then the eigenvalues of the monodromy
 * at the orbit into ev[2 n + ne]. */
static void shooting_multipliers(const struct model *s, double omega, double *z,
                                 gsl_vector_complex *ev)
{
    const int steps = 4000;
    size_t dz = 2 * s->n + s->ne;
    double scale = 0.0, Phi[MAXZ * MAXZ], r[MAXZ], zn[MAXZ], dx[MAXZ];
    for (size_t j = 0; j < dz; j++)
        scale = fmax(scale, fabs(z[j]));
    gsl_permutation *p = gsl_permutation_alloc(dz);
    for (int it = 0;; it++) {
        ck_assert_int_lt(it, 30);
        period(s, omega, steps, z, zn);
        double res = 0.0;
        for (size_t j = 0; j < dz; j++)
            r[j] = zn[j] - z[j], res = fmax(res, fabs(r[j]));
        if (res <= 1e-10 * scale)
            break;
        monodromy(s, omega, steps, z, Phi, scale);
        for (size_t j = 0; j < dz; j++)
            Phi[j * dz + j] -= 1.0;
        gsl_matrix_view A = gsl_matrix_view_array(Phi, dz, dz);
        gsl_vector_view b = gsl_vector_view_array(r, dz), x = gsl_vector_view_array(dx, dz);
        int sg;
        gsl_linalg_LU_decomp(&A.matrix, p, &sg);
        gsl_linalg_LU_solve(&A.matrix, p, &b.vector, &x.vector);
        for (size_t j = 0; j < dz; j++)
            z[j] -= dx[j];
    }
    gsl_permutation_free(p);
    monodromy(s, omega, steps, z, Phi, scale);
    gsl_matrix_view A = gsl_matrix_view_array(Phi, dz, dz);
    gsl_eigen_nonsymm_workspace *w = gsl_eigen_nonsymm_alloc(dz);
    ck_assert_int_eq(gsl_eigen_nonsymm(&A.matrix, ev, w), 0);
    gsl_eigen_nonsymm_free(w);
}

/* The shooting's multiplier of the largest modulus at the orbit it finds from z. */
static gsl_complex shooting_multiplier(const struct model *s, double omega, double *z)
{
    size_t dz = 2 * s->n + s->ne;
    gsl_vector_complex *ev = gsl_vector_complex_alloc(dz);
    shooting_multipliers(s, omega, z, ev);
    /* a slider stuck over the whole period holds its offset: its row of Phi is the identity's,
     * its multiplier exactly 1 (to the differences' rounding), neutral, which the HB leaves out */
    gsl_complex top = gsl_complex_rect(0.0, 0.0);
    for (size_t j = 0; j < dz; j++) {
        gsl_complex mu = gsl_vector_complex_get(ev, j);
        if (gsl_complex_abs(gsl_complex_sub_real(mu, 1.0)) > 1e-7 &&
            gsl_complex_abs(mu) > gsl_complex_abs(top))
            top = mu;
    }
    gsl_vector_complex_free(ev);
    return top;
}

/* The largest |eigenvalue| of the monodromy at the orbit shooting_multiplier finds. */
static double shooting_mu_max(const struct model *s, double omega, double *z)
{
    return gsl_complex_abs(shooting_multiplier(s, omega, z));
}

/* The state (x, v, w) at t = 0 of the last HB solution: x and v from its coefficients, each
 * slider's w from its return mapping run over two periods of its q(t) (from stuck). */
static void hb_state(fricreg_hb *hb, const struct model *s, double omega, double *z)
{
    size_t n = s->n;
    double x[MAXN * NC];
    ck_assert_int_eq(fricreg_hb_displacement(hb, n, NC, x), FRICREG_OK);
    for (size_t k = 0; k < n; k++) {
        z[k] = x[k * NC], z[n + k] = 0.0;
        for (int h = 1; h <= H; h++) {
            z[k] += x[k * NC + 2 * h - 1];
            z[n + k] += h * omega * x[k * NC + 2 * h];
        }
    }
    const int samples = 4000;
    double *w = z + 2 * n;
    for (int i = 0; i <= 2 * samples; i++) {
        double th = 2.0 * PI * i / samples, xt[MAXN], f, N, q;
        for (size_t k = 0; k < n; k++) {
            xt[k] = x[k * NC];
            for (int h = 1; h <= H; h++)
                xt[k] += x[k * NC + 2 * h - 1] * cos(h * th) + x[k * NC + 2 * h] * sin(h * th);
        }
        for (size_t e = 0; e < s->ne; e++) {
            if (i == 0) /* stuck where q starts */
                element(s, e, xt, 0.0, &f, &N, &w[e]);
            if (element(s, e, xt, w[e], &f, &N, &q))
                w[e] = q - f / s->kt[e];
        }
    }
}

/* A sweep by fixed-Omega solves from q (warm starts) over count frequencies from w0 by dw:
 * at each solution where |mu_max − 1| > 0.05, the verdict and (tol > 0) mu_max to tol of the
 * shooting's.
 * Returns the number of points compared. */
static int sweep_against_shooting(fricreg_hb *hb, const struct model *s, double *q, double w0,
                                  double dw, int count, double tol)
{
    int compared = 0;
    size_t nq = unknowns(s);
    for (int i = 0; i < count; i++) {
        double omega = w0 + i * dw, mu = 0.0, z[MAXZ];
        int stable = -1;
        if (fricreg_hb_solve(hb, omega, nq, q, q) != FRICREG_OK)
            break; /* past a fold */
        ck_assert_int_eq(fricreg_hb_point_stability(hb, FRICREG_HB_SOLUTION, &stable, &mu),
                         FRICREG_OK);
        if (fabs(mu - 1.0) <= 0.05)
            continue;
        hb_state(hb, s, omega, z);
        double ref = shooting_mu_max(s, omega, z);
        if (getenv("HB_PRINT"))
            fprintf(stderr, "Omega %.5f: HB stable %d mu_max %.6f, shooting %.6f (%.2e)\n", omega,
                    stable, mu, ref, mu / ref - 1.0);
        ck_assert_int_eq(stable, ref < 1.0);
        if (tol > 0.0)
            ck_assert_double_le(fabs(mu - ref), tol * ref);
        compared++;
    }
    return compared;
}

START_TEST(contact_pair_against_shooting)
{
    struct model s = contact_pair();
    fricreg_hb *hb = make(&s);
    double q[2 * NC], q0[2 * NC];
    int compared = 0;
    /* from Omega = 12 both ways, and from either end */
    ck_assert_int_eq(fricreg_hb_solve(hb, 12.0, 2 * NC, NULL, q0), FRICREG_OK);
    memcpy(q, q0, sizeof q);
    compared += sweep_against_shooting(hb, &s, q, 12.0, 0.02, 15, 5e-4);
    memcpy(q, q0, sizeof q);
    compared += sweep_against_shooting(hb, &s, q, 12.0, -0.02, 15, 5e-4);
    /* the lower and upper branches by sweeps from either end */
    ck_assert_int_eq(fricreg_hb_solve(hb, 11.5, 2 * NC, NULL, q), FRICREG_OK);
    compared += sweep_against_shooting(hb, &s, q, 11.5, 0.04, 25, 5e-4);
    ck_assert_int_eq(fricreg_hb_solve(hb, 12.5, 2 * NC, NULL, q), FRICREG_OK);
    compared += sweep_against_shooting(hb, &s, q, 12.5, -0.04, 25, 5e-4);
    ck_assert_int_ge(compared, 20);
    fricreg_hb_free(hb);
}
END_TEST

/* The event-driven shooting's largest |multiplier| of the contact pair's HB orbit at omega
 * (liftoff_events.h): the slider's offset's eigenvalue (its neutral 1 or its 0) left out as the
 * exact monodromy leaves it, the orbit's touchdowns into *touchdowns. */
static double event_mu_max(const struct model *s, fricreg_hb *hb, double omega, int *touchdowns)
{
    struct liftoff_system sys = {
        .n = s->n, .kt = s->kt[0], .mu = s->mu[0], .n0 = s->n0[0], .kn = s->kn[0], .omega = omega};
    for (size_t i = 0; i < s->n; i++) { /* unit masses, as liftoff_events.h's */
        ck_assert(s->M[i * s->n + i] == 1.0);
        sys.J[i] = s->J[i], sys.Jn[i] = s->Jn[i], sys.p[i] = s->pc[i];
        for (size_t k = 0; k < s->n; k++) {
            sys.K[i * s->n + k] = s->K[i * s->n + k];
            sys.C[i * s->n + k] = s->C[i * s->n + k];
        }
    }
    double x[MAXN * NC], t0 = 0.0, z[LIFTOFF_MAXZ], zn[LIFTOFF_MAXZ];
    double Phi[LIFTOFF_MAXZ * LIFTOFF_MAXZ];
    ck_assert_int_eq(fricreg_hb_displacement(hb, s->n, NC, x), FRICREG_OK);
    liftoff_start(&sys, H, x, &t0, z);
    liftoff_shoot(&sys, t0, z, Phi);
    liftoff_period(&sys, t0, z, zn, touchdowns);
    size_t dz = 2 * s->n + 1;
    gsl_matrix_view A = gsl_matrix_view_array(Phi, dz, dz);
    gsl_vector_complex *ev = gsl_vector_complex_alloc(dz);
    gsl_eigen_nonsymm_workspace *w = gsl_eigen_nonsymm_alloc(dz);
    ck_assert_int_eq(gsl_eigen_nonsymm(&A.matrix, ev, w), 0);
    gsl_eigen_nonsymm_free(w);
    size_t low = 0; /* the offset's: the one nearest 0 or 1 */
    for (size_t j = 1; j < dz; j++) {
        gsl_complex a = gsl_vector_complex_get(ev, j), b = gsl_vector_complex_get(ev, low);
        if (fmin(gsl_complex_abs(a), gsl_complex_abs(gsl_complex_sub_real(a, 1.0))) <
            fmin(gsl_complex_abs(b), gsl_complex_abs(gsl_complex_sub_real(b, 1.0))))
            low = j;
    }
    double top = 0.0;
    for (size_t j = 0; j < dz; j++)
        if (j != low)
            top = fmax(top, gsl_complex_abs(gsl_vector_complex_get(ev, j)));
    gsl_vector_complex_free(ev);
    return top;
}

/* A slider that sticks after a touchdown (the touchdown's saltation δw = (J_t − (u'/g') J_n) δx
 * at work), and orbits whose slider grazes its bound: the contact pair at mu = 1 and 3 and its
 * forcing scaled. The exact monodromy's mu_max against an event-driven shooting that locates
 * every switch to 1e-14 T (liftoff_events.h), to 2e-5 (measured 7.5e-7 at most), and the
 * orbit's touchdowns. Where the contact opens and closes once a period (mu = 3 at 12.5 and
 * 11.5 rad/s), the step-resolved shooting above, whose touchdown errs by a step for the whole
 * stick after it, is 4.9e-3 and 5.9e-3 off. Where the force only touches the bound (the other
 * three), the HB's march reports switches into the state the slider is in and slips of no
 * duration: the monodromy took them for slips and said 1.0 to 1.055 (an unstable verdict at
 * 1.055) where the slider sticks throughout, 0.926 to 0.935 (switches.c's effective_switches).
 * Points whose slip lasts about the graze's bound are left out: at mu = 1, half the forcing,
 * 11 rad/s, the reference BLAS's HB orbit slips for 1.35e-8 rad (OpenBLAS's not at all), and
 * the monodromy says 0.953 against 0.926. */
START_TEST(contact_pair_touchdown_against_event_shooting)
{
    const struct {
        double mu, force, omega;
        int touchdowns;
    } at[5] = {{3.0, 0.5, 12.5, 1},
               {3.0, 1.0, 11.5, 1},
               {1.0, 0.2, 12.5, 0},
               {3.0, 1.0, 11.0, 0},
               {3.0, 0.5, 12.25, 0}};
    for (int i = 0; i < 5; i++) {
        struct model s = contact_pair();
        s.mu[0] = at[i].mu;
        s.pc[0] *= at[i].force, s.pc[1] *= at[i].force;
        s.method = FRICREG_HB_STABILITY_MONODROMY;
        fricreg_hb *hb = make(&s);
        double q[2 * NC], mu = 0.0, z[MAXZ];
        int stable = -1, touchdowns = -1;
        ck_assert_int_eq(fricreg_hb_solve(hb, at[i].omega, 2 * NC, NULL, q), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_point_stability(hb, FRICREG_HB_SOLUTION, &stable, &mu),
                         FRICREG_OK);
        double ref = event_mu_max(&s, hb, at[i].omega, &touchdowns);
        hb_state(hb, &s, at[i].omega, z);
        double step_ref = shooting_mu_max(&s, at[i].omega, z);
        if (getenv("HB_PRINT"))
            fprintf(stderr,
                    "mu %g, force x%g, Omega %g: monodromy %.7f, event-driven shooting %.7f "
                    "(%d touchdown), step-resolved %.7f\n",
                    at[i].mu, at[i].force, at[i].omega, mu, ref, touchdowns, step_ref);
        ck_assert_int_eq(touchdowns, at[i].touchdowns);
        ck_assert_int_eq(stable, 1);
        ck_assert_double_le(fabs(mu - ref), 2e-5 * ref);
        fricreg_hb_free(hb);
    }
}
END_TEST

/* The Jenkins pair by the exact monodromy (the automatic choice): mu_max to 3e-3 of the
 * shooting's (measured 2.4e-3 at most, at Omega = 0.84: the shooting's first-order error in its
 * step); by Hill's method the verdict only (mu_max off by up to 0.44). */
START_TEST(jenkins_pair_against_shooting)
{
    struct model s = jenkins_pair();
    fricreg_hb *hb = make(&s);
    double q[NC];
    int method = -1;
    ck_assert_int_eq(fricreg_hb_get_stability_method(hb, &method), FRICREG_OK);
    ck_assert_int_eq(method, FRICREG_HB_STABILITY_MONODROMY);
    ck_assert_int_eq(fricreg_hb_solve(hb, 0.6, NC, NULL, q), FRICREG_OK);
    ck_assert_int_ge(sweep_against_shooting(hb, &s, q, 0.6, 0.08, 21, 3e-3), 20);
    ck_assert_int_eq(fricreg_hb_set_stability_method(hb, FRICREG_HB_STABILITY_HILL), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_get_stability_method(hb, &method), FRICREG_OK);
    ck_assert_int_eq(method, FRICREG_HB_STABILITY_HILL);
    ck_assert_int_eq(fricreg_hb_solve(hb, 0.6, NC, NULL, q), FRICREG_OK);
    ck_assert_int_ge(sweep_against_shooting(hb, &s, q, 0.6, 0.08, 21, 0.0), 20);
    fricreg_hb_free(hb);
}
END_TEST

/* Every multiplier of the Jenkins pair's orbit, from fricreg_hb_point_exponents, against the
 * shooting's monodromy (its 2 n + 1 eigenvalues less the one nearest 0, the slider's forgotten
 * offset, or its neutral 1 where it sticks throughout), each within 3e-3 (the shooting's
 * first-order error in its step, as above; measured 1.2e-3 at most) below, at and above the
 * resonance; and the exponents' largest |μ| is point_stability's mu_max. */
START_TEST(jenkins_pair_exponents_against_shooting)
{
    struct model s = jenkins_pair();
    fricreg_hb *hb = make(&s);
    const double omegas[3] = {0.6, 0.84, 1.4};
    double q[NC] = {0};
    size_t dz = 2 * s.n + s.ne;
    gsl_vector_complex *ev = gsl_vector_complex_alloc(dz);
    for (int i = 0; i < 3; i++) {
        double omega = omegas[i], lambda[4 * MAXN], z[MAXZ], mu_max = 0.0, top = 0.0;
        int stable = -1, used[MAXZ] = {0};
        ck_assert_int_eq(fricreg_hb_solve(hb, omega, NC, i ? q : NULL, q), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_point_stability(hb, FRICREG_HB_SOLUTION, &stable, &mu_max),
                         FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_point_exponents(hb, FRICREG_HB_SOLUTION, 2 * s.n, lambda),
                         FRICREG_OK);
        hb_state(hb, &s, omega, z);
        shooting_multipliers(&s, omega, z, ev);
        size_t low = 0; /* the forgotten offset's 0, or where the slider sticks, its neutral 1 */
        for (size_t j = 1; j < dz; j++) {
            gsl_complex a = gsl_vector_complex_get(ev, j), b = gsl_vector_complex_get(ev, low);
            if (fmin(gsl_complex_abs(a), gsl_complex_abs(gsl_complex_sub_real(a, 1.0))) <
                fmin(gsl_complex_abs(b), gsl_complex_abs(gsl_complex_sub_real(b, 1.0))))
                low = j;
        }
        used[low] = 1;
        for (size_t e = 0; e < 2 * s.n; e++) {
            double T = 2.0 * PI / omega, mod = exp(lambda[2 * e] * T);
            ck_assert(fabs(lambda[2 * e + 1]) <= 0.5 * omega * (1.0 + 1e-12));
            gsl_complex mu = gsl_complex_polar(mod, lambda[2 * e + 1] * T);
            size_t best = dz;
            for (size_t j = 0; j < dz; j++) {
                double d = gsl_complex_abs(gsl_complex_sub(mu, gsl_vector_complex_get(ev, j)));
                if (!used[j] &&
                    (best == dz ||
                     d < gsl_complex_abs(gsl_complex_sub(mu, gsl_vector_complex_get(ev, best)))))
                    best = j;
            }
            double d = gsl_complex_abs(gsl_complex_sub(mu, gsl_vector_complex_get(ev, best)));
            if (getenv("HB_PRINT"))
                fprintf(stderr, "Omega %.2f: mu %+.6f %+.6fi, shooting's %.2e off\n", omega,
                        GSL_REAL(mu), GSL_IMAG(mu), d);
            ck_assert_double_le(d, 3e-3);
            used[best] = 1;
            top = fmax(top, mod);
        }
        ck_assert_double_eq_tol(top, mu_max, 1e-12 * mu_max);
    }
    gsl_vector_complex_free(ev);
    fricreg_hb_free(hb);
}
END_TEST

/* The exponents of the linear pair M x'' + C x' + (K + k J^T J) x = 0 into lambda[2 n] as
 * (Re, Im) pairs sorted by Re then Im: GSL's eigenvalues of its first-order matrix, the
 * reference of the one-piece orbits below. */
static void linear_exponents(const struct model *s, double k, double *lambda)
{
    size_t n = s->n, dz = 2 * n;
    double A[4 * MAXN * MAXN] = {0};
    for (size_t i = 0; i < n; i++) {
        A[i * dz + n + i] = 1.0;
        for (size_t j = 0; j < n; j++) { /* M diagonal */
            double kij = s->K[i * n + j] + k * s->J[i] * s->J[j];
            A[(n + i) * dz + j] = -kij / s->M[i * n + i];
            A[(n + i) * dz + n + j] = -s->C[i * n + j] / s->M[i * n + i];
        }
    }
    gsl_matrix_view Av = gsl_matrix_view_array(A, dz, dz);
    gsl_vector_complex *ev = gsl_vector_complex_alloc(dz);
    gsl_eigen_nonsymm_workspace *w = gsl_eigen_nonsymm_alloc(dz);
    ck_assert_int_eq(gsl_eigen_nonsymm(&Av.matrix, ev, w), 0);
    gsl_eigen_nonsymm_free(w);
    for (size_t e = 0; e < dz; e++) {
        lambda[2 * e] = GSL_REAL(gsl_vector_complex_get(ev, e));
        lambda[2 * e + 1] = GSL_IMAG(gsl_vector_complex_get(ev, e));
    }
    gsl_vector_complex_free(ev);
}

static int by_re_im(const void *a, const void *b)
{
    const double *x = a, *y = b;
    return x[0] != y[0] ? (x[0] > y[0]) - (x[0] < y[0]) : (x[1] > y[1]) - (x[1] < y[1]);
}

/* Orbits on which nothing switches, one after the other on one object whose model changes in
 * between: the Jenkins pair with a slider that sticks throughout (slip force 100), then with
 * none (slip force 0: it slides throughout, a fixed force of 0). Each orbit's exponents are its
 * linear system's (the slider's spring in, then out), within 1e-9: the one-piece shortcut
 * (monodromy.c) keeps the last matrix's eigenvalues and must not reuse them for a new matrix of
 * the same order. Exponents wrap into Im in (−Ω/2, Ω/2]: the reference's too, at Ω = 3 above
 * both pairs' frequencies (1 to 2.7 rad/s) only by whole multiples of Ω. */
START_TEST(one_piece_orbits_follow_the_model)
{
    struct model s = jenkins_pair();
    const double omega = 3.0, T = 2.0 * PI / omega, bounds[2] = {100.0, 0.0};
    s.method = FRICREG_HB_STABILITY_MONODROMY;
    fricreg_hb *hb = make(&s);
    for (int k = 0; k < 2; k++) {
        double mun[1] = {bounds[k]}, lambda[4 * MAXN], want[4 * MAXN], q[NC];
        ck_assert_int_eq(fricreg_hb_set_elements(hb, s.ne, s.n, s.J, s.kt, mun), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_solve(hb, omega, NC, NULL, q), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_point_exponents(hb, FRICREG_HB_SOLUTION, 2 * s.n, lambda),
                         FRICREG_OK);
        linear_exponents(&s, k == 0 ? s.kt[0] : 0.0, want);
        for (size_t e = 0; e < 2 * s.n; e++) /* the reference's Im wrapped as the exponents' */
            want[2 * e + 1] = atan2(sin(want[2 * e + 1] * T), cos(want[2 * e + 1] * T)) / T;
        qsort(lambda, 2 * s.n, 2 * sizeof *lambda, by_re_im);
        qsort(want, 2 * s.n, 2 * sizeof *want, by_re_im);
        for (size_t e = 0; e < 4 * s.n; e++)
            ck_assert_msg(fabs(lambda[e] - want[e]) <= 1e-9, "slip force %g: %.12g against %.12g",
                          bounds[k], lambda[e], want[e]);
    }
    fricreg_hb_free(hb);
}
END_TEST

/* An Iwan element of two sliders (kt 2 and 1, slip forces 0.15 and 0.35) on the Jenkins pair's
 * dof 1, by the exact monodromy against the shooting with the sliders as two Jenkins elements:
 * each slider's offset its own state, its own switches. */
START_TEST(iwan_pair_against_shooting)
{
    struct model s = jenkins_pair();
    s.ne = 2, s.iwan = 1;
    s.J[2] = 1.0;
    s.kt[0] = 2.0, s.kt[1] = 1.0, s.mun[0] = 0.15, s.mun[1] = 0.35;
    fricreg_hb *hb = make(&s);
    double q[NC];
    ck_assert_int_eq(fricreg_hb_solve(hb, 0.6, NC, NULL, q), FRICREG_OK);
    ck_assert_int_ge(sweep_against_shooting(hb, &s, q, 0.6, 0.08, 21, 3e-3), 20);
    fricreg_hb_free(hb);
}
END_TEST

START_TEST(gap_pair_against_shooting)
{
    struct model s = gap_pair();
    fricreg_hb *hb = make(&s);
    double q[2 * NC];
    ck_assert_int_eq(fricreg_hb_solve(hb, 11.0, 2 * NC, NULL, q), FRICREG_OK);
    ck_assert_int_ge(sweep_against_shooting(hb, &s, q, 11.0, 0.1, 45, 2e-3), 20);
    fricreg_hb_free(hb);
}
END_TEST

/* ---- Crossings of the unit circle against independent references ------------------------- */

/* log mu_max of the point solve at omega, warm-started from and updating q: the test function
 * of the fine sweep (crossing) and of the shooting (shooting_crossing). */
struct crossing {
    const struct model *s;
    fricreg_hb *hb;
    double q[MAXQ], z[MAXZ], level;
};

static double hb_log_mu(double omega, void *p)
{
    struct crossing *c = p;
    int stable;
    double mu;
    int status = fricreg_hb_solve(c->hb, omega, unknowns(c->s), c->q, c->q);
    /* at a branch point the crossing is where the HB Jacobian is singular, and Brent comes to
     * it within rounding: Newton seeded from the point beside it may find no descent there
     * (coupled_pair_branch_points at 1.649368576 with one BLAS thread); the branches meet, so
     * the unseeded start's solution is the same point */
    if (status != FRICREG_OK)
        status = fricreg_hb_solve(c->hb, omega, unknowns(c->s), NULL, c->q);
    ck_assert_int_eq(status, FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_point_stability(c->hb, FRICREG_HB_SOLUTION, &stable, &mu),
                     FRICREG_OK);
    return log(mu) - c->level;
}

static double shooting_log_mu(double omega, void *p)
{
    struct crossing *c = p;
    return log(shooting_mu_max(c->s, omega, c->z));
}

/* The root of fn in [a, b] by Brent's method (gsl_root_fsolver_brent) to 1e-12 in Omega. */
static double brent(double (*fn)(double, void *), void *p, double a, double b)
{
    gsl_function f = {fn, p};
    gsl_root_fsolver *r = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    ck_assert_int_eq(gsl_root_fsolver_set(r, &f, a, b), GSL_SUCCESS);
    for (int it = 0;; it++) {
        ck_assert_int_lt(it, 100);
        ck_assert_int_eq(gsl_root_fsolver_iterate(r), GSL_SUCCESS);
        a = gsl_root_fsolver_x_lower(r), b = gsl_root_fsolver_x_upper(r);
        if (b - a <= 1e-12)
            break;
    }
    double x = gsl_root_fsolver_root(r);
    gsl_root_fsolver_free(r);
    return x;
}

/* The fine sweep's crossing near omega: point solves (fixed Omega, warm-started along the grid,
 * the first without a guess) on a grid of step 1e-3 over omega ± 0.02, whose sign change of
 * log mu_max − level nearest omega brackets the root, which Brent's method narrows to 1e-12.
 * level 0 is the unit circle, where the continuation's bisection puts a change of stability
 * (its stable flag flips at a margin, |mu| > 1 + 1e-6, fricreg_hb_set_stability). */
static double fine_crossing(const struct model *s, double omega, double level)
{
    struct crossing c = {.s = s, .hb = make(s), .level = level};
    if (s->sweep_tol > 0.0)
        ck_assert_int_eq(fricreg_hb_set_newton(c.hb, s->sweep_tol, 50), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_solve(c.hb, omega - 0.02, unknowns(s), NULL, c.q), FRICREG_OK);
    double prev = hb_log_mu(omega - 0.02, &c), lo = 0.0, dist = INFINITY, q[MAXQ];
    for (int i = 1; i <= 40; i++) {
        double w = omega - 0.02 + 1e-3 * i, g = hb_log_mu(w, &c);
        if ((g > 0.0) != (prev > 0.0) && fabs(w - 5e-4 - omega) < dist)
            dist = fabs(w - 5e-4 - omega), lo = w - 1e-3, memcpy(q, c.q, sizeof q);
        prev = g;
    }
    ck_assert(dist < 0.02);
    memcpy(c.q, q, sizeof q);
    double root = brent(hb_log_mu, &c, lo, lo + 1e-3);
    fricreg_hb_free(c.hb);
    return root;
}

/* The shooting's crossing of |mu| = 1 in [a, b] (Brent on log of shooting_mu_max's largest
 * |eigenvalue| of the monodromy, 4000 RK4 steps a period), from the state z of an orbit
 * nearby. */
static double shooting_crossing(const struct model *s, const double *z, double a, double b)
{
    struct crossing c = {.s = s};
    memcpy(c.z, z, sizeof c.z);
    return brent(shooting_log_mu, &c, a, b);
}

/* The bilinear oscillator across its period-doubled stretch, where two real negative
 * multipliers make four Hill exponents of |Im| = Omega/2 (fricreg_hb_set_stability): mu_max
 * to 2e-2 of the shooting's and the verdict at every point from 2.3 to 4.0 (measured 6e-4). */
/* The bilinear oscillator's sweep by the exact monodromy (the automatic choice), then by Hill's
 * method, whose selection of the exponents among the copies λ + i k Ω decides the period
 * doubling's two real negative multipliers. */
START_TEST(bilinear_against_shooting)
{
    for (int method = 0; method < 2; method++) {
        struct model s = bilinear_oscillator();
        s.method = method == 0 ? FRICREG_HB_STABILITY_AUTO : FRICREG_HB_STABILITY_HILL;
        fricreg_hb *hb = make(&s);
        double q[2 * NC];
        ck_assert_int_eq(fricreg_hb_solve(hb, 2.3, 2 * NC, NULL, q), FRICREG_OK);
        ck_assert_int_ge(sweep_against_shooting(hb, &s, q, 2.3, 0.1, 18, 0.02), 15);
        fricreg_hb_free(hb);
    }
}
END_TEST

/* A fine continuation of the gap pair's branch over [14.7, 17], across both folds (ds_max 1e-3,
 * no stability): the reference of fine_fold. */
static fricreg_hb *fine_continuation(const struct model *s)
{
    fricreg_hb *hb = make(s);
    ck_assert_int_eq(fricreg_hb_set_stability(hb, 0), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_continuation(hb, 1e-3, 1e-7, 1e-3, 100000), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_continue(hb, 14.7, 17.0, 2 * NC, NULL), FRICREG_OK);
    return hb;
}

/* The fold of the fine continuation hb near omega: among its points the extreme of Omega
 * nearest to omega (a local maximum when top, else minimum), and the vertex of the parabola
 * Omega(rms of dof 0) through it and its neighbours (rms runs monotonically through a fold). */
static double fine_fold(fricreg_hb *hb, const struct model *s, double omega, int top)
{
    size_t np = fricreg_hb_points(hb), best = 0;
    double w[3], r[3][MAXN], dist = INFINITY;
    for (size_t k = 1; k + 1 < np; k++) {
        for (int i = 0; i < 3; i++)
            QUIET_OK(fricreg_hb_point(hb, k - 1 + (size_t)i, &w[i], s->n, r[i]));
        int extreme = top ? w[1] >= w[0] && w[1] >= w[2] : w[1] <= w[0] && w[1] <= w[2];
        if (extreme && fabs(w[1] - omega) < dist)
            dist = fabs(w[1] - omega), best = k;
    }
    ck_assert_uint_gt(best, 0);
    for (int i = 0; i < 3; i++)
        fricreg_hb_point(hb, best - 1 + (size_t)i, &w[i], s->n, r[i]);
    double x0 = r[0][0], x1 = r[1][0], x2 = r[2][0];
    double d01 = (w[1] - w[0]) / (x1 - x0), d12 = (w[2] - w[1]) / (x2 - x1);
    double a = (d12 - d01) / (x2 - x0), xv = 0.5 * (x0 + x1) - d01 / (2.0 * a);
    return w[0] + d01 * (xv - x0) + a * (xv - x0) * (xv - x1); /* Newton's form's vertex */
}

/* The gap pair's branch from 11 to 17 rad/s overhangs: two turning points located against the
 * fine continuation's fold, to 1e-6 (measured 1.1e-11 at the upper fold at 16.0666 and 1.2e-7
 * at the lower one at 15.0296, from 14.7; the same continuation from 11 puts its grid
 * elsewhere and the lower fold's parabola 1.5e-6 off, so the reference's grid sets that
 * figure), the stable flag
 * flipping across each; a Neimark–Sacker bifurcation at each end of the unstable stretch,
 * against the fine sweep's crossing of the unit circle to 1e-6 (measured 6.5e-11 at
 * 13.5816831 and 4.4e-11 at 14.4257295; bisecting on the stable flag's margin instead put the
 * upper one 3.0e-6 past it, 1e-6 / (d log mu/dOmega) where the crossing is flat), and against
 * the shooting's to 2e-3 (5.1e-4, 6.9e-4; the shooting's own scatter between 4000 and 8000
 * steps a period is 5e-4 and 1.6e-4). */
START_TEST(gap_pair_bifurcations)
{
    struct model s = gap_pair();
    fricreg_hb *hb = make(&s), *fine = fine_continuation(&s);
    ck_assert_int_eq(fricreg_hb_continue(hb, 11.0, 17.0, 2 * NC, NULL), FRICREG_OK);
    size_t nb = fricreg_hb_bifurcations(hb), tps = 0, ns = 0;
    for (size_t i = 0; i < nb; i++) {
        int type = 0, s0 = -1, s1 = -1;
        double om = 0.0, rms[MAXN], mu;
        size_t k = 0;
        ck_assert_int_eq(fricreg_hb_bifurcation(hb, i, &type, &om, &k, s.n, rms), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_point_stability(hb, k, &s0, &mu), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_point_stability(hb, k + 1, &s1, &mu), FRICREG_OK);
        if (getenv("HB_PRINT"))
            fprintf(stderr, "bifurcation %d at Omega %.10f after point %zu: stable %d -> %d\n",
                    type, om, k, s0, s1);
        ck_assert_int_ne(s0, s1);
        if (type == FRICREG_HB_TP) {
            double fold = fine_fold(fine, &s, om, tps == 0);
            if (getenv("HB_PRINT"))
                fprintf(stderr, "  fine fold %.10f (%.2e)\n", fold, om - fold);
            ck_assert_double_le(fabs(om - fold), 1e-6);
            tps++;
        } else {
            ck_assert_int_eq(type, FRICREG_HB_NS);
            ck_assert(om > 13.5 && om < 14.6);
            double circle = fine_crossing(&s, om, 0.0);
            double q[2 * NC], z[MAXZ];
            ck_assert_int_eq(fricreg_hb_solve(hb, om, 2 * NC, NULL, q), FRICREG_OK);
            hb_state(hb, &s, om, z);
            double shot = shooting_crossing(&s, z, om - 0.02, om + 0.02);
            if (getenv("HB_PRINT"))
                fprintf(stderr, "  unit circle %.10f (%.2e), shooting %.10f (%.2e)\n", circle,
                        om - circle, shot, om - shot);
            ck_assert_double_le(fabs(om - circle), 1e-6);
            ck_assert_double_le(fabs(om - shot), 2e-3);
            ns++;
        }
    }
    ck_assert_uint_eq(tps, 2);
    ck_assert_uint_eq(ns, 2);
    fricreg_hb_free(fine);
    fricreg_hb_free(hb);
}
END_TEST

/* The bilinear oscillator's period doublings at either end of its unstable stretch: each
 * located by the continuation where a real multiplier crosses −1 (FRICREG_HB_PD), the stable
 * flag flipping across it, to 1e-6 of the fine sweep's crossing of the unit circle (measured
 * 1.3e-12 at 2.3482257, 1.8e-12 at 4.9083827);
 * against the shooting's crossing to 1e-3 (measured 2.4e-4, 2.6e-4: the shooting's own
 * scatter, its RK4 stepping across the spring's kink unlocated, is 3e-4 between 4000, 8000 and
 * 16000 steps a period; the HB's H = 15 against H = 40, 9e-5 and 1.2e-5). */
START_TEST(bilinear_period_doubling)
{
    struct model s = bilinear_oscillator();
    const double ends[2][2] = {{2.2, 2.5}, {4.8, 5.0}};
    for (int e = 0; e < 2; e++) {
        fricreg_hb *hb = make(&s);
        ck_assert_int_eq(fricreg_hb_continue(hb, ends[e][0], ends[e][1], 2 * NC, NULL), FRICREG_OK);
        ck_assert_uint_eq(fricreg_hb_bifurcations(hb), 1);
        int type = 0, s0 = -1, s1 = -1;
        double om = 0.0, rms, mu, z[MAXZ], q[2 * NC];
        size_t k = 0;
        ck_assert_int_eq(fricreg_hb_bifurcation(hb, 0, &type, &om, &k, s.n, &rms), FRICREG_OK);
        ck_assert_int_eq(type, FRICREG_HB_PD);
        ck_assert_int_eq(fricreg_hb_point_stability(hb, k, &s0, &mu), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_point_stability(hb, k + 1, &s1, &mu), FRICREG_OK);
        ck_assert_int_eq(s0, e == 0);
        ck_assert_int_eq(s1, e == 1);
        double circle = fine_crossing(&s, om, 0.0);
        ck_assert_int_eq(fricreg_hb_solve(hb, om, 2 * NC, NULL, q), FRICREG_OK);
        hb_state(hb, &s, om, z);
        double shot = shooting_crossing(&s, z, om - 0.02, om + 0.02);
        if (getenv("HB_PRINT"))
            fprintf(stderr, "PD at Omega %.10f: unit circle %.10f (%.2e), shooting %.10f (%.2e)\n",
                    om, circle, om - circle, shot, om - shot);
        ck_assert_double_le(fabs(om - circle), 1e-6);
        ck_assert_double_le(fabs(om - shot), 1e-3);
        fricreg_hb_free(hb);
    }
}
END_TEST

/* The coupled bilinear pair's branch points at either end of its unstable stretch: each
 * located by the continuation where a real multiplier crosses +1 off a turning point
 * (FRICREG_HB_BP), the stable flag flipping across it, the branch symmetric; to 1e-6 of the
 * fine sweep's crossing of the unit circle, and against the shooting's crossing (two elements,
 * six states); between them the shooting's largest multiplier is real and above +1 (a
 * pitchfork's, not a period doubling's −1 nor a Neimark–Sacker pair). */
START_TEST(coupled_pair_branch_points)
{
    struct model s = coupled_bilinear_pair();
    /* Hill's method, whose multiplier crosses +1 where the HB Jacobian is singular, at the
     * branch point itself; the exact monodromy's (the orbit's) crosses 1.8e-4 away, the HB's
     * truncation error at the unilateral spring's kink (H = 15) */
    s.method = FRICREG_HB_STABILITY_HILL;
    fricreg_hb *hb = make(&s);
    ck_assert_int_eq(fricreg_hb_continue(hb, 1.5, 1.9, unknowns(&s), NULL), FRICREG_OK);
    ck_assert_uint_eq(fricreg_hb_bifurcations(hb), 2);
    double at[2];
    for (size_t i = 0; i < 2; i++) {
        int type = 0, s0 = -1, s1 = -1;
        double om = 0.0, rms[2], mu, z[MAXZ], q[MAXQ];
        size_t k = 0;
        ck_assert_int_eq(fricreg_hb_bifurcation(hb, i, &type, &om, &k, s.n, rms), FRICREG_OK);
        ck_assert_int_eq(type, FRICREG_HB_BP);
        ck_assert_double_le(fabs(rms[0] - rms[1]), 1e-5 * rms[0]);
        ck_assert_int_eq(fricreg_hb_point_stability(hb, k, &s0, &mu), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_point_stability(hb, k + 1, &s1, &mu), FRICREG_OK);
        ck_assert_int_eq(s0, i == 0);
        ck_assert_int_eq(s1, i == 1);
        double circle = fine_crossing(&s, om, 0.0);
        ck_assert_int_eq(fricreg_hb_solve(hb, om, unknowns(&s), NULL, q), FRICREG_OK);
        hb_state(hb, &s, om, z);
        double shot = shooting_crossing(&s, z, om - 0.02, om + 0.02);
        if (getenv("HB_PRINT"))
            fprintf(stderr,
                    "BP at Omega %.10f (rms %.2e apart): unit circle %.10f (%.2e), shooting "
                    "%.10f (%.2e)\n",
                    om, rms[0] / rms[1] - 1.0, circle, om - circle, shot, om - shot);
        ck_assert_double_le(fabs(om - circle), 1e-6);
        ck_assert_double_le(fabs(om - shot), 1e-3);
        at[i] = om;
    }
    double q[MAXQ], z[MAXZ], mid = 0.5 * (at[0] + at[1]);
    ck_assert_int_eq(fricreg_hb_solve(hb, mid, unknowns(&s), NULL, q), FRICREG_OK);
    hb_state(hb, &s, mid, z);
    gsl_complex top = shooting_multiplier(&s, mid, z);
    if (getenv("HB_PRINT"))
        fprintf(stderr, "shooting's multiplier at %.4f: %.6f %+.2e i\n", mid, GSL_REAL(top),
                GSL_IMAG(top));
    ck_assert_double_gt(GSL_REAL(top), 1.01);
    ck_assert_double_le(fabs(GSL_IMAG(top)), 1e-9);
    fricreg_hb_free(hb);
}
END_TEST

/* The sparse model (the _csc setters: the companion filled from D_h's pattern) gives the dense
 * model's verdict and mu_max to 1e-12. */
START_TEST(sparse_as_dense)
{
    struct model s = gap_pair();
    fricreg_hb *hb = make(&s);
    double q[2 * NC], mu[2];
    int stable[2];
    for (int sparse = 0; sparse < 2; sparse++) {
        if (sparse) { /* M = I, K, C = 0.002 K whole, by columns */
            const int64_t cp[3] = {0, 2, 4}, ri[4] = {0, 1, 0, 1}, mp[3] = {0, 1, 2},
                          mi[2] = {0, 1};
            const double kv[4] = {140, -20, -20, 180}, cv[4] = {0.28, -0.04, -0.04, 0.36},
                         mv[2] = {1.0, 1.0};
            ck_assert_int_eq(fricreg_hb_set_mass_csc(hb, 2, 0, mp, mi, mv), FRICREG_OK);
            ck_assert_int_eq(fricreg_hb_set_stiffness_csc(hb, 2, 0, cp, ri, kv), FRICREG_OK);
            ck_assert_int_eq(fricreg_hb_set_damping_csc(hb, 2, 0, cp, ri, cv), FRICREG_OK);
        }
        ck_assert_int_eq(fricreg_hb_solve(hb, 11.0, 2 * NC, NULL, q), FRICREG_OK);
        ck_assert_int_eq(fricreg_hb_point_stability(hb, FRICREG_HB_SOLUTION, &stable[sparse],
                                                    &mu[sparse]),
                         FRICREG_OK);
    }
    ck_assert_int_eq(stable[0], stable[1]);
    ck_assert_double_le(fabs(mu[0] - mu[1]), 1e-12 * mu[0]);
    fricreg_hb_free(hb);
}
END_TEST

/* Every status of the three functions, nothing written on failure; a singular M fails the
 * solve with FRICREG_ESINGULAR and leaves q as it was. */
START_TEST(bad_input)
{
    struct model s = contact_pair();
    fricreg_hb *hb = make(&s);
    int stable = -7, type = -7;
    double mu = -7.0, om = -7.0, rms[2] = {-7.0, -7.0}, q[2 * NC];
    size_t k = 77;
    ck_assert_int_eq(fricreg_hb_set_stability(NULL, 1), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_set_stability(hb, 2), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_point_stability(NULL, 0, &stable, &mu), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_point_stability(hb, 0, NULL, &mu), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_point_stability(hb, 0, &stable, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_point_stability(hb, 0, &stable, &mu), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_point_stability(hb, FRICREG_HB_SOLUTION, &stable, &mu),
                     FRICREG_EINVAL);
    double lambda[8] = {-7.0, -7.0, -7.0, -7.0, -7.0, -7.0, -7.0, -7.0};
    ck_assert_int_eq(fricreg_hb_point_exponents(NULL, 0, 4, lambda), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_point_exponents(hb, 0, 4, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_point_exponents(hb, 0, 3, lambda), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_hb_point_exponents(hb, FRICREG_HB_SOLUTION, 4, lambda),
                     FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_bifurcations(NULL), 0);
    ck_assert_int_eq(fricreg_hb_bifurcation(NULL, 0, &type, &om, &k, 2, rms), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_bifurcation(hb, 0, NULL, &om, &k, 2, rms), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_bifurcation(hb, 0, &type, NULL, &k, 2, rms), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_bifurcation(hb, 0, &type, &om, &k, 2, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_bifurcation(hb, 0, &type, &om, &k, 2, rms), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_continue(hb, 11.5, 11.6, 2 * NC, NULL), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_point_stability(hb, fricreg_hb_points(hb), &stable, &mu),
                     FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_bifurcations(hb), 0);
    ck_assert_int_eq(fricreg_hb_bifurcation(hb, 0, &type, &om, &k, 3, rms), FRICREG_EINVAL);
    ck_assert(stable == -7 && mu == -7.0 && type == -7 && om == -7.0 && k == 77);
    ck_assert(rms[0] == -7.0 && rms[1] == -7.0);
    ck_assert_int_eq(fricreg_hb_point_exponents(hb, fricreg_hb_points(hb), 4, lambda),
                     FRICREG_EINVAL);
    for (int i = 0; i < 8; i++)
        ck_assert(lambda[i] == -7.0);
    /* a singular mass matrix: the solve fails, q untouched */
    const double M0[4] = {1.0, 0.0, 0.0, 0.0};
    ck_assert_int_eq(fricreg_hb_set_mass(hb, 2, M0), FRICREG_OK);
    for (size_t j = 0; j < 2 * NC; j++)
        q[j] = -7.0;
    ck_assert_int_eq(fricreg_hb_solve(hb, 12.0, 2 * NC, NULL, q), FRICREG_ESINGULAR);
    ck_assert(strstr(fricreg_hb_errmsg(hb), "mass matrix") != NULL);
    ck_assert(q[0] == -7.0);
    ck_assert_int_eq(fricreg_hb_set_stability(hb, 0), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_point_stability(hb, 0, &stable, &mu), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_point_exponents(hb, 0, 4, lambda), FRICREG_EINVAL);
    ck_assert(lambda[0] == -7.0);
    fricreg_hb_free(hb);
    /* too many coefficients for the dense companion */
    ck_assert_int_eq(fricreg_hb_create(40, 1, 15, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stability(hb, 1), FRICREG_EINVAL);
    fricreg_hb_free(hb);
    fricreg_hb_free(NULL);
}
END_TEST

/* The method's choice: the monodromy for lift-off, Hill's for the 3-D contact element (not
 * piecewise linear in the monodromy's sense: a disk), the monodromy refused there when chosen,
 * bad methods and NULLs refused with nothing changed, and no size limit for the monodromy (40
 * dofs at H = 15: 1240 coefficients, over Hill's 1024, whose refusal names the monodromy). */
START_TEST(method_choice)
{
    struct model s = contact_pair();
    fricreg_hb *hb = make(&s);
    int method = -7;
    ck_assert_int_eq(fricreg_hb_get_stability_method(hb, &method), FRICREG_OK);
    ck_assert_int_eq(method, FRICREG_HB_STABILITY_MONODROMY);
    fricreg_hb_free(hb);
    /* one dof, k = 1, m = 1, a 3-D contact element on it (both tangential rows), H = 3 */
    const double one = 1.0, c = 0.02, Je[2] = {1.0, 1.0}, Jn[1] = {-1.0}, kt = 1.0, mu = 0.3,
                 n0 = 2.0, kn = 1.0, pc = 0.5, ps = 0.0;
    double q[3 * 7];
    ck_assert_int_eq(fricreg_hb_create(1, 1, 3, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, 1, &one), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 1, &one), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_damping(hb, 1, &c), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_jenkins_2d_normal(hb, 1, 1, Je, Jn, &kt, &mu, &n0, &kn),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_excitation(hb, 1, &pc, &ps), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stability(hb, 1), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_get_stability_method(hb, &method), FRICREG_OK);
    ck_assert_int_eq(method, FRICREG_HB_STABILITY_HILL);
    ck_assert_int_eq(fricreg_hb_set_stability_method(hb, 4), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_set_stability_method(hb, -1), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_hb_set_stability_method(NULL, 0), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_get_stability_method(NULL, &method), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_get_stability_method(hb, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_hb_get_stability_method(hb, &method), FRICREG_OK);
    ck_assert_int_eq(method, FRICREG_HB_STABILITY_HILL);
    ck_assert_int_eq(fricreg_hb_solve(hb, 0.5, 3 * 7, NULL, q), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stability_method(hb, FRICREG_HB_STABILITY_MONODROMY),
                     FRICREG_OK);
    for (size_t j = 0; j < 3 * 7; j++)
        q[j] = -7.0;
    ck_assert_int_eq(fricreg_hb_solve(hb, 0.5, 3 * 7, NULL, q), FRICREG_EINVAL);
    ck_assert(strstr(fricreg_hb_errmsg(hb), "piecewise-linear") != NULL);
    ck_assert(q[0] == -7.0);
    fricreg_hb_free(hb);

    size_t n = 40;
    double *K = calloc(n * n, sizeof *K), J[40] = {1.0}, k40 = 1.0, mun40 = 0.1;
    ck_assert_ptr_nonnull(K);
    for (size_t i = 0; i < n; i++)
        K[i * n + i] = 1.0;
    ck_assert_int_eq(fricreg_hb_create(n, 1, 15, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, n, K), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_elements(hb, 1, n, J, &k40, &mun40), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stability_method(hb, FRICREG_HB_STABILITY_HILL), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stability(hb, 1), FRICREG_EINVAL);
    /* the refusal names the method that has no limit, since these elements have it */
    ck_assert(strstr(fricreg_hb_errmsg(hb), "FRICREG_HB_STABILITY_MONODROMY first") != NULL);
    ck_assert_int_eq(fricreg_hb_set_stability_method(hb, FRICREG_HB_STABILITY_AUTO), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stability(hb, 1), FRICREG_OK);
    fricreg_hb_free(hb);
    free(K);
}
END_TEST

Suite *hb_stability_suite(void)
{
    Suite *s = suite_create("hb_stability");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 300);
    tcase_add_test(tc, jenkins_pair_against_shooting);
    tcase_add_test(tc, jenkins_pair_exponents_against_shooting);
    tcase_add_test(tc, one_piece_orbits_follow_the_model);
    tcase_add_test(tc, contact_pair_touchdown_against_event_shooting);
    tcase_add_test(tc, iwan_pair_against_shooting);
    tcase_add_test(tc, gap_pair_against_shooting);
    tcase_add_test(tc, bilinear_against_shooting);
    tcase_add_test(tc, bad_input);
    tcase_add_test(tc, method_choice);
    tcase_add_test(tc, sparse_as_dense);
    suite_add_tcase(s, tc);

    /* The long sweeps (the contact pair's 200 points, the bisections): native and ASan only;
     * 16 s, the release tier's (hb_stability_release; ctest hb_stability_sweeps where the quick
     * entries run the release cases, tests/CMakeLists.txt). */
    TCase *sweeps = tcase_create("sweeps");
    tcase_set_timeout(sweeps, 300);
    tcase_set_tags(sweeps, "release");
    tcase_add_test(sweeps, contact_pair_against_shooting);
    tcase_add_test(sweeps, gap_pair_bifurcations);
    tcase_add_test(sweeps, bilinear_period_doubling);
    tcase_add_test(sweeps, coupled_pair_branch_points);
    suite_add_tcase(s, sweeps);
    return s;
}

int main(void)
{
    SRunner *sr = srunner_create(hb_stability_suite());
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
