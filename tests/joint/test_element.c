/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_element.c — Check suite for the element types of host codes (fricreg_element.h): a host
 * with its own state arrays, the types' sizes, purity, tangents and errors.
 *
 * Where the numbers come from:
 *   - jenkins under u = A sin t, A > mun/kt: after the first quarter each half cycle slides
 *     2A - 2 mun/kt at |f| = mun, so the dissipation per cycle, the sum of f dw over the
 *     steps, is 4 mun (A - mun/kt); the 1-D return mapping is exact between the turns, and the
 *     samples hit the turns (sin(pi/2) = 1 in double), so it holds to rounding.
 *   - jenkins_2d on the orbit u = A (cos t, sin t): in the steady state the slider circles at
 *     r = sqrt(A^2 - (mun/kt)^2) (test_jenkins.c derives it) and dissipates 2 pi mun r a
 *     revolution; backward Euler converges to it like h, so the test extrapolates two step
 *     sizes (Richardson, order 1) and checks the order.
 *   - the tangents against centred differences of the force, away from the stick/slip and
 *     lift-off borders; the parameters' derivatives likewise.
 *   - the objects fricreg_jenkins and fricreg_iwan run the same slider (joint/slider.c) in the
 *     same order: the same numbers bit for bit along a random path.
 *   - fricreg_element_segalman against fricreg_iwan_set_segalman, bit for bit. */
#include <check.h>
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg_element.h"
#include "fricreg_iwan.h"
#include "fricreg_jenkins.h"
#include "quiet_check.h"

#define SENTINEL (-777.125)
#define MAXP 64
static const double PI = 3.14159265358979323846;

/* A deterministic uniform number in [lo, hi) (a small LCG: the tests own their sequence). */
static double uniform(unsigned long *seed, double lo, double hi)
{
    *seed = *seed * 6364136223846793005UL + 1442695040888963407UL;
    return lo + (hi - lo) * (double)(*seed >> 11) / 9007199254740992.0;
}

static const fricreg_element_type *type_of(const char *name, size_t ns)
{
    const fricreg_element_type *t = fricreg_element_sliders(fricreg_element_lookup(name), ns);
    ck_assert_ptr_nonnull(t);
    return t;
}

/* Parameters of a type in range: stiffnesses near 2, bounds near 0.7, the normal law a preload
 * near 1 with kn near 3 (or, with a gap, n0 = 0). */
static void some_params(const fricreg_element_type *t, unsigned long *seed, int with_gap, double *p)
{
    size_t ns = fricreg_element_nsliders(t), np = fricreg_element_nparams(t);
    for (size_t s = 0; s < ns; s++) {
        p[s] = uniform(seed, 1.0, 3.0);
        p[ns + s] = uniform(seed, 0.3, 1.0);
    }
    if (np > 2 * ns) {
        p[2 * ns] = uniform(seed, 2.0, 4.0);
        p[2 * ns + 1] = with_gap ? 0.0 : uniform(seed, 0.5, 1.5);
        p[2 * ns + 2] = with_gap ? uniform(seed, 0.05, 0.2) : 0.0;
    }
}

static int is_normal(const fricreg_element_type *t)
{
    return fricreg_element_nparams(t) == 2 * fricreg_element_nsliders(t) + 3;
}

/* The names in the header's table, with dim, nparams and nstate at ns = 3 for the families. */
static const struct {
    const char *name;
    int dim;
    size_t ns, nparams, nstate;
} TYPES[] = {{"jenkins", 1, 1, 2, 1},    {"jenkins_2d", 2, 1, 2, 2},
             {"jenkins_3d", 3, 1, 2, 3}, {"jenkins_normal", 2, 1, 5, 1},
             {"contact_3d", 3, 1, 5, 2}, {"iwan", 1, 3, 6, 3},
             {"iwan_2d", 2, 3, 6, 6},    {"iwan_normal", 2, 3, 9, 3},
             {"iwan_3d", 3, 3, 6, 9}}; /* the slider types; spring has its own test */
#define NTYPES (sizeof TYPES / sizeof TYPES[0])

START_TEST(test_table)
{
    for (size_t i = 0; i < NTYPES; i++) {
        const fricreg_element_type *t = type_of(TYPES[i].name, TYPES[i].ns);
        ck_assert_str_eq(fricreg_element_name(t), TYPES[i].name);
        ck_assert_int_eq(fricreg_element_dim(t), TYPES[i].dim);
        ck_assert_uint_eq(fricreg_element_nparams(t), TYPES[i].nparams);
        ck_assert_uint_eq(fricreg_element_nstate(t), TYPES[i].nstate);
        ck_assert_uint_eq(fricreg_element_nsliders(t), TYPES[i].ns);
    }
    /* the list: every type once, found by its name; the F77 codes of fricreg_element_f77.f90 */
    static const char *const codes[] = {"jenkins",     "jenkins_2d", "contact_3d",     "iwan",
                                        "iwan_normal", "jenkins_3d", "jenkins_normal", "iwan_2d",
                                        "iwan_3d",     "spring"};
    static const int code_of[] = {FRICREG_ELEMENT_JENKINS,        FRICREG_ELEMENT_JENKINS_2D,
                                  FRICREG_ELEMENT_CONTACT_3D,     FRICREG_ELEMENT_IWAN,
                                  FRICREG_ELEMENT_IWAN_NORMAL,    FRICREG_ELEMENT_JENKINS_3D,
                                  FRICREG_ELEMENT_JENKINS_NORMAL, FRICREG_ELEMENT_IWAN_2D,
                                  FRICREG_ELEMENT_IWAN_3D,        FRICREG_ELEMENT_SPRING};
    ck_assert_uint_ge(fricreg_element_count(), NTYPES);
    for (size_t i = 0; i < sizeof codes / sizeof codes[0]; i++) {
        ck_assert_str_eq(fricreg_element_name(fricreg_element_at(i)), codes[i]);
        ck_assert_str_eq(fricreg_element_name(fricreg_element_at((size_t)code_of[i] - 1)),
                         codes[i]);
    }
    for (size_t i = 0; i < fricreg_element_count(); i++) {
        const fricreg_element_type *t = fricreg_element_at(i);
        ck_assert_ptr_eq(fricreg_element_lookup(fricreg_element_name(t)), t);
        ck_assert_uint_eq(fricreg_element_nsliders(t), 1);
    }
    ck_assert_ptr_null(fricreg_element_at(fricreg_element_count()));
    ck_assert_ptr_null(fricreg_element_lookup("coulomb"));
    ck_assert_ptr_null(fricreg_element_lookup(NULL));
    ck_assert_ptr_null(fricreg_element_lookup("Jenkins"));
    /* the slider counts: 1..FRICREG_ELEMENT_MAX_SLIDERS for the families, 1 for the others */
    const fricreg_element_type *iwan = fricreg_element_lookup("iwan");
    ck_assert_ptr_null(fricreg_element_sliders(iwan, 0));
    ck_assert_ptr_null(fricreg_element_sliders(iwan, FRICREG_ELEMENT_MAX_SLIDERS + 1));
    ck_assert_ptr_null(fricreg_element_sliders(NULL, 1));
    const fricreg_element_type *big = fricreg_element_sliders(iwan, FRICREG_ELEMENT_MAX_SLIDERS);
    ck_assert_uint_eq(fricreg_element_nparams(big), 2 * FRICREG_ELEMENT_MAX_SLIDERS);
    ck_assert_ptr_eq(fricreg_element_sliders(big, 1), iwan);
    const fricreg_element_type *jk = fricreg_element_lookup("jenkins");
    ck_assert_ptr_eq(fricreg_element_sliders(jk, 1), jk);
    ck_assert_ptr_null(fricreg_element_sliders(jk, 2));
    ck_assert_ptr_null(fricreg_element_name(NULL));
    ck_assert_int_eq(fricreg_element_dim(NULL), 0);
    ck_assert_uint_eq(fricreg_element_nparams(NULL), 0);
    ck_assert_uint_eq(fricreg_element_nstate(NULL), 0);
    ck_assert_uint_eq(fricreg_element_nsliders(NULL), 0);
}
END_TEST

