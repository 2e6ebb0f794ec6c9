#!/usr/bin/env bash
# snell vs minimal hand-written kernels: for each
# strategy of kernel_study.cpp, checks that the kernel gives snell's output bits
# on every ray (fails loudly otherwise), counts instructions per ray with
# callgrind (machine independent: (Ir(20000 rays) - Ir(0 rays)) / 20000) and
# times both in one process (interleaved
# rounds, median ns/ray), at -O2 -ffp-contract=off and at that plus
# -march=x86-64-v3; prints a Markdown table. Fails when the callgrind binary's
# ray loop is not instruction for instruction the one timed. Not part of the suite.
# Usage: bash benchmarks/kernels/kernel_table.sh [strategy ...]
#   CXX=g++ (default)       the compiler
#   KERNEL_TABLE_DEFINES=...  extra -D options for every build
#   KERNEL_TABLE_JOBS=2     builds and callgrind runs in parallel
#   KERNEL_TABLE_BREAKDOWN=1  also print, per strategy, where snell's instructions
#                           per ray go (callgrind, source file of the inlined
#                           code, -O2 -ffp-contract=off, the ray loop only)
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
src=$root/benchmarks/kernels/kernel_study.cpp
cxx=${CXX:-g++}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
strategies=("$@")
[ ${#strategies[@]} -gt 0 ] || strategies=(single_sample plane_normal_0 plane_normal_1 plane_normal_2 cbs_5
  plane_depth_0 plane_depth_1 plane_depth_2 linear_march_32x4 dda_1)
flagsets=("" "-march=x86-64-v3")
base=(-std=c++17 -O2 -ffp-contract=off)
rays=20000
maxjobs=${KERNEL_TABLE_JOBS:-2}  # builds and callgrind runs at a time (2 cores); timing runs alone

pool() {  # run "$@" in the background, at most $maxjobs at a time
  while [ "$(jobs -rp | wc -l)" -ge "$maxjobs" ]; do wait -n || true; done
  "$@" &
}
fail() { echo "kernel_table.sh: $*" >&2; exit 1; }

build() {  # out, flag-set index, defines... (-g changes no instruction: it names
           # the source lines for the breakdown; the precompiled kernel_scene.hpp
           # saves a third of each build and changes no instruction either)
  local out=$1 fi=$2
  shift 2
  # shellcheck disable=SC2086
  if ! "$cxx" "${base[@]}" -g ${flagsets[$fi]} -Winvalid-pch -include "$tmp/pch$fi/kernel_scene.hpp" \
      -I"$root/benchmarks/kernels" -I"$root/include" -I"$root/glsl" ${KERNEL_TABLE_DEFINES:-} "$@" "$src" -o "$out" \
      2>"$out.err"; then
    touch "$tmp/FAILED"
  fi
}
pch() {  # flag-set index
  local d=$tmp/pch$1
  mkdir -p "$d"
  ln -s "$root/benchmarks/kernels/kernel_scene.hpp" "$d/kernel_scene.hpp"
  # shellcheck disable=SC2086
  "$cxx" "${base[@]}" -g ${flagsets[$1]} -I"$root/benchmarks/kernels" -I"$root/include" -I"$root/glsl" \
    ${KERNEL_TABLE_DEFINES:-} -x c++-header "$root/benchmarks/kernels/kernel_scene.hpp" -o "$d/kernel_scene.hpp.gch" 2>"$d.err" || touch "$tmp/FAILED"
}
ir() {  # binary, ray count -> prints callgrind's instruction count
  valgrind --tool=callgrind --callgrind-out-file=/dev/null "$1" "$2" 2>&1 | grep -oE 'Collected : [0-9]+' | awk '{print $3}'
}
count() {  # binary -> writes binary.ir: Ir(0 rays) Ir(rays)
  local a b
  if a=$(ir "$1" 0) && b=$(ir "$1" $rays) && [ -n "$a" ] && [ -n "$b" ]; then
    echo "$a $b" >"$1.ir"
  else
    touch "$tmp/FAILED"
  fi
}

# 1. build
for fi in "${!flagsets[@]}"; do pool pch "$fi"; done
wait
for s in "${strategies[@]}"; do
  for fi in "${!flagsets[@]}"; do
    pool build "$tmp/$s.$fi.snell" "$fi" -DSTRATEGY="$s" -DIMPL=snell
    pool build "$tmp/$s.$fi.kernel" "$fi" -DSTRATEGY="$s" -DIMPL=kernel
    pool build "$tmp/$s.$fi.ct" "$fi" -DSTRATEGY="$s" -DCHECK -DTIME
  done
done
wait
if [ -e "$tmp/FAILED" ]; then
  cat "$tmp"/*.err "$tmp"/*/*.err >&2 2>/dev/null || true
  fail "a build failed"
fi
echo "kernel_table.sh: built in ${SECONDS} s" >&2

# 2. instructions per ray
for s in "${strategies[@]}"; do
  for fi in "${!flagsets[@]}"; do
    pool count "$tmp/$s.$fi.snell"
    pool count "$tmp/$s.$fi.kernel"
  done
done
wait
[ -e "$tmp/FAILED" ] && fail "a callgrind run failed"
echo "kernel_table.sh: counted by ${SECONDS} s" >&2

# 3. bit-identity and time, one process per strategy and flag set, nothing else running
for s in "${strategies[@]}"; do
  for fi in "${!flagsets[@]}"; do
    out=$("$tmp/$s.$fi.ct") || { echo "$out" >&2; fail "$s ${flagsets[$fi]}: the kernel's outputs differ from snell's (above)"; }
    echo "$out" >"$tmp/$s.$fi.out"
    if ! a=$("$tmp/$s.$fi.snell") || ! b=$("$tmp/$s.$fi.kernel"); then fail "$s ${flagsets[$fi]}: an -DIMPL binary failed"; fi
    [ "$a" = "$b" ] || fail "$s ${flagsets[$fi]}: -DIMPL=snell prints $a, -DIMPL=kernel $b"
    while read -r line; do
      case $line in
        "check $s "*) d=$(sed -E 's/.* differ=([0-9]+) .*/\1/' <<<"$line")
          [ "$d" = 0 ] || { echo "$out" >&2; fail "$s ${flagsets[$fi]}: $d rays differ"; } ;;
      esac
    done <<<"$out"
  done
