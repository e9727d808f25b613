#!/bin/sh
# The sub-flow order study behind kernel::split_order (splitting; argument 4:
# split_order4, splitting4's base map), see splitting_kernel.hpp. Arguments
# `max` (worst error over t = 1..10 s) and `csv` (one row per case) too.
# Needs a release build of tumble_core: cmake --build --preset release --target tumble_core
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
${CXX:-g++} -std=c++20 -O2 -ffp-contract=off -I"$root/src" -I/usr/include/eigen3 \
  "$root/scripts/splitting_order_study.cpp" "$root/build/release/src/core/libtumble_core.a" -o "$out/study"
"$out/study" "$@"
