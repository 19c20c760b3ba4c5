/* SPDX-License-Identifier: GPL-3.0-or-later */
/* element_kernel.c — fricreg-bench-element-kernel [count CASE ITEM]: the element types' kernel
 * (fricreg_element_eval, fricreg_element_eval_batch) against hand-written return mappings.
 *
 * Three cases, each over a set of points with their own parameters (a host's integration
 * points), about half of them sticking and half slipping, fixed seed:
 *   jenkins     the 1-D return mapping and its tangent;
 *   contact_3d  the radial return in the contact plane under the normal law of lift-off (a
 *               few points open), the 3x3 tangent;
 *   iwan        NS sliders of one displacement, summed in order, in an Iwan element's state:
 *               slip displacements b/k spread evenly from 0.002 to 0.04 in the sliders' order,
 *               all offsets at the point's last reversal, so that the sliders weaker than the
 *               excursion slip and the others stick (a prefix of the sliders, as in a joint).
 *               Independent random offsets per slider, as until 1.9, make the stick/slip
 *               branches a pattern of 10 000 that the branch predictor learns over the sweeps,
 *               or not, by where the code lands: 15 against 38 ns a call for the same
 *               instructions, from one change elsewhere in the library.
 * The hand routines are what a host's friction routine would write: no validation, the same
 * operations as the library's (hypot for the norms, the same sums), so that their results
 * agree bit for bit; the program checks they do before timing. dfdu is asked for, dfdp not.
 * Each library item is timed against the hand item of the same shape:
 *   batch          against the hand loop (the routine inlined into a loop over the points);
 *   batch, shared  the same with every point on point 0's parameters (params_stride 0);
 *   eval           against the hand routine called per point through a non-inlined call,
 *                  as a host calls its friction routine at each point.
 * Each figure is the median of REPEATS interleaved timings, in ns per point, on two sets: 1000
 * points, swept again and again, whose every stick/slip branch the processor learns (the hand
 * loop's ~3 cycles a point), and a host's mesh of 65 536 points, which no branch predictor
 * holds, so that the branches cost what they cost in a host (and the memory what it costs:
 * the mesh's arrays are 2 to 30 MB). "count CASE ITEM" runs one item (its name in item_names,
 * or none) alone on the 1000 points, for instruction counts (bench/element_kernel.sh:
 * callgrind's total less that of ITEM none). */
#define _POSIX_C_SOURCE 199309L /* clock_gettime */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <fricreg_element.h>

/* The point sets timed: 1000 points, whose stick/slip branches the processor learns point by
 * point over the sweeps, and a host's mesh of 65 536, which no branch predictor holds; each
 * timing evaluates WORK points (sweeps of a set). */
enum { NSETS = 2, WORK = 200000, NS = 10, REPEATS = 21, NCASES = 3, COUNT_SWEEPS = 10 };
static const size_t set_points[NSETS] = {1000, 65536};

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
    size_t npoints, dim, np, nstate;
    double *p, *w, *u;     /* inputs */
    double *f, *t, *wn;    /* the hand loop's outputs */
    double *lf, *lt, *lwn; /* the library's */
};

/* ---- The hand-written return mappings ------------------------------------------------------ */

/* One point each, inline: the loops below inline them (the hand loop), and hand_point calls
 * them through a non-inlined routine per point, as a host calls its own friction routine. */

/* kt, b; w; u; f; t; wn. */
static inline void hand_jenkins(const double *p, const double *w, const double *u, double *f,
                                double *t, double *wn)
{
    double kt = p[0], b = p[1], d = u[0] - w[0], r = fabs(d);
    if (kt * r <= b) {
        f[0] = kt * d;
        t[0] = kt;
        wn[0] = w[0];
    } else {
        f[0] = b * (d / r);
        t[0] = 0.0;
        wn[0] = u[0] - f[0] / kt;
    }
}

