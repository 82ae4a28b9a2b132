#!/usr/bin/env bash
# The side-by-side learning benchmark: builds relmap in build/ (the one build of
# scripts/configure-build.sh), then runs every learner on the default suite with
# the scikit-learn reference. Extra arguments go to relmap-bench-learning (e.g.
# --stream real=train.csv:test.csv). Results: out/bench-learning/.
set -euo pipefail
cd "$(dirname "$0")/.."
# The batch reference (random forest, RBF SVM, logistic regression) runs on Debian's scikit-learn.
./scripts/install-deps.sh python3-sklearn
./scripts/configure-build.sh
mkdir -p out/bench-learning
build/server/tools/relmap-bench-learning --out out/bench-learning --reference "$@" |
  tee out/bench-learning/table.txt
