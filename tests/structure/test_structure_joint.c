/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_structure_joint.c — Check suite for friction contacts of bound > 0 and Jenkins/Iwan
 * elements in one fricreg_structure step (joint_step.c: one Newton over both forces).
 *
 * Where the numbers come from:
 *   - a stuck contact (law (4) at rest inside its band holds the contact's velocity at 0
 *     exactly: f = f_eq) and a stuck element (a spring kt) make the linear system with the
 *     contact's dof clamped and kt added: average-acceleration Newmark of that one-dof system,
 *     written out here, agrees to 1e-12;
 *   - a hand-written average-acceleration Newmark of the same two-dof model, Newton on the
 *     accelerations with the law from a fricreg_ctx (its tangent for the Jacobian) and the
 *     element's return mapping from a fricreg_jenkins (with a normal law: its lift-off),
 *     GSL's LU for the Newton steps: the displacement histories agree to 1e-10 of the
 *     amplitude, with the contact sticking and slipping and the element slipping (and opening);
 *   - average-acceleration Newmark's energy balance closes with both dissipations;
 *   - HHT-alpha and the central difference: the same scene converges to the fine-step
 *     Newmark solution as dt shrinks (central: second order). */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_linalg.h>

#include "fricreg.h"
#include "fricreg_jenkins.h"
#include "fricreg_structure.h"

#define N 2

static const double PI = 3.14159265358979323846;

/* Two dofs coupled by K, M diagonal; a contact on dof 0 (law (4)), a Jenkins element on dof 1
 * to the ground, optionally with a normal law on g = u0 - u1 + 0.05 (n0 absorbs the offset);
 * the load p sin(omega t). */
struct model {
    double M[N * N], C[N * N], K[N * N], p[N], omega;
    size_t mc;                     /* contacts, 1 or 2 */
    double Jc[2 * N], mun[2], eps; /* [mc N] row-major, [mc] */
    double Je[N], kt, mue;
    int normal;
    double Jn[N], mu, n0, kn;
};

static struct model scene(void)
{
    struct model m = {
        .M = {1.0, 0.0, 0.0, 0.6},
        .C = {0.05, -0.01, -0.01, 0.03},
        .K = {2.5, -1.2, -1.2, 1.8},
        .p = {0.3, 0.7},
        .omega = 1.3,
        .mc = 1,
        .Jc = {1.0, 0.0},
        .mun = {0.6},
        .eps = 1e-3,
        .Je = {0.0, 1.0},
        .kt = 1.5,
        .mue = 0.25,
    };
    return m;
}

/* The scene with the element's bound from a normal law: N = max(0, n0 + kn (u0 - u1)). */
static struct model scene_normal(void)
{
    struct model m = scene();
    m.normal = 1;
    m.Jn[0] = 1.0;
    m.Jn[1] = -1.0;
    m.mu = 0.5;
    m.n0 = 0.3;
    m.kn = 1.2;
    return m;
}

/* A second contact on the drift u1 - u0: W = J M^-1 J^T is not diagonal. */
static struct model scene_coupled(void)
{
    struct model m = scene();
    m.mc = 2;
    m.Jc[2] = -1.0;
    m.Jc[3] = 1.0;
    m.mun[1] = 0.15;
    return m;
}

static double dot(const double x[], const double y[])
{
    return x[0] * y[0] + x[1] * y[1];
}

/* ---- The reference: average-acceleration Newmark, Newton on a1 ------------------------ */

struct reference {
    struct model m;
    double dt, t, u[N], v[N], a[N];
    fricreg_ctx *ctx;
    fricreg_jenkins *jk;
    double f[2], fe, nf; /* the contacts', the element's and its normal force at the step's end */
};

