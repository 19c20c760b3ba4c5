#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# A release in P stops (FRICREG_RELEASE_SCOPE="full K/P", tests/release_part.sh) runs the whole
# full scope: for P = 1 to 3 the parts' mutants (tests/mutation/run.sh --names --part) and
# valgrind programs (each asked as tests/valgrind.sh asks, of FILE) are every one of them, none
# in two parts, and no part costs more than the mean and the largest cost. The check bites: a
# partition that drops a name, gives one to two parts or loads one part must fail it.
# Usage: release_parts.sh ROOT VALGRIND_FILE (the build's tests/valgrind_parts.txt)
root=$1 valgrind=$2
part_sh=$root/tests/release_part.sh
[ -f "$valgrind" ] || { echo "FAIL: no file $valgrind"; exit 1; }
work=$(mktemp -d "${TMPDIR:-/tmp}/fricreg-parts.XXXXXX")
trap 'rm -rf "$work"' EXIT
fails=0 checks=0
check() { # what, expected, actual
    checks=$((checks + 1))
    if [ "$2" != "$3" ]; then
        echo "FAIL: $1: expected '$2', got '$3'"
        fails=$((fails + 1))
    fi
}

# The faults of the parts $work/part1..P of COSTS ("NAME SECONDS" lines), one a line: a name in
# no part, in two, not in COSTS, a part past the bound; "ok" without one.
judge() { # COSTS P
    p=$2 k=1
    set -- "$1"
    while [ $k -le "$p" ]; do set -- "$@" "$work/part$k" && k=$((k + 1)); done
    awk -v p="$p" '
    BEGIN { for (i = 2; i < ARGC; i++) part[ARGV[i]] = i - 1 }
    FILENAME == ARGV[1] {
        if (NF) { c = ($2 ~ /^[0-9]+(\.[0-9]*)?$/) ? $2 : 1; cost[$1] = c; total += c; if (c > big) big = c }
        next }
    !NF { next }
    !($1 in cost) { print $1 " is not in the list"; bad++; next }
    $1 in seen { print $1 " is in parts " seen[$1] " and " part[FILENAME]; bad++; next }
    { seen[$1] = part[FILENAME]; load[part[FILENAME]] += cost[$1] }
    END {
        for (n in cost) if (!(n in seen)) { print n " is in no part"; bad++ }
        for (k = 1; k <= p; k++) if (load[k] > total / p + big + 1e-9) {
            printf "part %d costs %g, past the mean %g and the largest %g\n", k, load[k], total / p, big
            bad++ }
        if (!bad) print "ok" }' "$@"
}
# The valgrind parts as valgrind.sh finds them: NAME in part K by PARTITIONER's answer.
valgrind_parts() { # PARTITIONER COSTS P
    k=1
    while [ $k -le "$3" ]; do
        for name in $(awk 'NF {print $1}' "$2"); do
            sh "$1" "$k/$3" "$2" "$name" >/dev/null && echo "$name"
        done >"$work/part$k"
        k=$((k + 1))
    done
}
sed -n 's/^mutant \([^ ]*\).*/\1 1/p' "$root/tests/mutation/mutants.txt" >"$work/mutants"
for p in 1 2 3; do
    k=1
    while [ $k -le $p ]; do
        sh "$root/tests/mutation/run.sh" --names --part "$k/$p" --work "$work/run" \
            >"$work/part$k" 2>/dev/null || echo "run.sh --part $k/$p failed" >"$work/part$k"
        k=$((k + 1))
    done
    check "the mutants in $p parts" ok "$(judge "$work/mutants" $p)"
    valgrind_parts "$part_sh" "$valgrind" $p
    check "the valgrind programs in $p parts" ok "$(judge "$valgrind" $p)"
done
check "at least 100 mutants" yes "$([ "$(grep -c . "$work/mutants")" -ge 100 ] && echo yes)"
check "at least 50 valgrind programs" yes "$([ "$(grep -c . "$valgrind")" -ge 50 ] && echo yes)"

# It bites: copies of release_part.sh each broken one way, on the valgrind file in 2 parts.
bites() { # WHAT EXPECTED-FAULT SED-SCRIPT
    sed "$3" "$part_sh" >"$work/broken.sh"
    if cmp -s "$part_sh" "$work/broken.sh"; then
        check "$1: the broken copy differs" yes no
        return
    fi
    valgrind_parts "$work/broken.sh" "$valgrind" 2
    check "$1 fails" yes "$(judge "$valgrind" 2 | grep -q -- "$2" && echo yes)"
}
bites "a part that drops its last name" "in no part" \
    's/^\[ "\$j" -eq "\$k" \]$/[ "$j" -eq "$k" ] \&\& [ "$name" != "$(awk "NF {n = \\$1} END {print n}" "$file")" ]/'
bites "a name in two parts" "is in parts" 's/^\[ "\$j" -eq "\$k" \]$/[ "$j" -ge "$k" ]/'
bites "every name in the first part" "past the mean" 's/if (load\[i\] < load\[best\]) best = i/best = 1/'
echo "$((checks - fails)) passed, $fails failed"
[ $fails -eq 0 ]