done

echo "kernel_table.sh: checked and timed by ${SECONDS} s" >&2

# The counted code must be the timed code: the ray loop of each callgrind binary
# has the same instructions as in the CHECK/TIME binary (addresses and
# alignment padding aside; in the same order, or at least the same multiset).
loopasm() {  # binary, implementation, strategy
  objdump -d --no-show-raw-insn -C "$1" |
    awk -v pat="runRays<&(anonymous namespace)::$2_$3>" 'index($0, pat) && />:$/ {p = 1; next} /^$/ {p = 0} p' |
    sed -E 's/^ *[0-9a-f]+:[[:space:]]*//; s/[0-9a-f]+ <[^>]*>/ADDR/g; s/-?0x[0-9a-f]+\(%rip\)/RIP/g' |
    grep -vE '^(nop|xchg +%ax,%ax|data16|cs nop)'  # alignment padding
}
for s in "${strategies[@]}"; do
  for fi in "${!flagsets[@]}"; do
    for impl in snell kernel; do
      loopasm "$tmp/$s.$fi.$impl" $impl "$s" >"$tmp/a1"
      loopasm "$tmp/$s.$fi.ct" $impl "$s" >"$tmp/a2"
      [ -s "$tmp/a1" ] || fail "$s $impl: no ray loop found in the disassembly"
      if ! cmp -s "$tmp/a1" "$tmp/a2"; then
        # the same instructions in another order (the scheduler's choice) count the same
        cmp -s <(sort "$tmp/a1") <(sort "$tmp/a2") ||
          fail "$s ${flagsets[$fi]} $impl: the counted loop differs from the timed one"
        echo "kernel_table.sh: $s ${base[*]:1}${flagsets[$fi]:+ ${flagsets[$fi]}} $impl: the counted loop is the timed one" \
          "scheduled differently" >&2
      fi
    done
  done
done

