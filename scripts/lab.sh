#!/usr/bin/env bash
# The README's main-job command. The lab (every technique rendered on Mesa against
# a ray tracer) is not built yet; until it is, this installs what is missing,
# builds, and runs the C++ tool example: rays through a glass ball traced with
# the same snellRefract/Fresnel functions the shaders use.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
build=${SNELL_BUILD_DIR:-build}
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j "$(nproc)" --target snell_tool_example
"$build/examples/snell_tool_example"
