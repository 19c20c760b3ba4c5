/* SPDX-License-Identifier: GPL-3.0-or-later */
/* option_table.c — the one way fricreg-sim reads its options: each subcommand declares a table
 * of rows (name, kind, slot), and cli_parse_options walks argv against it. Every error is one
 * line on stderr that names the option, and exit status 2; nothing is run or written. */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "fricreg_structure.h" /* enum fricreg_estimate_companions */

const struct cli_name_table cli_law_names = {"law", fricreg_law_from_name, fricreg_law_name};
const struct cli_name_table cli_integrator_names = {"integrator", fricreg_integrator_from_name,
                                                    fricreg_integrator_name};
const struct cli_word cli_output_words[] = {{"summary", CLI_SUMMARY},
                                            {"trajectory", CLI_TRAJECTORY},
                                            {NULL, 0}};
const struct cli_word cli_estimator_words[] = {{"on", FRICREG_ESTIMATE_TWO_COMPANIONS},
                                               {"off", FRICREG_ESTIMATE_OFF},
                                               {"one", FRICREG_ESTIMATE_ONE_COMPANION},
                                               {NULL, 0}};
const struct cli_word cli_companions_words[] = {{"auto", FRICREG_COMPANIONS_AUTO},
                                                {"finer", FRICREG_COMPANIONS_FINER},
                                                {"coarser", FRICREG_COMPANIONS_COARSER},
                                                {NULL, 0}};

int cli_usage_error(const char *option, const char *what)
{
    fprintf(stderr, "fricreg-sim: %s: %s\n", option, what);
    return CLI_EXIT_USAGE;
}

int cli_next_option(int argc, char **argv, int *k, char **option, char **value)
{
    *option = argv[*k];
    *value = NULL; /* none follows: the caller says so once it knows the option */
    if (strncmp(*option, "--", 2) != 0)
        return cli_usage_error(*option, "unexpected argument");
    char *eq = strchr(*option, '=');
    if (eq != NULL) { /* --name=value */
        *eq = '\0';
        *value = eq + 1;
    } else if (*k + 1 < argc) {
        *value = argv[++*k];
    }
    return 0;
}

const char *cli_names(char *buf, size_t len, const char *(*name_of)(int), const char *sep)
{
    size_t used = 0;
    buf[0] = '\0';
    for (int k = 1; name_of(k) != NULL && used < len; k++)
        used += (size_t)snprintf(buf + used, len - used, "%s%s", k > 1 ? sep : "", name_of(k));
    return buf;
}

const char *cli_join_words(char *buf, size_t len, const struct cli_word words[],
                           const char *last_sep)
{
    size_t used = 0;
    buf[0] = '\0';
    for (size_t k = 0; words[k].word != NULL && used < len; k++) {
        const char *sep = k == 0 ? "" : words[k + 1].word == NULL ? last_sep : ", ";
        used += (size_t)snprintf(buf + used, len - used, "%s%s", sep, words[k].word);
    }
    return buf;
}

const struct cli_word *cli_find_word(const struct cli_word words[], const char *text)
{
    for (size_t k = 0; words[k].word != NULL; k++)
        if (strcmp(words[k].word, text) == 0)
            return &words[k];
    return NULL;
}

/* strtod's ERANGE for an overflow; an underflow is the subnormal or zero meant, as
 * cli_parse_number keeps it. */
static int overflowed(double x)
{
    return errno == ERANGE && fabs(x) == HUGE_VAL;
}

int cli_parse_rayleigh(const char *option, const char *text, double *a0, double *a1)
{
    char *end = NULL;
    errno = 0;
    *a0 = strtod(text, &end);
    if (end == text || *end != ',' || overflowed(*a0))
        return cli_usage_error(option, "expected A0,A1 (two numbers, comma-separated)");
    const char *second = end + 1;
    errno = 0;
    *a1 = strtod(second, &end);
    if (end == second || *end != '\0' || overflowed(*a1) || !isfinite(*a0) || !isfinite(*a1))
        return cli_usage_error(option, "expected A0,A1 (two finite numbers)");
    if (*a0 < 0.0 || *a1 < 0.0)
        return cli_usage_error(option, "A0 and A1 must be >= 0");
    return 0;
}

/* strtod sets ERANGE on underflow too (1e-310, 1e-400), returning the subnormal or zero nearest
 * the text: that is the number meant, so it is kept; only an overflow (±HUGE_VAL) is refused. */
int cli_parse_number(const char *option, const char *text, double *value)
{
    char *end = NULL;
    errno = 0;
    double x = strtod(text, &end);
    if (end == text || *end != '\0')
        return cli_usage_error(option, "not a number");
    if (errno == ERANGE && fabs(x) == HUGE_VAL)
        return cli_usage_error(option, "out of the range of a double");
    if (!isfinite(x))
        return cli_usage_error(option, "not a finite number");
    *value = x;
    return 0;
}

/* A bound as the messages write it: a power of ten from 10^6 on as 10^k, else as %g. */
static const char *bound_text(char *buf, size_t len, double x)
{
    int k = x >= 1e6 ? (int)lround(log10(x)) : 0;
    if (k > 0 && x == pow(10.0, k))
        snprintf(buf, len, "10^%d", k);
    else
        snprintf(buf, len, "%g", x);
    return buf;
}

