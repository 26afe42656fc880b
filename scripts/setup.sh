#!/usr/bin/env bash
# Installs every Debian package shadowtune needs to build, test and run the editor.
# Idempotent: exits at once when everything is present. Run as root (or with sudo).
# fonts-dejavu-core: every chart and label names its DejaVu family (report/chart_fonts.h), so
# other installed fonts cannot change an image. jq: the command-line tests read JSON with it.
# chromium, libxml2-utils: the check tests open its HTML report in headless Chromium and validate
# its JUnit XML with xmllint --schema (tests/check). lld-14: the asan preset links with it (a tenth of
# ld.bfd's time for an ASan test binary; cmake/unity.cmake).
# The web engines (engine-check, engines/README.md): node and npm (Debian's nodejs/npm when no node is
# installed), then `npm ci` in engines/ from its package-lock.json whenever node_modules is missing or
# older than the lock. puppeteer-core drives Debian's chromium; no browser is ever downloaded.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  build-essential cmake ninja-build pkg-config git
  dpkg-dev file bc
  libglm-dev nlohmann-json3-dev libcli11-dev libtinygltf-dev libstb-dev
  libopenimageio-dev openimageio-tools
  libepoxy-dev libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri
  libglfw3-dev libimgui-dev
  libembree-dev
  libplplot-dev plplot-driver-cairo
  libcairo2-dev libfontconfig-dev
  fonts-dejavu-core
  jq
  libgtest-dev googletest
  xvfb xauth xdotool
  chromium libxml2-utils
  clang-14 libclang-rt-14-dev llvm-14 lld-14
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
# A node from elsewhere (nodesource's nodejs carries its own npm) is kept: Debian's npm would conflict.
command -v node >/dev/null && command -v npm >/dev/null || missing+=(nodejs npm)

sudo=""
[[ $(id -u) -ne 0 ]] && sudo="sudo"
if ((${#missing[@]} == 0)); then
  echo "setup: all ${#packages[@]} packages present, node $(node --version)"
else
  echo "setup: installing ${missing[*]}"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
  echo "setup: packages done"
fi

# engines/node_modules from the lock (the esbuild binary comes as its platform package; its
# postinstall only checks it, so scripts stay off).
if [[ ! -f engines/node_modules/.package-lock.json || engines/package-lock.json -nt engines/node_modules/.package-lock.json ]]; then
  echo "setup: npm ci in engines/ (three, @babylonjs/core, @babylonjs/loaders, puppeteer-core, esbuild)"
  (cd engines && npm ci --no-audit --no-fund --ignore-scripts --loglevel=error)
fi
