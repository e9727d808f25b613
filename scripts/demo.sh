#!/usr/bin/env bash
# Quick start 1: install what is missing, build, render the default demo into out/.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh
./build/release/src/app/tumble render scenes/dzhanibekov.toml "$@"
