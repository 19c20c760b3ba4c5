/* SPDX-License-Identifier: GPL-3.0-or-later */
/* structure_run.c — `fricreg-sim structure`: a linear structure with friction contacts
 * (fricreg_structure.h) from Matrix Market files, run with Newmark, HHT-alpha, central
 * difference or one of GSL's steppers; a JSON summary or a CSV row per step on stdout.
 * Every bad option or file is one line on stderr naming it, exit 2, nothing on stdout. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "dof_list.h"
#include "structure_checkpoint.h"
#include "structure_model.h"
#include "structure_steps.h"
#include "structure_summary.h"

/* ---- Setting up the structure ------------------------------------------------------------ */

/* The default eps, 1 % of the ground's peak velocity |integral of a_g| as the library computes
 * it for its warnings (a velocity scale known before the run; docs/structural.md, "Choosing
 * eps"), or the library's 1e-3 without motion. */
static double default_eps(const fricreg_structure *s)
{
    double peak = 0.0;
    fricreg_structure_get_value(s, FRICREG_SVALUE_GROUND_PGV, &peak);
    return peak > 0.0 ? 0.01 * peak : 1e-3;
}

static int set_scheme(fricreg_structure *s, const struct structure_options *o)
{
    int status = FRICREG_OK;
    if (o->scheme == SCHEME_HHT && (status = fricreg_structure_set_hht(s, o->alpha)) != 0)
        return cli_usage_error("--alpha", fricreg_structure_errmsg(s));
    if (o->scheme == SCHEME_CENTRAL)
        status = fricreg_structure_set_central_difference(s);
    return status == FRICREG_OK ? 0 : cli_usage_error("--integrator", fricreg_structure_errmsg(s));
}

static int setup(const struct structure_options *o, const struct structure_input *in,
                 fricreg_structure *s, double *eps)
{
    int status = cli_set_model(o, in, s);
    if (status != 0)
        return status;
    *eps = o->eps > 0.0 ? o->eps : default_eps(s);
    int law_status = fricreg_structure_set_law(s, o->law, *eps);
    if (law_status != FRICREG_OK && o->eps > 0.0)
        return cli_usage_error("--eps", fricreg_structure_errmsg(s));
    if (law_status != FRICREG_OK) { /* the default, from the record: name the record */
        char why[320];
        snprintf(why, sizeof why,
                 "the default eps, 1 %% of the record's peak ground velocity, is %g, which the "
                 "law refuses (%s): check the record's times, or give --eps",
                 *eps, fricreg_structure_errmsg(s));
        return cli_usage_error("--ground-accel", why);
    }
    /* The library's error estimate (companions at eps / 2 and eps / 4 along dt, or an adaptive
     * run's tolerances; one with --error-estimate one): the summary's only, a trajectory has
     * no place for it. */
    if (o->error_estimate && o->output == CLI_SUMMARY) {
        fricreg_structure_set_error_estimate(s, o->error_estimate);
        fricreg_structure_set_error_companions(s, o->error_companions); /* the parser's */
    }
    fricreg_structure_set_answer_rtol(s, o->answer_rtol);       /* > 0 and finite: the parser's */
    fricreg_structure_set_contact_solver(s, o->contact_solver); /* one of the words' */
    return set_scheme(s, o);
}

/* ---- Running ------------------------------------------------------------------------------ */

/* A refused step size is a bad --dt (exit 2); any other failure of the run exits 1. */
static int run_failed(const fricreg_structure *s, int status)
{
    double t = cli_structure_value(s, FRICREG_SVALUE_TIME);
    if (status == FRICREG_ESTEP) {
        fprintf(stderr, "fricreg-sim: --dt: %s\n", fricreg_structure_errmsg(s));
        return CLI_EXIT_USAGE;
    }
    if (status == FRICREG_EWORK) { /* --max-steps bounds the whole run, not one call */
        fprintf(stderr, "fricreg-sim: --max-steps: the run's adaptive steps passed the bound: %s\n",
                fricreg_structure_errmsg(s));
        return CLI_EXIT_RUN;
    }
    fprintf(stderr, "fricreg-sim: structure: the run failed after t = %g: %s\n", t,
            fricreg_structure_errmsg(s));
    return CLI_EXIT_RUN;
}

static void copy_stream(FILE *from, FILE *to)
{
    char chunk[1 << 16];
    size_t got;
    rewind(from);
    while ((got = fread(chunk, 1, sizeof chunk, from)) > 0)
        fwrite(chunk, 1, got, to);
}

/* The dofs and contacts the output shows (--output-dofs, --output-contacts) into run, their
 * lists into *dof and *contact (the caller frees them; NULL: all). 0 or a usage error. */
