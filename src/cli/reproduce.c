/* SPDX-License-Identifier: GPL-3.0-or-later */
/* reproduce.c — `fricreg-sim reproduce --out DIR`: the paper's experiments (Figs. 5, 6, 9
 * and 11 of Quinn 2004), one CSV per figure, a PNG per figure when gnuplot is installed, and a
 * table of each paper number beside ours on stdout. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "out_file.h"

#include "cli.h"

#define PAPER_X_REST (-0.750090) /* Sec. 3.1.1, law (4), dt = 0.01, eps = 2 dt */
#define PAPER_D_CHAIN 0.0105     /* Fig. 9, n = 32, a = 0.25, omega = 0.5 */
#define UNFORCED_T_END 20.0
#define CHAIN_CYCLES 4

/* The time series an observer collects: t and up to 8 named columns per step. */
struct series {
    size_t n, cap, width;
    double *rows; /* n rows of (t, columns…) */
    int (*columns)(const struct series *s, double t, const double x[], const double v[],
                   const double f[], const double f_eq[], double out[]);
};

static int series_push(void *user, double t, size_t ndof, const double x[], const double v[],
                       size_t m, const double f[], const double f_eq[])
{
    (void)ndof, (void)m;
    struct series *s = user;
    if (s->n == s->cap) {
        size_t cap = s->cap ? 2 * s->cap : 4096;
        double *rows = realloc(s->rows, cap * (s->width + 1) * sizeof *rows);
        if (rows == NULL)
            return 1; /* stop the run; the caller sees the short series */
        s->rows = rows;
        s->cap = cap;
    }
    double *row = s->rows + s->n++ * (s->width + 1);
    row[0] = t;
    return s->columns(s, t, x, v, f, f_eq, row + 1);
}

static int cols_x_f(const struct series *s, double t, const double x[], const double v[],
                    const double f[], const double f_eq[], double out[])
{
    (void)s, (void)t, (void)v;
    out[0] = x[0];
    out[1] = f[0];
    out[2] = isnan(f_eq[0]) ? x[0] : f_eq[0]; /* Eq. (5), a = 0: f_eq = x */
    return 0;
}

/* Two blocks: x1, x2, zdot1, zdot2, f1, f2 with the default belt u = sin(0.5 t). */
static int cols_twoblock(const struct series *s, double t, const double x[], const double v[],
                         const double f[], const double f_eq[], double out[])
{
    (void)s, (void)f_eq;
    double belt_v = 0.5 * cos(0.5 * t);
    double row[6] = {x[0], x[1], v[0] - belt_v, v[1] - v[0], f[0], f[1]};
    memcpy(out, row, sizeof row);
    return 0;
}

/* Runs `system` with `law`, the given partition of coupled contacts and RK4 at step dt (eps
 * by the paper's rule) for t_end or, if t_end is 0, `cycles` cycles; collects s if given.
 * Returns the simulation, or NULL. */
static fricreg_sim *run_partition(int system, int law, int partition, double dt, double t_end,
                                  int cycles, struct series *s)
{
    fricreg_sim *sim = NULL;
    int status = fricreg_sim_create(system, &sim);
    if (status == FRICREG_OK)
        status = fricreg_sim_set_law(sim, law, 0.0);
    if (status == FRICREG_OK)
        status = fricreg_sim_set_partition(sim, partition);
    if (status == FRICREG_OK)
        status = fricreg_sim_set_integrator(sim, FRICREG_INT_RK4, dt, 0.0, 0.0);
    if (status == FRICREG_OK && s != NULL)
        status = fricreg_sim_set_observer(sim, series_push, s);
    if (status == FRICREG_OK)
        status = t_end > 0.0 ? fricreg_sim_run(sim, t_end) : fricreg_sim_run_cycles(sim, cycles);
    if (status != FRICREG_OK) {
        fprintf(stderr, "fricreg-sim: reproduce: %s, law %s, dt %g: %s\n", cli_system_name(system),
                fricreg_law_name(law), dt, fricreg_sim_errmsg(sim));
        fricreg_sim_free(sim);
        return NULL;
    }
    return sim;
}