/* Dissipation per cycle of a host driving jenkins over u = A sin t, N steps a cycle, from the
 * second cycle on (the first quarter is the transient). */
static double jenkins_cycle(double kt, double mun, double amp, int n)
{
    const fricreg_element_type *t = type_of("jenkins", 1);
    double p[2] = {kt, mun}, w, f, dfdu, d = 0.0;
    ck_assert_int_eq(fricreg_element_init(t, p, &w), FRICREG_OK);
    for (int k = 1; k <= 2 * n; k++) {
        double u = amp * sin(2.0 * PI * k / n), w_new;
        QUIET_OK(fricreg_element_eval(t, p, &w, &u, &f, &dfdu, NULL, &w_new));
        if (k > n)
            d += f * (w_new - w);
        w = w_new;
    }
    return d;
}

START_TEST(test_jenkins_dissipation)
{
    static const double cases[][3] = {{2.385, 0.7125, 1.0}, {40.0, 3.0, 0.5}, {1.0, 0.25, 3.0}};
    for (size_t c = 0; c < 3; c++) {
        double kt = cases[c][0], mun = cases[c][1], amp = cases[c][2];
        double exact = 4.0 * mun * (amp - mun / kt);
        double d = jenkins_cycle(kt, mun, amp, 400);
        ck_assert_msg(fabs(d - exact) <= 1e-12 * exact,
                      "case %zu: D = %.17g, 4 mun (A - mun/kt) = %.17g", c, d, exact);
    }
    /* below the slip amplitude it never slides */
    ck_assert_double_eq(jenkins_cycle(2.0, 1.0, 0.4, 400), 0.0);
}
END_TEST

/* Dissipation of the third revolution of jenkins_2d on u = A (cos t, sin t), n steps each. */
static double orbit_cycle(double kt, double mun, double amp, int n)
{
    const fricreg_element_type *t = type_of("jenkins_2d", 1);
    double p[2] = {kt, mun}, w[2], f[2], d = 0.0;
    ck_assert_int_eq(fricreg_element_init(t, p, w), FRICREG_OK);
    for (int k = 1; k <= 3 * n; k++) {
        double u[2] = {amp * cos(2.0 * PI * k / n), amp * sin(2.0 * PI * k / n)}, w_new[2];
        QUIET_OK(fricreg_element_eval(t, p, w, u, f, NULL, NULL, w_new));
        if (k > 2 * n)
            d += f[0] * (w_new[0] - w[0]) + f[1] * (w_new[1] - w[1]);
        w[0] = w_new[0];
        w[1] = w_new[1];
    }
    return d;
}

START_TEST(test_jenkins_2d_orbit)
{
    double kt = 2.385, mun = 0.7125, amp = 1.0;
    double exact = 2.0 * PI * mun * sqrt(amp * amp - (mun / kt) * (mun / kt));
    double d1 = orbit_cycle(kt, mun, amp, 8000), d2 = orbit_cycle(kt, mun, amp, 16000),
           d4 = orbit_cycle(kt, mun, amp, 32000);
    double order = log2(fabs(d1 - exact) / fabs(d2 - exact));
    ck_assert_msg(order > 0.9 && order < 1.1, "order %g", order);
    double richardson = 2.0 * d4 - d2;
    ck_assert_msg(fabs(richardson - exact) <= 1e-7 * exact,
                  "extrapolated D = %.15g, 2 pi mun r = %.15g", richardson, exact);
}
END_TEST

/* One random point of a type: state near 0, u of the scale of the slip displacements. */
static void some_point(const fricreg_element_type *t, unsigned long *seed, double *state, double *u)
{
    for (size_t i = 0; i < fricreg_element_nstate(t); i++)
        state[i] = uniform(seed, -0.4, 0.4);
    for (int a = 0; a < fricreg_element_dim(t); a++)
        u[a] = uniform(seed, -0.9, 0.9);
}

/* Whether every slider and the normal law are clear of their borders by rel at (p, w, u). */
static int clear_of_kinks(const fricreg_element_type *t, const double *p, const double *w,
                          const double *u, double rel)
{
    size_t ns = fricreg_element_nsliders(t);
    int dim = fricreg_element_dim(t), normal = is_normal(t), td = dim - normal;
    double n = 1.0;
    if (normal) {
        double nc = p[2 * ns + 1] + p[2 * ns] * (u[td] - p[2 * ns + 2]);
        if (fabs(nc) < rel)
            return 0;
        n = fmax(0.0, nc);
    }
    for (size_t s = 0; s < ns; s++) {
        double r = 0.0;
        for (int a = 0; a < td; a++)
            r += (u[a] - w[td * s + a]) * (u[a] - w[td * s + a]);
        r = sqrt(r);
        if (fabs(p[s] * r - p[ns + s] * n) < rel || r < rel)
            return 0;
    }
    return 1;
}

/* The centred difference of f in x[j] (x is u or params, which the call perturbs and
 * restores), step h, into col[dim]. */
static void centred(const fricreg_element_type *t, double *p, const double *w, double *u, double *x,
                    size_t j, double h, double *col)
{
    double fp[3], fm[3], wn[MAXP], x0 = x[j];
    x[j] = x0 + h;
    QUIET_OK(fricreg_element_eval(t, p, w, u, fp, NULL, NULL, wn));
    x[j] = x0 - h;
    QUIET_OK(fricreg_element_eval(t, p, w, u, fm, NULL, NULL, wn));
    x[j] = x0;
    for (int a = 0; a < fricreg_element_dim(t); a++)
        col[a] = (fp[a] - fm[a]) / (2 * h);
}

