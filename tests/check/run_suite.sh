#!/usr/bin/env bash
# One preset of a shipped check suite, as CTest runs it: `shadowtune check`, the command users run,
# with its report (index.html, results.json, images) and JUnit left in REPORT_DIR.
# ST_UPDATE_GOLDENS=1 (./test.sh --update-goldens) passes --update instead: review the new goldens.
# usage: run_suite.sh SHADOWTUNE SUITE GOLDEN_DIR REPORT_DIR PRESET_NAME
set -euo pipefail
bin=$1 suite=$2 golden=$3 report=$4 only=$5
update=()
[[ ${ST_UPDATE_GOLDENS:-} == 1 ]] && update=(--update)
exec "$bin" check "$suite" --golden "$golden" --only "$only" --report "$report" --junit "$report/junit.xml" "${update[@]}"
