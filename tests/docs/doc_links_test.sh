#!/usr/bin/env bash
# Comments and docs cite only files of the repository: every docs/architecture.md#<anchor> names
# a heading of docs/architecture.md, every file a README link names exists, and nothing cites
# the design notes outside the repository (DESIGN.md, STYLE.md).
# usage: doc_links_test.sh SOURCE_DIR
set -uo pipefail
cd "$1" || exit 1
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }
sources() { git ls-files 2>/dev/null || find . -path ./build -prune -o -type f -print; }

# GitHub's anchors: lower case, punctuation dropped, spaces to hyphens.
anchors=$(sed -n 's/^##* //p' docs/architecture.md | tr 'A-Z' 'a-z' | sed 's/[^a-z0-9 -]//g; s/ /-/g')
while IFS=: read -r file anchor; do
  grep -qxF -- "$anchor" <<<"$anchors" || fail "$file cites docs/architecture.md#$anchor, no such heading"
done < <(sources | grep -vE '^(build|tests/fuzz/corpus)/' | xargs grep -oE 'docs/architecture\.md#[a-z0-9-]+' 2>/dev/null |
         sed 's/docs\/architecture\.md#//' | sort -u)
for doc in README.md docs/architecture.md; do
  for target in $(grep -oE '\]\([^)#]+' "$doc" | sed 's/^](//' | grep -v '://'); do
    [[ -e "$(dirname "$doc")/$target" ]] || fail "$doc links to $target, which does not exist"
  done
done
if grep -nE 'DESIGN\.md|STYLE\.md' $(sources | grep -vE '^(build/|tests/docs/)') 2>/dev/null; then
  fail "the lines above cite design notes outside the repository; cite docs/architecture.md"
fi
echo "$failures failure(s)"
((failures == 0))
