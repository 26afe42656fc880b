#!/usr/bin/env bash
# Set up (if needed), build, and run the whole test suite.
#   ./test.sh                   run everything
#   ./test.sh --update-goldens  re-render the golden images into tests/golden/ (review them!)
set -euo pipefail
cd "$(dirname "$0")"
scripts/setup.sh
cmake --preset release >/dev/null
cmake --build --preset release
if [[ "${1:-}" == "--update-goldens" ]]; then
  exec env ST_UPDATE_GOLDENS=1 ctest --preset release -R golden
fi
ctest --preset release "$@"
