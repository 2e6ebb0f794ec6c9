#!/usr/bin/env bash
# A long fuzzing campaign, not part of CI:
#
#     bash tests/fuzz/campaign.sh                 # every target, the default times
#     bash tests/fuzz/campaign.sh obj:90 image_png:5  # chosen targets, minutes each
#
# Default: include_flattener 30, scene 60, scene_render 30, obj 60, gltf 30, and 30 for
# each image format (image_png, image_jpeg, image_exr, image_hdr)
# (SNELL_CAMPAIGN_MINUTES=N sets every default time to N). Targets run one
# after another, each on its own core in libFuzzer's fork mode, which goes on
# after a finding (-ignore_crashes/-ignore_ooms/-ignore_timeouts) so one bug
# does not end the campaign. Each target starts from its committed corpus
# plus what earlier campaigns on this machine kept ($dir/<target>/corpus);
# at the end, libFuzzer's merge adds to tests/fuzz/corpus/<target>/ only the
# inputs that reach new coverage (capped at 4 KiB each, named by content hash):
# review and commit them. Findings are left in $dir/<target>/findings/: fix
# the cause, then commit each input to tests/fuzz/regressions/<target>/ with
# a unit test (tests/fuzz/README.md). The summary (executions, coverage
# before/after, corpus added, findings with their first sanitizer line) goes
# to $dir/summary.md and stdout. Exits non-zero when anything was found.
#
# Environment: SNELL_FUZZ_BUILD_DIR (default build/fuzz; the campaign works in
# $SNELL_FUZZ_BUILD_DIR/campaign), CLANGXX as for run_fuzzers.sh,
# SNELL_FUZZ_DECODERS (default source: the image decoders built instrumented
# from Debian's source packages, build_decoders.sh; debian: Debian's builds).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
out=${SNELL_FUZZ_BUILD_DIR:-$root/build/fuzz}
dir=$out/campaign
default=${SNELL_CAMPAIGN_MINUTES:-}
# shellcheck source=tests/fuzz/targets.sh
source "$root/tests/fuzz/targets.sh"
plan=("$@")
[ ${#plan[@]} -gt 0 ] || plan=("include_flattener:${default:-30}" "scene:${default:-60}" "scene_render:${default:-30}" "obj:${default:-60}" "gltf:${default:-30}" "image_png:${default:-30}"
                             "image_jpeg:${default:-30}" "image_exr:${default:-30}" "image_hdr:${default:-30}")

targets=()
for p in "${plan[@]}"; do
  t=${p%%:*}
  [[ " $snell_fuzz_targets " == *" $t "* ]] || { echo "campaign: unknown target '$t' (one of: $snell_fuzz_targets)" >&2; exit 2; }
  m=${p#*:}; [ "$m" != "$p" ] || m=${default:-30}
  [[ "$m" =~ ^[0-9]+$ ]] && [ "$m" -gt 0 ] || { echo "campaign: '$p': minutes must be a positive whole number" >&2; exit 2; }
  targets+=("$t")
done
SNELL_FUZZ_DECODERS=${SNELL_FUZZ_DECODERS:-source} SNELL_FUZZ_BUILD_DIR=$out SNELL_FUZZ_TARGETS="${targets[*]}" SNELL_FUZZ_BUILD_ONLY=1 \
  bash "$root/tests/fuzz/run_fuzzers.sh"

export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
limits=(-rss_limit_mb=2048 -malloc_limit_mb=1024 -timeout=25 -max_len=65536)
# "cov: N ft: M" of a corpus, as libFuzzer reports it after loading it.
coverage() { { "$out/fuzz_$1" -runs=0 "${limits[@]}" "$2" 2>&1 || true; } | grep -oE 'INITED cov: [0-9]+ ft: [0-9]+' | head -n 1 | sed 's/INITED //' || true; }

# One target: fuzz, merge into the committed corpus, write its summary row.
campaign_target() {
  set +e  # a step that fails leaves "?" in the row, it does not end the campaign
  local t=$1 m=$2
  local work=$dir/$t/corpus findings=$dir/$t/findings committed=$root/tests/fuzz/corpus/$(corpus_of "$t")
  rm -f "$dir/$t/row.md"
  mkdir -p "$work" "$findings"
  cp -n "$committed/"* "$work/" 2>/dev/null || true
  local before; before=$(coverage "$t" "$committed")
  echo "campaign: $t: fuzzing for $m min (log: $dir/$t/fuzz.log)"
  # shellcheck disable=SC2046
  "$out/fuzz_$t" "$work" $(dict_of "$t") -fork=1 -ignore_crashes=1 -ignore_ooms=1 -ignore_timeouts=1 \
    -max_total_time=$((m * 60)) "${limits[@]}" -artifact_prefix="$findings/" > "$dir/$t/fuzz.log" 2>&1 || true
  local last; last=$(grep -E '^#[0-9]+: cov:' "$dir/$t/fuzz.log" | tail -n 1 || true)
  local execs rate
  execs=$(sed -E 's/^#([0-9]+):.*/\1/' <<< "$last")
  rate=$(sed -E 's/.*exec\/s ([0-9]+).*/\1/' <<< "$last")
  # Only inputs that reach new edges (-use_counters=0: hit counts are no news), none
  # larger than 4 KiB
  # (libFuzzer names what it adds by its SHA-1).
  find "$work" -type f -size +4k -delete
  local entries; entries=$(ls "$committed" | wc -l)
  "$out/fuzz_$t" -merge=1 -use_counters=0 "${limits[@]}" "$committed" "$work" > "$dir/$t/merge.log" 2>&1 || true
  local added=$(( $(ls "$committed" | wc -l) - entries ))
  local after; after=$(coverage "$t" "$committed")
  local list="" f why
  for f in "$findings"/*; do
    [ -e "$f" ] || continue
    why=$({ "$out/fuzz_$t" "${limits[@]}" "$f" 2>&1 || true; } | grep -E 'runtime error|ERROR: (AddressSanitizer|LeakSanitizer|libFuzzer)' | head -n 1)
    [ -n "$why" ] || why="no longer reproduces"
    list+="$(basename "$f"): ${why//|/\\|}<br>"
  done
  echo "| $t | $m | ${execs:-?} | ${rate:-?} | ${before:-?} | ${after:-?} | $added | ${list:-none} |" > "$dir/$t/row.md"
  echo "campaign: $t: ${execs:-?} executions, coverage ${before:-?} -> ${after:-?}, $added corpus inputs added, findings: ${list:-none}"
}

# SNELL_CAMPAIGN_JOBS targets at a time (default 1; each uses one core).
jobs=${SNELL_CAMPAIGN_JOBS:-1}
mkdir -p "$dir"
running=()
for p in "${plan[@]}"; do
  t=${p%%:*}
  m=${p#*:}; [ "$m" != "$p" ] || m=${default:-30}
  campaign_target "$t" "$m" &
  running+=($!)
  if [ ${#running[@]} -ge "$jobs" ]; then wait "${running[0]}"; running=("${running[@]:1}"); fi
done
for j in "${running[@]}"; do wait "$j"; done

summary=$dir/summary.md
{
  echo "# Fuzzing campaign, finished $(date -u '+%Y-%m-%d %H:%M UTC'), commit $(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo '?')"
  echo
  echo "Coverage is libFuzzer's \"cov: edges ft: features\" on the committed corpus before and after the merge."
  echo
  echo "| target | minutes | executions | exec/s | coverage before | coverage after | corpus added | findings |"
  echo "|---|---|---|---|---|---|---|---|"
  for t in "${targets[@]}"; do cat "$dir/$t/row.md" 2>/dev/null || echo "| $t | | | | | | | did not finish |"; done
} > "$summary"
echo
cat "$summary"
if grep -q '| none |$' "$summary" && [ "$(grep -c '^| ' "$summary")" -eq $(( ${#targets[@]} + 1 )) ] &&
   [ "$(grep -c '| none |$' "$summary")" -eq ${#targets[@]} ]; then exit 0; fi
echo "campaign: findings in $dir/*/findings/: fix each, then commit it to tests/fuzz/regressions/<target>/" >&2
exit 1
