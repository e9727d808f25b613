#!/bin/sh
# rk45 (and with `dop853`, dop853) against odeint's dopri5 at equal delivered
# error on the T-handle and the forced T-handle; `rk4`: rk4 against dop853 at
# 1e-10 rad on the T-handle. See src/bench/studies/adaptive_study.cpp; built
# as the target tumble_adaptive_study of a bench build (scripts/test.sh makes one).
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD:-$root/build/release}
cmake --build "$build" --target tumble_adaptive_study -j2 >/dev/null
"$build/src/bench/tumble_adaptive_study" "$@"
