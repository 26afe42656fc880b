#!/usr/bin/env bash
# The docs say only what is true: every relative link of the pages names an existing file (and,
# with #anchor, a heading of it, as GitHub computes anchors), every command of a ```sh block that
# starts with `shadowtune`, `build/release/shadowtune`, `build/release/app/shadowtune` or `./`
# exits 0, and every option of `shadowtune COMMAND --help` has its row in docs/cli.md (and every
# row names an option that exists).
#
# A command is not run, and is listed as such, when its line ends with `# not run: REASON`, when
# its block's first line is `# not run: REASON`, or when the line just before the block's fence
# is `<!-- not run: REASON -->` (invisible on GitHub). The reason may not be empty.
#
# Commands run in a temporary folder per page that links every top-level entry of the source tree
# (so `presets/...` and `./scripts/...` resolve) and holds `shadowtune` on the PATH and at
# build/release/shadowtune: the binary given, not the source tree's build.
#
# usage: docs_test.sh SOURCE_DIR BINARY [PAGE.md...]   (default: README.md docs/*.md)
#        docs_test.sh --self-test SOURCE_DIR BINARY    a broken page fails each check, a good one passes
set -uo pipefail
export LC_ALL=C.UTF-8

failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }

# Lines outside ``` fences, as "LINE<TAB>text".
prose() { awk '/^[[:space:]]*```/ { fence = !fence; next } !fence { print NR "\t" $0 }' "$1"; }

# The anchors GitHub gives a page's headings: markup and punctuation dropped, lower case, spaces to
# hyphens, the n-th repeat of an anchor suffixed -n.
anchors() {
  prose "$1" | cut -f2- | sed -n 's/^#\{1,6\}[[:space:]]\+//p' | sed 's/[[:space:]]*#*[[:space:]]*$//' |
    sed 's/!\?\[\([^]]*\)\]([^)]*)/\1/g' | tr '[:upper:]' '[:lower:]' |
    sed 's/[^[:alnum:] _-]//g; s/ /-/g' |
    awk '{ n = seen[$0]++; print (n ? $0 "-" n : $0) }'
}

# Every link target of a page (outside code), as "LINE<TAB>target".
links() {
  prose "$1" | sed 's/`[^`]*`//g' |
    awk -F'\t' '{ s = $2; while (match(s, /\]\([^) ]+/)) { print $1 "\t" substr(s, RSTART + 2, RLENGTH - 2); s = substr(s, RSTART + RLENGTH) } }'
}

