#!/usr/bin/env bash
# Builds the libFuzzer targets of tests/fuzz with clang++ (standalone, not
# through the main CMake build: -fsanitize=fuzzer needs clang) and
#   1. runs each target once over its committed crash regressions
#      (tests/fuzz/regressions/<target>/): every input there once crashed;
#   2. fuzzes each target for a bounded time on a copy of its seed corpus
#      (tests/fuzz/corpus/<target>/; the committed corpus is never modified).
# Exits non-zero on any crash, leak, sanitizer report or escaped exception; the
# crashing input is left in $out/crashes/<target>/ with the command to commit it.
#
# Environment: SNELL_FUZZ_TIME (seconds per target, default 6),
# SNELL_FUZZ_BUILD_DIR (default build/fuzz), CLANGXX (default clang++-14 or clang++),
# SNELL_FUZZ_TARGETS (default: every target tests/fuzz/targets.sh lists; the
# image_<format> targets are one source, fuzz_image.cpp, each fuzzed from its
# own format's corpus), targets fuzzed $(nproc) at a time,
# SNELL_FUZZ_BUILD_ONLY=1 (build the targets and stop: tests/fuzz/campaign.sh),
# SNELL_FUZZ_DECODERS=debian|source (default debian): the image libraries
# (libspng, libjpeg-turbo, OpenEXRCore) the targets link. debian: Debian's
# builds, not instrumented (coverage and sanitizers see snell's side of each
# call), enough for the smoke run; source: Debian's source packages built with
# the targets' instrumentation by build_decoders.sh (in $out/decoders), so a
# campaign's coverage reaches inside the decoder (campaign.sh's default).
# Needs clang-14 and libclang-rt-14-dev (scripts/install-deps.sh).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
out=${SNELL_FUZZ_BUILD_DIR:-$root/build/fuzz}
seconds=${SNELL_FUZZ_TIME:-6}
# shellcheck source=tests/fuzz/targets.sh
source "$root/tests/fuzz/targets.sh"
targets=${SNELL_FUZZ_TARGETS:-$snell_fuzz_targets}
cxx=${CLANGXX:-$(command -v clang++-14 || command -v clang++ || true)}
[ -n "$cxx" ] || { echo "run_fuzzers: clang++ not found (install clang-14 libclang-rt-14-dev)" >&2; exit 1; }
mkdir -p "$out/obj/image_decoders"

common=(-std=c++17 -g -O1 -fno-omit-frame-pointer -fsanitize=address,undefined -fno-sanitize-recover=undefined
        -I"$root/include" -I"$root/glsl" -I"$root/examples/lab/include" -I"$root/examples/lab/src")
lab_sources=(camera environment file_util image_io image_decoders/exr_decoder image_decoders/jpeg_decoder
             image_decoders/png_decoder image_decoders/radiance_decoder json_lines json_reader mesh mesh_generators
             obj_loader painting scene gltf_loader)
decoders=${SNELL_FUZZ_DECODERS:-debian}
case $decoders in
  debian)
    # shellcheck disable=SC2207
    image_libs=($(pkg-config --libs spng libjpeg) -lOpenEXRCore-3_1) ;;
  source)
    bash "$root/tests/fuzz/build_decoders.sh" "$out/decoders"
    image_libs=("$out/decoders/lib/libspng.a" "$out/decoders/lib/libjpeg.a" "$out/decoders/lib/libOpenEXRCore.a" -lz -lm) ;;
  *) echo "run_fuzzers: SNELL_FUZZ_DECODERS is debian or source, not '$decoders'" >&2; exit 2 ;;
esac
# The targets remember which decoders they were linked with: a change rebuilds them.
[ "$(cat "$out/decoders.kind" 2>/dev/null)" = "$decoders" ] || { rm -f "$out"/fuzz_*; echo "$decoders" > "$out/decoders.kind"; }
common+=($(pkg-config --cflags-only-I OpenEXR | sed 's/-I/-isystem /g'))

# The lab core, instrumented for coverage; the tracer (Embree) only for scene_render.
render_sources=(tracer progress)
objs=() render_objs=() pids=()
for s in "${lab_sources[@]}" "${render_sources[@]}"; do
  src=$root/examples/lab/src/$s.cpp o=$out/obj/$s.o
  if [ ! -f "$o" ] || [ "$src" -nt "$o" ] || [ -n "$(find "$root/examples/lab" "$root/include" -newer "$o" -name '*.hpp' -print -quit)" ]; then
    echo "run_fuzzers: compiling $s.cpp"
    "$cxx" "${common[@]}" -fsanitize=fuzzer-no-link -c "$src" -o "$o.tmp" && mv "$o.tmp" "$o" &
    pids+=($!)
    # at most $(nproc) compilers at a time
    if [ ${#pids[@]} -ge "$(nproc)" ]; then wait "${pids[0]}"; pids=("${pids[@]:1}"); fi
  fi
  case " ${render_sources[*]} " in *" $s "*) render_objs+=("$o") ;; *) objs+=("$o") ;; esac
