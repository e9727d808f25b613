#!/bin/sh
# Regenerates the README's figures from the code, so none is copied by hand:
#  - the method table between <!-- BEGIN/END methods --> in README.md
#    (`tumble methods --readme`, from core's method table; instant);
#  - the accuracy table between <!-- BEGIN/END bench:accuracy-table --> in
#    README.md (`tumble bench --readme-table`, about a minute);
#  - docs/bench_work_precision_t_handle.png and docs/bench_stability_map.png
#    from a full `tumble bench` (a few minutes; skipped with --table-only);
#  - the `tumble info scenes/thruster.toml` method block between
#    <!-- BEGIN/END info:thruster --> in README.md (instant);
#  - the render figures between <!-- BEGIN/END bench:render --> and
#    bench:render-dense (frames/s with
#    FXAA and 4x MSAA, video paths, FXAA against 4x MSAA; `tumble bench
#    --render`, about a minute; skipped with --table-only).
# Timings depend on the machine and its load: run it on an idle one.
set -eu
cd "$(dirname "$0")/.."
tumble=${TUMBLE:-build/release/src/app/tumble}
out=${OUT:-out/bench}
if [ ! -x "$tumble" ]; then
  echo "readme_figures: $tumble not found; build first: cmake --preset release && cmake --build --preset release --target tumble" >&2
  exit 1
fi
if [ "${1:-}" != "--table-only" ]; then
  "$tumble" bench -o "$out"
  for f in work_precision_t_handle stability_map; do
    [ -s "$out/$f.png" ] || { echo "readme_figures: $out/$f.png missing (is gnuplot installed?)" >&2; exit 1; }
  done
  cp "$out/work_precision_t_handle.png" docs/bench_work_precision_t_handle.png.tmp
  mv docs/bench_work_precision_t_handle.png.tmp docs/bench_work_precision_t_handle.png
  cp "$out/stability_map.png" docs/bench_stability_map.png.tmp
  mv docs/bench_stability_map.png.tmp docs/bench_stability_map.png
  "$tumble" bench --render --frames 120 -o "$out" --readme-table README.md
fi
"$tumble" methods --readme README.md
# auto's pick for the shipped thruster: `info`'s method line and its candidates.
"$tumble" info scenes/thruster.toml | python3 -c '
import re, sys
info = sys.stdin.read().splitlines()
first = next(i for i, l in enumerate(info) if l.startswith("  method "))
last = next(i for i in range(first + 1, len(info)) if not info[i].startswith("    "))
body = "\n".join("    " + l[2:].rstrip() for l in info[first:last])
readme = open("README.md").read()
new = re.sub(r"(<!-- BEGIN info:thruster -->\n).*?(<!-- END info:thruster -->)",
             lambda m: m.group(1) + "\n" + body + "\n\n" + m.group(2), readme, flags=re.S)
if new == readme and "info:thruster" not in readme:
    sys.exit("README.md has no <!-- BEGIN/END info:thruster --> block")
open("README.md.tmp", "w").write(new)
'
mv README.md.tmp README.md
"$tumble" bench --readme-table README.md
