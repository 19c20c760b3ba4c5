#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The README's first five commands (set-up and the main job, the quick tier, the release
# tier, the MPI tests with PETSc, the Octave tests) are exactly what .ci/run runs; the commands
# after them are optional tiers (CalculiX, cmake/calculix.cmake) that .ci/run does not run: CI
# keeps to its time. Usage: readme_commands.sh ROOT
root=$1
blocks() { awk -v from="$1" -v to="$2" '/^```sh$/ {inside = 1; n++; next} /^```$/ {inside = 0}
                                        inside && n >= from && n <= to' "$root/README.md"; }
commands=$(blocks 1 5)
[ -n "$commands" ] || { echo "FAIL: no sh blocks in README.md"; exit 1; }
fails=0
echo "$commands" | while IFS= read -r line; do
    grep -qxF -- "$line" "$root/.ci/run" || { echo "FAIL: README command not in .ci/run: $line"; exit 1; }
done || fails=$((fails + 1))
blocks 6 1000 | while IFS= read -r line; do
    [ -n "$line" ] || continue
    ! grep -qxF -- "$line" "$root/.ci/run" || { echo "FAIL: an optional tier's README command is in .ci/run: $line"; exit 1; }
done || fails=$((fails + 1))
echo "$((2 - fails)) passed, $fails failed"
[ $fails -eq 0 ]
