#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The guarding tests must bite: each mutant of tests/mutation/mutants.txt (one change to one
# source file) is built in a scratch copy of the tree and the tests it names are run there;
# each must fail on it (caught). A mutant they pass (survived), one whose change does not apply
# to the source or does not compile (stillborn: the list needs updating) fails the run.
#
# The copy (the files git knows, tracked or not ignored; the whole folder outside git) is built
# once without Fortran, only the test programs the list names, and every named test must pass
# on it before any mutant counts; a mutant rebuilds what its file touches. "tsan" names
# tests/tsan.sh, run on the copy with its own ThreadSanitizer tree (skipped, and its mutants
# with it, where the compiler has no ThreadSanitizer).
#
# With --changed-since REF only the mutants that guard what changed since REF run
# (tests/mutation/select.sh: their file, their tests' sources or their entry changed); the
# release tier's changed scope (FRICREG_RELEASE_SCOPE=changed) passes "release", the last
# release (tests/changed_files.sh). The run says which ran and why; with no git, a shallow
# clone or a REF not found, every mutant runs. With --part K/P (a release in P stops,
# FRICREG_RELEASE_SCOPE="full K/P") only the K-th of P shares of the list runs
# (tests/release_part.sh: every P-th mutant in the list's order, so that each test's mutants,
# which stand together, are spread over the parts).
#
# Usage: tests/mutation/run.sh [--src DIR] [--work DIR] [--cc CC] [--list FILE] [--only NAME]...
#                              [--changed-since REF|release] [--part K/P] [--names]
#   --src   the tree to mutate (default: this script's tree)
#   --work  scratch folder, reused between runs (default: ${TMPDIR:-/tmp}/fricreg-mutation)
#   --cc    C compiler (default: $CC or cc)
#   --list  the mutants (default: tests/mutation/mutants.txt beside this script)
#   --only  run this mutant only (repeatable)
#   --changed-since  only the mutants that guard a change since REF (a commit, or "release")
#   --part  only part K of P of the list
#   --names print the names of the mutants it would run, one a line, and exit (no build)
#   --check only check that every mutant applies to the source (no build): after an edit
# Exit status 0 if every mutant was caught, 1 otherwise, 2 on a usage or set-up error.
set -u
here=$(cd "$(dirname "$0")" && pwd)
src=$(cd "$here/../.." && pwd)
work=${TMPDIR:-/tmp}/fricreg-mutation
cc=${CC:-cc}
list=$here/mutants.txt
only=""
since=""
part=""
check=0
names=0
limit=900 # seconds per mutant's tests: a loosened bound may turn a refusal into a long run
while [ $# -gt 0 ]; do
    case $1 in
    --check)
        check=1
        shift
        continue
        ;;
    --names)
        names=1
        shift
        continue
        ;;
    --src) src=$2 ;;
    --work) work=$2 ;;
    --cc) cc=$2 ;;
    --list) list=$2 ;;
    --only) only="$only $2" ;;
    --changed-since) since=$2 ;;
    --part) part=$2 ;;
    -h | --help)
        sed -n '2,/^set -u/p' "$0" | sed '$d' | sed 's/^# \{0,1\}//'
        exit 0
        ;;
    *)
        echo "run.sh: unknown argument $1" >&2
        exit 2
        ;;
    esac
    [ $# -ge 2 ] || {
        echo "run.sh: $1 needs a value" >&2
        exit 2
    }
    shift 2
done
[ -f "$list" ] || {
    echo "run.sh: no list $list" >&2
    exit 2
}
start=$(date +%s)
# --names: the names alone on the output, the run's other words on stderr
[ $names -eq 1 ] && exec 3>&1 >&2
mkdir -p "$work" || exit 2
work=$(cd "$work" && pwd)
tree=$work/src build=$work/build log=$work/log
: >"$log"

