#!/usr/bin/env bash
# Instructions per ray (callgrind, machine-independent) and the output hash of
# flag_study.cpp under each candidate flag set; not part of the suite.
# Usage: bash benchmarks/flags/flag_study.sh [g++]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
cxx=${1:-g++}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "| strategy | flags | instructions/ray | output hash |"
echo "|---|---|---:|---|"
for v in plane-normal-1 CBS-5; do
  def=(); [ $v = CBS-5 ] && def=(-DCBS)
  for f in "" "-march=x86-64-v2" "-march=x86-64-v3" "-fno-math-errno" "-march=x86-64-v3 -fno-math-errno"; do
    declare -A ir=()
    for n in 0 20000; do
      # shellcheck disable=SC2086
      "$cxx" -std=c++17 -O2 -ffp-contract=off "${def[@]}" -DRAYS=$n $f -I"$root/include" -I"$root/glsl" \
        "$root/benchmarks/flags/flag_study.cpp" -o "$tmp/r"
      ir[$n]=$(valgrind --tool=callgrind --callgrind-out-file=/dev/null "$tmp/r" 2>&1 | grep -oE 'Collected : [0-9]+' | awk '{print $3}')
      [ $n = 0 ] || hash=$("$tmp/r")
    done
    echo "| $v | -O2 -ffp-contract=off ${f} | $(( (ir[20000] - ir[0]) / 20000 )) | ${hash%% *} |"
  done
done
