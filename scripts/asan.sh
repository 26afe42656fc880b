#!/usr/bin/env bash
# Builds the `asan` preset (clang 14 at -O0, AddressSanitizer + UndefinedBehaviorSanitizer, leak
# checks on; also the libFuzzer targets) and runs the whole CTest suite on it: unit, headless GL,
# golden-image, command-line and Xvfb editor tests. Any sanitizer report (error, UB, leak) fails
# its test.
#
#   scripts/asan.sh               build, then every test
#   scripts/asan.sh -R Gltf       extra arguments go to ctest
#
# The Mesa driver: tests/sanitizers/no_dlclose.cpp is preloaded so EGL cannot unload the driver
# at eglTerminate (see there: unloaded, its never-freed globals look leaked from an unknown
# module). tests/sanitizers/lsan.supp may list driver libraries only, never project code.
set -euo pipefail
cd "$(dirname "$0")/.."

start=$SECONDS
cmake --preset asan >/dev/null
cmake --build --preset asan
built=$SECONDS
echo "asan: build took $((built - start)) s"

# verify_asan_link_order=0: the preloaded no_dlclose.so comes before the ASan runtime; it defines
# nothing but dlclose, so ASan's interceptors are unaffected. tests/CMakeLists.txt keeps a copy of
# these options (ST_ASAN_OPTIONS) for the editor tests' children: keep the two in step.
# intercept_tls_get_addr=0: up to LLVM 16 the runtime's __tls_get_addr interceptor takes a dynamic
# TLS block whose address is 16 bytes into a page for a pre-2.25 glibc block with a header, reads
# a bogus range from the words before it, and LeakSanitizer's tracer then dies scanning it at exit
# ("Tracer caught signal 11", "DTLS 39 at 0x2bf3-0x1800003cf5", no report; google/sanitizers#1322).
# Where a malloc'd block lands is fixed for a given binary and input, so the crash repeats
# (golden.scenes.living-room hit it every run). glibc 2.36 mallocs those blocks: LeakSanitizer still
# sees them as heap, only not as roots, so a leak is still reported, never hidden.
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:detect_stack_use_after_return=1:check_initialization_order=1:verify_asan_link_order=0:intercept_tls_get_addr=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$PWD/tests/sanitizers/lsan.supp:print_suppressions=0}

# The build made it (target st_no_dlclose, tests/CMakeLists.txt); tests that start the editor
# preload it in their children themselves (tests/editor/child_sanitizer_env.cpp).
preload="$PWD/build/asan/tests/no_dlclose.so${LD_PRELOAD:+ $LD_PRELOAD}"
status=0
LD_PRELOAD=$preload ctest --preset asan "$@" || status=$?

# LeakSanitizer's own tracer now and then crashes as a test exits ("Tracer caught signal 11",
# "LeakSanitizer has encountered a fatal error") while driver or Embree worker threads wind down:
# the checker failed, it reported nothing. Tests that failed only that way run once more; a
# sanitizer report, a failed assertion or any other failure stands.
testlog=build/asan/Testing/Temporary/LastTest.log
section() {  # the output of test $1 in the last run
  awk -v t="$1" '{ n = index($0, " Testing: ") } n && substr($0, n + 10) == t { on = 1 }
                 on { print } on && /^Test (Failed|Passed)\./ { exit }' "$testlog"
}
lsan_tracer_crash_only() {
  local out
  out=$(section "$1")
  grep -q "LeakSanitizer has encountered a fatal error" <<<"$out" &&
    ! grep -qE 'ERROR: [A-Za-z]+Sanitizer: |runtime error:|\[  FAILED  \]' <<<"$out"
}
if ((status != 0)) && [[ -s build/asan/Testing/Temporary/LastTestsFailed.log ]]; then
  mapfile -t failed < <(cut -d: -f2- build/asan/Testing/Temporary/LastTestsFailed.log)
  retry=1
  for t in "${failed[@]}"; do lsan_tracer_crash_only "$t" || retry=0; done
  if ((retry)); then
    echo "asan: LeakSanitizer's tracer crashed at exit (no report) in: ${failed[*]}; running them once more"
    status=0
    LD_PRELOAD=$preload ctest --preset asan --rerun-failed || status=$?
  fi
fi
echo "asan: tests took $((SECONDS - built)) s (total $((SECONDS - start)) s)"
exit "$status"
