#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# valgrind memcheck over one C test program, in one process (CK_FORK=no, so that valgrind sees
# every test and its leaks): any error or leak fails. With CASE names, only those Check cases
# run, one valgrind run each, and each must run at least one check (a renamed case fails here
# rather than testing nothing). Exits 77 (ctest: skipped) without valgrind. With
# --changed-since REF ROOT SOURCE (the release tier's changed scope, a stop), it runs only when
# the program guards a change since REF (tests/valgrind_scope.sh; SOURCE is its source file
# from the tree's top ROOT) and else exits 77 saying why. With --part K/P FILE NAME (part K of
# the full scope in P stops, a release) it runs only when tests/release_part.sh gives NAME, its
# ctest name, to part K of FILE's, and else exits 77 naming the part that runs it.
# Usage: valgrind.sh [--changed-since REF ROOT SOURCE | --part K/P FILE NAME] PROGRAM [CASE...]
if [ "${1:-}" = --changed-since ]; then
    why=$(sh "$(dirname "$0")/valgrind_scope.sh" "$3" "$2" "$4") || {
        echo "SKIP: $why (FRICREG_RELEASE_SCOPE=full runs it)"
        exit 77
    }
    echo "runs: $why"
    shift 4
elif [ "${1:-}" = --part ]; then
    where=$(sh "$(dirname "$0")/release_part.sh" "$2" "$3" "$4")
    case $? in
    0) echo "runs: $4 is in $where" ;;
    1)
        j=${where#part } j=${j%% *}
        echo "SKIP: $4 runs in $where (FRICREG_RELEASE_SCOPE=\"full $j/${2#*/}\", or full)"
        exit 77
        ;;
    *) exit 1 ;;
    esac
    shift 4
fi
command -v valgrind >/dev/null 2>&1 || { echo "SKIP: valgrind not found"; exit 77; }
program=$1
shift
# Programs that replace malloc themselves (test_exact fails its calloc on demand) keep theirs:
# valgrind intercepts only the C library's (somalloc=nouserintercepts).
# tests/valgrind.supp: libgomp's thread pool (CHOLMOD's supernodal factorizations).
supp=$(dirname "$0")/valgrind.supp
run() {
    CK_FORK=no valgrind -q --error-exitcode=1 --leak-check=full --suppressions="$supp" \
        --soname-synonyms=somalloc=nouserintercepts "$program"
}
[ $# -eq 0 ] && { run; exit $?; }
fails=0
for case in "$@"; do
    out=$(CK_RUN_CASE=$case run 2>&1)
    status=$?
    printf '%s\n' "$out"
    if [ $status -ne 0 ]; then
        fails=$((fails + 1))
    elif ! printf '%s\n' "$out" | grep -q "Checks: [1-9]"; then
        echo "FAIL: case $case ran no check"
        fails=$((fails + 1))
    fi
done
echo "$(($# - fails)) passed, $fails failed"
[ $fails -eq 0 ]
