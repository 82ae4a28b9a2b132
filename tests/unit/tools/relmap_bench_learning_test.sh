#!/usr/bin/env bash
# relmap-bench-learning end to end on two tiny streams: the table, CSV and JSON
# are written and parse, every balanced accuracy lies in [0, 1], an external
# stream and an unknown learner are handled.
set -u
bench=$1
dataset=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL $*"; exit 1; }

"$dataset" --problem moons --samples 60 --dimension 3 --seed 1 >"$dir/train.csv"
"$dataset" --problem moons --samples 100 --dimension 3 --seed 2 >"$dir/test.csv"
"$bench" --streams xor2d --stream "ext=$dir/train.csv:$dir/test.csv" \
  --learners corrected,no_such_learner,gnb,sgd,knn --train-samples 60 --test-samples 100 \
  --curve 20 --replications 1 --seed 3 --out "$dir/out" >"$dir/stdout" 2>"$dir/stderr" ||
  fail "exit $?: $(cat "$dir/stderr")"
grep -q "skipping learner 'no_such_learner'" "$dir/stderr" || fail "no warning for the unknown learner"
grep -q '^best on ext: ' "$dir/stdout" || fail "no best line: $(cat "$dir/stdout")"
for f in table.csv table.json curves.csv curves/xor2d.png curves/ext.png streams/xor2d.r0.train.csv; do
  [ -s "$dir/out/$f" ] || fail "missing $f"
done
# Any python3 can check the files: the standard library's csv and json suffice.
python3 - "$dir/out" <<'PY' || fail "the CSV or JSON does not check out"
import csv, json, sys
out = sys.argv[1]
rows = list(csv.DictReader(open(f"{out}/table.csv")))
report = json.load(open(f"{out}/table.json"))
assert len(rows) == 8 == len(report["rows"]), (len(rows), len(report["rows"]))
for r in rows:
    assert 0.0 <= float(r["balanced_accuracy_mean"]) <= 1.0, r
for r in report["rows"]:
    assert 0.0 <= r["balanced_accuracy"]["mean"] <= 1.0, r
assert set(report["best"]) == {"xor2d", "ext"}
assert report["curves"][0]["samples"] == [20, 40, 60]
PY
# --flip: a flipped copy of the stream after it, exactly round(0.2 × 60) = 12 of its
# training labels flipped, the same ones on a second run.
for run in a b; do
  "$bench" --stream "ext=$dir/train.csv:$dir/test.csv" --flip 0.2 --learners gnb --seed 3 \
    --out "$dir/flip-$run" >"$dir/flip-$run.txt" 2>&1 || fail "--flip exit $?: $(cat "$dir/flip-$run.txt")"
done
grep -q '^best on ext-flip20: ' "$dir/flip-a.txt" || fail "no ext-flip20 row: $(cat "$dir/flip-a.txt")"
flips=$(paste -d' ' <(cut -d, -f1 "$dir/flip-a/streams/ext.r0.train.csv") \
  <(cut -d, -f1 "$dir/flip-a/streams/ext-flip20.r0.train.csv") | awk '$1 != $2' | wc -l)
[ "$flips" -eq 12 ] || fail "--flip 0.2 flipped $flips of 60 labels, not 12"
cmp -s "$dir/flip-a/streams/ext-flip20.r0.train.csv" "$dir/flip-b/streams/ext-flip20.r0.train.csv" ||
  fail "--flip is not reproducible"
cmp -s "$dir/flip-a/streams/ext.r0.test.csv" "$dir/flip-a/streams/ext-flip20.r0.test.csv" ||
  fail "--flip changed the test set"
"$bench" --flip 0.2 >/dev/null 2>&1
[ $? -eq 2 ] || fail "--flip without --stream should exit 2"
"$bench" --streams nowhere >/dev/null 2>&1
[ $? -eq 2 ] || fail "an unknown stream should exit 2"
echo "ok   relmap-bench-learning"