static int select_output(const struct structure_options *o, const struct structure_input *in,
                         struct structure_run *run, size_t **dof, size_t **contact)
{
    int status = 0;
    if (o->output_dofs != NULL)
        status = cli_expand_dof_list("--output-dofs", &cli_dof_list, o->output_dofs, in->n,
                                     &run->ndof, dof);
    if (status == 0 && o->output_contacts != NULL && strcmp(o->output_contacts, "none") == 0)
        run->ncontact = 0;
    else if (status == 0 && o->output_contacts != NULL)
        status = cli_expand_dof_list("--output-contacts", &cli_contact_list, o->output_contacts,
                                     in->m, &run->ncontact, contact);
    if (status != 0) {
        free(*dof);
        *dof = NULL;
        return status;
    }
    run->dof = *dof;
    run->contact = *contact;
    return 0;
}

/* Runs the set-up structure; the trajectory goes to a temporary file first, so that a failed
 * run writes nothing to out. */
static int run_structure(fricreg_structure *s, const struct structure_options *o,
                         const struct structure_input *in, double eps, FILE *out)
{
    struct structure_run run = {.ndof = in->n,
                                .ncontact = in->m,
                                .m = in->m,
                                .dt = o->dt,
                                .t_end = o->t_end,
                                .every = o->output_every,
                                .s = s};
    size_t *dof = NULL, *contact = NULL;
    int listed = select_output(o, in, &run, &dof, &contact);
    if (listed == 0)
        listed = cli_element_columns_make(o->output_elements, in, &run.elements);
    if (listed != 0) {
        cli_element_columns_free(&run.elements);
        free(dof);
        free(contact);
        return listed;
    }
    /* De: the old options' 2 me, or the sets' D[me] and forces[nforces] */
    double *buf = calloc(3 * in->n + in->mlib + 2 * in->el.m + in->sets.me + in->sets.nforces,
                         sizeof *buf);
    if (buf == NULL) {
        free(dof);
        free(contact);
        cli_element_columns_free(&run.elements);
        return cli_usage_error("structure", "out of memory");
    }
    run.u = buf;
    run.v = buf + in->n;
    run.peak = buf + 2 * in->n;
    run.f = buf + 3 * in->n;
    run.De = in->el.m > 0 || in->sets.me > 0 ? buf + 3 * in->n + in->mlib : NULL;
    if (o->output == CLI_TRAJECTORY) {
        if ((run.rows = tmpfile()) == NULL) {
            free(buf);
            free(dof);
            free(contact);
            cli_element_columns_free(&run.elements);
            fprintf(stderr, "fricreg-sim: cannot create a temporary file\n");
            return CLI_EXIT_RUN;
        }
        cli_structure_csv_header(&run);
    }
    clock_t start = clock();
    int status = cli_structure_advance(s, o, in, &run);
    double cpu_seconds = (double)(clock() - start) / CLOCKS_PER_SEC;
    /* The checkpoint before the reads below, which settle auto's screen (the finer companions
     * where it doubts now): the continued run is judged where it is read, as the run in one. */
    int saved = status == FRICREG_OK && o->checkpoint_out != NULL
                    ? cli_checkpoint_out(s, o->checkpoint_out)
                    : 0;
    struct cli_warnings warnings;
    cli_structure_warnings(s, &warnings);
    struct structure_estimate est = {0};
    fricreg_structure_get_peak_displacement(s, in->n, run.peak);
    if (status == FRICREG_OK)
        cli_structure_estimate(s, in, &est);
    if (status != FRICREG_OK)
        status = run_failed(s, status);
    else
        status = saved; /* the run's output only with its checkpoint */
    if (status == 0 && run.rows != NULL)
        copy_stream(run.rows, out);
    else if (status == 0)
        cli_structure_summary(out, o, in, s, &run, eps, cpu_seconds, &warnings, &est);
    free(est.peak_err);
    free(est.peak_kind);
    if (run.rows != NULL)
        fclose(run.rows);
    free(buf);
    free(dof);
    free(contact);
    cli_element_columns_free(&run.elements);
    return status;
}

int cli_structure(int argc, char **argv, FILE *out)
{
    struct structure_options o;
    int status = cli_parse_structure(argc, argv, &o);
    if (status != 0)
        return status;
    struct structure_input in = {0};
    if ((status = cli_read_model(&o, &in)) != 0) {
        cli_free_model(&in);
        return status;
    }
    fricreg_structure *s = NULL;
    if (fricreg_structure_create(in.n, in.mlib, &s) != FRICREG_OK) {
        cli_free_model(&in);
        return cli_usage_error("structure", "cannot create the structure (out of memory)");
    }
    double eps = 0.0;
    status = setup(&o, &in, s, &eps);
    cli_free_matrices(&in);
    if (status == 0 && o.checkpoint_in != NULL)
        status = cli_checkpoint_in(s, &o);
    if (status == 0)
        status = run_structure(s, &o, &in, eps, out);
    fricreg_structure_free(s);
    cli_free_model(&in);
    return status;
}
