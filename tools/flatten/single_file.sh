#!/usr/bin/env bash
# Writes single_file/: the whole library and each family as one GLSL file with
# every #include spliced in (snell-flatten --no-line), with and without
# comments, for engines that cannot resolve includes.
# Usage: single_file.sh <snell-flatten> <repo root> <output dir>
set -euo pipefail
flatten=$1 root=$2 out=$3
version=$(sed -nE 's/^#define SNELL_VERSION_(MAJOR|MINOR|PATCH) ([0-9]+)$/\2/p' "$root/glsl/snell/version.glsl" | paste -sd.)
mkdir -p "$out"
for family in snell optics camera intersect shade; do
  src=snell/$family.glsl
  [ "$family" = snell ] && name=snell || name=snell_$family
  for variant in "" .nocomments; do
    args=(--no-line)
    [ -z "$variant" ] || args+=(--strip-comments)
    {
      echo "// snell $version, single-file GLSL: glsl/$src with every #include spliced in"
      echo "// (snell-flatten ${args[*]}). Generated: do not edit; regenerate with"
      echo "// \`cmake --build build --target single_file\`. No #version line: put it, and on"
      echo "// ES the precision statements, before this text."
      "$flatten" "${args[@]}" -I"$root/glsl" "$root/glsl/$src"
    } > "$out/$name$variant.glsl.tmp"
    mv "$out/$name$variant.glsl.tmp" "$out/$name$variant.glsl"
  done
done
