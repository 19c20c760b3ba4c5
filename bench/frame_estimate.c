/* SPDX-License-Identifier: GPL-3.0-or-later */
/* frame_estimate.c — the structure's error estimate on a 3-storey shear frame with two
 * friction dampers under harmonic ground motion, against a reference from runs at much
 * smaller eps and dt.
 *
 * The frame: m = 1e5 kg and k = 5e7 N/m per storey (modes 1.58, 4.44, 6.41 Hz), 2 % Rayleigh
 * on modes 1 and 3, damper 1 between storey 1 and the ground, damper 2 between storeys 2 and
 * 1, each with mu N = 30 % of a storey's weight (--mun F: another fraction); a_g = 0.3 g
 * sin(2 pi 1.5 t) sampled every 0.25 ms; 8 s; law (4) (Quinn's, fricreg-sim structure's
 * default) at the CLI's default eps, 1 % of the ground's peak velocity; Newmark and HHT
 * (alpha = -0.05, the CLI's) at dt = 10, 5, 2.5 ms. At 30 % the run at 5 ms and its companion
 * agree on a wrong D2 (the error stalls along the path): 1.6's estimate is 5x under.
 *
 * The reference (no event-driven solver applies: src/exact/ is the one-mass oscillator's):
 * the same frame at eps0 / 64, / 256, / 1024, each extrapolated to dt -> 0 from dt = 5 ms /
 * 2^8, / 2^9, / 2^10, then to eps -> 0 (Richardson with the observed order held to [1, 2]);
 * its uncertainty the corrections' sizes plus 10 % of the last differences. Printed: each
 * run's true error against the library's estimate, and the CPU of a run with and without.
 *
 *   fricreg-bench-frame-estimate [--mun F]            the table (seconds)
 *   fricreg-bench-frame-estimate [--mun F] --ladder   the reference's runs only
 *   fricreg-bench-frame-estimate [--mun F] --companions   finer, coarser and auto companions
 *     (fricreg_structure_set_error_companions; auto: the coarser screen, the finer confirming
 *     where it would warn): per mode, the estimates that bound the error, the runs the finer
 *     confirmed (auto), each run's CPU against the same run without an estimate (their mean),
 *     the median estimate / error (all, and of kind asymptotic), the runs warned, those of them
 *     whose error is surely above the answer tolerance (1e-2; the warnings' precision), the
 *     runs surely off by more than it (and 3x it) without a warning (their recall), and the CPU
 *     of a run with each against one without, all in this process
 *   FRAME_GRID=1 fricreg-bench-frame-estimate         D on a grid of eps and dt
 *   --ground sweep|random   problems the estimators were not derived on: a sine sweep, or
 *     Gaussian samples (ground_record); --jenkins the dampers as Jenkins elements (Newmark and
 *     HHT only: run_ode does not take elements). eps follows the record (1 % of its PGV). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <fricreg.h>
#include <fricreg_structure.h>

#define NDOF 3
#define M_C 2
#define MASS 1e5
#define STIFF 5e7
#define ZETA 0.02
#define G 9.81
#define AG (0.3 * G)
#define F_G 1.5
#define T_END 8.0
#define REC_DT 2.5e-4
#define NREC 32001 /* T_END / REC_DT + 1 */
#define PI 3.14159265358979323846

enum { NEWMARK = 0, HHT = 1, RKF45 = 2 }; /* RKF45: adaptive, rtol 1e-6, called every dt */
#define RKF45_RTOL 1e-6

static double mun_fraction = 0.3;                 /* mu N / (m g) per damper (--mun) */
static int companions = FRICREG_COMPANIONS_FINER; /* the runs' (--companions switches) */
#define MUN (mun_fraction * MASS * G)

