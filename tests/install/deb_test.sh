#!/usr/bin/env bash
# `cpack -G DEB` of this build into a temporary folder: the package holds the tool, its presets
# and schema and the CMake package, and Depends names the runtime libraries and Mesa's drivers.
# Skipped (exit 77) without dpkg-deb and dpkg-shlibdeps (Debian's dpkg-dev).
# usage: deb_test.sh CPACK BUILD_DIR
set -uo pipefail
cpack=$1 build=$2
command -v dpkg-deb >/dev/null && command -v dpkg-shlibdeps >/dev/null ||
  { echo "skipped: dpkg-deb or dpkg-shlibdeps missing (apt-get install dpkg-dev file)"; exit 77; }
work=$(mktemp -d) && trap 'rm -rf "$work"' EXIT
failures=0
check() {  # check NAME CONDITION...: records a failure with NAME when the condition fails
  local name=$1; shift
  if "$@"; then echo "ok   $name"; else echo "FAIL $name"; failures=$((failures + 1)); fi
}

"$cpack" -G DEB --config "$build/CPackConfig.cmake" -B "$work" >"$work/cpack.log" 2>&1
check "cpack -G DEB succeeds" test $? = 0
deb=$(ls "$work"/shadowtune_*.deb 2>/dev/null | head -1)
check "a .deb came out" test -s "$deb"
((failures == 0)) || { cat "$work/cpack.log"; exit 1; }
dpkg-deb -c "$deb" | awk '{print $6}' >"$work/contents"
for f in ./usr/bin/shadowtune ./usr/share/shadowtune/presets/default.json ./usr/share/shadowtune/schema/preset.schema.json \
         ./usr/lib/cmake/shadowtune/shadowtuneConfig.cmake ./usr/include/shadowtune/renderer/csm/splits.h; do
  check "the package holds $f" grep -qxF "$f" "$work/contents"
done
check "the package holds no test or fuzz binary" bash -c "! grep -iE 'test|fuzz' '$work/contents'"
depends=$(dpkg-deb -f "$deb" Depends)
echo "Depends: $depends"
for p in libepoxy0 libegl1 libglfw3 libembree3-3 libopenimageio2.4 libegl-mesa0 libgl1-mesa-dri fonts-dejavu-core; do
  check "Depends names $p" grep -qE "(^|, )$p( |,|$)" <<<"$depends"
done
echo "$failures failure(s)"
((failures == 0))