START_TEST(test_tangents)
{
    unsigned long seed = 11;
    for (size_t i = 0; i < NTYPES; i++) {
        const fricreg_element_type *t = type_of(TYPES[i].name, TYPES[i].ns);
        int dim = fricreg_element_dim(t);
        size_t np = fricreg_element_nparams(t);
        int checked = 0;
        for (int trial = 0; trial < 400 && checked < 40; trial++) {
            double p[MAXP], w[MAXP], u[3], f[3], dfdu[9], dfdp[3 * MAXP], wn[MAXP], col[3];
            some_params(t, &seed, trial % 2, p);
            some_point(t, &seed, w, u);
            if (!clear_of_kinks(t, p, w, u, 1e-3))
                continue;
            checked++;
            QUIET_OK(fricreg_element_eval(t, p, w, u, f, dfdu, dfdp, wn));
            for (int c = 0; c < dim; c++) {
                centred(t, p, w, u, u, (size_t)c, 1e-6, col);
                for (int a = 0; a < dim; a++)
                    QUIET_ASSERT(fabs(col[a] - dfdu[dim * a + c]) <= 1e-7,
                                 "%s: df%d/du%d = %g, centred %g", TYPES[i].name, a, c,
                                 dfdu[dim * a + c], col[a]);
            }
            for (size_t j = 0; j < np; j++) {
                if (p[j] == 0.0) /* n0 = 0 with a gap, or gap = 0 with n0: no valid
                                  * neighbour (test_contact_3d_one_form_columns) */
                    continue;
                centred(t, p, w, u, p, j, 1e-6, col);
                for (int a = 0; a < dim; a++)
                    QUIET_ASSERT(fabs(col[a] - dfdp[np * a + j]) <= 1e-7,
                                 "%s: df%d/dp%zu = %g, centred %g", TYPES[i].name, a, j,
                                 dfdp[np * a + j], col[a]);
            }
        }
        ck_assert_msg(checked >= 40, "%s: only %d points clear of the kinks", TYPES[i].name,
                      checked);
    }
}
END_TEST

/* A path of steps for a host: each converged step from the last state; every step evaluated
 * again from its old state after other calls (a cut-back), which must give the same bits. */
START_TEST(test_pure)
{
    unsigned long seed = 5;
    for (size_t i = 0; i < NTYPES; i++) {
        const fricreg_element_type *t = type_of(TYPES[i].name, TYPES[i].ns);
        int dim = fricreg_element_dim(t);
        size_t np = fricreg_element_nparams(t), nst = fricreg_element_nstate(t);
        double p[MAXP], w[MAXP], u[3] = {0.0, 0.0, 0.0};
        some_params(t, &seed, 0, p);
        ck_assert_int_eq(fricreg_element_init(t, p, w), FRICREG_OK);
        for (size_t k = 0; k < nst; k++)
            ck_assert_double_eq(w[k], 0.0);
        for (int step = 0; step < 300; step++) {
            for (int a = 0; a < dim; a++)
                u[a] += uniform(&seed, -0.2, 0.2);
            double f1[3], t1[9], q1[3 * MAXP], w1[MAXP], f2[3], t2[9], q2[3 * MAXP], w2[MAXP];
            QUIET_OK(fricreg_element_eval(t, p, w, u, f1, t1, q1, w1));
            double other[3] = {u[0] + 5.0, -u[0], 2.0}, fo[3], wo[MAXP];
            QUIET_OK(fricreg_element_eval(t, p, w, other, fo, NULL, NULL, wo));
            QUIET_OK(fricreg_element_eval(t, p, w, u, f2, t2, q2, w2));
            QUIET_CHECK(memcmp(f1, f2, (size_t)dim * sizeof *f1) == 0);
            QUIET_CHECK(memcmp(t1, t2, (size_t)(dim * dim) * sizeof *t1) == 0);
            QUIET_CHECK(memcmp(q1, q2, (size_t)dim * np * sizeof *q1) == 0);
            QUIET_CHECK(memcmp(w1, w2, nst * sizeof *w1) == 0);
            /* state_out = state_in: the same numbers */
            double wa[MAXP];
            memcpy(wa, w, nst * sizeof *w);
            QUIET_OK(fricreg_element_eval(t, p, wa, u, f2, NULL, NULL, wa));
            QUIET_CHECK(memcmp(wa, w1, nst * sizeof *w1) == 0);
            QUIET_CHECK(memcmp(f1, f2, (size_t)dim * sizeof *f1) == 0);
            memcpy(w, w1, nst * sizeof *w);
        }
    }
}
END_TEST

/* The objects' trial from their committed sliders against the types from the host's state. */
START_TEST(test_same_as_objects)
{
    unsigned long seed = 21;
    for (int dim = 1; dim <= 2; dim++) {
        fricreg_jenkins *j;
        fricreg_iwan *iw;
        const size_t ns = 4;
        ck_assert_int_eq(fricreg_jenkins_create(dim, 1, &j), FRICREG_OK);
        ck_assert_int_eq(fricreg_iwan_create(dim, 1, ns, &iw), FRICREG_OK);
        double pj[5] = {2.5, 0.6, 3.0, 0.9, 0.0}, pi[2 * 4];
        for (size_t s = 0; s < ns; s++) {
            pi[s] = uniform(&seed, 0.5, 2.0);
            pi[ns + s] = uniform(&seed, 0.1, 0.5);
        }
        ck_assert_int_eq(fricreg_jenkins_set_params(j, 1, &pj[0], &pj[1]), FRICREG_OK);
        ck_assert_int_eq(fricreg_iwan_set_params(iw, 1, ns, pi, &pi[ns]), FRICREG_OK);
        const fricreg_element_type *tj = type_of(dim == 1 ? "jenkins" : "jenkins_2d", 1),
                                   *ti = type_of(dim == 1 ? "iwan" : "iwan_2d", ns),
                                   *tn = type_of(dim == 1 ? "jenkins_normal" : "contact_3d", 1);
        double wj[2] = {0.0, 0.0}, wi[8] = {0.0}, wn[2] = {0.0, 0.0}, u[3] = {0.0, 0.0, 0.0};
        fricreg_jenkins *jn;
        ck_assert_int_eq(fricreg_jenkins_create(dim, 1, &jn), FRICREG_OK);
        ck_assert_int_eq(fricreg_jenkins_set_params(jn, 1, &pj[0], &pj[1]), FRICREG_OK);
        ck_assert_int_eq(fricreg_jenkins_set_normal(jn, 1, &pj[1], &pj[3], &pj[2]), FRICREG_OK);
        for (int step = 0; step < 400; step++) {
            for (int a = 0; a <= dim; a++)
                u[a] += uniform(&seed, -0.25, 0.25);
            double fo[2], to[4], fe[3], te[9], wout[8];
            /* fixed bound: jenkins(_2d) */
            QUIET_OK(fricreg_jenkins_trial(j, 1, u, fo, to));
            QUIET_OK(fricreg_element_eval(tj, pj, wj, u, fe, te, NULL, wout));
            QUIET_CHECK(memcmp(fo, fe, (size_t)dim * sizeof *fo) == 0);
            QUIET_CHECK(memcmp(to, te, (size_t)(dim * dim) * sizeof *to) == 0);
            memcpy(wj, wout, (size_t)dim * sizeof *wj);
            QUIET_OK(fricreg_jenkins_commit(j));
            /* Iwan */
            QUIET_OK(fricreg_iwan_trial(iw, 1, u, fo, to));
            QUIET_OK(fricreg_element_eval(ti, pi, wi, u, fe, te, NULL, wout));
            QUIET_CHECK(memcmp(fo, fe, (size_t)dim * sizeof *fo) == 0);
            QUIET_CHECK(memcmp(to, te, (size_t)(dim * dim) * sizeof *to) == 0);
            memcpy(wi, wout, (size_t)dim * ns * sizeof *wi);
            QUIET_OK(fricreg_iwan_commit(iw));
            /* normal law with lift-off: g = u[dim] */
            double g = u[dim] - 0.2, nf, dg[2], un[3];
            memcpy(un, u, (size_t)dim * sizeof *u);
            un[dim] = g;
            QUIET_OK(fricreg_jenkins_trial_normal(jn, 1, u, &g, fo, &nf, to, dg));
            QUIET_OK(fricreg_element_eval(tn, pj, wn, un, fe, te, NULL, wout));
            int d1 = dim + 1;
            for (int a = 0; a < dim; a++) {
                QUIET_CHECK(fo[a] == fe[a]);
                QUIET_CHECK(dg[a] == te[d1 * a + dim]);
                for (int c = 0; c < dim; c++)
                    QUIET_CHECK(to[dim * a + c] == te[d1 * a + c]);
            }
            QUIET_CHECK(nf == fe[dim]);
            memcpy(wn, wout, (size_t)dim * sizeof *wn);
            QUIET_OK(fricreg_jenkins_commit(jn));
        }
        double wobj[8];
        ck_assert_int_eq(fricreg_iwan_get_slider(iw, 1, ns, wobj), FRICREG_OK);
        ck_assert(memcmp(wobj, wi, (size_t)dim * ns * sizeof *wi) == 0);
        fricreg_jenkins_free(j);
        fricreg_jenkins_free(jn);
        fricreg_iwan_free(iw);
    }
}
END_TEST

