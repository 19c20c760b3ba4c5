/* SPDX-License-Identifier: GPL-3.0-or-later */
/* membrane_contacts.c — a friction interface on a continuum: the cost of coupled contacts
 * against a frictionless Newmark run on the same factor.
 *
 * The model: an N x N grid of 1 kg nodes, one degree of freedom each (a membrane's
 * out-of-plane displacement), springs of K N/m between neighbours and 10^3 N/m from every node
 * to the ground (an elastic foundation: its mode at 5 Hz), Rayleigh C = 0.002 s K, shaken by
 * a_g(t) = 0.35 g sin(2 pi 4 t) (influence vector of ones). K sets how far a contact's
 * compliance over a step reaches: at K = 10^4 (dt omega_max = 1.4) W_eff = J K_eff^-1 J^T of
 * the edge is banded (10 % of its entries above the rounding of its diagonal at N = 316); at
 * the default K = 3 10^6 (dt omega_max = 24, the implicit step of a stiff continuum) most of
 * it is (61 % at 10^6, 99.7 % at 10^7).
 * The interface: a contact on every node of the edge row against the ground (J row e_(0,c),
 * mu N = 20 N), and on every node of each further row of ROWS against the node before it in
 * its column (J row e_(r,c) - e_(r-1,c), mu N = 4 N): ROWS N contacts, coupled through their
 * shared nodes and through the continuum. Quinn's law (the structure's default consistent
 * partition), eps = 10^-3 m/s, average-acceleration Newmark, dt = 5 ms.
 *
 * The baseline is Newmark written with CHOLMOD alone (linear_newmark.h), one solve a step.
 * Figures: each side's whole run (set-up, factorization, STEPS steps) in CPU seconds, their
 * ratio, and the median over REPEATS batches of STEPS/REPEATS steps of each side's time per
 * step, the first batch (which factors) left out; Newton iterations per step; the contacts'
 * mean stuck fraction over the steps (|f_i| below 0.999 mu N_i, read after every step, so that
 * the run is known to stick and slip); peak resident memory (both sides, one process).
 *
 * PATHS, the near-stick block's solver (fricreg_structure_set_contact_solver): dense, sparse,
 * or both, each run in turn in this process against the one frictionless run.
 *
 * LAYOUT, where the rows lie: stacked (the default), interior, spread or grounded (below).
 *
 *   usage: fricreg-bench-membrane-contacts [N [ROWS [STEPS [REPEATS [K [PATHS [LAYOUT]]]]]]]
 *          (defaults 316 2 400 8 3e6 dense: 10^5 dofs, two coupled rows, 2 s)
 * Prints one line a path: n m steps run_s linear_run_s run_ratio step_s linear_step_s
 * step_ratio newton_mean stuck_fraction peak_MiB path (peak_MiB: the process's, all runs). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>

#include "bench.h"
#include "fricreg_structure.h"
#include "linear_newmark.h"

#define MASS 1.0
#define SPRING_K 3e6 /* N/m, the default K */
#define GROUND_K 1e3
#define RAYLEIGH_A1 0.002
#define GROUND_A (0.35 * 9.81)
#define FREQUENCY 4.0
#define EDGE_MUN 20.0
#define ROW_MUN 4.0
#define DT 0.005
#define EPS 1e-3
#define TWO_PI 6.283185307179586

struct membrane {
    size_t side, n, m;
    int64_t *kp, *ki; /* K, upper triangle, CSC */
    double *kx;
    int64_t *jp, *ji; /* J, CSR: row j = contact j */
    double *jx, *mun, *ones, *ag;
    size_t nrecord;
};

static double ground_accel(double t)
{
    return GROUND_A * sin(TWO_PI * FREQUENCY * t);
}

/* K = spring_k times the grid's graph Laplacian plus GROUND_K I, upper triangle: column j holds
 * its upper neighbour (j - side), its left neighbour (j - 1) and itself. */
static void membrane_stiffness(struct membrane *g, double spring_k)
{
    size_t side = g->side, n = g->n, q = 0;
    g->kp = malloc((n + 1) * sizeof *g->kp);
    g->ki = malloc(3 * n * sizeof *g->ki);
    g->kx = malloc(3 * n * sizeof *g->kx);
    g->kp[0] = 0;
    for (size_t j = 0; j < n; j++) {
        size_t r = j / side, c = j % side;
        double neighbours = (r > 0) + (r + 1 < side) + (c > 0) + (c + 1 < side);
        if (r > 0) {
            g->ki[q] = (int64_t)(j - side);
            g->kx[q++] = -spring_k;
        }
        if (c > 0) {
            g->ki[q] = (int64_t)(j - 1);
            g->kx[q++] = -spring_k;
        }
        g->ki[q] = (int64_t)j;
        g->kx[q++] = neighbours * spring_k + GROUND_K;
        g->kp[j + 1] = (int64_t)q;
    }
}

