#!/usr/bin/env bash
# The installed tool and package, away from the source tree: installs the build into a
# temporary prefix, moves the prefix elsewhere, then from an empty folder runs the installed
# binary (with the source tree's shaders/, presets/ and schema/ hidden under empty tmpfs mounts
# in a private mount namespace where unshare allows it) and builds examples/csm_consumer against
# the installed find_package(shadowtune).
# usage: install_test.sh CMAKE BUILD_DIR SOURCE_DIR CXX_COMPILER BUILD_TYPE GENERATOR
set -uo pipefail
cmake=$1 build=$2 src=$3 cxx=$4 type=$5 generator=$6
work=$(mktemp -d) && trap 'rm -rf "$work"' EXIT
failures=0
check() {  # check NAME CONDITION...: records a failure with NAME when the condition fails
  local name=$1; shift
  if "$@"; then echo "ok   $name"; else echo "FAIL $name"; failures=$((failures + 1)); fi
}
err_has() { grep -qF -- "$1" "$work/stderr"; }

"$cmake" --install "$build" --prefix "$work/staged" >"$work/install.log" 2>&1
check "cmake --install succeeds" test $? = 0
mv "$work/staged" "$work/prefix"  # nothing may depend on the path it was installed to
P=$work/prefix
mkdir "$work/cwd" && cd "$work/cwd" || exit 1

check "bin/ holds the tool alone (no tests, no fuzzers)" test "$(ls "$P/bin")" = shadowtune
check "no test or fuzz files anywhere" bash -c "! find '$P' -iname '*test*' -o -iname '*fuzz*' | grep -q ."
for f in share/shadowtune/presets/default.json share/shadowtune/presets/scenes/fox.json \
         share/shadowtune/schema/preset.schema.json lib/cmake/shadowtune/shadowtuneConfig.cmake \
         lib/cmake/shadowtune/shadowtuneConfigVersion.cmake include/shadowtune/renderer/csm/splits.h \
         include/shadowtune/renderer/settings/settings.h include/shadowtune/renderer/settings/split_range.h; do
  check "installed $f" test -s "$P/$f"
done
# Each installed preset's "$schema" resolves next to it.
for preset in "$P"/share/shadowtune/presets/*.json "$P"/share/shadowtune/presets/scenes/*.json \
              "$P"/share/shadowtune/presets/engines/*.json; do
  schema=$(sed -n 's/^ *"\$schema": *"\([^"]*\)".*/\1/p' "$preset")
  check "$(basename "$preset")'s \$schema ($schema) resolves" test -s "$(dirname "$preset")/$schema"
done
# Every quoted #include of an installed header is installed too (shaders/codes.h included).
for header in $(cd "$P/include/shadowtune" && find . -name '*.h'); do
  for inc in $(sed -n 's/^#include "\([^"]*\)".*/\1/p' "$P/include/shadowtune/$header"); do
    check "$header's #include \"$inc\" is installed" test -f "$P/include/shadowtune/$inc"
  done
done

# The binary, from an empty folder, with the source tree's data out of reach.
hide=()
for flags in "--mount" "--mount --map-root-user"; do
  # shellcheck disable=SC2086
  if unshare $flags --propagation private sh -c "mount -t tmpfs none '$src/shaders'" 2>/dev/null; then
    hide=(unshare $flags --propagation private); break
  fi
