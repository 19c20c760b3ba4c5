/* SPDX-License-Identifier: GPL-3.0-or-later */
/* hb_stability_size.c — the cost and the agreement of the default stability
 * (FRICREG_HB_STABILITY_AUTO) on models of growing size, their matrices compressed (KLU factors
 * D_h: dense, a 1000-dof continuation takes hours):
 * - the Jenkins chain: n unit masses, springs s = (2n/π)² (first mode near 1 rad/s), fixed at
 *   one end, Rayleigh damping 0.2 ζ ω1 M + 1.8 ζ/ω1 K, ζ = 0.02, 10 Jenkins elements (kt = 1,
 *   μN = 0.05) to the ground (tests/floquet/test_hb_condensed.c's), 0.1 n/60 cos Ωt on the free end
 *   (the tip's resonance falls as 1/n: the sliders slip at every n), continued over 0.8 to 1.3
 *   times the first mode at H = 3 and 7, Newton's tolerance 1e-9 (the solves' rounding reaches
 *   5e-10 of q at 1000 dofs: fricreg_hb.h's header);
 * - the gap chain: tests/floquet/test_hb_stability.c's gap pair joined to a stiff chain (gap_chain),
 *   continued from 11 to 17 rad/s at H = 7, through two folds and two Neimark–Sacker points.
 *
 * Per model: the wall time per stored point without stability and with the default (its
 * method named), their ratio (the target: at most 3); and, where n is at most max_ref_dofs, the
 * same branch with the exact monodromy of the whole model (FRICREG_HB_STABILITY_MONODROMY) as
 * the reference: its cost, the points it finds unstable, the points whose count of unstable
 * multipliers (fricreg_hb_point_exponents: Re λ 2π/Ω > 1e-6) differs from it, the largest
 * difference of the largest |μ| (the target: every count equal, within 1e-3) and the
 * bifurcations located, each against the reference's. The two branches are compared point by
 * point when they have the same points (the stability does not steer the continuation), else
 * the row says so.
 *
 * Usage: fricreg-bench-hb-stability-size [max_dofs [max_ref_dofs [repeats [chains]]]],
 * defaults 1000, 300, 3 (the median time per point of repeats branches each way) and "all"
 * ("jenkins" or "gap" for one kind). */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "fricreg_element.h"
#include "fricreg_hb.h"

#define NE 10
static const double PI = 3.14159265358979323846;

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* M = I and the tridiagonal K (diagonal d[n], the one below b[n − 1]), compressed by K's lower
 * triangle; FRICREG_OK or the first failure. */
static int tridiagonal_model(fricreg_hb *hb, size_t n, const double *d, const double *b)
{
    int64_t *ptr = calloc(n + 1, sizeof(int64_t)), *row = calloc(2 * n, sizeof(int64_t));
    double *k = calloc(2 * n, sizeof(double)), *m = calloc(n, sizeof(double));
    int status = FRICREG_ENOMEM;
    if (ptr && row && k && m) {
        int64_t nnz = 0;
        for (size_t i = 0; i < n; i++) {
            ptr[i] = nnz, m[i] = 1.0;
            row[nnz] = (int64_t)i, k[nnz++] = d[i];
            if (i + 1 < n)
                row[nnz] = (int64_t)i + 1, k[nnz++] = b[i];
        }
        ptr[n] = nnz;
        status = fricreg_hb_set_stiffness_csc(hb, n, FRICREG_SPARSE_LOWER, ptr, row, k);
        for (size_t i = 0; i <= n; i++) /* M's pattern: the diagonal */
            ptr[i] = row[i] = (int64_t)i;
        if (status == FRICREG_OK)
            status = fricreg_hb_set_mass_csc(hb, n, FRICREG_SPARSE_LOWER, ptr, row, m);
    }
    free(ptr), free(row), free(k), free(m);
    return status;
}

/* The Jenkins chain of n dofs as a driver at H harmonics (NULL on failure); its first mode in
 * *w1. */
