#!/bin/sh
# The comparison figures between renders that a golden suite must call the
# same: a re-run, LP_NUM_THREADS=1 against 2, OSMesa against EGL, llvmpipe's
# 128-bit (SSE) against its native 256-bit (AVX) code, for every
# golden scene at its golden times with MSAA 4 and 0; and, for scale, MSAA 4
# against MSAA 0 of the same frame (anti-aliasing on every edge). Prints one
# line per pair kind with the worst figures; docs/golden.md's defaults
# come from this.
#   usage: scripts/golden_noise.sh [TUMBLE_BINARY] [OUT_DIR] [WIDTHxHEIGHT]
set -eu
T=${1:-build/release/src/app/tumble}
O=${2:-out/golden-noise}
SIZE=${3:-320x240}
W=${SIZE%x*}
H=${SIZE#*x}
scenes="dzhanibekov:0.5,4,12 methods_compare:0.78,6,15 reference:0.5,3,9 stable_spin:0.5,5,11 symmetric_top:0.5,4,9 thrown_box:0.2,0.9,1.6"
rm -rf "$O"
render() { # variant, then env assignments / options
  v=$1; shift
  for sc in $scenes; do
    name=${sc%%:*}; at=${sc#*:}
    env "$@" "$T" golden "scenes/$name.toml" --at "$at" --dir "$O/$v/$name" --msaa 4,0 --width "$W" --height "$H" \
      --update >/dev/null
  done
}
render base LP_NUM_THREADS=2 TUMBLE_GL=osmesa
render rerun LP_NUM_THREADS=2 TUMBLE_GL=osmesa
render t1 LP_NUM_THREADS=1 TUMBLE_GL=osmesa
render egl LP_NUM_THREADS=2 TUMBLE_GL=egl
render sse LP_NUM_THREADS=2 TUMBLE_GL=osmesa LP_NATIVE_VECTOR_WIDTH=128
# Worst over the pairs of: pixels over the threshold, largest region, windowed mean, max delta.
worst() { # label, then pairs "actual expected" on stdin
  while read -r a e; do "$T" compare "$a" "$e" || true; done | awk -v label="$1" '
    /^(same|different):/ {
      n++; over = $2 + 0;
      match($0, /largest region [0-9]+/); r = substr($0, RSTART + 15, RLENGTH - 15) + 0;
      match($0, /mean [0-9.]+/); m = substr($0, RSTART + 5, RLENGTH - 5) + 0;
      match($0, /max delta [0-9]+/); d = substr($0, RSTART + 10, RLENGTH - 10) + 0;
      if (over > O) O = over; if (r > R) R = r; if (m > M) M = m; if (d > D) D = d;
      if ($1 == "different:") f++ }
    END { printf "%-28s %3d pairs, %3d fail; worst: over %5d px, region %5d px, window mean %6.2f, max delta %3d\n",
          label, n, f, O, R, M, D }'
}
pairs() { # variant
  for f in "$O"/base/*/*.png; do echo "$O/$1/${f#"$O"/base/} $f"; done
}
echo "golden noise at ${W}x${H} (default limits of tumble compare)"
pairs rerun | worst "re-run"
pairs t1 | worst "LP_NUM_THREADS 1 vs 2"
pairs egl | worst "EGL vs OSMesa"
pairs sse | worst "128- vs 256-bit llvmpipe"
for f in "$O"/base/*/*_msaa4.png; do echo "${f%_msaa4.png}_msaa0.png $f"; done | worst "MSAA 0 vs 4 (not noise)"
