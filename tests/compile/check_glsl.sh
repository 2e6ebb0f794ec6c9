#!/usr/bin/env bash
# Compiles every file of glsl/snell in every language mode the common subset
# promises (GLSL 330 core, 450 core, ES 310, and HLSL through glslang's HLSL
# front end to SPIR-V; glslangValidator resolves #include only when it
# generates SPIR-V, hence -G, OpenGL semantics), and lints the subset rules a C++ compiler cannot catch.
# Usage: check_glsl.sh <glslangValidator> <repo root>
set -u
validator=$1
root=$(cd "$2" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
count=0

cd "$root/glsl" || exit 1
files=$(find snell -name '*.glsl' | sort)
[ -n "$files" ] || { echo "no GLSL files found under $root/glsl"; exit 1; }

compile() {  # mode file wrapper-extension stage [extra args...]
  local mode=$1 file=$2 ext=$3; shift 3
  local out
  if ! out=$("$validator" "$@" "$tmp/w.$ext" 2>&1); then
    echo "FAIL [$mode] $file"
    echo "$out" | sed 's/^/    /'
    fail=1
  fi
}

for f in $files; do
  count=$((count + 1))
  inc="#extension GL_GOOGLE_include_directive : require
#include \"$f\""
  printf '#version 330 core\n%s\nvoid main() {}\n' "$inc" > "$tmp/w.frag"
  compile "glsl 330 core" "$f" frag -G -S frag -o "$tmp/w.spv" -I"$root/glsl"
  printf '#version 450 core\n%s\nlayout(local_size_x = 1) in;\nvoid main() {}\n' "$inc" > "$tmp/w.comp"
  compile "glsl 450 core" "$f" comp -G -S comp -o "$tmp/w.spv" -I"$root/glsl"
  printf '#version 310 es\nprecision highp float;\nprecision highp int;\nprecision highp sampler2D;\n%s\nlayout(local_size_x = 1) in;\nvoid main() {}\n' "$inc" > "$tmp/w.comp"
  compile "glsl es 310" "$f" comp -G -S comp -o "$tmp/w.spv" -I"$root/glsl"
  printf '#include "bridge.hlsl"\n#include "%s"\nfloat4 main() : SV_Target { return float4(0.0f, 0.0f, 0.0f, 0.0f); }\n' "$f" > "$tmp/w.hlsl"
  compile "hlsl" "$f" hlsl -D -e main -S frag -V -o "$tmp/w.spv" -I"$root/hlsl_like/snell" -I"$root/glsl"

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

# The shader examples the README shows compile as written.
for f in "$root"/examples/glsl/*.frag; do
  [ -e "$f" ] || continue
  count=$((count + 1))
  if ! out=$("$validator" -G -o "$tmp/w.spv" -I"$root/glsl" "$f" 2>&1); then
    echo "FAIL [example] $f"; echo "$out" | sed 's/^/    /'; fail=1
  fi
done

echo "checked $count GLSL files in 4 language modes (examples as written)"
if [ "$fail" -ne 0 ]; then echo "compile check FAILED"; exit 1; fi
echo "compile check passed"