struct frame_run {
    double D[M_C], peak[NDOF];         /* results */
    double D_err[M_C], peak_err[NDOF]; /* the library's estimates (estimate on) */
    int warned;                        /* FRICREG_WARN_ERROR_ESTIMATE raised */
    int bound;                         /* a dissipation's estimate of kind BOUND (1.7: the
                                        * "not asymptotic" warning) */
    int D_kind[M_C], peak_kind[NDOF];  /* every estimate's kind */
    double companion_cpu;              /* FRICREG_SVALUE_COMPANION_CPU */
    double used;                       /* FRICREG_SVALUE_COMPANIONS_USED */
    double cpu;                        /* seconds */
};

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double cpu_now(void)
{
    return (double)clock() / CLOCKS_PER_SEC;
}

/* Rayleigh coefficients for ZETA on modes 1 and 3: the shear chain's eigenvalues
 * (k/m) (2 - 2 cos((2j - 1) pi / 7)), j = 1 .. 3. */
static void rayleigh(double *a0, double *a1)
{
    double w1 = sqrt(STIFF / MASS * (2.0 - 2.0 * cos(PI / 7.0)));
    double w3 = sqrt(STIFF / MASS * (2.0 - 2.0 * cos(5.0 * PI / 7.0)));
    *a0 = 2.0 * ZETA * w1 * w3 / (w1 + w3);
    *a1 = 2.0 * ZETA / (w1 + w3);
}

/* The ground motion (--ground): the harmonic one above; "sweep", a linear sine sweep of 0.3 g
 * from 0.5 to 8 Hz over the 8 s (through the three modes); "random", Gaussian samples every
 * 20 ms from a fixed seed, linear between them, scaled to a peak of 0.3 g. */
static const char *ground = "sine";

/* Uniform (0, 1) from a fixed-seed 64-bit LCG (Knuth's MMIX constants): the same record on
 * every machine. */
static double uniform(unsigned long long *x)
{
    *x = *x * 6364136223846793005ULL + 1442695040888963407ULL;
    return ((double)(*x >> 11) + 0.5) / 9007199254740992.0;
}

static void ground_record(double ag[NREC])
{
    if (strcmp(ground, "sweep") == 0) {
        for (size_t k = 0; k < NREC; k++) {
            double t = (double)k * REC_DT;
            ag[k] = AG * sin(2.0 * PI * (0.5 * t + (8.0 - 0.5) * t * t / (2.0 * T_END)));
        }
    } else if (strcmp(ground, "random") == 0) {
        enum { EVERY = 80, NS = (NREC - 1) / EVERY + 1 }; /* a sample every 20 ms */
        double g[NS], peak = 0.0;
        unsigned long long x = 20261126ULL;
        for (int i = 0; i < NS; i++) { /* Box-Muller */
            double u1 = uniform(&x), u2 = uniform(&x);
            g[i] = sqrt(-2.0 * log(u1)) * cos(2.0 * PI * u2);
        }
        for (size_t k = 0; k < NREC; k++) {
            size_t i = k / EVERY;
            double f = (double)(k % EVERY) / EVERY;
            ag[k] = i + 1 < NS ? (1.0 - f) * g[i] + f * g[i + 1] : g[i];
            peak = fmax(peak, fabs(ag[k]));
        }
        for (size_t k = 0; k < NREC; k++)
            ag[k] *= AG / peak;
    } else {
        for (size_t k = 0; k < NREC; k++)
            ag[k] = AG * sin(2.0 * PI * F_G * (double)k * REC_DT);
    }
}

/* --jenkins: the dampers are Jenkins elements on the same rows (kt = k, slip force mu N), the
 * contacts left at bound 0 (no force, no dissipation; a structure has at least one); the
 * elements' dissipations are the D's, their errors dt's alone. */
static int jenkins = 0;