# 4. the table
echo "| strategy | flags | snell instr/ray | kernel instr/ray | ratio | snell ns/ray | kernel ns/ray | time ratio | identical rays |"
echo "|---|---|---:|---:|---:|---:|---:|---:|---|"
for s in "${strategies[@]}"; do
  for fi in "${!flagsets[@]}"; do
    read -r s0 s1 <"$tmp/$s.$fi.snell.ir"
    read -r k0 k1 <"$tmp/$s.$fi.kernel.ir"
    out=$(cat "$tmp/$s.$fi.out")
    bench=$(grep "^check $s bench" <<<"$out" | sed -E 's/.* rays=([0-9]+) differ=([0-9]+) .*/\1 \2/')
    wide=$(grep "^check $s wide" <<<"$out" | sed -E 's/.* rays=([0-9]+) differ=([0-9]+) .*/\1 \2/')
    tline=$(grep "^time $s " <<<"$out")
    ts=$(sed -E 's/.*snell_ns=([0-9.]+).*/\1/' <<<"$tline")
    tk=$(sed -E 's/.*kernel_ns=([0-9.]+).*/\1/' <<<"$tline")
    awk -v s="$s" -v f="${base[*]:1}${flagsets[$fi]:+ ${flagsets[$fi]}}" -v s0="$s0" -v s1="$s1" -v k0="$k0" -v k1="$k1" \
      -v n=$rays -v ts="$ts" -v tk="$tk" -v bench="$bench" -v wide="$wide" 'BEGIN {
        si = (s1 - s0) / n; ki = (k1 - k0) / n
        split(bench, b, " "); split(wide, w, " ")
        printf "| %s | %s | %.0f | %.0f | %.2fx | %.1f | %.1f | %.2fx | %d/%d (wide set %d/%d) |\n",
          s, f, si, ki, si / ki, ts, tk, ts / tk, b[1] - b[2], b[1], w[1] - w[2], w[1]
      }'
  done
done

# 5. optional: where snell's instructions per ray go
if [ "${KERNEL_TABLE_BREAKDOWN:-0}" = 1 ]; then
  echo
  echo "Where snell's instructions per ray go (-O2 -ffp-contract=off; source file of the inlined code, the ray loop only):"
  for s in "${strategies[@]}"; do
    for impl in snell kernel; do
      valgrind --tool=callgrind --toggle-collect='*runRays*' --callgrind-out-file="$tmp/$s.$impl.cg" \
        "$tmp/$s.0.$impl" $rays >/dev/null 2>&1
    done
    k=$(callgrind_annotate --auto=no "$tmp/$s.kernel.cg" 2>/dev/null | awk '/PROGRAM TOTALS/ {gsub(",", "", $1); print $1}')
    callgrind_annotate --auto=no --threshold=100 "$tmp/$s.snell.cg" 2>/dev/null | awk -v n=$rays -v s="$s" -v k="$k" -v root="$root/" '
      /PROGRAM TOTALS/ { gsub(",", "", $1); total = $1 }
      / \([ 0-9.]+%\)  / && !/PROGRAM TOTALS/ {
        ir = $1; gsub(",", "", ir)
        fn = $0; sub(/^[^)]*\)  /, "", fn); file = fn; sub(/:.*/, "", file)
        sub(root, "", file); sub(/.*glsl\/snell\//, "", file); sub(/[a-z_]+\/\.\.\//, "", file)
        sub(/^\/usr\/include\/glm\/detail\//, "glm/", file)
        if (file ~ /c\+\+\/[0-9]+\/cmath$/) file = "cmath"
        else if (file ~ /c\+\+\/[0-9]+\//) file = "libstdc++"
        else if (file ~ /kernel_study.cpp$/) file = "loop+store"
        else if (file ~ /^\?\?\?/) { file = fn; sub(/^\?\?\?:/, "", file); sub(/ .*/, "", file); file = "libm " file }
        by[file] += ir
      }
      END {
        printf "- %s: %.0f per ray in the loop (kernel: %.0f):", s, total / n, k / n
        m = 0
        for (f in by) { keys[++m] = f }
        for (i = 1; i <= m; i++) for (j = i + 1; j <= m; j++) if (by[keys[j]] > by[keys[i]]) { t = keys[i]; keys[i] = keys[j]; keys[j] = t }
        for (i = 1; i <= m && i <= 8; i++) printf " %s %.0f%s", keys[i], by[keys[i]] / n, i < m && i < 8 ? "," : ""
        printf "\n"
      }'
  done
fi
