#!/usr/bin/env bash
# Runs the libFuzzer targets (built by the `fuzz` preset) for SECONDS each
# (default 30), seeded from the shipped scenes, the broken-scene corpus, assimp's
# PLY models and the regression corpus. A crash leaves crash-* in build/fuzz/artifacts/<target>/: add the
# input to tests/fuzz/regressions/{scene,cloud,ply,mesh}/ (replayed by scene_tests). fuzz_mesh
# inputs start with a byte naming the format (o, s, p, f: OBJ, STL, PLY, OFF), then the file.
set -euo pipefail
cd "$(dirname "$0")/.."
SECONDS_EACH="${1:-30}"
BUILD="${FUZZ_BUILD_DIR:-build/fuzz}"
work="$BUILD/corpus"
mkdir -p "$work/scene" "$work/cloud" "$work/ply" "$work/mesh"
cp scenes/*.toml tests/scene/broken/*.toml tests/fuzz/regressions/scene/* "$work/scene/" 2>/dev/null || true
cp tests/fuzz/regressions/cloud/* "$work/cloud/" 2>/dev/null || true
cp tests/fuzz/regressions/ply/* tests/scene/broken/data/*.ply /usr/share/assimp/models/PLY/*.ply "$work/ply/" 2>/dev/null || true
cp tests/fuzz/regressions/mesh/* "$work/mesh/" 2>/dev/null || true
models=/usr/share/assimp/models
for f in $models/OBJ/*.obj $models/STL/*.stl $models/PLY/*.ply $models/OFF/*.off scenes/meshes/*.stl; do
  [ -f "$f" ] && [ "$(stat -c %s "$f")" -le 65535 ] || continue
  case "${f##*.}" in obj) k=o ;; stl) k=s ;; ply) k=p ;; off) k=f ;; esac
  { printf %s "$k"; cat "$f"; } >"$work/mesh/seed_$(basename "$f")"
done
# One target for SECONDS_EACH, its artifacts in a folder of its own so that a
# failure names its target even when targets run side by side.
fuzz_one() {
  local t=$1 art="$BUILD/artifacts/$1"
  mkdir -p "$art"
  # -timeout 60: a valid scene near the 10⁷-particle cap takes ~15 s to build
  # under the fuzz build's sanitizers (a t_handle 5.1 m thick at 63/m did, and
  # failed CI at -timeout=10); a real hang still trips it. -report_slow_units
  # at the same 60 s: libFuzzer's default (10 s) writes such a valid slow scene
  # as a slow-unit-* artifact, which is not a failure (dzhanibekov.toml with
  # thickness 5.1, 3.9 M particles, took 22 s).
  "$BUILD/tests/fuzz/fuzz_$t" -max_total_time="$SECONDS_EACH" -timeout=60 -report_slow_units=60 -rss_limit_mb=2048 -max_len=65536 \
    -print_final_stats=1 -artifact_prefix="$art/" "$work/$t" 2>&1 | grep -E "^(stat::|#[0-9]+ *DONE|==|SUMMARY|Done)" | sed "s/^/fuzz_$t: /" || true
  if ls "$art" | grep -q .; then
    echo "fuzz: fuzz_$t found a failing input:" && ls "$art"
    return 1
  fi
}
# FUZZ_JOBS targets at once (default 2: CI's cores); each is single-threaded.
jobs="${FUZZ_JOBS:-2}"
rm -rf "$BUILD/artifacts"
status=0
pids=()
for t in scene cloud ply mesh; do
  echo "fuzz: fuzz_$t for ${SECONDS_EACH}s"
  fuzz_one "$t" & pids+=($!)
  if [ "${#pids[@]}" -ge "$jobs" ]; then
    for p in "${pids[@]}"; do wait "$p" || status=1; done
    pids=()
  fi
done
for p in "${pids[@]}"; do wait "$p" || status=1; done
exit "$status"
