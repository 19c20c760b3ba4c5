#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The version tells the truth about what is exported and what is released:
#  - it is at least the newest version node of src/fricreg.map (a node FRICREG_1.8 needs 1.8.0
#    or a development version 1.7.90 above the last release);
#  - a release version (patch below 90) is CHANGELOG.md's newest release, dated;
#  - a development version (patch 90 and above) is above CHANGELOG.md's newest release.
# Usage: version_truth.sh ROOT VERSION (VERSION from project(VERSION), passed in by CMake)
root=$1 version=$2
fails=0
fail() { echo "FAIL: $1"; fails=$((fails + 1)); }
# version_le A B: A <= B in version order
version_le() { [ "$(printf '%s\n%s\n' "$1" "$2" | sort -V | head -n 1)" = "$1" ]; }

# A development version X.Y.9x is the way to X.(Y+1): it may export that node.
major=${version%%.*} minor=${version#*.} minor=${minor%%.*} patch=${version##*.}
covers=$version
[ "$patch" -ge 90 ] && covers=$major.$((minor + 1)).0
node=$(sed -n 's/^FRICREG_\([0-9][0-9]*\.[0-9][0-9]*\) *{.*/\1/p' "$root/src/fricreg.map" | sort -V | tail -n 1)
[ -n "$node" ] || fail "no version node in src/fricreg.map"
[ -n "$node" ] && ! version_le "$node.0" "$covers" &&
    fail "version $version is below the newest exported node FRICREG_$node (raise project(VERSION) to $node.0, or to a development version above the last release)"

heading=$(grep -m 1 '^## \[[0-9]' "$root/CHANGELOG.md")
released=$(echo "$heading" | sed -n 's/^## \[\([0-9][0-9.]*\)\] - [0-9]\{4\}-[0-9]\{2\}-[0-9]\{2\}$/\1/p')
[ -n "$released" ] || fail "CHANGELOG.md's newest release heading is not '## [X.Y.Z] - YYYY-MM-DD': $heading"
if [ -n "$released" ]; then
    if [ "$patch" -lt 90 ]; then
        [ "$released" = "$version" ] ||
            fail "release version $version is not CHANGELOG.md's newest release $released"
    elif version_le "$version" "$released"; then
        fail "development version $version is not above CHANGELOG.md's newest release $released"
    fi
fi
echo "version $version, newest node FRICREG_$node, newest release $released: $fails failed"
[ $fails -eq 0 ]