static fricreg_structure *frame(void)
{
    static double ag[NREC];
    size_t nrec = NREC;
    ground_record(ag);
    double M[9] = {MASS, 0, 0, 0, MASS, 0, 0, 0, MASS};
    double K[9] = {2 * STIFF, -STIFF, 0, -STIFF, 2 * STIFF, -STIFF, 0, -STIFF, STIFF};
    double J[6] = {1, 0, 0, -1, 1, 0}, mun[2] = {MUN, MUN}, zero[3] = {0, 0, 0}, one[3] = {1, 1, 1},
           kt[2] = {STIFF, STIFF}, a0, a1;
    rayleigh(&a0, &a1);
    fricreg_structure *s = NULL;
    if (fricreg_structure_create(NDOF, M_C, &s) != FRICREG_OK)
        return NULL;
    if (fricreg_structure_set_mass(s, NDOF, M) || fricreg_structure_set_stiffness(s, NDOF, K) ||
        fricreg_structure_set_rayleigh(s, a0, a1) ||
        fricreg_structure_set_influence(s, NDOF, one) ||
        fricreg_structure_set_contacts(s, M_C, NDOF, J) ||
        fricreg_structure_set_bounds(s, M_C, jenkins ? zero : mun) ||
        (jenkins && fricreg_structure_set_jenkins(s, M_C, NDOF, J, kt, mun)) ||
        fricreg_structure_set_ground_accel(s, 0.0, REC_DT, nrec, ag) ||
        fricreg_structure_set_initial(s, NDOF, zero, zero)) {
        fricreg_structure_free(s);
        return NULL;
    }
    return s;
}

/* The CLI's default eps: 1 % of the record's peak ground velocity. */
static double default_eps(void)
{
    fricreg_structure *s = frame();
    double pgv = 0.0;
    fricreg_structure_get_value(s, FRICREG_SVALUE_GROUND_PGV, &pgv);
    fricreg_structure_free(s);
    return 0.01 * pgv;
}

static int run(int scheme, double eps, double dt, int estimate, struct frame_run *r)
{
    memset(r, 0, sizeof *r);
    fricreg_structure *s = frame();
    if (s == NULL)
        return FRICREG_ENOMEM;
    int status = fricreg_structure_set_law(s, FRICREG_LAW_QUINN, eps);
    if (status == FRICREG_OK && scheme == HHT)
        status = fricreg_structure_set_hht(s, -0.05); /* the CLI's alpha */
    if (status == FRICREG_OK)
        status = fricreg_structure_set_error_estimate(s, estimate);
    if (status == FRICREG_OK)
        status = fricreg_structure_set_error_companions(s, companions);
    double t0 = cpu_now();
    if (status == FRICREG_OK && scheme != RKF45)
        status = fricreg_structure_run(s, dt, T_END);
    for (long k = 1, n = lround(T_END / dt); scheme == RKF45 && status == FRICREG_OK && k <= n;
         k++) /* sampled every dt, as fricreg-sim's adaptive runs: the tolerances from eps */
        status = fricreg_structure_run_ode(s, FRICREG_INT_RKF45, dt, RKF45_RTOL,
                                           FRICREG_ATOL_FROM_EPS, k == n ? T_END : (double)k * dt);
    if (status == FRICREG_OK && estimate) /* the first read settles auto's screen: its cost */
        fricreg_structure_get_peak_displacement_error(s, NDOF, r->peak_err);
    r->cpu = cpu_now() - t0;
    if (status == FRICREG_OK) {
        if (jenkins)
            fricreg_structure_get_jenkins_state(s, M_C, NULL, NULL, r->D);
        else
            fricreg_structure_get_dissipation(s, M_C, r->D);
        fricreg_structure_get_peak_displacement(s, NDOF, r->peak);
    }
    if (status == FRICREG_OK && estimate) {
        if (jenkins)
            fricreg_structure_get_jenkins_dissipation_error(s, M_C, r->D_err);
        else
            fricreg_structure_get_dissipation_error(s, M_C, r->D_err);
        fricreg_structure_get_peak_displacement_error(s, NDOF, r->peak_err);
        size_t nw = fricreg_structure_warning_count(s);
        for (size_t k = 0; k < nw; k++) {
            int code = 0;
            fricreg_structure_get_warning(s, k, &code, NULL, 0);
            r->warned |= code == FRICREG_WARN_ERROR_ESTIMATE;
        }
        fricreg_structure_get_error_kind(s,
                                         jenkins ? FRICREG_EST_ELEMENT_DISSIPATION
                                                 : FRICREG_EST_DISSIPATION,
                                         M_C, r->D_kind);
        fricreg_structure_get_error_kind(s, FRICREG_EST_PEAK_DISPLACEMENT, NDOF, r->peak_kind);
        for (int j = 0; j < M_C; j++)
            r->bound |= r->D_kind[j] == FRICREG_EST_KIND_BOUND;
        fricreg_structure_get_value(s, FRICREG_SVALUE_COMPANION_CPU, &r->companion_cpu);
        fricreg_structure_get_value(s, FRICREG_SVALUE_COMPANIONS_USED, &r->used);
    }
    if (status != FRICREG_OK)
        fprintf(stderr, "run eps %g dt %g: %s\n", eps, dt, fricreg_structure_errmsg(s));
    fricreg_structure_free(s);
    return status;
}

