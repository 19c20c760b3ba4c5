/* SPDX-License-Identifier: GPL-3.0-or-later */
/* fuzz_cli_problems.c — fuzz target: the option parsers of `fricreg-sim hold|belt|disk`
 * (src/cli/problems.c, cli_problems.h), without the runs. The input's first byte picks the
 * subcommand; the rest is argv, one argument per line. Contract (problems.c and the usage
 * text): the status is 0 or CLI_EXIT_USAGE (2), never a crash or undefined behaviour (UBSan);
 * on success every parameter is finite and in its option's range, the derived ones too
 * (hold's tilt below 90 degrees, an even whole number of steps from 2 to 10^9; belt's
 * fk <= fs and a whole number of cycles from 2 to 1000), the run is at most 10^9 steps, the
 * RK4 step is inside the stick zone's stability bound (dt 2 bound/(m eps) <= 2.78), and eps
 * is one the library's laws take (DBL_MIN <= eps, and eps <= 1e250 for the 2-D laws of hold
 * and disk), so that no run is refused by the library for a value the parser let through. */
#include <math.h>

#include "fuzz_argv.h"
#include "fuzz_input.h"

#include "cli_problems.h"
#include "fricreg_disk.h"

#define PI 3.14159265358979323846
#define RK4_STABLE 2.78

static int positive(double x)
{
    return isfinite(x) && x > 0.0;
}

/* eps as the laws take it: at least DBL_MIN, and at most 1e250 for the 2-D laws
 * (fricreg_disk.h; the belt's 1-D Stribeck law has no upper limit). */
static void check_eps(const char *who, double eps, double upper)
{
    FUZZ_REQUIRE(isfinite(eps) && eps >= DBL_MIN && eps <= upper, "%s: eps %g", who, eps);
}

static void check_stable(const char *who, double bound_per_mass, double dt, double eps)
{
    FUZZ_REQUIRE(2.0 * bound_per_mass / eps * dt <= RK4_STABLE, "%s: dt %g eps %g bound %g", who,
                 dt, eps, bound_per_mass);
}

static void check_hold(const struct prob_hold *p)
{
    FUZZ_REQUIRE(positive(p->mass) && positive(p->g) && positive(p->mu) && positive(p->dt),
                 "hold: mass %g g %g mu %g dt %g", p->mass, p->g, p->mu, p->dt);
    check_eps("hold", p->eps, 1e250);
    FUZZ_REQUIRE(isfinite(p->theta0) && p->theta0 >= 0.0 && p->theta0 < 0.5 * PI, "hold: theta0 %g",
                 p->theta0);
    FUZZ_REQUIRE(isfinite(p->phi) && isfinite(p->kappa) && p->kappa >= 0.0, "hold: phi %g kappa %g",
                 p->phi, p->kappa);
    FUZZ_REQUIRE(p->steps == floor(p->steps) && p->steps >= 2.0 && p->steps <= 1e9 &&
                     fmod(p->steps, 2.0) == 0.0,
                 "hold: steps %g", p->steps);
    check_stable("hold", p->mu * p->g, p->dt, p->eps);
}

static void check_belt(const struct prob_belt *p)
{
    FUZZ_REQUIRE(positive(p->fs) && isfinite(p->fk) && p->fk >= 0.0 && p->fk <= p->fs,
                 "belt: fs %g fk %g", p->fs, p->fk);
    FUZZ_REQUIRE(positive(p->vs) && positive(p->delta) && positive(p->v_belt) && positive(p->dt) &&
                     positive(p->ref_dt),
                 "belt: vs %g delta %g v_belt %g dt %g ref_dt %g", p->vs, p->delta, p->v_belt,
                 p->dt, p->ref_dt);
    check_eps("belt", p->eps, DBL_MAX);
    FUZZ_REQUIRE(p->cycles >= 2 && p->cycles <= 1000, "belt: cycles %d", p->cycles);
    double length = (p->cycles + 1) * (2.0 * PI + 2.0 * p->fs / p->v_belt);
    FUZZ_REQUIRE(length / p->dt <= 1e9 && length / p->ref_dt <= 1e9,
                 "belt: length %g, dt %g ref_dt %g", length, p->dt, p->ref_dt);
    check_stable("belt", p->fs, p->dt, p->eps);
}

static void check_disk(const struct prob_disk *p, double ref_eps)
{
    FUZZ_REQUIRE(fricreg_disk_law_name(p->law) != NULL, "disk: law %d", p->law);
    FUZZ_REQUIRE(positive(p->a) && positive(p->omega) && positive(p->dt),
                 "disk: a %g omega %g dt %g", p->a, p->omega, p->dt);
    check_eps("disk", p->eps, 1e250);
    FUZZ_REQUIRE(isfinite(ref_eps) && ref_eps >= 0.0, "disk: ref_eps %g", ref_eps);
    if (ref_eps > 0.0)
        check_eps("disk reference", ref_eps, 1e250);
    double turns = (p->turns_transient + 1) * 2.0 * PI * p->cycles_per_turn / p->omega;
    FUZZ_REQUIRE(turns / p->dt <= 1e9 && (ref_eps == 0.0 || turns / (0.5 * ref_eps) <= 1e9),
                 "disk: %g turns' time, dt %g ref_eps %g", turns, p->dt, ref_eps);
    check_stable("disk", 1.0, p->dt, p->eps);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size == 0)
        return 0;
    static struct fuzz_argv a;
    fuzz_argv_split(data, size, 1, &a);
    enum cli_output output = CLI_SUMMARY;
    struct cli_estimate_options estimate = {FRICREG_ESTIMATE_OFF, 0.0};
    int status;
    switch (data[0] % 3) {
    case 0: {
        struct prob_hold p;
        if ((status = cli_parse_hold(a.argc, a.argv, &p, &output, &estimate)) == 0)
            check_hold(&p);
        break;
    }
    case 1: {
        struct prob_belt p;
        if ((status = cli_parse_belt(a.argc, a.argv, &p, &output, &estimate)) == 0)
            check_belt(&p);
        break;
    }
    default: {
        struct prob_disk p;
        double ref_eps = -1.0;
        if ((status = cli_parse_disk(a.argc, a.argv, &p, &ref_eps, &output, &estimate)) == 0)
            check_disk(&p, ref_eps);
    }
    }
    FUZZ_REQUIRE(status == 0 || status == CLI_EXIT_USAGE, "parse: status %d", status);
    FUZZ_REQUIRE(status != 0 || output == CLI_SUMMARY || output == CLI_TRAJECTORY, "output %d",
                 (int)output);
    FUZZ_REQUIRE(status != 0 || (estimate.estimator >= FRICREG_ESTIMATE_OFF &&
                                 estimate.estimator <= FRICREG_ESTIMATE_ONE_COMPANION),
                 "estimator %d", estimate.estimator);
    /* the library's setters take the answer tolerance finite and > 0 */
    FUZZ_REQUIRE(status != 0 || (estimate.answer_rtol > 0.0 && isfinite(estimate.answer_rtol)),
                 "answer_rtol %g", estimate.answer_rtol);
    return 0;
}
