/* SPDX-License-Identifier: GPL-3.0-or-later */
/* fuzz_cli_hb.c — fuzz target: what `fricreg-sim hb` and `fricreg-sim nma` parse (src/cli/
 * hb.c, nma.c, cli_hb.h; the model's options of hb_model.h and the elements' of
 * jenkins_input.h), without reading a file or running. The input's first byte picks the
 * subcommand (even: hb, odd: nma); the rest is argv, one argument per line. Contract: the
 * status is 0 or CLI_EXIT_USAGE (2), never a crash, undefined behaviour (UBSan) or leak
 * (ASan); on success the options are complete and consistent: --mass and --stiffness, one
 * element file set (--jenkins with exactly one parameter file, no 2-D rows) or --elements sets
 * (each of a known type) without the element options, not both --damping
 * and --rayleigh (two numbers >= 0), 1 <= H <= FRICREG_HB_MAX_HARMONICS, Newton's tolerance
 * > 0 finite with 1 to 1000 iterations, --max-seconds finite >= 0 where given; hb: --excitation,
 * the continued parameter's own options only (omega: both ends > 0, finite and distinct;
 * level: --omega > 0, both levels >= 0, finite and distinct), step sizes > 0 and finite,
 * 2 <= max_points; nma: 0 < A0 < A1 finite, a mode >= 1, 2 to 2000 points, a known damping
 * option. */
#include "fuzz_argv.h"
#include "fuzz_input.h"

#include "cli_hb.h"

static void check_model(const struct cli_hb_model_options *m, int harmonics, double newton_tol,
                        int newton_max, const struct cli_deadline *d)
{
    FUZZ_REQUIRE(m->mass != NULL && m->stiffness != NULL, "--mass or --stiffness missing");
    FUZZ_REQUIRE(!(m->damping != NULL && m->rayleigh_given), "--damping and --rayleigh");
    FUZZ_REQUIRE(!m->rayleigh_given ||
                     (isfinite(m->a0) && isfinite(m->a1) && m->a0 >= 0.0 && m->a1 >= 0.0),
                 "rayleigh %g %g", m->a0, m->a1);
    const struct cli_element_files *e = &m->elements;
    int files = (e->jenkins != NULL) + (e->iwan != NULL) + (e->segalman != NULL) +
                (e->normal != NULL || e->normal_params != NULL);
    if (m->element_sets.n > 0) { /* --elements: sets of known types, no element option beside */
        FUZZ_REQUIRE(e->rows == NULL && e->rows_2d == NULL && files == 0 &&
                         e->iwan_normal == NULL && !e->sliders_given && !e->resolution_given,
                     "--elements beside the element options");
        for (size_t k = 0; k < m->element_sets.n; k++)
            FUZZ_REQUIRE(m->element_sets.set[k].type != NULL, "set %zu without a type", k);
    } else {
        FUZZ_REQUIRE(e->rows != NULL && e->rows_2d == NULL, "element rows");
        FUZZ_REQUIRE(files == 1, "%d element parameter files", files);
    }
    FUZZ_REQUIRE(harmonics >= 1 && harmonics <= FRICREG_HB_MAX_HARMONICS, "H %d", harmonics);
    FUZZ_REQUIRE(isfinite(newton_tol) && newton_tol > 0.0 && newton_max >= 1 && newton_max <= 1000,
                 "newton %g %d", newton_tol, newton_max);
    FUZZ_REQUIRE(!d->given || (isfinite(d->seconds) && d->seconds >= 0.0), "max-seconds %g",
                 d->seconds);
}

static int positive(double x)
{
    return isfinite(x) && x > 0.0;
}

static void check_hb(const struct hb_options *o)
{
    check_model(&o->model, o->harmonics, o->newton_tol, o->newton_max, &o->deadline);
    FUZZ_REQUIRE(o->excitation != NULL, "--excitation missing");
    FUZZ_REQUIRE(o->output == HB_SUMMARY || o->output == HB_FRF, "output %d", o->output);
    FUZZ_REQUIRE(positive(o->ds) && positive(o->ds_min) && positive(o->ds_max) &&
                     o->max_points >= 2,
                 "steps %g %g %g, points %d", o->ds, o->ds_min, o->ds_max, o->max_points);
    if (o->continue_in == HB_IN_LEVEL) {
        FUZZ_REQUIRE(!o->omega_start_given && !o->omega_end_given && o->omega_given &&
                         positive(o->omega) && o->level_start_given && o->level_end_given,
                     "level's options");
        FUZZ_REQUIRE(isfinite(o->level_start) && isfinite(o->level_end) && o->level_start >= 0.0 &&
                         o->level_end >= 0.0 && o->level_start != o->level_end,
                     "levels %g %g", o->level_start, o->level_end);
    } else {
        FUZZ_REQUIRE(o->continue_in == HB_IN_OMEGA, "continue-in %d", o->continue_in);
        FUZZ_REQUIRE(!o->omega_given && !o->level_start_given && !o->level_end_given &&
                         o->omega_start_given && o->omega_end_given,
                     "omega's options");
        FUZZ_REQUIRE(positive(o->omega_start) && positive(o->omega_end) &&
                         o->omega_start != o->omega_end,
                     "omega %g %g", o->omega_start, o->omega_end);
    }
}

static void check_nma(const struct nma_options *o)
{
    check_model(&o->model, o->harmonics, o->newton_tol, o->newton_max, &o->deadline);
    FUZZ_REQUIRE(o->a0_given && o->a1_given && positive(o->a0) && positive(o->a1) && o->a0 < o->a1,
                 "amplitudes %g %g", o->a0, o->a1);
    FUZZ_REQUIRE(o->mode >= 1 && o->points >= 2 && o->points <= 2000, "mode %d, points %d", o->mode,
                 o->points);
    FUZZ_REQUIRE(o->linear_damping == FRICREG_HB_NMA_DAMPING_MATRIX ||
                     o->linear_damping == FRICREG_HB_NMA_DAMPING_MODAL,
                 "damping %d", o->linear_damping);
    FUZZ_REQUIRE(o->output == NMA_SUMMARY || o->output == NMA_BACKBONE, "output %d", o->output);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size == 0)
        return 0;
    static struct fuzz_argv a;
    fuzz_argv_split(data, size, 1, &a);
    int status;
    if (data[0] % 2 == 0) {
        struct hb_options o;
        status = cli_parse_hb(a.argc, a.argv, &o);
        if (status == 0)
            check_hb(&o);
    } else {
        struct nma_options o;
        status = cli_parse_nma(a.argc, a.argv, &o);
        if (status == 0)
            check_nma(&o);
    }
    FUZZ_REQUIRE(status == 0 || status == CLI_EXIT_USAGE, "parse: status %d", status);
    return 0;
}
