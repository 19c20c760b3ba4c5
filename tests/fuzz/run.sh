#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# Run one libFuzzer target for a while, then merge what it found into its in-tree corpus
# (minimized: only inputs that add coverage are kept). Build the targets first:
#   CC=clang cmake -S . -B build-fuzz -DFRICREG_FUZZ=ON && cmake --build build-fuzz --target fuzz
# Usage: run.sh BUILD_DIR TARGET SECONDS [extra libFuzzer flags]
# The log is BUILD_DIR/tests/fuzz/TARGET.log; a finding is saved as crash-*/timeout-* there.
build=$(cd "$1" && pwd) target=$2 seconds=$3
shift 3
here=$(cd "$(dirname "$0")" && pwd)
bin=$build/tests/fuzz/fuzz_$target
work=$build/tests/fuzz/work_$target
corpus=$here/corpus/$target
[ -x "$bin" ] || { echo "no $bin: build the target fuzz with FRICREG_FUZZ=ON"; exit 1; }
mkdir -p "$work" "$corpus"
dict=
[ -f "$here/$target.dict" ] && dict=-dict=$here/$target.dict
cd "$build/tests/fuzz" || exit 1
# The CLI parsers' usage messages would flood the log: its stderr is closed (a finding's
# message then shows when its input is replayed: fuzz_replay_cli_options FILE).
quiet=
case $target in cli_*) quiet=-close_fd_mask=2 ;; esac
# shellcheck disable=SC2086 # $dict and $quiet are one word or none
"$bin" "$work" "$corpus" $dict $quiet -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
    -max_len=512 -print_final_stats=1 "$@" >"$target.log" 2>&1
status=$?
tail -n 15 "$target.log"
# Keep the in-tree corpus small: the minimal set covering what corpus and work reach, by
# edges and hit counts; over 300 files, by edges alone (the replay stays a few hundred files).
merge() {
    rm -rf "$work.merged" && mkdir -p "$work.merged" &&
        "$bin" -merge=1 $quiet "$@" "$work.merged" "$corpus" "$work" >/dev/null 2>&1
}
merge && [ "$(ls "$work.merged" | wc -l)" -gt 300 ] && merge -use_counters=0
[ -n "$(ls "$work.merged")" ] &&
    rm -f "$corpus"/* && cp "$work.merged"/* "$corpus"/ && rm -rf "$work.merged"
echo "corpus $corpus: $(ls "$corpus" | wc -l) files"
exit $status
