#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# Every tracked source file names its licence in an SPDX line: C (.c, .h), Fortran (.f90, .F90,
# .f, .F), CMake (CMakeLists.txt, .cmake), MATLAB/Octave (.m), shell scripts (.sh or a #!
# first line) and .in templates, within their first 3 lines; a script on the line right after
# its shebang.
# Markdown, LICENSE, the ABI baseline and data files are not checked.
# One awk reads the first lines of every file (thousands, the fuzz corpora among them): a
# process or two per file took a minute.
# Usage: spdx_check.sh ROOT. Lists every file that lacks the line, and fails if there is one.
root=$1
cd "$root" || exit 1
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    list() { git ls-files; }
else # an unpacked release: every file but the build trees
    list() { find . -path ./.git -prune -o -path './build*' -prune -o -type f -print | sed 's|^\./||'; }
fi
# only regular files ([ -f ] is the shell's own: no process per file); awk cannot read a folder
list | while IFS= read -r file; do [ -f "$file" ] && printf '%s\n' "$file"; done | awk -v tag='SPDX-License-Identifier: GPL-3.0-or-later' -v root="$root" '
{
    file = $0
    if ((getline first < file) <= 0) { # empty: a source file without the line
        close(file)
        if (is_source(file)) { checked++; fail(file) }
        next
    }
    shebang = (substr(first, 1, 2) == "#!")
    if (!is_source(file) && !shebang) { close(file); next }
    checked++
    found = 0
    if (shebang) { # the line right after the shebang
        if ((getline line < file) > 0 && index(line, tag)) found = 1
    } else {
        found = index(first, tag) > 0
        for (n = 2; !found && n <= 3 && (getline line < file) > 0; n++) found = index(line, tag) > 0
    }
    close(file)
    if (!found) fail(file)
}
function is_source(f) {
    return f ~ /\.(c|h|f90|F90|f|F|cmake|in|sh|m)$/ || f ~ /(^|\/)CMakeLists\.txt$/
}
function fail(f) { printf "FAIL: no '\''%s'\'' line: %s\n", tag, f; fails++ }
END {
    if (checked == 0) { print "FAIL: no source files found under " root; exit 1 }
    printf "%d passed, %d failed\n", checked - fails, fails
    exit fails > 0
}'
