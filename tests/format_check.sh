#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The tracked C sources and headers are formatted as .clang-format says (clang-format
# --dry-run -Werror). Exits 77, which ctest reports as skipped, when clang-format is absent.
# One clang-format run reads every file (a run per file took most of a minute); its report is
# counted per file.
# To apply: git ls-files '*.c' '*.h' | xargs clang-format -i
# Usage: format_check.sh ROOT CLANG_FORMAT|-
root=$1 clang_format=$2
if [ "$clang_format" = "-" ] || ! command -v "$clang_format" >/dev/null 2>&1; then
    echo "clang-format not found: the format check is skipped"
    exit 77
fi
cd "$root" || exit 1
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    list() { git ls-files '*.c' '*.h'; }
else # an unpacked release
    list() { find . -path './build*' -prune -o -type f \( -name '*.c' -o -name '*.h' \) -print; }
fi
work=$(mktemp -d "${TMPDIR:-/tmp}/fricreg-format.XXXXXX")
trap 'rm -rf "$work"' EXIT
# A tracked file deleted from the work tree fails here: clang-format's own message would not
# name it. ([ -f ] is the shell's own: no process per file.)
list | while IFS= read -r file; do
    if [ -f "$file" ]; then printf '%s\n' "$file"; else echo "$file" >&3; fi
done >"$work/files" 3>"$work/unreadable"
"$clang_format" --version
status=0
if [ -s "$work/files" ]; then
    # xargs splits the list only past the system's argument limit
    tr '\n' '\0' <"$work/files" | xargs -0 "$clang_format" --style=file --dry-run -Werror \
        2>"$work/report" || status=$?
fi
# The report's "FILE:LINE:COL: error: ..." lines, counted per file, in the list's order.
awk -v status="$status" '
FILENAME == ARGV[1] { printf "FAIL: %s: cannot be read\n", $0; fails++; unreadable++; next }
FILENAME == ARGV[2] { order[++n] = $0; listed[$0] = 1; next }
{
    if (match($0, /:[0-9]+:[0-9]+: error: /) && (substr($0, 1, RSTART - 1) in listed)) {
        errors[substr($0, 1, RSTART - 1)]++
    } else if ($0 !~ /^[ \t]*\^?[ \t~]*$/ && prev !~ /: error: /) { # not a quoted line or caret
        other = other "\n" $0
    }
    prev = $0
}
END {
    for (i = 1; i <= n; i++) if (errors[order[i]]) {
        printf "FAIL: %s: %d places not formatted\n", order[i], errors[order[i]]; fails++
    }
    # clang-format failed and named no file (one unreadable, a broken .clang-format)
    if (status != 0 && fails == 0) {
        printf "FAIL: %s exited with %s:%s\n", "clang-format", status, other; fails = 1
    }
    printf "%d passed, %d failed\n", n + unreadable - fails, fails
    exit fails > 0
}' "$work/unreadable" "$work/files" "$work/report"
