#!/usr/bin/env bash
# The three.js page (examples/web) on one of the lab's scenes: installs what is missing (Debian and npm
# packages), builds snell-lab, writes the scene's frame with `snell-lab --web-bundle` (the lab runs the
# normal plane, 2 it., once, with its ray tracer: about 20 s) to web-out/<scene>, then serves the page on
# http://127.0.0.1:8080/ until Ctrl-C; open it in a browser with WebGL 2.
#   bash scripts/web.sh                                   # the bundled bunny
#   bash scripts/web.sh examples/scenes/sphere_painting.json [--port=8081] [--technique=dir]
#   bash scripts/web.sh examples/scenes/gltf/glass_bunny.glb [--renderer=threejs]   # a glTF asset (picker)
# Options after the scene go to examples/web/serve.mjs.
# Paths are taken relative to the directory it is run from; the build happens in the repository.
set -euo pipefail
scene=""
if [ $# -gt 0 ] && [ "${1#--}" = "$1" ]; then
  scene=$1
  shift
fi
here=$(pwd)
root="$(cd "$(dirname "$0")/.." && pwd)"
lab=$(bash "$root/scripts/build-target.sh" snell-lab)/examples/lab/snell-lab
[ -z "$scene" ] && scene="$root/examples/scenes/bunny.json"
case "$scene" in /*) ;; *) scene="$here/$scene" ;; esac
[ -f "$scene" ] || { echo "web.sh: no scene file $scene" >&2; exit 3; }
name=$(basename "$scene")
out="$root/web-out/${name%.*}"  # bunny.json, glass_bunny.glb: web-out/bunny, web-out/glass_bunny
"$lab" "$scene" --technique plane-normal-2 --frames 1 --quiet --out "" --web-bundle "$out"
exec node "$root/examples/web/serve.mjs" "$out" "$@"
