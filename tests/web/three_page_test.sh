#!/usr/bin/env bash
# One scene of the three.js page's test (tests/web/CMakeLists.txt):
#   three_page_test.sh SNELL_LAB NODE SCENE OUT_DIR --technique=NAME --page-floor=F [--lab-max-diff=N]
#                      [--threejs-floor=F] [--fault]
# SCENE: a scene file (.json) or a glTF asset (.glb). OUT_DIR/bundle: the frame with the technique;
# OUT_DIR/{lab,page}_buffers.json: the agreement; OUT_DIR/page.png: the page's screenshot. The checks below
# are one serve.mjs run, one Chromium: starting it, and loading the page, once per check cost seconds each.
# - On the lab's buffers: every object pixel but one in a thousand within 2/255 of the lab's picture, and none
#   beyond --lab-max-diff levels (default 4).
# - On the page's own buffers: at least --page-floor of the object pixels within 2/255.
# - --threejs-floor (a glTF scene, whose bundle carries the asset and the lab's render of it with three.js's
#   own renderer): the page also draws the asset with three.js's own renderer (serve.mjs --renderer=threejs),
#   compared with that render over the same object pixels (OUT_DIR/threejs.json, OUT_DIR/threejs.png); a
#   bundle without that render fails.
# - --fault: the page on the lab's buffers with every IOR 0.2 % higher (serve.mjs --fault=ior) must fail the
#   lab-buffer check (serve.mjs --must-fail; OUT_DIR/fault.json). It runs right after that check, whose
#   program the page draws it with: the IOR is a uniform, and the compile is most of a check's time.
set -euo pipefail
lab=$1 node=$2 scene=$3 out=$4
shift 4
technique="" floor="" max_diff=4 threejs_floor="" fault=""
for a in "$@"; do
  case $a in
    --technique=*) technique=${a#*=} ;;
    --page-floor=*) floor=${a#*=} ;;
    --lab-max-diff=*) max_diff=${a#*=} ;;
    --threejs-floor=*) threejs_floor=${a#*=} ;;
    --fault) fault=1 ;;
    *) echo "three_page_test.sh: unknown argument $a" >&2; exit 2 ;;
  esac
done
[ -n "$technique" ] && [ -n "$floor" ] || { echo "three_page_test.sh: --technique and --page-floor are required" >&2; exit 2; }
serve="$(cd "$(dirname "$0")/../.." && pwd)/examples/web/serve.mjs"
rm -rf "$out"
"$lab" "$scene" --technique "$technique" --frames 1 --quiet --out "" --web-bundle "$out/bundle"
lab_check=("--technique=$technique" --buffers=lab --min-share=0.999 "--max-diff=$max_diff")
checks=(--test "${lab_check[@]}" --report="$out/lab_buffers.json")
if [ -n "$fault" ]; then
  checks+=(--then "${lab_check[@]}" --fault=ior --must-fail --report="$out/fault.json")
fi
checks+=(--then "--technique=$technique" --buffers=page --min-share="$floor" --report="$out/page_buffers.json"
         --screenshot="$out/page.png")
if [ -n "$threejs_floor" ]; then
  checks+=(--then --renderer=threejs --min-share="$threejs_floor" --report="$out/threejs.json"
           --screenshot="$out/threejs.png")
fi
"$node" "$serve" "$out/bundle" "${checks[@]}"
