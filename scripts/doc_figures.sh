#!/bin/sh
# Regenerates the generated figures of docs/ from the code, so none is copied
# by hand (tumble_docs, the maintainers' tool of a bench build, writes them):
#  - the method table between <!-- BEGIN/END methods --> in docs/methods.md
#    (`tumble_docs methods`, from core's method table; instant);
#  - the accuracy table between <!-- BEGIN/END bench:accuracy-table --> in
#    docs/methods.md (`tumble_docs accuracy`, about a minute);
#  - docs/bench_work_precision_t_handle.png and docs/bench_stability_map.png
#    from a full `tumble bench` (a few minutes; skipped with --table-only);
#  - the `tumble info scenes/thruster.toml` method block between
#    <!-- BEGIN/END info:thruster --> in docs/methods.md (instant);
#  - the render figures between <!-- BEGIN/END bench:render --> and
#    bench:render-dense in docs/rendering.md (frames/s with FXAA and 4x MSAA,
#    video paths, FXAA against 4x MSAA; `tumble_docs render`, about a minute;
#    skipped with --table-only).
# The per-step speed table is scripts/gen_method_costs.sh's. Timings depend on
# the machine and its load: run it on an idle one.
set -eu
cd "$(dirname "$0")/.."
build=${BUILD:-build/release}
tumble=$build/src/app/tumble
docs_tool=$build/src/bench/tumble_docs
out=${OUT:-out/bench}
for t in "$tumble" "$docs_tool"; do
  if [ ! -x "$t" ]; then
    echo "doc_figures: $t not found; build first: scripts/test.sh, or cmake --build $build --target tumble tumble-bench tumble_docs" >&2
    exit 1
  fi
done
if [ "${1:-}" != "--table-only" ]; then
  "$tumble" bench -o "$out"
  for f in work_precision_t_handle stability_map; do
    [ -s "$out/$f.png" ] || { echo "doc_figures: $out/$f.png missing (is gnuplot installed?)" >&2; exit 1; }
  done
  cp "$out/work_precision_t_handle.png" docs/bench_work_precision_t_handle.png.tmp
  mv docs/bench_work_precision_t_handle.png.tmp docs/bench_work_precision_t_handle.png
  cp "$out/stability_map.png" docs/bench_stability_map.png.tmp
  mv docs/bench_stability_map.png.tmp docs/bench_stability_map.png
  "$docs_tool" render docs/rendering.md --frames 120 -o "$out"
fi
"$docs_tool" methods docs/methods.md
# auto's pick for the shipped thruster: `info`'s method line and its candidates.
"$tumble" info scenes/thruster.toml | python3 -c '
import re, sys
info = sys.stdin.read().splitlines()
first = next(i for i, l in enumerate(info) if l.startswith("  method "))
last = next(i for i in range(first + 1, len(info)) if not info[i].startswith("    "))
body = "\n".join("    " + l[2:].rstrip() for l in info[first:last])
doc = open("docs/methods.md").read()
new = re.sub(r"(<!-- BEGIN info:thruster -->\n).*?(<!-- END info:thruster -->)",
             lambda m: m.group(1) + "\n" + body + "\n\n" + m.group(2), doc, flags=re.S)
if new == doc and "info:thruster" not in doc:
    sys.exit("docs/methods.md has no <!-- BEGIN/END info:thruster --> block")
open("docs/methods.md.tmp", "w").write(new)
'
mv docs/methods.md.tmp docs/methods.md
"$docs_tool" accuracy docs/methods.md
