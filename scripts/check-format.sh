#!/usr/bin/env bash
# Fails if a tracked C++ source of the project is not clang-formatted
# (.clang-format at the root). Prints the files to fix.
# One clang-format call checks them all: one process per file cost ~0.1 s each, most
# of the test's time for ~570 files.
set -euo pipefail
cd "$(dirname "$0")/.."
mapfile -t files < <(git ls-files --cached --others --exclude-standard -- \
  '*.h' '*.hpp' '*.cc' '*.cpp' | while read -r f; do [ -f "$f" ] && echo "$f"; done)
# A violation is reported as "<file>:<line>:<col>: error: ... [-Wclang-format-violations]".
report=$(clang-format --dry-run -Werror "${files[@]}" 2>&1 >/dev/null) && status=0 || status=$?
if [ "$status" -ne 0 ]; then
  mapfile -t bad < <(sed -n 's/^\(.*\):[0-9]*:[0-9]*: error: code should be clang-formatted.*/\1/p' \
    <<<"$report" | sort -u)
  if [ ${#bad[@]} -eq 0 ]; then
    echo "clang-format failed:" >&2
    echo "$report" >&2
    exit 1
  fi
  echo "not clang-formatted (run: clang-format -i <file>):"
  printf '  %s\n' "${bad[@]}"
  exit 1
fi
echo "format: ${#files[@]} files clean"
