#!/usr/bin/env bash
# The table that chooses the video encode's x264 preset and threads (docs/rendering.md,
# "Video encoder"): the demo's frames at 1280x720, CRF 18 as tumble encodes
# them, fed as raw RGB (as `render` pipes them) to libx264 at each preset and
# thread count; time (wall and CPU, user + system), file size, and PSNR and
# SSIM of the decoded video against the PNG frames (ffmpeg's psnr/ssim
# filters, in ffmpeg's yuv420p comparison: the colour subsampling is common
# to every row). Timings depend on the machine's load: run it on a quiet one.
#   scripts/video_presets.sh [tumble binary] [frames] > table.md
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
tumble=${1:-$root/build/release/src/app/tumble}
frames=${2:-120}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$tumble" render "$root/scenes/dzhanibekov.toml" -o "$work/frames" --width 1280 --height 720 \
  --frames "0:$((frames - 1))" --video none --progress none >/dev/null
ffmpeg -nostdin -loglevel error -framerate 30 -i "$work/frames/frame_%06d.png" -f rawvideo -pix_fmt rgb24 "$work/raw.rgb"
cpus=$(nproc)
echo "libx264, CRF 18, ${frames} frames of scenes/dzhanibekov.toml at 1280x720 piped as raw RGB; ${cpus} cores available;"
echo "$(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //'); $(ffmpeg -version | head -1 | cut -d' ' -f1-3)."
echo
echo "| preset | threads | wall ms/frame | CPU ms/frame | frames/s | size, kB | PSNR, dB | SSIM |"
echo "|---|---|---|---|---|---|---|---|"
for preset in ultrafast superfast veryfast faster fast medium; do
  for threads in 1 2 0; do
    out="$work/$preset-$threads.mp4"
    t=$( { /usr/bin/time -f '%e %U %S' ffmpeg -nostdin -loglevel error -y -f rawvideo -pix_fmt rgb24 -s 1280x720 \
      -framerate 30 -i "$work/raw.rgb" -c:v libx264 -preset "$preset" -threads "$threads" -pix_fmt yuv420p \
      -crf 18 -f mp4 "$out"; } 2>&1 | tail -1)
    read -r wall user sys <<<"$t"
    q=$(ffmpeg -nostdin -hide_banner -i "$out" -framerate 30 -i "$work/frames/frame_%06d.png" \
      -lavfi '[0:v]split[a][b];[1:v]format=yuv420p,split[c][d];[a][c]psnr;[b][d]ssim' -f null - 2>&1)
    psnr=$(grep -o 'average:[0-9.inf]*' <<<"$q" | head -1 | cut -d: -f2)
    ssim=$(grep -o 'All:[0-9.]*' <<<"$q" | head -1 | cut -d: -f2)
    kb=$(( $(stat -c %s "$out") / 1024 ))
    awk -v p="$preset" -v th="$threads" -v w="$wall" -v u="$user" -v s="$sys" -v n="$frames" -v kb="$kb" \
      -v psnr="$psnr" -v ssim="$ssim" 'BEGIN {
        printf "| %s | %s | %.1f | %.1f | %.0f | %d | %.2f | %.4f |\n", p, (th == 0 ? "auto" : th),
          1000 * w / n, 1000 * (u + s) / n, n / w, kb, psnr, ssim }'
  done
done