static void reference_init(struct reference *r, const struct model *m, double dt)
{
    memset(r, 0, sizeof *r);
    r->m = *m;
    r->dt = dt;
    double W[4]; /* J M^-1 J^T */
    for (size_t i = 0; i < m->mc; i++)
        for (size_t j = 0; j < m->mc; j++)
            W[i * m->mc + j] = m->Jc[i * N] * m->Jc[j * N] / m->M[0] +
                               m->Jc[i * N + 1] * m->Jc[j * N + 1] / m->M[3];
    ck_assert_int_eq(fricreg_ctx_create(m->mc, &r->ctx), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_law(r->ctx, FRICREG_LAW_QUINN, m->eps), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_set_bounds(r->ctx, m->mc, m->mun), FRICREG_OK);
    if (m->mc == 1)
        ck_assert_int_eq(fricreg_ctx_set_coupling_diagonal(r->ctx, 1, W), FRICREG_OK);
    else
        ck_assert_int_eq(fricreg_ctx_set_coupling_dense(r->ctx, m->mc, W), FRICREG_OK);
    ck_assert_int_eq(fricreg_jenkins_create(1, 1, &r->jk), FRICREG_OK);
    ck_assert_int_eq(fricreg_jenkins_set_params(r->jk, 1, &m->kt, &m->mue), FRICREG_OK);
    if (m->normal)
        ck_assert_int_eq(fricreg_jenkins_set_normal(r->jk, 1, &m->mu, &m->n0, &m->kn), FRICREG_OK);
    /* a(0) from rest at the origin: the preload max(0, n0) pushes (p(0) = 0, fe(0) = 0) and the
     * law answers at zdot = 0 */
    double n0 = m->normal ? fmax(0.0, m->n0) : 0.0, zdot[2] = {0.0, 0.0}, afree[2] = {0.0, 0.0};
    for (size_t c = 0; c < m->mc; c++)
        for (int k = 0; k < N; k++)
            afree[c] -= m->Jc[c * N + k] * m->Jn[k] * n0 / m->M[k * N + k];
    ck_assert_int_eq(fricreg_ctx_eval(r->ctx, m->mc, zdot, afree, r->f, NULL), FRICREG_OK);
    for (int k = 0; k < N; k++) {
        r->a[k] = -m->Jn[k] * n0;
        for (size_t c = 0; c < m->mc; c++)
            r->a[k] += m->Jc[c * N + k] * r->f[c];
        r->a[k] /= m->M[k * N + k];
    }
}

static void reference_free(struct reference *r)
{
    fricreg_ctx_free(r->ctx);
    fricreg_jenkins_free(r->jk);
}

/* R(a1) = M a1 + C v1 + K u1 + J_e^T fe + J_n^T N - p(t1) - J^T f and its Jacobian (row-major)
 * at a1; ||R||_2 returned. */