static fricreg_hb *chain(size_t n, int H, double *w1)
{
    double *d = malloc(n * sizeof(double)), *b = malloc(n * sizeof(double));
    double *J = calloc(NE * n, sizeof(double)), *p = calloc(n, sizeof(double));
    double *ps = calloc(n, sizeof(double)), params[2 * NE];
    fricreg_hb *hb = NULL;
    double s = (2.0 * (double)n / PI) * (2.0 * (double)n / PI), zeta = 0.02;
    *w1 = 2.0 * sqrt(s) * sin(PI / (2.0 * (2.0 * (double)n + 1.0)));
    if (d && b && J && p && ps && fricreg_hb_create(n, NE, H, &hb) == FRICREG_OK) {
        for (size_t i = 0; i < n; i++)
            d[i] = i + 1 < n ? 2.0 * s : s, b[i] = -s;
        for (size_t e = 0; e < NE; e++) {
            J[e * n + (n / NE - 1) + e * (n - n / NE) / (NE - 1)] = 1.0;
            params[2 * e] = 1.0, params[2 * e + 1] = 0.05;
        }
        p[n - 1] = 0.1 * (double)n / 60.0; /* the tip's resonance falls as 1/n: slip at any n */
        if (tridiagonal_model(hb, n, d, b) != FRICREG_OK ||
            fricreg_hb_set_rayleigh(hb, 0.2 * zeta * *w1, 1.8 * zeta / *w1) != FRICREG_OK ||
            fricreg_hb_add_elements(hb, fricreg_element_lookup("jenkins"), NE, n, J, params) !=
                FRICREG_OK ||
            fricreg_hb_set_excitation(hb, n, p, ps) != FRICREG_OK ||
            fricreg_hb_set_newton(hb, 1e-9, 50) != FRICREG_OK) {
            fricreg_hb_free(hb);
            hb = NULL;
        }
    }
    free(d), free(b), free(J), free(p), free(ps);
    return hb;
}

/* The gap pair of tests/floquet/test_hb_stability.c (2 dofs: K = [140 −20; −20 180], C = 0.002 K, a
 * contact on dof 1's tangential and −x_0 normal, kt = 40, mu = 0.01, N0 = −10, kn = 500, so
 * a gap of 0.02 that closes at large amplitude; p_c = (2, 1)) joined by a spring kc = 5 to a
 * chain of n − 2 dofs fixed at its far end, stiff enough (its springs (40 (n − 2)/π)²) that its
 * modes lie above 20 rad/s, C = 0.002 K throughout: the branch from 11 to 17 rad/s overhangs
 * with folds and has the pair's Neimark–Sacker points. NULL on failure. */
static fricreg_hb *gap_chain(size_t n, int H)
{
    double *d = malloc(n * sizeof(double)), *b = malloc(n * sizeof(double));
    double *J = calloc(n, sizeof(double)), *Jn = calloc(n, sizeof(double));
    double *p = calloc(n, sizeof(double)), *ps = calloc(n, sizeof(double));
    double s = (40.0 * (double)(n - 2) / PI) * (40.0 * (double)(n - 2) / PI), kc = 5.0;
    double kt = 40.0, mu = 0.01, n0 = -10.0, kn = 500.0;
    fricreg_hb *hb = NULL;
    if (d && b && J && Jn && p && ps && fricreg_hb_create(n, 1, H, &hb) == FRICREG_OK) {
        for (size_t i = 0; i < n; i++) {
            d[i] = i == 0 ? 140.0 : i == 1 ? 180.0 + kc : i == 2 ? kc + s : 2.0 * s;
            b[i] = i == 0 ? -20.0 : i == 1 ? -kc : -s;
        }
        J[1] = 1.0, Jn[0] = -1.0, p[0] = 2.0, p[1] = 1.0;
        if (tridiagonal_model(hb, n, d, b) != FRICREG_OK ||
            fricreg_hb_set_rayleigh(hb, 0.0, 0.002) != FRICREG_OK ||
            fricreg_hb_set_normal_elements(hb, 1, n, J, Jn, &kt, &mu, &n0, &kn) != FRICREG_OK ||
            fricreg_hb_set_excitation(hb, n, p, ps) != FRICREG_OK) {
            fricreg_hb_free(hb);
            hb = NULL;
        }
    }
    free(d), free(b), free(J), free(Jn), free(p), free(ps);
    return hb;
}

/* The models: the Jenkins chain (0.8 to 1.3 times its first mode) and the gap chain (11 to 17
 * rad/s), each as a driver with its branch's ends and unknowns. */
enum { JENKINS_CHAIN, GAP_CHAIN };

static fricreg_hb *model(int kind, size_t n, int H, double *w0, double *w1, size_t *nq)
{
    if (kind == GAP_CHAIN) {
        *w0 = 11.0, *w1 = 17.0, *nq = 2 * (2 * (size_t)H + 1);
        return gap_chain(n, H);
    }
    double mode1 = 0.0;
    fricreg_hb *hb = chain(n, H, &mode1);
    *w0 = 0.8 * mode1, *w1 = 1.3 * mode1, *nq = NE * (2 * (size_t)H + 1);
    return hb;
}

