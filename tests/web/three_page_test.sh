#!/usr/bin/env bash
# One scene of the three.js page's test (tests/web/CMakeLists.txt):
#   three_page_test.sh SNELL_LAB NODE SCENE_JSON OUT_DIR PAGE_FLOOR
# OUT_DIR/bundle: the frame; OUT_DIR/{lab,page}_buffers.json: the agreement; OUT_DIR/page.png: the
# page's screenshot.
set -euo pipefail
lab=$1 node=$2 scene=$3 out=$4 floor=$5
serve="$(cd "$(dirname "$0")/../.." && pwd)/examples/web/serve.mjs"
rm -rf "$out"
"$lab" "$scene" --technique plane-normal-2 --frames 1 --quiet --out "" --web-bundle "$out/bundle"
"$node" "$serve" "$out/bundle" --test --technique=plane-normal-2 --buffers=lab --min-share=0.99 \
  --report="$out/lab_buffers.json"
"$node" "$serve" "$out/bundle" --test --technique=plane-normal-2 --buffers=page --min-share="$floor" \
  --report="$out/page_buffers.json" --screenshot="$out/page.png"
