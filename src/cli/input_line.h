/* SPDX-License-Identifier: GPL-3.0-or-later */
/* input_line.h — what the input files of `fricreg-sim structure` share (input_line.c): one
 * line at a time into a fixed buffer, the tokens a line holds, and the one-line message that
 * names option, file and line. */
#ifndef FRICREG_CLI_INPUT_LINE_H
#define FRICREG_CLI_INPUT_LINE_H

#include <stdio.h>

/* The longest line read, its end included: a longer one is an error, not two lines. */
#define CLI_LINE_MAX 512
/* The longest line of an element's parameters, 2 ns numbers and a few: 1024 sliders (the
 * kernels' and fricreg_hb's limit) written to 17 digits fit. */
#define CLI_SLIDER_LINE_MAX 65536

/* Prints "fricreg-sim: OPTION PATH: line LINE: WHAT" (without "line LINE: " when line is 0)
 * on stderr, WHAT formatted as printf does, and returns CLI_EXIT_USAGE. */
int cli_file_error(const char *option, const char *path, long line, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;

/* Reads the next line into buf[len] and counts it in *line. 0 at the end of the file, or on a
 * line longer than len - 1 characters (*too_long set then). */
int cli_next_line(FILE *f, char *buf, size_t len, long *line, int *too_long);

/* Whether s holds only blanks, tabs and line ends. */
int cli_blank(const char *s);

/* A finite double as the whole token starting at text (ending at a blank, a comma, a line end
 * or the string's end); *end after it. An underflow (a subnormal, 1e-310) is kept as the
 * number meant, as the options' parser keeps it; an overflow is refused. 1 if read, else 0. */
int cli_read_number(const char *text, char **end, double *value);

/* A whole number from 1 to max as the token at text (ending at a blank, a line end or the
 * string's end); *end after it. 1 if read, else 0. */
int cli_read_index(const char *text, char **end, long max, long *value);

/* The numbers of the line p (line LINE of option's file path) into v[*count], room for cap,
 * separated by blanks or commas: 0, or CLI_EXIT_USAGE after the line's message. */
int cli_line_numbers(const char *option, const char *path, long line, char *p, double *v,
                     size_t cap, size_t *count);
#endif