int cli_check_whole(const char *option, double value, double lo, double hi)
{
    if (value >= lo && value <= hi && value == floor(value))
        return 0;
    char low[32], high[32], what[96];
    snprintf(what, sizeof what, "must be a whole number from %s to %s",
             bound_text(low, sizeof low, lo), bound_text(high, sizeof high, hi));
    return cli_usage_error(option, what);
}

/* ---- One parser per kind ------------------------------------------------------------------ */

static int parse_real(const struct cli_option *row, const char *text)
{
    double x;
    int status = cli_parse_number(row->name, text, &x);
    if (status != 0)
        return status;
    if (row->kind == CLI_POSITIVE && !(x > 0.0))
        return cli_usage_error(row->name, "must be > 0");
    if (row->kind == CLI_NONNEGATIVE && !(x >= 0.0))
        return cli_usage_error(row->name, "must be >= 0");
    *(double *)row->slot = x;
    return 0;
}

/* Checked as a double before the conversion: NaN or 1e300 never reaches (int). */
static int parse_whole(const struct cli_option *row, const char *text)
{
    double x;
    int status = cli_parse_number(row->name, text, &x);
    if (status == 0)
        status = cli_check_whole(row->name, x, row->lo, row->hi);
    if (status == 0)
        *(int *)row->slot = (int)x;
    return status;
}

static int parse_name(const struct cli_option *row, const char *text)
{
    int id = row->names->from_name(text);
    if (id != 0) {
        *(int *)row->slot = id;
        return 0;
    }
    char names[256], what[300];
    snprintf(what, sizeof what, "unknown %s (%s)", row->names->what,
             cli_names(names, sizeof names, row->names->name_of, ", "));
    return cli_usage_error(row->name, what);
}

static int parse_choice(const struct cli_option *row, const char *text)
{
    const struct cli_word *word = cli_find_word(row->words, text);
    if (word != NULL) {
        *(int *)row->slot = word->value;
        return 0;
    }
    char words[128], what[160];
    snprintf(what, sizeof what, "expected %s",
             cli_join_words(words, sizeof words, row->words, " or "));
    return cli_usage_error(row->name, what);
}

static int parse_file(const struct cli_option *row, const char *text)
{
    *(const char **)row->slot = text; /* read later, by the option's reader */
    return 0;
}

static int parse_custom(const struct cli_option *row, const char *text)
{
    return row->parse(row, text);
}

static int (*const parsers[])(const struct cli_option *, const char *) = {
    [CLI_NUMBER] = parse_real, [CLI_POSITIVE] = parse_real, [CLI_NONNEGATIVE] = parse_real,
    [CLI_WHOLE] = parse_whole, [CLI_NAME] = parse_name,     [CLI_CHOICE] = parse_choice,
    [CLI_FILE] = parse_file,   [CLI_CUSTOM] = parse_custom};

int cli_parse_value(const struct cli_option *row, const char *text)
{
    return parsers[row->kind](row, text);
}

size_t cli_copy_rows(struct cli_option table[], const struct cli_option rows[], size_t n)
{
    if (n > CLI_MAX_ROWS) {
        fprintf(stderr, "fricreg-sim: an option table has %zu rows, more than %d\n", n,
                CLI_MAX_ROWS);
        abort();
    }
    memcpy(table, rows, n * sizeof rows[0]);
    return n;
}

/* ---- The loop ----------------------------------------------------------------------------- */

static const struct cli_option *find_row(const struct cli_option table[], size_t n,
                                         const char *option)
{
    for (size_t k = 0; k < n; k++)
        if (strcmp(table[k].name, option) == 0)
            return &table[k];
    return NULL;
}

/* An option is looked up before its value is asked for, so that an unknown one is called
 * unknown also as the last argument; one given twice is refused, whichever value was meant. */
int cli_parse_options(int argc, char **argv, const struct cli_option table[], size_t n,
                      const char *command)
{
    unsigned char seen[CLI_MAX_ROWS] = {0};
    for (int k = 0; k < argc; k++) {
        char *option = NULL, *value = NULL;
        int status = cli_next_option(argc, argv, &k, &option, &value);
        if (status != 0)
            return status;
        const struct cli_option *row = find_row(table, n, option);
        if (row == NULL) {
            char what[96];
            snprintf(what, sizeof what, "unknown option for %s (see fricreg-sim %s --help)",
                     command, command);
            return cli_usage_error(option, what);
        }
        size_t index = (size_t)(row - table);
        if (index < CLI_MAX_ROWS && seen[index] && !row->repeatable)
            return cli_usage_error(option, "given twice (give each option once)");
        if (index < CLI_MAX_ROWS)
            seen[index] = 1;
        if (value == NULL)
            return cli_usage_error(option, "missing value");
        if ((status = cli_parse_value(row, value)) != 0)
            return status;
        if (row->given != NULL)
            *row->given = 1;
    }
    return 0;
}
