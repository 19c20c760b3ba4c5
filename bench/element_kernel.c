/* SPDX-License-Identifier: GPL-3.0-or-later */
/* element_kernel.c — fricreg-bench-element-kernel [count]: the element types' kernel
 * (fricreg_element_eval, fricreg_element_eval_batch) against hand-written return mappings.
 *
 * Three cases, each over NPOINTS points with their own parameters (a host's integration
 * points), about half of them sticking and half slipping, fixed seed:
 *   jenkins     the 1-D return mapping and its tangent;
 *   contact_3d  the radial return in the contact plane under the normal law of lift-off (a
 *               few points open), the 3x3 tangent;
 *   iwan        NS sliders of one displacement, summed in order.
 * The hand loops are what a host's friction routine would write: no validation, the same
 * operations as the library's (hypot for the norms, the same sums), so that their results
 * agree bit for bit; the program checks they do before timing. dfdu is asked for, dfdp not.
 * Each figure is the median of REPEATS interleaved timings, in ns per point; the ratios are
 * to the hand loop of the same case. "count CASE ITEM" runs one item alone, for instruction
 * counts (bench/element_kernel.sh: callgrind's total less that of ITEM none). */
#define _POSIX_C_SOURCE 199309L /* clock_gettime */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <fricreg_element.h>

enum { NPOINTS = 1000, NS = 10, REPEATS = 21, SWEEPS = 200, NCASES = 3, COUNT_SWEEPS = 10 };

#if defined(__GNUC__)
#define NOINLINE __attribute__((noinline))
#else
#define NOINLINE
#endif

static double cpu_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median(double *x, size_t n)
{
    qsort(x, n, sizeof *x, cmp_double);
    return x[n / 2];
}

static uint64_t rng_state = 0x2385u;
static double uniform(double lo, double hi)
{
    rng_state ^= rng_state << 13;
    rng_state ^= rng_state >> 7;
    rng_state ^= rng_state << 17;
    return lo + (hi - lo) * (double)(rng_state >> 11) * 0x1p-53;
}

/* One case's inputs and outputs, point after point (fricreg_element_eval_batch's layout). */
struct element_case {
    const char *name;
    const fricreg_element_type *type;
    size_t dim, np, nstate;
    double *p, *w, *u;     /* inputs */
    double *f, *t, *wn;    /* the hand loop's outputs */
    double *lf, *lt, *lwn; /* the library's */
};

/* ---- The hand-written loops ---------------------------------------------------------------- */

static NOINLINE void hand_jenkins(size_t n, const double *p, const double *w, const double *u,
                                  double *f, double *t, double *wn)
{
    for (size_t i = 0; i < n; i++) {
        double kt = p[2 * i], b = p[2 * i + 1], d = u[i] - w[i], r = fabs(d);
        if (kt * r <= b) {
            f[i] = kt * d;
            t[i] = kt;
            wn[i] = w[i];
        } else {
            f[i] = b * (d / r);
            t[i] = 0.0;
            wn[i] = u[i] - f[i] / kt;
        }
    }
}

/* kt, mu, kn, n0, gap; w[2]; u = (u_t[2], g); f = (f_t[2], N); t[3x3]. */
static NOINLINE void hand_contact_3d(size_t n, const double *p, const double *w, const double *u,
                                     double *f, double *t, double *wn)
{
    for (size_t i = 0; i < n; i++) {
        const double *pi = p + 5 * i, *wi = w + 2 * i, *ui = u + 3 * i;
        double *fi = f + 3 * i, *ti = t + 9 * i, *wni = wn + 2 * i;
        double kt = pi[0], mu = pi[1], kn = pi[2], gg = ui[2] - pi[4], nc = pi[3] + kn * gg;
        if (nc < 0.0) {
            wni[0] = ui[0];
            wni[1] = ui[1];
            fi[0] = fi[1] = fi[2] = 0.0;
            for (int a = 0; a < 9; a++)
                ti[a] = 0.0;
            continue;
        }
        double N = fmax(0.0, nc), b = mu * N, d0 = ui[0] - wi[0], d1 = ui[1] - wi[1];
        double r = hypot(d0, d1);
        fi[2] = N;
        ti[6] = ti[7] = 0.0;
        ti[8] = kn;
        if (kt * r <= b) {
            fi[0] = kt * d0;
            fi[1] = kt * d1;
            wni[0] = wi[0];
            wni[1] = wi[1];
            ti[0] = ti[4] = kt;
            ti[1] = ti[3] = ti[2] = ti[5] = 0.0;
        } else {
            double n0 = d0 / r, n1 = d1 / r, s = b / r, dbdg = mu * kn;
            fi[0] = b * n0;
            fi[1] = b * n1;
            wni[0] = ui[0] - fi[0] / kt;
            wni[1] = ui[1] - fi[1] / kt;
            ti[0] = s * (1.0 - n0 * n0);
            ti[1] = s * (0.0 - n0 * n1);
            ti[3] = s * (0.0 - n1 * n0);
            ti[4] = s * (1.0 - n1 * n1);
            ti[2] = dbdg * n0;
            ti[5] = dbdg * n1;
        }
    }
}

