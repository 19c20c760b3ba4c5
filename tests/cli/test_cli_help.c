/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_cli_help.c — fricreg-sim's help and man page (src/cli/help.c) against the option tables
 * its parsers read: every row of every command has a meaning and a placeholder and is listed
 * in the command's help and man page; the synopses and descriptions name only options the
 * command has; the help fits 79 columns. tests/cli_help.sh checks the same from outside:
 * the options the parser takes are the ones the help lists. */
#include <check.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "quiet_check.h"

/* What print wrote for command, as a string the caller frees. */
static char *captured(void (*print)(FILE *, const struct cli_command *),
                      const struct cli_command *command)
{
    FILE *f = tmpfile();
    ck_assert_ptr_nonnull(f);
    print(f, command);
    long len = ftell(f);
    ck_assert_int_gt(len, 0);
    rewind(f);
    char *text = malloc((size_t)len + 1);
    ck_assert_ptr_nonnull(text);
    ck_assert_uint_eq(fread(text, 1, (size_t)len, f), (size_t)len);
    text[len] = '\0';
    fclose(f);
    return text;
}

static void print_man(FILE *out, const struct cli_command *command)
{
    (void)command;
    cli_print_man(out);
}

static void print_overview(FILE *out, const struct cli_command *command)
{
    (void)command;
    cli_print_overview(out);
}

/* The row of table[n] named name (the whole of it), or NULL. */
static const struct cli_option *row_named(const struct cli_option table[], size_t n,
                                          const char *name, size_t len)
{
    for (size_t k = 0; k < n; k++)
        if (strlen(table[k].name) == len && strncmp(table[k].name, name, len) == 0)
            return &table[k];
    return NULL;
}

/* Every "--name" in text is a row of the command's table, and not hidden if visible is set. */
static void options_are_rows(const struct cli_command *command, const char *text, int visible)
{
    struct cli_option table[CLI_MAX_ROWS];
    size_t n = command->table(table);
    for (const char *p = strstr(text, "--"); p != NULL; p = strstr(p + 2, "--")) {
        size_t len = 2 + strspn(p + 2, "abcdefghijklmnopqrstuvwxyz0123456789-");
        const struct cli_option *row = row_named(table, n, p, len);
        ck_assert_msg(row != NULL, "%s: %.*s is named but no option of it", command->name, (int)len,
                      p);
        ck_assert_msg(!visible || !row->hidden, "%s: %.*s is named but hidden", command->name,
                      (int)len, p);
    }
}

static void lines_fit(const char *who, const char *text)
{
    for (const char *line = text; *line != '\0';) {
        size_t len = strcspn(line, "\n");
        ck_assert_msg(len <= 79, "%s: a line of %zu columns: %.*s", who, len, (int)len, line);
        line += len + (line[len] == '\n');
    }
}

static void ascii_only(const char *who, const char *text)
{
    for (const unsigned char *c = (const unsigned char *)text; *c != '\0'; c++)
        QUIET_ASSERT(*c == '\n' || (*c >= 32 && *c < 127), "%s: byte 0x%02x", who, *c);
}

START_TEST(every_row_has_its_help)
{
    for (size_t c = 0; cli_commands[c] != NULL; c++) {
        const struct cli_command *command = cli_commands[c];
        struct cli_option table[CLI_MAX_ROWS];
        size_t n = command->table(table);
        ck_assert_uint_gt(n, 0);
        ck_assert_uint_le(n, CLI_MAX_ROWS);
        for (size_t k = 0; k < n; k++) {
            const struct cli_option *row = &table[k];
            ck_assert_msg(strncmp(row->name, "--", 2) == 0, "%s: %s", command->name, row->name);
            ck_assert_msg(row->help != NULL && row->help[0] != '\0', "%s %s: no help text",
                          command->name, row->name);
            ascii_only(row->name, row->help);
            /* names and words: the help lists the parser's own; a hidden row is not shown */
            ck_assert_msg(row->meta != NULL || row->kind == CLI_NAME || row->kind == CLI_CHOICE ||
                              row->hidden,
                          "%s %s: no placeholder", command->name, row->name);
            ck_assert_msg(row_named(table, k, row->name, strlen(row->name)) == NULL,
                          "%s %s: twice in the table", command->name, row->name);
        }
        ck_assert(command->summary != NULL && command->synopsis != NULL &&
                  command->description != NULL);
        ascii_only(command->name, command->description);
    }
}
END_TEST