/* The paper's own method: its partition of coupled contacts (Sec. 3.3). */
static fricreg_sim *run_paper(int system, int law, double dt, double t_end, int cycles,
                              struct series *s)
{
    return run_partition(system, law, FRICREG_PARTITION_PAPER, dt, t_end, cycles, s);
}

static double final_position(const fricreg_sim *sim)
{
    double x[1], v[1];
    fricreg_sim_get_state(sim, 1, x, v);
    return x[0];
}

static double last_cycle_dissipation(const fricreg_sim *sim)
{
    double D[CHAIN_CYCLES] = {0};
    fricreg_sim_get_dissipation(sim, CHAIN_CYCLES, D);
    return D[CHAIN_CYCLES - 1];
}

/* Every file reproduce writes into --out (out_file.h), the manifest last. */
static const char *const outputs[] = {"fig5_unforced.csv",   "fig6_force.csv",
                                      "fig9_chain.csv",      "fig11_twoblock.csv",
                                      "hold_breakaway.csv",  "belt_limit_cycle.csv",
                                      "disk_oscillator.csv", "hb_frf.csv",
                                      "hb_overhang.csv",     "plots.gp",
                                      "fig5_unforced.png",   "fig6_force.png",
                                      "fig9_chain.png",      "fig11_twoblock.png",
                                      "hold_breakaway.png",  "belt_limit_cycle.png",
                                      "disk_oscillator.png", "hb_frf.png",
                                      "hb_overhang.png"};
#define N_CSV 10 /* the CSVs and plots.gp come first in outputs[] */
#define N_OUTPUTS (sizeof outputs / sizeof outputs[0])

/* Opens dir/name for writing (a temporary file until cli_out_commit): o->f, or NULL. */
static FILE *open_in(const char *dir, const char *name, struct cli_out *o)
{
    return cli_out_open(o, dir, name) == 0 ? o->f : NULL;
}

static void table_row_vs(const char *figure, const char *quantity, double paper, double ours,
                         int relative)
{
    char p[32], d[48];
    snprintf(p, sizeof p, "%.6f", paper);
    if (relative)
        snprintf(d, sizeof d, "%+.2f%%", 100.0 * (ours - paper) / fabs(paper));
    else
        snprintf(d, sizeof d, "%+.1e", ours - paper);
    cli_table_row(figure, quantity, p, ours, d);
}

/* ---- Figure 5 and 6: the unforced oscillator -------------------------------------------- */

static int figure5(const char *dir)
{
    static const int laws[4] = {FRICREG_LAW_COULOMB, FRICREG_LAW_FORCE_BALANCE,
                                FRICREG_LAW_VELOCITY_LIMITED, FRICREG_LAW_QUINN};
    static const char *const label[4] = {"(1) Coulomb", "(2) force balance", "(3) velocity-limited",
                                         "(4) Quinn"};
    struct series s[4];
    double x_final[4];
    int ok = 1;
    for (int k = 0; k < 4 && ok; k++) {
        s[k] = (struct series){.width = 3, .columns = cols_x_f};
        fricreg_sim *sim = run_paper(FRICREG_SYSTEM_OSCILLATOR, laws[k], 0.01, UNFORCED_T_END, 0,
                                     &s[k]);
        ok = sim != NULL && s[k].n == s[0].n;
        x_final[k] = ok ? final_position(sim) : NAN;
        fricreg_sim_free(sim);
    }
    struct cli_out o;
    FILE *out = ok ? open_in(dir, "fig5_unforced.csv", &o) : NULL;
    if (out != NULL) {
        fprintf(out, "t,x_coulomb,x_force_balance,x_velocity_limited,x_quinn\n");
        for (size_t i = 0; i < s[0].n; i++) {
            fprintf(out, "%.10g", s[0].rows[4 * i]);
            for (int k = 0; k < 4; k++)
                fprintf(out, ",%.10g", s[k].rows[4 * i + 1]);
            fputc('\n', out);
        }
    }
    for (int k = 0; k < 4; k++)
        free(ok ? s[k].rows : NULL);
    if (out == NULL || cli_out_commit(&o) != 0)
        return 1;
    char q[64];
    for (int k = 0; k < 3; k++) {
        snprintf(q, sizeof q, "x(t=20), %s", label[k]);
        cli_table_row("Fig. 5", q, "drifts to 0", x_final[k], "(no stick at -0.75)");
    }
    table_row_vs("Fig. 5", "x(t=20), (4) Quinn, dt 0.01, eps 2dt", PAPER_X_REST, x_final[3], 0);
    table_row_vs("Fig. 5", "x(t=20), (4) Quinn, vs exact rest -0.75", -0.75, x_final[3], 0);
    return 0;
}

