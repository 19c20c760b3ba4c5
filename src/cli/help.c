/* SPDX-License-Identifier: GPL-3.0-or-later */
/* help.c — fricreg-sim's help texts and its man page, all from the subcommands' option tables
 * (cli.h's struct cli_option: placeholder, meaning, default), the same rows their parsers
 * read: an option the parser takes is in the help, and the help names no other. */
#include <string.h>

#include "cli.h"

/* Where `cmake --install` puts the documentation (GNUInstallDirs' DOCDIR), for the man page. */
#ifndef FRICREG_DOCDIR
#define FRICREG_DOCDIR "/usr/local/share/doc/fricreg"
#endif

const struct cli_command *const cli_commands[] = {&cli_oscillator_command,
                                                  &cli_chain_command,
                                                  &cli_twoblock_command,
                                                  &cli_exact_command,
                                                  &cli_reproduce_command,
                                                  &cli_structure_command,
                                                  &cli_hb_command,
                                                  &cli_nma_command,
                                                  &cli_fit_command,
                                                  &cli_hold_command,
                                                  &cli_belt_command,
                                                  &cli_disk_command,
                                                  NULL};

const struct cli_command *cli_find_command(const char *name)
{
    for (size_t k = 0; cli_commands[k] != NULL; k++)
        if (strcmp(cli_commands[k]->name, name) == 0)
            return cli_commands[k];
    return NULL;
}

/* ---- A row's texts ------------------------------------------------------------------------ */

/* The value's placeholder: the row's, or for names and words the list the parser accepts. */
static const char *meta_text(const struct cli_option *row, char *buf, size_t len)
{
    if (row->meta != NULL)
        return row->meta;
    if (row->kind == CLI_NAME)
        return cli_names(buf, len, row->names->name_of, "|");
    if (row->kind == CLI_CHOICE) {
        size_t used = 0;
        buf[0] = '\0';
        for (size_t k = 0; row->words[k].word != NULL && used < len; k++)
            used += (size_t)snprintf(buf + used, len - used, "%s%s", k ? "|" : "",
                                     row->words[k].word);
        return buf;
    }
    return "VALUE";
}

/* x as %g writes it, its exponent without sign or zeros it does not need (1e-6, 1e7). */
static const char *number_text(char *buf, size_t len, double x)
{
    snprintf(buf, len, "%g", x);
    char *e = strchr(buf, 'e');
    if (e != NULL) {
        char *digits = e + 1;
        if (*digits == '+')
            memmove(digits, digits + 1, strlen(digits + 1) + 1);
        else if (*digits == '-')
            digits++;
        while (digits[0] == '0' && digits[1] != '\0')
            memmove(digits, digits + 1, strlen(digits + 1) + 1);
    }
    return buf;
}

/* The default: the row's text, else the slot's value before parsing; NULL for none. */
static const char *default_text(const struct cli_option *row, char *buf, size_t len)
{
    if (row->dflt != NULL)
        return row->dflt[0] != '\0' ? row->dflt : NULL;
    switch (row->kind) {
    case CLI_NUMBER:
    case CLI_POSITIVE:
    case CLI_NONNEGATIVE: return number_text(buf, len, *(const double *)row->slot);
    case CLI_WHOLE: snprintf(buf, len, "%d", *(const int *)row->slot); return buf;
    case CLI_NAME: return row->names->name_of(*(const int *)row->slot);
    case CLI_CHOICE:
        for (size_t k = 0; row->words[k].word != NULL; k++)
            if (row->words[k].value == *(const int *)row->slot)
                return row->words[k].word;
        return NULL;
    case CLI_FILE: return *(const char *const *)row->slot;
    default: return NULL;
    }
}

/* The meaning with the default in brackets, into buf[len]. */
static const char *help_text(const struct cli_option *row, char *buf, size_t len)
{
    char value[64];
    const char *dflt = default_text(row, value, sizeof value);
    if (dflt != NULL)
        snprintf(buf, len, "%s [%s]", row->help, dflt);
    else
        snprintf(buf, len, "%s", row->help);
    return buf;
}

/* ---- Plain text --------------------------------------------------------------------------- */

enum { WIDTH = 79, HELP_COLUMN = 26 };

/* Prints text's words from column on, wrapping at WIDTH to lines indented by indent, and ends
 * the line. A word starts a line only when the line is empty. */
static void wrap(FILE *out, const char *text, size_t column, size_t indent)
{
    for (const char *p = text; *p != '\0';) {
        if (*p == ' ') {
            p++;
            continue;
        }
        size_t len = strcspn(p, " ");
        if (column > indent && column + 1 + len > WIDTH) {
            fprintf(out, "\n%*s", (int)indent, "");
            column = indent;
        } else if (column > indent) {
            fputc(' ', out);
            column++;
        } else if (column < indent) {
            fprintf(out, "%*s", (int)(indent - column), "");
            column = indent;
        }
        fwrite(p, 1, len, out);
        column += len;
        p += len;
    }
    fputc('\n', out);
}

