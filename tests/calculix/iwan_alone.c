/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * iwan_alone.c — the CalculiX tier's Iwan reference (test calculix_iwan, iwan.sh): fricreg's
 * element kernel driven alone, iwan_3d with the sliders of the deck's laws file (frccx.c's
 * default c_s), on the history that the patched ccx printed for each contact node (its relative
 * tangential displacement t and pressure p, ccx's 7 digits), and the hysteresis loop's
 * dissipation, sum over the increments of
 * (f_k + f_{k-1})/2 . (t_k - t_{k-1}), from ccx's printed shear stresses against the kernel's.
 * Built by the tier (cmake/calculix.cmake) and linked with fricreg only, never with ccx.
 *
 * The kernel works per unit area, as ccx prints: k_s = kt/ns and phi_s = c_s mu |p|,
 * c_s = 2 s/(ns (ns + 1)), where ccx's hook (frccx.c) has k_s = xk/ns = kt A/ns and phi_s =
 * c_s mu |F_n| = c_s mu A |p| (A the node's area; the return mapping is homogeneous in them).
 *
 * Usage: iwan_alone HISTORY KT MU NS TOL LOOP_OUT
 *   HISTORY   lines "node increment gap t1 t2 p tau1 tau2" (iwan.sh's awk of the .dat);
 *             t = (t1, t2, 0): the master is flat in z, so ccx's t1, t2 are x, y.
 *   LOOP_OUT  the loops for gnuplot: per node "t1 tau1_ccx tau1_kernel", nodes 2 blank lines apart
 * Checks, each node and their sum: the dissipations agree to TOL relative, the stresses to TOL of
 * their largest; the deck passes through microslip and macroslip and reverses; and the check is
 * not blind: a history off by 1e-5, one slider (Coulomb) in place of ns, and a bound frozen at
 * the last pressure (not following ccx's normal force) each move the dissipation by more than
 * TOL.
 */
#include <fricreg_element.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_NODES 64
#define MAX_SLIDERS 16

typedef struct {
    int node;
    size_t n, cap;
    double *t;   /* n x 2 */
    double *p;   /* n */
    double *tau; /* n x 2 */
} history;

typedef struct {
    double scale_t; /* t multiplied by this */
    int frozen;     /* the bound at the last increment's p, not following it */
    size_t ns;      /* sliders */
} variant;

static int fails = 0;

static void check(int ok, const char *what)
{
    if (!ok) {
        printf("FAIL: %s\n", what);
        ++fails;
    }
}

/* The kernel alone along h: its dissipation, its stresses (tau_out, or NULL) and the number of
   increments in microslip (some sliders slide), macroslip (all slide). Returns 0, or -1 when
   the kernel refuses (message printed). */
static int drive(const history *h, double kt, double mu, variant v, double *w_out, double *tau_out,
                 size_t *micro, size_t *macro)
{
    const fricreg_element_type *T = fricreg_element_sliders(fricreg_element_lookup("iwan_3d"),
                                                            v.ns);
    double params[2 * MAX_SLIDERS], w[3 * MAX_SLIDERS], wn[3 * MAX_SLIDERS];
    double u[3], f[3], fprev[2] = {0.0, 0.0}, uprev[2] = {0.0, 0.0}, diss = 0.0;
    size_t k, s;
    if (T == NULL || v.ns > MAX_SLIDERS) {
        printf("FAIL: no iwan_3d with %zu sliders\n", v.ns);
        return -1;
    }
    memset(w, 0, sizeof w);
    if (micro)
        *micro = 0;
    if (macro)
        *macro = 0;
    for (k = 0; k < h->n; ++k) {
        size_t sliding = 0;
        double p = h->p[v.frozen ? h->n - 1 : k];
        int st;
        u[0] = h->t[2 * k] * v.scale_t;
        u[1] = h->t[2 * k + 1] * v.scale_t;
        u[2] = 0.0;
        for (s = 0; s < v.ns; ++s) {
            params[s] = kt / (double)v.ns;
            params[v.ns + s] = mu * fabs(p) * (2.0 * (double)(s + 1) / (double)(v.ns * (v.ns + 1)));
        }
        st = fricreg_element_eval(T, params, w, u, f, NULL, NULL, wn);
        if (st != FRICREG_OK) {
            char msg[256];
            fricreg_element_explain(T, params, w, u, msg, sizeof msg);
            printf("FAIL: node %d, increment %zu: %s\n", h->node, k + 1, msg);
            return -1;
        }
        for (s = 0; s < v.ns; ++s)
            if (wn[3 * s] != w[3 * s] || wn[3 * s + 1] != w[3 * s + 1] ||
                wn[3 * s + 2] != w[3 * s + 2])
                ++sliding;
        if (micro && sliding > 0 && sliding < v.ns)
            ++*micro;
        if (macro && sliding == v.ns)
            ++*macro;
        memcpy(w, wn, sizeof(double) * 3 * v.ns);
        diss += 0.5 *
                ((f[0] + fprev[0]) * (u[0] - uprev[0]) + (f[1] + fprev[1]) * (u[1] - uprev[1]));
        fprev[0] = f[0];
        fprev[1] = f[1];
        uprev[0] = u[0];
        uprev[1] = u[1];
        if (tau_out) {
            tau_out[2 * k] = f[0];
            tau_out[2 * k + 1] = f[1];
        }
    }
    *w_out = diss;
    return 0;
}

/* ccx's own dissipation from its printed stresses, by the same sum */
static double ccx_dissipation(const history *h)
{
    double diss = 0.0, fp[2] = {0.0, 0.0}, up[2] = {0.0, 0.0};
    size_t k;
    for (k = 0; k < h->n; ++k) {
        const double *t = h->t + 2 * k, *f = h->tau + 2 * k;
        diss += 0.5 * ((f[0] + fp[0]) * (t[0] - up[0]) + (f[1] + fp[1]) * (t[1] - up[1]));
        fp[0] = f[0];
        fp[1] = f[1];
        up[0] = t[0];
        up[1] = t[1];
    }
    return diss;
}

/* reversals of t1's direction, counting moves above 1e-12 of its range */
static size_t reversals(const history *h)
{
    double lo = h->t[0], hi = h->t[0], last = 0.0;
    size_t k, count = 0;
    for (k = 1; k < h->n; ++k) {
        lo = fmin(lo, h->t[2 * k]);
        hi = fmax(hi, h->t[2 * k]);
    }
    for (k = 1; k < h->n; ++k) {
        double d = h->t[2 * k] - h->t[2 * (k - 1)];
        if (fabs(d) <= 1e-12 * (hi - lo))
            continue;
        if (last != 0.0 && (d > 0) != (last > 0))
            ++count;
        last = d;
    }
    return count;
}

static int push(history *h, const double t[2], double p, const double tau[2])
{
    if (h->n == h->cap) {
        size_t cap = h->cap ? 2 * h->cap : 256;
        double *a = realloc(h->t, 2 * cap * sizeof *a), *b, *c;
        if (!a)
            return -1;
        h->t = a;
        if (!(b = realloc(h->p, cap * sizeof *b)))
            return -1;
        h->p = b;
        if (!(c = realloc(h->tau, 2 * cap * sizeof *c)))
            return -1;
        h->tau = c;
        h->cap = cap;
    }
    h->t[2 * h->n] = t[0];
    h->t[2 * h->n + 1] = t[1];
    h->p[h->n] = p;
    h->tau[2 * h->n] = tau[0];
    h->tau[2 * h->n + 1] = tau[1];
    ++h->n;
    return 0;
}

static double rel(double a, double ref)
{
    return fabs(a - ref) / fabs(ref);
}

int main(int argc, char **argv)
{
    history hs[MAX_NODES];
    size_t nn = 0, i, k;
    double kt, mu, tol, total_ccx = 0.0, total_kernel = 0.0;
    double total_off = 0.0, total_jenkins = 0.0, total_frozen = 0.0;
    size_t ns;
    char line[512];
    FILE *in, *out;
    if (argc != 7) {
        fprintf(stderr, "usage: iwan_alone HISTORY KT MU NS TOL LOOP_OUT\n");
        return 2;
    }
    kt = atof(argv[2]);
    mu = atof(argv[3]);
    ns = (size_t)atoi(argv[4]);
    tol = atof(argv[5]);
    if (!(in = fopen(argv[1], "r"))) {
        printf("FAIL: cannot read %s\n", argv[1]);
        return 1;
    }
    memset(hs, 0, sizeof hs);
    while (fgets(line, sizeof line, in)) {
        int node;
        long inc;
        double gap, t[2], p, tau[2];
        if (sscanf(line, "%d %ld %lf %lf %lf %lf %lf %lf", &node, &inc, &gap, &t[0], &t[1], &p,
                   &tau[0], &tau[1]) != 8) {
            printf("FAIL: a history line of %s is not 8 numbers: %s", argv[1], line);
            return 1;
        }
        for (i = 0; i < nn && hs[i].node != node; ++i) {
        }
        if (i == nn) {
            if (nn == MAX_NODES) {
                printf("FAIL: more than %d contact nodes\n", MAX_NODES);
                return 1;
            }
            hs[nn++].node = node;
        }
        if ((size_t)inc != hs[i].n + 1) {
            printf("FAIL: node %d misses increment %zu (out of contact?): the kernel alone would "
                   "need ccx's state there\n",
                   node, hs[i].n + 1);
            return 1;
        }
        if (push(&hs[i], t, p, tau)) {
            printf("FAIL: out of memory\n");
            return 1;
        }
    }
    fclose(in);
    if (nn == 0) {
        printf("FAIL: no contact history in %s\n", argv[1]);
        return 1;
    }
    if (!(out = fopen(argv[6], "w"))) {
        printf("FAIL: cannot write %s\n", argv[6]);
        return 1;
    }
    for (i = 0; i < nn; ++i) {
        const history *h = &hs[i];
        variant base = {1.0, 0, ns}, off = base, jen = base, frozen = base;
        double wc = ccx_dissipation(h), wk, woff, wjen, wfroz, taumax = 0.0, dtau = 0.0;
        double pmin = h->p[0], pmax = h->p[0];
        double *tau = malloc(2 * h->n * sizeof *tau);
        size_t micro, macro, rev = reversals(h);
        char what[200];
        off.scale_t = 1.0 + 1e-5;
        jen.ns = 1;
        frozen.frozen = 1;
        if (!tau || drive(h, kt, mu, base, &wk, tau, &micro, &macro) ||
            drive(h, kt, mu, off, &woff, NULL, NULL, NULL) ||
            drive(h, kt, mu, jen, &wjen, NULL, NULL, NULL) ||
            drive(h, kt, mu, frozen, &wfroz, NULL, NULL, NULL))
            return 1;
        for (k = 0; k < h->n; ++k) {
            taumax = fmax(taumax, hypot(h->tau[2 * k], h->tau[2 * k + 1]));
            dtau = fmax(dtau,
                        hypot(h->tau[2 * k] - tau[2 * k], h->tau[2 * k + 1] - tau[2 * k + 1]));
            pmin = fmin(pmin, h->p[k]);
            pmax = fmax(pmax, h->p[k]);
            fprintf(out, "%.17g %.17g %.17g\n", h->t[2 * k], h->tau[2 * k], tau[2 * k]);
        }
        fprintf(out, "\n\n");
        printf("node %d: %zu increments, p %.6g .. %.6g, %zu in microslip, %zu in macroslip, %zu "
               "reversals\n",
               h->node, h->n, pmin, pmax, micro, macro, rev);
        printf("node %d: dissipation ccx %.12e, kernel alone %.12e, relative difference %.3e; "
               "stresses within %.3e of their largest\n",
               h->node, wc, wk, rel(wc, wk), dtau / taumax);
        printf("node %d: the kernel alone with t off by 1e-5: %.3e; one slider (Coulomb): %.3e; "
               "the bound frozen at the last p: %.3e\n",
               h->node, rel(woff, wk), rel(wjen, wk), rel(wfroz, wk));
        snprintf(what, sizeof what, "node %d: the dissipations differ by more than %g", h->node,
                 tol);
        check(rel(wc, wk) <= tol, what);
        snprintf(what, sizeof what, "node %d: the stresses differ by more than %g", h->node, tol);
        check(dtau <= tol * taumax, what);
        snprintf(what, sizeof what,
                 "node %d: the loop has no microslip, macroslip or two reversals", h->node);
        check(micro > 0 && macro > 0 && rev >= 2, what);
        snprintf(what, sizeof what,
                 "node %d: the comparison is blind to a history off by 1e-5, to Coulomb in Iwan's "
                 "place or to a frozen bound",
                 h->node);
        check(rel(woff, wk) > tol && rel(wjen, wk) > tol && rel(wfroz, wk) > tol, what);
        total_ccx += wc;
        total_kernel += wk;
        total_off += woff;
        total_jenkins += wjen;
        total_frozen += wfroz;
        free(tau);
    }
    fclose(out);
    printf("all %zu nodes: dissipation ccx %.12e, kernel alone %.12e, relative difference %.3e "
           "(tolerance %g)\n",
           nn, total_ccx, total_kernel, rel(total_ccx, total_kernel), tol);
    printf("all %zu nodes, the kernel alone with t off by 1e-5: %.3e; one slider: %.3e; frozen "
           "bound: %.3e\n",
           nn, rel(total_off, total_kernel), rel(total_jenkins, total_kernel),
           rel(total_frozen, total_kernel));
    check(rel(total_ccx, total_kernel) <= tol, "the total dissipations differ");
    for (i = 0; i < nn; ++i) {
        free(hs[i].t);
        free(hs[i].p);
        free(hs[i].tau);
    }
    printf("%d passed, %d failed\n", fails ? 0 : 1, fails ? 1 : 0);
    return fails ? 1 : 0;
}
