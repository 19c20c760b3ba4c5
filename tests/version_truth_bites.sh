#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The version check can fail: on copies of src/fricreg.map and CHANGELOG.md it passes for a
# release and for a development version above it, and fails, naming the cause, for a node
# newer than the version, a release version that is not the changelog's, and a development
# version not above the last release.
# Usage: version_truth_bites.sh CHECK
check=$1
work=$(mktemp -d "${TMPDIR:-/tmp}/fricreg-version-bites.XXXXXX")
trap 'rm -rf "$work"' EXIT
fails=0 passes=0
mkdir "$work/src"
fresh() { # a tree whose map's newest node is 1.7 and whose newest release is 1.7.0
    printf 'FRICREG_1.6 {\n  global:\n    a;\n};\nFRICREG_1.7 {\n  global:\n    b;\n} FRICREG_1.6;\n' \
        >"$work/src/fricreg.map"
    printf '# Changelog\n\n## [Unreleased]\n\n## [1.7.0] - 2026-11-25\n\n## [1.6.0] - 2026-11-23\n' \
        >"$work/CHANGELOG.md"
}
expect() { # NAME VERSION EXPECTED: the check must fail, naming EXPECTED
    sh "$check" "$work" "$2" >"$work/out" 2>&1 && { echo "FAIL: $1: the check passed"; fails=$((fails + 1)); return; }
    if grep -q "FAIL: .*$3" "$work/out"; then
        passes=$((passes + 1))
    else
        echo "FAIL: $1: the check failed without naming $3:"; cat "$work/out"; fails=$((fails + 1))
    fi
}
clean() { # NAME VERSION: the check must pass
    if sh "$check" "$work" "$2" >"$work/out" 2>&1; then
        passes=$((passes + 1))
    else
        echo "FAIL: $1: the check failed:"; cat "$work/out"; fails=$((fails + 1))
    fi
}

fresh
clean "the release" 1.7.0
expect "a release the changelog does not have" 1.7.1 "not CHANGELOG.md's newest release 1.7.0"
sed -i 's/^## \[1.7.0\] - 2026-11-25/## [1.7.1] - 2026-11-26/' "$work/CHANGELOG.md"
clean "a patch release" 1.7.1
fresh
expect "a version below its node" 1.6.0 "below the newest exported node FRICREG_1.7"
printf 'FRICREG_1.8 {\n  global:\n    c;\n} FRICREG_1.7;\n' >>"$work/src/fricreg.map"
expect "a new node under the release's number" 1.7.0 "below the newest exported node FRICREG_1.8"
clean "a development version for the new node" 1.7.90
expect "the next release before its changelog entry" 1.8.0 "not CHANGELOG.md's newest release"
printf 'FRICREG_1.9 {\n  global:\n    d;\n} FRICREG_1.8;\n' >>"$work/src/fricreg.map"
expect "a development version two nodes short" 1.7.90 "below the newest exported node FRICREG_1.9"
expect "a development version not above the last release" 1.6.90 "not above CHANGELOG.md's newest release 1.7.0"
fresh
sed -i 's/^## \[1.7.0\] - 2026-11-25/## [1.7.0]/' "$work/CHANGELOG.md"
expect "an undated release" 1.7.0 "newest release heading is not"
echo "$passes passed, $fails failed"
[ $fails -eq 0 ]
