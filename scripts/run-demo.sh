#!/usr/bin/env bash
# The main job: builds everything, then
#  1. streams a seeded 48-d non-convex problem (XOR blobs) through relmap-cmm
#     for each classifier configuration, prints the learning curves and plots
#     them to out/demo/learning_curves.png;
#  2. lets the choice map pick the samples (--active) and compares;
#  3. segments a real Kinect cloud (or a synthetic one) with relmap-perception
#     and renders the supervoxels to PNG;
#  4. starts relmap-server on a loopback port and, through the relmap CLI, asks
#     for the maps of the real cloud (PNG renderings), posts the outcome of the
#     drawn push as the after-push cloud (the change detector labels it), and
#     streams the XOR training set into a feature session with a progress bar;
#  5. runs the simulator (relmap-sim, which starts its own relmap-server) on the
#     paper's MoveableBalls scene: 100 oracle push iterations, 2 replications, with
#     a progress bar; maps and learning curves as PNGs in out/demo/sim/.
# Everything lands in out/demo/.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/configure-build.sh
out=out/demo
mkdir -p "$out"
tools=build/server/tools
seed=${SEED:-1}

"$tools/relmap-dataset" --problem xor --dimension 48 --samples 1000 --seed "$seed" >"$out/train.csv"
"$tools/relmap-dataset" --problem xor --dimension 48 --samples 2000 --seed $((seed + 1000)) >"$out/test.csv"

# Prints one row per point of a report's learning curve.
curve() {
  sed 's/.*"curve":\[//; s/\]}$//; s/},{/}\n{/g' "$1" |
    sed -E 's/.*"samples":([0-9]+),"components":\[([0-9]+),([0-9]+)\],"soft_accuracy":([^,]+),"thresholded_accuracy":([^,]+),"accuracy_at_0_5":([^}]+)}?/    \1 samples  \2+\3 components  soft accuracy \4  thresholded-soft \5  at 0.5: \6/'
}

run() {  # run <name> <relmap-cmm flags...>
  local name=$1
  shift
  "$tools/relmap-cmm" --train "$out/train.csv" --test "$out/test.csv" --curve 100 --seed "$seed" \
    --curve-csv "$out/$name-curve.csv" "$@" >"$out/$name.json"
  echo "== $name ($*)"
  curve "$out/$name.json"
}

echo "relmap-cmm on a 48-d XOR-blobs stream (1000 training, 2000 test samples, seed $seed)"
run corrected --variant corrected
run corrected_v1 --variant corrected_v1
run corrected_v1-lambda-1e-3 --variant corrected_v1 --regularization 1e-3
run paper2018 --variant paper2018
run one-component-per-class --variant corrected --alpha 1
run corrected-active --variant corrected --active --budget 400
"$tools/relmap-plot" --out "$out/learning_curves.png" --x samples --y accuracy_at_0_5 \
  --title "48-d XOR blobs: test accuracy (seed $seed)" --x-label "training samples" \
  --y-label "accuracy at 0.5" --y-min 0.4 --y-max 1 \
  "corrected=$out/corrected-curve.csv" "corrected_v1=$out/corrected_v1-curve.csv" \
  "corrected_v1 lambda 1e-3=$out/corrected_v1-lambda-1e-3-curve.csv" \
  "paper2018=$out/paper2018-curve.csv" "one per class=$out/one-component-per-class-curve.csv" \
  "corrected active=$out/corrected-active-curve.csv"
echo "learning curves: $out/learning_curves.png"

cloud=../shared/data/real/table_scene_mug_stereo_textured.pcd
[ -f "$cloud" ] || cloud=synthetic:640x480
echo "== relmap-perception on $cloud"
build/server/perception/tools/relmap-perception "$cloud" --repeat 1 --png "$out/segmentation.png" | tee "$out/perception.json"
echo "== relmap-server and the relmap CLI"
server_dir=$(mktemp -d)
build/server/relmap-server --listen 127.0.0.1:0 --port-file "$server_dir/port" \
  --data-dir "$server_dir/data" 2>"$out/server.log" &
server_pid=$!
trap 'kill $server_pid 2>/dev/null; wait $server_pid 2>/dev/null; rm -rf "$server_dir"' EXIT
for _ in $(seq 200); do [ -s "$server_dir/port" ] && break; sleep 0.05; done
export RELMAP_SERVER=127.0.0.1:$(cat "$server_dir/port")
relmap=build/client/relmap
json_field() { /usr/bin/python3 -c "import json,sys; print(json.load(sys.stdin)['$1'])"; }

created=$("$relmap" session create --seed "$seed")
session=$(json_field sessionId <<<"$created")
export RELMAP_TOKEN=$(json_field sessionToken <<<"$created")
if [ "${cloud#synthetic:}" = "$cloud" ]; then
  "$relmap" maps "$session" "$cloud" --png "$out/relevance.png" --choice-png "$out/choice.png" \
    --pcd "$out/relevance.pcd" >"$out/maps.json"
  frame=$(json_field frameId <"$out/maps.json")
  target=$(json_field targetSupervoxelId <"$out/maps.json")
  echo "maps of frame $frame: $(grep -o '"id":' "$out/maps.json" | wc -l) supervoxels, target $target"
  echo "outcome from the after-push cloud (the same scene: nothing moved):"
  "$relmap" outcome "$session" "$frame" "$target" --after-cloud "$cloud" | tee "$out/outcome.json"
fi
features=$("$relmap" session create --seed "$seed" --feature-dimension 48 --variant corrected)
export RELMAP_TOKEN=$(json_field sessionToken <<<"$features")
"$relmap" stream "$(json_field sessionId <<<"$features")" "$out/train.csv" --batch 100 | tee "$out/stream.json"
echo "== relmap-sim: MoveableBalls, oracle mode (the paper's simplified setup)"
build/sim_backend/relmap-sim run --scene MoveableBalls --mode oracle --iterations "${ITERATIONS:-100}" \
  --replications 2 --seed "$seed" --out "$out/sim"
# What learning does to a map: the first replication's relevance map at its first push (a
# session that has learned nothing maps every supervoxel 0.5) and at its last.
cp "$out/sim/relevance-0-1.png" "$out/relevance-before-learning.png"
cp "$out/sim/relevance-0-${ITERATIONS:-100}.png" "$out/relevance-after-learning.png"
echo "a session's relevance map before and after learning: $out/relevance-before-learning.png," \
  "$out/relevance-after-learning.png"
echo "reports, learning curves, segmentation.png, relevance.png and choice.png are in $out/;"
echo "the simulated run's maps (relevance-*.png, choice-*.png) and curves (accuracy.png, ...) in $out/sim/"
