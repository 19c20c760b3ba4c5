#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The mutants of a list that guard what changed since REF (tests/changed_files.sh: a commit,
# "landed", the last stop that landed, or "release", the last release): those whose file changed, whose tests' sources changed
# (tests/<module>/test_<name>.c, in the folder of the module it tests; tests/alloc/
# test_alloc_failure.c for alloc_failure_*; tests/tsan.sh and tests/reliability/test_threads.c
# for tsan; the program's source for hb_stability_sweeps and hb_march_orbit, entries of one
# case of test_hb_stability and test_hb_march), or whose entry in the list is new or edited since REF (its
# lines, comments aside, are not in the list as it was at REF). tests/mutation/run.sh
# --changed-since runs only these.
#
# Usage: select.sh SOURCE_DIR LIST REF
# Prints "NAME<tab>WHY" for each mutant selected and "since COMMIT (WHY)" on stderr; exits 0.
# Exits 1 with the reason on stderr when the changes cannot be known (tests/changed_files.sh):
# the caller then runs every mutant.
here=$(cd "$(dirname "$0")" && pwd)
src=$1 list=$2 ref=$3
since=$(mktemp "${TMPDIR:-/tmp}/fricreg-since.XXXXXX") || exit 1
trap 'rm -f "$since"' EXIT
changes=$(sh "$here/../changed_files.sh" "$src" "$ref" 2>"$since") || { cat "$since" >&2; exit 1; }
cat "$since" >&2
commit=$(sed -n 's/^since \([0-9a-f]*\) .*/\1/p' "$since")

# One line per entry of a list: its lines in order, comments and blank lines left out,
# tab-separated (an entry's identity).
entries() {
    awk '/^#/ || /^$/ {next} /^mutant / {if (e != "") print e; e = $0; next} {e = e "\t" $0}
         END {if (e != "") print e}'
}
# the list as it was at REF (empty if it was not there, or lies outside the tree)
list_abs=$(cd "$(dirname "$list")" && pwd)/$(basename "$list")
top=$(git -C "$src" rev-parse --show-toplevel)
old=$(git -C "$src" show "$commit:${list_abs#"$top"/}" 2>/dev/null | entries)

changed() { printf '%s\n' "$changes" | grep -qxF "$1"; }
entries <"$list" | while IFS= read -r entry; do
    name=$(printf '%s\n' "$entry" | tr '\t' '\n' | sed -n 's/^mutant //p')
    file=$(printf '%s\n' "$entry" | tr '\t' '\n' | sed -n 's/^file //p')
    tests=$(printf '%s\n' "$entry" | tr '\t' '\n' | sed -n 's/^tests //p')
    why=""
    changed "$file" && why="its file $file changed"
    for t in $tests; do
        [ -z "$why" ] || break
        case $t in
        tsan) sources="tests/tsan.sh tests/reliability/test_threads.c" ;;
        alloc_failure_*) sources=tests/alloc/test_alloc_failure.c ;;
        hb_stability_sweeps) sources=tests/floquet/test_hb_stability.c ;;
        hb_march_orbit) sources=tests/hb/test_hb_march.c ;;
        *) sources=$(cd "$src" && ls -d tests/*/test_"$t".c 2>/dev/null) ;;
        esac
        for f in $sources; do
            changed "$f" && why="its test's source $f changed"
        done
    done
    if [ -z "$why" ] && ! printf '%s\n' "$old" | grep -qxF "$entry"; then
        why="its entry is new or edited"
    fi
    [ -n "$why" ] && printf '%s\t%s\n' "$name" "$why"
done
exit 0
