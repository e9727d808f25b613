#!/bin/sh
# Regenerates the README's figures from the code, so none is copied by hand:
#  - the method table between <!-- BEGIN/END methods --> in README.md
#    (`tumble methods --readme`, from core's method table; instant);
#  - the accuracy table between <!-- BEGIN/END bench:accuracy-table --> in
#    README.md (`tumble bench --readme-table`, about a minute);
#  - docs/bench_work_precision_t_handle.png and docs/bench_stability_map.png
#    from a full `tumble bench` (a few minutes; skipped with --table-only);
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
"$tumble" bench --readme-table README.md
