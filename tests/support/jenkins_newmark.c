/* SPDX-License-Identifier: GPL-3.0-or-later */
/* jenkins_newmark.c — the hand-written Newmark reference with Jenkins elements
 * (jenkins_newmark.h). */
#include <check.h>
#include <math.h>
#include <string.h>

#include <gsl/gsl_linalg.h>

#include "fricreg_jenkins.h"
#include "jenkins_newmark.h"
#include "quiet_check.h"

#define MAXN JENKINS_MODEL_MAXN
#define MAXM JENKINS_MODEL_MAXM
static const double PI = 3.14159265358979323846;

/* One dof on a spring to ground with a Jenkins element to ground. */
struct jenkins_model jenkins_model_oscillator(void)
{
    struct jenkins_model s = {.n = 1, .m = 1};
    s.M[0] = 1.3;
    s.K[0] = 2.385;
    s.C[0] = 0.12;
    s.J[0] = 1.0;
    s.kt[0] = 1.7;
    s.mun[0] = 0.35;
    s.pc[0] = 0.6;
    s.ps[0] = 0.0;
    return s;
}

/* Three masses in a chain on springs (ground–1, 1–2, 2–3), Rayleigh damping a0 M + a1 K;
 * element 0 between mass 3 and ground, element 1 between masses 1 and 2; mass 1 excited. */
struct jenkins_model jenkins_model_chain(void)
{
    struct jenkins_model s = {.n = 3, .m = 2};
    const double mass[3] = {1.1, 0.9, 1.25}, k[3] = {3.2, 2.1, 1.6};
    for (int i = 0; i < 3; i++)
        s.M[4 * i] = mass[i];
    s.K[0] = k[0] + k[1];
    s.K[1] = s.K[3] = -k[1];
    s.K[4] = k[1] + k[2];
    s.K[5] = s.K[7] = -k[2];
    s.K[8] = k[2];
    for (int i = 0; i < 9; i++)
        s.C[i] = 0.03 * s.M[i] + 0.01 * s.K[i];
    s.J[2] = 1.0;                /* q_0 = x_3 */
    s.J[3] = -1.0, s.J[4] = 1.0; /* q_1 = x_2 − x_1 */
    s.kt[0] = 2.5, s.kt[1] = 1.4;
    s.mun[0] = 0.3, s.mun[1] = 0.12;
    s.pc[0] = 0.8, s.ps[0] = 0.25;
    return s;
}

