#!/usr/bin/env bash
# The README's test command: install what is missing, configure, build with
# warnings as errors, run the whole suite (unit, GPU parity on both OSMesa and
# EGL, compile checks in every language mode, install/consumer).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
build=${SNELL_BUILD_DIR:-build}
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DSNELL_WERROR=ON
cmake --build "$build" -j "$(nproc)"
# The GL tests must run: a missing context fails them (never a skip).
ctest --test-dir "$build" --output-on-failure -j "$(nproc)"
