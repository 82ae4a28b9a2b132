#!/usr/bin/env bash
# The paper's simulated experiments (docs/results.md §K) and the benchmark scenes:
# each setup in oracle mode with the default classifier, 10 replications, the
# ablations side by side (one component per class, paper2018, random sampling) and
# physical labelling. Needs the build (scripts/configure-build.sh), or RELMAP_SIM naming a
# relmap-sim with its relmap-server beside it. Results go to
# out/results-kinect/<experiment>/ (summary.json, replication-<r>.csv, plots); the
# summaries and accuracy plots are kept in docs/results/kinect/ (below), in order in its
# experiments.txt; an experiment kept there is skipped, so a run can be resumed.
# Then scripts/results-sim-table.py prints the tables of docs/results.md.
set -euo pipefail
cd "$(dirname "$0")/.."
sim=${RELMAP_SIM:-build/sim_backend/relmap-sim}  # or a copy, to rebuild while it runs
out=${OUT:-out/results-kinect}
reps=${REPLICATIONS:-10}

keep=${KEEP:-docs/results/kinect}  # what docs/results.md cites, committed
# ONLY: an extended regular expression; experiments whose names do not match it are left
# for a later run (e.g. ONLY='-(paper2018|random)$' while the change detector is changing).
only=${ONLY:-.}

# Each finished experiment's summary.json and accuracy plot are kept under $keep/<name>/,
# in git: a run that the 180-minute sessions cut short resumes from a clean clone where it
# stopped, and the tables are made from what is kept.
run() {  # run <experiment> <relmap-sim run flags...>
  local name=$1
  shift
  if ! grep -Eq -- "$only" <<<"$name"; then
    echo "== $name: not in ONLY=$only, left"
    return
  fi
  mkdir -p "$out" "$keep"
  grep -qx "$name" "$keep/experiments.txt" 2>/dev/null || echo "$name" >>"$keep/experiments.txt"
  if [ -f "$keep/$name/summary.json" ]; then
    echo "== $name: done already ($keep/$name)"
    return
  fi
  if [ ! -f "$out/$name/summary.json" ]; then
    echo "== $name: $sim run $* --replications $reps --seed 1 --parallel 2 --out $out/$name"
    "$sim" run "$@" --replications "$reps" --seed 1 --parallel 2 --out "$out/$name"
  fi
  mkdir -p "$keep/$name"
  cp "$out/$name/summary.json" "$out/$name/accuracy.png" "$keep/$name/"
}

# With the default camera, the simulated Kinect v1 (sim_backend/scenes/README.md,
# "Camera"); docs/results.md §S1-§S2 were made before it, with the ideal camera.
# Most telling first, so that a partial run says the most: the benchmark scenes with the
# default classifier and with one component per class, then the paper's setups and the
# remaining ablations, then every setup's physical labelling (its change detector also
# checked on its own by scripts/check-change-detection.sh).
benchmarks=(ShelfClutter Workbench KitchenCounter)
paper=(MoveableBalls MoveableBricks1 MoveableBricks2 WhiteMoveableBalls WhiteMoveableBricks
  SimKitchen)
file_of() {
  if [ -f "sim_backend/scenes/benchmark/$1.json" ]; then
    echo "sim_backend/scenes/benchmark/$1.json"
  else
    echo "sim_backend/scenes/$1.json"
  fi
}
for scene in "${benchmarks[@]}"; do
  run "$scene" --scene "$(file_of "$scene")" --mode oracle --iterations 200
  run "$scene-alpha1" --scene "$(file_of "$scene")" --mode oracle --alpha 1 --iterations 200
done
for scene in "${paper[@]}"; do
  run "$scene" --scene "$(file_of "$scene")" --mode oracle --iterations 200
  run "$scene-alpha1" --scene "$(file_of "$scene")" --mode oracle --alpha 1 --iterations 200
done
for scene in "${paper[@]}" "${benchmarks[@]}"; do
  run "$scene-paper2018" --scene "$(file_of "$scene")" --mode oracle --variant paper2018 \
    --iterations 200
  run "$scene-random" --scene "$(file_of "$scene")" --mode oracle --sampling random \
    --iterations 200
done
for scene in "${paper[@]}" "${benchmarks[@]}"; do
  run "$scene-physical" --scene "$(file_of "$scene")" --mode physical --iterations 100
done
# A push labels what moved with the target (docs/method.md §4.5): oracle mode posts the
# target's true body, physical mode learns what the change detector saw move.
for scene in "${benchmarks[@]}" "${paper[@]}"; do
  run "$scene-object" --scene "$(file_of "$scene")" --mode oracle --labels object \
    --iterations 200
  run "$scene-physical-object" --scene "$(file_of "$scene")" --mode physical --labels object \
    --iterations 100
done
# A push labels the rest of its object only when it moved it (docs/method.md §4.5): what a
# camera sees; or that and the few supervoxels of a still body nearest the target; the
# exploration ablations with the same labels, for a paired comparison.
for scene in "${benchmarks[@]}" "${paper[@]}"; do
  run "$scene-moved" --scene "$(file_of "$scene")" --mode oracle --labels moved --iterations 200
  run "$scene-near" --scene "$(file_of "$scene")" --mode oracle --labels near --iterations 200
done
for scene in "${benchmarks[@]}"; do
  run "$scene-random-moved" --scene "$(file_of "$scene")" --mode oracle --labels moved \
    --sampling random --iterations 200
  run "$scene-paper2018-moved" --scene "$(file_of "$scene")" --mode oracle --labels moved \
    --variant paper2018 --iterations 200
  run "$scene-physical-moved" --scene "$(file_of "$scene")" --mode physical --labels moved \
    --iterations 200
done
# The class-balanced choice rule (docs/method.md §4.4), alone and with object labels.
for scene in "${benchmarks[@]}" "${paper[@]}"; do
  run "$scene-balanced" --scene "$(file_of "$scene")" --mode oracle --class-balanced on \
    --iterations 200
  run "$scene-balanced-object" --scene "$(file_of "$scene")" --mode oracle --class-balanced on \
    --labels object --iterations 200
done
/usr/bin/env python3 scripts/results-sim-table.py "$keep"