/* A placeholder from column on, a list of names broken after a '|' where it would pass WIDTH,
 * its lines aligned with its start; returns the column it ends at. */
static size_t list(FILE *out, const char *names, size_t column)
{
    const size_t start = column;
    for (const char *p = names; *p != '\0';) {
        size_t len = strcspn(p, "|");
        len += p[len] == '|';
        if (column > start && column + len > WIDTH) {
            fprintf(out, "\n%*s", (int)start, "");
            column = start;
        }
        fwrite(p, 1, len, out);
        column += len;
        p += len;
    }
    return column;
}

/* Each paragraph of text (separated by "\n\n") wrapped, with a blank line after each. */
static void paragraphs(FILE *out, const char *text)
{
    char buf[2048];
    for (const char *p = text; *p != '\0';) {
        const char *end = strstr(p, "\n\n");
        size_t len = end != NULL ? (size_t)(end - p) : strlen(p);
        snprintf(buf, sizeof buf, "%.*s", (int)len, p);
        for (char *c = buf; *c != '\0'; c++)
            if (*c == '\n')
                *c = ' ';
        wrap(out, buf, 0, 0);
        fputc('\n', out);
        p += len;
        while (*p == '\n')
            p++;
    }
}

void cli_print_overview(FILE *out)
{
    fputs("usage: fricreg-sim COMMAND [OPTION]...\n"
          "       fricreg-sim COMMAND --help\n"
          "       fricreg-sim --help | --version\n"
          "\n",
          out);
    paragraphs(out, "Runs the dry-friction systems of Quinn (2004) and the problems beyond them "
                    "with the regularized friction laws of libfricreg, and prints a JSON summary "
                    "or CSV rows.");
    fputs("Commands:\n", out);
    for (size_t k = 0; cli_commands[k] != NULL; k++)
        fprintf(out, "  %-11s %s\n", cli_commands[k]->name, cli_commands[k]->summary);
    fputc('\n', out);
    paragraphs(out, "`fricreg-sim COMMAND --help` lists a command's options with their units and "
                    "defaults; `man fricreg-sim` describes every command.");
    wrap(out,
         "Exit status: 0 success, 1 the simulation failed or its output could not be written "
         "(the message names the file), 2 bad option or value (run lengths and --out included).",
         0, 0);
}

void cli_print_command_help(FILE *out, const struct cli_command *command)
{
    struct cli_option rows[CLI_MAX_ROWS];
    size_t n = command->table(rows);
    char line[64], meta[256], help[1024];
    int len = snprintf(line, sizeof line, "usage: fricreg-sim %s", command->name);
    fputs(line, out);
    wrap(out, command->synopsis, (size_t)len, 11);
    fputc('\n', out);
    paragraphs(out, command->description);
    fputs("Options (defaults in brackets):\n", out);
    for (size_t k = 0; k < n; k++) {
        if (rows[k].hidden)
            continue;
        len = fprintf(out, "  %s ", rows[k].name);
        len = (int)list(out, meta_text(&rows[k], meta, sizeof meta), (size_t)len);
        if (len >= HELP_COLUMN) { /* a long name or list: the meaning on the next line */
            fputc('\n', out);
            len = 0;
        }
        wrap(out, help_text(&rows[k], help, sizeof help), (size_t)len, HELP_COLUMN);
    }
    fprintf(out, "  %-*s", HELP_COLUMN - 2, "--help, -h");
    wrap(out, "this help", HELP_COLUMN, HELP_COLUMN);
}

/* ---- roff ----------------------------------------------------------------------------------- */

/* text as roff: a backslash as \e, every hyphen as \- (options are typed with ASCII hyphens),
 * and a line start that roff would read as a request escaped. */
static void roff(FILE *out, const char *text)
{
    if (text[0] == '.' || text[0] == '\'')
        fputs("\\&", out);
    for (const char *p = text; *p != '\0'; p++) {
        if (*p == '\\')
            fputs("\\e", out);
        else if (*p == '-')
            fputs("\\-", out);
        else if (*p == '\n')
            fputc(' ', out);
        else if (*p == '|') /* a break point in a long list of names */
            fputs("|\\:", out);
        else
            fputc(*p, out);
    }
}

/* Each paragraph of text (separated by "\n\n") after a .PP. */
static void roff_paragraphs(FILE *out, const char *text)
{
    char buf[2048];
    for (const char *p = text; *p != '\0';) {
        const char *end = strstr(p, "\n\n");
        size_t len = end != NULL ? (size_t)(end - p) : strlen(p);
        snprintf(buf, sizeof buf, "%.*s", (int)len, p);
        fputs(".PP\n", out);
        roff(out, buf);
        fputc('\n', out);
        p += len;
        while (*p == '\n')
            p++;
    }
}

