#!/bin/sh
# Regenerates the documentation's frames (docs/demo_frame.png, docs/explained_*.png,
# docs/poinsot_*.png, docs/tennis_racket_flip.png, docs/methods_compare_frame.png,
# docs/readme_scene.png: the README's scene, from its toml block) and the lessons'
# storyboards (docs/storyboard_<scene>.png): the demo and a few frames
# of the explanatory scenes rendered at 960x540 (`tumble info` lists what each frame shows); at
# 640x360 the keys' text is ~6.5 px and thin stems (l, i, I) drop out.
set -eu
cd "$(dirname "$0")/.."
tumble=${TUMBLE:-build/release/src/app/tumble}
out=${OUT:-out/explain_frames}
if [ ! -x "$tumble" ]; then
  echo "explain_frames: $tumble not found; build first: cmake --build --preset release --target tumble" >&2
  exit 1
fi
# scene frame docs-name: frame 40 = the title card; 1050 = the stop at the
# first flip (t = 1.29 s, the stem across L); 1376 = t = 2.28 s, Π near −e₂
# between the flips; poinsot 1215 = t = 3 s;
# tennis_racket 600 = the hold at the middle racket's first flip (t = 0.47 s);
# dzhanibekov 800 = the demo's hold at flip 2 (t = 5.09 s: ω 28° off L, seen across,
# the two stable spins either side of the T); methods_compare 680 = the stop at t = 0.78 s,
# explicit Euler's energy just past the separatrix (ringed on the plot).
for spec in "dzhanibekov 800 demo_frame" "dzhanibekov_explained 40 explained_start" "dzhanibekov_explained 1050 explained_flip" \
            "dzhanibekov_explained 1376 explained_after" "poinsot 1215 poinsot_3s" \
            "tennis_racket 600 tennis_racket_flip" "methods_compare 680 methods_compare_frame"; do
  set -- $spec
  "$tumble" render "scenes/$1.toml" --frames "$2:$2" --width 960 --height 540 --video none --progress none \
    --force -o "$out/$1" >/dev/null
  png=$(printf '%s/%s/frame_%06d.png' "$out" "$1" "$2")
  cp "$png" "docs/$3.png.tmp"
  mv "docs/$3.png.tmp" "docs/$3.png"
done
# The storyboards: 8 frames spread over each lesson and one at every event, drawn
# at 960x540 and shown 400 px wide (tumble storyboard).
for scene in dzhanibekov_explained tennis_racket poinsot methods_compare dzhanibekov; do
  "$tumble" storyboard "scenes/$scene.toml" --width 960 --height 540 -n 8 --tile-width 400 --progress none \
    -o "docs/storyboard_$scene.png" >/dev/null
done
# The README's scene, as its toml block says, at frame 54 (t = 1.8 s, the first flip).
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
python3 -c 'import re, sys; sys.stdout.write(re.search(r"```toml\n(.*?)```", open("README.md").read(), re.S).group(1))' >"$tmp/flip.toml"
"$tumble" render "$tmp/flip.toml" --frames 54:54 --width 960 --height 540 --video none --progress none --force \
  -o "$out/flip" >/dev/null
cp "$out/flip/frame_000054.png" docs/readme_scene.png.tmp
mv docs/readme_scene.png.tmp docs/readme_scene.png
