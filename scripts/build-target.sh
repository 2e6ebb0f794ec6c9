#!/usr/bin/env bash
# What the README's example commands (scripts/lab.sh, scripts/gallery.sh) do
# before they run a program: install what is missing (Debian packages),
# configure the Release build in $SNELL_BUILD_DIR (default build/, in the
# repository) and build one target. Progress goes to stderr; stdout is the
# build directory's absolute path, for the caller to find the program in.
# Usage: build=$(bash scripts/build-target.sh <cmake target>)
set -euo pipefail
[ $# -eq 1 ] || { echo "usage: build-target.sh <cmake target>" >&2; exit 2; }
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh >&2
build=${SNELL_BUILD_DIR:-build}
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j "$(nproc)" --target "$1" >&2
cd "$build" && pwd
