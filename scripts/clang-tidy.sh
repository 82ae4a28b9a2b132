#!/usr/bin/env bash
# clang-tidy (.clang-tidy at the root) on every C++ translation unit of the project's
# own sources in build/compile_commands.json, in parallel; the `clang_tidy` test.
# Findings in the project's headers count too; generated code (build/) and
# third-party headers do not. Exits 1 and prints the findings when there is one.
#   scripts/clang-tidy.sh [build-dir] [file-regex]
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
build=${1:-build}
files=${2:-"^$root/(common|server|client|sim_backend|robot_adapter|tests)/.*\\.cpp\$"}
# Not a test yet (a full run takes longer than CI's budget), so the test command's
# install leaves clang-tidy out; this script installs it when it is missing.
./scripts/install-deps.sh clang-tidy
log=$(mktemp)
trap 'rm -f "$log"' EXIT
jobs=$(nproc)
start=$(date +%s)
# -quiet keeps the output to the findings; the header filter names the project's folders
# under the source root, which the build folder's generated headers are not in.
# run-clang-tidy colours its output whatever it writes to; the colours are taken out.
status=0
run-clang-tidy -quiet -j "$jobs" -p "$build" \
  -header-filter "^$root/(common|server|client|sim_backend|robot_adapter|tests)/" \
  "$files" >"$log" 2>&1 || status=$?
sed -i 's/\x1b\[[0-9;]*m//g' "$log"
units=$(grep -c '"file"' "$build/compile_commands.json" || true)
findings=$(grep -cE '^/.*: (warning|error):' "$log" || true)
echo "clang-tidy: $findings findings in $(($(date +%s) - start)) s ($jobs jobs, $units units in the database)"
if [ "$status" -ne 0 ] || [ "$findings" -ne 0 ]; then
  grep -E -A3 '^/.*: (warning|error):' "$log" | head -400
  exit 1
fi
