#!/usr/bin/env bash
# The dialect matrix: every file of glsl/snell compiles as
#   GLSL 330 core, 450 core, ES 3.00 (WebGL 2), ES 3.10  - flattened by
#     snell-flatten and validated by glslangValidator with GL rules, which is
#     what a driver sees from glShaderSource;
#   Vulkan GLSL 450 - glslang's own #include (GL_GOOGLE_include_directive) to
#     SPIR-V (-V), then spirv-val;
#   HLSL - glslang's HLSL front end to SPIR-V;
# and lints the subset rules a C++ compiler cannot catch. The library's
# passes (glsl/passes: whole shader stages) and the portable examples
# (examples/glsl/*.frag but the lab's and the gallery's own
# lab_*/gallery_* shaders) compile in all five GLSL dialects with only their
# #version line changed; the lab's and the gallery's shaders are GL 4.5
# programs and compile as written.
# Usage: check_glsl.sh <glslangValidator> <repo root> <snell-flatten> <spirv-val>
set -u
validator=$1
root=$(cd "$2" && pwd)
flatten=$3
spirv_val=$4
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
count=0

cd "$root/glsl" || exit 1
files=$(find snell -name '*.glsl' | sort)
[ -n "$files" ] || { echo "no GLSL files found under $root/glsl"; exit 1; }

report() {  # mode file output
  echo "FAIL [$1] $2"
  echo "$3" | sed 's/^/    /'
  fail=1
}
# GL dialects: flatten (as an engine would), then validate with GL semantics.
gl_check() {  # mode file source stage
  local out
  if ! out=$("$flatten" -I"$root/glsl" -o "$tmp/flat.$4" "$3" 2>&1) ||
     ! out=$("$validator" -S "$4" "$tmp/flat.$4" 2>&1); then report "$1" "$2" "$out"; fi
}
vulkan_check() {  # file source stage
  local out
  if ! out=$("$validator" -V -S "$3" -o "$tmp/vk.spv" -I"$root/glsl" "$2" 2>&1) ||
     ! out=$("$spirv_val" --target-env vulkan1.0 "$tmp/vk.spv" 2>&1); then report "vulkan glsl 450" "$1" "$out"; fi
}
es_header='precision highp float;
precision highp int;
precision highp sampler2D;'

for f in $files; do
  count=$((count + 1))
  inc="#extension GL_GOOGLE_include_directive : require
#include \"$f\""
  printf '#version 330 core\n%s\nvoid main() {}\n' "$inc" > "$tmp/w330.frag"
  gl_check "glsl 330 core" "$f" "$tmp/w330.frag" frag
  printf '#version 450 core\n%s\nlayout(local_size_x = 1) in;\nvoid main() {}\n' "$inc" > "$tmp/w450.comp"
  gl_check "glsl 450 core" "$f" "$tmp/w450.comp" comp
  printf '#version 300 es\n%s\n%s\nvoid main() {}\n' "$es_header" "$inc" > "$tmp/w300.frag"
  gl_check "glsl es 300" "$f" "$tmp/w300.frag" frag
  printf '#version 310 es\n%s\n%s\nlayout(local_size_x = 1) in;\nvoid main() {}\n' "$es_header" "$inc" > "$tmp/w310.comp"
  gl_check "glsl es 310" "$f" "$tmp/w310.comp" comp
  printf '#version 450\n%s\nlayout(local_size_x = 1) in;\nvoid main() {}\n' "$inc" > "$tmp/wvk.comp"
  vulkan_check "$f" "$tmp/wvk.comp" comp
  printf '#include "bridge.hlsl"\n#include "%s"\nfloat4 main() : SV_Target { return float4(0.0f, 0.0f, 0.0f, 0.0f); }\n' "$f" > "$tmp/w.hlsl"
  if ! out=$("$validator" -D -e main -S frag -V -o "$tmp/w.spv" -I"$root/hlsl_like/snell" -I"$root/glsl" "$tmp/w.hlsl" 2>&1); then
    report hlsl "$f" "$out"
  fi

  # Subset rules (DESIGN.md sec. 1) on the code with comments removed.
  code=$(perl -0777 -pe 's{/\*.*?\*/}{ }gs; s{//[^\n]*}{}g' "$f")
  lint() {  # pattern message
    local hits
    hits=$(printf '%s\n' "$code" | grep -nP "$1")
    if [ -n "$hits" ]; then
      echo "FAIL [subset] $f: $2"
      echo "$hits" | sed 's/^/    /'
      fail=1
    fi
  }
  lint '(?<![\w.])\d+\.\d*(?:[eE][-+]?\d+)?(?![\d.eEfF])|(?<![\w.])\d+[eE][-+]?\d+(?![fF\d])' "float literal without f suffix"
  lint '\b(?:mod|fract|atan2?)\s*\(' "mod/fract/atan differ between GLSL and HLSL: not allowed in shared code"
  lint '(?<![\w#])%' "% differs between GLSL and HLSL"
  lint '\b(?:out|inout)\s+\w+\s+\w+\s*[,)]' "out/inout parameters: return a struct"
  lint '^(?!\s*#).*(?:\w__|__\w)' "identifiers with __ are reserved in GLSL"
  lint '\.(?:[xyzw]{2,4}|[rgba]{2,4})\b' "swizzles: write vec2(p.x, p.y)"
  guard="SNELL_$(echo "${f#snell/}" | sed 's/\.glsl$//; s|/|_|g' | tr a-z A-Z)_GLSL"
  grep -q "^#ifndef $guard\$" "$f" || { echo "FAIL [guard] $f: expected include guard $guard"; fail=1; }
done

# The library's passes and the examples: portable ones in every GLSL dialect,
# the lab's and the gallery's as written.
for f in "$root"/glsl/passes/* "$root"/examples/glsl/*.frag "$root"/examples/glsl/*.vert "$root"/examples/glsl/*.comp; do
  [ -e "$f" ] || continue
  count=$((count + 1))
  name=${f#"$root"/}
  stage=${f##*.}
  head -n 1 "$f" | grep -q '^#version 450 core$' || { echo "FAIL [example] $name: line 1 must be #version 450 core"; fail=1; continue; }
  case $(basename "$f") in
    lab_*|gallery_*)
      gl_check "example as written" "$name" "$f" "$stage" ;;
    *)
      for v in "330 core" "450 core" "300 es" "310 es"; do
        { echo "#version $v"; tail -n +2 "$f"; } > "$tmp/ex.$stage"
        gl_check "example, glsl $v" "$name" "$tmp/ex.$stage" "$stage"
      done
      { echo "#version 450"; tail -n +2 "$f"; } > "$tmp/exvk.$stage"
      vulkan_check "$name (example)" "$tmp/exvk.$stage" "$stage" ;;
  esac
done

echo "checked $count GLSL files: library files in 6 modes (GLSL 330 core, 450 core, ES 3.00, ES 3.10, Vulkan, HLSL), passes and portable examples in the 5 GLSL ones"
if [ "$fail" -ne 0 ]; then echo "compile check FAILED"; exit 1; fi
echo "compile check passed"