START_TEST(test_segalman)
{
    enum { NS = 12 };
    double k[NS], phi[NS], ko[NS], phio[NS];
    double fs = 2.0, kt = 5.0, chi = -0.5, beta = 0.3, res = 1e-4;
    ck_assert_int_eq(fricreg_element_segalman(NS, fs, kt, chi, beta, res, k, phi), FRICREG_OK);
    fricreg_iwan *iw;
    ck_assert_int_eq(fricreg_iwan_create(1, 1, NS, &iw), FRICREG_OK);
    ck_assert_int_eq(fricreg_iwan_set_segalman(iw, 1, &fs, &kt, &chi, &beta, res), FRICREG_OK);
    ck_assert_int_eq(fricreg_iwan_get_params(iw, 1, NS, ko, phio), FRICREG_OK);
    fricreg_iwan_free(iw);
    ck_assert(memcmp(k, ko, sizeof k) == 0);
    ck_assert(memcmp(phi, phio, sizeof phi) == 0);
    /* the sums telescope to K_T and F_S (fricreg_iwan.h) */
    double sk = 0.0, sf = 0.0;
    for (int s = 0; s < NS; s++) {
        sk += k[s];
        sf += phi[s];
    }
    ck_assert_double_eq_tol(sk, kt, 1e-13 * kt);
    ck_assert_double_eq_tol(sf, fs, 1e-13 * fs);
    /* errors: nothing written */
    double k1[NS], phi1[NS];
    for (int s = 0; s < NS; s++)
        k1[s] = phi1[s] = SENTINEL;
    ck_assert_int_eq(fricreg_element_segalman(NS, fs, kt, NAN, beta, res, k1, phi1),
                     FRICREG_ENONFINITE);
    ck_assert_int_eq(fricreg_element_segalman(NS, -fs, kt, chi, beta, res, k1, phi1),
                     FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_element_segalman(NS, fs, kt, -1.0, beta, res, k1, phi1),
                     FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_element_segalman(1, fs, kt, chi, beta, res, k1, phi1), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_element_segalman(NS, fs, kt, chi, beta, 1.5, k1, phi1),
                     FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_element_segalman(0, fs, kt, chi, beta, res, k1, phi1), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_element_segalman(FRICREG_ELEMENT_MAX_SLIDERS + 1, fs, kt, chi, beta,
                                              res, k1, phi1),
                     FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_element_segalman(NS, fs, kt, chi, beta, res, NULL, phi1),
                     FRICREG_ENULL);
    for (int s = 0; s < NS; s++)
        ck_assert(k1[s] == SENTINEL && phi1[s] == SENTINEL);
}
END_TEST

/* eval with a bad input: the status, nothing written, and explain's status and message. */
static void refused(const fricreg_element_type *t, const double *p, const double *w,
                    const double *u, int status, const char *word)
{
    double f[3], dfdu[9], dfdp[3 * MAXP], wo[MAXP];
    for (size_t i = 0; i < 3 * MAXP; i++)
        dfdp[i] = SENTINEL;
    for (size_t i = 0; i < MAXP; i++)
        wo[i] = SENTINEL;
    for (int i = 0; i < 9; i++)
        dfdu[i] = SENTINEL;
    f[0] = f[1] = f[2] = SENTINEL;
    ck_assert_int_eq(fricreg_element_eval(t, p, w, u, f, dfdu, dfdp, wo), status);
    for (size_t i = 0; i < 3 * MAXP; i++)
        ck_assert(dfdp[i] == SENTINEL);
    for (size_t i = 0; i < MAXP; i++)
        ck_assert(wo[i] == SENTINEL);
    for (int i = 0; i < 9; i++)
        ck_assert(dfdu[i] == SENTINEL);
    ck_assert(f[0] == SENTINEL && f[1] == SENTINEL && f[2] == SENTINEL);
    char msg[200];
    ck_assert_int_eq(fricreg_element_explain(t, p, w, u, msg, sizeof msg), status);
    ck_assert_msg(strstr(msg, word) != NULL, "message '%s' lacks '%s'", msg, word);
    ck_assert_msg(strstr(msg, fricreg_element_name(t)) == msg, "message '%s'", msg);
}

