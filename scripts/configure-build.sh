#!/usr/bin/env bash
# Installs what is missing, configures the one build (Release, Ninja) in build/
# and builds everything once. Shared by the main job and the test suite.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
# Two jobs: a PCL translation unit takes ~0.6 GB of compiler memory.
cmake --build build -j 2
