#!/usr/bin/env bash
# Prints the function reference of docs/api.md (the part after its
# "generated below" marker) from the header blocks of glsl/snell: per file,
# the first sentence block of its description and every public function's
# signature (SNELL_FN ... snellName(...), macro parameters such as
# SNELL_IN(T) included), in include order of the families.
# tests/compile/check_api_doc.sh fails when docs/api.md differs from it.
# Usage: functions.sh <repo root>
set -euo pipefail
root=$(cd "$1" && pwd)
cd "$root/glsl"
for family in optics camera intersect shade; do
  echo
  echo "### $family (\`snell/$family.glsl\`, \`<snell/$family.hpp>\`)"
  for f in $(find "snell/$family" -name '*.glsl' | sort); do
    sigs=$(perl -0777 -ne '
      s{/\*.*?\*/}{}gs; s{//[^\n]*}{}g;
      while (/^SNELL_FN(?:_INLINE)?\s+([^{;]*?\bsnell\w+\s*\((?:[^()]|\([^()]*\))*\))/mg) { my $s = $1; $s =~ s/\s+/ /g; print "$s\n"; }' "$f")
    [ -n "$sigs" ] || continue
    desc=$(perl -0777 -ne 'if (m{/\*\s*\ndescription:\s*(.*?)\n(?:[a-z]+:|\*/)}s) { my $d = $1; $d =~ s/\s+/ /g; print $d; }' "$f")
    echo
    echo "**\`$f\`**${desc:+: $desc}"
    echo
    echo '```glsl'
    echo "$sigs"
    echo '```'
  done
done
