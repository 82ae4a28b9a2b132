#!/usr/bin/env bash
# How often physical mode labels a push wrong: every scene (the paper's six and the
# benchmark ones) at 320x240 and 640x480, with the default simulated Kinect, through the
# real server. A label is wrong when it says "moved" and the simulator moved the target by
# no more than the scene's motion threshold, or "not moved" when it moved it by more.
# scripts/change_detection_table.py prints the table and exits 1 when a scene's rate of
# wrong labels exceeds 5 % or any target that did not move is called "moved".
# ITERATIONS (default 100) x REPLICATIONS (2) pushes per scene and resolution; METHOD
# visibility (default) or paper2018. Uses build/ (scripts/configure-build.sh builds it when
# missing), or the relmap-sim named by RELMAP_SIM. Results: out/change-detection/.
set -euo pipefail
cd "$(dirname "$0")/.."
sim=${RELMAP_SIM:-build/sim_backend/relmap-sim}
if [ ! -x "$sim" ]; then
  ./scripts/configure-build.sh
fi
method=${METHOD:-visibility}
out=${OUT:-out/change-detection}/$method
iterations=${ITERATIONS:-100}
replications=${REPLICATIONS:-2}
# SCENES / RESOLUTIONS (space-separated) run a subset or another order; the table
# covers every run in the folder.
all_scenes="MoveableBalls MoveableBricks1 MoveableBricks2 WhiteMoveableBalls WhiteMoveableBricks"
all_scenes+=" SimKitchen ShelfClutter Workbench KitchenCounter"
read -r -a scenes <<<"${SCENES:-$all_scenes}"
read -r -a resolutions <<<"${RESOLUTIONS:-320x240 640x480}"
mkdir -p "$out"
for scene in "${scenes[@]}"; do
  file=sim_backend/scenes/$scene.json
  [ -f "sim_backend/scenes/benchmark/$scene.json" ] && file=sim_backend/scenes/benchmark/$scene.json
  for resolution in "${resolutions[@]}"; do
    run=$out/$scene-$resolution
    [ -f "$run/summary.json" ] && continue  # resumable
    "$sim" run --scene "$file" --mode physical --resolution "$resolution" \
      --change-method "$method" --iterations "$iterations" --replications "$replications" \
      --snapshots none --out "$run" 2>&1 | grep -E '^relmap-sim run' || true
  done
done
python3 scripts/change_detection_table.py "$out" | tee "$out/table.md"
