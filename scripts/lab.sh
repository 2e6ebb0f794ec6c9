#!/usr/bin/env bash
# The README's main-job command: installs what is missing (Debian packages),
# builds snell-lab (Release) and runs it with its defaults: the Stanford bunny
# scene at 512x512, every technique rendered on Mesa llvmpipe (OSMesa, or EGL
# where OSMesa is missing) against the Embree ray tracer. Prints the table;
# pictures, table.md and table.json go to lab-out/. Extra arguments are passed
# to snell-lab (e.g. `bash scripts/lab.sh examples/scenes/sphere_painting.json`,
# `bash scripts/lab.sh --help`). About a minute on 2 cores after the build.
# Paths in the arguments (scene files, --out) are taken relative to the
# directory it is run from; the build happens in the repository.
set -euo pipefail
lab=$(bash "$(dirname "$0")/build-target.sh" snell-lab)/examples/lab/snell-lab
"$lab" "$@"
