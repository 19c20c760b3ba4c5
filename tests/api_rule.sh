#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The API's rule (docs/contributing.md, "What earns a public function its place"): a variant of
# an existing input is an argument of the setter that exists, not a new function. So the
# newest version node of the map adds no storage-format twin (a name ending in _csr or _csc:
# the format is an argument, enum fricreg_matrix_format) and no setter per element kind (a
# set_ name carrying an element family, Jenkins, Iwan, a contact or a disk: the kind is an
# argument of one element setter; set_contact_solver, the choice of a solver, is none). Nor
# does it add a count/getter pair per kind: a pair is a name N exported with its plural N + "s"
# (fricreg_hb_nma_point, fricreg_hb_nma_points), its object N without its last _word
# (fricreg_hb_nma) and its kind that word; the object's stored points, kind "point", are its
# list, and a pair of the newest node (N or N + "s" in it) of another kind fails when the same
# object exports a pair of a third kind (fricreg_hb_nma_fold beside fricreg_hb_nma_crossing):
# the kind is an out-argument of one getter, as fricreg_hb_bifurcation's type
# (fricreg_hb_nma_special_point's object is fricreg_hb_nma_special, with one pair). Nodes
# before FIRST (those released before the rule was checked, up to FRICREG_1.7) are history and
# are not re-judged.
# Usage: api_rule.sh MAP FIRST
map=$1 first=$2
node=$(sed -n 's/^\(FRICREG_[0-9][0-9]*\.[0-9][0-9]*\) *{.*/\1/p' "$map" | sort -V | tail -n 1)
[ -n "$node" ] || { echo "FAIL: no version node in $map"; exit 1; }
if [ "$(printf '%s\n%s\n' "$node" "$first" | sort -V | head -n 1)" != "$first" ]; then
    echo "$node: released before $first, not judged"
    exit 0
fi
names=$(awk -v node="$node" '$1 == node {inside = 1; next} inside && /^}/ {inside = 0}
        inside && /^ *fricreg_/ {gsub(/[ ;]/, ""); print}' "$map")
fails=0
for name in $names; do
    case $name in
    *_csr | *_csc)
        echo "FAIL: $node adds $name: a storage format is an argument (enum fricreg_matrix_format)"
        fails=$((fails + 1)) ;;
    *_set_contact_solver) ;; # how the contacts' block is solved: a setting, not an element
    *_set_jenkins* | *_set_iwan* | *_set_contact* | *_set_disk* | *_set_*_normal)
        echo "FAIL: $node adds $name: an element kind is an argument of one element setter"
        fails=$((fails + 1)) ;;
    esac
done
# the per-kind pairs: "N N+s OBJECT OTHER" per newest pair whose object has another kind's pair
kinds=$(awk -v node="$node" '$1 == node {inside = 1; next} inside && /^}/ {inside = 0}
        /^ *fricreg_/ {n = $0; gsub(/[ ;]/, "", n); all[n] = 1; if (inside) fresh[n] = 1}
        function object(n,    o) {o = n; sub(/_[^_]*$/, "", o); return o}
        function kind(n) {return substr(n, length(object(n)) + 2)}
        END {
            for (n in all) if ((n "s") in all && kind(n) != "point") pair[n] = 1
            for (n in pair) {
                if (!(n in fresh) && !((n "s") in fresh)) continue
                for (m in pair)
                    if (m != n && object(m) == object(n)) {print n, n "s", object(n), m; break}
            }
        }' "$map" | sort)
while read -r getter count object other; do
    [ -n "$getter" ] || continue
    echo "FAIL: $node adds $getter: with $count, a list per kind of $object beside $other's:" \
         "a kind is an out-argument of one getter, as fricreg_hb_bifurcation's type"
    fails=$((fails + 1))
done <<EOF
$kinds
EOF
echo "$node: $(echo "$names" | grep -c .) names checked, $fails against the rule"
[ $fails -eq 0 ]