/* .SY/.YS (groff's an-ext, mandoc): the arguments hang under the command's name. */
static void roff_synopsis(FILE *out, const struct cli_command *command)
{
    fputs(".SY \"fricreg\\-sim ", out);
    roff(out, command->name);
    fputs("\"\n", out);
    roff(out, command->synopsis);
    fputs("\n.YS\n", out);
}

static void roff_command(FILE *out, const struct cli_command *command)
{
    struct cli_option rows[CLI_MAX_ROWS];
    size_t n = command->table(rows);
    char meta[256], help[1024];
    fputs(".SS ", out);
    roff(out, command->name);
    fputs("\n.PP\n", out);
    roff_synopsis(out, command);
    roff_paragraphs(out, command->description);
    for (size_t k = 0; k < n; k++) {
        if (rows[k].hidden)
            continue;
        fputs(".TP\n\\fB", out);
        roff(out, rows[k].name);
        fputs("\\fR \\fI", out);
        roff(out, meta_text(&rows[k], meta, sizeof meta));
        fputs("\\fR\n", out);
        roff(out, help_text(&rows[k], help, sizeof help));
        fputc('\n', out);
    }
}

void cli_print_man(FILE *out)
{
    fputs(".\\\" fricreg-sim(1), written by `fricreg-sim --man` from its option tables.\n", out);
    fprintf(out, ".TH FRICREG\\-SIM 1 \"\" \"fricreg %s\" \"User Commands\"\n", fricreg_version());
    /* ragged right, no hyphenation: option names and file names stay whole */
    fputs(".ad l\n.nh\n.nr HY 0\n", out);
    fputs(".SH NAME\n"
          "fricreg\\-sim \\- dry\\-friction simulations with regularized friction laws\n"
          ".SH SYNOPSIS\n",
          out);
    for (size_t k = 0; cli_commands[k] != NULL; k++)
        roff_synopsis(out, cli_commands[k]);
    fputs(".SY fricreg\\-sim\n"
          "\\fICOMMAND\\fR \\fB\\-\\-help\\fR\n"
          ".YS\n"
          ".SY fricreg\\-sim\n"
          "\\fB\\-\\-help\\fR | \\fB\\-\\-version\\fR\n"
          ".YS\n"
          ".SH DESCRIPTION\n"
          ".B fricreg\\-sim\n"
          "runs the dry\\-friction systems of Quinn (2004) and the problems beyond them with the\n"
          "regularized friction laws of libfricreg, and prints a JSON summary (one object) or\n"
          "CSV rows on standard output.\n"
          "Options are written \\fB\\-\\-name\\fR \\fIvalue\\fR or \\fB\\-\\-name=\\fR"
          "\\fIvalue\\fR, each at most once.\n"
          "Defaults are given in brackets.\n"
          ".PP\n"
          "Every bad option or value is one line on standard error naming the option, and\n"
          "nothing is run or written.\n"
          ".SH COMMANDS\n",
          out);
    for (size_t k = 0; cli_commands[k] != NULL; k++)
        roff_command(out, cli_commands[k]);
    fputs(".SH EXIT STATUS\n"
          ".TP\n.B 0\nsuccess\n"
          ".TP\n.B 1\nthe simulation failed, or its output could not be written (the message\n"
          "names the file)\n"
          ".TP\n.B 2\na bad option or value (run lengths and \\fB\\-\\-out\\fR included):\n"
          "nothing is written\n"
          ".SH FILES\n"
          ".TP\n.I ",
          out);
    roff(out, FRICREG_DOCDIR);
    fputs("\nREADME.md, CHANGELOG.md and LICENSE\n"
          ".TP\n.I ",
          out);
    roff(out, FRICREG_DOCDIR "/docs");
    fputs(
        "\nthe documentation: integrators.md (choosing an integrator and eps),\n"
        "structural.md (\\fBstructure\\fR), joints.md (the elements), harmonic_balance.md\n"
        "(\\fBhb\\fR), nonlinear_modes.md (\\fBnma\\fR), laws2d.md (\\fBhold\\fR,\n"
        "\\fBbelt\\fR, \\fBdisk\\fR), reproduction.md (\\fBreproduce\\fR), usage.md (the library\n"
        "from C), install.md and the others\n"
        ".SH SEE ALSO\n"
        "The API reference in the installed headers (fricreg.h, fricreg_sim.h), and\n"
        ".IR integrators.md ,\n"
        ".IR structural.md ,\n"
        ".IR joints.md ,\n"
        ".IR harmonic_balance.md ,\n"
        ".I laws2d.md\n"
        "in the documentation folder above.\n",
        out);
}
