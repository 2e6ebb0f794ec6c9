#!/usr/bin/env bash
# The README's test command: install what is missing, configure, build with
# warnings as errors, run the whole suite (unit, GPU parity on both OSMesa and
# EGL, compile checks in every language mode, install/consumer).
set -euo pipefail
cd "$(dirname "$0")/.."
# How long each phase took (the fresh-clone budget is 30 minutes on 2 cores).
started=$SECONDS last=$SECONDS
phase() { echo "test.sh: $1 took $((SECONDS - last)) s ($((SECONDS - started)) s in all)"; last=$SECONDS; }
bash scripts/install-deps.sh
phase "installing"
build=${SNELL_BUILD_DIR:-build}
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DSNELL_WERROR=ON
cmake --build "$build" -j "$(nproc)"
phase "configuring and building"
# The GL tests must run: a missing context fails them (never a skip).
ctest --test-dir "$build" --output-on-failure -j "$(nproc)"
phase "ctest"
# libFuzzer targets (clang): the committed crash regressions once, then 6 s of
# fuzzing per target (SNELL_FUZZ_TIME, default 6) on a copy of the seed corpus (tests/fuzz/run_fuzzers.sh).
SNELL_FUZZ_BUILD_DIR="$build/fuzz" bash tests/fuzz/run_fuzzers.sh
phase "fuzzing"

# Sanitizers: a second build with AddressSanitizer + UBSan running the
# unit, property and lab loader tests; any report fails the script (halt_on_error,
# -fno-sanitize-recover=undefined). The GL tests (parity, gpu, lab end-to-end
# runs) are not in it: Mesa's own allocations are not ours to vet.
san=${SNELL_SAN_BUILD_DIR:-${build}-san}
# -Og keeps the sanitizer build short on 2 cores (half the compile time of -O1,
# measured; the tests run about as fast).
cmake -S . -B "$san" -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-Og -g1" -DSNELL_WERROR=ON -DSNELL_SANITIZE=ON
cmake --build "$san" -j "$(nproc)" --target snell_unit_tests snell_property_tests snell_lab_loader_tests
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
export ASAN_OPTIONS=detect_leaks=1
# Every unit test but the two whole-frame sweeps (37 of the 65 s under ASan at
# -O1), which repeat, on every pixel of a frame, the functions the other
# tests call; they run in ctest above.
"$san/tests/snell_unit_tests" --gtest_filter=-TechniqueBound.ConvergesToTheExactExitPoints:TechniqueTwoInterface.PaintingBehindTheSphere
# Scene, OBJ and image loading on hostile files (no GL, no ray tracing).
"$san/tests/lab/snell_lab_loader_tests"
# 100,000 hostile inputs per function here; the full 1,000,000 ran in ctest above.
SNELL_PROPERTY_INPUTS=100000 "$san/tests/property/snell_property_tests"
phase "the sanitizer build and its tests"
