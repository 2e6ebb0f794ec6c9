#!/usr/bin/env bash
# single_file/: the committed files are what tools/flatten/single_file.sh
# makes from glsl/snell today, and each compiles, as it is, after a #version
# line in every GL dialect snell claims (330 core, 450 core, ES 3.00, ES 3.10),
# plus the three.js ShaderMaterial recipe of docs/recipes.md: three.js's WebGL 2
# prefix, then the single file, then the shader body.
# Usage: check_single_file.sh <snell-flatten> <glslangValidator> <repo root>
set -u
flatten=$1 validator=$2 root=$(cd "$3" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
bash "$root/tools/flatten/single_file.sh" "$flatten" "$root" "$tmp/fresh" || exit 1
if ! diff -r "$root/single_file" "$tmp/fresh" > "$tmp/diff"; then
  echo "FAIL single_file/ is out of date with glsl/snell: run cmake --build build --target single_file"
  head -n 20 "$tmp/diff" | sed 's/^/    /'
  fail=1
fi
es='precision highp float;
precision highp int;
precision highp sampler2D;'
for f in "$root"/single_file/*.glsl; do
  for v in "330 core" "450 core" "300 es" "310 es"; do
    { echo "#version $v"; case $v in *es) echo "$es" ;; esac; cat "$f"; echo "void main() {}"; } > "$tmp/t.frag"
    if ! out=$("$validator" -S frag "$tmp/t.frag" 2>&1); then
      echo "FAIL [glsl $v] single_file/$(basename "$f")"; echo "$out" | head -n 10 | sed 's/^/    /'; fail=1
    fi
  done
done
# docs/recipes.md, three.js: what a ShaderMaterial (glslVersion: THREE.GLSL3) hands WebGL 2.
sed -n '/^<!-- three-prefix -->$/,/^<!-- \/three-prefix -->$/p' "$root/docs/recipes.md" | sed '1,2d;$d' | sed '$d' > "$tmp/prefix"
sed -n '/^<!-- three-body -->$/,/^<!-- \/three-body -->$/p' "$root/docs/recipes.md" | sed '1,2d;$d' | sed '$d' > "$tmp/body"
if [ ! -s "$tmp/prefix" ] || [ ! -s "$tmp/body" ]; then
  echo "FAIL docs/recipes.md: the three.js recipe blocks (three-prefix, three-body) are missing"; fail=1
else
  { cat "$tmp/prefix"; cat "$root/single_file/snell_optics.nocomments.glsl"; cat "$tmp/body"; } > "$tmp/three.frag"
  if ! out=$("$validator" -S frag "$tmp/three.frag" 2>&1); then
    echo "FAIL [three.js recipe] docs/recipes.md"; echo "$out" | head -n 10 | sed 's/^/    /'; fail=1
  fi
fi
[ $fail -eq 0 ] && echo "single_file/ up to date; $(ls "$root"/single_file/*.glsl | wc -l) files compile in 4 GL dialects; the three.js recipe compiles"
exit $fail
