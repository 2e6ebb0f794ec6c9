#!/usr/bin/env bash
# Compiles every HLSL entry file of hlsl_like/snell (and the HLSL examples) with
# glslang's HLSL front end, shader model 5 style (-D -e main -S frag|comp -V), to
# SPIR-V, validates it with spirv-val and cross-compiles it with spirv-cross to
# GLSL 450 (what the parity suite then runs). Each entry is compiled
#  - from the source tree with only hlsl_like/ on the include path (the relative
#    `#include "../../glsl/snell/..."` must reach the bodies by itself),
#  - with SNELL_HLSL_FLIP_V (the D3D uv-origin option of the bridge),
#  - from an install-layout copy (share/snell/hlsl_like next to share/snell/glsl).
# Usage: check_hlsl.sh <glslangValidator> <spirv-val> <spirv-cross> <repo root> <work dir>
set -u
validator=$1
spirv_val=$2
spirv_cross=$3
root=$(cd "$4" && pwd)
work=$5
rm -rf "$work"
mkdir -p "$work"
fail=0
count=0

run() {  # label cmd...: runs, prints the output indented on failure
  local label=$1; shift
  local out
  if ! out=$("$@" 2>&1); then
    echo "FAIL [$label]"
    echo "$out" | sed 's/^/    /'
    fail=1
    return 1
  fi
}

# compile <label> <stage frag|comp> <hlsl file> <include dir> [extra glslang args...]
compile() {
  local label=$1 stage=$2 file=$3 inc=$4; shift 4
  local spv="$work/$count.spv"
  count=$((count + 1))
  run "$label: glslangValidator -D -S $stage" "$validator" -D -e main -S "$stage" -V "$@" -I"$inc" -o "$spv" "$file" || return
  run "$label: spirv-val" "$spirv_val" "$spv" || return
  run "$label: spirv-cross --version 450 --no-es" "$spirv_cross" --version 450 --no-es \
      --combined-samplers-inherit-bindings --output "$work/$count.glsl" "$spv"
}

# An install-layout copy: share/snell/{glsl,hlsl_like} as CMake installs them.
install_share="$work/install/share/snell"
mkdir -p "$install_share"
cp -R "$root/glsl" "$install_share/glsl"
cp -R "$root/hlsl_like" "$install_share/hlsl_like"

entries=$(cd "$root/hlsl_like/snell" && ls *.hlsl | grep -v '^bridge\.hlsl$' | sort)
[ -n "$entries" ] || { echo "no HLSL entry files under $root/hlsl_like/snell"; exit 1; }
for family in optics camera intersect shade snell; do
  echo "$entries" | grep -qx "$family.hlsl" || { echo "FAIL [entry] hlsl_like/snell/$family.hlsl is missing"; fail=1; }
done

for e in $entries; do
  # Every entry includes the bridge first.
  first=$(perl -0777 -pe 's{/\*.*?\*/}{ }gs; s{//[^\n]*}{}g' "$root/hlsl_like/snell/$e" | grep -m1 '^\s*#\s*include')
  case "$first" in
    *'"bridge.hlsl"'*) ;;
    *) echo "FAIL [entry] $e: the first #include must be \"bridge.hlsl\" (found: $first)"; fail=1 ;;
  esac
  printf '#include "snell/%s"\nfloat4 main(float4 pos : SV_Position) : SV_Target { return float4(0.0f, 0.0f, 0.0f, 0.0f); }\n' "$e" > "$work/ps_$e"
  printf '#include "snell/%s"\n[numthreads(64, 1, 1)]\nvoid main(uint3 id : SV_DispatchThreadID) {}\n' "$e" > "$work/cs_$e"
  compile "$e ps_5_0, source tree" frag "$work/ps_$e" "$root/hlsl_like"
  compile "$e cs_5_0, source tree" comp "$work/cs_$e" "$root/hlsl_like"
  compile "$e ps_5_0, SNELL_HLSL_FLIP_V" frag "$work/ps_$e" "$root/hlsl_like" -DSNELL_HLSL_FLIP_V=1
  compile "$e ps_5_0, install tree" frag "$work/ps_$e" "$install_share/hlsl_like"
done

# The examples compile as written (pixel shaders, entry main; the entry files
# cover the install tree, and a full technique takes glslang seconds).
for f in "$root"/examples/hlsl/*.hlsl; do
  [ -e "$f" ] || continue
  compile "example $(basename "$f")" frag "$f" "$root/hlsl_like"
done

echo "compiled $count HLSL shaders (glslangValidator -D -> spirv-val -> spirv-cross GLSL 450)"
if [ "$fail" -ne 0 ]; then echo "HLSL check FAILED"; exit 1; fi
echo "HLSL check passed"
