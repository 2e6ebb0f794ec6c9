#!/usr/bin/env bash
# What the speed targets would take: the kernel tables (kernel_table.sh, and
# with --gpu gpu_kernel_table.sh) re-run on copies of glsl/ from which the
# patches in guard_study/ take away, cumulatively, what the kernels leave out:
#   1-trusted       every finiteness, overflow, range and zero-denominator test
#                   of the projection, the reconstruction and the depth read
#                   (snell's contracts need them for hostile input)
#   2-fixed-setup   the depth convention (GL), the filter (NEAREST) and the
#                   level (0) as constants, and SNELL_PERSPECTIVE_ONLY 1
#                   (a C++ surface carries them as run-time fields; a shader
#                   folds them already, and the GPU table's own
#                   SNELL_PERSPECTIVE_ONLY rows show the define)
#   3-kernel-shape  the ray's finiteness and length tests and the off-centre
#                   terms of the perspective (the kernels assume a symmetric
#                   glm::perspective and finite, non-degenerate rays)
#   4-plane         the plane's normal read as one texel (the kernels' A6: at a
#                   texel centre the other bilinear weights are 0) and the
#                   ray-plane intersection's finiteness and length tests
# The patched copies are not snell: they exist to measure. The tables check,
# as always, that each still gives the kernel's bits on every benchmark ray.
# About 2 minutes, 25 with --gpu; not part of the suite.
# Usage: bash benchmarks/kernels/guard_study.sh [--gpu]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
gpu=0
case "${1:-}" in
  "") ;;
  --gpu) gpu=1 ;;
  *) echo "guard_study.sh: unknown argument '$1' (usage: bash benchmarks/kernels/guard_study.sh [--gpu])" >&2; exit 2 ;;
esac
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir "$tmp/tree"
cp -r "$root/glsl" "$root/include" "$root/benchmarks" "$tmp/tree/"
level=0
for p in "$root"/benchmarks/kernels/guard_study/*.patch; do
  level=$((level + 1))
  name=$(basename "$p" .patch)
  (cd "$tmp/tree" && git apply -p0 "$p") || { echo "guard_study.sh: $name no longer applies to glsl/" >&2; exit 1; }
  defines=${KERNEL_TABLE_DEFINES:-}
  [ "$level" -ge 2 ] && defines="$defines -DSNELL_PERSPECTIVE_ONLY=1"
  echo "## up to $name (C++, instructions per ray)"
  KERNEL_TABLE_DEFINES="$defines" bash "$tmp/tree/benchmarks/kernels/kernel_table.sh" single_sample plane_normal_1 cbs_5
  if [ "$gpu" = 1 ]; then
    echo "## up to $name (GLSL on llvmpipe, instructions per pixel)"
    bash "$tmp/tree/benchmarks/kernels/gpu_kernel_table.sh" 1 | sed -n '/instructions per pixel/,$p'
  fi
done
