/* SPDX-License-Identifier: GPL-3.0-or-later */
/* structure_summary.c — the JSON summary of `fricreg-sim structure` (structure_summary.h): the
 * library's warnings and estimates read once the run has ended, the per-dof arrays at the dofs
 * shown, the contacts' and the elements' dissipations and forces, the energy balance. */
#include <math.h>
#include <stdlib.h>

#include "base/companion_estimate.h" /* fr_estimate_kind_name */
#include "structure_summary.h"

static int64_t sstat(const fricreg_structure *s, int which)
{
    int64_t v = 0;
    fricreg_structure_get_stat(s, which, &v);
    return v;
}

void cli_structure_warnings(fricreg_structure *s, struct cli_warnings *w)
{
    size_t count = fricreg_structure_warning_count(s);
    w->n = 0;
    for (size_t k = 0; k < count && w->n < 16; k++, w->n++)
        fricreg_structure_get_warning(s, k, &w->code[w->n], w->message[w->n], sizeof w->message[0]);
    cli_print_warnings(w);
}

static const char *scheme_name(const struct structure_options *o)
{
    static const char *const names[] = {"newmark", "hht", "central"};
    return o->scheme == SCHEME_GSL ? fricreg_integrator_name(o->integrator) : names[o->scheme];
}

/* "name": [a at the dofs shown], as cli_json_array. */
static void json_shown(FILE *out, const char *name, const struct structure_run *run,
                       const double a[])
{
    if (run->dof == NULL) {
        cli_json_array(out, name, run->ndof, a);
        return;
    }
    fprintf(out, ", \"%s\": [", name);
    for (size_t k = 0; k < run->ndof; k++) {
        fputs(k > 0 ? ", " : "", out);
        cli_json_number(out, a[run->dof[k]]);
    }
    fputs("]", out);
}

/* ", \"NAME\": [the kinds at the dofs shown]", as json_shown; counted into *c. */
static void kinds_shown(FILE *out, const char *name, const struct structure_run *run,
                        const int kind[], struct cli_kind_counts *c)
{
    if (run->dof == NULL) {
        cli_json_kinds(out, name, run->ndof, kind);
        cli_count_kinds(c, run->ndof, kind);
        return;
    }
    fprintf(out, ", \"%s\": [", name);
    for (size_t k = 0; k < run->ndof; k++) {
        const int *shown = &kind[run->dof[k]];
        cli_count_kinds(c, 1, shown);
        fprintf(out, "%s\"%s\"", k > 0 ? ", " : "", fr_estimate_kind_name(*shown));
    }
    fputs("]", out);
}

/* run_ode's tolerances per component (u, v, W_in, E_visc, D_1 .. D_m), the dofs' entries
 * those shown, the contacts' the files' (none of the one standing in for none). */
static void json_atol(FILE *out, const struct structure_input *in, const fricreg_structure *s,
                      const struct structure_run *run)
{
    size_t dim = 2 * in->n + 2 + in->mlib;
    double *atol = malloc(dim * sizeof *atol);
    if (atol == NULL || fricreg_structure_get_ode_abs_tolerances(s, dim, atol) != FRICREG_OK) {
        free(atol);
        return;
    }
    fputs(", \"atol_used\": [", out);
    for (size_t k = 0; k < 2 * run->ndof; k++) {
        fputs(k > 0 ? ", " : "", out);
        cli_json_number(
            out, atol[cli_structure_shown(run, k % run->ndof) + (k < run->ndof ? 0 : in->n)]);
    }
    for (size_t k = 2 * in->n; k < 2 * in->n + 2 + in->m; k++) {
        fputs(", ", out);
        cli_json_number(out, atol[k]);
    }
    fputs("]", out);
    free(atol);
}

/* The --elements sets' fields, in the order of the old options' (njenkins ...
 * jenkins_dissipation, element_kind): their count, each element's dissipation (and its error
 * estimate), the sum, the kind, each set's type and sliders, and each element's force, its
 * dim components. De[me + nforces] is room for the dissipations and forces. */