/* Total variation of f over the rows, divided by its net change: 1 for a monotone force,
 * large when it chatters. */
static double variation_ratio(const struct series *s, double t_from)
{
    double tv = 0.0, first = NAN, last = NAN;
    for (size_t i = 0; i < s->n; i++) {
        const double *r = s->rows + 4 * i;
        if (r[0] < t_from - 1e-9)
            continue;
        tv += isnan(last) ? 0.0 : fabs(r[2] - last);
        first = isnan(first) ? r[2] : first;
        last = r[2];
    }
    return tv / fabs(last - first);
}

static int figure6(const char *dir)
{
    struct series s = {.width = 3, .columns = cols_x_f};
    fricreg_sim *sim = run_paper(FRICREG_SYSTEM_OSCILLATOR, FRICREG_LAW_QUINN, 0.01, 3.5, 0, &s);
    fricreg_sim_free(sim);
    struct cli_out o;
    FILE *out = sim ? open_in(dir, "fig6_force.csv", &o) : NULL;
    int failed = out == NULL;
    if (out != NULL) {
        fprintf(out, "t,x,f,f_eq\n");
        for (size_t i = 0; i < s.n; i++) {
            const double *r = s.rows + 4 * i;
            if (r[0] >= 2.5 - 1e-9)
                fprintf(out, "%.10g,%.10g,%.10g,%.10g\n", r[0], r[1], r[2], r[3]);
        }
        failed = cli_out_commit(&o) != 0;
        const double *last = s.rows + 4 * (s.n - 1);
        cli_table_row("Fig. 6", "f: total variation / net change, (4)", "1 (no chatter)",
                      variation_ratio(&s, 2.5), "");
        table_row_vs("Fig. 6", "f - f_eq at t = 3.5, (4) (force balance)", 0.0, last[2] - last[3],
                     0);
    }
    free(s.rows);
    return failed;
}

/* ---- Figure 9: the chain's dissipation against the step -------------------------------- */

/* D of the chain's last cycle under `law` at dt, or NaN if the step guard refuses dt (at
 * dt = 0.02 the chain's highest frequency 64 gives dt*omega = 1.28 > 1/sqrt 2, where a friction
 * reversal within one step can put energy in); nonzero on any other failure. */
static int chain_dissipation(int law, double dt, double *D)
{
    fricreg_sim *sim = NULL;
    int status = fricreg_sim_create(FRICREG_SYSTEM_CHAIN, &sim);
    if (status == FRICREG_OK)
        status = fricreg_sim_set_law(sim, law, 0.0);
    if (status == FRICREG_OK)
        status = fricreg_sim_set_integrator(sim, FRICREG_INT_RK4, dt, 0.0, 0.0);
    if (status == FRICREG_OK)
        status = fricreg_sim_run_cycles(sim, CHAIN_CYCLES);
    *D = status == FRICREG_OK ? last_cycle_dissipation(sim) : NAN;
    if (status != FRICREG_OK && status != FRICREG_ESTEP)
        fprintf(stderr, "fricreg-sim: reproduce: chain, law %s, dt %g: %s\n", fricreg_law_name(law),
                dt, fricreg_sim_errmsg(sim));
    fricreg_sim_free(sim);
    return status != FRICREG_OK && status != FRICREG_ESTEP;
}