/* NS sliders k[NS], phi[NS] on one displacement; f and t summed in the sliders' order. */
static NOINLINE void hand_iwan(size_t n, const double *p, const double *w, const double *u,
                               double *f, double *t, double *wn)
{
    for (size_t i = 0; i < n; i++) {
        const double *k = p + 2 * NS * i, *phi = k + NS, *wi = w + NS * i;
        double ui = u[i], fs = 0.0, ts = 0.0;
        for (size_t s = 0; s < NS; s++) {
            double d = ui - wi[s], r = fabs(d);
            if (k[s] * r <= phi[s]) {
                fs += k[s] * d;
                ts += k[s];
                wn[NS * i + s] = wi[s];
            } else {
                double fsl = phi[s] * (d / r);
                fs += fsl;
                ts += 0.0;
                wn[NS * i + s] = ui - fsl / k[s];
            }
        }
        f[i] = fs;
        t[i] = ts;
    }
}

/* ---- The library ----------------------------------------------------------------------------- */

static NOINLINE int lib_eval(const struct element_case *c)
{
    int status = FRICREG_OK;
    for (size_t i = 0; i < NPOINTS && status == FRICREG_OK; i++)
        status = fricreg_element_eval(c->type, c->p + c->np * i, c->w + c->nstate * i,
                                      c->u + c->dim * i, c->lf + c->dim * i,
                                      c->lt + c->dim * c->dim * i, NULL, c->lwn + c->nstate * i);
    return status;
}

static NOINLINE int lib_batch(const struct element_case *c)
{
    return fricreg_element_eval_batch(c->type, NPOINTS, c->p, c->np, c->w, c->u, c->lf, c->lt, NULL,
                                      c->lwn, NULL);
}

static NOINLINE void hand(const struct element_case *c, int which)
{
    if (which == 0)
        hand_jenkins(NPOINTS, c->p, c->w, c->u, c->f, c->t, c->wn);
    else if (which == 1)
        hand_contact_3d(NPOINTS, c->p, c->w, c->u, c->f, c->t, c->wn);
    else
        hand_iwan(NPOINTS, c->p, c->w, c->u, c->f, c->t, c->wn);
}

/* ---- The inputs -------------------------------------------------------------------------------- */

static double *array(size_t n)
{
    double *a = calloc(n, sizeof *a);
    if (a == NULL) {
        fprintf(stderr, "fricreg-bench-element-kernel: out of memory\n");
        exit(1);
    }
    return a;
}

static void make_case(struct element_case *c, const char *name, size_t ns)
{
    c->name = name;
    c->type = fricreg_element_sliders(fricreg_element_lookup(name), ns);
    c->dim = (size_t)fricreg_element_dim(c->type);
    c->np = fricreg_element_nparams(c->type);
    c->nstate = fricreg_element_nstate(c->type);
    c->p = array(c->np * NPOINTS);
    c->w = array(c->nstate * NPOINTS);
    c->u = array(c->dim * NPOINTS);
    c->f = array(c->dim * NPOINTS);
    c->lf = array(c->dim * NPOINTS);
    c->t = array(c->dim * c->dim * NPOINTS);
    c->lt = array(c->dim * c->dim * NPOINTS);
    c->wn = array(c->nstate * NPOINTS);
    c->lwn = array(c->nstate * NPOINTS);
    for (size_t i = 0; i < NPOINTS; i++) {
        double *p = c->p + c->np * i, *w = c->w + c->nstate * i, *u = c->u + c->dim * i;
        /* slip starts at |u - w| = b / k, about 0.01 (N about 1 for the contact): about half
         * stick; the Iwan sliders' b / k spread from 0.002 to 0.04 */
        for (size_t s = 0; s < ns; s++) {
            p[s] = uniform(80.0, 120.0);
            p[ns + s] = p[s] * (ns > 1 ? uniform(0.002, 0.04) : uniform(0.005, 0.015));
        }
        for (size_t j = 0; j < c->nstate; j++)
            w[j] = uniform(-0.01, 0.01);
        for (size_t a = 0; a < c->dim; a++)
            u[a] = (a < c->nstate ? w[a] : 0.0) + uniform(-0.02, 0.02);
        if (strcmp(name, "contact_3d") == 0) { /* kt, mu, kn, n0, gap = 0; 1 in 8 open */
            p[2] = 1000.0;
            p[3] = 1.0;
            p[4] = 0.0;
            u[2] = uniform(-0.0013, 0.001);
        }
    }
}

