/* SPDX-License-Identifier: GPL-3.0-or-later */
/* main.c — fricreg-sim: runs the paper's reference systems from the command line. */
#include <errno.h>
#include <signal.h>
#include <string.h>

#include <gsl/gsl_errno.h>

#include "cli.h"

/* The law and integrator names come from the library (fricreg_law_name,
 * fricreg_integrator_name); their defaults from the parser's (no options given). */
static void usage(FILE *out)
{
    char names[256];
    struct cli_run defaults;
    cli_parse_run(FRICREG_SYSTEM_OSCILLATOR, 0, NULL, &defaults);
    fputs("usage: fricreg-sim oscillator|chain|twoblock [options]\n"
          "       fricreg-sim exact [--a --omega --mun --x0 --v0] [--t-end T | --cycles N]\n"
          "       fricreg-sim reproduce --out DIR\n"
          "       fricreg-sim structure --mass M.mtx --stiffness K.mtx [--damping C.mtx |\n"
          "           --rayleigh A0,A1] --contacts J.mtx --mun MUN.txt [--influence R.mtx]\n"
          "           [--ground-accel FILE] [--jenkins J.mtx ELEMENTS |\n"
          "           --jenkins-2d J2.mtx --jenkins-params P.txt] [--law L]\n"
          "           [--eps E] --integrator newmark|hht|central|<GSL stepper> [--alpha A]\n"
          "           [--rtol R --atol A] --dt DT --t-end T [--max-steps N]\n"
          "           [--output summary|trajectory]   (docs/structural.md)\n"
          "       fricreg-sim hb --mass M.mtx --stiffness K.mtx [--damping C.mtx |\n"
          "           --rayleigh A0,A1] --excitation F.txt --jenkins J.mtx ELEMENTS\n"
          "           [--harmonics H] --omega-start W0 --omega-end W1 [--newton-tol TOL]\n"
          "           [--newton-max N] [--ds DS] [--ds-min DS] [--ds-max DS] [--max-points N]\n"
          "           [--output summary|frf]   harmonic balance (docs/joints.md)\n"
          "         ELEMENTS, one line per row of J.mtx (the element's q = J x):\n"
          "           --jenkins-params P.txt      Jenkins: kt mun\n"
          "           --iwan-params P.txt         Iwan: k_1 phi_1 ... k_ns phi_ns, same ns on\n"
          "                                       every line\n"
          "           --iwan-segalman S.txt [--iwan-sliders NS] [--iwan-resolution R]\n"
          "                                       Iwan, Segalman's F_S K_T chi beta in NS\n"
          "                                       sliders [50] down to R phi_max [1e-6]\n"
          "           --normal Jn.mtx --normal-params Q.txt   lift-off: kt mu n0 kn, the normal\n"
          "                                       g = Jn x, N = max(0, n0 + kn g)\n"
          "         --jenkins-2d J2.mtx (structure only): 2-D elements, element i on rows\n"
          "           2i-1 (x) and 2i (y) of J2.mtx, a line kt mun per element (isotropic)\n"
          "       fricreg-sim hold [--mu --mass --g --theta-deg --phi-deg --dt --eps --steps]\n"
          "           [--tilt-rate DEG_PER_S]   block on an incline: creep (m/s), break-away\n"
          "       fricreg-sim belt [--fs --fk --vs --delta --v-belt --dt --eps --cycles --ref-dt]\n"
          "           Stribeck belt oscillator: limit-cycle period, amplitude vs event-driven\n"
          "       fricreg-sim disk [--law quinn|quinn-lens|quinn-nested|coulomb|force-balance]\n"
          "           [--a --omega --dt --eps --ref-eps]   2-D oscillator, D per forcing cycle\n"
          "           (these three: --output summary|trajectory; docs/laws2d.md)\n"
          "       fricreg-sim --help | --version\n"
          "\n"
          "Common options (defaults in brackets):\n",
          out);
    fprintf(out, "  --law %s   [%s]\n", cli_names(names, sizeof names, fricreg_law_name, "|"),
            fricreg_law_name(defaults.law));
    fprintf(out, "  --integrator %s [%s]\n",
            cli_names(names, sizeof names, fricreg_integrator_name, "|"),
            fricreg_integrator_name(defaults.integrator));
    fputs("  --dt STEP        fixed step, or the first step when adaptive          [0.01]\n"
          "  --rtol R --atol A  adaptive step control (both 0: fixed step); without\n"
          "                     --atol, velocities to min(1e-3 eps, R), x and D to R  [0 eps]\n"
          "                     (structure: 1e-3 eps / sum_k |J_ik| where read)\n"
          "  --eps EPS        regularization; default 2dt, or 10*omega*dt for chain\n"
          "  --t-end T | --cycles N   run length in time or forcing cycles         [--cycles 4]\n"
          "  --output summary|trajectory   JSON summary, or CSV row per step       [summary]\n"
          "  --extrapolate LEVELS   also run at eps/2 … eps/2^(LEVELS-1) and add D extrapolated\n"
          "                   to eps -> 0, with its error estimate, to the summary (2 … 8)\n"
          "  --extrapolate-order P   the leading order in eps where the levels show none\n"
          "                   (2 levels), 0 … 4                                     [0: 1]\n"
          "  --extrapolate-window W  the finer levels over the last W cycles only, from\n"
          "                   the state of the first level there (0: the whole run)  [0]\n"
          "  --max-steps N    adaptive steps a forcing cycle may take (0: no bound)\n"
          "                   [10^4 for coulomb, force-balance, karnopp; else 10^6]\n"
          "  --kink-location on|off   adaptive steps stop at the friction law's kinks and\n"
          "                   restart the stepper there (docs/integrators.md)      [on]\n"
          "  --error-estimate on|off   one companion run at eps/2 (dt/2, or tolerances/16)\n"
          "                   adds dissipation_error_estimate per cycle, ~3x the cost [on]\n",
          out);
    cli_print_param_defaults(out);
    fputs("            --partition paper|consistent  coupled contacts' near-stick law "
          "[consistent]\n",
          out);
    cli_print_problem_defaults(out);
    fputs("Exit status: 0 success, 1 the simulation failed or its output could not be written\n"
          "(the message names the file), 2 bad option or value (run lengths and --out included).\n",
          out);
}