done
for p in "${pids[@]}"; do wait "$p"; done
# The targets, $(nproc) at a time; a failed build fails the script.
pids=()
build_status=0
for t in $targets; do
  bin=$out/fuzz_$t
  src=$(source_of "$t")
  if [ -f "$bin" ] && [ -z "$(find "$root/tests/fuzz/fuzz_$src.cpp" "$root/include" "$root/glsl" -newer "$bin" -print -quit)" ] &&
     [ -z "$(find "$out/obj" -newer "$bin" -print -quit)" ]; then continue; fi
  echo "run_fuzzers: building fuzz_$t"
  extra=()
  case $t in
    include_flattener) ;;
    scene_render) extra=("${objs[@]}" "${render_objs[@]}" "${image_libs[@]}" -lembree3) ;;
    image_*) extra=("-DSNELL_FUZZ_IMAGE_$(tr '[:lower:]' '[:upper:]' <<< "${t#image_}")" "${objs[@]}" "${image_libs[@]}") ;;
    *) extra=("${objs[@]}" "${image_libs[@]}") ;;
  esac
  "$cxx" "${common[@]}" -fsanitize=fuzzer "$root/tests/fuzz/fuzz_$src.cpp" "${extra[@]}" -o "$bin.tmp" -lpthread &&
    mv "$bin.tmp" "$bin" &
  pids+=($!)
  if [ ${#pids[@]} -ge "$(nproc)" ]; then wait "${pids[0]}" || build_status=1; pids=("${pids[@]:1}"); fi
done
for p in "${pids[@]}"; do wait "$p" || build_status=1; done
[ "$build_status" = 0 ] || { echo "run_fuzzers: a fuzz target failed to build" >&2; exit 1; }

[ "${SNELL_FUZZ_BUILD_ONLY:-0}" = 1 ] && exit 0

export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
# One target: its regressions once, then fuzzing; the outcome goes to $out/$t.status.
fuzz_target() {
  local t=$1 ok=1
  local reg=$root/tests/fuzz/regressions/$t
  if [ -d "$reg" ] && [ -n "$(ls -A "$reg")" ]; then
    echo "run_fuzzers: $t: regressions ($(ls "$reg" | wc -l) inputs)"
    if ! "$out/fuzz_$t" -rss_limit_mb=2048 -timeout=25 "$reg"/* > "$out/$t.regressions.log" 2>&1; then
      tail -n 40 "$out/$t.regressions.log" >&2
      echo "run_fuzzers: $t: a regression input fails again (log: $out/$t.regressions.log)" >&2
      ok=0
    fi
  fi
  local work=$out/corpus/$t crashes=$out/crashes/$t
  rm -rf "$work" "$crashes"
  mkdir -p "$work" "$crashes"
  cp "$root/tests/fuzz/corpus/$(corpus_of "$t")/"* "$work/"
  echo "run_fuzzers: $t: fuzzing for ${seconds}s"
  # shellcheck disable=SC2046
  if "$out/fuzz_$t" "$work" $(dict_of "$t") -max_total_time="$seconds" -rss_limit_mb=2048 -malloc_limit_mb=1024 -timeout=25 \
       -max_len=65536 -print_final_stats=1 -artifact_prefix="$crashes/" > "$out/$t.log" 2>&1; then
    echo "run_fuzzers: $t: $(grep -h 'stat::number_of_executed_units' "$out/$t.log" | awk '{print $2}') executions, no crash"
  else
    tail -n 60 "$out/$t.log" >&2
    echo "run_fuzzers: $t: CRASH; input(s): $(ls "$crashes")" >&2
    echo "run_fuzzers: fix it, then commit the input: cp $crashes/* $reg/" >&2
    ok=0
  fi
  echo "$ok" > "$out/$t.status"
}
# $(nproc) targets at a time: each fuzzes one core.
pids=()
for t in $targets; do
  rm -f "$out/$t.status"
  fuzz_target "$t" &
  pids+=($!)
  if [ ${#pids[@]} -ge "$(nproc)" ]; then wait "${pids[0]}" || true; pids=("${pids[@]:1}"); fi
done
for p in "${pids[@]}"; do wait "$p" || true; done
status=0
for t in $targets; do
  [ "$(cat "$out/$t.status" 2>/dev/null)" = 1 ] || { echo "run_fuzzers: $t: failed" >&2; status=1; }
done
exit $status
