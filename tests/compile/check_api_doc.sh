#!/usr/bin/env bash
# docs/api.md: its function reference is what tools/api/functions.sh
# makes from the header blocks today, and every public function (each
# SNELL_FN snell...( definition in glsl/snell, each C++-only helper named in
# the check below) appears on the page.
# Usage: check_api_doc.sh <repo root>
set -u
root=$(cd "$1" && pwd)
doc=$root/docs/api.md
marker='<!-- generated below by tools/api/functions.sh: do not edit by hand -->'
fail=0
grep -qxF "$marker" "$doc" || { echo "FAIL docs/api.md: the marker line is missing: $marker"; exit 1; }
if ! diff <(sed -n "/^$(printf '%s' "$marker" | sed 's/[][\/.*^$]/\\&/g')\$/,\$p" "$doc" | tail -n +2) \
          <(bash "$root/tools/api/functions.sh" "$root") > /tmp/api_doc_diff.$$; then
  echo "FAIL docs/api.md is out of date with the header blocks: regenerate the part after the marker with"
  echo "    bash tools/api/functions.sh . >> docs/api.md   (after deleting the old part)"
  head -n 20 /tmp/api_doc_diff.$$ | sed 's/^/    /'
  fail=1
fi
rm -f /tmp/api_doc_diff.$$
missing=""
for name in $(cd "$root/glsl" && perl -0777 -ne 's{/\*.*?\*/}{}gs; s{//[^\n]*}{}g; print "$1\n" while /^SNELL_FN(?:_INLINE)?\s+[^{;(]*?\b(snell\w+)\s*\(/mg' $(find snell -name '*.glsl')) \
            Image Texture2D TextureCube snellBuildDepthPyramid snellBuildNormalMips computeWymanDn \
            snellTechniqueTable snellFindTechnique snellDescribeTechnique snellDescribeIntersect \
            Context flattenGlslFile flattenGlslSource mapInfoLog Program DepthPyramidPass compareFrames runParityGpu runParityHlsl; do
  grep -qw "$name" "$doc" || missing+=" $name"
done
if [ -n "$missing" ]; then echo "FAIL docs/api.md does not mention:$missing"; fail=1; fi
[ $fail -eq 0 ] && echo "docs/api.md is up to date and lists every public function"
exit $fail