START_TEST(help_lists_every_row)
{
    for (size_t c = 0; cli_commands[c] != NULL; c++) {
        const struct cli_command *command = cli_commands[c];
        char *help = captured(cli_print_command_help, command);
        char usage[64];
        snprintf(usage, sizeof usage, "usage: fricreg-sim %s ", command->name);
        ck_assert_msg(strncmp(help, usage, strlen(usage)) == 0, "%s", help);
        struct cli_option table[CLI_MAX_ROWS];
        size_t n = command->table(table);
        for (size_t k = 0; k < n; k++) {
            char line[64];
            snprintf(line, sizeof line, "\n  %s ", table[k].name);
            if (table[k].hidden)
                ck_assert_msg(strstr(help, line) == NULL, "%s: hidden %s listed", command->name,
                              table[k].name);
            else
                ck_assert_msg(strstr(help, line) != NULL, "%s: %s not in its help", command->name,
                              table[k].name);
        }
        ck_assert_ptr_nonnull(strstr(help, "\n  --help, -h "));
        lines_fit(command->name, help);
        ascii_only(command->name, help);
        free(help);
    }
}
END_TEST

START_TEST(synopsis_and_description_name_its_options)
{
    for (size_t c = 0; cli_commands[c] != NULL; c++) {
        options_are_rows(cli_commands[c], cli_commands[c]->synopsis, 1);
        options_are_rows(cli_commands[c], cli_commands[c]->description, 0);
    }
}
END_TEST

/* The defaults come from the slots the parser starts from: a few as the code sets them. */
START_TEST(defaults_from_the_parser)
{
    char *help = captured(cli_print_command_help, cli_find_command("hb"));
    ck_assert_ptr_nonnull(strstr(help, "harmonics kept in the solution [7]\n"));
    ck_assert_ptr_nonnull(strstr(help, "[1e-10]\n"));
    free(help);
    help = captured(cli_print_command_help, cli_find_command("oscillator"));
    ck_assert_ptr_nonnull(strstr(help, "--x0 X0                 initial position [2.75]\n"));
    ck_assert_ptr_nonnull(strstr(help, "[4]\n"));
    free(help);
}
END_TEST

START_TEST(overview_names_every_command)
{
    char *overview = captured(print_overview, NULL);
    for (size_t c = 0; cli_commands[c] != NULL; c++) {
        char line[64];
        snprintf(line, sizeof line, "\n  %-11s %s\n", cli_commands[c]->name,
                 cli_commands[c]->summary);
        ck_assert_msg(strstr(overview, line) != NULL, "%s", cli_commands[c]->name);
        ck_assert_ptr_eq(cli_find_command(cli_commands[c]->name), cli_commands[c]);
    }
    ck_assert_ptr_null(cli_find_command("frobnicate"));
    ck_assert_ptr_nonnull(strstr(overview, "man fricreg-sim"));
    lines_fit("overview", overview);
    free(overview);
}
END_TEST

START_TEST(man_page_lists_every_row)
{
    char *man = captured(print_man, NULL);
    ascii_only("man page", man);
    const char *sections[] = {"\n.SH NAME\n",     "\n.SH SYNOPSIS\n",    "\n.SH DESCRIPTION\n",
                              "\n.SH COMMANDS\n", "\n.SH EXIT STATUS\n", "\n.SH FILES\n",
                              "\n.SH SEE ALSO\n"};
    for (size_t k = 0; k < sizeof sections / sizeof sections[0]; k++)
        ck_assert_msg(strstr(man, sections[k]) != NULL, "%s", sections[k]);
    for (size_t c = 0; cli_commands[c] != NULL; c++) {
        const struct cli_command *command = cli_commands[c];
        char heading[64];
        snprintf(heading, sizeof heading, "\n.SS %s\n", command->name);
        const char *at = strstr(man, heading);
        ck_assert_msg(at != NULL, "%s", heading);
        const char *end = strstr(at + 1, "\n.SS ");
        end = end != NULL ? end : strstr(at, "\n.SH ");
        struct cli_option table[CLI_MAX_ROWS];
        size_t n = command->table(table);
        for (size_t k = 0; k < n; k++) {
            char tag[80] = ".TP\n\\fB", *t = tag + strlen(tag);
            for (const char *p = table[k].name; *p != '\0'; p++) /* -- as roff's \-\- */
                t += *p == '-' ? sprintf(t, "\\-") : sprintf(t, "%c", *p);
            sprintf(t, "\\fR");
            const char *found = strstr(at, tag);
            int inside = found != NULL && found < end;
            ck_assert_msg(inside == !table[k].hidden, "%s %s: %s in the man page", command->name,
                          table[k].name, inside ? "hidden but" : "not");
        }
    }
    free(man);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("cli_help");
    TCase *tc = tcase_create("help");
    tcase_add_test(tc, every_row_has_its_help);
    tcase_add_test(tc, help_lists_every_row);
    tcase_add_test(tc, synopsis_and_description_name_its_options);
    tcase_add_test(tc, defaults_from_the_parser);
    tcase_add_test(tc, overview_names_every_command);
    tcase_add_test(tc, man_page_lists_every_row);
    suite_add_tcase(s, tc);
    SRunner *sr = srunner_create(s);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