int jenkins_newmark_rms(const struct jenkins_model *s, double omega, int N, int periods,
                        double *rms, double *prev, double *hist)
{
    size_t n = s->n, m = s->m;
    double dt = 2.0 * PI / omega / N, beta = 0.25, gamma = 0.5;
    double x[MAXN] = {0}, v[MAXN] = {0}, a[MAXN] = {0}, xn[MAXN], an[MAXN], vn[MAXN];
    double q[MAXM], f[MAXM], df[MAXM], R[MAXN], Kt[MAXN * MAXN], dx[MAXN];
    double g[MAXM], nf[MAXM], dfdg[MAXM], dndg[MAXM];
    int opened[MAXM] = {0}, closed[MAXM] = {0};
    double sum[MAXN] = {0}, qmax[MAXM], qmin[MAXM], xscale = 0.0; /* largest |x| so far */
    int slips = 1;
    fricreg_jenkins *jk = NULL;
    ck_assert_int_eq(fricreg_jenkins_create(1, m, &jk), FRICREG_OK);
    ck_assert_int_eq(fricreg_jenkins_set_params(jk, m, s->kt, s->normal ? s->mu : s->mun),
                     FRICREG_OK);
    if (s->normal)
        ck_assert_int_eq(fricreg_jenkins_set_normal(jk, m, s->mu, s->n0, s->kn), FRICREG_OK);
    gsl_permutation *p = gsl_permutation_alloc(n);
    for (int step = 1; step <= periods * N; step++) {
        double t = step * dt, ct = cos(omega * t), st = sin(omega * t);
        memcpy(xn, x, sizeof x);
        for (int it = 0;; it++) {
            QUIET_CHECK(it < 50);
            for (size_t i = 0; i < n; i++) {
                an[i] = (xn[i] - x[i] - dt * v[i]) / (beta * dt * dt) - (0.5 / beta - 1.0) * a[i];
                vn[i] = v[i] + dt * ((1.0 - gamma) * a[i] + gamma * an[i]);
            }
            for (size_t e = 0; e < m; e++) {
                q[e] = g[e] = 0.0;
                for (size_t k = 0; k < n; k++) {
                    q[e] += s->J[e * n + k] * xn[k];
                    g[e] += s->Jn[e * n + k] * xn[k];
                }
                nf[e] = dfdg[e] = dndg[e] = 0.0;
            }
            if (s->normal) {
                QUIET_OK(fricreg_jenkins_trial_normal(jk, m, q, g, f, nf, df, dfdg));
                for (size_t e = 0; e < m; e++)
                    dndg[e] = s->n0[e] + s->kn[e] * g[e] >= 0.0 ? s->kn[e] : 0.0;
            } else {
                QUIET_OK(fricreg_jenkins_trial(jk, m, q, f, df));
            }
            double rmax = 0.0;
            for (size_t i = 0; i < n; i++) {
                R[i] = -(s->pc[i] * ct + s->ps[i] * st);
                for (size_t k = 0; k < n; k++) {
                    R[i] += s->M[i * n + k] * an[k] + s->C[i * n + k] * vn[k] +
                            s->K[i * n + k] * xn[k];
                    Kt[i * n + k] = s->M[i * n + k] / (beta * dt * dt) +
                                    gamma / (beta * dt) * s->C[i * n + k] + s->K[i * n + k];
                    for (size_t e = 0; e < m; e++)
                        Kt[i * n + k] += s->J[e * n + i] * (df[e] * s->J[e * n + k] +
                                                            dfdg[e] * s->Jn[e * n + k]) +
                                         s->Jn[e * n + i] * dndg[e] * s->Jn[e * n + k];
                }
                for (size_t e = 0; e < m; e++)
                    R[i] += s->J[e * n + i] * f[e] + s->Jn[e * n + i] * nf[e];
                rmax = fmax(rmax, fabs(R[i]));
            }
            (void)rmax;
            gsl_matrix_view Kv = gsl_matrix_view_array(Kt, n, n);
            gsl_vector_view Rv = gsl_vector_view_array(R, n), dv = gsl_vector_view_array(dx, n);
            int sg;
            gsl_linalg_LU_decomp(&Kv.matrix, p, &sg);
            gsl_linalg_LU_solve(&Kv.matrix, p, &Rv.vector, &dv.vector);
            double dm = 0.0;
            for (size_t i = 0; i < n; i++) {
                xn[i] -= dx[i];
                xscale = fmax(xscale, fabs(xn[i]));
                dm = fmax(dm, fabs(dx[i]));
            }
            if (dm <= 1e-14 * xscale)
                break;
        }
        QUIET_OK(fricreg_jenkins_commit(jk));
        memcpy(x, xn, sizeof x);
        memcpy(v, vn, sizeof v);
        memcpy(a, an, sizeof a);
        if (hist != NULL)
            memcpy(hist + (size_t)(step - 1) * n, x, n * sizeof *x);
        int k = step % N;
        if (step > (periods - 2) * N) {
            for (size_t i = 0; i < n; i++)
                sum[i] += x[i] * x[i];
            for (size_t e = 0; e < m && step > (periods - 1) * N; e++) {
                opened[e] |= s->n0[e] + s->kn[e] * g[e] < 0.0;
                closed[e] |= s->n0[e] + s->kn[e] * g[e] >= 0.0;
                qmax[e] = step == (periods - 1) * N + 1 ? q[e] : fmax(qmax[e], q[e]);
                qmin[e] = step == (periods - 1) * N + 1 ? q[e] : fmin(qmin[e], q[e]);
            }
        }
        if (k == 0 && step == (periods - 1) * N)
            for (size_t i = 0; i < n; i++)
                prev[i] = sqrt(sum[i] / N), sum[i] = 0.0;
    }
    for (size_t i = 0; i < n; i++)
        rms[i] = sqrt(sum[i] / N);
    for (size_t e = 0; e < m; e++)
        slips = slips && (s->normal ? opened[e] && closed[e]
                                    : s->kt[e] * (qmax[e] - qmin[e]) > 2.0 * s->mun[e]);
    gsl_permutation_free(p);
    fricreg_jenkins_free(jk);
    return slips;
}
