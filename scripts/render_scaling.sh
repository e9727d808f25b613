#!/usr/bin/env bash
# The render scaling table without a GPU: `tumble render` of the demo
# (scenes/dzhanibekov.toml, FXAA) pinned by `taskset` to 1 core and to 2
# cores, at --jobs 1..4, two ways: PNG frames (--video none) and the H.264
# video streamed (--frames-out none). frames/s is the difference of two
# renders, LONG and SHORT seconds of the scene, so start-up (simulation,
# GL context, ffprobe's check) cancels out; CPU is user + system of tumble and
# ffmpeg over the same difference. Timings depend on the machine's load: run
# it on a quiet one (about 90 s on 2 cores at the defaults).
#   scripts/render_scaling.sh [tumble binary] > table.md
# Environment: SIZE (WxH, default 1280x720), LONG and SHORT (scene seconds,
# default 5 and 1, at 30 frames/s), CORES (taskset lists, default "0 0,1"),
# JOBS (default "1 2 3 4").
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
tumble=${1:-$root/build/release/src/app/tumble}
size=${SIZE:-1280x720}
long=${LONG:-5}
short=${SHORT:-1}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for s in "$long" "$short"; do
  sed "s/^duration = .*/duration = $s/" "$root/scenes/dzhanibekov.toml" >"$work/dz_$s.toml"
done

# One render: prints "wall_s cpu_s frames".
render() {  # cores jobs seconds args...
  local cores=$1 jobs=$2 s=$3
  shift 3
  local t
  t=$( { /usr/bin/time -f '%e %U %S' taskset -c "$cores" "$tumble" render "$work/dz_$s.toml" -o "$work/out" --force \
    --width "${size%x*}" --height "${size#*x}" --jobs "$jobs" --progress none "$@" >/dev/null; } 2>&1 | tail -1)
  local frames
  frames=$(grep -o '"frames_written": [0-9]*' "$work/out/manifest.json" | grep -o '[0-9]*$')
  echo "$t $frames"
}

# frames/s and CPU ms/frame of a LONG render minus the SHORT one ($base).
rate() {  # cores jobs args...
  local cores=$1 jobs=$2
  shift 2
  awk -v a="$(render "$cores" "$jobs" "$long" "$@")" -v b="$base" 'BEGIN {
    split(a, x, " "); split(b, y, " "); n = x[4] - y[4]
    printf "%.1f | %.1f", n / (x[1] - y[1]), 1000 * ((x[2] + x[3]) - (y[2] + y[3])) / n }'
}

echo "tumble render of scenes/dzhanibekov.toml at $size, FXAA: frames/s and CPU (tumble + ffmpeg, user + system) of"
echo "$((long * 30 + 1)) frames minus $((short * 30 + 1)) (start-up cancels); $(nproc) cores available;"
echo "$(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //')."
echo
echo "| cores (taskset -c) | --jobs | PNG frames/s | PNG CPU ms/frame | video (streamed H.264) frames/s | video CPU ms/frame |"
echo "|---|---|---|---|---|---|"
png=(--video none)
video=(--video mp4 --frames-out none)
for cores in ${CORES:-0 0,1}; do
  # The short render (start-up and a few frames) once per cores and path: --jobs barely changes it.
  declare -A rows=()
  for path in png video; do
    declare -n args=$path
    base=$(render "$cores" 1 "$short" "${args[@]}")
    for jobs in ${JOBS:-1 2 3 4}; do rows[$jobs$path]=$(rate "$cores" "$jobs" "${args[@]}"); done
  done
  for jobs in ${JOBS:-1 2 3 4}; do echo "| $cores | $jobs | ${rows[${jobs}png]} | ${rows[${jobs}video]} |"; done
  unset rows
done
