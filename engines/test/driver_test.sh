#!/usr/bin/env bash
# The engine driver end to end (engines/run.mjs + engines/threejs/page.js in headless Chromium):
#   1. builds a small glTF scene (ground, box, alpha-tested fence; test/make_scene.mjs), runs the
#      driver and checks samples.f32 (test/check_samples.mjs): ground under the box shadowed, open
#      ground lit, background coverage 0, alpha-test holes see through and let the sun through;
#   2. bad jobs: a missing glTF, an unknown engine and a missing Chromium exit 2 with one line
#      naming the problem; an unknown setting (an exception in the page) exits 1.
# Usage: engines/test/driver_test.sh [ENGINE]  (default threejs). ST_TEST_KEEP=1 keeps the work
# directory (with a preview.png of the result). Exits non-zero on the first failure.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
engines=$(dirname "$here")
engine=${1:-threejs}
work=$(mktemp -d "${TMPDIR:-/tmp}/shadowtune-driver-test.XXXXXX")
if [[ ${ST_TEST_KEEP:-0} == 1 ]]; then
  echo "driver_test: work directory $work"
else
  trap 'rm -rf "$work"' EXIT
fi

fail() {
  echo "driver_test: FAIL: $*" >&2
  exit 1
}

# expect_exit CODE PATTERN -- command...: runs the command, checks its exit code and that its stderr
# matches PATTERN (extended regex).
expect_exit() {
  local want=$1 pattern=$2
  shift 3
  local rc=0
  "$@" >"$work/stdout" 2>"$work/stderr" || rc=$?
  [[ $rc == "$want" ]] || fail "expected exit $want, got $rc from: $* (stderr: $(cat "$work/stderr"))"
  grep -Eq "$pattern" "$work/stderr" || fail "stderr of '$*' does not match /$pattern/: $(cat "$work/stderr")"
  echo "ok   exit $want: $(grep -E "$pattern" "$work/stderr" | head -n 1)"
}

# 1. the scene
job=$(node "$here/make_scene.mjs" "$work/scene" "$engine")
start=$(date +%s%N)
node "$engines/run.mjs" "$job" || fail "run.mjs exited $? on $job"
echo "driver_test: one run took $((($(date +%s%N) - start) / 1000000)) ms"
node "$here/check_samples.mjs" "$job" || fail "sample checks"
if [[ ${ST_TEST_KEEP:-0} == 1 ]]; then node "$here/preview.mjs" "$work/scene/out"; fi

# 2. bad jobs
node -e '
  const fs = require("fs");
  const [job, dir] = process.argv.slice(1);
  const j = JSON.parse(fs.readFileSync(job, "utf8"));
  const put = (name, edit) => { const k = JSON.parse(JSON.stringify(j)); edit(k); k.out = dir + "/" + name + ".out"; fs.writeFileSync(dir + "/" + name + ".json", JSON.stringify(k)); };
  put("missing-gltf", (k) => { k.scene.gltf = dir + "/no-such-scene.gltf"; });
  put("unknown-engine", (k) => { k.engine = "no-such-engine"; });
  put("unknown-setting", (k) => { k.settings = { noSuchSetting: 1 }; });
' "$job" "$work"
expect_exit 2 'scene\.gltf not found: .*no-such-scene\.gltf' -- node "$engines/run.mjs" "$work/missing-gltf.json"
[[ $(wc -l <"$work/stderr") == 1 ]] || fail "the missing-glTF message is not one line"
[[ ! -e "$work/missing-gltf.out" ]] || fail "a rejected job created its output directory"
expect_exit 2 'unknown engine "no-such-engine"' -- node "$engines/run.mjs" "$work/unknown-engine.json"
expect_exit 2 'Chromium not found' -- env ST_CHROMIUM="$work/no-chromium" node "$engines/run.mjs" "$job"
expect_exit 2 'usage' -- node "$engines/run.mjs"
if [[ $engine == threejs ]]; then
  expect_exit 1 'exception|unknown setting' -- node "$engines/run.mjs" "$work/unknown-setting.json"
fi

echo "driver_test: all passed"
