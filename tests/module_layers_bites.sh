#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The layering check can fail: on copies of src/ with one arrow run back up (an include, a
# call), ctx_internal.h included outside src/ctx/, forced_internal.h included from a floor
# above forced/, forced/'s state on the driver (hb->forced) named outside src/forced/, a
# folder missing from the module table, or a circle of calls or includes inside a folder, or
# inside forced/ a file unlisted by floor, an include or a call up its floors, it must fail
# and name the break. Usage: module_layers_bites.sh CHECK SRC_DIR C_COMPILER
check=$1 src=$2 cc=$3
work=$(mktemp -d "${TMPDIR:-/tmp}/fricreg-layers-bites.XXXXXX")
trap 'rm -rf "$work"' EXIT
fails=0 passes=0
fresh() { rm -rf "$work/src" "$work/build" && cp -R "$src" "$work/src"; }
expect() { # NAME EXPECTED [BUILD_DIR]: the check on $work/src must fail, naming EXPECTED
    if [ -n "${3:-}" ]; then sh "$check" "$work/src" "$3"; else sh "$check" "$work/src"; fi \
        >"$work/out" 2>&1 && { echo "FAIL: $1: the check passed"; fails=$((fails + 1)); return; }
    if grep -q "FAIL: .*$2" "$work/out"; then
        passes=$((passes + 1))
    else
        echo "FAIL: $1: the check failed without naming $2:"; cat "$work/out"; fails=$((fails + 1))
    fi
}

fresh
echo '#include "sim/sim_internal.h"' >>"$work/src/base/error.c"
expect "an include back up" "src/base/error.c (floor 0) includes sim/sim_internal.h of sim/"

fresh
echo '#include "structure/structure_internal.h"' >>"$work/src/sim/sim.c"
expect "an include between siblings" "src/sim/sim.c (floor 3) includes structure/structure_internal.h"

fresh
sed 's|#include "ctx/ctx_driver.h"|#include "ctx/ctx_internal.h"|' "$src/sim/sim.c" >"$work/src/sim/sim.c"
expect "ctx_internal.h outside the context" "src/sim/sim.c includes ctx/ctx_internal.h outside src/ctx/"

# A module's layout included by a module above it, which the floors allow.
fresh
echo '#include "forced/forced_internal.h"' >>"$work/src/fit/fit_run.c"
expect "forced_internal.h outside forced/" "src/fit/fit_run.c includes forced/forced_internal.h outside src/forced/"

# The forced response's store read below it, through the driver's pointer: floquet/ clearing
# the points as it once did on a change of stability.
fresh
echo 'static void fr_drop(fricreg_hb *hb) { hb->forced->npts = 0; }' \
    >>"$work/src/floquet/stability_method.c"
expect "forced/'s state named outside forced/" "src/floquet/stability_method.c names ->forced, the state forced/ hangs on the driver, outside src/forced/"

fresh
mkdir "$work/src/joints" && echo 'int fr_joint;' >"$work/src/joints/joint.c"
expect "a folder not in the table" "src/joints/ is not in src/README.md's module table"

# A call back up, in objects named as a build tree names them.
fresh
printf 'int fr_layers_up(void);\nint fr_layers_base(void) { return fr_layers_up(); }\n' \
    >"$work/src/base/layers_base.c"
printf 'int fr_layers_up(void) { return 1; }\n' >"$work/src/sim/layers_up.c"
objects=$work/build/CMakeFiles/fricreg_objects.dir/src
mkdir -p "$objects/base" "$objects/sim"
"$cc" -c "$work/src/base/layers_base.c" -o "$objects/base/layers_base.c.o" &&
    "$cc" -c "$work/src/sim/layers_up.c" -o "$objects/sim/layers_up.c.o" ||
    { echo "FAIL: $cc did not compile the probe"; exit 1; }
expect "a call back up" "src/base/layers_base.c (floor 0) calls fr_layers_up of sim/" "$work/build"

# A circle of calls between two files of one folder.
fresh
printf 'int fr_circle_b(void);\nint fr_circle_a(int k) { return k ? fr_circle_b() : 0; }\n' \
    >"$work/src/base/circle_a.c"
printf 'int fr_circle_a(int k);\nint fr_circle_b(void) { return fr_circle_a(0); }\n' \
    >"$work/src/base/circle_b.c"
objects=$work/build/CMakeFiles/fricreg_objects.dir/src
mkdir -p "$objects/base"
"$cc" -c "$work/src/base/circle_a.c" -o "$objects/base/circle_a.c.o" &&
    "$cc" -c "$work/src/base/circle_b.c" -o "$objects/base/circle_b.c.o" ||
    { echo "FAIL: $cc did not compile the probe"; exit 1; }
expect "a circle inside a folder" "src/base/circle_a.c is on a circle of calls and includes (it uses base/circle_b.c)" "$work/build"

# A circle of includes: each of two files includes the other's header.
fresh
for x in a b; do echo "int fr_include_$x;" >"$work/src/base/include_$x.h"; done
echo '#include "include_b.h"' >"$work/src/base/include_a.c"
echo '#include "include_a.h"' >"$work/src/base/include_b.c"
expect "a circle of includes inside a folder" "src/base/include_a.c is on a circle of calls and includes (it uses base/include_b.c)"

# Inside forced/, whose files src/README.md lists by floor: a file not listed, an include up.
fresh
echo 'int fr_hb_unlisted;' >"$work/src/forced/unlisted.c"
expect "a forced/ file not listed" "src/forced/unlisted.c is not in src/README.md's table of forced/'s files"

fresh
echo '#include "arclength.h"' >>"$work/src/forced/corrector.c"
expect "an include up inside forced/" "src/forced/corrector.c (forced/ floor 0) includes arclength.h of forced/arclength (floor 2)"

# A call up inside forced/: a file of floor 0 calling one of floor 4.
fresh
# shellcheck disable=SC2016 # the backquotes are the table's, not a command
sed -e 's/^| `forced\/` | 0 | /| `forced\/` | 0 | `layers_low` /' \
    -e 's/^| `forced\/` | 4 | /| `forced\/` | 4 | `layers_high` /' "$src/README.md" >"$work/src/README.md"
printf 'int fr_hb_layers_high(void);\nint fr_hb_layers_low(void) { return fr_hb_layers_high(); }\n' \
    >"$work/src/forced/layers_low.c"
printf 'int fr_hb_layers_high(void) { return 1; }\n' >"$work/src/forced/layers_high.c"
objects=$work/build/CMakeFiles/fricreg_objects.dir/src
mkdir -p "$objects/forced"
"$cc" -c "$work/src/forced/layers_low.c" -o "$objects/forced/layers_low.c.o" &&
    "$cc" -c "$work/src/forced/layers_high.c" -o "$objects/forced/layers_high.c.o" ||
    { echo "FAIL: $cc did not compile the probe"; exit 1; }
expect "a call up inside forced/" "src/forced/layers_low.c (forced/ floor 0) calls src/forced/layers_high.c (floor 4)" "$work/build"

# A file over 600 lines.
fresh
seq 601 | sed 's|.*|/* line */|' >"$work/src/base/long.c"
expect "a file over 600 lines" "src/base/long.c has 601 lines, over 600"

echo "$passes passed, $fails failed"
[ $fails -eq 0 ]
