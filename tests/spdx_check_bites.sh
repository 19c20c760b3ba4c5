#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The SPDX check can fail: on a small tree of its own (a git tree, then the same files as an
# unpacked release) it passes the files that carry the line where it must be, and fails each
# file that does not, naming it. Usage: spdx_check_bites.sh CHECK
check=$1
work=$(mktemp -d "${TMPDIR:-/tmp}/fricreg-spdx-bites.XXXXXX")
trap 'rm -rf "$work"' EXIT
tag='SPDX-License-Identifier: GPL-3.0-or-later'
fails=0 passes=0
t=$work/tree
mkdir -p "$t/src/sub" "$t/tools"
# carry it: a C file on line 1, a CMake file on line 3, a script right after its shebang, a
# data file (not checked)
printf '/* %s */\nint a;\n' "$tag" >"$t/src/good.c"
printf '#\n#\n# %s\n' "$tag" >"$t/src/sub/CMakeLists.txt"
printf '#!/bin/sh\n# %s\n' "$tag" >"$t/tools/good"
printf 'no licence line\n' >"$t/src/data.csv"
# fail: the line on line 4, an empty header, the line below a shebang's next line, a file
# name with a space
printf '/* a */\n/* b */\n/* c */\n/* %s */\n' "$tag" >"$t/src/late.c"
: >"$t/src/empty.h"
printf '#!/bin/sh\n\n# %s\n' "$tag" >"$t/tools/late"
printf 'int b;\n' >"$t/src/with space.c"
expected="src/late.c src/empty.h tools/late"
run() { # NAME: the check on $t fails on the expected files, and only on them
    sh "$check" "$t" >"$work/out" 2>&1 && { echo "FAIL: $1: the check passed"; fails=$((fails + 1)); return; }
    for f in $expected "src/with space.c"; do
        if grep -qxF "FAIL: no '$tag' line: $f" "$work/out"; then passes=$((passes + 1)); else
            echo "FAIL: $1: the check did not name $f:"; cat "$work/out"; fails=$((fails + 1)); fi
    done
    if grep -q "good\|data.csv" "$work/out"; then
        echo "FAIL: $1: the check named a good file:"; cat "$work/out"; fails=$((fails + 1))
    else
        passes=$((passes + 1))
    fi
}
run "an unpacked release (find)"
if command -v git >/dev/null 2>&1; then
    (cd "$t" && git init -q && git add -A) || { echo "FAIL: git init"; exit 1; }
    rm "$t/src/good.c" # tracked, deleted from the work tree: not a file to check
    run "a git tree (git ls-files)"
fi
echo "$passes passed, $fails failed"
[ $fails -eq 0 ]
