#!/bin/sh
# rk45 (and with `dop853`, dop853) against odeint's dopri5 at equal delivered
# error on the T-handle and the forced T-handle; `rk4`: rk4 against dop853 at
# 1e-10 rad on the T-handle. See scripts/adaptive_study.cpp.
# Needs a release build: cmake --build --preset release --target tumble_bench
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
lib=$root/build/release/src
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
${CXX:-g++} -std=c++20 -O2 -DNDEBUG -ffp-contract=off -I"$root/src" -I/usr/include/eigen3 "$root/scripts/adaptive_study.cpp" \
  "$lib/bench/libtumble_bench.a" "$lib/io/libtumble_io.a" "$lib/core/libtumble_core.a" \
  $(pkg-config --libs bullet-float64 2>/dev/null || pkg-config --libs bullet 2>/dev/null) \
  $(pkg-config --libs ode 2>/dev/null) -o "$out/study"
"$out/study" "$@"