START_TEST(test_errors)
{
    unsigned long seed = 3;
    for (size_t i = 0; i < NTYPES; i++) {
        const fricreg_element_type *t = type_of(TYPES[i].name, TYPES[i].ns);
        size_t ns = TYPES[i].ns, np = TYPES[i].nparams;
        double p[MAXP], q[MAXP], w[MAXP] = {0.0}, u[3] = {0.3, -0.2, 0.1}, f[3], wo[MAXP];
        some_params(t, &seed, 0, p);
        char msg[200] = "x";
        ck_assert_int_eq(fricreg_element_explain(t, p, w, u, msg, sizeof msg), FRICREG_OK);
        ck_assert_str_eq(msg, "");
        /* NULLs */
        ck_assert_int_eq(fricreg_element_eval(NULL, p, w, u, f, NULL, NULL, wo), FRICREG_ENULL);
        ck_assert_int_eq(fricreg_element_eval(t, NULL, w, u, f, NULL, NULL, wo), FRICREG_ENULL);
        ck_assert_int_eq(fricreg_element_eval(t, p, NULL, u, f, NULL, NULL, wo), FRICREG_ENULL);
        ck_assert_int_eq(fricreg_element_eval(t, p, w, NULL, f, NULL, NULL, wo), FRICREG_ENULL);
        ck_assert_int_eq(fricreg_element_eval(t, p, w, u, NULL, NULL, NULL, wo), FRICREG_ENULL);
        ck_assert_int_eq(fricreg_element_eval(t, p, w, u, f, NULL, NULL, NULL), FRICREG_ENULL);
        ck_assert_int_eq(fricreg_element_init(t, p, NULL), FRICREG_ENULL);
        ck_assert_int_eq(fricreg_element_init(NULL, p, w), FRICREG_ENULL);
        ck_assert_int_eq(fricreg_element_explain(t, NULL, NULL, NULL, msg, sizeof msg),
                         FRICREG_ENULL);
        /* each parameter NaN, then out of its range */
        for (size_t j = 0; j < np; j++) {
            memcpy(q, p, np * sizeof *p);
            q[j] = NAN;
            refused(t, q, w, u, FRICREG_ENONFINITE, "params[");
        }
        memcpy(q, p, np * sizeof *p);
        q[ns - 1] = 0.0; /* a stiffness */
        refused(t, q, w, u, FRICREG_EINVAL, "must be > 0");
        memcpy(q, p, np * sizeof *p);
        q[2 * ns - 1] = -0.1; /* a bound or coefficient */
        refused(t, q, w, u, FRICREG_EINVAL, ">= 0");
        double state0[MAXP];
        for (size_t k = 0; k < MAXP; k++)
            state0[k] = SENTINEL;
        ck_assert_int_eq(fricreg_element_init(t, q, state0), FRICREG_EINVAL);
        for (size_t k = 0; k < MAXP; k++)
            ck_assert(state0[k] == SENTINEL);
        if (is_normal(t)) {
            memcpy(q, p, np * sizeof *p);
            q[2 * ns] = -1.0;
            refused(t, q, w, u, FRICREG_EINVAL, "kn");
            memcpy(q, p, np * sizeof *p);
            q[2 * ns + 2] = 0.1; /* a gap beside the preload */
            refused(t, q, w, u, FRICREG_EINVAL, "not both");
            memcpy(q, p, np * sizeof *p);
            q[2 * ns] = 1e300;
            double ubig[3] = {0.0, 0.0, 0.0};
            ubig[TYPES[i].dim - 1] = 1e300;
            refused(t, q, w, ubig, FRICREG_ENONFINITE, "overflow");
        }
        /* u and the state */
        double ub[3] = {u[0], u[1], u[2]};
        ub[TYPES[i].dim - 1] = INFINITY;
        refused(t, p, w, ub, FRICREG_ENONFINITE, "u[");
        double wb[MAXP] = {0.0};
        wb[fricreg_element_nstate(t) - 1] = NAN;
        refused(t, p, wb, u, FRICREG_ENONFINITE, "state[");
        double wf[MAXP] = {0.0}, uf[3] = {1e308, 1e308, 0.0};
        wf[0] = -1e308;
        refused(t, p, wf, uf, FRICREG_ENONFINITE, "overflows");
    }
}
END_TEST

/* contact_3d: lift-off, the memory reset and re-contact; a gap instead of a preload. */
START_TEST(test_contact_3d)
{
    const fricreg_element_type *t = type_of("contact_3d", 1);
    double p[5] = {10.0, 0.5, 4.0, 2.0, 0.0}; /* kt, mu, kn, n0, gap */
    double w[2] = {0.0, 0.0}, f[3], dfdu[9], wo[2];
    double u1[3] = {0.05, 0.0, 0.0}; /* closed, stick: f = kt u, N = n0 */
    ck_assert_int_eq(fricreg_element_eval(t, p, w, u1, f, dfdu, NULL, wo), FRICREG_OK);
    ck_assert_double_eq_tol(f[0], 0.5, 1e-15);
    ck_assert_double_eq(f[2], 2.0);
    ck_assert_double_eq(dfdu[8], 4.0);
    double u2[3] = {0.3, 0.1, -0.6}; /* open: n0 + kn g = -0.4 < 0 */
    ck_assert_int_eq(fricreg_element_eval(t, p, w, u2, f, dfdu, NULL, wo), FRICREG_OK);
    for (int a = 0; a < 3; a++)
        ck_assert_double_eq(f[a], 0.0);
    for (int a = 0; a < 9; a++)
        ck_assert_double_eq(dfdu[a], 0.0);
    ck_assert_double_eq(wo[0], 0.3); /* the slider follows: the memory reset */
    ck_assert_double_eq(wo[1], 0.1);
    double u3[3] = {0.3, 0.1, 0.0}, wo3[2]; /* re-contact where it opened: unloaded */
    ck_assert_int_eq(fricreg_element_eval(t, p, wo, u3, f, NULL, NULL, wo3), FRICREG_OK);
    ck_assert_double_eq(f[0], 0.0);
    ck_assert_double_eq(f[1], 0.0);
    ck_assert_double_eq(f[2], 2.0);
    /* slip: |f_t| = mu N, along d */
    double u4[3] = {1.3, 0.1, 0.25};
    ck_assert_int_eq(fricreg_element_eval(t, p, wo3, u4, f, dfdu, NULL, wo), FRICREG_OK);
    ck_assert_double_eq_tol(hypot(f[0], f[1]), 0.5 * (2.0 + 4.0 * 0.25), 1e-14);
    /* a gap of 0.1: open below g = 0.1, N = kn (g - 0.1) above */
    double pg[5] = {10.0, 0.5, 4.0, 0.0, 0.1}, ug[3] = {0.0, 0.0, 0.35};
    ck_assert_int_eq(fricreg_element_eval(t, pg, w, ug, f, NULL, NULL, wo), FRICREG_OK);
    ck_assert_double_eq_tol(f[2], 1.0, 1e-15);
    ug[2] = 0.09;
    ck_assert_int_eq(fricreg_element_eval(t, pg, w, ug, f, NULL, NULL, wo), FRICREG_OK);
    ck_assert_double_eq(f[2], 0.0);
}
END_TEST