/* Where the ROWS rows of contacts lie (LAYOUT): stacked from the edge (the default; each row
 * against the one before it, so that rows share nodes), stacked in the membrane's middle, spread
 * evenly from the edge (row k at k N/ROWS, against the grid row before it: rows coupled through
 * the continuum only), or stacked from the edge with every row against the ground. */
enum layout { STACKED, INTERIOR, SPREAD, GROUNDED, LAYOUTS };
static const char *const LAYOUT_NAMES[LAYOUTS] = {"stacked", "interior", "spread", "grounded"};

static size_t grid_row(enum layout layout, size_t k, size_t rows, size_t side)
{
    switch (layout) {
    case INTERIOR: return side / 2 - rows / 2 + k;
    case SPREAD: return k * (side / rows);
    case STACKED:
    case GROUNDED:
    case LAYOUTS: break;
    }
    return k;
}

/* The first row's contacts against the ground (mu N = EDGE_MUN), then each further row's against
 * the grid row before it, or the ground (GROUNDED), mu N = ROW_MUN. */
static void membrane_contacts(struct membrane *g, size_t rows, enum layout layout)
{
    size_t side = g->side, q = 0;
    g->m = rows * side;
    g->jp = malloc((g->m + 1) * sizeof *g->jp);
    g->ji = malloc(2 * g->m * sizeof *g->ji);
    g->jx = malloc(2 * g->m * sizeof *g->jx);
    g->mun = malloc(g->m * sizeof *g->mun);
    g->jp[0] = 0;
    for (size_t j = 0; j < g->m; j++) {
        size_t k = j / side, node = grid_row(layout, k, rows, side) * side + j % side;
        if (k > 0 && layout != GROUNDED) { /* against the node before it in its column */
            g->ji[q] = (int64_t)(node - side);
            g->jx[q++] = -1.0;
        }
        g->ji[q] = (int64_t)node;
        g->jx[q++] = 1.0;
        g->jp[j + 1] = (int64_t)q;
        g->mun[j] = k == 0 ? EDGE_MUN : ROW_MUN;
    }
    g->ones = malloc(g->n * sizeof *g->ones);
    for (size_t i = 0; i < g->n; i++)
        g->ones[i] = 1.0;
}

static void membrane_record(struct membrane *g, size_t steps)
{
    g->nrecord = steps + 2;
    g->ag = malloc(g->nrecord * sizeof *g->ag);
    for (size_t i = 0; i < g->nrecord; i++)
        g->ag[i] = ground_accel((double)i * DT);
}

static void membrane_free(struct membrane *g)
{
    void *blocks[] = {g->kp, g->ki, g->kx, g->jp, g->ji, g->jx, g->mun, g->ones, g->ag};
    for (size_t i = 0; i < sizeof blocks / sizeof *blocks; i++)
        free(blocks[i]);
}

static double peak_mib(void)
{
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    return (double)ru.ru_maxrss / 1024.0;
}

static void die(const char *what, const fricreg_structure *s)
{
    fprintf(stderr, "membrane_contacts: %s: %s\n", what, s ? fricreg_structure_errmsg(s) : "");
    exit(1);
}

static fricreg_structure *structure(const struct membrane *g)
{
    fricreg_structure *s = NULL;
    size_t n = g->n;
    int64_t *mp = malloc((n + 1) * sizeof *mp);
    double *mx = malloc(n * sizeof *mx);
    for (size_t i = 0; i <= n; i++)
        mp[i] = (int64_t)i;
    for (size_t i = 0; i < n; i++)
        mx[i] = MASS;
    if (fricreg_structure_create(n, g->m, &s) != FRICREG_OK ||
        fricreg_structure_set_mass_csc(s, n, 0, mp, mp, mx) != FRICREG_OK ||
        fricreg_structure_set_stiffness_csc(s, n, FRICREG_SPARSE_UPPER, g->kp, g->ki, g->kx) !=
            FRICREG_OK ||
        fricreg_structure_set_rayleigh(s, 0.0, RAYLEIGH_A1) != FRICREG_OK ||
        fricreg_structure_set_contacts_csr(s, g->m, n, 0, g->jp, g->ji, g->jx) != FRICREG_OK ||
        fricreg_structure_set_bounds(s, g->m, g->mun) != FRICREG_OK ||
        fricreg_structure_set_law(s, FRICREG_LAW_QUINN, EPS) != FRICREG_OK ||
        fricreg_structure_set_influence(s, n, g->ones) != FRICREG_OK ||
        fricreg_structure_set_ground_accel(s, 0.0, DT, g->nrecord, g->ag) != FRICREG_OK)
        die("set-up", s);
    free(mp);
    free(mx);
    return s;
}