/* The reference: q(eps, dt) at eps0 / 64, / 256, / 1024, each extrapolated to dt -> 0 from
 * dt = 5 ms / 2^8, / 2^9, / 2^10 (Richardson with the observed order, held to [1, 2]), then
 * those three extrapolated to eps -> 0 the same way (ratio 4). unc: the corrections' sizes. */
struct reference {
    double D[M_C], D_unc[M_C], peak[NDOF], peak_unc[NDOF];
};

/* q[0], q[1], q[2] at h, h / ratio, h / ratio^2: the limit h -> 0, *unc its uncertainty. */
static double extrapolate(const double q[3], double ratio, double *unc)
{
    double d1 = q[0] - q[1], d2 = q[1] - q[2];
    double p = d2 != 0.0 && d1 / d2 > 0.0 ? log(d1 / d2) / log(ratio) : 1.0;
    p = fmin(fmax(p, 1.0), 2.0);
    double corr = d2 / (pow(ratio, p) - 1.0);
    *unc = fabs(corr) + 0.1 * fabs(d2); /* the correction, and a margin for its order */
    return q[2] + corr;
}

enum { NQ = M_C + NDOF };

static int reference(double eps0, int print, struct reference *ref)
{
    double in_eps[3][NQ], unc_dt[NQ] = {0};
    for (int a = 0; a < 3; a++) {
        double eps = ldexp(eps0, -(6 + 2 * a)), in_dt[3][NQ];
        for (int b = 0; b < 3; b++) {
            struct frame_run r;
            double dt = ldexp(5e-3, -(8 + b));
            if (run(NEWMARK, eps, dt, 0, &r) != FRICREG_OK)
                return 1;
            memcpy(in_dt[b], r.D, sizeof r.D);
            memcpy(in_dt[b] + M_C, r.peak, sizeof r.peak);
            if (print)
                printf("reference run eps %.4g dt %.4g: D1 %.9g D2 %.9g peak %.7g %.7g %.7g\n", eps,
                       dt, r.D[0], r.D[1], r.peak[0], r.peak[1], r.peak[2]);
        }
        for (int j = 0; j < NQ; j++) {
            double q[3] = {in_dt[0][j], in_dt[1][j], in_dt[2][j]}, u;
            in_eps[a][j] = extrapolate(q, 2.0, &u);
            unc_dt[j] = fmax(unc_dt[j], u);
        }
    }
    for (int j = 0; j < NQ; j++) {
        double q[3] = {in_eps[0][j], in_eps[1][j], in_eps[2][j]}, u;
        double v = extrapolate(q, 4.0, &u);
        if (j < M_C) {
            ref->D[j] = v;
            ref->D_unc[j] = u + unc_dt[j];
        } else {
            ref->peak[j - M_C] = v;
            ref->peak_unc[j - M_C] = u + unc_dt[j];
        }
    }
    if (print) {
        for (int j = 0; j < M_C; j++)
            printf("reference D%d %.12g +- %.2g\n", j + 1, ref->D[j], ref->D_unc[j]);
        for (int i = 0; i < NDOF; i++)
            printf("reference peak%d %.12g +- %.2g\n", i + 1, ref->peak[i], ref->peak_unc[i]);
    }
    return 0;
}