check_links() {  # check_links PAGE
  local page=$1 dir line target file anchor
  dir=$(dirname "$page")
  while IFS=$'\t' read -r line target; do
    case $target in *://* | mailto:*) continue ;; esac
    file=${target%%#*} anchor=
    [[ $target == *#* ]] && anchor=${target#*#}
    if [[ -z $file ]]; then file=$page; else file=$dir/$file; fi
    if [[ ! -e $file ]]; then
      fail "$page:$line: link to $target: no such file"
    elif [[ -n $anchor ]] && ! anchors "$file" | grep -qxF -- "$anchor"; then
      fail "$page:$line: link to $target: no heading with anchor #$anchor in $file"
    fi
  done < <(links "$page")
}

# The commands of a page's ```sh blocks, as "LINE<US>skip-reason<US>command" (US = \037, not a
# tab: read would merge an empty reason's two tabs); continuation lines joined; only the commands
# the docs promise run: see the header.
commands() {
  awk '
    function emit(text, n) {
      sub(/^[[:space:]]+/, "", text)
      if (text !~ /^(shadowtune|build\/release\/shadowtune|build\/release\/app\/shadowtune|\.\/)/) return
      reason = block
      if (reason == "" && match(text, /#[[:space:]]*not run:[[:space:]]*[^[:space:]].*$/)) {
        reason = substr(text, RSTART, RLENGTH); sub(/^#[[:space:]]*not run:[[:space:]]*/, "", reason)
      }
      print n "\037" reason "\037" text
    }
    /^[[:space:]]*```/ {
      if (!insh && !inother) {
        if ($0 ~ /^[[:space:]]*```sh[[:space:]]*$/) {
          insh = 1; first = 1; block = ""
          if (prev ~ /^[[:space:]]*<!--[[:space:]]*not run:[[:space:]]*[^[:space:]].*-->[[:space:]]*$/) {
            block = prev; sub(/^[[:space:]]*<!--[[:space:]]*not run:[[:space:]]*/, "", block); sub(/[[:space:]]*-->[[:space:]]*$/, "", block)
          }
        } else inother = 1
      } else { insh = 0; inother = 0 }
      prev = $0; next
    }
    insh {
      if (first && $0 ~ /^[[:space:]]*#[[:space:]]*not run:[[:space:]]*[^[:space:]]/) {
        block = $0; sub(/^[[:space:]]*#[[:space:]]*not run:[[:space:]]*/, "", block)
      }
      first = 0
      if (pending != "") { line = pending " " $0; n = pn } else { line = $0; n = NR }
      if (line ~ /\\$/) { sub(/\\$/, "", line); pending = line; pn = n; next }
      pending = ""; emit(line, n); next
    }
    { prev = $0 }
  ' "$1"
}

# A scratch folder that looks like the source tree, with `shadowtune` being BINARY.
scratch() {  # scratch SOURCE_DIR BINARY -> prints the folder
  local src=$1 bin=$2 dir entry
  dir=$(mktemp -d "${TMPDIR:-/tmp}/docs-test.XXXXXX")
  for entry in "$src"/* "$src"/.ci; do
    [[ -e $entry ]] || continue
    case $(basename "$entry") in build | out) continue ;; esac
    ln -s "$entry" "$dir/$(basename "$entry")"
  done
  mkdir -p "$dir/.bin" "$dir/build/release/app"
  ln -s "$bin" "$dir/.bin/shadowtune"
  ln -s "$bin" "$dir/build/release/shadowtune"
  ln -s "$bin" "$dir/build/release/app/shadowtune"
  echo "$dir"
}

check_commands() {  # check_commands PAGE SOURCE_DIR BINARY
  local page=$1 work line reason cmd log start
  work=$(scratch "$2" "$3")
  log=$work/.log
  while IFS=$'\037' read -r line reason cmd; do
    if [[ -n $reason ]]; then
      echo "not run  $page:$line: ${cmd%%#*}  ($reason)"
      continue
    fi
    start=$SECONDS
    if (cd "$work" && PATH="$work/.bin:$PATH" timeout 120 bash -o pipefail -c "$cmd") >"$log" 2>&1 </dev/null; then
      echo "ok       $page:$line: $cmd  ($((SECONDS - start)) s)"
    else
      fail "$page:$line: exit $? from: $cmd"
      tail -n 15 "$log" | sed 's/^/    /'
    fi
  done < <(commands "$page")
  rm -rf "$work"
}

# Each command's --help options against the rows `| \`--option ...` of its "## COMMAND" section.
check_cli_options() {  # check_cli_options CLI_MD BINARY
  local md=$1 bin=$2 cmd opt documented offered
  for cmd in $("$bin" --help | awk '/^SUBCOMMANDS:|^Subcommands:/ { on = 1; next } on && /^  [a-z]/ { print $1 }'); do
    documented=$(awk -v h="## $cmd" '$0 == h { on = 1; next } /^## / { on = 0 } on' "$md" |
                 grep -E '^\| `--' | grep -oE '`--[a-z][a-z0-9-]*' | tr -d '`' | sort -u)
    offered=$("$bin" "$cmd" --help | grep -oE '^ +(-[a-zA-Z], )?--[a-z][a-z0-9-]*' | grep -oE -- '--[a-z0-9-]+' |
              grep -vx -- '--help' | sort -u)
    [[ -n $offered ]] || fail "$bin $cmd --help lists no options"
    for opt in $(comm -23 <(echo "$offered") <(echo "$documented")); do
      fail "$md: section '## $cmd' has no row for $cmd $opt"
    done
    for opt in $(comm -13 <(echo "$offered") <(echo "$documented")); do
      fail "$md: section '## $cmd' documents $opt, which $cmd --help does not offer"
    done
  done
}

check_pages() {  # check_pages SOURCE_DIR BINARY PAGE...
  local src=$1 bin=$2 page
  shift 2
  for page in "$@"; do
    check_links "$page"
    check_commands "$page" "$src" "$bin"
  done
}

self_test() {  # self_test SOURCE_DIR BINARY: the checks catch a broken page and pass a good one
  local src=$1 bin=$2 dir out
  dir=$(mktemp -d "${TMPDIR:-/tmp}/docs-self-test.XXXXXX")
  mkdir "$dir/docs"
  cat >"$dir/docs/good.md" <<'EOF'
# A good page

## Its second heading

## Its second heading

## `sweep --merge`: joins shards

Links: [itself](#a-good-page), [the heading](good.md#its-second-heading), [its repeat](#its-second-heading-1),
[code in a heading](#sweep---merge-joins-shards), [a file](../README.md).

```sh
shadowtune --version
build/release/shadowtune render presets/box-over-plane.json --out o --size 160x90
shadowtune editor  # not run: needs a display
cmake --version
```
<!-- not run: the block as a whole -->
```sh
./no-such-script.sh
```
EOF
  echo "# readme" >"$dir/README.md"
  cat >"$dir/docs/bad.md" <<'EOF'
# A bad page

[gone](missing.md) and [no heading](#nowhere) and `[in code](not-a-link.md)`.

```sh
shadowtune render presets/no-such-preset.json --out o
./no-such-script.sh  # not run:
```
EOF
  out=$(check_pages "$src" "$bin" "$dir/docs/good.md" 2>&1)
  if grep -q '^FAIL' <<<"$out"; then fail "self-test: the good page failed:"; echo "$out"; fi
  grep -q '^not run  .*shadowtune editor' <<<"$out" || fail "self-test: the marked editor line was not listed as not run"
  grep -q '^not run  .*no-such-script' <<<"$out" || fail "self-test: the block marked by <!-- not run --> was run"
  grep -q '^ok .*render presets/box-over-plane' <<<"$out" || fail "self-test: the good render was not run"

  cat >"$dir/docs/cli.md" <<'EOF'
## export

| option | meaning |
| --- | --- |
| `--to ENGINE` | the engine |
| `--bogus` | an option export does not have |
EOF
  out=$(check_cli_options "$dir/docs/cli.md" "$bin" 2>&1)
  grep -q "has no row for export --json" <<<"$out" || fail "self-test: an undocumented option was not reported"
  grep -q "documents --bogus, which export --help does not offer" <<<"$out" ||
    fail "self-test: a documented option that does not exist was not reported"
  grep -q "no row for export --to" <<<"$out" && fail "self-test: a documented option was reported missing"

  out=$(check_pages "$src" "$bin" "$dir/docs/bad.md" 2>&1)
  echo "$out" | sed 's/^/  bad.md: /'
  grep -q 'link to missing.md: no such file' <<<"$out" || fail "self-test: the broken link was not reported"
  grep -q 'link to #nowhere: no heading' <<<"$out" || fail "self-test: the missing anchor was not reported"
  grep -q 'not-a-link' <<<"$out" && fail "self-test: a link inside inline code was checked"
  grep -q 'FAIL .*exit [0-9]* from: shadowtune render presets/no-such-preset.json' <<<"$out" ||
    fail "self-test: the failing command was not reported"
  grep -q 'FAIL .*from: ./no-such-script.sh' <<<"$out" || fail "self-test: a marker without a reason skipped a command"
  rm -rf "$dir"
}

if [[ ${1:-} == --self-test ]]; then
  self_test "$(realpath "$2")" "$(realpath "$3")"
else
  src=$(realpath "$1") bin=$(realpath "$2")
  shift 2
  cd "$src" || exit 1
  (($# > 0)) || set -- README.md docs/*.md
  check_pages "$src" "$bin" "$@"
  [[ " $* " == *" docs/cli.md "* ]] && check_cli_options docs/cli.md "$bin"
fi
echo "$failures failure(s)"
((failures == 0))