/* The fraction of contacts whose force is below 0.999 of its bound (stuck or near it). */
static double stuck_fraction(const fricreg_structure *s, const struct membrane *g, double f[])
{
    if (fricreg_structure_get_forces(s, g->m, f) != FRICREG_OK)
        die("forces", s);
    size_t stuck = 0;
    for (size_t i = 0; i < g->m; i++)
        stuck += fabs(f[i]) < 0.999 * g->mun[i];
    return (double)stuck / (double)g->m;
}

/* One friction run's figures: the whole run, the per-step median (the first batch left out),
 * Newton iterations per step, the mean stuck fraction. */
struct friction_run {
    double run, step, newton, stuck;
};

static struct friction_run friction_run(const struct membrane *g, int solver, size_t batch,
                                        size_t repeats)
{
    double fr[64], stuck = 0.0, *f = malloc(g->m * sizeof *f);
    double t0 = bench_cpu_seconds();
    fricreg_structure *s = structure(g);
    if (fricreg_structure_set_contact_solver(s, solver) != FRICREG_OK)
        die("contact solver", s);
    for (size_t r = 0; r < repeats; r++) {
        double tb = bench_cpu_seconds();
        for (size_t k = 0; k < batch; k++) {
            if (fricreg_structure_step(s, DT) != FRICREG_OK)
                die("step", s);
            stuck += stuck_fraction(s, g, f);
        }
        fr[r] = (bench_cpu_seconds() - tb) / (double)batch;
    }
    struct friction_run out = {.run = bench_cpu_seconds() - t0};
    int64_t iterations = 0, taken = 0;
    fricreg_structure_get_stat(s, FRICREG_SSTAT_NEWTON_ITERATIONS, &iterations);
    fricreg_structure_get_stat(s, FRICREG_SSTAT_STEPS, &taken);
    fricreg_structure_free(s);
    free(f);
    out.stuck = stuck / (double)(batch * repeats);
    out.newton = (double)iterations / (double)taken;
    out.step = bench_median(fr + 1, repeats - 1); /* the first batch holds the factorizations */
    return out;
}

int main(int argc, char **argv)
{
    struct membrane g = {.side = argc > 1 ? strtoul(argv[1], NULL, 10) : 316};
    size_t rows = argc > 2 ? strtoul(argv[2], NULL, 10) : 2;
    size_t steps = argc > 3 ? strtoul(argv[3], NULL, 10) : 400;
    size_t repeats = argc > 4 ? strtoul(argv[4], NULL, 10) : 8;
    double spring_k = argc > 5 ? strtod(argv[5], NULL) : SPRING_K;
    const char *paths = argc > 6 ? argv[6] : "dense";
    int dense = !strcmp(paths, "dense") || !strcmp(paths, "both");
    int sparse = !strcmp(paths, "sparse") || !strcmp(paths, "both");
    enum layout layout = STACKED;
    while (argc > 7 && layout < LAYOUTS && strcmp(argv[7], LAYOUT_NAMES[layout]) != 0)
        layout++;
    if (g.side < 3 || rows < 1 || rows > g.side / 2 || repeats < 2 || repeats > 64 ||
        steps < repeats || !(spring_k > 0.0) || !(dense || sparse) || layout == LAYOUTS) {
        fprintf(stderr,
                "usage: %s [N >= 3 [ROWS 1..N/2 [STEPS [REPEATS 2..64 <= STEPS [K "
                "[dense|sparse|both [stacked|interior|spread|grounded]]]]]]]\n",
                argv[0]);
        return 2;
    }
    g.n = g.side * g.side;
    membrane_stiffness(&g, spring_k);
    membrane_contacts(&g, rows, layout);
    membrane_record(&g, steps);
    size_t batch = steps / repeats;
    struct friction_run runs[2];
    if (dense)
        runs[0] = friction_run(&g, FRICREG_CONTACT_SOLVER_DENSE, batch, repeats);
    if (sparse)
        runs[1] = friction_run(&g, FRICREG_CONTACT_SOLVER_SPARSE, batch, repeats);

    double lin[64], t0 = bench_cpu_seconds();
    struct linear_newmark l;
    linear_newmark_start(&l, g.n, g.kp, g.ki, g.kx, MASS, RAYLEIGH_A1, DT);
    for (size_t r = 0; r < repeats; r++)
        lin[r] = linear_newmark_batch(&l, ground_accel, batch);
    double linear_run = bench_cpu_seconds() - t0;
    linear_newmark_free(&l);
    double peak = peak_mib();
    membrane_free(&g);

    double ls = bench_median(lin + 1, repeats - 1);
    for (int k = 0; k < 2; k++) {
        if (!(k == 0 ? dense : sparse))
            continue;
        const struct friction_run *fr = &runs[k];
        printf("%zu %zu %zu %.3f %.3f %.2f %.4g %.4g %.2f %.2f %.3f %.0f %s\n", g.n, g.m,
               batch * repeats, fr->run, linear_run, fr->run / linear_run, fr->step, ls,
               fr->step / ls, fr->newton, fr->stuck, peak, k == 0 ? "dense" : "sparse");
    }
    return 0;
}