static int figure9(const char *dir)
{
    static const double dts[] = {1e-4, 2e-4, 5e-4, 1e-3, 2e-3, 5e-3, 1e-2, 2e-2};
    static const int laws[3] = {FRICREG_LAW_COULOMB, FRICREG_LAW_VELOCITY_LIMITED,
                                FRICREG_LAW_QUINN};
    enum { NDT = sizeof dts / sizeof dts[0] };
    double D[NDT][3];
    for (int i = 0; i < NDT; i++)
        for (int k = 0; k < 3; k++)
            if (chain_dissipation(laws[k], dts[i], &D[i][k]) != 0)
                return 1;
    struct cli_out o;
    FILE *out = open_in(dir, "fig9_chain.csv", &o);
    if (out == NULL)
        return 1;
    fprintf(out, "dt,D_coulomb,D_velocity_limited,D_quinn\n");
    for (int i = 0; i < NDT; i++)
        fprintf(out, "%g,%.10g,%.10g,%.10g\n", dts[i], D[i][0], D[i][1], D[i][2]);
    if (cli_out_commit(&o) != 0)
        return 1;
    const int at_001 = 6;
    table_row_vs("Fig. 9", "D, 4th cycle, (4) Quinn, dt 0.01", PAPER_D_CHAIN, D[at_001][2], 1);
    table_row_vs("Fig. 9", "D, 4th cycle, (1) Coulomb, dt 0.01", PAPER_D_CHAIN, D[at_001][0], 1);
    table_row_vs("Fig. 9", "D, 4th cycle, (3) vel.-limited, dt 0.01", PAPER_D_CHAIN, D[at_001][1],
                 1);
    table_row_vs("Fig. 9", "D, 4th cycle, (4) Quinn, dt 1e-4", PAPER_D_CHAIN, D[0][2], 1);
    table_row_vs("Fig. 9", "D, 4th cycle, (1) Coulomb, dt 1e-4", PAPER_D_CHAIN, D[0][0], 1);
    table_row_vs("Fig. 9", "D, 4th cycle, (3) vel.-limited, dt 1e-4", PAPER_D_CHAIN, D[0][1], 1);
    table_row_vs("Sec 3.2", "D, (4) dt 1e-4, vs continuum 2a^3/3", 2.0 * pow(0.25, 3) / 3.0,
                 D[0][2], 1);
    return 0;
}

/* ---- Figure 11: two blocks on a belt --------------------------------------------------- */

static int figure11(const char *dir)
{
    struct series s = {.width = 6, .columns = cols_twoblock};
    fricreg_sim *sim = run_paper(FRICREG_SYSTEM_TWOBLOCK, FRICREG_LAW_QUINN, 0.01, 0.0,
                                 CHAIN_CYCLES, &s);
    double stick[2] = {0, 0};
    if (sim != NULL)
        fricreg_sim_get_stick_fraction(sim, 2, stick);
    struct cli_out o;
    FILE *out = sim ? open_in(dir, "fig11_twoblock.csv", &o) : NULL;
    fricreg_sim_free(sim);
    if (out == NULL) {
        free(s.rows);
        return 1;
    }
    fprintf(out, "t,x1,x2,zdot1,zdot2,f1,f2\n");
    for (size_t i = 0; i < s.n; i++) {
        const double *r = s.rows + 7 * i;
        fprintf(out, "%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g\n", r[0], r[1], r[2], r[3], r[4],
                r[5], r[6]);
    }
    free(s.rows);
    if (cli_out_commit(&o) != 0)
        return 1;
    cli_table_row("Fig. 11", "stick fraction, lower interface, 4th cycle", "long sticks", stick[0],
                  "");
    cli_table_row("Fig. 11", "stick fraction, upper interface, 4th cycle", "long sticks", stick[1],
                  "");
    /* The same run under the consistent near-stick law (beyond the paper), beside it. */
    sim = run_partition(FRICREG_SYSTEM_TWOBLOCK, FRICREG_LAW_QUINN, FRICREG_PARTITION_CONSISTENT,
                        0.01, 0.0, CHAIN_CYCLES, NULL);
    if (sim == NULL)
        return 1;
    fricreg_sim_get_stick_fraction(sim, 2, stick);
    fricreg_sim_free(sim);
    cli_table_row("Fig. 11", "  the same, lower, consistent law", "(beyond paper)", stick[0], "");
    cli_table_row("Fig. 11", "  the same, upper, consistent law", "(beyond paper)", stick[1], "");
    return 0;
}