/* One branch: its points' frequencies, counts of unstable multipliers and largest |μ|. */
struct branch {
    size_t points, bifurcations;
    int method;
    double seconds, *omega, *mu_max, bif_omega[16];
    int *unstable, bif_type[16];
};

static void branch_free(struct branch *b)
{
    free(b->omega), free(b->mu_max), free(b->unstable);
}

/* The branch of the model (kind, n, H) without stability (method < 0) or with the method; 0 on
 * success (b to be freed either way). */
static int run(int kind, size_t n, int H, int method, struct branch *b)
{
    double w0 = 0.0, w1 = 0.0;
    size_t nq = 0;
    fricreg_hb *hb = model(kind, n, H, &w0, &w1, &nq);
    *b = (struct branch){0};
    if (hb == NULL)
        return -1;
    if (method >= 0 && (fricreg_hb_set_stability_method(hb, method) != FRICREG_OK ||
                        fricreg_hb_set_stability(hb, 1) != FRICREG_OK ||
                        fricreg_hb_get_stability_method(hb, &b->method) != FRICREG_OK)) {
        fprintf(stderr, "n = %zu: %s\n", n, fricreg_hb_errmsg(hb));
        fricreg_hb_free(hb);
        return -1;
    }
    double t0 = now();
    int status = fricreg_hb_continue(hb, w0, w1, nq, NULL);
    b->seconds = now() - t0;
    b->points = fricreg_hb_points(hb);
    b->bifurcations = fricreg_hb_bifurcations(hb);
    b->omega = malloc((b->points + 1) * sizeof(double));
    b->mu_max = malloc((b->points + 1) * sizeof(double));
    b->unstable = malloc((b->points + 1) * sizeof(int));
    double *lambda = malloc(4 * n * sizeof(double)), *rms = malloc(n * sizeof(double));
    if (status != FRICREG_OK || !b->omega || !b->mu_max || !b->unstable || !lambda || !rms) {
        fprintf(stderr, "n = %zu, H = %d: %s\n", n, H, fricreg_hb_errmsg(hb));
        status = -1;
    }
    for (size_t k = 0; status == FRICREG_OK && k < b->points; k++) {
        int stable = 0;
        status = fricreg_hb_point(hb, k, &b->omega[k], n, rms);
        if (method < 0 || status != FRICREG_OK)
            continue;
        status = fricreg_hb_point_stability(hb, k, &stable, &b->mu_max[k]);
        if (status == FRICREG_OK)
            status = fricreg_hb_point_exponents(hb, k, 2 * n, lambda);
        b->unstable[k] = 0;
        for (size_t e = 0; status == FRICREG_OK && e < 2 * n; e++)
            b->unstable[k] += lambda[2 * e] * 2.0 * PI / b->omega[k] > 1e-6;
    }
    for (size_t i = 0, at = 0; status == FRICREG_OK && i < b->bifurcations && i < 16; i++)
        status = fricreg_hb_bifurcation(hb, i, &b->bif_type[i], &b->bif_omega[i], &at, n, rms);
    free(lambda), free(rms);
    fricreg_hb_free(hb);
    return status == FRICREG_OK ? 0 : -1;
}

static const char *method_name(int method)
{
    return method == FRICREG_HB_STABILITY_CONDENSED   ? "condensed"
           : method == FRICREG_HB_STABILITY_MONODROMY ? "monodromy"
                                                      : "hill";
}

/* Each bifurcation of the branch b (its type, Ω) and how far the reference's of the same place
 * in the list and type lies, relatively. */
static void bifurcations(const struct branch *b, const struct branch *ref)
{
    static const char *names[4] = {"TP", "BP", "PD", "NS"}; /* FRICREG_HB_TP = 1 ... */
    for (size_t i = 0; i < b->bifurcations && i < 16; i++) {
        int t = b->bif_type[i];
        printf("#   %s at %.9f rad/s", t >= 1 && t <= 4 ? names[t - 1] : "?", b->bif_omega[i]);
        if (i < ref->bifurcations && ref->bif_type[i] == t)
            printf(", %.1e relative to the reference's", b->bif_omega[i] / ref->bif_omega[i] - 1.0);
        printf("\n");
    }
}

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* One row: the costs (the medians over repeats, the two branches run in turn), and the
 * agreement with the reference where it ran. */
