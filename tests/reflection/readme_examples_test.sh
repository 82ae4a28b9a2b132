#!/usr/bin/env bash
# Runs the grpcurl examples of a markdown file as written, against a real server, with
# scripts/grpcurl-lite standing for grpcurl: every ```sh block, in order, in one shell
# (later blocks use the variables earlier ones set), under set -e. Where the file has
# the grpcurl-examples begin and end markers, only the blocks between them run.
# usage: readme_examples_test.sh <relmap-server binary> <markdown file> <PCD cloud>
set -eu
server_binary=$1
markdown=$(cd "$(dirname "$2")" && pwd)/$(basename "$2")
# shellcheck source=harness.sh
source "$(dirname "$0")/harness.sh"
[ -f "$3" ] || fail "no cloud at $3"

begin_marker='<!-- grpcurl-examples:begin -->'
end_marker='<!-- grpcurl-examples:end -->'

# extract_examples <markdown file>: the ```sh blocks as one bash script, each block
# announced with its line number.
extract_examples() {
  local inside=1 in_block=0 number=0 line fence='```'
  if grep -qF "$begin_marker" "$1"; then inside=0; fi
  while IFS= read -r line || [ -n "$line" ]; do
    number=$((number + 1))
    if [ "$in_block" = 1 ]; then
      if [ "$line" = "$fence" ]; then
        in_block=0
      else
        printf '%s\n' "$line"
      fi
    elif [ "$line" = "$begin_marker" ]; then
      inside=1
    elif [ "$line" = "$end_marker" ]; then
      inside=0
    elif [ "$inside" = 1 ] && [ "$line" = "${fence}sh" ]; then
      in_block=1
      printf 'example_at %d\n' "$number"
    fi
  done <"$1"
}

example_at() {
  example_line=$1
  echo "--- $markdown:$example_line"
}

# Called by the harness when the test exits with a failure.
describe_failure() {
  [ -z "${example_line:-}" ] ||
    echo "FAIL the example at $markdown:$example_line failed (exit status $1)" >&2
}

CLOUD=$(cd "$(dirname "$3")" && pwd)/$(basename "$3")
export CLOUD
script=$(extract_examples "$markdown")
[ -n "$script" ] || fail "no \`\`\`sh blocks in $markdown"
start_server "$server_binary"
cd "$workdir" # the files the examples write (session.json, ...) go with the server's
set -o pipefail
eval "$script"
example_line=
echo "readme_grpcurl_examples: $(grep -c '^example_at ' <<<"$script") example blocks ran"