/* jenkins_3d keeps a plane: u and w in a tilted plane give f and the new w in it. */
START_TEST(test_jenkins_3d_plane)
{
    const fricreg_element_type *t = type_of("jenkins_3d", 1);
    double nrm[3] = {0.2, -0.5, 0.8}, len = sqrt(0.04 + 0.25 + 0.64);
    for (int a = 0; a < 3; a++)
        nrm[a] /= len;
    double e1[3] = {0.5, 0.2, 0.0}, e2[3]; /* e1 in the plane: e1 . nrm = 0.1 - 0.1 = 0 */
    e2[0] = nrm[1] * e1[2] - nrm[2] * e1[1];
    e2[1] = nrm[2] * e1[0] - nrm[0] * e1[2];
    e2[2] = nrm[0] * e1[1] - nrm[1] * e1[0];
    double p[2] = {3.0, 0.4}, w[3] = {0.0, 0.0, 0.0}, f[3], wo[3];
    unsigned long seed = 8;
    for (int step = 0; step < 200; step++) {
        double x = uniform(&seed, -1.0, 1.0), y = uniform(&seed, -1.0, 1.0), u[3];
        for (int a = 0; a < 3; a++)
            u[a] = x * e1[a] + y * e2[a];
        QUIET_OK(fricreg_element_eval(t, p, w, u, f, NULL, NULL, wo));
        double fn = f[0] * nrm[0] + f[1] * nrm[1] + f[2] * nrm[2],
               wn = wo[0] * nrm[0] + wo[1] * nrm[1] + wo[2] * nrm[2];
        QUIET_ASSERT(fabs(fn) <= 1e-15 && fabs(wn) <= 1e-15, "out of plane: f.n = %g, w.n = %g", fn,
                     wn);
        QUIET_CHECK(sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]) <= 0.4 * (1 + 1e-15));
        memcpy(w, wo, sizeof w);
    }
}
END_TEST

/* spring: f = k u, df/du = k, df/dk = u, no state; k <= 0, NaN and an overflowing k u refused
 * with nothing written. */
START_TEST(test_spring)
{
    const fricreg_element_type *t = fricreg_element_lookup("spring");
    ck_assert_int_eq(fricreg_element_dim(t), 1);
    ck_assert_uint_eq(fricreg_element_nparams(t), 1);
    ck_assert_uint_eq(fricreg_element_nstate(t), 0);
    ck_assert_uint_eq(fricreg_element_nsliders(t), 1);
    double k = 0.7, u = 0.3, f = -1.0, dfdu = -1.0, dfdp = -1.0, none[1] = {42.0};
    ck_assert_int_eq(fricreg_element_init(t, &k, none), FRICREG_OK);
    ck_assert_double_eq(none[0], 42.0); /* no state to write */
    ck_assert_int_eq(fricreg_element_eval(t, &k, none, &u, &f, &dfdu, &dfdp, none), FRICREG_OK);
    ck_assert_double_eq(f, 0.7 * 0.3);
    ck_assert_double_eq(dfdu, 0.7);
    ck_assert_double_eq(dfdp, 0.3);
    static const double bad_k[3] = {0.0, -1.0, NAN};
    static const int want[3] = {FRICREG_EINVAL, FRICREG_EINVAL, FRICREG_ENONFINITE};
    for (int i = 0; i < 3; i++) {
        f = -1.0;
        ck_assert_int_eq(fricreg_element_eval(t, &bad_k[i], none, &u, &f, NULL, NULL, none),
                         want[i]);
        ck_assert_double_eq(f, -1.0);
    }
    double huge = 1e300, big_u = 1e10;
    ck_assert_int_eq(fricreg_element_eval(t, &huge, none, &big_u, &f, NULL, NULL, none),
                     FRICREG_ENONFINITE);
    ck_assert_double_eq(f, -1.0);
}
END_TEST

/* iwan_3d on u = (u1, u2, 0) is iwan_2d on (u1, u2), bit for bit (the ball's norm of
 * (d1, d2, 0) is the disk's exactly: hypot(r, 0) = r), with f3 = 0 and each slider's third
 * state component 0; on a tilted plane, f and the sliders' state stay in it. */
START_TEST(test_iwan_3d)
{
    const size_t ns = 5;
    const fricreg_element_type *t3 = type_of("iwan_3d", ns), *t2 = type_of("iwan_2d", ns);
    double p[2 * 5], w3[3 * 5] = {0.0}, w2[2 * 5] = {0.0};
    unsigned long seed = 33;
    for (size_t s = 0; s < ns; s++) {
        p[s] = uniform(&seed, 0.5, 3.0);
        p[ns + s] = uniform(&seed, 0.05, 0.4);
    }
    double u[3] = {0.0, 0.0, 0.0};
    for (int step = 0; step < 300; step++) {
        u[0] += uniform(&seed, -0.3, 0.3);
        u[1] += uniform(&seed, -0.3, 0.3);
        double f3[3], t3m[9], o3[3 * 5], f2[2], t2m[4], o2[2 * 5];
        QUIET_OK(fricreg_element_eval(t3, p, w3, u, f3, t3m, NULL, o3));
        QUIET_OK(fricreg_element_eval(t2, p, w2, u, f2, t2m, NULL, o2));
        QUIET_CHECK(f3[0] == f2[0] && f3[1] == f2[1] && f3[2] == 0.0);
        QUIET_CHECK(t3m[0] == t2m[0] && t3m[1] == t2m[1] && t3m[3] == t2m[2] && t3m[4] == t2m[3]);
        for (size_t s = 0; s < ns; s++)
            QUIET_CHECK(o3[3 * s] == o2[2 * s] && o3[3 * s + 1] == o2[2 * s + 1] &&
                        o3[3 * s + 2] == 0.0);
        memcpy(w3, o3, sizeof w3);
        memcpy(w2, o2, sizeof w2);
    }
    /* a tilted plane through 0, normal nrm: the sums of sliders kept in it */
    const double nrm[3] = {0.48, -0.6, 0.64}; /* |nrm| = 1 */
    const double e1[3] = {0.8, 0.64, 0.0},
                 e2[3] = {nrm[1] * e1[2] - nrm[2] * e1[1], nrm[2] * e1[0] - nrm[0] * e1[2],
                          nrm[0] * e1[1] - nrm[1] * e1[0]};
    memset(w3, 0, sizeof w3);
    for (int step = 0; step < 200; step++) {
        double x = uniform(&seed, -1.0, 1.0), y = uniform(&seed, -1.0, 1.0), f[3], o[3 * 5];
        for (int a = 0; a < 3; a++)
            u[a] = x * e1[a] + y * e2[a];
        QUIET_OK(fricreg_element_eval(t3, p, w3, u, f, NULL, NULL, o));
        double fn = f[0] * nrm[0] + f[1] * nrm[1] + f[2] * nrm[2];
        QUIET_ASSERT(fabs(fn) <= 1e-14, "out of plane: f.n = %g", fn);
        for (size_t s = 0; s < ns; s++) {
            double wn = o[3 * s] * nrm[0] + o[3 * s + 1] * nrm[1] + o[3 * s + 2] * nrm[2];
            QUIET_ASSERT(fabs(wn) <= 1e-14, "slider %zu out of plane: w.n = %g", s, wn);
        }
        memcpy(w3, o, sizeof w3);
    }
}
END_TEST

/* explain's NULLs (fricreg_element.h): one of state_in and u NULL is eval's call with that
 * argument NULL, so FRICREG_ENULL and a message naming it, even with bad parameters (eval
 * checks its NULLs first); both NULL is init's check of the parameters alone. */
