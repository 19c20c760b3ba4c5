/* SPDX-License-Identifier: GPL-3.0-or-later */
/* fuzz_exact.c — fuzz target: the exact solver's object API (include/fricreg_exact.h) with
 * arbitrary parameters and run lengths, held to the header: statuses in the documented sets,
 * the solution held kept (end time, switches) when a run fails, caller arrays untouched on
 * failure; on success the end time and period as asked, increasing switching times in
 * (0, t_end] (a stick may follow a stick: a slip phase of zero length between them, where
 * |f_eq| touches mun, is not listed), the initial state at t = 0, the force balance
 * at rest (|x - a sin(omega t)| <= mun in every stick phase, where x' = 0), dissipation per
 * cycle >= 0, stick fraction in [0, 1].
 *
 * The run length is capped: a run is made only when the header says it is refused before any
 * work (t_end NaN, Inf, <= 0 or over 10^6 cycles), or when its scan is short, t_end max(1,
 * omega) <= 16 (about 2600 scan points), at most 4 runs per input: the solver's work is bounded
 * (the limits of fricreg_exact.h), but a long run is slow, and fuzzing wants many short ones. */
#include "fuzz_input.h"

#include "fricreg_exact.h"

#define CODE(c) (1u << (c))
#define TWO_PI 6.283185307179586
#define WORK_CAP 16.0
#define MAX_RUNS 4

static void require(int status, unsigned allowed, const char *call)
{
    FUZZ_REQUIRE(status == FRICREG_OK || (status > 0 && status < 32 && (allowed >> status & 1u)),
                 "%s: status %d (%s) not documented", call, status, fricreg_strerror(status));
}

/* Refused before any work, by the header's own rules. */
static int refused_t_end(double t_end, double omega)
{
    return !isfinite(t_end) || !(t_end > 0.0) || t_end * omega / TWO_PI > 1e6;
}

static int affordable(double t_end, double omega)
{
    return t_end * fmax(1.0, omega) <= WORK_CAP;
}

