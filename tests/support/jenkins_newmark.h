/* SPDX-License-Identifier: GPL-3.0-or-later */
/* jenkins_newmark.h — the time-domain reference of a linear structure with 1-D Jenkins elements
 * under harmonic forcing, M x'' + C x' + K x + J^T f(J x) = p_c cos(Omega t) + p_s sin(Omega t),
 * written out by hand: average-acceleration Newmark (beta = 1/4, gamma = 1/2) with Newton on
 * the displacements and the elements' return mapping (fricreg_jenkins_trial, commit after each
 * step), GSL's LU for the Newton steps, from rest. With normal set, the elements carry a normal
 * load with lift-off (fricreg_jenkins_trial_normal): M x'' + C x' + K x + J^T f + Jn^T N = p,
 * N = max(0, N0 + kn Jn x), f bounded by mu N. The reference of test_hb (harmonic balance),
 * test_hb_liftoff and test_structure_jenkins (fricreg_structure's elements). */
#ifndef FRICREG_TEST_JENKINS_NEWMARK_H
#define FRICREG_TEST_JENKINS_NEWMARK_H

#include <stddef.h>

#define JENKINS_MODEL_MAXN 3
#define JENKINS_MODEL_MAXM 2

/* A model: n dofs, m elements, dense row-major matrices (J, Jn: m x n). normal: J holds the
 * tangential rows, Jn the normal ones, mu, n0, kn the normal law (mun unused). */
struct jenkins_model {
    size_t n, m;
    double M[JENKINS_MODEL_MAXN * JENKINS_MODEL_MAXN], C[JENKINS_MODEL_MAXN * JENKINS_MODEL_MAXN],
        K[JENKINS_MODEL_MAXN * JENKINS_MODEL_MAXN], J[JENKINS_MODEL_MAXM * JENKINS_MODEL_MAXN];
    double kt[JENKINS_MODEL_MAXM], mun[JENKINS_MODEL_MAXM], pc[JENKINS_MODEL_MAXN],
        ps[JENKINS_MODEL_MAXN];
    int normal;
    double Jn[JENKINS_MODEL_MAXM * JENKINS_MODEL_MAXN], mu[JENKINS_MODEL_MAXM],
        n0[JENKINS_MODEL_MAXM], kn[JENKINS_MODEL_MAXM];
};

/* The harmonic-balance suites' models (test_hb, test_hb_truncation): one dof on a spring to
 * ground with a Jenkins element to ground, cosine forcing; and three masses in a chain on
 * springs (ground–1, 1–2, 2–3), C = 0.03 M + 0.01 K, element 0 between mass 3 and ground,
 * element 1 between masses 1 and 2, mass 1 excited. */
struct jenkins_model jenkins_model_oscillator(void);
struct jenkins_model jenkins_model_chain(void);

/* periods periods of N steps each from rest at Omega = omega: the RMS of each dof over the last
 * period into rms[n] and over the one before into prev[n]; x after every step into
 * hist[step * n + k] (step 0 .. periods N - 1) where hist is not NULL. Returns whether every
 * element's range over the last period exceeded its slip range 2 mun/kt; with normal, whether
 * every element was both open (N0 + kn g < 0) and closed at steps of the last period. Check
 * assertions on failure. */
int jenkins_newmark_rms(const struct jenkins_model *s, double omega, int N, int periods,
                        double *rms, double *prev, double *hist);

#endif