START_TEST(test_explain_nulls)
{
    for (size_t i = 0; i < NTYPES; i++) {
        const fricreg_element_type *t = type_of(TYPES[i].name, TYPES[i].ns);
        size_t np = TYPES[i].nparams;
        unsigned long seed = 21;
        double p[MAXP], q[MAXP], w[MAXP] = {0.0}, u[3] = {0.3, -0.2, 0.1}, f[3], wo[MAXP];
        some_params(t, &seed, 0, p);
        memcpy(q, p, np * sizeof *p);
        q[0] = 0.0; /* a stiffness out of range */
        char msg[200];
        for (int bad = 0; bad < 2; bad++) {
            const double *pp = bad ? q : p;
            ck_assert_int_eq(fricreg_element_eval(t, pp, w, NULL, f, NULL, NULL, wo),
                             FRICREG_ENULL);
            ck_assert_int_eq(fricreg_element_explain(t, pp, w, NULL, msg, sizeof msg),
                             FRICREG_ENULL);
            ck_assert_msg(strncmp(msg, "u is NULL", 9) == 0, "message '%s'", msg);
            ck_assert_int_eq(fricreg_element_eval(t, pp, NULL, u, f, NULL, NULL, wo),
                             FRICREG_ENULL);
            ck_assert_int_eq(fricreg_element_explain(t, pp, NULL, u, msg, sizeof msg),
                             FRICREG_ENULL);
            ck_assert_msg(strncmp(msg, "state_in is NULL", 16) == 0, "message '%s'", msg);
        }
        strcpy(msg, "x");
        ck_assert_int_eq(fricreg_element_explain(t, p, NULL, NULL, msg, sizeof msg), FRICREG_OK);
        ck_assert_str_eq(msg, "");
        ck_assert_int_eq(fricreg_element_explain(t, q, NULL, NULL, msg, sizeof msg),
                         FRICREG_EINVAL);
        ck_assert_int_eq(fricreg_element_init(t, q, wo), FRICREG_EINVAL);
        ck_assert_int_eq(fricreg_element_explain(NULL, p, w, u, msg, sizeof msg), FRICREG_ENULL);
        ck_assert_str_eq(msg, "type is NULL");
        ck_assert_int_eq(fricreg_element_explain(t, NULL, w, u, msg, sizeof msg), FRICREG_ENULL);
        ck_assert_str_eq(msg, "params is NULL");
        ck_assert_int_eq(fricreg_element_explain(t, p, w, NULL, NULL, 0), FRICREG_ENULL);
    }
}
END_TEST

/* The message of a parameter out of its range names the one condition it fails, the
 * parameter's name and its index, whatever else is wrong after it (a host code reads it). */
static void says(const char *name, size_t ns, const double *p, const char *expected)
{
    const fricreg_element_type *t = type_of(name, ns);
    char msg[200];
    ck_assert_int_eq(fricreg_element_explain(t, p, NULL, NULL, msg, sizeof msg), FRICREG_EINVAL);
    ck_assert_str_eq(msg, expected);
}

START_TEST(test_messages)
{
    const double jk[2] = {1000.0, -0.3}, jk0[2] = {0.0, -0.3}, sp[1] = {-2.5};
    says("jenkins", 1, jk, "jenkins: mun = -0.3 must be >= 0 (params[1])");
    says("jenkins", 1, jk0, "jenkins: kt = 0 must be > 0 (params[0])");
    says("spring", 1, sp, "spring: k = -2.5 must be > 0 (params[0])");
    const double iw[6] = {1.0, 2.0, 3.0, 0.5, 0.25, -0.125}; /* k[3], phi[3] */
    says("iwan", 3, iw, "iwan: phi[2] = -0.125 must be >= 0 (params[5])");
    const double iwk[6] = {1.0, -2.0, 3.0, 0.5, -0.25, 0.125};
    says("iwan_2d", 3, iwk, "iwan_2d: k[1] = -2 must be > 0 (params[1])");
    const double c_mu[5] = {1000.0, -0.3, 4.0, 2.0, 0.0}, c_kn[5] = {1000.0, 0.3, -4.0, 2.0, 0.0},
                 c_both[5] = {1000.0, 0.3, 4.0, 2.0, 0.5};
    says("contact_3d", 1, c_mu, "contact_3d: mu = -0.3 must be >= 0 (params[1])");
    says("contact_3d", 1, c_kn, "contact_3d: kn = -4 must be >= 0 (params[2])");
    says("contact_3d", 1, c_both,
         "contact_3d: n0 = 2 (params[3]) and gap = 0.5 (params[4]) must not both be nonzero: a "
         "preload or a gap");
    const double in[9] = {1.0, 1.0, 1.0, 0.5, -0.5, 0.5, -1.0, 2.0, 0.0}; /* mu[1] and kn bad */
    says("iwan_normal", 3, in, "iwan_normal: mu[1] = -0.5 must be >= 0 (params[4])");
}
END_TEST

/* contact_3d's normal law with a negative gap, a negative n0 and kn = 0, each taken as the
 * header says. The numbers are exact in binary: kn = 4, gap = -0.25 at g = 0.5 gives
 * N = 4 (0.5 + 0.25) = 3, the preload form's 1 + 4 0.5 = 3; n0 = -1 opens below
 * g = -n0/kn = 0.25, as the gap form with gap = 0.25; kn = 0 gives N = n0 whatever g. */
