#!/usr/bin/env bash
# Soak: KILLS random kill -9 points over the three commands that
# change an output folder — a shard render, its --resume, and assemble (with
# an mp4) — then each is run to the end. The folder must end byte-identical
# to a clean run (frames, video, frames.sums aside: it records each write, so
# a killed run's re-writes add lines) with no stray file.
#   scripts/soak_kill.sh [KILLS=200] [FRAMES=200] [TUMBLE=build/release/src/app/tumble]
set -euo pipefail
cd "$(dirname "$0")/.."
KILLS="${1:-200}"
FRAMES="${2:-200}"
TUMBLE="$(realpath "${3:-build/release/src/app/tumble}")"
SEED="${SOAK_SEED:-26}"
RANDOM=$SEED
work="$(mktemp -d /tmp/tumble_soak_kill.XXXXXX)"
trap 'rm -rf "$work"' EXIT
# soak_render at 100 fps, FRAMES frames of 48x36: two shards and assemble.
sed -e "s/^duration = .*/duration = $(awk "BEGIN{print ($FRAMES - 1) / 100}")/" tests/app/data/soak_render.toml >"$work/scene.toml"
half=$((FRAMES / 2 - 1))
shards=("0:$half" "$((half + 1)):$((FRAMES - 1))")
render() { "$TUMBLE" render "$work/scene.toml" -o "$1" --progress none --video mp4 --frames "$2" "${@:3}"; }
assemble() { "$TUMBLE" assemble "$1" --progress none; }

t0=$(date +%s.%N)
for s in "${shards[@]}"; do render "$work/clean" "$s" >/dev/null 2>&1; done
assemble "$work/clean" >/dev/null
clean_s=$(awk "BEGIN{print $(date +%s.%N) - $t0}")
echo "soak_kill: clean run ${clean_s} s for $FRAMES frames"

out="$work/out"
kills=0 runs=0 finished=0
declare -A killed_in=([render]=0 [resume]=0 [assemble]=0)
t0=$(date +%s.%N)
while [ "$kills" -lt "$KILLS" ]; do
  runs=$((runs + 1))
  s=${shards[$((RANDOM % 2))]}
  # The binary itself in the background (not a function: $! would be a subshell).
  r=("$TUMBLE" render "$work/scene.toml" -o "$out" --progress none --video mp4 --frames "$s")
  case $((RANDOM % 3)) in
    0) what=render; cmd=("${r[@]}") ;;
    1) what=resume; cmd=("${r[@]}" --resume) ;;
    2) what=assemble; cmd=("$TUMBLE" assemble "$out" --progress none) ;;
  esac
  # A kill point anywhere in a run: uniform over half the clean run's time.
  delay=$(awk -v r=$RANDOM -v c="$clean_s" 'BEGIN{printf "%.3f", r / 32768 * c / 2}')
  "${cmd[@]}" >/dev/null 2>&1 &
  pid=$!
  sleep "$delay"
  if kill -9 "$pid" 2>/dev/null; then
    kills=$((kills + 1))
    killed_in[$what]=$((killed_in[$what] + 1))
  else
    finished=$((finished + 1))
  fi
  wait "$pid" 2>/dev/null || true
done
soak_s=$(awk "BEGIN{print $(date +%s.%N) - $t0}")
# Then to the end: both shards resumed, then assembled.
for s in "${shards[@]}"; do render "$out" "$s" --resume >/dev/null 2>"$work/err" || { cat "$work/err"; exit 1; }; done
assemble "$out" >/dev/null 2>"$work/err" || { cat "$work/err"; exit 1; }

fail=0
stray=$(comm -3 <(ls -A "$work/clean") <(ls -A "$out") | tr -d '\t' | tr '\n' ' ')
[ -z "$stray" ] || { echo "soak_kill: the folders differ in files: $stray"; fail=1; }
for f in "$work/clean"/*; do
  n=$(basename "$f")
  case "$n" in frames.sums | manifest.json) continue ;; esac
  cmp -s "$f" "$out/$n" || { echo "soak_kill: $n differs from the clean run's"; fail=1; }
done
grep -q '"complete": true' "$out/manifest.json" || { echo "soak_kill: manifest not complete"; fail=1; }
echo "soak_kill: $kills kill -9 (render ${killed_in[render]}, resume ${killed_in[resume]}, assemble ${killed_in[assemble]}), $finished runs ended before their kill, $runs runs in ${soak_s} s; stray files: ${stray:-0}; $(ls "$out" | grep -c '^frame_') frames and the video byte-identical: $([ $fail = 0 ] && echo yes || echo NO)"
exit $fail