/* kt, mu, kn, n0, gap; w[2]; u = (u_t[2], g); f = (f_t[2], N); t[3x3]; wn[2]. */
static inline void hand_contact_3d(const double *p, const double *w, const double *u, double *f,
                                   double *t, double *wn)
{
    double kt = p[0], mu = p[1], kn = p[2], gg = u[2] - p[4], nc = p[3] + kn * gg;
    if (nc < 0.0) {
        wn[0] = u[0];
        wn[1] = u[1];
        f[0] = f[1] = f[2] = 0.0;
        for (int a = 0; a < 9; a++)
            t[a] = 0.0;
        return;
    }
    double N = 0.0 > nc ? 0.0 : nc, b = mu * N, d0 = u[0] - w[0], d1 = u[1] - w[1];
    double r = hypot(d0, d1);
    f[2] = N;
    t[6] = t[7] = 0.0;
    t[8] = kn;
    if (kt * r <= b) {
        f[0] = kt * d0;
        f[1] = kt * d1;
        wn[0] = w[0];
        wn[1] = w[1];
        t[0] = t[4] = kt;
        t[1] = t[3] = t[2] = t[5] = 0.0;
    } else {
        double n0 = d0 / r, n1 = d1 / r, s = b / r, dbdg = mu * kn;
        f[0] = b * n0;
        f[1] = b * n1;
        wn[0] = u[0] - f[0] / kt;
        wn[1] = u[1] - f[1] / kt;
        t[0] = s * (1.0 - n0 * n0);
        t[1] = s * (0.0 - n0 * n1);
        t[3] = s * (0.0 - n1 * n0);
        t[4] = s * (1.0 - n1 * n1);
        t[2] = dbdg * n0;
        t[5] = dbdg * n1;
    }
}

/* NS sliders k[NS], phi[NS] on one displacement; f and t summed in the sliders' order. */
static inline void hand_iwan(const double *p, const double *w, const double *u, double *f,
                             double *t, double *wn)
{
    const double *k = p, *phi = p + NS;
    double ui = u[0], fs = 0.0, ts = 0.0;
    for (size_t s = 0; s < NS; s++) {
        double d = ui - w[s], r = fabs(d);
        if (k[s] * r <= phi[s]) {
            fs += k[s] * d;
            ts += k[s];
            wn[s] = w[s];
        } else {
            double fsl = phi[s] * (d / r);
            fs += fsl;
            ts += 0.0;
            wn[s] = ui - fsl / k[s];
        }
    }
    f[0] = fs;
    t[0] = ts;
}

typedef void hand_fn(const double *p, const double *w, const double *u, double *f, double *t,
                     double *wn);

/* Case c's points through one, inlined (the loop of each case is its own function). */
#define HAND_LOOP(one)                                                                             \
    static NOINLINE void loop_##one(const struct element_case *c, size_t p_stride)                 \
    {                                                                                              \
        for (size_t i = 0; i < c->npoints; i++)                                                    \
            one(c->p + p_stride * i, c->w + c->nstate * i, c->u + c->dim * i, c->f + c->dim * i,   \
                c->t + c->dim * c->dim * i, c->wn + c->nstate * i);                                \
    }                                                                                              \
    static NOINLINE void point_##one(const double *p, const double *w, const double *u, double *f, \
                                     double *t, double *wn)                                        \
    {                                                                                              \
        one(p, w, u, f, t, wn);                                                                    \
    }
HAND_LOOP(hand_jenkins)
HAND_LOOP(hand_contact_3d)
HAND_LOOP(hand_iwan)

/* The hand loop of case which (0, 1, 2); p_stride 0: every point on the first point's
 * parameters. */
static void hand(const struct element_case *c, int which, size_t p_stride)
{
    if (which == 0)
        loop_hand_jenkins(c, p_stride);
    else if (which == 1)
        loop_hand_contact_3d(c, p_stride);
    else
        loop_hand_iwan(c, p_stride);
}

/* The hand routine called per point, as lib_eval calls fricreg_element_eval. */
static NOINLINE void hand_point(const struct element_case *c, int which)
{
    hand_fn *one = which == 0   ? point_hand_jenkins
                   : which == 1 ? point_hand_contact_3d
                                : point_hand_iwan;
    for (size_t i = 0; i < c->npoints; i++)
        one(c->p + c->np * i, c->w + c->nstate * i, c->u + c->dim * i, c->f + c->dim * i,
            c->t + c->dim * c->dim * i, c->wn + c->nstate * i);
}

/* ---- The library ----------------------------------------------------------------------------- */

