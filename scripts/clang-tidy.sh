#!/usr/bin/env bash
# clang-tidy (.clang-tidy at the root) on every C++ translation unit of the project's
# own sources in build/compile_commands.json, in parallel batches
# (scripts/clang_tidy_batches.py says why); the `clang_tidy` test. Findings in the
# project's headers count too; generated code (build/) and third-party headers do not.
# Exits 1 and prints the findings when there is one.
#   scripts/clang-tidy.sh [build-dir] [file-regex]
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
build=${1:-build}
folders="common|server|client|sim_backend|robot_adapter|tests"
files=${2:-"^$root/($folders)/.*\\.cpp\$"}
if ! command -v clang-tidy >/dev/null; then
  echo "clang-tidy: not installed (scripts/install-deps.sh installs it)" >&2
  exit 1
fi
exec python3 scripts/clang_tidy_batches.py "$build" "$files" "^$root/($folders)/" \
  --jobs "$(nproc)"
