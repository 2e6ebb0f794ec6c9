#!/usr/bin/env bash
# One scene of the three.js page's test (tests/web/CMakeLists.txt):
#   three_page_test.sh SNELL_LAB NODE SCENE OUT_DIR PAGE_FLOOR [THREEJS_FLOOR]
# SCENE: a scene file (.json) or a glTF asset (.glb). OUT_DIR/bundle: the frame; OUT_DIR/{lab,page}_buffers.json:
# the agreement; OUT_DIR/page.png: the page's screenshot. With THREEJS_FLOOR (a glTF scene, whose bundle
# carries the asset and the lab's render of it with three.js's own renderer): the page also draws the asset
# with three.js's own renderer (serve.mjs --renderer=threejs), compared with that render over the same object
# pixels (OUT_DIR/threejs.json, OUT_DIR/threejs.png); a bundle without that render fails.
set -euo pipefail
lab=$1 node=$2 scene=$3 out=$4 floor=$5 threejs_floor=${6:-}
serve="$(cd "$(dirname "$0")/../.." && pwd)/examples/web/serve.mjs"
rm -rf "$out"
"$lab" "$scene" --technique plane-normal-2 --frames 1 --quiet --out "" --web-bundle "$out/bundle"
"$node" "$serve" "$out/bundle" --test --technique=plane-normal-2 --buffers=lab --min-share=0.99 \
  --report="$out/lab_buffers.json"
"$node" "$serve" "$out/bundle" --test --technique=plane-normal-2 --buffers=page --min-share="$floor" \
  --report="$out/page_buffers.json" --screenshot="$out/page.png"
if [ -n "$threejs_floor" ]; then
  "$node" "$serve" "$out/bundle" --test --renderer=threejs --min-share="$threejs_floor" \
    --report="$out/threejs.json" --screenshot="$out/threejs.png"
fi