static int row(int kind, size_t n, int H, int repeats, size_t max_ref_dofs)
{
    struct branch off = {0}, on = {0}, ref = {0};
    double t_off[16], t_on[16];
    for (int r = 0; r < repeats; r++) {
        if (r > 0)
            branch_free(&off), branch_free(&on);
        if (run(kind, n, H, -1, &off) != 0 ||
            run(kind, n, H, FRICREG_HB_STABILITY_AUTO, &on) != 0) {
            branch_free(&off), branch_free(&on);
            return -1;
        }
        t_off[r] = off.seconds / (double)off.points;
        t_on[r] = on.seconds / (double)on.points;
    }
    qsort(t_off, (size_t)repeats, sizeof(double), by_value);
    qsort(t_on, (size_t)repeats, sizeof(double), by_value);
    double per_off = t_off[repeats / 2], per_on = t_on[repeats / 2];
    printf("%8s %6zu %3d %7zu %12.2f %10s %12.2f %8.2f", kind == GAP_CHAIN ? "gap" : "Jenkins", n,
           H, on.points, 1e3 * per_off, method_name(on.method), 1e3 * per_on, per_on / per_off);
    if (n <= max_ref_dofs && run(kind, n, H, FRICREG_HB_STABILITY_MONODROMY, &ref) == 0) {
        int same = ref.points == on.points;
        for (size_t k = 0; same && k < on.points; k++)
            same = fabs(ref.omega[k] - on.omega[k]) <= 1e-9 * ref.omega[k];
        size_t differ = 0, unstable = 0;
        double worst = 0.0;
        for (size_t k = 0; same && k < on.points; k++) {
            differ += on.unstable[k] != ref.unstable[k];
            unstable += ref.unstable[k] > 0;
            worst = fmax(worst, fabs(on.mu_max[k] - ref.mu_max[k]));
        }
        double per_ref = ref.seconds / (double)ref.points;
        if (!same) {
            printf(" %10.2f   the branches' points differ (%zu, %zu)\n", per_ref / per_off,
                   on.points, ref.points);
        } else {
            printf(" %10.2f %8zu %8zu %10.1e %4zu/%zu\n", per_ref / per_off, unstable, differ,
                   worst, on.bifurcations, ref.bifurcations);
            bifurcations(&on, &ref);
        }
    } else {
        printf(" %10s %8s %8s %10s %4zu\n", "-", "-", "-", "-", on.bifurcations);
    }
    branch_free(&off), branch_free(&on), branch_free(&ref);
    return 0;
}

int main(int argc, char **argv)
{
    size_t max_dofs = argc > 1 ? (size_t)atol(argv[1]) : 1000;
    size_t max_ref_dofs = argc > 2 ? (size_t)atol(argv[2]) : 300;
    int repeats = argc > 3 ? atoi(argv[3]) : 3;
    const char *chains = argc > 4 ? argv[4] : "all";
    int jenkins = strcmp(chains, "gap") != 0, gap = strcmp(chains, "jenkins") != 0;
    if (repeats < 1 || repeats > 16) {
        fprintf(stderr, "repeats: 1 to 16\n");
        return EXIT_FAILURE;
    }
    const size_t sizes[3] = {60, 300, 1000};
    const int harmonics[2] = {3, 7};
    printf("# Stability by size (bench/hb_stability_size.c): ms per stored point (median of %d),"
           "\n# ratios to without; the reference the whole model's monodromy\n",
           repeats);
    printf("%8s %6s %3s %7s %12s %10s %12s %8s %10s %8s %8s %10s %6s\n", "chain", "dofs", "H",
           "points", "without", "default", "default", "ratio", "ref ratio", "unstable", "differ",
           "|dmu_max|", "bifs");
    for (int i = 0; i < 3; i++)
        for (int h = 0; h < 2 && jenkins && sizes[i] <= max_dofs; h++)
            if (row(JENKINS_CHAIN, sizes[i], harmonics[h], repeats, max_ref_dofs) != 0)
                return EXIT_FAILURE;
    for (int i = 0; i < 2; i++) /* its HB at H = 7 */
        if (gap && sizes[i] <= max_dofs && row(GAP_CHAIN, sizes[i], 7, repeats, max_ref_dofs) != 0)
            return EXIT_FAILURE;
    return EXIT_SUCCESS;
}
