#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The API-rule check can fail: on a small map whose newest node keeps the rule it passes (its
# older node's format twins are history, and so is a newest node before the first judged
# one), and a newest node with a _csr or _csc twin, a per-element-kind setter, or a
# count/getter pair per kind (two of one object besides its stored points, or one beside an older
# node's) must fail, naming the function; one pair of its own object (the special points) passes.
# Usage: api_rule_bites.sh CHECK
check=$1
work=$(mktemp -d "${TMPDIR:-/tmp}/fricreg-api-rule-bites.XXXXXX")
trap 'rm -rf "$work"' EXIT
fails=0 passes=0
map() { # NAME...: a map whose node FRICREG_1.7 has format twins and count/getter pairs (stored
    # points, bifurcations) and whose newest node has NAME...
    printf 'FRICREG_1.7 {\n  global:\n    fricreg_ctx_solve_step_csr;\n    fricreg_hb_set_iwan_normal;\n' >"$work/map"
    for name in fricreg_hb_bifurcation fricreg_hb_bifurcations fricreg_hb_nma_point fricreg_hb_nma_points \
                fricreg_hb_point fricreg_hb_points; do printf '    %s;\n' "$name" >>"$work/map"; done
    printf '} FRICREG_1.6;\n\nFRICREG_1.8 {\n  global:\n' >>"$work/map"
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
map fricreg_ctx_solve_step_matrix fricreg_structure_set_output_dofs fricreg_hb_nma_special_point \
    fricreg_hb_nma_special_points fricreg_hb_element_count
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
# count/getter pairs per kind: two kinds of fricreg_hb_nma beside its stored points (each named),
# and one kind of fricreg_hb beside its older bifurcations
map fricreg_hb_nma_fold fricreg_hb_nma_folds fricreg_hb_nma_crossing fricreg_hb_nma_crossings
expect fricreg_hb_nma_fold
expect fricreg_hb_nma_crossing
map fricreg_ctx_solve_step_matrix fricreg_hb_fold fricreg_hb_folds
expect fricreg_hb_fold
echo "$passes passed, $fails failed"
[ $fails -eq 0 ]
