#!/usr/bin/env bash
# Set up (if needed), build, and run the whole test suite: every CTest test (unit, headless GL,
# golden images, command line, the editor under Xvfb) on the `asan` build (clang 14, ASan +
# UBSan), then each libFuzzer target for a bounded time from the same build. Both stages run
# even if the first failed; the exit code is non-zero if either did.
#   ./test.sh                   run everything (what .ci/run does)
#   ./test.sh -R Gltf           only the CTest suite, extra arguments go to ctest
#   ./test.sh --update-goldens  re-render the golden images into tests/golden/ with the release
#                               build (review them!)
set -euo pipefail
cd "$(dirname "$0")"
start=$SECONDS
scripts/setup.sh
if [[ "${1:-}" == "--update-goldens" ]]; then
  cmake --preset release >/dev/null
  cmake --build --preset release
  exec env ST_UPDATE_GOLDENS=1 ctest --preset release -R golden
fi
if (($#)); then
  exec scripts/asan.sh "$@"
fi

declare -a summary
failed=0
stage() {
  local name=$1 t0=$SECONDS
  shift
  if "$@"; then
    summary+=("$(printf '%-6s ok      %4d s' "$name" $((SECONDS - t0)))")
  else
    failed=1
    summary+=("$(printf '%-6s FAILED  %4d s' "$name" $((SECONDS - t0)))")
  fi
}
stage ctest scripts/asan.sh
# The two fuzzers run at once for 30 s each (scripts/fuzz.sh alone: 60 s): within the suite's
# 15 minutes; the saved crash inputs still run first, whole, and CTest's fuzz.*.corpus run every seed.
stage fuzz env FUZZ_SECONDS="${FUZZ_SECONDS:-30}" scripts/fuzz.sh
echo
echo "test.sh summary (total $((SECONDS - start)) s, setup included):"
printf '  %s\n' "${summary[@]}"
exit "$failed"
