#!/usr/bin/env bash
# relmap-bench-learning on real-like streams (issue 32). Per benchmark scene:
#   SCENE        the pushes of `relmap-sim dataset --mode physical` (a physical-mode run,
#                seed 1, $PUSHES pushes): each target's feature with the label the
#                server's change detector gave it, so the label noise is the detector's;
#   SCENE-flip20 the same with 20 % of the training labels flipped (--flip 0.2);
#   SCENE-truth  the same pushes labelled with the ground truth (what the detector cost),
#                and SCENE-truth-flip20.
# Every stream is tested on the ground truth of every usable supervoxel of
# $TEST_FRAMES frames of another instance of the scene (`relmap-sim dataset`, seed 2):
# what the relevance map is scored on. Then every online learner and the batch
# reference (random forest, tuned RBF SVM, tuned logistic regression) side by side.
# Results: $OUT (table.txt, table.csv); the streams are kept in $OUT/data and made
# again only when missing. SKIP_BUILD=1: use build/ as it is.
set -euo pipefail
cd "$(dirname "$0")/.."
OUT=${OUT:-out/bench-learning-real-like}
PUSHES=${PUSHES:-400}
TEST_FRAMES=${TEST_FRAMES:-4}
RESOLUTION=${RESOLUTION:-320x240}
SCENES=${SCENES:-ShelfClutter Workbench KitchenCounter}
if [ -z "${SKIP_BUILD:-}" ]; then
  ./scripts/install-deps.sh python3-sklearn
  ./scripts/configure-build.sh
fi
sim=build/sim_backend/relmap-sim
data=$OUT/data
mkdir -p "$data"
streams=()
for scene in $SCENES; do
  file=sim_backend/scenes/benchmark/$scene.json
  if [ ! -s "$data/$scene.train.csv" ]; then
    nice -n 19 "$sim" dataset --mode physical --scene "$file" --seed 1 --frames "$PUSHES" \
      --resolution "$RESOLUTION" --out "$data/$scene.train.csv" \
      --truth-out "$data/$scene.truth.csv" 2>&1 | tail -1 | tee "$data/$scene.train.log"
  fi
  if [ ! -s "$data/$scene.test.csv" ]; then
    nice -n 19 "$sim" dataset --scene "$file" --seed 2 --frames "$TEST_FRAMES" \
      --resolution "$RESOLUTION" --out "$data/$scene.test.csv" 2>&1 | tail -1 |
      tee "$data/$scene.test.log"
  fi
  streams+=(--stream "$scene=$data/$scene.train.csv:$data/$scene.test.csv"
    --stream "$scene-truth=$data/$scene.truth.csv:$data/$scene.test.csv")
done
nice -n 19 build/server/tools/relmap-bench-learning "${streams[@]}" --flip 0.2 --seed 1 \
  --out "$OUT" --reference | tee "$OUT/table.txt"
