#!/usr/bin/env bash
# serve.mjs when Chromium itself crashes: the check is drawn again in a new Chromium, once per run, and a
# second crash ends the run with the crash named. The "Chromium" here is a stand-in that records each start,
# kills itself with SIGSEGV as many times as asked, then acts as the page: it posts a canvas equal to the
# bundle's lab picture (a 4x4 black frame). No real browser, so the test takes a second.
#   serve_chromium_crash_test.sh NODE WORK_DIR
set -euo pipefail
node=$1 work=$2
serve="$(cd "$(dirname "$0")/../.." && pwd)/examples/web/serve.mjs"
rm -rf "$work"
mkdir -p "$work/bundle"
cat > "$work/bundle/bundle.json" <<'JSON'
{"scene": "black", "width": 4, "height": 4, "objectMask": {"bits": "mask.u8"},
 "techniques": [{"name": "plane-normal-2", "labImage": {"texels": "lab.f32", "width": 4, "height": 4, "channels": 4}}]}
JSON
head -c $((4 * 4 * 4 * 4)) /dev/zero > "$work/bundle/lab.f32"
printf '\1%.0s' $(seq 16) > "$work/bundle/mask.u8"
cat > "$work/chromium" <<'FAKE'
#!/usr/bin/env bash
n=$(cat "$FAKE_STARTS" 2>/dev/null || echo 0)
echo $((n + 1)) > "$FAKE_STARTS"
[ "$n" -lt "$FAKE_CRASHES" ] && kill -SEGV $$
exec "$FAKE_NODE" -e '
  const url = new URL(process.argv.at(-1));
  fetch(new URL(`report/pixels?check=${url.searchParams.get("check")}`, url), { method: "POST", body: new Uint8Array(64) })
    .then(() => setTimeout(() => {}, 60000));' "${@: -1}"
FAKE
chmod +x "$work/chromium"

# run CRASHES EXPECTED_STATUS EXPECTED_STARTS PATTERN: serve.mjs's output must match PATTERN.
run() {
  local crashes=$1 want_status=$2 want_starts=$3 pattern=$4 status=0
  rm -f "$work/starts"
  FAKE_STARTS="$work/starts" FAKE_CRASHES=$crashes FAKE_NODE=$node \
    "$node" "$serve" "$work/bundle" --test --chromium="$work/chromium" > "$work/out.txt" 2>&1 || status=$?
  local starts; starts=$(cat "$work/starts")
  if [ "$status" != "$want_status" ] || [ "$starts" != "$want_starts" ] || ! grep -q -- "$pattern" "$work/out.txt"; then
    echo "FAIL: Chromium crashing $crashes time(s): exit $status (want $want_status), $starts start(s) (want" \
      "$want_starts), output to match \"$pattern\":"
    cat "$work/out.txt"
    exit 1
  fi
  echo "ok: Chromium crashing $crashes time(s): exit $status, $starts start(s)"
}
run 0 0 1 "100.00 % of 16 object pixels"
run 1 0 2 "Chromium exited (SIGSEGV) before the page was done: drawing the check again"
run 2 1 2 "Chromium exited (SIGSEGV) before the page was done; its last output"
