#!/usr/bin/env bash
# The whole test suite on a fresh Debian 12 machine: install, build, run CTest
# (unit, integration and format tests) and print its summary.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/configure-build.sh
ctest --test-dir build --output-on-failure -j 2
