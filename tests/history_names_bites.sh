#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The history-names check can fail: on a copy of the checked folders it passes, and with one
# "issue N" written into a copy of a file it must fail and name that file. Run both as an
# unpacked release (grep -r) and, when git is there, as a git tree (git grep).
# Usage: history_names_bites.sh CHECK ROOT
check=$1 root=$2
work=$(mktemp -d "${TMPDIR:-/tmp}/fricreg-history-bites.XXXXXX")
trap 'rm -rf "$work"' EXIT
fails=0 passes=0
fresh() { # a copy of the checked paths, outside any git tree
    rm -rf "$work/tree" && mkdir "$work/tree"
    for p in src include bench fortran docs examples cmake CMakeLists.txt README.md; do
        [ -e "$root/$p" ] && cp -R "$root/$p" "$work/tree/"
    done
    return 0
}
restore() { # FILE: the copy's FILE as in ROOT again (one copy of the tree serves every probe)
    cp "$root/$1" "$work/tree/$1"
}
expect() { # NAME EXPECTED: the check on $work/tree must fail, naming EXPECTED
    sh "$check" "$work/tree" >"$work/out" 2>&1 && { echo "FAIL: $1: the check passed"; fails=$((fails + 1)); return; }
    if grep -q "FAIL: .*$2" "$work/out"; then
        passes=$((passes + 1))
    else
        echo "FAIL: $1: the check failed without naming $2:"; cat "$work/out"; fails=$((fails + 1))
    fi
}
clean() { # NAME: the check on $work/tree must pass
    if sh "$check" "$work/tree" >"$work/out" 2>&1; then
        passes=$((passes + 1))
    else
        echo "FAIL: $1: the check failed on a clean copy:"; cat "$work/out"; fails=$((fails + 1))
    fi
}

fresh
clean "a copy of the tree"

echo '/* the batch of issue 12 */' >>"$work/tree/src/law/law.h"
expect "issue N in a comment" "src/law/law.h:.*issue 12"
restore src/law/law.h

printf '\n## Issue #3: the Fortran guide\n' >>"$work/tree/docs/usage.md"
expect "Issue #N in a heading" "docs/usage.md:.*Issue #3"
restore docs/usage.md

echo '#include "issue13.h"' >>"$work/tree/bench/bench.h"
expect "issueN in a file name" "bench/bench.h:.*issue13"
restore bench/bench.h

if command -v git >/dev/null 2>&1; then
    (cd "$work/tree" && git init -q && git add -A) || { echo "FAIL: git init"; exit 1; }
    clean "a clean git tree"
    echo '! the module of issue-3' >>"$work/tree/fortran/fricreg_c.f90"
    expect "issue-N in a tracked file (git grep)" "fortran/fricreg_c.f90:.*issue-3"
fi
echo "$passes passed, $fails failed"
[ $fails -eq 0 ]