START_TEST(test_contact_3d_normal_law)
{
    const fricreg_element_type *t = type_of("contact_3d", 1);
    double w[2] = {0.0, 0.0}, f[3], f2[3], dfdu[9], wo[2], wo2[2], st[2];
    double inter[5] = {10.0, 0.5, 4.0, 0.0, -0.25}, pre[5] = {10.0, 0.5, 4.0, 1.0, 0.0};
    ck_assert_int_eq(fricreg_element_init(t, inter, st), FRICREG_OK);
    double u0[3] = {0.01, -0.02, 0.0}, u[3] = {0.03, 0.01, 0.5};
    ck_assert_int_eq(fricreg_element_eval(t, inter, w, u0, f, NULL, NULL, wo), FRICREG_OK);
    ck_assert_double_eq(f[2], 1.0); /* closed at g = 0: the interference's preload kn |gap| */
    ck_assert_int_eq(fricreg_element_eval(t, inter, w, u, f, NULL, NULL, wo), FRICREG_OK);
    ck_assert_int_eq(fricreg_element_eval(t, pre, w, u, f2, NULL, NULL, wo2), FRICREG_OK);
    ck_assert_double_eq(f[2], 3.0);
    for (int a = 0; a < 3; a++)
        ck_assert_double_eq(f[a], f2[a]);
    ck_assert(wo[0] == wo2[0] && wo[1] == wo2[1]);
    /* a clearance: n0 = -1 is the gap 0.25 */
    double clear[5] = {10.0, 0.5, 4.0, -1.0, 0.0}, gapf[5] = {10.0, 0.5, 4.0, 0.0, 0.25};
    ck_assert_int_eq(fricreg_element_init(t, clear, st), FRICREG_OK);
    double uo[3] = {0.03, 0.01, 0.125}, uc[3] = {0.03, 0.01, 0.75};
    ck_assert_int_eq(fricreg_element_eval(t, clear, w, uo, f, dfdu, NULL, wo), FRICREG_OK);
    for (int a = 0; a < 3; a++)
        ck_assert_double_eq(f[a], 0.0); /* open: -1 + 4 0.125 = -0.5 < 0 */
    ck_assert_double_eq(dfdu[8], 0.0);
    ck_assert_int_eq(fricreg_element_eval(t, clear, w, uc, f, NULL, NULL, wo), FRICREG_OK);
    ck_assert_int_eq(fricreg_element_eval(t, gapf, w, uc, f2, NULL, NULL, wo2), FRICREG_OK);
    ck_assert_double_eq(f[2], 2.0); /* -1 + 4 0.75 = 4 (0.75 - 0.25) = 2 */
    for (int a = 0; a < 3; a++)
        ck_assert_double_eq(f[a], f2[a]);
    /* kn = 0: the host's normal force n0, whatever g; in slip |f_t| = mu n0 */
    double given[5] = {10.0, 0.5, 0.0, 2.0, 0.0};
    ck_assert_int_eq(fricreg_element_init(t, given, st), FRICREG_OK);
    const double gs[3] = {-5.2, 0.0, 0.37};
    for (int k = 0; k < 3; k++) {
        double ug[3] = {0.8, 0.3, gs[k]};
        ck_assert_int_eq(fricreg_element_eval(t, given, w, ug, f, dfdu, NULL, wo), FRICREG_OK);
        ck_assert_double_eq(f[2], 2.0);
        ck_assert_double_eq_tol(hypot(f[0], f[1]), 1.0, 1e-15);
        ck_assert_double_eq(dfdu[2], 0.0); /* df_t/dg */
        ck_assert_double_eq(dfdu[5], 0.0);
        ck_assert_double_eq(dfdu[8], 0.0); /* dN/dg */
    }
    double tension[5] = {10.0, 0.5, 0.0, -2.0, 0.0}, none[5] = {10.0, 0.5, 0.0, 0.0, 0.1};
    double ut[3] = {0.8, 0.3, 100.0};
    ck_assert_int_eq(fricreg_element_eval(t, tension, w, ut, f, NULL, NULL, wo), FRICREG_OK);
    ck_assert(f[0] == 0.0 && f[1] == 0.0 && f[2] == 0.0 && wo[0] == 0.8 && wo[1] == 0.3);
    ck_assert_int_eq(fricreg_element_eval(t, none, w, ut, f, NULL, NULL, wo), FRICREG_OK);
    ck_assert(f[0] == 0.0 && f[1] == 0.0 && f[2] == 0.0);
}
END_TEST

/* dfdp's n0 and gap columns where only one form is valid: the other parameter's step is
 * refused on both sides (EINVAL), and the column is the centred difference along the other
 * form (a gap step h is the preload step -kn h), as the header says. */
START_TEST(test_contact_3d_one_form_columns)
{
    const fricreg_element_type *t = type_of("contact_3d", 1);
    const double h = 1e-6, kn = 3.7;
    double w[2] = {0.11, -0.04}, u[3] = {0.9, 0.35, 0.42}, f[3], fp[3], fm[3], wo[2];
    double dfdp[15];
    /* the preload form n0 = 1.3: its gap column */
    double p[5] = {8.5, 0.45, kn, 1.3, 0.0}, q[5];
    ck_assert_int_eq(fricreg_element_eval(t, p, w, u, f, NULL, dfdp, wo), FRICREG_OK);
    memcpy(q, p, sizeof p);
    q[4] = h;
    ck_assert_int_eq(fricreg_element_eval(t, q, w, u, fp, NULL, NULL, wo), FRICREG_EINVAL);
    q[4] = -h;
    ck_assert_int_eq(fricreg_element_eval(t, q, w, u, fp, NULL, NULL, wo), FRICREG_EINVAL);
    memcpy(q, p, sizeof p);
    q[3] = p[3] - kn * h;
    ck_assert_int_eq(fricreg_element_eval(t, q, w, u, fp, NULL, NULL, wo), FRICREG_OK);
    q[3] = p[3] + kn * h;
    ck_assert_int_eq(fricreg_element_eval(t, q, w, u, fm, NULL, NULL, wo), FRICREG_OK);
    for (int a = 0; a < 3; a++) {
        ck_assert_double_eq_tol((fp[a] - fm[a]) / (2 * h), dfdp[5 * a + 4], 1e-7);
        ck_assert_double_eq_tol(dfdp[5 * a + 4], -kn * dfdp[5 * a + 3], 1e-15);
    }
    ck_assert(fabs(dfdp[5 * 0 + 4]) > 0.1); /* slipping: the tangential column is not 0 */
    /* the gap form gap = 0.2: its n0 column (an n0 step h is the gap step -h/kn) */
    double g[5] = {8.5, 0.45, kn, 0.0, 0.2};
    ck_assert_int_eq(fricreg_element_eval(t, g, w, u, f, NULL, dfdp, wo), FRICREG_OK);
    memcpy(q, g, sizeof g);
    q[3] = h;
    ck_assert_int_eq(fricreg_element_eval(t, q, w, u, fp, NULL, NULL, wo), FRICREG_EINVAL);
    q[3] = -h;
    ck_assert_int_eq(fricreg_element_eval(t, q, w, u, fp, NULL, NULL, wo), FRICREG_EINVAL);
    memcpy(q, g, sizeof g);
    q[4] = g[4] - h / kn;
    ck_assert_int_eq(fricreg_element_eval(t, q, w, u, fp, NULL, NULL, wo), FRICREG_OK);
    q[4] = g[4] + h / kn;
    ck_assert_int_eq(fricreg_element_eval(t, q, w, u, fm, NULL, NULL, wo), FRICREG_OK);
    for (int a = 0; a < 3; a++)
        ck_assert_double_eq_tol((fp[a] - fm[a]) / (2 * h), dfdp[5 * a + 3], 1e-7);
    ck_assert_double_eq(dfdp[5 * 2 + 3], 1.0); /* dN/dn0 */
}
END_TEST

static Suite *element_suite(void)
{
    Suite *s = suite_create("element");
    TCase *tc = tcase_create("element");
    tcase_add_test(tc, test_table);
    tcase_add_test(tc, test_jenkins_dissipation);
    tcase_add_test(tc, test_jenkins_2d_orbit);
    tcase_add_test(tc, test_tangents);
    tcase_add_test(tc, test_pure);
    tcase_add_test(tc, test_same_as_objects);
    tcase_add_test(tc, test_segalman);
    tcase_add_test(tc, test_errors);
    tcase_add_test(tc, test_contact_3d);
    tcase_add_test(tc, test_explain_nulls);
    tcase_add_test(tc, test_messages);
    tcase_add_test(tc, test_contact_3d_normal_law);
    tcase_add_test(tc, test_contact_3d_one_form_columns);
    tcase_add_test(tc, test_jenkins_3d_plane);
    tcase_add_test(tc, test_iwan_3d);
    tcase_add_test(tc, test_spring);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    SRunner *sr = srunner_create(element_suite());
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? 0 : 1;
}
