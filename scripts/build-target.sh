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
# A build folder copied with the tree (or made by another checkout) names that tree's sources in its cache:
# CMake then stops with a cache-directory error that does not say what to do.
if [ -f "$build/CMakeCache.txt" ]; then
  home=$(sed -n 's/^CMAKE_HOME_DIRECTORY:INTERNAL=//p' "$build/CMakeCache.txt")
  if [ -n "$home" ] && [ "$(cd "$home" 2>/dev/null && pwd -P)" != "$(pwd -P)" ]; then
    dir=$(cd "$build" && pwd)
    echo "build-target.sh: $dir was configured for the sources in $home, not this tree ($(pwd))." >&2
    echo "build-target.sh: remove it (rm -rf '$dir') or set SNELL_BUILD_DIR to another folder, then run again." >&2
    exit 2
  fi
fi
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j "$(nproc)" --target "$1" >&2
cd "$build" && pwd
