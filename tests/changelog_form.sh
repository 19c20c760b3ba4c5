#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# CHANGELOG.md's newest section with entries (from the first "## [" heading up to the next, or
# the release below an [Unreleased] left empty by a release) stays a changelog a user reads: at most 150 lines, headings and blank lines included, and no entry (a line
# starting "- " with its indented continuation lines) longer than three lines. Test names,
# tolerances and measurements belong in docs/, commit messages and bench/.
# Usage: changelog_form.sh ROOT
root=$1
file=$root/CHANGELOG.md
[ -f "$file" ] || { echo "FAIL: no CHANGELOG.md under $root"; echo "0 passed, 1 failed"; exit 1; }
awk -v max_section=150 -v max_entry=3 '
function words(line,    w, n, i, out) { # the first five words of an entry
    n = split(line, w, /[ \t]+/)
    out = w[2]
    for (i = 3; i <= n && i <= 6; i++) out = out " " w[i]
    return n > 6 ? out " ..." : out
}
function close_entry() {
    if (!start) return
    checked++
    if (len > max_entry) {
        printf "FAIL: line %d: the entry \"%s\" has %d lines (at most %d)\n", start, first, len, max_entry
        fails++
    }
    start = 0
}
/^## \[/ { if (inside && entries) exit; inside = 1; head = NR; title = $0; lines = 0 }
!inside { next }
{ lines++ }
/^- / { close_entry(); entries++; start = NR; len = 1; first = words($0); next }
/^[ \t]+[^ \t]/ { if (start) len++; next }
{ close_entry() }
END {
    close_entry()
    checked++ # the length of the section, or its heading
    if (!inside) {
        print "FAIL: CHANGELOG.md has no section heading \"## [\""
        fails++
    } else {
        if (lines > max_section) {
            printf "FAIL: line %d: the section \"%s\" has %d lines (at most %d)\n", head, title, lines, max_section
            fails++
        }
    }
    printf "%d passed, %d failed\n", checked - fails, fails
    exit fails > 0
}' "$file"