# ---- The list: one folder per mutant, its fields one file each ------------------------------
blocks=$work/mutants
rm -rf "$blocks" && mkdir -p "$blocks"
n=0 dir=""
while IFS= read -r line || [ -n "$line" ]; do
    case $line in '#'* | '') continue ;; esac
    key=${line%% *} value=${line#* }
    case $key in
    mutant)
        n=$((n + 1))
        dir=$blocks/$(printf '%03d' $n)
        mkdir -p "$dir" && printf '%s\n' "$value" >"$dir/name"
        ;;
    tests | file | sed)
        [ -n "$dir" ] || {
            echo "run.sh: $list: '$key' before the first mutant" >&2
            exit 2
        }
        printf '%s\n' "$value" >>"$dir/$key"
        ;;
    *)
        echo "run.sh: $list: unknown line: $line" >&2
        exit 2
        ;;
    esac
done <"$list"
for dir in "$blocks"/*; do
    for key in name tests file sed; do
        [ -s "$dir/$key" ] || {
            echo "run.sh: mutant $(cat "$dir/name" 2>/dev/null) has no '$key'" >&2
            exit 2
        }
    done
done

# ---- The changed scope: the mutants that guard what changed since $since -------------------
if [ -n "$since" ] && [ $check -eq 0 ]; then
    if sh "$here/select.sh" "$src" "$list" "$since" >"$work/selected" 2>"$work/since"; then
        echo "changed scope: the mutants guarding a change $(cat "$work/since"):"
        kept=0
        for dir in "$blocks"/*; do
            name=$(cat "$dir/name")
            why=$(awk -F '\t' -v n="$name" '$1 == n {print $2; exit}' "$work/selected")
            if [ -n "$why" ]; then
                kept=$((kept + 1))
                printf '  %-38s %s\n' "$name" "$why"
            else
                rm -rf "$dir"
            fi
        done
        echo "changed scope: $kept of $n mutants run; the others guard files unchanged since" \
            "(all of them: FRICREG_RELEASE_SCOPE=full, or run.sh without --changed-since)"
        if [ $kept -eq 0 ]; then
            echo "0 mutants: none guards a change; $(($(date +%s) - start)) s"
            exit 0
        fi
    else
        echo "changed scope: $(cat "$work/since"): every mutant runs"
    fi
fi

# ---- A part of the full scope: every mutant costs the same -----------------------------------
if [ -n "$part" ]; then
    for dir in "$blocks"/*; do echo "$(cat "$dir/name") 1"; done >"$work/costs"
    sh "$here/../release_part.sh" "$part" "$work/costs" >"$work/part" || exit 2
    for dir in "$blocks"/*; do
        grep -qxF "$(cat "$dir/name")" "$work/part" || rm -rf "$dir"
    done
    echo "part $part of the full scope: $(grep -c . "$work/part") of $n mutants run;" \
        "the other parts run the others"
    if ! grep -q . "$work/part"; then
        echo "0 mutants in this part; $(($(date +%s) - start)) s"
        exit 0
    fi
fi
if [ $names -eq 1 ]; then
    for dir in "$blocks"/*; do
        [ -d "$dir" ] || continue
        name=$(cat "$dir/name")
        [ -z "$only" ] || echo " $only " | grep -q " $name " && echo "$name" >&3
    done
    exit 0
fi

# ---- The scratch copy and its build ----------------------------------------------------------
# Extracted with fresh times (tar -m): newer than any object a mutant left in the reused build.
echo "copying $src to $tree"
rm -rf "$tree" && mkdir -p "$tree" || exit 2
if git -C "$src" rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    (cd "$src" && git ls-files -z --cached --others --exclude-standard |
        tar --null --ignore-failed-read -T - -cf -) | tar -C "$tree" -m -xf - || exit 2
else
    (cd "$src" && tar --exclude='./build*' -cf - .) | tar -C "$tree" -m -xf - || exit 2
fi
# Writes the mutant of folder $1 over its file in the copy (the original in $work/original);
# returns 1 if its sed fails, 2 if it changes nothing.
mutate() { # folder
    mutant=$1
    target=$tree/$(cat "$mutant/file")
    [ -f "$target" ] || return 3
    cp "$target" "$work/original" || exit 2
    set --
    while IFS= read -r script; do set -- "$@" -e "$script"; done <"$mutant/sed"
    sed "$@" "$work/original" >"$target" 2>>"$log" || return 1
    cmp -s "$target" "$work/original" && return 2
    return 0
}

if [ $check -eq 1 ]; then
    bad=0
    for dir in "$blocks"/*; do
        mutate "$dir"
        case $? in
        0) verdict=applies ;;
        1) verdict="sed fails" ;;
        2) verdict="does not apply" ;;
        *) verdict="no file" ;;
        esac
        [ -f "$work/original" ] && [ -f "$tree/$(cat "$dir/file")" ] &&
            cp "$work/original" "$tree/$(cat "$dir/file")"
        printf '%-15s %s\n' "$verdict" "$(cat "$dir/name")"
        [ "$verdict" = applies ] || bad=$((bad + 1))
    done
    [ $bad -eq 0 ]
    exit $?
fi

# The programs of quick-tier ctest names: test_<name>, and test_alloc_failure for
# alloc_failure_<case>, test_hb_stability for hb_stability_sweeps, test_hb_march for
# hb_march_orbit (one Check case each).
programs_of() { # names...
    for t in "$@"; do
        case $t in
        alloc_failure_*) t=alloc_failure ;;
        hb_stability_sweeps) t=hb_stability ;;
        hb_march_orbit) t=hb_march ;;
        esac
        echo "test_$t"
    done | sort -u | tr '\n' ' '
}

# the ctest names of the quick tier the list uses
ctests=$(cat "$blocks"/*/tests | tr ' ' '\n' | grep -v '^tsan$' | grep . | sort -u)
# shellcheck disable=SC2086 # a list of words
targets=$(programs_of $ctests)
grep -q tsan "$blocks"/*/tests && targets="$targets test_threads"
echo "building the copy: $targets"
# Without the warning gate: a mutant may leave a variable unused, which must not make it
# stillborn. The quick entries the list names run their long cases too (the Check cases tagged
# release, the CLI's long runs, every allocation failure: FRICREG_QUICK_LONG_CASES), which the
# quick tier leaves to the release tier: a mutant that only a long case catches is caught here.
if ! cmake -S "$tree" -B "$build" -DCMAKE_C_COMPILER="$cc" -DFRICREG_FORTRAN=OFF -DFRICREG_WERROR=OFF \
        -DFRICREG_QUICK_LONG_CASES=ON >>"$log" 2>&1 ||
    ! cmake --build "$build" -j2 --target $targets >>"$log" 2>&1; then
    tail -n 30 "$log"
    echo "run.sh: the unmutated copy does not build" >&2
    exit 2
fi

# The quick tier's tests named (ctest in the copy's build); their status.
run_ctests() { # names...
    [ $# -gt 0 ] || return 0
    names=$(echo "$@" | tr ' ' '|')
    timeout "$limit" ctest --test-dir "$build" -j2 -R "^($names)\$" --output-on-failure \
        >>"$log" 2>&1
}

# tests/tsan.sh on the copy: 0 clean, 1 a ThreadSanitizer report or a failed check, 77 no
# ThreadSanitizer, 3 anything else (the TSan tree did not build, a crash).
run_tsan() {
    out=$work/tsan.out
    timeout "$limit" sh "$tree/tests/tsan.sh" "$tree" "$work/tsan" "$cc" >"$out" 2>&1
    s=$?
    cat "$out" >>"$log"
    [ $s -eq 0 ] || [ $s -eq 77 ] && return $s
    grep -q -e 'ThreadSanitizer report' -e 'Failures: [1-9]' -e 'Errors: [1-9]' "$out" && return 1
    return 3
}

# Splits a mutant's tests into $quick (ctest names) and $tsan (1 if tsan is named).
split_tests() { # tests...
    quick="" tsan=0
    for t in "$@"; do
        if [ "$t" = tsan ]; then tsan=1; else quick="$quick $t"; fi
    done
}

# shellcheck disable=SC2046,SC2086 # lists of words
split_tests $(cat "$blocks"/*/tests | tr ' ' '\n' | grep . | sort -u)
echo "the unmutated copy must pass:$quick$([ $tsan -eq 1 ] && echo ' tsan')"
# shellcheck disable=SC2086 # a list of words
if ! run_ctests $quick; then
    tail -n 40 "$log"
    echo "run.sh: the unmutated copy fails its tests" >&2
    exit 2
