#!/usr/bin/env bash
# relmap-cmm as a user runs it: exit codes, error messages, and the JSON report.
set -u
cmm=$1
dataset=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
failures=0
expect() {  # expect <name> <wanted exit code> <wanted text in output> <command...>
  local name=$1 code=$2 text=$3
  shift 3
  local out
  out=$("$@" 2>&1)
  local got=$?
  if [ "$got" -ne "$code" ] || ! grep -qF -- "$text" <<<"$out"; then
    echo "FAIL $name: exit $got (wanted $code), output: $out"
    failures=$((failures + 1))
  else
    echo "ok   $name"
  fi
}

printf '1,0.5,2\n0,1\n' >"$dir/ragged.csv"
printf '1,0.5\n0,abc\n' >"$dir/text.csv"
printf '1,0.5\n3,1\n' >"$dir/label.csv"
printf '' >"$dir/empty.csv"
printf '1,0.5\n0,1\n' >"$dir/one-feature.csv"
"$dataset" --problem moons --samples 300 --dimension 3 --seed 1 >"$dir/train.csv"
"$dataset" --problem moons --samples 200 --dimension 3 --seed 2 >"$dir/test.csv"

expect ragged 2 "ragged.csv:2: row has 1 features" "$cmm" --train "$dir/ragged.csv"
expect non-numeric 2 "text.csv:2: field 2 'abc' is not a number" "$cmm" --train "$dir/text.csv"
expect label 2 "label.csv:2: label '3' is not 0 or 1" "$cmm" --train "$dir/label.csv"
expect empty 2 "empty.csv: no data row" "$cmm" --train "$dir/empty.csv"
expect missing 2 "cannot open" "$cmm" --train "$dir/none.csv"
expect no-train 2 "--train is required" "$cmm"
expect bad-alpha 2 "alpha must lie in [0, 1]" "$cmm" --train "$dir/train.csv" --alpha 3
expect bad-variant 2 "unknown classifier variant" "$cmm" --train "$dir/train.csv" --variant x
expect dimension-mismatch 2 "one-feature.csv has 1 features per row" "$cmm" --train "$dir/train.csv" --test "$dir/one-feature.csv"
expect online 0 '"mode":"online"' "$cmm" --train "$dir/train.csv" --test "$dir/test.csv" --curve 100
expect test-scores 0 '"balanced_accuracy":0.' "$cmm" --train "$dir/train.csv" --test "$dir/test.csv"
expect test-log-loss 0 '"log_loss":' "$cmm" --train "$dir/train.csv" --test "$dir/test.csv"
expect active 0 '"mode":"active","dimension":3,"samples":[' "$cmm" --train "$dir/train.csv" --active --budget 50 --seed 3
expect paper 0 '"variant":"paper2018"' "$cmm" --train "$dir/train.csv" --variant paper2018
expect curve-csv-needs-test 2 "--curve-csv needs --curve N and --test" "$cmm" --train "$dir/train.csv" --curve-csv "$dir/c.csv"
expect curve-csv 0 '"curve":[{"samples":100' "$cmm" --train "$dir/train.csv" --test "$dir/test.csv" --curve 100 --curve-csv "$dir/curve.csv"
expect curve-csv-rows 0 "300,"  cat "$dir/curve.csv"
expect picks-need-active 2 "--picks-out needs --active" "$cmm" --train "$dir/train.csv" --picks-out "$dir/picks.txt"
"$cmm" --train "$dir/train.csv" --active --budget 50 --seed 3 --picks-out "$dir/picks.txt" >/dev/null
# 50 picks, each a distinct row of the 300.
if [ "$(wc -l <"$dir/picks.txt")" -eq 50 ] && [ "$(sort -u "$dir/picks.txt" | wc -l)" -eq 50 ] &&
  [ "$(sort -n "$dir/picks.txt" | tail -1)" -lt 300 ]; then
  echo "ok   picks-out"
else
  echo "FAIL picks-out: $(tr '\n' ' ' <"$dir/picks.txt")"
  failures=$((failures + 1))
fi

