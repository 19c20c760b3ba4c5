#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The release tier's changed scope runs a program under valgrind by rules that bite
# (tests/valgrind_scope.sh), on a small git tree of its own: two programs, one exercising hb/
# through its public header and a test header with a .c beside it, one exercising structure/,
# both on a floor above joint/ and base/. Each case changes one file and checks which of the
# two runs; without git both run.
# Usage: valgrind_scope_rules.sh SOURCE_DIR
command -v git >/dev/null 2>&1 || { echo "SKIP: no git"; exit 77; }
src=$1
scope=$src/tests/valgrind_scope.sh
work=$(mktemp -d "${TMPDIR:-/tmp}/fricreg-vscope.XXXXXX")
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
mkdir -p "$t/src/base" "$t/src/joint" "$t/src/hb" "$t/src/forced" "$t/src/structure" "$t/include" \
    "$t/tests/support" "$t/tests/hb" "$t/tests/structure" "$t/docs"
g() { git -C "$t" -c user.name=t -c user.email=t@t -c commit.gpgsign=false "$@" >/dev/null; }
cat >"$t/src/README.md" <<'TABLE'
| floor | module | what |
|---|---|---|
| 0 | `base/` | errors |
| 2 | `joint/` | sliders |
| 3 | `structure/` | structures |
| 3 | `hb/` | harmonic balance |
| 5 | `forced/` | the forced response |
TABLE
for f in src/base/error.c src/joint/slider.c src/hb/newton.c src/forced/solve.c src/structure/step.c \
    include/fricreg_hb.h include/fricreg_structure.h tests/support/rod.c docs/hb.md \
    tests/valgrind.sh CMakeLists.txt; do
    echo "/* $f */" >"$t/$f"
done
printf '#include "fricreg_hb.h"\n#include "rod.h"\n' >"$t/tests/hb/test_hb.c"
printf '#include "fricreg_structure.h"\n' >"$t/tests/structure/test_structure.c"
echo '#include "quiet.h"' >"$t/tests/support/rod.h"
echo '/* quiet */' >"$t/tests/support/quiet.h"
g init -q && g add -A && g commit -q -m start
runs() { # the programs that run since HEAD, space-separated
    for p in hb structure; do
        sh "$scope" "$t" HEAD "tests/$p/test_$p.c" >/dev/null && printf '%s ' "$p"
    done | sed 's/ $//'
}
touched() { # FILE: the programs that run with FILE changed (then restored)
    echo "enum { changed };" >>"$t/$1" # code: a comment alone is no change (changed_files.sh)
    runs
    git -C "$t" checkout -q -- "$1"
}
check "nothing changed" "" "$(runs)"
check "its module" "hb" "$(touched src/hb/newton.c)"
check "the other module of its floor" "structure" "$(touched src/structure/step.c)"
check "a module over hb/ behind fricreg_hb.h" "hb" "$(touched src/forced/solve.c)"
check "a module on a lower floor" "hb structure" "$(touched src/joint/slider.c)"
check "the bottom floor" "hb structure" "$(touched src/base/error.c)"
check "its module's public header" "hb" "$(touched include/fricreg_hb.h)"
check "its own source" "structure" "$(touched tests/structure/test_structure.c)"
check "the .c beside an included test header" "hb" "$(touched tests/support/rod.c)"
check "a header included by an included one" "hb" "$(touched tests/support/quiet.h)"
check "the harness" "hb structure" "$(touched tests/valgrind.sh)"
check "the docs" "" "$(touched docs/hb.md)"
check "CMake's lists (a new file is a change of its module)" "" "$(touched CMakeLists.txt)"
echo "/* new */" >"$t/src/hb/corrector.c"
check "an untracked file of its module" "hb" "$(runs)"
rm "$t/src/hb/corrector.c"
echo '| 3 | `sim/` | simulations |' >>"$t/src/README.md" && mkdir "$t/src/sim" && echo x >"$t/src/sim/run.c"
check "a module of a floor of its own" "" "$(runs)"
echo x >"$t/src/cli.c" && mkdir -p "$t/src/cli" && echo x >"$t/src/cli/main.c"
check "a module outside the table" "hb structure" "$(runs)"
rm -rf "$t/src/cli" "$t/src/cli.c" "$t/src/sim" && git -C "$t" checkout -q -- src/README.md
mkdir "$work/plain" && cp -r "$t/src" "$t/tests" "$t/include" "$work/plain/"
check "no git: every program" "yes" \
    "$(sh "$scope" "$work/plain" HEAD tests/structure/test_structure.c >/dev/null && echo yes)"
echo "$((checks - fails)) passed, $fails failed"
[ $fails -eq 0 ]
