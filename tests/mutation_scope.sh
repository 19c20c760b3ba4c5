#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The release tier's changed scope picks its mutants by rules that bite: on a small git tree of
# its own (no tags), tests/changed_files.sh finds the last release by its VERSION (not a
# development X.Y.90) and the stop that landed by .ci/landed (the release when it names no
# commit on the way to HEAD), and tests/mutation/select.sh selects a mutant when its file
# changed, when its test's source changed, when its entry is new, and no other (a file moved
# unchanged, or a C file whose comments alone changed, is no change); it gives up
# (the run is then full) without git, in a shallow clone and without a release.
# Usage: mutation_scope.sh SOURCE_DIR
command -v git >/dev/null 2>&1 || { echo "SKIP: no git"; exit 77; }
src=$1
select=$src/tests/mutation/select.sh
work=$(mktemp -d "${TMPDIR:-/tmp}/fricreg-scope.XXXXXX")
trap 'rm -rf "$work"' EXIT
fails=0 checks=0
check() { # what, expected, actual
    checks=$((checks + 1))
    if [ "$2" != "$3" ]; then
        echo "FAIL: $1: expected '$2', got '$3'"
        fails=$((fails + 1))
    fi
}
t=$work/tree
mkdir -p "$t/src" "$t/tests/mutation" "$t/tests/y"
g() { git -C "$t" -c user.name=t -c user.email=t@t -c commit.gpgsign=false "$@" >/dev/null; }
version() { echo "project(fricreg VERSION $1 LANGUAGES C)" >"$t/CMakeLists.txt"; }
entry() { printf 'mutant %s\ntests %s\nfile %s\nsed s/x/y/\n\n' "$1" "$2" "$3"; }
g init -q
version 1.0.0
echo a >"$t/src/a.c" && echo b >"$t/src/b.c" && echo y >"$t/tests/y/test_y.c"
{ echo "# the list"; entry m-a x src/a.c; entry m-b y src/b.c; } >"$t/tests/mutation/mutants.txt"
g add -A && g commit -q -m "release 1.0.0"
release=$(git -C "$t" rev-parse HEAD)
version 1.0.90 && g commit -q -am "development"
selected() { # REF: the names selected, space-separated, or "full" when select.sh gives up
    out=$(sh "$select" "$1" "$1/tests/mutation/mutants.txt" "${2:-release}" 2>/dev/null) ||
        { echo full; return; }
    printf '%s\n' "$out" | cut -f1 | tr '\n' ' ' | sed 's/ $//'
}
check "nothing changed" "" "$(selected "$t")"
check "the release found without tags, past 1.0.90" "since $release (release 1.0.0)" \
    "$(sh "$src/tests/changed_files.sh" "$t" release 2>&1 >/dev/null)"
echo a2 >"$t/src/a.c" && g commit -q -am "a changed"
check "a changed file selects its mutant" "m-a" "$(selected "$t")"
check "the reason" "its file src/a.c changed" \
    "$(sh "$select" "$t" "$t/tests/mutation/mutants.txt" release 2>/dev/null | cut -f2)"
echo y2 >"$t/tests/y/test_y.c"
check "a changed test source selects its mutants (uncommitted)" "m-a m-b" "$(selected "$t")"
git -C "$t" checkout -q -- tests/y/test_y.c
entry m-c z src/b.c >>"$t/tests/mutation/mutants.txt"
check "a new entry is selected" "m-a m-c" "$(selected "$t")"
sed -i 's#^sed s/x/y/$#sed s/x/z/#' "$t/tests/mutation/mutants.txt"
check "an edited entry is selected" "m-a m-b m-c" "$(selected "$t")"
g checkout -q -- tests/mutation/mutants.txt
echo 'b /* a comment that names no code */' >"$t/src/b.c"
check "a C file whose comments alone changed selects nothing more" "m-a" "$(selected "$t")"
g checkout -q -- src/b.c
mkdir -p "$t/tests/z" && g mv tests/y/test_y.c tests/z/test_y.c
check "a test source moved unchanged selects nothing more" "m-a" "$(selected "$t")"
g mv tests/z/test_y.c tests/y/test_y.c
check "a commit as REF" "" "$(selected "$t" HEAD)"
# "landed": the commit .ci/landed names, else the release
mkdir -p "$t/.ci"
check "landed: no .ci/landed, since the release" "m-a" "$(selected "$t" landed)"
echo "# the stop that landed" >"$t/.ci/landed" && git -C "$t" rev-parse HEAD >>"$t/.ci/landed"
g add .ci/landed && g commit -q -m "landed"
check "landed: since the commit it names" "" "$(selected "$t" landed)"
echo a3 >"$t/src/a.c" && g commit -q -am "a changed again"
check "landed: a change since it" "m-a" "$(selected "$t" landed)"
echo 0123456789abcdef0123456789abcdef01234567 >"$t/.ci/landed"
check "landed: a commit not on the way to HEAD, since the release" \
    "since $release (release 1.0.0)" "$(sh "$src/tests/changed_files.sh" "$t" landed 2>&1 >/dev/null | grep "^since")"
git -C "$t" checkout -q -- .ci/landed
check "an unknown REF: full" full "$(selected "$t" no-such-ref)"
version 1.1.0 && g commit -q -am "release 1.1.0"
check "the newest release" "" "$(selected "$t")"
# no git: the tree's files without .git
mkdir "$work/plain" && cp -r "$t/src" "$t/tests" "$t/CMakeLists.txt" "$work/plain/"
check "no git: full" full "$(selected "$work/plain")"
git clone -q --depth 1 "file://$t" "$work/shallow" 2>/dev/null
check "a shallow clone: full" full "$(selected "$work/shallow")"
# no release: only development versions
rm -rf "$t/.git" && g init -q && version 1.0.90 && g add -A && g commit -q -m dev
check "no release: full" full "$(selected "$t")"
echo "$((checks - fails)) passed, $fails failed"
[ $fails -eq 0 ]