static void write_element_sets(FILE *out, const fricreg_structure *s,
                               const struct cli_element_sets *sets, double *De,
                               const struct structure_estimate *est, struct cli_kind_counts *kinds)
{
    double *f = De + sets->me;
    fricreg_structure_get_elements(s, sets->me, f, NULL, De);
    fprintf(out, ", \"nelements\": %zu", sets->me);
    cli_json_array(out, "dissipation_per_element", sets->me, De);
    if (est->De_err != NULL) {
        cli_json_array(out, "dissipation_per_element_error_estimate", sets->me, est->De_err);
        cli_json_kinds(out, "dissipation_per_element_error_kind", sets->me, est->De_kind);
        cli_count_kinds(kinds, sets->me, est->De_kind);
    }
    fprintf(out, ", \"element_dissipation\": %.17g",
            cli_structure_value(s, FRICREG_SVALUE_JENKINS));
    cli_json_element_sets(out, sets);
    fputs(", \"element_forces\": [", out);
    for (size_t k = 0, i = 0; k < sets->n; k++)
        for (size_t e = 0; e < sets->set[k].me; e++, i++) { /* element i's dim components */
            fputs(i > 0 ? ", [" : "[", out);
            for (size_t c = 0; c < sets->set[k].dim; c++, f++) {
                fputs(c > 0 ? ", " : "", out);
                cli_json_number(out, *f);
            }
            fputs("]", out);
        }
    fputs("]", out);
}

static const char *companions_name(int which)
{
    return which == FRICREG_COMPANIONS_AUTO      ? "auto"
           : which == FRICREG_COMPANIONS_COARSER ? "coarser"
                                                 : "finer";
}

/* The estimate's companions: the choice, those that gave the estimate, their CPU seconds and
 * share of cpu_seconds; where auto's finer companions confirmed, what the screen had said
 * (its largest peak's and summed dissipations' estimates, null where it failed). */
static void json_companions(FILE *out, const fricreg_structure *s,
                            const struct structure_options *o, double cpu_seconds)
{
    double cpu = cli_structure_value(s, FRICREG_SVALUE_COMPANION_CPU);
    double used = cli_structure_value(s, FRICREG_SVALUE_COMPANIONS_USED);
    fprintf(out,
            ", \"error_companions\": \"%s\", \"estimate_companions\": \"%s\", "
            "\"companion_cpu_seconds\": %.6f, \"companion_cpu_share\": ",
            companions_name(o->error_companions), companions_name((int)used), cpu);
    cli_json_number(out, cpu_seconds > 0.0 ? cpu / cpu_seconds : NAN);
    if (o->error_companions != FRICREG_COMPANIONS_AUTO || used != FRICREG_COMPANIONS_FINER)
        return;
    double peak = cli_structure_value(s, FRICREG_SVALUE_SCREEN_PEAK_ERR);
    fprintf(out, ", \"screen\": {\"failed\": %s, \"peak_displacement_error\": ",
            isinf(peak) ? "true" : "false");
    cli_json_number(out, peak);
    fputs(", \"dissipation_error\": ", out);
    cli_json_number(out, cli_structure_value(s, FRICREG_SVALUE_SCREEN_DISS_ERR));
    fputs("}", out);
}