static void row(const char *name, double truth, double unc, double old, double est, int warned)
{
    printf("| %s | %.3g (+- %.2g) | %.3g | %.3g | %.2f | %s |\n", name, truth, unc, old, est,
           est / truth, warned ? "yes" : "no");
}

static const char *const scheme_names[] = {"Newmark", "HHT", "rkf45"};

/* One scheme and step: a row per quantity, the old (one companion) and new (two) estimates. */
static int table_rows(int scheme, double eps0, double dt, const struct reference *ref)
{
    struct frame_run one, two;
    if (run(scheme, eps0, dt, FRICREG_ESTIMATE_ONE_COMPANION, &one) != FRICREG_OK ||
        run(scheme, eps0, dt, FRICREG_ESTIMATE_TWO_COMPANIONS, &two) != FRICREG_OK)
        return 1;
    int warned = two.warned || two.bound; /* the table's "warned": a warning or a bound */
    for (int j = 0; j < NQ; j++) {
        char name[96];
        snprintf(name, sizeof name, "%s %g ms %s%d", scheme_names[scheme], 1e3 * dt,
                 j < M_C ? "D" : "peak", j < M_C ? j + 1 : j - M_C + 1);
        if (j < M_C)
            row(name, fabs(two.D[j] - ref->D[j]), ref->D_unc[j], one.D_err[j], two.D_err[j],
                warned);
        else
            row(name, fabs(two.peak[j - M_C] - ref->peak[j - M_C]), ref->peak_unc[j - M_C],
                one.peak_err[j - M_C], two.peak_err[j - M_C], warned);
    }
    return 0;
}

/* Whether run r's error is surely above factor times the default answer tolerance (1e-2) by the
 * warning's measures: the largest peak's error against the largest peak, or the summed
 * dissipations' errors against their sum, each less the reference's uncertainty. */
static int truly_off(const struct frame_run *r, const struct reference *ref, double factor)
{
    double peak = 0.0, peak_err = 0.0, D = 0.0, D_err = 0.0;
    for (int i = 0; i < NDOF; i++) {
        peak = fmax(peak, fabs(r->peak[i]));
        peak_err = fmax(peak_err, fabs(r->peak[i] - ref->peak[i]) - ref->peak_unc[i]);
    }
    for (int j = 0; j < M_C; j++) {
        D += fabs(r->D[j]);
        D_err += fabs(r->D[j] - ref->D[j]) - ref->D_unc[j];
    }
    return peak_err > factor * 1e-2 * peak || D_err > factor * 1e-2 * D;
}

/* --companions: each mode's estimates on the table's runs (Newmark and HHT at 10, 5, 2.5 ms)
 * and adaptive RKF45 sampled at 20, 10, 5 ms against the reference, and its cost against no
 * estimate (Newmark at 2.5 ms, medians of interleaved runs). */
