#!/usr/bin/env bash
# Times the volume fill of a 100 000-triangle mesh: a torus
# (R = 0.1 m, r = 0.04 m, 250 × 200 quads) written as binary STL, closed and
# with 3 triangles removed (a small hole: the winding-number tree's path),
# resolution 190 (about 10⁶ particles). Prints `tumble info`'s particle lines
# and the wall time of each. Run on an idle machine:
#   scripts/mesh_fill_timing.sh [build/release/src/app/tumble]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
tumble=${1:-$root/build/release/src/app/tumble}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
python3 - "$dir" <<'PY'
import math, struct, sys
R, r, nu, nv = 0.1, 0.04, 250, 200
def point(i, j):
    u, v = 2 * math.pi * (i % nu) / nu, 2 * math.pi * (j % nv) / nv
    return ((R + r * math.cos(v)) * math.cos(u), (R + r * math.cos(v)) * math.sin(u), r * math.sin(v))
tris = []
for i in range(nu):
    for j in range(nv):
        a, b, c, d = point(i, j), point(i + 1, j), point(i + 1, j + 1), point(i, j + 1)
        tris += [(a, b, c), (a, c, d)]
for name, skip in (("torus.stl", ()), ("torus_hole.stl", (1000, 1001, 55000))):
    kept = [t for k, t in enumerate(tris) if k not in skip]
    with open(f"{sys.argv[1]}/{name}", "wb") as f:
        f.write(b"\0" * 80 + struct.pack("<I", len(kept)))
        for t in kept:
            f.write(struct.pack("<3f", 0, 0, 0) + b"".join(struct.pack("<3f", *p) for p in t) + b"\0\0")
PY
for mesh in torus torus_hole; do
  cat >"$dir/$mesh.toml" <<TOML
name = "$mesh"
[simulation]
method = "splitting"
dt = 1e-3
duration = 1.0
[[bodies]]
name = "$mesh"
shape = { type = "mesh", file = "$mesh.stl", units = "m", density = 1000.0, resolution = 190 }
omega_body = [0.0, 1.0, 0.0]
TOML
  start=$(date +%s.%N)
  "$tumble" info "$dir/$mesh.toml" | grep -E "^    (triangles|watertight|inside test|particles|relative error)"
  end=$(date +%s.%N)
  awk -v m="$mesh" -v a="$start" -v b="$end" 'BEGIN { printf "%s: tumble info took %.2f s wall\n", m, b - a }'
done