void cli_structure_summary(FILE *out, const struct structure_options *o,
                           const struct structure_input *in, const fricreg_structure *s,
                           const struct structure_run *run, double eps, double cpu_seconds,
                           const struct cli_warnings *warnings,
                           const struct structure_estimate *est)
{
    int64_t steps = sstat(s, FRICREG_SSTAT_STEPS);
    double *D = run->f; /* the forces are not needed any more */
    fricreg_structure_get_dissipation(s, in->mlib, D);
    fricreg_structure_get_state(s, in->n, run->u, run->v, NULL);
    fprintf(out, "{\"system\": \"structure\", \"law\": \"%s\", \"integrator\": \"%s\", ",
            fricreg_law_name(o->law), scheme_name(o));
    if (o->scheme == SCHEME_HHT)
        fprintf(out, "\"alpha\": %.17g, ", o->alpha);
    if (o->scheme == SCHEME_NEWMARK || o->scheme == SCHEME_HHT) { /* the path in force */
        int solver = FRICREG_CONTACT_SOLVER_DENSE;
        fricreg_structure_get_contact_solver(s, &solver);
        fprintf(out, "\"contact_solver\": \"%s\", ",
                solver == FRICREG_CONTACT_SOLVER_SPARSE ? "sparse" : "dense");
    }
    int adaptive = o->rtol > 0.0 || o->atol != 0.0;
    fprintf(out, "\"adaptive\": %s, \"dt\": %.17g, \"rtol\": %.17g, \"atol\": ",
            adaptive ? "true" : "false", o->dt, o->rtol);
    if (o->atol == FRICREG_ATOL_FROM_EPS) /* as the sim's summaries (output.c) */
        fprintf(out, "\"eps\", ");
    else
        fprintf(out, "%.17g, ", o->atol);
    fprintf(out,
            "\"eps\": %.17g, \"steps\": %lld, \"t\": %.17g, \"ndof\": %zu, "
            "\"ncontacts\": %zu",
            eps, (long long)steps, cli_structure_value(s, FRICREG_SVALUE_TIME), in->n, in->m);
    if (run->dof != NULL) { /* --output-dofs: the dofs the per-dof arrays show, from 1 */
        fputs(", \"output_dofs\": [", out);
        for (size_t k = 0; k < run->ndof; k++)
            fprintf(out, "%s%zu", k > 0 ? ", " : "", run->dof[k] + 1);
        fputs("]", out);
    }
    json_shown(out, "x", run, run->u);
    json_shown(out, "v", run, run->v);
    if (adaptive)
        json_atol(out, in, s, run);
    json_shown(out, "peak_displacement", run, run->peak);
    struct cli_kind_counts kinds = {{0}};
    if (est->peak_err != NULL) {
        json_shown(out, "peak_displacement_error_estimate", run, est->peak_err);
        kinds_shown(out, "peak_displacement_error_kind", run, est->peak_kind, &kinds);
    }
    cli_json_array(out, "dissipation_per_contact", in->m, D);
    if (est->D_err != NULL) {
        cli_json_array(out, "dissipation_per_contact_error_estimate", in->m, est->D_err);
        cli_json_kinds(out, "dissipation_per_contact_error_kind", in->m, est->D_kind);
        cli_count_kinds(&kinds, in->m, est->D_kind);
    }
    const struct cli_elements *el = &in->el;
    if (el->m > 0) {
        fprintf(out, ", \"njenkins\": %zu", el->m);
        fricreg_structure_get_jenkins_state(s, el->m, NULL, NULL, run->De);
        cli_json_array(out, "dissipation_per_jenkins", el->m, run->De);
        if (est->De_err != NULL) {
            cli_json_array(out, "dissipation_per_jenkins_error_estimate", el->m, est->De_err);
            cli_json_kinds(out, "dissipation_per_jenkins_error_kind", el->m, est->De_kind);
            cli_count_kinds(&kinds, el->m, est->De_kind);
        }
        fprintf(out, ", \"jenkins_dissipation\": %.17g, \"element_kind\": \"%s\"",
                cli_structure_value(s, FRICREG_SVALUE_JENKINS), cli_element_kind_name(el));
        if (el->kind == CLI_ELEMENTS_IWAN || el->kind == CLI_ELEMENTS_IWAN_NORMAL)
            fprintf(out, ", \"sliders_per_element\": %zu", el->ns);
        int planar = el->kind == CLI_ELEMENTS_JENKINS_2D || el->kind == CLI_ELEMENTS_CONTACT_3D;
        if (planar) { /* element i's [f_x, f_y], as J_e's rows */
            fricreg_structure_get_jenkins_2d_state(s, el->m, run->De, NULL, NULL);
            fputs(", \"jenkins_forces\": [", out);
            for (size_t i = 0; i < el->m; i++) {
                fputs(i > 0 ? ", [" : "[", out);
                cli_json_number(out, run->De[2 * i]);
                fputs(", ", out);
                cli_json_number(out, run->De[2 * i + 1]);
                fputs("]", out);
            }
            fputs("]", out);
        }
        if (el->kind == CLI_ELEMENTS_NORMAL || el->kind == CLI_ELEMENTS_CONTACT_3D ||
            el->kind == CLI_ELEMENTS_IWAN_NORMAL) {
            fricreg_structure_get_normal_forces(s, el->m, run->De);
            cli_json_array(out, "normal_forces", el->m, run->De);
        }
    }
    if (in->sets.me > 0)
        write_element_sets(out, s, &in->sets, run->De, est, &kinds);
    if (est->peak_err != NULL)
        cli_json_kind_counts(out, &kinds);
    fprintf(out,
            ", \"energy_balance\": {\"initial\": %.17g, \"input\": %.17g, "
            "\"kinetic\": %.17g, \"strain\": %.17g, \"viscous\": %.17g, \"friction\": %.17g, ",
            cli_structure_value(s, FRICREG_SVALUE_INITIAL),
            cli_structure_value(s, FRICREG_SVALUE_INPUT),
            cli_structure_value(s, FRICREG_SVALUE_KINETIC),
            cli_structure_value(s, FRICREG_SVALUE_STRAIN),
            cli_structure_value(s, FRICREG_SVALUE_VISCOUS),
            cli_structure_value(s, FRICREG_SVALUE_FRICTION));
    if (el->m > 0 || in->sets.me > 0) /* every element's, whatever its type */
        fprintf(out, "\"jenkins\": %.17g, ", cli_structure_value(s, FRICREG_SVALUE_JENKINS));
    fprintf(out, "\"residual\": %.17g}", cli_structure_value(s, FRICREG_SVALUE_RESIDUAL));
    int64_t iterations = sstat(s, FRICREG_SSTAT_NEWTON_ITERATIONS);
    fprintf(out,
            ", \"newton_iterations\": {\"mean\": %.17g, \"max\": %lld}, "
            "\"newton_failures\": %lld, \"cpu_seconds\": %.6f",
            steps > 0 ? (double)iterations / (double)steps : 0.0,
            (long long)sstat(s, FRICREG_SSTAT_NEWTON_MAX),
            (long long)sstat(s, FRICREG_SSTAT_NEWTON_FAILURES), cpu_seconds);
    if (est->peak_err != NULL) /* the estimate's share of cpu_seconds */
        json_companions(out, s, o, cpu_seconds);
    cli_json_warnings(out, warnings);
    fputs("}\n", out);
}

