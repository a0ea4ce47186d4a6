#!/usr/bin/env bash
# The bash completion and the man page the build generated from the option tables (BUILD/share):
# completion as bash itself runs it, for every command and option `opf <command> --help` lists;
# the man page rendered by man and groff without warnings.
#   bash tests/cli/completion_and_manual.sh BUILD_DIR OPF
set -euo pipefail
build="$1"
opf="$2"
completion="$build/share/bash-completion/completions/opf"
page="$build/share/man/man1/opf.1"
# shellcheck source=/dev/null
source "$completion"

# Completes `words...` with the cursor after the last word; prints the candidates.
complete_line() {
  COMP_WORDS=("$@")
  COMP_CWORD=$((${#COMP_WORDS[@]} - 1))
  COMPREPLY=()
  _opf
  echo "${COMPREPLY[*]:-}"
}
expect() {  # expect DESCRIPTION ACTUAL EXPECTED
  [ "$2" = "$3" ] || { echo "completion: $1: got '$2', expected '$3'" >&2; exit 1; }
}

commands="$("$opf" --help | awk '/^Commands:/ {on = 1; next} on && NF == 0 {on = 0} on {print $1}')"
[ "$(wc -w <<<"$commands")" -ge 9 ] || { echo "no command list in opf --help" >&2; exit 1; }
expect "commands" "$(complete_line opf '')" "$(echo $commands) --help --version"
expect "a prefix" "$(complete_line opf tr)" "track"
expect "estimator names" "$(complete_line opf track --estimator '')" "opf pf cvkf imm oapf"
expect "presets" "$(complete_line opf reproduce --preset p)" "paper"
expect "a free value" "$(complete_line opf track --seed '')" ""
checked=0
for command in $commands; do
  # Every option its --help lists is offered, and nothing else.
  listed="$("$opf" "$command" --help | grep -oE '^  --[a-z0-9-]+' | tr -d ' ' | sort | tr '\n' ' ')"
  offered="$(complete_line opf "$command" -- | tr ' ' '\n' | sort | tr '\n' ' ')"
  expect "$command's options" "$offered" "$listed"
  grep -q "^\.SS \"opf $command" "$page" || { echo "man page: no section for $command" >&2; exit 1; }
  checked=$((checked + 1))
done
# File names where an option takes a file: the page itself, from its directory.
expect "a file" "$(cd "$(dirname "$page")" && complete_line opf track --in opf.)" "opf.1"

warnings="$(groff -man -Tutf8 -ww -z "$page" 2>&1)"
[ -z "$warnings" ] || { echo "man page: groff warns: $warnings" >&2; exit 1; }
rendered="$(MANWIDTH=100 man -l "$page" 2>/dev/null)"
grep -q "OPF(1)" <<<"$rendered" || { echo "man page: does not render" >&2; exit 1; }
grep -q -- "--estimator" <<<"$rendered" || { echo "man page: options missing" >&2; exit 1; }
echo "completion and man page: $checked commands, every option offered and documented"
