#!/usr/bin/env bash
# Every public GLSL function (each SNELL_FN snell...( definition in glsl/snell)
# is called by a unit test in tests/unit, comments left out, or is listed with
# a reason in tests/unit/functions_without_unit_test.txt; an entry there that a
# test now calls, or that names no public function, fails too, so the list only
# shrinks. Prints the functions without a unit test.
# Usage: check_unit_test_per_function.sh <repo root>
set -u
root=$(cd "$1" && pwd)
allow=$root/tests/unit/functions_without_unit_test.txt
code=$(perl -0777 -ne 's{/\*.*?\*/}{}gs; s{//[^\n]*}{}g; print' "$root"/tests/unit/*.cpp)
public=$(cd "$root/glsl" && perl -0777 -ne 's{/\*.*?\*/}{}gs; s{//[^\n]*}{}g; print "$1\n" while /^SNELL_FN(?:_INLINE)?\s+[^{;(]*?\b(snell\w+)\s*\(/mg' $(find snell -name '*.glsl') | sort -u)
[ -n "$public" ] || { echo "FAIL no public function found under $root/glsl/snell"; exit 1; }
listed=$(grep -v '^#' "$allow" | awk 'NF { print $1 }' | sort)
fail=0
untested=""
for name in $public; do
  grep -qP "\\b$name\\s*\\(" <<<"$code" || untested+="$name "
done
for name in $untested; do
  grep -qxF "$name" <<<"$listed" || { echo "FAIL $name has no unit test (tests/unit) and is not listed in $allow"; fail=1; }
done
for name in $listed; do
  grep -qxF "$name" <<<"$public" || { echo "FAIL $allow lists $name, which is no public function"; fail=1; continue; }
  grep -qw "$name" <<<"$untested" || { echo "FAIL $name has a unit test now: remove it from $allow"; fail=1; }
done
grep -v '^#' "$allow" | awk 'NF == 1 { print "FAIL " $1 " is listed without a reason"; bad = 1 } END { exit bad }' || fail=1
count=$(wc -w <<<"$untested")
echo "public functions: $(wc -w <<<"$public"); without a unit test: $count${untested:+ ($untested)}"
exit $fail
