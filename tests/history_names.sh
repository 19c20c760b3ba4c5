#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# Names and comments say what a thing is, not which work item brought it: no "issue N"
# ("issue 12", "Issue #3", "issue13", "issue-10") in the library, the headers, the benchmarks,
# the Fortran interface, the docs, the examples or the build files. History lives in
# CHANGELOG.md, which is not checked; nor is tests/, whose probe writes such lines on purpose.
# Searches the tracked files with git grep in a git tree, every file with grep -r otherwise.
# Usage: history_names.sh ROOT. Lists every line that matches, and fails if there is one.
root=$1
cd "$root" || exit 1
pattern='(^|[^[:alnum:]_])issues?[-_ ]?#?[0-9]+'
paths=
for p in src include bench fortran docs examples cmake CMakeLists.txt README.md; do
    [ -e "$p" ] && paths="$paths $p"
done
[ -n "$paths" ] || { echo "FAIL: none of src/, include/, docs/ ... under $root"; exit 1; }
out=$(mktemp "${TMPDIR:-/tmp}/fricreg-history.XXXXXX")
trap 'rm -f "$out"' EXIT
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    checked=$(git ls-files -- $paths | wc -l)
    git grep -n -I -i -E "$pattern" -- $paths >"$out"
else # an unpacked release
    checked=$(find $paths -type f | wc -l)
    grep -r -n -I -i -E "$pattern" $paths >"$out"
fi
[ "$checked" -gt 0 ] || { echo "FAIL: no files found under $root"; exit 1; }
sed 's/^/FAIL: names a work item, not what it is: /' "$out"
fails=$(cut -d: -f1 "$out" | sort -u | wc -l) # files
echo "$((checked - fails)) passed, $fails failed"
[ "$fails" -eq 0 ]
