#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The release tier's full scope in P parts (FRICREG_RELEASE_SCOPE="full K/P": a release over
# P stops, each of which lands, since all of it at once does not fit CI's time): which part
# runs which mutant (tests/mutation/run.sh --part) and which valgrind program (tests/
# valgrind.sh --part). Each name of FILE goes to one part by its cost, the costliest first,
# each to the part with the least cost so far (the lower part on a tie): no part's total then
# exceeds the mean by more than the largest cost. The same FILE gives the same parts at every
# stop, so P stops with no code change between them run each name once (test release_parts).
#
# Usage: release_part.sh K/P FILE [NAME]
#   FILE  lines "NAME SECONDS"; a name without a number costs 1
#   without NAME: prints part K's names, in FILE's order
#   with NAME: prints "part J of P", the part that runs it; exits 0 if J is K, else 1
# Exits 2 on a usage error: not 1 <= K <= P, no FILE, a name twice in it, NAME not in it.
usage() {
    echo "release_part.sh: $1" >&2
    exit 2
}
[ $# -ge 2 ] || usage "usage: release_part.sh K/P FILE [NAME]"
k="" p=""
case $1 in */*) k=${1%%/*} p=${1#*/} ;; esac
case $k$p in '' | *[!0-9]*) usage "a part is K/P, not $1" ;; esac
if [ "$k" -lt 1 ] || [ "$k" -gt "$p" ]; then usage "a part is K/P with 1 <= K <= P, not $1"; fi
file=$2 name=${3:-}
[ -f "$file" ] || usage "no file $file"
twice=$(awk 'NF {print $1}' "$file" | LC_ALL=C sort | uniq -d | head -n 1)
[ -z "$twice" ] || usage "$file names $twice twice"
# "LINE NAME PART" for every name, in FILE's order
parts=$(awk 'NF {print NR, $1, ($2 ~ /^[0-9]+(\.[0-9]*)?$/ ? $2 : 1)}' "$file" |
    LC_ALL=C sort -k3,3nr -k1,1n |
    awk -v p="$p" '{
        best = 1
        for (i = 2; i <= p; i++) if (load[i] < load[best]) best = i
        load[best] += $3
        print $1, $2, best }' | LC_ALL=C sort -k1,1n)
if [ -z "$name" ]; then
    printf '%s\n' "$parts" | awk -v k="$k" '$3 == k {print $2}'
    exit 0
fi
j=$(printf '%s\n' "$parts" | awk -v n="$name" '$2 == n {print $3}')
[ -n "$j" ] || usage "$file does not name $name"
echo "part $j of $p"
[ "$j" -eq "$k" ]
