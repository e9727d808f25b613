#!/bin/sh
# The font check against damaged fonts under AddressSanitizer + UBSan (the
# render library is not in the fuzz preset): builds scripts/font_mutations.cpp
# with the check, the atlas and the input reader, and runs ROUNDS copies.
#   scripts/font_mutations.sh [ROUNDS=6000] [SEED=1]
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
src=$root/src
${CXX:-g++} -std=c++20 -O1 -g -fsanitize=address,undefined -fno-sanitize-recover=all -I"$src" -I/usr/include/eigen3 \
  "$root/scripts/font_mutations.cpp" "$src/render/font_check.cpp" "$src/render/font_atlas.cpp" \
  "$src/base/input_file.cpp" -o "$out/mutations"
"$out/mutations" "${1:-6000}" "${2:-1}" "$out/font.ttf"
