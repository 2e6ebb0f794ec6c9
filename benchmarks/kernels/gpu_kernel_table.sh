#!/usr/bin/env bash
# The kernel study on the GPU path: snell's GLSL single sample, normal plane
# (1 it.), CBS-5, linear march (32 steps, 4 refinements) and the whole
# two-interface technique (normal plane, 2 it.) beside the hand-written GLSL
# kernels of gpu_kernels.glsl, one ray (or front-face fragment) per pixel of a
# 512x512 pass on Mesa llvmpipe (gpu_kernel_study.cpp). Fails unless each
# kernel gives snell's output bits on every ray; prints the median pass times
# (all variants interleaved in one run) and, with callgrind (llvmpipe
# rendering on the calling thread, LP_NUM_THREADS=0), the instructions per
# pixel each pass executes, JIT code and texture sampling included:
# repeatable where the times are not. About 6 minutes; not part of the suite;
# the `bench` target runs it. GPU_KERNEL_TABLE_OUT=FILE also writes the output
# there. Usage: bash benchmarks/kernels/gpu_kernel_table.sh [rounds] [backend]
set -euo pipefail
if [ -n "${GPU_KERNEL_TABLE_OUT:-}" ]; then
  mkdir -p "$(dirname "$GPU_KERNEL_TABLE_OUT")"
  exec > >(tee "$GPU_KERNEL_TABLE_OUT")
fi
root=$(cd "$(dirname "$0")/../.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
rounds=${1:-21}
backend=${2:-osmesa}
"${CXX:-g++}" -std=c++17 -O2 -ffp-contract=off -I"$root/benchmarks/kernels" -I"$root/include" -I"$root/glsl" \
  -DSNELL_GLSL_DIR="\"$root/glsl\"" -DSNELL_KERNELS_DIR="\"$root/benchmarks/kernels\"" \
  "$root/benchmarks/kernels/gpu_kernel_study.cpp" -o "$tmp/study" -ldl
"$tmp/study" "$rounds" "$backend" | tee "$tmp/run.txt"
# One pass per variant under callgrind (the study's drawVariant<V>, the untimed
# first passes that compile the programs excluded).
LP_NUM_THREADS=0 valgrind --tool=callgrind --smc-check=all --collect-atstart=no --toggle-collect='*drawVariant*' \
  --callgrind-out-file="$tmp/cg.out" "$tmp/study" 1 "$backend" >/dev/null 2>"$tmp/cg.err" ||
  { cat "$tmp/cg.err" >&2; exit 1; }
callgrind_annotate --inclusive=yes "$tmp/cg.out" | grep -E 'drawVariant<[0-9]+>' |
  sed -E 's/^ *([0-9,]+) .*drawVariant<([0-9]+)>.*/\2 \1/' | tr -d , | sort -n >"$tmp/ir.txt"
echo
echo "| variant | instructions per pixel (callgrind) | over its single sample | over the kernel |"
echo "|---|---:|---:|---:|"
awk -v pixels=$((512 * 512)) '
  FNR == NR {  # "variant V single S twin T: name" (gpu_kernel_study.cpp)
    if ($1 == "variant") { v = $2; single[v] = $4; twin[v] = $6 + 0; line = $0; sub(/^[^:]*: /, "", line); name[v] = line }
    next
  }
  { ir[$1] = $2 / pixels; n = $1 > n ? $1 : n }
  END {
    for (v = 0; v <= n; ++v) {
      t = twin[v]
      printf "| %s | %.0f | %.2fx | %s |\n", name[v], ir[v], ir[v] / ir[single[v]], t < 0 ? "" : sprintf("%.2fx", ir[v] / ir[t])
    }
  }' "$tmp/run.txt" "$tmp/ir.txt"