done
run() {  # run ARGS...: the installed binary; stdout, stderr and the exit code into $work
  local mounts="" d
  for d in shaders presets schema; do mounts+="mount -t tmpfs none '$src/$d' && "; done
  if ((${#hide[@]})); then
    "${hide[@]}" sh -c "$mounts"'test -z "$(ls "$0/shaders")" && exec "$@"' "$src" "$P/bin/shadowtune" "$@"
  else
    "$P/bin/shadowtune" "$@"
  fi >"$work/stdout" 2>"$work/stderr"
  echo $? >"$work/rc"
}
((${#hide[@]})) || echo "note: unshare cannot mount here; the source tree stays visible (the binary runs from a moved prefix)"

run --version
version=$(cat "$work/stdout")
check "--version exits 0" test "$(cat "$work/rc")" = 0
check "--version says 'shadowtune <version> (commit <hash>|unknown)': $version" \
  grep -qE '^shadowtune [0-9]+\.[0-9]+(\.[0-9]+)? \(commit ([0-9a-f]{12}(-dirty)?|unknown)\)$' "$work/stdout"
built=$(sed -n 's/^#define ST_GIT_COMMIT "\(.*\)"$/\1/p' "$build/app/generated/st_version.h")
check "--version names the commit the build recorded ($built)" grep -qF "(commit $built)" "$work/stdout"
# The script behind it: HEAD in this checkout, "unknown" outside any.
version_of() {  # version_of DIR: the commit cmake/version_header.cmake finds for DIR
  "$cmake" -DSOURCE_DIR="$1" -DOUT="$work/v.h" -DVERSION=0 -DGIT="$(command -v git)" \
    -P "$src/cmake/version_header.cmake" && sed -n 's/^#define ST_GIT_COMMIT "\(.*\)"$/\1/p' "$work/v.h"
}
if head=$(git -C "$src" rev-parse --short=12 HEAD 2>/dev/null) && [[ $(git -C "$src" rev-parse --show-toplevel) -ef $src ]]; then
  check "version_header.cmake gives HEAD $head" grep -qE "^$head(-dirty)?$" <<<"$(version_of "$src")"
fi
check "version_header.cmake gives unknown outside a checkout" test "$(version_of "$work/cwd")" = unknown

run render "$P/share/shadowtune/presets/default.json" --out "$work/o" --size 160x90
check "render of the installed default.json exits 0" test "$(cat "$work/rc")" = 0
check "render wrote a PNG" bash -c "head -c 8 '$work/o/default.png' | od -An -tx1 | grep -q '89 50 4e 47 0d 0a 1a 0a'"
check "the PNG is 160x90" test "$(od -An -tu1 -j16 -N8 "$work/o/default.png" | tr -s ' ')" = " 0 0 0 160 0 0 0 90"
check "render wrote frame statistics" grep -q '"splits"' "$work/o/default.json"
# The scene presets are installed but their glTF files are not (see docs/install.md).
run render "$P/share/shadowtune/presets/scenes/fox.json" --out "$work/o"
check "a scene preset without its assets fails" test "$(cat "$work/rc")" = 1
check "... saying the scene file is missing" err_has "shared/assets/fox/Fox.glb: scene file not found"

# An engine's build: find_package(shadowtune) + shadowtune::csm, from the installed prefix only.
"$cmake" -S "$src/examples/csm_consumer" -B "$work/consumer" -G "$generator" -DCMAKE_PREFIX_PATH="$P" \
  -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_BUILD_TYPE="$type" >"$work/consumer.log" 2>&1 &&
  "$cmake" --build "$work/consumer" >>"$work/consumer.log" 2>&1
built=$?
check "the consumer configures and builds against the package" test $built = 0
((built == 0)) || cat "$work/consumer.log"
consumer=$work/consumer/csm_consumer
expect() {  # expect N F COUNT LAMBDA: the practical splits z_i = l n (f/n)^(i/N) + (1-l)(n + (i/N)(f-n))
  awk -v n="$1" -v f="$2" -v c="$3" -v l="$4" 'BEGIN { for (i = 0; i <= c; ++i)
    printf "%.9g ", l * n * (f / n) ^ (i / c) + (1 - l) * (n + (i / c) * (f - n)) }'
}
close() {  # close "A..." "B...": same count, each within 1e-5 relative
  awk -v a="$1" -v b="$2" 'BEGIN { na = split(a, x); nb = split(b, y); if (na != nb) exit 1
    for (i = 1; i <= na; ++i) { d = x[i] - y[i]; if (d < 0) d = -d; if (d > 1e-5 * (y[i] < 0 ? -y[i] : y[i]) + 1e-7) exit 1 } }'
}
for args in "0.1 400 4 0.5" "0.5 200 4 0.75" "1 1000 3 1" "0.25 80 6 0" "0.1 50 1 0.3"; do
  # shellcheck disable=SC2086
  got=$("$consumer" $args) && want=$(expect $args)
  check "consumer splits for n f N lambda = $args: $got ~ $want" close "$got" "$want"
done
check "consumer without arguments uses the SplitParams defaults" close "$("$consumer")" "$(expect 0.1 400 4 0.5)"
"$consumer" 0.1 400 0 0.5 >/dev/null 2>"$work/stderr"
check "consumer reports a bad count" err_has "count"

page=$(cat "$src/docs/install.md")
for f in CMakeLists.txt main.cpp; do
  check "docs/install.md shows examples/csm_consumer/$f verbatim" test -n "$(grep -F '' "$src/examples/csm_consumer/$f")" -a \
    "${page/"$(cat "$src/examples/csm_consumer/$f")"/}" != "$page"
done

echo "$failures failure(s)"
((failures == 0))