# Frames: rows 0-99 frame 1, 100-199 frame 2, 200-299 frame 3; each frame's rows in
# bodies of 10 (body = row / 10).
{ echo "frame,body"; for i in $(seq 0 299); do echo "$((i / 100 + 1)),$((i / 10))"; done; } >"$dir/train.csv.frames"
expect frames-need-active 2 "--pool-frames needs --active" "$cmm" --train "$dir/train.csv" --pool-frames "$dir/train.csv.frames"
expect moved-needs-frames 2 "--moved-with-target and --object-labels need --pool-frames" "$cmm" --train "$dir/train.csv" --active --moved-with-target
expect exploration-needs-active 2 "--exploration needs --active" "$cmm" --train "$dir/train.csv" --exploration novelty
expect bad-exploration 2 "is not one of paper | balanced | novelty | random" "$cmm" --train "$dir/train.csv" --active --exploration greedy
expect novelty 0 '"mode":"active"' "$cmm" --train "$dir/train.csv" --active --budget 20 --exploration novelty,random=0.1
"$cmm" --train "$dir/train.csv" --active --budget 6 --seed 3 --pool-frames "$dir/train.csv.frames" \
  --picks-out "$dir/frame-picks.txt" >/dev/null
# One frame at a time, in turn: picks 1 and 4 from frame 1, 2 and 5 from frame 2, ...
if [ "$(awk '{ printf "%d", int($1 / 100) + 1 }' "$dir/frame-picks.txt")" = 123123 ]; then
  echo "ok   pool-frames"
else
  echo "FAIL pool-frames: $(tr '\n' ' ' <"$dir/frame-picks.txt")"
  failures=$((failures + 1))
fi
# Bodies as relmap-sim dataset writes them: a moveable row shows body row / 10, a
# background row none (-1).
awk -F, 'NR > 1 { print int((NR - 2) / 100) + 1 "," ($1 == 1 ? int((NR - 2) / 10) : -1) }
  NR == 1 { print "frame,body" }' "$dir/train.csv" >"$dir/bodies.frames"
"$cmm" --train "$dir/train.csv" --active --budget 30 --seed 3 --pool-frames "$dir/bodies.frames" \
  --moved-with-target --picks-out "$dir/body-picks.txt" >/dev/null
# 30 picks; a moveable one brings every other row of its body at once, so each body's
# rows come together and the file has more than 30 distinct rows.
if [ "$(sort -u "$dir/body-picks.txt" | wc -l)" -eq "$(wc -l <"$dir/body-picks.txt")" ] &&
  [ "$(wc -l <"$dir/body-picks.txt")" -gt 30 ] &&
  awk -F, 'NR == FNR { if (FNR > 1) body[FNR - 2] = $2; next }
    { b = body[$1] } b >= 0 && b in done { exit 1 } b != last && last >= 0 { done[last] = 1 }
    { last = b }' "$dir/bodies.frames" "$dir/body-picks.txt"; then
  echo "ok   moved-with-target"
else
  echo "FAIL moved-with-target: $(tr '\n' ' ' <"$dir/body-picks.txt")"
  failures=$((failures + 1))
fi
# --object-labels: every pick, moveable or not, brings the rest of its body (here every
# row is on body row / 10): 30 picks are the 30 bodies, ten rows each, one body at a time.
awk -F, 'NR > 1 { print int((NR - 2) / 100) + 1 "," int((NR - 2) / 10) }
  NR == 1 { print "frame,body" }' "$dir/train.csv" >"$dir/all-bodies.frames"
"$cmm" --train "$dir/train.csv" --active --budget 30 --seed 3 \
  --pool-frames "$dir/all-bodies.frames" --object-labels --picks-out "$dir/object-picks.txt" >/dev/null
if [ "$(sort -u "$dir/object-picks.txt" | wc -l)" -eq 300 ] &&
  awk '{ b = int($1 / 10) } NR % 10 == 1 { first = b } b != first { exit 1 }' "$dir/object-picks.txt"; then
  echo "ok   object-labels"
else
  echo "FAIL object-labels: $(tr '\n' ' ' <"$dir/object-picks.txt")"
  failures=$((failures + 1))
fi

# Same seed, same report (latencies aside).
a=$("$cmm" --train "$dir/train.csv" --test "$dir/test.csv" --active --seed 9 | sed 's/"latency_us".*"curve"/"curve"/')
b=$("$cmm" --train "$dir/train.csv" --test "$dir/test.csv" --active --seed 9 | sed 's/"latency_us".*"curve"/"curve"/')
if [ "$a" = "$b" ]; then echo "ok   reproducible"; else echo "FAIL reproducible"; failures=$((failures + 1)); fi

exit $((failures > 0))