static NOINLINE int lib_eval(const struct element_case *c)
{
    int status = FRICREG_OK;
    for (size_t i = 0; i < c->npoints && status == FRICREG_OK; i++)
        status = fricreg_element_eval(c->type, c->p + c->np * i, c->w + c->nstate * i,
                                      c->u + c->dim * i, c->lf + c->dim * i,
                                      c->lt + c->dim * c->dim * i, NULL, c->lwn + c->nstate * i);
    return status;
}

/* p_stride 0: every point on the first point's parameters, checked once. */
static NOINLINE int lib_batch(const struct element_case *c, size_t p_stride)
{
    return fricreg_element_eval_batch(c->type, c->npoints, c->p, p_stride, c->w, c->u, c->lf, c->lt,
                                      NULL, c->lwn, NULL);
}

/* The items timed, each over a case's points: the hand loop and fricreg_element_eval_batch
 * with parameters per point and shared, the hand routine per point and fricreg_element_eval. */
enum item { HAND_LOOP, BATCH, HAND_SHARED, BATCH_SHARED, HAND_POINT, EVAL, NITEMS };
static const char *const item_names[NITEMS] = {"hand",         "batch",      "hand_shared",
                                               "batch_shared", "hand_point", "eval"};

/* Item `item` of case which; its status (the hand items' is FRICREG_OK). */
static int run_item(const struct element_case *c, int which, int item)
{
    switch (item) {
    case HAND_LOOP: hand(c, which, c->np); return FRICREG_OK;
    case BATCH: return lib_batch(c, c->np);
    case HAND_SHARED: hand(c, which, 0); return FRICREG_OK;
    case BATCH_SHARED: return lib_batch(c, 0);
    case HAND_POINT: hand_point(c, which); return FRICREG_OK;
    default: return lib_eval(c);
    }
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

static void make_case(struct element_case *c, const char *name, size_t ns, size_t npoints)
{
    c->name = name;
    c->npoints = npoints;
    c->type = fricreg_element_sliders(fricreg_element_lookup(name), ns);
    c->dim = (size_t)fricreg_element_dim(c->type);
    c->np = fricreg_element_nparams(c->type);
    c->nstate = fricreg_element_nstate(c->type);
    c->p = array(c->np * npoints);
    c->w = array(c->nstate * npoints);
    c->u = array(c->dim * npoints);
    c->f = array(c->dim * npoints);
    c->lf = array(c->dim * npoints);
    c->t = array(c->dim * c->dim * npoints);
    c->lt = array(c->dim * c->dim * npoints);
    c->wn = array(c->nstate * npoints);
    c->lwn = array(c->nstate * npoints);
    for (size_t i = 0; i < npoints; i++) {
        double *p = c->p + c->np * i, *w = c->w + c->nstate * i, *u = c->u + c->dim * i;
        /* slip starts at |u - w| = b / k, about 0.01 (N about 1 for the contact): about half
         * stick; the Iwan sliders' b / k from 0.002 to 0.04 in order, one reversal's offsets */
        for (size_t s = 0; s < ns; s++) {
            p[s] = uniform(80.0, 120.0);
            p[ns + s] = p[s] * (ns > 1 ? 0.002 + 0.038 * ((double)s + 0.5) / (double)ns
                                       : uniform(0.005, 0.015));
        }
        double reversal = uniform(-0.01, 0.01);
        for (size_t j = 0; j < c->nstate; j++)
            w[j] = ns > 1 ? reversal : uniform(-0.01, 0.01);
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
    for (size_t i = 0; i < c->dim * c->npoints; i++)
        bad += c->f[i] != c->lf[i];
    for (size_t i = 0; i < c->dim * c->dim * c->npoints; i++)
        bad += c->t[i] != c->lt[i];
    for (size_t i = 0; i < c->nstate * c->npoints; i++)
        bad += c->wn[i] != c->lwn[i];
    return bad;
}

/* Each library item's results equal those of its hand item, bit for bit. */
static int check_case(struct element_case *c, int which)
{
    static const int pairs[3][2] = {{HAND_LOOP, BATCH},
                                    {HAND_SHARED, BATCH_SHARED},
                                    {HAND_POINT, EVAL}};
    for (int k = 0; k < 3; k++) {
        run_item(c, which, pairs[k][0]);
        memset(c->lf, 0xff, c->dim * c->npoints * sizeof *c->lf);
        int status = run_item(c, which, pairs[k][1]);
        size_t bad = mismatches(c);
        if (status != FRICREG_OK || bad != 0) {
            fprintf(stderr, "%s: %s: status %d, %zu numbers differ from %s\n", c->name,
                    item_names[pairs[k][1]], status, bad, item_names[pairs[k][0]]);
            return 1;
        }
    }
    return 0;
}

/* "count CASE ITEM": ITEM (an item's name, or none) of case CASE (0, 1, 2) COUNT_SWEEPS times,
 * for an instruction count: (count(ITEM) - count(none)) / (COUNT_SWEEPS 1000), on the set of
 * 1000 points. */
static int count(struct element_case *c, int k, const char *name)
{
    int item = 0;
    while (item < NITEMS && strcmp(name, item_names[item]) != 0)
        item++;
    if (item == NITEMS)
        return strcmp(name, "none") != 0;
    for (int sweep = 0; sweep < COUNT_SWEEPS; sweep++)
        run_item(&c[k], k, item);
    return 0;
}

static void free_case(struct element_case *c)
{
    double *arrays[] = {c->p, c->w, c->u, c->f, c->lf, c->t, c->lt, c->wn, c->lwn};
    for (size_t k = 0; k < sizeof arrays / sizeof *arrays; k++)
        free(arrays[k]);
}

/* The three cases on a set of npoints: 0, or 1 when a library item's results differ. */
static int make_cases(struct element_case c[NCASES], size_t npoints)
{
    make_case(&c[0], "jenkins", 1, npoints);
    make_case(&c[1], "contact_3d", 1, npoints);
    make_case(&c[2], "iwan", NS, npoints);
    for (int k = 0; k < NCASES; k++)
        if (check_case(&c[k], k) != 0)
            return 1;
    return 0;
}

/* Every item of every case, REPEATS interleaved timings of WORK points each; the table. */
static void time_set(struct element_case c[NCASES])
{
    static double times[NCASES][NITEMS][REPEATS];
    int sweeps = (int)(WORK / c[0].npoints) + 1;
    for (int r = 0; r < REPEATS; r++)
        for (int k = 0; k < NCASES; k++)
            for (int item = 0; item < NITEMS; item++) {
                double t0 = cpu_seconds();
                for (int sweep = 0; sweep < sweeps; sweep++)
                    run_item(&c[k], k, item);
                times[k][item][r] = (cpu_seconds() - t0) * 1e9 / (sweeps * (double)c[k].npoints);
            }
    printf("%zu points: ns per point, median of %d interleaved runs (iwan: %d sliders); ratios: "
           "the library to its hand item\n",
           c[0].npoints, REPEATS, NS);
    printf("%-11s %6s %6s %6s %6s %6s %6s %8s %8s %8s\n", "case", "loop", "batch", "loop_s",
           "batch_s", "point", "eval", "batch/h", "batch_s/h", "eval/h");
    double jenkins_eval = median(times[0][EVAL], REPEATS);
    for (int k = 0; k < NCASES; k++) {
        double m[NITEMS];
        for (int item = 0; item < NITEMS; item++)
            m[item] = median(times[k][item], REPEATS);
        printf("%-11s %6.2f %6.2f %6.2f %6.2f %6.2f %6.2f %8.2f %8.2f %8.2f\n", c[k].name,
               m[HAND_LOOP], m[BATCH], m[HAND_SHARED], m[BATCH_SHARED], m[HAND_POINT], m[EVAL],
               m[BATCH] / m[HAND_LOOP], m[BATCH_SHARED] / m[HAND_SHARED], m[EVAL] / m[HAND_POINT]);
        if (k == 2)
            printf("iwan eval / %d jenkins evals: %.2f\n", NS, m[EVAL] / (NS * jenkins_eval));
    }
}

int main(int argc, char **argv)
{
    struct element_case c[NCASES];
    int counting = argc == 4 && strcmp(argv[1], "count") == 0;
    for (int set = 0; set < (counting ? 1 : NSETS); set++) {
        int status = make_cases(c, set_points[set]);
        if (status == 0 && counting)
            status = count(c, atoi(argv[2]) % NCASES, argv[3]);
        else if (status == 0)
            time_set(c);
        for (int k = 0; k < NCASES; k++)
            free_case(&c[k]);
        if (status != 0 || counting)
            return status;
    }
    return 0;
}
