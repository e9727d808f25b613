#!/usr/bin/env bash
# A hostile probe over every subcommand: special files where tumble reads or
# writes, outputs that are inputs of the same run, damaged resources, absurd
# but legal sizes. Each case runs under a time limit (20 s) and 2 GB of
# address space and is judged: "ok" when tumble neither hung, crashed nor
# said "internal error", exited as the case expects, and every input (and
# special file) is as it was; otherwise what went wrong.
#
#   scripts/hostile_probe.sh TUMBLE               one binary: a TSV (case, command, verdict); exit 1 unless all ok
#   scripts/hostile_probe.sh OLD_TUMBLE NEW_TUMBLE  a markdown table: case | command | before | after
#
# Needs GL (OSMesa) for the render cases, ffmpeg for none. Runs in a temp folder.
set -uo pipefail
src=$(cd "$(dirname "$0")/.." && pwd)

if [ $# -eq 2 ]; then
  a=$(mktemp) b=$(mktemp)
  "$0" "$1" >"$a" 2>/dev/null
  "$0" "$2" >"$b"
  echo "| case | command | before | after |"
  echo "|---|---|---|---|"
  paste "$a" "$b" | awk -F'\t' '{ printf "| %s | `%s` | %s | %s |\n", $1, $2, $3, $6 }'
  rm -f "$a" "$b"
  exit 0
fi

bin=$(readlink -f "$1")
work=$(mktemp -d /tmp/tumble_probe.XXXXXX)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1

# A small scene with its cloud beside it, and a mesh scene.
setup() {
  rm -rf "$work"/c && mkdir -p "$work"/c && cd "$work"/c || exit 1
  printf 'x,y,z,m\n1,0,0,1\n-1,0,0,1\n0,1,0,2\n0,0,1,3\n' >cloud.csv
  printf 'name = "s"\n[simulation]\nduration = 0.3\nfps = 10\n[[bodies]]\ncloud = "cloud.csv"\n[output]\nwidth = 64\nheight = 48\nvideo = "none"\n' >s.toml
  cp "$src/scenes/meshes/wing_nut.stl" nut.stl 2>/dev/null || true
  printf 'name = "m"\n[simulation]\nduration = 0.3\nfps = 10\n[[bodies]]\nshape = { type = "mesh", file = "nut.stl", units = "mm", density = 7850 }\n' >m.toml
  sha256sum cloud.csv s.toml >sums.before
}

# run CASE EXPECT CMD...: EXPECT is the exit code wanted (a list like "1|2").
T=tumble
run() {
  local name=$1 expect=$2
  shift 2
  local cmd="$*" shown=${*//$bin/tumble}
  local t0 rc err verdict
  t0=$(date +%s.%N)
  [[ $cmd == tumble\ * ]] && cmd="$bin ${cmd#tumble }"
  bash -c "ulimit -v 2000000; $pre exec timeout -s KILL 20 $cmd" >out.txt 2>err.txt </dev/null
  rc=$?
  err=$(grep -v '^$' err.txt | head -1 | cut -c1-110 | tr '\t|' '  ')
  local secs
  secs=$(awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }')
  if [ $rc -eq 137 ]; then verdict="HANG (killed at 20 s)"
  elif [ $rc -gt 128 ]; then verdict="CRASH (signal $((rc - 128)))"
  elif grep -q "internal error" err.txt; then verdict="internal error, exit $rc"
  elif ! grep -qE "^($expect)$" <<<"$rc"; then verdict="exit $rc (wanted ${expect//|/ or })"
  elif ! sha256sum -c --quiet sums.before >/dev/null 2>&1; then verdict="INPUT CHANGED, exit $rc"
  elif [ -n "$check" ] && ! (eval "$check") >/dev/null 2>&1; then verdict="check failed ($check), exit $rc"
  else verdict="ok: exit $rc"
  fi
  printf '%s\t%s\t%s, %s s: %s\n' "$name" "$shown" "$verdict" "$secs" "${err:-(no message)}"
  [[ $verdict == ok:* ]] || failures=$((failures + 1))
  pre="" check=""
}
pre="" check="" failures=0

# --- special files ---------------------------------------------------------
setup; mkfifo out.fifo; check='[ -p out.fifo ]'
run "CSV onto a FIFO" "1|2" tumble simulate s.toml --csv out.fifo
# As root a device of our own (a tumble that writes over it breaks only that one).
setup; full=/dev/full; [ "$(id -u)" = 0 ] && mknod full c 1 7 && full=$PWD/full; check="[ -c $full ]"
run "CSV onto a device (full, c 1 7)" "1|2" tumble simulate s.toml --csv "$full"
setup; mkfifo o; check='[ -p o ]'
run "render -o a FIFO" "1|2" tumble render s.toml -o o --progress none
setup; mkdir o; mkfifo o/.tumble.lock; check='[ -p o/.tumble.lock ]'
run "lock file is a FIFO" "1|2" tumble render s.toml -o o --progress none
setup; tumble_ok=$("$bin" render s.toml -o o --progress none >/dev/null 2>&1; echo $?); rm -f o/frames.sums; mkfifo o/frames.sums
run "resume with frames.sums a FIFO (render ok: $tumble_ok)" "1|2" tumble render s.toml -o o --resume --progress none
setup; mkfifo a.png
run "compare a FIFO" "1|2" tumble compare a.png a.png
setup
run "compare /dev/zero" "1|2" tumble compare /dev/zero /dev/zero
setup; mkdir g; mkfifo g/s.trajectory.csv
run "golden trajectory a FIFO" "1|2" tumble golden s.toml --dir g --frames 1 --physics-only
setup; mkdir g; "$bin" golden s.toml --dir g --frames 1 --update >/dev/null 2>&1; png=$(ls g/*.png | head -1); rm -f "$png"; mkfifo "$png"
run "golden PNG a FIFO" "1|2" tumble golden s.toml --dir g --frames 1
setup; mkdir sh; mkfifo sh/manifest.part-000000-000001.json
run "shard part a FIFO" "1|2" tumble assemble sh --progress none
setup; mkfifo x.glb; check='[ -p x.glb ]'
run "export onto a FIFO" "1|2" tumble export s.toml --gltf x.glb
setup; printf 'name = "p"\n[[bodies]]\ncloud = "/dev/stdin"\n' >p.toml
run "cloud is /dev/stdin" "1|2" tumble info p.toml
setup; mkdir sh; printf '{"tool": "tumble", "scene_hash": "a", "settings_hash": "b", "fps": 10, "width": 64, "height": 48, "frame_count": 2, "frames": [0, 1], "frames_written": 2, "video_format": "none", "crf": 18, "complete": true}\n' >sh/manifest.part-000000-000001.json; ln -s /dev/urandom sh/frames.sums
run "assemble, frames.sums -> /dev/urandom" "1|2" tumble assemble sh --progress none

# --- outputs that are inputs -------------------------------------------------
setup; ln -s s.toml link.csv
run "CSV = the scene, by a link" "2" tumble simulate s.toml --csv link.csv
setup; ln cloud.csv hard.csv
run "CSV = the cloud, by a hard link" "2" tumble simulate s.toml --csv hard.csv
setup
run "layout = the cloud file" "2" tumble render s.toml --layout cloud.csv
setup; cp s.toml s.glb; sha256sum s.glb >>sums.before
run "glTF = the scene file" "2" tumble export s.glb --gltf ./s.glb
setup; cp "$src/tests/golden/poinsot/poinsot_f000030_fxaa.png" sdiff.png; sha256sum sdiff.png >>sums.before
run "compare --diff = an input" "2" tumble compare sdiff.png sdiff.png --diff ./sdiff.png
setup; mkdir rep; cp s.toml rep/index.html; sha256sum rep/index.html >>sums.before
run "golden --report over a user's page" "1|2" tumble golden s.toml --dir g --frames 1 --physics-only --report rep
setup; mkdir o; cp cloud.csv o/; cp s.toml o/s.gif; sed -i 's/video = "none"/video = "gif"/' o/s.gif; sha256sum o/s.gif >>sums.before
run "video named like the scene file" "2" tumble render o/s.gif -o o --progress none
setup; mkdir m; cp cloud.csv m/; cp s.toml m/manifest.json; sha256sum m/manifest.json >>sums.before
run "scene file is OUT/manifest.json" "1|2" tumble render m/manifest.json -o m --progress none

# --- damaged resources -------------------------------------------------------
resource_tree() {  # a copy of tumble whose resource folder is ./res
  mkdir -p res/bin res/fonts && cp "$bin" res/bin/tumble && cp -r "$src/shaders" res/shaders
  cp /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf res/fonts/ 2>/dev/null
}
setup; resource_tree; head -c 3000 /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf >res/fonts/DejaVuSans.ttf
run "font truncated to 3000 bytes" "1" res/bin/tumble render s.toml -o o --progress none
setup; resource_tree; head -c 300000 /dev/urandom >res/fonts/DejaVuSans.ttf
run "font of random bytes" "1" res/bin/tumble render s.toml -o o --progress none
setup; resource_tree; printf 'garbage {\n' >res/shaders/mesh.frag
run "shader garbage" "1" res/bin/tumble render s.toml -o o --progress none
setup; resource_tree; rm res/shaders/line.vert; mkfifo res/shaders/line.vert
run "shader is a FIFO" "1" res/bin/tumble render s.toml -o o --progress none

# --- absurd but legal sizes --------------------------------------------------
setup
run "16384 x 16384 frame, 2 GB address space" "0|1|2" tumble render s.toml -o big --width 16384 --height 16384 --frames 0:0 --progress none
setup; printf 'name = "c"\n[[bodies]]\nshape = { type = "cylinder", radius = 1e-300, length = 1, mass = 1 }\n' >c.toml
run "cylinder radius 1e-300" "2" tumble info c.toml
setup; printf 'name = "c"\n[[bodies]]\nshape = { type = "box", size = [1e300, 1e300, 1e300], mass = 1e300 }\n' >c.toml
run "box of 1e300 m, 1e300 kg" "2" tumble info c.toml
setup; printf 'x,y,z,m\n1,0,0,1e308\n-1,0,0,1e308\n0,1,0,1e308\n0,0,1,1e308\n' >cloud.csv; sha256sum cloud.csv s.toml >sums.before
run "cloud masses 1e308" "2" tumble info s.toml
setup
run "golden --at 1e300" "2" tumble golden s.toml --dir g --at 1e300 --physics-only
setup; printf 'name = "l"\n[simulation]\nduration = 1e9\nfps = 1000\n[[bodies]]\ncloud = "cloud.csv"\n' >l.toml
run "duration 1e9 s at 1000 fps" "2" tumble render l.toml -o o --progress none
setup; pre="ulimit -f 16;"; check='! ls o/*.tmp-* 2>/dev/null'
run "render under ulimit -f 16 (KiB)" "1" tumble render s.toml -o o --width 640 --height 480 --progress none
setup; pre="ulimit -f 4;"; check='! ls ./*.tmp-* 2>/dev/null'
run "export under ulimit -f 4" "1" tumble export m.toml --gltf x.glb
setup; printf 'name = "e"\n[[bodies]]\nshape = { type = "ellipsoid", semi_axes = [1e-200, 1, 1], mass = 1 }\n' >e.toml
run "ellipsoid semi-axis 1e-200 (a disc)" "0|2" tumble info e.toml

[ "$failures" -eq 0 ] || { echo "hostile probe: $failures case(s) not ok" >&2; exit 1; }
