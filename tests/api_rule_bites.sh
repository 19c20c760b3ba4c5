#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The API-rule check can fail: on a small map whose newest node keeps the rule it passes (its
# older node's format twins are history, and so is a newest node before the first judged
# one), and a newest node with a _csr or _csc twin or a
# per-element-kind setter must fail, naming the function.
# Usage: api_rule_bites.sh CHECK
check=$1
work=$(mktemp -d "${TMPDIR:-/tmp}/fricreg-api-rule-bites.XXXXXX")
trap 'rm -rf "$work"' EXIT
fails=0 passes=0
map() { # NAME...: a map whose node FRICREG_1.7 has format twins and whose newest node has NAME...
    printf 'FRICREG_1.7 {\n  global:\n    fricreg_ctx_solve_step_csr;\n    fricreg_hb_set_iwan_normal;\n} FRICREG_1.6;\n\nFRICREG_1.8 {\n  global:\n' >"$work/map"
    for name in "$@"; do printf '    %s;\n' "$name" >>"$work/map"; done
    printf '} FRICREG_1.7;\n' >>"$work/map"
}
expect() { # NAME: the check on $work/map must fail, naming NAME
    sh "$check" "$work/map" FRICREG_1.8 >"$work/out" 2>&1 && { echo "FAIL: $1: the check passed"; fails=$((fails + 1)); return; }
    if grep -q "FAIL: FRICREG_1.8 adds $1:" "$work/out"; then
        passes=$((passes + 1))
    else
        echo "FAIL: $1: the check failed without naming it:"; cat "$work/out"; fails=$((fails + 1))
    fi
}
map fricreg_ctx_solve_step_matrix fricreg_structure_set_output_dofs
if sh "$check" "$work/map" FRICREG_1.8 >"$work/out" 2>&1; then passes=$((passes + 1)); else
    echo "FAIL: a node that keeps the rule:"; cat "$work/out"; fails=$((fails + 1)); fi
map fricreg_structure_set_load_csr
if sh "$check" "$work/map" FRICREG_1.9 >"$work/out" 2>&1; then passes=$((passes + 1)); else
    echo "FAIL: a node before the first judged one:"; cat "$work/out"; fails=$((fails + 1)); fi
for bad in fricreg_structure_set_load_csr fricreg_hb_set_damping_csc fricreg_structure_set_jenkins_3d \
           fricreg_hb_set_iwan_2d fricreg_structure_set_contact_3d fricreg_hb_set_disk \
           fricreg_structure_set_bristle_normal; do
    map fricreg_ctx_solve_step_matrix "$bad"
    expect "$bad"
done
echo "$passes passed, $fails failed"
[ $fails -eq 0 ]
