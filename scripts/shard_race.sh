#!/usr/bin/env bash
# The shard race under load: runs the test of four GNU Parallel shards
# replacing an earlier render (Assemble.ShardsReplacingAnEditedRenderLeaveNothingOfIt)
# RUNS times with HOGS busy loops beside it, and counts the failures.
#   scripts/shard_race.sh [RUNS=40] [HOGS=4] [APP_TESTS=build/release/tests/app/app_tests]
# TUMBLE_TEST_BIN=<other tumble> runs it against another build (main's, say).
set -uo pipefail
cd "$(dirname "$0")/.."
runs=${1:-40} hogs=${2:-4} bin=${3:-build/release/tests/app/app_tests}
pids=()
stop_hogs() { for p in "${pids[@]}"; do kill "$p" 2>/dev/null; done; wait 2>/dev/null; }
trap stop_hogs EXIT
for ((h = 0; h < hogs; ++h)); do (while :; do :; done) & pids+=($!); done
failed=0
for ((i = 1; i <= runs; ++i)); do
  if ! out=$("$bin" --gtest_filter='Assemble.ShardsReplacingAnEditedRenderLeaveNothingOfIt' 2>&1); then
    failed=$((failed + 1))
    echo "run $i failed: $(grep -m1 -o 'is in use by[^;]*' <<<"$out" || grep -m1 'Failure' <<<"$out")"
  fi
done
echo "shard race: $failed failed of $runs runs ($hogs busy loops beside; $(nproc) cores)"
[ "$failed" -eq 0 ]