/* ---- Plots ----------------------------------------------------------------------------- */

/* The PNGs go to outdir (a variable the command line sets; '' when a user runs the script in
 * DIR), so that gnuplot never writes over a file of the user's. */
static const char plot_script[] =
    "if (!exists('outdir')) outdir = ''\n"
    "set terminal pngcairo noenhanced size 900,560\n"
    "set datafile separator ','\n"
    "set key autotitle columnhead\n"
    "set output outdir.'fig5_unforced.png'\n"
    "set title 'Fig. 5: unforced oscillator, dt = 0.01'\n"
    "set xlabel 't'; set ylabel 'x'\n"
    "plot for [c=2:5] 'fig5_unforced.csv' using 1:c with lines\n"
    "set output outdir.'fig6_force.png'\n"
    "set title 'Fig. 6: force near stick, law (4)'\n"
    "plot 'fig6_force.csv' using 1:2 with lines, '' using 1:3 with lines\n"
    "set output outdir.'fig9_chain.png'\n"
    "set title 'Fig. 9: chain, D on the 4th cycle'\n"
    "set logscale x; set xlabel 'dt'; set ylabel 'D'\n"
    "plot for [c=2:4] 'fig9_chain.csv' using 1:c with linespoints\n"
    "unset logscale x\n"
    "set output outdir.'fig11_twoblock.png'\n"
    "set title 'Fig. 11: two blocks on a belt, law (4), paper partition'\n"
    "set xlabel 't'; set ylabel 'relative velocity'\n"
    "plot 'fig11_twoblock.csv' using 1:4 with lines, '' using 1:5 with lines\n"
    /* beyond the paper (reproduce_beyond.c, docs/laws2d.md) */
    "set output outdir.'hold_breakaway.png'\n"
    "set title 'Hold: block on an incline tilted at 0.02 rad/s, 2-D law quinn, dt 1e-4'\n"
    "set xlabel 'tilt (degrees)'; set ylabel 'speed |v| (m/s)'\n"
    "set key top left\n"
    "set arrow 1 from 28.3024641, graph 0 to 28.3024641, graph 1 nohead dashtype 2 lc 'black'\n"
    "plot 'hold_breakaway.csv' using 2:3 with lines lw 2 title 'speed (exactly 0 until "
    "break-away)', NaN with lines dashtype 2 lc 'black' title 'atan(mu) = 28.3025 deg'\n"
    "unset arrow 1\n"
    "set output outdir.'belt_limit_cycle.png'\n"
    "set title 'Belt-driven Stribeck oscillator: 12th cycle, RK4 dt 0.0025, eps 0.005'\n"
    "set xlabel 'x'; set ylabel 'dx/dt'\n"
    "set key center\n"
    "plot 'belt_limit_cycle.csv' using ($1 == 1 ? $3 : NaN):4 with lines lw 3 "
    "title 'event-driven reference', '' using ($1 == 0 ? $3 : NaN):4 every 15 with points "
    "pt 6 ps 1 title 'Stribeck law, regularized (every 15th step)'\n"
    "set output outdir.'disk_oscillator.png'\n"
    "set title '2-D oscillator, forcing along a rotating direction: one turn, law quinn, dt 0.01'\n"
    "set key top right\n"
    "set xlabel 'x1 (and f1)'; set ylabel 'x2 (and f2)'; set size ratio -1\n"
    "plot 'disk_oscillator.csv' using 2:3 with lines title 'position x', '' using 4:5 with "
    "lines title 'friction force f (|f| <= mu N = 1)'\n"
    "set output outdir.'hb_frf.png'\n"
    "set title 'Harmonic balance, H = 7: 3-dof chain with two Jenkins elements, mass 1'\n"
    "set size noratio; set key top left; set logscale y\n"
    "set xlabel 'excitation frequency Omega (rad/s)'; set ylabel 'RMS displacement of mass 1'\n"
    "plot 'hb_frf.csv' using ($1 == 0 ? $2 : NaN):3 with lines dashtype 2 title "
    "'elements slipping freely (mu N = 0)', '' using ($1 == 1 ? $2 : NaN):3 with lines lw 2 "
    "title 'Jenkins elements (stick-slip)', '' using ($1 == 2 ? $2 : NaN):3 with lines "
    "dashtype 3 title 'elements stuck'\n"
    "unset logscale y\n"
    "set output outdir.'hb_overhang.png'\n"
    "set title 'Harmonic balance, H = 15: gap pair (unilateral spring), Hill stability'\n"
    "set key top left\n"
    "set xlabel 'excitation frequency Omega (rad/s)'; set ylabel 'RMS displacement of mass 1'\n"
    "plot 'hb_overhang.csv' using ($1 == 0 && $5 == 1 ? $2 : NaN):3 with lines lw 2 "
    "title 'stable', '' using ($1 == 0 && $5 == 0 ? $2 : NaN):3 with lines dashtype 2 lw 2 "
    "title 'unstable', '' using ($1 == 1 && $6 == 1 ? $2 : NaN):3 with points pt 7 ps 1.5 "
    "title 'turning points', '' using ($1 == 1 && $6 != 1 ? $2 : NaN):3 with points pt 6 "
    "ps 1.5 title 'other bifurcations (here Neimark-Sacker)'\n"
    "set size noratio\n";

