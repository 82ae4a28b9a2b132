#!/usr/bin/env bash
# Where the benchmark scenes' learning gap comes from (issue 32, docs/results.md §G):
# exports each benchmark scene's labelled supervoxels for a training seed and a test
# seed (relmap-sim dataset), then scripts/learning-gap.py scores the oracle forest, a
# forest and the CMM on random and on choice-map samples, side by side.
# Env: OUT (out/learning-gap), FRAMES (12 per seed), BUDGET (200), REPS (5).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh python3-sklearn
[ -x build/sim_backend/relmap-sim ] && [ -x build/server/tools/relmap-cmm ] || ./scripts/configure-build.sh
out=${OUT:-out/learning-gap}
mkdir -p "$out"
for scene in ShelfClutter Workbench KitchenCounter; do
  for seed in 1 2; do
    csv=$out/$scene-s$seed.csv
    [ -f "$csv" ] && continue
    build/sim_backend/relmap-sim dataset --scene "sim_backend/scenes/benchmark/$scene.json" \
      --frames "${FRAMES:-12}" --seed "$seed" --out "$csv" 2>&1 | grep -v '^\['
  done
done
# Debian's python3, the one python3-sklearn installs into.
/usr/bin/python3 scripts/learning-gap.py --data "$out" --budget "${BUDGET:-200}" \
  --replications "${REPS:-5}" | tee "$out/table-${BUDGET:-200}.md"