static int compare_companions(double eps0, const struct reference *ref)
{
    static const char *const names[] = {"finer", "coarser", "auto"};
    const double dts[] = {1e-2, 5e-3, 2.5e-3};
    const double samples[] = {2e-2, 1e-2, 5e-3}; /* RKF45's */
    enum { RUNS = 3 * 3, REPS = 7 };
    printf("\n| companions | estimates | bounded | median est/err | asymptotic | median "
           "est/err (asymptotic) | runs warned | warnings right | off, unwarned (> 3x) | cost / "
           "run without | runs confirmed | mean cost / run without |\n"
           "|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    double cost[4][REPS];
    for (int k = 0; k < REPS; k++)
        for (int e = -1; e <= FRICREG_COMPANIONS_AUTO; e++) {
            struct frame_run r;
            companions = e < 0 ? FRICREG_COMPANIONS_FINER : e;
            run(NEWMARK, eps0, 2.5e-3, e < 0 ? 0 : 1, &r);
            cost[e + 1][k] = r.cpu;
        }
    for (int e = 0; e < 4; e++)
        qsort(cost[e], REPS, sizeof cost[e][0], by_value);
    for (int mode = FRICREG_COMPANIONS_FINER; mode <= FRICREG_COMPANIONS_AUTO; mode++) {
        double ratio[RUNS * NQ], asym[RUNS * NQ];
        int n = 0, na = 0, bounded = 0, warned = 0, right = 0, missed = 0, missed3 = 0;
        int confirmed = 0;
        double cost_ratio = 0.0; /* summed over the runs: each against the same run without */
        companions = mode;
        for (int scheme = NEWMARK; scheme <= (jenkins ? HHT : RKF45); scheme++)
            for (int k = 0; k < 3; k++) { /* the elements: fricreg_structure_step's schemes */
                struct frame_run r;
                double dt = scheme == RKF45 ? samples[k] : dts[k];
                struct frame_run bare;
                if (run(scheme, eps0, dt, 1, &r) != FRICREG_OK ||
                    run(scheme, eps0, dt, 0, &bare) != FRICREG_OK)
                    return 1;
                cost_ratio += r.cpu / bare.cpu;
                warned += r.warned;
                confirmed += r.used == FRICREG_COMPANIONS_FINER && mode == FRICREG_COMPANIONS_AUTO;
                right += r.warned && truly_off(&r, ref, 1.0);
                missed += !r.warned && truly_off(&r, ref, 1.0);
                missed3 += !r.warned && truly_off(&r, ref, 3.0);
                for (int j = 0; j < NQ; j++) {
                    double err = j < M_C ? fabs(r.D[j] - ref->D[j])
                                         : fabs(r.peak[j - M_C] - ref->peak[j - M_C]);
                    double est = j < M_C ? r.D_err[j] : r.peak_err[j - M_C];
                    int kind = j < M_C ? r.D_kind[j] : r.peak_kind[j - M_C];
                    ratio[n++] = est / err;
                    bounded += est >= err;
                    if (kind == FRICREG_EST_KIND_ASYMPTOTIC)
                        asym[na++] = est / err;
                    if (getenv("FRAME_PRINT") != NULL)
                        printf("%s %s %g ms q%d: error %.3g estimate %.3g (%.3g) %s%s%s\n",
                               names[mode], scheme_names[scheme], 1e3 * dt, j, err, est, est / err,
                               kind == FRICREG_EST_KIND_ASYMPTOTIC ? "asymptotic" : "bound",
                               r.warned ? ", warned" : "",
                               r.used == FRICREG_COMPANIONS_FINER ? ", by the finer" : "");
                }
            }
        qsort(ratio, (size_t)n, sizeof ratio[0], by_value);
        qsort(asym, (size_t)na, sizeof asym[0], by_value);
        printf("| %s | %d | %d | %.3g | %d | %.3g | %d of %d | %d | %d (%d) | %.2f | %d | %.2f |\n",
               names[mode], n, bounded, ratio[n / 2], na, na > 0 ? asym[na / 2] : NAN, warned,
               n / NQ, right, missed, missed3, cost[mode + 1][REPS / 2] / cost[0][REPS / 2],
               confirmed, cost_ratio / (n / NQ));
    }
    printf("\ncost: Newmark at 2.5 ms, median of %d interleaved runs: none %.4f s\n", REPS,
           cost[0][REPS / 2]);
    return 0;
}

int main(int argc, char **argv)
{
    double eps0;
    struct reference ref;
    int ladder = 0, compare = 0;
    for (int k = 1; k < argc; k++) {
        if (strcmp(argv[k], "--ladder") == 0)
            ladder = 1;
        else if (strcmp(argv[k], "--companions") == 0)
            compare = 1;
        else if (strcmp(argv[k], "--mun") == 0 && k + 1 < argc)
            mun_fraction = atof(argv[++k]);
        else if (strcmp(argv[k], "--ground") == 0 && k + 1 < argc)
            ground = argv[++k];
        else if (strcmp(argv[k], "--jenkins") == 0)
            jenkins = 1;
    }
    eps0 = default_eps(); /* the record's, as the CLI's */
    printf("frame: eps = %.6g m/s (1 %% of the PGV), mu N = %.4g N per damper\n", eps0, MUN);
    if (getenv("FRAME_GRID") != NULL) {
        for (int a = 4; a <= 10; a += 2)
            for (int b = 6; b <= 10; b++) {
                struct frame_run r;
                run(NEWMARK, ldexp(eps0, -a), ldexp(5e-3, -b), 0, &r);
                printf("grid eps/2^%d dt/2^%d: D1 %.9g D2 %.9g\n", a, b, r.D[0], r.D[1]);
            }
        return 0;
    }
    if (reference(eps0, 1, &ref) != 0)
        return 1;
    if (getenv("FRAME_PATH") != NULL) { /* the path's levels and observed orders */
        for (int scheme = NEWMARK; scheme <= HHT; scheme++)
            for (double dt = 1e-2; dt > 2e-3; dt /= 2) {
                struct frame_run r[4];
                for (int l = 0; l < 4; l++)
                    run(scheme, ldexp(eps0, -l), ldexp(dt, -l), 0, &r[l]);
                for (int j = 0; j < NQ; j++) {
                    double q[4], t = j < M_C ? ref.D[j] : ref.peak[j - M_C];
                    for (int l = 0; l < 4; l++)
                        q[l] = j < M_C ? r[l].D[j] : r[l].peak[j - M_C];
                    printf("%s %g ms q%d: err %.3g %.3g %.3g %.3g  ratios %.3g %.3g\n",
                           scheme_names[scheme], 1e3 * dt, j, q[0] - t, q[1] - t, q[2] - t,
                           q[3] - t, (q[0] - q[1]) / (q[1] - q[2]), (q[1] - q[2]) / (q[2] - q[3]));
                }
            }
        return 0;
    }
    if (ladder)
        return 0;
    if (compare)
        return compare_companions(eps0, &ref);
    printf("\n| case | true error | old estimate | new estimate | new / error | warned or bound |\n"
           "|---|---|---|---|---|---|\n");
    const double dts[] = {1e-2, 5e-3, 2.5e-3};
    for (int scheme = NEWMARK; scheme <= HHT; scheme++)
        for (size_t k = 0; k < sizeof dts / sizeof dts[0]; k++)
            if (table_rows(scheme, eps0, dts[k], &ref) != 0)
                return 1;
    /* Cost: medians of REPS runs of each estimator and of none, Newmark at 2.5 ms. */
    enum { REPS = 11 };
    double cpu[3][REPS], med[3];
    for (int k = 0; k < REPS; k++)
        for (int e = 0; e < 3; e++) {
            struct frame_run r;
            run(NEWMARK, eps0, 2.5e-3, e, &r);
            cpu[e][k] = r.cpu;
        }
    for (int e = 0; e < 3; e++) {
        qsort(cpu[e], REPS, sizeof cpu[e][0], by_value);
        med[e] = cpu[e][REPS / 2];
    }
    printf("\ncost (Newmark, 2.5 ms, median of %d): no estimate %.4f s; two companions %.4f s "
           "(%.2fx); one companion %.4f s (%.2fx)\n",
           REPS, med[0], med[1], med[1] / med[0], med[2], med[2] / med[0]);
    return 0;
}