static double reference_residual(struct reference *r, double t1, const double a1[], double R[],
                                 double Jac[])
{
    const struct model *m = &r->m;
    double dt = r->dt, bd = 0.25 * dt * dt, gd = 0.5 * dt, u1[N], v1[N], Fnet[N];
    for (int k = 0; k < N; k++) {
        u1[k] = r->u[k] + dt * r->v[k] + 0.25 * dt * dt * r->a[k] + bd * a1[k];
        v1[k] = r->v[k] + 0.5 * dt * r->a[k] + gd * a1[k];
    }
    double q = dot(m->Je, u1), dfdq = 0.0, dfdg = 0.0, dNdg = 0.0;
    r->nf = 0.0;
    if (m->normal) {
        double g = dot(m->Jn, u1);
        ck_assert_int_eq(fricreg_jenkins_trial_normal(r->jk, 1, &q, &g, &r->fe, &r->nf, &dfdq,
                                                      &dfdg),
                         FRICREG_OK);
        dNdg = m->n0 + m->kn * g >= 0.0 ? m->kn : 0.0;
    } else {
        ck_assert_int_eq(fricreg_jenkins_trial(r->jk, 1, &q, &r->fe, &dfdq), FRICREG_OK);
    }
    double load = sin(m->omega * t1);
    for (int k = 0; k < N; k++) {
        Fnet[k] = m->p[k] * load - m->Je[k] * r->fe - m->Jn[k] * r->nf;
        for (int l = 0; l < N; l++)
            Fnet[k] -= m->C[k * N + l] * v1[l] + m->K[k * N + l] * u1[l];
    }
    size_t mc = m->mc;
    double zdot[2], afree[2], fz[4], fa[4];
    for (size_t c = 0; c < mc; c++) {
        zdot[c] = dot(m->Jc + c * N, v1);
        afree[c] = m->Jc[c * N] * Fnet[0] / m->M[0] + m->Jc[c * N + 1] * Fnet[1] / m->M[3];
    }
    ck_assert_int_eq(fricreg_ctx_eval(r->ctx, mc, zdot, afree, r->f, NULL), FRICREG_OK);
    ck_assert_int_eq(fricreg_ctx_tangent(r->ctx, mc, fz, fa), FRICREG_OK);
    double dF[N * N], dafree[2 * N], df[2 * N], sum = 0.0;
    for (int k = 0; k < N; k++)
        for (int l = 0; l < N; l++)
            dF[k * N + l] = -(gd * m->C[k * N + l] + bd * m->K[k * N + l]) -
                            bd * (m->Je[k] * (dfdq * m->Je[l] + dfdg * m->Jn[l]) +
                                  m->Jn[k] * dNdg * m->Jn[l]);
    for (size_t c = 0; c < mc; c++)
        for (int l = 0; l < N; l++)
            dafree[c * N + l] = m->Jc[c * N] * dF[0 * N + l] / m->M[0] +
                                m->Jc[c * N + 1] * dF[1 * N + l] / m->M[3];
    for (size_t c = 0; c < mc; c++) /* df/da1 through zdot and a_free */
        for (int l = 0; l < N; l++) {
            df[c * N + l] = 0.0;
            for (size_t d = 0; d < mc; d++)
                df[c * N + l] += fz[c * mc + d] * gd * m->Jc[d * N + l] +
                                 fa[c * mc + d] * dafree[d * N + l];
        }
    for (int k = 0; k < N; k++) {
        R[k] = -Fnet[k];
        for (size_t c = 0; c < mc; c++)
            R[k] -= m->Jc[c * N + k] * r->f[c];
        for (int l = 0; l < N; l++) {
            R[k] += m->M[k * N + l] * a1[l];
            Jac[k * N + l] = m->M[k * N + l] - dF[k * N + l];
            for (size_t c = 0; c < mc; c++)
                Jac[k * N + l] -= m->Jc[c * N + k] * df[c * N + l];
        }
        sum += R[k] * R[k];
    }
    return sqrt(sum);
}

/* One step: Newton on a1 from a, halving until ||R||_2 decreases, to ||R||_inf <= 1e-14. */
static void reference_step(struct reference *r)
{
    double t1 = r->t + r->dt, a1[N], R[N], Jac[N * N], d[N], at[N], Rt[N], Jt[N * N];
    memcpy(a1, r->a, sizeof a1);
    double phi = reference_residual(r, t1, a1, R, Jac);
    int it;
    for (it = 0; it < 200 && fmax(fabs(R[0]), fabs(R[1])) > 1e-14; it++) {
        gsl_matrix_view A = gsl_matrix_view_array(Jac, N, N);
        gsl_vector_view b = gsl_vector_view_array(R, N), x = gsl_vector_view_array(d, N);
        gsl_permutation *perm = gsl_permutation_alloc(N);
        int sign;
        gsl_linalg_LU_decomp(&A.matrix, perm, &sign);
        gsl_linalg_LU_solve(&A.matrix, perm, &b.vector, &x.vector);
        gsl_permutation_free(perm);
        double lambda = 1.0, phi_t = INFINITY;
        for (int cut = 0; cut < 60; cut++, lambda *= 0.5) {
            for (int k = 0; k < N; k++)
                at[k] = a1[k] - lambda * d[k];
            phi_t = reference_residual(r, t1, at, Rt, Jt);
            if (phi_t < phi)
                break;
        }
        ck_assert_msg(phi_t < phi, "reference: no decrease at t = %g", t1);
        memcpy(a1, at, sizeof a1);
        memcpy(R, Rt, sizeof R);
        memcpy(Jac, Jt, sizeof Jac);
        phi = phi_t;
    }
    ck_assert_msg(it < 200, "reference: Newton did not converge at t = %g", t1);
    reference_residual(r, t1, a1, R, Jac); /* the trial state at a1, for the commit */
    ck_assert_int_eq(fricreg_jenkins_commit(r->jk), FRICREG_OK);
    for (int k = 0; k < N; k++) {
        r->u[k] += r->dt * r->v[k] + 0.25 * r->dt * r->dt * (r->a[k] + a1[k]);
        r->v[k] += 0.5 * r->dt * (r->a[k] + a1[k]);
        r->a[k] = a1[k];
    }
    r->t = t1;
}