/* The library's results equal the hand loop's (0 when they all do). */
static size_t mismatches(const struct element_case *c)
{
    size_t bad = 0;
    for (size_t i = 0; i < c->dim * NPOINTS; i++)
        bad += c->f[i] != c->lf[i];
    for (size_t i = 0; i < c->dim * c->dim * NPOINTS; i++)
        bad += c->t[i] != c->lt[i];
    for (size_t i = 0; i < c->nstate * NPOINTS; i++)
        bad += c->wn[i] != c->lwn[i];
    return bad;
}

static int check_case(struct element_case *c, int which)
{
    hand(c, which);
    for (int pass = 0; pass < 2; pass++) {
        memset(c->lf, 0xff, c->dim * NPOINTS * sizeof *c->lf);
        int status = pass == 0 ? lib_eval(c) : lib_batch(c);
        size_t bad = mismatches(c);
        if (status != FRICREG_OK || bad != 0) {
            fprintf(stderr, "%s: %s: status %d, %zu numbers differ from the hand loop\n", c->name,
                    pass == 0 ? "eval" : "eval_batch", status, bad);
            return 1;
        }
    }
    return 0;
}

/* "count CASE ITEM": ITEM (hand, eval, batch or none) of case CASE (0, 1, 2) COUNT_SWEEPS
 * times, for an instruction count: (count(ITEM) - count(none)) / (COUNT_SWEEPS NPOINTS). */
static int count(struct element_case *c, int k, const char *item)
{
    for (int sweep = 0; sweep < COUNT_SWEEPS; sweep++) {
        if (strcmp(item, "hand") == 0)
            hand(&c[k], k);
        else if (strcmp(item, "eval") == 0)
            lib_eval(&c[k]);
        else if (strcmp(item, "batch") == 0)
            lib_batch(&c[k]);
        else if (strcmp(item, "none") != 0)
            return 1;
    }
    return 0;
}

int main(int argc, char **argv)
{
    struct element_case c[NCASES];
    make_case(&c[0], "jenkins", 1);
    make_case(&c[1], "contact_3d", 1);
    make_case(&c[2], "iwan", NS);
    for (int k = 0; k < NCASES; k++)
        if (check_case(&c[k], k) != 0)
            return 1;
    if (argc == 4 && strcmp(argv[1], "count") == 0)
        return count(c, atoi(argv[2]) % NCASES, argv[3]);
    double times[NCASES][3][REPEATS];
    for (int r = 0; r < REPEATS; r++)
        for (int k = 0; k < NCASES; k++)
            for (int item = 0; item < 3; item++) {
                double t0 = cpu_seconds();
                for (int sweep = 0; sweep < SWEEPS; sweep++) {
                    if (item == 0)
                        hand(&c[k], k);
                    else if (item == 1)
                        lib_eval(&c[k]);
                    else
                        lib_batch(&c[k]);
                }
                times[k][item][r] = (cpu_seconds() - t0) * 1e9 / (SWEEPS * (double)NPOINTS);
            }
    printf("%-12s %10s %10s %10s %8s %8s   (ns per point, median of %d; iwan: %d sliders)\n",
           "case", "hand", "eval", "batch", "eval/h", "batch/h", REPEATS, NS);
    for (int k = 0; k < NCASES; k++) {
        double h = median(times[k][0], REPEATS), e = median(times[k][1], REPEATS),
               b = median(times[k][2], REPEATS);
        printf("%-12s %10.2f %10.2f %10.2f %8.2f %8.2f\n", c[k].name, h, e, b, e / h, b / h);
    }
    return 0;
}