/* Moves the PNGs gnuplot made in the temporary directory tmp (inside dir) to dir, and removes
 * tmp with whatever is left in it. Returns 0 or 1 (message printed). */
static int install_plots(const char *dir, const char *tmp, int made)
{
    int failed = 0;
    for (size_t k = N_CSV; k < N_OUTPUTS; k++) {
        char from[2 * CLI_OUT_PATH];
        snprintf(from, sizeof from, "%s/%s", tmp, outputs[k]);
        if (made && !failed)
            failed = cli_out_install(from, dir, outputs[k]) != 0;
        else
            unlink(from);
    }
    rmdir(tmp);
    return failed;
}

/* PNGs through gnuplot, when it is installed; the CSVs stand on their own without it.
 * Returns 0, or -1 on failure (message printed). */
static int plot(const char *dir)
{
    struct cli_out o;
    FILE *gp = open_in(dir, "plots.gp", &o);
    if (gp == NULL)
        return -1;
    fputs(plot_script, gp);
    if (cli_out_commit(&o) != 0)
        return -1;
    if (system("command -v gnuplot >/dev/null 2>&1") != 0) {
        printf("gnuplot not found: CSVs and %s written, no PNGs\n", o.path);
        return 0;
    }
    char tmp[CLI_OUT_PATH], command[3 * CLI_OUT_PATH];
    snprintf(tmp, sizeof tmp, "%s/.fricreg-plots.XXXXXX", dir);
    if (mkdtemp(tmp) == NULL) {
        fprintf(stderr, "fricreg-sim: reproduce: cannot create %s: %s\n", tmp, strerror(errno));
        return -1;
    }
    /* "--" and the quotes: a directory named like an option or with spaces is still one. */
    snprintf(command, sizeof command, "cd -- '%s' && gnuplot -e \"outdir='%s/'\" plots.gp", dir,
             strrchr(tmp, '/') + 1);
    int made = system(command) == 0;
    if (!made)
        fprintf(stderr, "fricreg-sim: reproduce: gnuplot failed on %s: no PNGs\n", o.path);
    int failed = install_plots(dir, tmp, made);
    return made && !failed ? 0 : -1;
}

/* --out: a directory, created if absent, where no file reproduce writes belongs to the user
 * (out_file.h). Returns 0 or CLI_EXIT_USAGE (message printed). */
