#!/usr/bin/env bash
# Builds the libFuzzer targets (in the `asan` preset: clang 14, ASan + UBSan) and runs each for a
# bounded time on a copy of its seed corpus. Fails on any crash, sanitizer report, leak, timeout
# or out-of-memory; the input that caused it is left in build/fuzz/artifacts/.
#
#   scripts/fuzz.sh              every target (preset, gltf), FUZZ_SECONDS each
#   scripts/fuzz.sh gltf         only the named targets
#
#   FUZZ_SECONDS=60      time per target
#   FUZZ_PARALLEL=1      run the targets at the same time, one process each (0: one after another)
#   FUZZ_KEEP_CORPUS=0   1: continue from the corpus of the last run instead of the seeds
#
# The committed seeds (tests/fuzz/corpus/<target>) are never written to. Saved crash inputs
# (tests/fuzz/crashes/<target>) are run first, so a bug that is still there (or back) fails at once.
# Reproduce a failure: build/asan/tests/fuzz/fuzz_<target> build/fuzz/artifacts/<target>-crash-...
set -euo pipefail
cd "$(dirname "$0")/.."

seconds=${FUZZ_SECONDS:-60}
parallel=${FUZZ_PARALLEL:-1}
keep=${FUZZ_KEEP_CORPUS:-0}
targets=("$@")
((${#targets[@]})) || targets=(preset gltf)

declare -A max_len=([preset]=8192 [gltf]=16384)
for t in "${targets[@]}"; do
  [[ -n "${max_len[$t]:-}" ]] || { echo "fuzz: unknown target '$t' (preset, gltf)" >&2; exit 2; }
done

# clang 14 and its libFuzzer runtime (scripts/setup.sh installs clang-14 libclang-rt-14-dev llvm-14).
if ! command -v clang++-14 >/dev/null ||
   [[ ! -f "$(clang++-14 --print-runtime-dir)/libclang_rt.fuzzer-x86_64.a" ]]; then
  echo "fuzz: clang++-14 or its libFuzzer runtime is missing: run scripts/setup.sh" >&2
  exit 2
fi

start=$SECONDS
cmake --preset asan >/dev/null
cmake --build --preset asan --target fuzz_preset fuzz_gltf
echo "fuzz: build took $((SECONDS - start)) s"

bin=build/asan/tests/fuzz
out=build/fuzz
mkdir -p "$out/artifacts" "$out/logs" "$out/corpus-work"
# intercept_tls_get_addr=0: see scripts/asan.sh (LeakSanitizer's tracer and dynamic TLS blocks).
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:symbolize=1:intercept_tls_get_addr=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
# Function names and lines in the reports (llvm-14 ships it; the unversioned name needs `llvm`).
if [[ -z "${ASAN_SYMBOLIZER_PATH:-}" && -x /usr/lib/llvm-14/bin/llvm-symbolizer ]]; then
  export ASAN_SYMBOLIZER_PATH=/usr/lib/llvm-14/bin/llvm-symbolizer
fi

# The targets write a file per input: keep their scratch folders in RAM, and remove what a
# crashed process leaves behind.
if [[ -z "${ST_FUZZ_TMPDIR:-}" && -d /dev/shm && -w /dev/shm ]]; then
  export ST_FUZZ_TMPDIR=/dev/shm/shadowtune-fuzz-$$
  mkdir -p "$ST_FUZZ_TMPDIR"
  trap 'rm -rf "$ST_FUZZ_TMPDIR"' EXIT
fi

run() {
  local t=$1 work="$out/corpus-work/$1"
  if [[ "$keep" != 1 || ! -d "$work" ]]; then
    rm -rf "$work"
    mkdir -p "$work"
    cp tests/fuzz/corpus/"$t"/* "$work"/
  fi
  : >"$out/logs/$t.log"
  rm -f "$out/artifacts/$t-"*
  local flags=(-timeout=10 -rss_limit_mb=2048 -artifact_prefix="$out/artifacts/$t-")
  # Saved crash inputs first, each whole (fuzzing cuts inputs to -max_len).
  local crashes=()
  [[ -d tests/fuzz/crashes/$t ]] && mapfile -t crashes < <(find tests/fuzz/crashes/"$t" -type f ! -name '.*' | sort)
  if ((${#crashes[@]})); then
    "$bin/fuzz_$t" "${flags[@]}" "${crashes[@]}" >>"$out/logs/$t.log" 2>&1 || return
  fi
  "$bin/fuzz_$t" "$work" "${flags[@]}" -max_total_time="$seconds" -max_len="${max_len[$t]}" \
    -dict="tests/fuzz/$t.dict" -print_final_stats=1 >>"$out/logs/$t.log" 2>&1
}

declare -A status
if [[ "$parallel" == 1 ]]; then
  declare -A pids
  for t in "${targets[@]}"; do run "$t" & pids[$t]=$!; done
  for t in "${targets[@]}"; do
    if wait "${pids[$t]}"; then status[$t]=0; else status[$t]=$?; fi
  done
else
  for t in "${targets[@]}"; do
    if run "$t"; then status[$t]=0; else status[$t]=$?; fi
  done
fi

failed=0
for t in "${targets[@]}"; do
  log="$out/logs/$t.log"
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  saved=$(grep -q '^stat::' "$log" || sed -n 's/^Running: //p' "$log" | tail -1)
  corpus=$(find "$out/corpus-work/$t" -type f | wc -l)
  # A sanitizer report is a failure even if the process somehow exited 0.
  if [[ ${status[$t]} -ne 0 ]] || grep -qE 'ERROR: (Address|Leak|UndefinedBehavior)Sanitizer|runtime error:|==ERROR: libFuzzer' "$log"; then
    failed=1
    if [[ -n "$saved" ]]; then
      echo "fuzz: $t: FAILED (exit ${status[$t]}): the saved crash input $saved still fails; log $log" >&2
    else
      echo "fuzz: $t: FAILED (exit ${status[$t]}) after ${execs:-?} executions; log $log" >&2
    fi
    grep -E -m1 -A40 'ERROR: |runtime error:|fuzz check failed|deadly signal|timeout|out-of-memory' "$log" >&2 || tail -40 "$log" >&2
    ls -1 "$out"/artifacts/"$t"-* 2>/dev/null | sed 's/^/fuzz:   input: /' >&2 || true
  else
    echo "fuzz: $t: ok, ${execs:-?} executions in ${seconds} s, corpus $corpus inputs"
  fi
done
echo "fuzz: total $((SECONDS - start)) s"
exit "$failed"
