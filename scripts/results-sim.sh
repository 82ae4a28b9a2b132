#!/usr/bin/env bash
# The paper's simulated experiments (docs/results.md): each setup in oracle mode
# with the default classifier, 10 replications, then the ablations side by side
# (corrected_v1, one component per class, paper2018, random sampling, physical
# labelling). Needs the build (scripts/configure-build.sh). Results go to
# out/results/<experiment>/ (summary.json, replication-<r>.csv, plots); an
# experiment whose summary.json exists is skipped, so a run can be resumed.
# Then scripts/results-sim-table.py prints the tables of docs/results.md.
set -euo pipefail
cd "$(dirname "$0")/.."
sim=build/sim_backend/relmap-sim
out=${OUT:-out/results}
reps=${REPLICATIONS:-10}

run() {  # run <experiment> <relmap-sim run flags...>
  local name=$1
  shift
  if [ -f "$out/$name/summary.json" ]; then
    echo "== $name: done already"
    return
  fi
  echo "== $name: $sim run $* --replications $reps --seed 1 --parallel 2 --out $out/$name"
  "$sim" run "$@" --replications "$reps" --seed 1 --parallel 2 --out "$out/$name"
}

# The headline comparison first: the setup where one Gaussian per class used to
# win, with the default and with corrected_v1 side by side.
run MoveableBalls --scene MoveableBalls --mode oracle --variant corrected --iterations 200
run WhiteMoveableBricks-400 --scene WhiteMoveableBricks --mode oracle --variant corrected --iterations 400
run WhiteMoveableBricks-400-corrected_v1 --scene WhiteMoveableBricks --mode oracle --variant corrected_v1 --iterations 400
run SimKitchen --scene SimKitchen --mode oracle --variant corrected --iterations 200
run WhiteMoveableBricks-400-alpha1 --scene WhiteMoveableBricks --mode oracle --variant corrected --alpha 1 --iterations 400
for scene in MoveableBricks1 MoveableBricks2 WhiteMoveableBalls; do
  run "$scene" --scene "$scene" --mode oracle --variant corrected --iterations 200
done
run MoveableBricks1-corrected_v1 --scene MoveableBricks1 --mode oracle --variant corrected_v1 --iterations 200
run MoveableBricks1-paper2018 --scene MoveableBricks1 --mode oracle --variant paper2018 --iterations 200
run MoveableBricks1-random --scene MoveableBricks1 --mode oracle --variant corrected --sampling random --iterations 200
run MoveableBalls-physical --scene MoveableBalls --mode physical --variant corrected --iterations 100
run WhiteMoveableBricks-1000 --scene WhiteMoveableBricks --mode oracle --variant corrected --iterations 1000