static int check_out_dir(const char *dir)
{
    struct stat st;
    if (dir == NULL || *dir == '\0' || strchr(dir, '\'') != NULL || strchr(dir, '"') != NULL) {
        fprintf(stderr, "fricreg-sim: --out: a directory name is required (no quotes)\n");
        return CLI_EXIT_USAGE;
    }
    if (mkdir(dir, 0777) != 0 && errno != EEXIST) {
        fprintf(stderr, "fricreg-sim: --out: cannot create %s: %s\n", dir, strerror(errno));
        return CLI_EXIT_USAGE;
    }
    if (stat(dir, &st) != 0 || !S_ISDIR(st.st_mode)) {
        fprintf(stderr, "fricreg-sim: --out: %s is not a directory\n", dir);
        return CLI_EXIT_USAGE;
    }
    for (size_t k = 0; k < N_OUTPUTS; k++)
        if (!cli_out_may_replace(dir, outputs[k]))
            return CLI_EXIT_USAGE;
    return cli_out_may_replace(dir, CLI_OUT_MANIFEST) ? 0 : CLI_EXIT_USAGE;
}

/* The rows over dir: the parser's and the help's one table. */
static size_t reproduce_table(const char **dir, struct cli_option table[])
{
    *dir = NULL;
    const struct cli_option opts[] = {
        {"--out", CLI_FILE, .slot = dir, .meta = "DIR",
         .help = "the folder for the CSV files, plots.gp, the PNGs (with gnuplot) and the "
                 "manifest; created if absent, and no file in it not written by reproduce is "
                 "replaced (required)"}};
    return cli_copy_rows(table, opts, sizeof opts / sizeof opts[0]);
}

static size_t reproduce_help_table(struct cli_option table[])
{
    static const char *dir; /* the help's row points here */
    return reproduce_table(&dir, table);
}

const struct cli_command cli_reproduce_command = {
    "reproduce", "--out DIR", "the paper's experiments: CSVs, plots and a comparison table",
    "Runs the experiments of Quinn (2004), Figs. 5, 6, 9 and 11, and the problems beyond the "
    "paper (hold, belt, disk, hb): a CSV per figure in DIR, a PNG per figure when gnuplot is "
    "installed, and on standard output a table of each paper number beside ours "
    "(docs/reproduction.md).",
    reproduce_help_table};

int cli_reproduce(int argc, char **argv)
{
    const char *dir = NULL;
    struct cli_option table[CLI_MAX_ROWS];
    size_t rows = reproduce_table(&dir, table);
    int status = cli_parse_options(argc, argv, table, rows, "reproduce");
    if (status == 0)
        status = check_out_dir(dir);
    if (status != 0)
        return status;
    printf("fricreg %s: reproduction of Quinn (2004), RK4, paper's eps rules; files in %s\n\n",
           fricreg_version(), dir);
    printf("%-7s %-44s %-16s %-12s %s\n", "figure", "quantity", "paper", "ours", "difference");
    int failed = figure5(dir) || figure6(dir) || figure9(dir) || figure11(dir) ||
                 cli_reproduce_beyond(dir);
    if (failed)
        return CLI_EXIT_RUN;
    putchar('\n');
    int plotted = plot(dir);
    /* The manifest lists the outputs now in dir, so that a rerun may replace exactly those:
     * each was written by this run, or listed before (check_out_dir refused any other). */
    const char *present[N_OUTPUTS];
    size_t n = 0;
    for (size_t k = 0; k < N_OUTPUTS; k++) {
        char path[CLI_OUT_PATH];
        struct stat st;
        snprintf(path, sizeof path, "%s/%s", dir, outputs[k]);
        if (lstat(path, &st) == 0 && S_ISREG(st.st_mode))
            present[n++] = outputs[k];
    }
    if (cli_out_write_manifest(dir, present, n) != 0)
        return CLI_EXIT_RUN;
    return plotted == 0 ? 0 : CLI_EXIT_RUN;
}
