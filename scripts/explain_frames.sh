#!/bin/sh
# Regenerates the README's frames of the explanatory scenes (docs/explained_*.png,
# docs/poinsot_*.png): a few frames of scenes/dzhanibekov_explained.toml and
# scenes/poinsot.toml rendered at 640x360.
set -eu
cd "$(dirname "$0")/.."
tumble=${TUMBLE:-build/release/src/app/tumble}
out=${OUT:-out/explain_frames}
if [ ! -x "$tumble" ]; then
  echo "explain_frames: $tumble not found; build first: cmake --build --preset release --target tumble" >&2
  exit 1
fi
# scene frame docs-name: frame 30 = title and first caption (t = 0.5 s);
# 204 = mid-flip (t = 1.9 s, in the 1/8-speed segment); 420 = t = 4 s.
for spec in "dzhanibekov_explained 30 explained_start" "dzhanibekov_explained 204 explained_flip" \
            "dzhanibekov_explained 420 explained_after" "poinsot 180 poinsot_3s"; do
  set -- $spec
  "$tumble" render "scenes/$1.toml" --frames "$2:$2" --width 640 --height 360 --video none --progress none \
    --force -o "$out/$1" >/dev/null
  png=$(printf '%s/%s/frame_%06d.png' "$out" "$1" "$2")
  cp "$png" "docs/$3.png.tmp"
  mv "docs/$3.png.tmp" "docs/$3.png"
done