fi
tsan_ok=0
if [ $tsan -eq 1 ]; then
    run_tsan
    case $? in
    0) tsan_ok=1 ;;
    77) echo "no ThreadSanitizer with $cc: the tsan mutants are skipped" ;;
    *)
        tail -n 40 "$log"
        echo "run.sh: the unmutated copy fails tsan" >&2
        exit 2
        ;;
    esac
fi
echo "baseline: $(($(date +%s) - start)) s"

# ---- The mutants -------------------------------------------------------------------------------
caught=0 survived=0 stillborn=0 skipped=0 failed_names=""
for dir in "$blocks"/*; do
    name=$(cat "$dir/name") file=$(cat "$dir/file") tests=$(cat "$dir/tests")
    if [ -n "$only" ] && ! echo " $only " | grep -q " $name "; then
        continue
    fi
    t0=$(date +%s)
    target=$tree/$file
    # shellcheck disable=SC2086 # a list of words
    split_tests $tests
    # what must compile natively: the tests' programs, and test_threads for a tsan mutant
    # shellcheck disable=SC2086 # a list of words
    programs=$(programs_of $quick)
    [ $tsan -eq 1 ] && programs="$programs test_threads"
    verdict="" why=""
    echo "==== mutant $name ($file)" >>"$log"
    mutate "$dir"
    case $? in
    0)
        diff "$work/original" "$target" >>"$log"
        # shellcheck disable=SC2086 # a list of words
        if ! cmake --build "$build" -j2 --target $programs >>"$log" 2>&1; then
            verdict=stillborn why="does not compile"
        fi
        ;;
    1) verdict=stillborn why="sed failed" ;;
    2) verdict=stillborn why="the change does not apply" ;;
    *) verdict=stillborn why="no file $file" ;;
    esac
    if [ -f "$target" ]; then
        if [ -z "$verdict" ]; then
            # shellcheck disable=SC2086 # a list of words
            run_ctests $quick
            [ $? -ne 0 ] && verdict=caught
            if [ -z "$verdict" ] && [ $tsan -eq 1 ]; then
                if [ $tsan_ok -eq 0 ]; then
                    verdict=skipped why="no ThreadSanitizer"
                else
                    run_tsan
                    case $? in
                    0) ;;
                    1) verdict=caught ;;
                    *) verdict=stillborn why="tsan.sh failed to build or run" ;;
                    esac
                fi
            fi
            [ -z "$verdict" ] && verdict=survived
        fi
        cp "$work/original" "$target" # a fresh mtime: the next build recompiles it
    fi
    printf '%-9s %-38s %-28s %4d s %s\n' "$verdict" "$name" "$tests" $(($(date +%s) - t0)) "$why"
    case $verdict in
    caught) caught=$((caught + 1)) ;;
    skipped) skipped=$((skipped + 1)) ;;
    survived) survived=$((survived + 1)) failed_names="$failed_names $name" ;;
    *) stillborn=$((stillborn + 1)) failed_names="$failed_names $name" ;;
    esac
done
total=$((caught + survived + stillborn + skipped))
echo "$total mutants: $caught caught, $survived survived, $stillborn stillborn, $skipped skipped;" \
    "$(($(date +%s) - start)) s (log: $log)"
if [ $((survived + stillborn)) -gt 0 ]; then
    echo "not caught:$failed_names"
    exit 1
fi
exit 0
