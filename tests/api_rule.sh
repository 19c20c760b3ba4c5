#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The API's rule (docs/contributing.md, "What earns a public function its place"): a variant of
# an existing input is an argument of the setter that exists, not a new function. So the
# newest version node of the map adds no storage-format twin (a name ending in _csr or _csc:
# the format is an argument, enum fricreg_matrix_format) and no setter per element kind (a
# set_ name carrying an element family, Jenkins, Iwan, a contact or a disk: the kind is an
# argument of one element setter; set_contact_solver, the choice of a solver, is none). Nodes
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
echo "$node: $(echo "$names" | grep -c .) names checked, $fails against the rule"
[ $fails -eq 0 ]