static void check_solution(fricreg_exact *ex, double a, double omega, double mun, double x0,
                           double v0, double t_end)
{
    double value = NAN;
    FUZZ_REQUIRE(fricreg_exact_get_value(ex, FRICREG_EXACT_VALUE_TIME, &value) == FRICREG_OK &&
                     value == t_end,
                 "TIME %g, ran to %g", value, t_end);
    FUZZ_REQUIRE(fricreg_exact_get_value(ex, FRICREG_EXACT_VALUE_PERIOD, &value) == FRICREG_OK &&
                     (value == TWO_PI / omega || fabs(value - TWO_PI / omega) <= 1e-15 * value),
                 "PERIOD %g, omega %g", value, omega);
    double x, v;
    int status = fricreg_exact_state(ex, 0.0, &x, &v);
    FUZZ_REQUIRE(status == FRICREG_OK, "state(0): %d", status);
    double scale = fabs(x0) + fabs(v0) + fabs(a) + mun;
    FUZZ_REQUIRE(fabs(x - x0) <= 1e-9 * scale && fabs(v - v0) <= 1e-9 * scale,
                 "state(0) (%.17g, %.17g), start (%.17g, %.17g)", x, v, x0, v0);

    size_t n = fricreg_exact_nswitches(ex);
    if (n > 4096)
        return; /* the checks below are O(n) each: keep the target fast */
    double *times = malloc((n + 1) * sizeof *times);
    int *sticks = malloc((n + 1) * sizeof *sticks);
    if (times == NULL || sticks == NULL) {
        free(times), free(sticks);
        return;
    }
    fuzz_fill(times, (n + 1) * sizeof *times);
    status = fricreg_exact_switches(ex, n + 1, times, sticks);
    FUZZ_REQUIRE(status == FRICREG_ESIZE && fuzz_untouched(times, (n + 1) * sizeof *times),
                 "switches(n + 1): %d", status);
    status = fricreg_exact_switches(ex, n, times, sticks);
    FUZZ_REQUIRE(status == FRICREG_OK, "switches: %d", status);
    for (size_t k = 0; k < n; k++) {
        FUZZ_REQUIRE(times[k] > 0.0 && times[k] <= t_end && (k == 0 || times[k] > times[k - 1]),
                     "switch %zu at %.17g (t_end %g)", k, times[k], t_end);
        FUZZ_REQUIRE(sticks[k] == 0 || sticks[k] == 1, "sticks[%zu] = %d", k, sticks[k]);
    }
    /* the force balance in the middle of every stick phase */
    for (size_t k = 0; k < n; k++) {
        if (!sticks[k])
            continue;
        double t = k + 1 < n ? 0.5 * (times[k] + times[k + 1]) : 0.5 * (times[k] + t_end);
        status = fricreg_exact_state(ex, t, &x, &v);
        FUZZ_REQUIRE(status == FRICREG_OK, "state(%g): %d", t, status);
        double f_eq = x - a * sin(omega * t);
        FUZZ_REQUIRE(v == 0.0, "stick phase %zu: v(%g) = %g", k, t, v);
        /* relative to the motion's scale, and 1e-300 absolute: a motion of amplitude near
         * DBL_MIN (x0 = 2.2e-308, mun = 0) is at rest to underflow */
        FUZZ_REQUIRE(fabs(f_eq) <= mun + 1e-8 * (mun + fabs(x) + fabs(a)) + 1e-300,
                     "stick phase %zu at t %.17g: |f_eq| = %.17g > mun %.17g", k, t, fabs(f_eq),
                     mun);
    }
    free(times);
    free(sticks);

    size_t nc = fricreg_exact_ncycles(ex);
    double expected = floor(t_end * omega / TWO_PI);
    FUZZ_REQUIRE(fabs((double)nc - expected) <= 1.0, "ncycles %zu, t_end/T %g", nc, expected);
    if (nc <= 4096) {
        double *D = malloc((nc + 1) * sizeof *D);
        if (D != NULL) {
            fuzz_fill(D, (nc + 1) * sizeof *D);
            status = fricreg_exact_dissipation(ex, nc + 1, D);
            FUZZ_REQUIRE(status == FRICREG_ESIZE && fuzz_untouched(D, (nc + 1) * sizeof *D),
                         "dissipation(nc + 1): %d", status);
            status = fricreg_exact_dissipation(ex, nc, D);
            FUZZ_REQUIRE(status == FRICREG_OK, "dissipation: %d", status);
            for (size_t k = 0; k < nc; k++)
                FUZZ_REQUIRE(D[k] >= 0.0, "D[%zu] = %g", k, D[k]);
            free(D);
        }
    }
    double fraction = NAN;
    status = fricreg_exact_stick_fraction(ex, 0.0, t_end, &fraction);
    FUZZ_REQUIRE(status == FRICREG_OK && fraction >= 0.0 && fraction <= 1.0,
                 "stick_fraction: %d, %g", status, fraction);
    fuzz_fill(&fraction, sizeof fraction);
    status = fricreg_exact_stick_fraction(ex, t_end, 0.0, &fraction);
    FUZZ_REQUIRE(status == FRICREG_EINVAL && fuzz_untouched(&fraction, sizeof fraction),
                 "stick_fraction(t_end, 0): %d", status);
    for (int which = -1; which <= 3; which++) {
        int64_t count;
        fuzz_fill(&count, sizeof count);
        status = fricreg_exact_get_stat(ex, which, &count);
        int known = which >= 0 && which <= FRICREG_EXACT_STAT_ROOT_ITERS;
        FUZZ_REQUIRE(status == (known ? FRICREG_OK : FRICREG_EINVAL), "get_stat(%d)", which);
        FUZZ_REQUIRE(known ? count >= 0 : fuzz_untouched(&count, sizeof count), "stat %d", which);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    struct fuzz_input in = {data, size, 0};
    double a = fuzz_double(&in), omega = fuzz_double(&in), mun = fuzz_double(&in);
    double x0 = fuzz_double(&in), v0 = fuzz_double(&in);
    fricreg_exact *ex = NULL;
    int status = fricreg_exact_create(a, omega, mun, x0, v0, &ex);
    require(status, CODE(FRICREG_ENONFINITE) | CODE(FRICREG_EINVAL) | CODE(FRICREG_ENOMEM),
            "create");
    int valid = isfinite(a) && isfinite(omega) && isfinite(mun) && isfinite(x0) && isfinite(v0) &&
                omega > 0.0 && mun >= 0.0;
    if (status != FRICREG_OK) {
        FUZZ_REQUIRE(ex == NULL, "create wrote out on failure");
        FUZZ_REQUIRE(!valid || status == FRICREG_ENOMEM, "create refused valid parameters: %d",
                     status);
        return 0;
    }
    FUZZ_REQUIRE(valid, "create took a %g w %g mun %g x0 %g v0 %g", a, omega, mun, x0, v0);
    FUZZ_REQUIRE(fricreg_exact_state(ex, 0.0, &(double){0}, &(double){0}) == FRICREG_EINVAL,
                 "state before any run");
    double held = 0.0; /* end time of the solution held */
    for (int runs = 0; runs < MAX_RUNS && !fuzz_done(&in); runs++) {
        uint8_t op = fuzz_byte(&in);
        double t_end;
        size_t n_before = fricreg_exact_nswitches(ex);
        if (op & 1) {
            int cycles = fuzz_int(&in, -1, 8);
            t_end = cycles * (TWO_PI / omega);
            if (cycles >= 1 && cycles <= 1000000 && !affordable(t_end, omega))
                continue;
            status = fricreg_exact_run_cycles(ex, cycles);
            FUZZ_REQUIRE(status != FRICREG_OK || (cycles >= 1 && cycles <= 1000000),
                         "run_cycles took %d", cycles);
            if (status == FRICREG_OK)
                FUZZ_REQUIRE(fricreg_exact_ncycles(ex) == (size_t)cycles, "ncycles after %d",
                             cycles);
        } else {
            t_end = fuzz_double(&in);
            if (!refused_t_end(t_end, omega) && !affordable(t_end, omega))
                continue;
            status = fricreg_exact_run(ex, t_end);
            FUZZ_REQUIRE(status != FRICREG_OK || !refused_t_end(t_end, omega), "run took t_end %g",
                         t_end);
        }
        require(status,
                CODE(FRICREG_ENONFINITE) | CODE(FRICREG_EINVAL) | CODE(FRICREG_ENOMEM) |
                    CODE(FRICREG_EINTEGRATOR) | CODE(FRICREG_EDIVERGED),
                "run");
        if (status != FRICREG_OK) {
            double kept = NAN;
            fricreg_exact_get_value(ex, FRICREG_EXACT_VALUE_TIME, &kept);
            FUZZ_REQUIRE(kept == held && fricreg_exact_nswitches(ex) == n_before,
                         "failed run changed the solution held");
            FUZZ_REQUIRE(fricreg_exact_errcode(ex) == status && fricreg_exact_errmsg(ex)[0],
                         "failed run: errcode %d, message '%s'", fricreg_exact_errcode(ex),
                         fricreg_exact_errmsg(ex));
            continue;
        }
        fricreg_exact_get_value(ex, FRICREG_EXACT_VALUE_TIME, &held);
        check_solution(ex, a, omega, mun, x0, v0, held);
    }
    fricreg_exact_free(ex);
    return 0;
}
