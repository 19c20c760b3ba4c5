#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The README's first four commands (set-up and the main job, the quick tier, the release
# tier, the MPI tests with PETSc) are exactly what .ci/run runs. Usage: readme_commands.sh ROOT
root=$1
commands=$(awk '/^```sh$/ {inside = 1; n++; next} /^```$/ {inside = 0} inside && n <= 4' "$root/README.md")
[ -n "$commands" ] || { echo "FAIL: no sh blocks in README.md"; exit 1; }
fails=0
echo "$commands" | while IFS= read -r line; do
    grep -qxF -- "$line" "$root/.ci/run" || { echo "FAIL: README command not in .ci/run: $line"; exit 1; }
done || fails=1
echo "$((1 - fails)) passed, $fails failed"
[ $fails -eq 0 ]
