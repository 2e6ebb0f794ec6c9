#!/usr/bin/env bash
# Instructions per ray (callgrind, machine-independent) and the hash of every
# output bit of snell's C++ build under each candidate compile flag set, for the
# normal plane (1 it.) and CBS-5 on the rays and buffers of
# benchmarks/kernels/kernel_scene.hpp (docs/api.md, "Compile flags for tools").
# It builds benchmarks/kernels/kernel_study.cpp (-DIMPL=snell): one binary per
# flag set, the ray loop outside main() and its count given at run time, so
# (Ir(20000 rays) - Ir(0 rays)) / 20000 counts the same code that runs.
# A flag set that changes a result shows as another hash. Not part of the suite.
# Usage: bash benchmarks/flags/flag_study.sh [g++]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
cxx=${1:-g++}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
ir() {  # binary, rays
  valgrind --tool=callgrind --callgrind-out-file=/dev/null "$1" "$2" 2>&1 | grep -oE 'Collected : [0-9]+' | awk '{print $3}'
}
echo "| strategy | flags | instructions/ray | output hash |"
echo "|---|---|---:|---|"
for s in plane_normal_1 cbs_5; do
  for f in "" "-march=x86-64-v2" "-march=x86-64-v3" "-fno-math-errno" "-march=x86-64-v3 -fno-math-errno"; do
    # shellcheck disable=SC2086
    "$cxx" -std=c++17 -O2 -ffp-contract=off $f -I"$root/benchmarks/kernels" -I"$root/include" -I"$root/glsl" \
      -DSTRATEGY=$s -DIMPL=snell "$root/benchmarks/kernels/kernel_study.cpp" -o "$tmp/r"
    a=$(ir "$tmp/r" 0)
    b=$(ir "$tmp/r" 20000)
    hash=$("$tmp/r")
    echo "| $s | -O2 -ffp-contract=off${f:+ $f} | $(( (b - a) / 20000 )) | ${hash%% *} |"
  done
done