/* ---- The structure --------------------------------------------------------------------- */

static fricreg_structure *make(const struct model *m, double dt, int nsteps)
{
    fricreg_structure *s = NULL;
    ck_assert_int_eq(fricreg_structure_create(N, m->mc, &s), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_mass(s, N, m->M), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_stiffness(s, N, m->K), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_damping(s, N, m->C), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_contacts(s, m->mc, N, m->Jc), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_bounds(s, m->mc, m->mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_law(s, FRICREG_LAW_QUINN, m->eps), FRICREG_OK);
    if (m->normal)
        ck_assert_int_eq(fricreg_structure_set_jenkins_normal(s, 1, N, m->Je, m->Jn, &m->kt, &m->mu,
                                                              &m->n0, &m->kn),
                         FRICREG_OK);
    else
        ck_assert_int_eq(fricreg_structure_set_jenkins(s, 1, N, m->Je, &m->kt, &m->mue),
                         FRICREG_OK);
    double *g = malloc(((size_t)nsteps + 1) * sizeof *g);
    ck_assert_ptr_nonnull(g);
    for (int k = 0; k <= nsteps; k++)
        g[k] = sin(m->omega * k * dt);
    ck_assert_int_eq(fricreg_structure_set_load(s, N, m->p, 0.0, dt, (size_t)nsteps + 1, g),
                     FRICREG_OK);
    free(g);
    ck_assert_int_eq(fricreg_structure_set_newton(s, 1e-13, 50), FRICREG_OK);
    return s;
}

/* Steps of dt on run's clock (step k ends at k dt exactly). */
static void run_to(fricreg_structure *s, double dt, int k)
{
    ck_assert_int_eq(fricreg_structure_run(s, dt, k * dt), FRICREG_OK);
}

static void iterations(fricreg_structure *s, const char *what, double *mean, int64_t *imax);

/* A stuck contact (mun huge, at rest: f = f_eq keeps dof 0 at 0) and a stuck element (a
 * spring kt): dof 1 alone, M11 a + C11 v + (K11 + kt) u = p1 sin(omega t), by
 * average-acceleration Newmark's recurrence. */
START_TEST(stuck_is_linear)
{
    struct model m = scene();
    m.mun[0] = 1e6;
    m.mue = 1e6;
    const double dt = 0.01;
    const int nsteps = 1000;
    fricreg_structure *s = make(&m, dt, nsteps);
    double k1 = m.K[3] + m.kt, u = 0.0, v = 0.0, a = 0.0, amp = 0.0, err = 0.0, u0max = 0.0;
    double keff = m.M[3] + 0.5 * dt * m.C[3] + 0.25 * dt * dt * k1;
    for (int k = 1; k <= nsteps; k++) {
        double up = u + dt * v + 0.25 * dt * dt * a, vp = v + 0.5 * dt * a;
        double a1 = (m.p[1] * sin(m.omega * k * dt) - m.C[3] * vp - k1 * up) / keff;
        u = up + 0.25 * dt * dt * a1;
        v = vp + 0.5 * dt * a1;
        a = a1;
        double x[N];
        run_to(s, dt, k);
        ck_assert_int_eq(fricreg_structure_get_state(s, N, x, NULL, NULL), FRICREG_OK);
        amp = fmax(amp, fabs(u));
        err = fmax(err, fabs(x[1] - u));
        u0max = fmax(u0max, fabs(x[0]));
    }
    double mean;
    int64_t imax;
    iterations(s, "stuck", &mean, &imax);
    if (getenv("JOINT_PRINT"))
        fprintf(stderr, "stuck: max |u1 - linear| %.3e of %.3e, max |u0| %.3e\n", err, amp, u0max);
    ck_assert(amp > 0.1);
    ck_assert_msg(err <= 1e-12 * amp, "err %g of %g", err, amp);
    ck_assert_msg(u0max <= 1e-12 * amp, "u0 %g", u0max);
    fricreg_structure_free(s);
}
END_TEST

/* The structure's run against the reference over nsteps of dt: the largest difference of the
 * displacements relative to their amplitude; the stick steps (|zdot| < eps/2) of the contact
 * and the element's slip steps (|fe| = its bound) and open steps are counted. */
static double against_reference(const struct model *m, double dt, int nsteps, int *stick, int *slip,
                                int *open, fricreg_structure **out)
{
    struct reference r;
    reference_init(&r, m, dt);
    fricreg_structure *s = make(m, dt, nsteps);
    double amp = 0.0, diff = 0.0;
    *stick = *slip = *open = 0;
    for (int k = 1; k <= nsteps; k++) {
        reference_step(&r);
        run_to(s, dt, k);
        double x[N], fe;
        ck_assert_int_eq(fricreg_structure_get_state(s, N, x, NULL, NULL), FRICREG_OK);
        ck_assert_int_eq(fricreg_structure_get_jenkins_state(s, 1, &fe, NULL, NULL), FRICREG_OK);
        for (int i = 0; i < N; i++) {
            amp = fmax(amp, fabs(r.u[i]));
            diff = fmax(diff, fabs(x[i] - r.u[i]));
        }
        *stick += fabs(dot(m->Jc, r.v)) < 0.5 * m->eps; /* contact 0 in law (4)'s band */
        double bound = m->normal ? m->mu * r.nf : m->mue;
        *slip += r.nf > 0.0 || !m->normal ? fabs(fabs(r.fe) - bound) <= 1e-12 : 0;
        *open += m->normal && r.nf == 0.0;
    }
    reference_free(&r);
    *out = s;
    return diff / amp;
}

static void iterations(fricreg_structure *s, const char *what, double *mean, int64_t *imax)
{
    int64_t iters, steps, fails;
    fricreg_structure_get_stat(s, FRICREG_SSTAT_NEWTON_ITERATIONS, &iters);
    fricreg_structure_get_stat(s, FRICREG_SSTAT_STEPS, &steps);
    fricreg_structure_get_stat(s, FRICREG_SSTAT_NEWTON_MAX, imax);
    fricreg_structure_get_stat(s, FRICREG_SSTAT_NEWTON_FAILURES, &fails);
    *mean = (double)iters / (double)steps;
    if (getenv("JOINT_PRINT"))
        fprintf(stderr, "%s: %lld steps, mean %.2f max %lld iterations, %lld failures\n", what,
                (long long)steps, *mean, (long long)*imax, (long long)fails);
    ck_assert_int_eq(fails, 0);
}

START_TEST(jenkins_against_reference)
{
    struct model m = scene();
    int stick, slip, open;
    fricreg_structure *s;
    double rel = against_reference(&m, 0.01, 2000, &stick, &slip, &open, &s);
    double mean, residual, input, friction, jenkins;
    int64_t imax;
    iterations(s, "jenkins", &mean, &imax);
    fricreg_structure_get_value(s, FRICREG_SVALUE_RESIDUAL, &residual);
    fricreg_structure_get_value(s, FRICREG_SVALUE_INPUT, &input);
    fricreg_structure_get_value(s, FRICREG_SVALUE_FRICTION, &friction);
    fricreg_structure_get_value(s, FRICREG_SVALUE_JENKINS, &jenkins);
    if (getenv("JOINT_PRINT"))
        fprintf(stderr,
                "jenkins: rel diff %.3e, stick %d slip %d of 2000; energy residual %.3e of "
                "input %.3e (friction %.3e, jenkins %.3e)\n",
                rel, stick, slip, residual, input, friction, jenkins);
    ck_assert_msg(rel <= 1e-10, "rel %g", rel);
    ck_assert(stick > 100 && stick < 1900); /* the contact sticks and slips */
    ck_assert(slip > 100);                  /* the element slips */
    ck_assert(friction > 0.05 * input && jenkins > 0.05 * input);
    ck_assert_msg(fabs(residual) <= 1e-9 * fabs(input), "residual %g of %g", residual, input);
    ck_assert(mean <= 3.0 && imax <= 12);
    fricreg_structure_free(s);
}
END_TEST

START_TEST(liftoff_against_reference)
{
    struct model m = scene_normal();
    int stick, slip, open;
    fricreg_structure *s;
    double rel = against_reference(&m, 0.01, 2000, &stick, &slip, &open, &s);
    double mean;
    int64_t imax;
    iterations(s, "liftoff", &mean, &imax);
    if (getenv("JOINT_PRINT"))
        fprintf(stderr, "liftoff: rel diff %.3e, stick %d slip %d open %d of 2000\n", rel, stick,
                slip, open);
    ck_assert_msg(rel <= 1e-10, "rel %g", rel);
    ck_assert(stick > 100 && stick < 1900);
    ck_assert(slip > 50);
    ck_assert(open > 50);
    ck_assert(mean <= 3.0 && imax <= 12);
    fricreg_structure_free(s);
}
END_TEST

START_TEST(coupled_against_reference)
{
    struct model m = scene_coupled();
    int stick, slip, open;
    fricreg_structure *s;
    double rel = against_reference(&m, 0.01, 2000, &stick, &slip, &open, &s);
    double mean, residual, input;
    int64_t imax;
    iterations(s, "coupled", &mean, &imax);
    fricreg_structure_get_value(s, FRICREG_SVALUE_RESIDUAL, &residual);
    fricreg_structure_get_value(s, FRICREG_SVALUE_INPUT, &input);
    if (getenv("JOINT_PRINT"))
        fprintf(stderr, "coupled: rel diff %.3e, stick %d slip %d of 2000, residual %.3e of %.3e\n",
                rel, stick, slip, residual, input);
    ck_assert_msg(rel <= 1e-10, "rel %g", rel);
    ck_assert(stick > 100 && stick < 1900);
    ck_assert(slip > 100);
    ck_assert_msg(fabs(residual) <= 1e-9 * fabs(input), "residual %g of %g", residual, input);
    ck_assert(mean <= 3.0 && imax <= 12);
    fricreg_structure_free(s);
}
END_TEST

/* An Iwan element of two equal sliders of half the stiffness and half the bound is the Jenkins
 * element: the same run to rounding. */
START_TEST(iwan_halves_are_jenkins)
{
    struct model m = scene();
    const double dt = 0.01;
    const int nsteps = 1000;
    fricreg_structure *a = make(&m, dt, nsteps), *b = make(&m, dt, nsteps);
    double k[2] = {0.5 * m.kt, 0.5 * m.kt}, phi[2] = {0.5 * m.mue, 0.5 * m.mue};
    ck_assert_int_eq(fricreg_structure_set_iwan(b, 1, N, m.Je, 2, k, phi), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_run(a, dt, nsteps * dt), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_run(b, dt, nsteps * dt), FRICREG_OK);
    double xa[N], xb[N], Da, Db;
    fricreg_structure_get_state(a, N, xa, NULL, NULL);
    fricreg_structure_get_state(b, N, xb, NULL, NULL);
    fricreg_structure_get_value(a, FRICREG_SVALUE_JENKINS, &Da);
    fricreg_structure_get_value(b, FRICREG_SVALUE_JENKINS, &Db);
    for (int i = 0; i < N; i++)
        ck_assert_msg(fabs(xa[i] - xb[i]) <= 1e-12 * fabs(xa[i]), "%g %g", xa[i], xb[i]);
    ck_assert(Da > 0.0 && fabs(Da - Db) <= 1e-12 * Da);
    fricreg_structure_free(a);
    fricreg_structure_free(b);
}
END_TEST

/* The largest difference of u at the times k dt_max, k dt_max <= T, between a run of dt and
 * the reference's samples ref[k] (u at k dt_max, both dofs). */
static double run_error(fricreg_structure *s, double dt, int stride, int samples,
                        const double ref[])
{
    double err = 0.0;
    for (int k = 1; k <= samples; k++) {
        double x[N];
        ck_assert_int_eq(fricreg_structure_run(s, dt, k * stride * dt), FRICREG_OK);
        fricreg_structure_get_state(s, N, x, NULL, NULL);
        for (int i = 0; i < N; i++)
            err = fmax(err, fabs(x[i] - ref[k * N + i]));
    }
    return err;
}

/* HHT-alpha and the central difference beside the joint Newmark: the same scene (eps = 0.01,
 * the central difference's step guard needing eps > 2.2 dt W mun) converges to the Newmark
 * run at dt/64 as dt halves. */
START_TEST(hht_and_central_converge)
{
    struct model m = scene();
    m.eps = 0.01;
    const double dt0 = 0.004, T = 4.0;
    const int samples = (int)(T / dt0 + 0.5), fine = 64;
    double *ref = calloc((size_t)(samples + 1) * N, sizeof *ref);
    ck_assert_ptr_nonnull(ref);
    fricreg_structure *s = make(&m, dt0 / fine, samples * fine);
    for (int k = 1; k <= samples; k++) {
        ck_assert_int_eq(fricreg_structure_run(s, dt0 / fine, k * fine * (dt0 / fine)), FRICREG_OK);
        fricreg_structure_get_state(s, N, ref + k * N, NULL, NULL);
    }
    fricreg_structure_free(s);
    double err[2][3];
    for (int scheme = 0; scheme < 2; scheme++)
        for (int h = 0; h < 3; h++) {
            int stride = 1 << h;
            double dt = dt0 / stride;
            fricreg_structure *c = make(&m, dt, samples * stride);
            if (scheme == 0)
                ck_assert_int_eq(fricreg_structure_set_hht(c, -0.1), FRICREG_OK);
            else
                ck_assert_int_eq(fricreg_structure_set_central_difference(c), FRICREG_OK);
            err[scheme][h] = run_error(c, dt, stride, samples, ref);
            if (scheme == 0) {
                double mean;
                int64_t imax;
                iterations(c, "hht", &mean, &imax);
                ck_assert(mean <= 3.0 && imax <= 12);
            }
            if (getenv("JOINT_PRINT"))
                fprintf(stderr, "%s dt %g: max |u - u_fine| %.3e\n", scheme ? "central" : "hht", dt,
                        err[scheme][h]);
            fricreg_structure_free(c);
        }
    free(ref);
    for (int scheme = 0; scheme < 2; scheme++)
        for (int h = 1; h < 3; h++)
            ck_assert_msg(err[scheme][h] < 0.4 * err[scheme][h - 1], "scheme %d: %g then %g",
                          scheme, err[scheme][h - 1], err[scheme][h]);
}
END_TEST

static Suite *structure_joint_suite(void)
{
    Suite *suite = suite_create("structure_joint");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, stuck_is_linear);
    tcase_add_test(tc, jenkins_against_reference);
    tcase_add_test(tc, liftoff_against_reference);
    tcase_add_test(tc, coupled_against_reference);
    tcase_add_test(tc, iwan_halves_are_jenkins);
    tcase_add_test(tc, hht_and_central_converge);
    suite_add_tcase(suite, tc);
    return suite;
}

int main(void)
{
    SRunner *sr = srunner_create(structure_joint_suite());
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