static int system_of(const char *name)
{
    if (strcmp(name, "oscillator") == 0)
        return FRICREG_SYSTEM_OSCILLATOR;
    if (strcmp(name, "chain") == 0)
        return FRICREG_SYSTEM_CHAIN;
    if (strcmp(name, "twoblock") == 0)
        return FRICREG_SYSTEM_TWOBLOCK;
    return 0;
}

static int dispatch(int argc, char **argv);

/* --help or -h anywhere after a subcommand asks for the usage text, as it does before one
 * (no number, name or sensible file name is spelled so; before, it was a "missing value"). */
static int wants_help(int argc, char **argv)
{
    for (int k = 2; k < argc; k++)
        if (strcmp(argv[k], "--help") == 0 || strcmp(argv[k], "-h") == 0)
            return 1;
    return 0;
}

/* Every byte written reaches its file, or the exit status says it did not: stdout's last
 * buffer is flushed and closed here, and a file-size limit fails a write (EFBIG) instead of
 * killing the program with SIGXFSZ. */
int main(int argc, char **argv)
{
    signal(SIGXFSZ, SIG_IGN);
    int status = dispatch(argc, argv);
    if (fflush(stdout) != 0 || ferror(stdout)) {
        fprintf(stderr, "fricreg-sim: writing standard output: %s\n", strerror(errno));
        fclose(stdout);
        return status ? status : CLI_EXIT_RUN;
    }
    if (fclose(stdout) != 0) {
        fprintf(stderr, "fricreg-sim: closing standard output: %s\n", strerror(errno));
        return status ? status : CLI_EXIT_RUN;
    }
    return status;
}

static int dispatch(int argc, char **argv)
{
    /* The program's own choice (docs/reliability.md): GSL reports by status, never aborts —
     * memory running out inside a GSL stepper. */
    gsl_set_error_handler_off();
    if (argc < 2) {
        usage(stderr);
        return CLI_EXIT_USAGE;
    }
    if (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0 || wants_help(argc, argv)) {
        usage(stdout);
        return 0;
    }
    if (strcmp(argv[1], "--version") == 0) {
        printf("fricreg-sim %s\n", fricreg_version());
        return 0;
    }
    if (strcmp(argv[1], "reproduce") == 0)
        return cli_reproduce(argc - 2, argv + 2);
    if (strcmp(argv[1], "structure") == 0)
        return cli_structure(argc - 2, argv + 2, stdout);
    if (strcmp(argv[1], "hb") == 0)
        return cli_hb(argc - 2, argv + 2, stdout);
    int problem = cli_problem(argv[1], argc - 2, argv + 2, stdout);
    if (problem >= 0)
        return problem;
    struct cli_run run;
    if (strcmp(argv[1], "exact") == 0) {
        int status = cli_parse_exact(argc - 2, argv + 2, &run);
        return status ? status : cli_exact_summary(&run, stdout);
    }
    int system = system_of(argv[1]);
    if (system == 0) {
        fprintf(stderr, "fricreg-sim: %s: unknown command (see fricreg-sim --help)\n", argv[1]);
        return CLI_EXIT_USAGE;
    }
    int status = cli_parse_run(system, argc - 2, argv + 2, &run);
    if (status != 0)
        return status;
    return run.output == CLI_SUMMARY ? cli_run_summary(&run, stdout)
                                     : cli_run_trajectory(&run, stdout);
}