void cli_structure_estimate(const fricreg_structure *s, const struct structure_input *in,
                            struct structure_estimate *est)
{
    size_t n = in->n, m = in->mlib, me = in->el.m + in->sets.me; /* one of them 0 */
    double *buf = malloc((n + m + me + 1) * sizeof *buf);
    int *kind = malloc((n + m + me + 1) * sizeof *kind);
    if (buf != NULL && kind != NULL &&
        fricreg_structure_get_peak_displacement_error(s, n, buf) == FRICREG_OK &&
        fricreg_structure_get_dissipation_error(s, m, buf + n) == FRICREG_OK &&
        fricreg_structure_get_jenkins_dissipation_error(s, me, buf + n + m) == FRICREG_OK &&
        fricreg_structure_get_error_kind(s, FRICREG_EST_PEAK_DISPLACEMENT, n, kind) == FRICREG_OK &&
        fricreg_structure_get_error_kind(s, FRICREG_EST_DISSIPATION, m, kind + n) == FRICREG_OK &&
        fricreg_structure_get_error_kind(s, FRICREG_EST_ELEMENT_DISSIPATION, me, kind + n + m) ==
            FRICREG_OK) {
        *est = (struct structure_estimate){buf, buf + n, buf + n + m, kind, kind + n, kind + n + m};
    } else {
        free(buf);
        free(kind);
    }
}
