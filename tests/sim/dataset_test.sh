#!/usr/bin/env bash
# relmap-sim dataset end to end: two frames of MoveableBalls, twice. The same seed
# gives the same bytes; relmap-cmm reads the file as it is; both classes are there;
# every row has 48 features in [0, 1]; the frames file has a frame per row.
set -u
sim=$1
cmm=$2
server=$3
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
failures=0
check() {  # check <name> <condition command...>
  local name=$1
  shift
  if "$@"; then echo "ok   $name"; else echo "FAIL $name"; failures=$((failures + 1)); fi
}

for run in a b; do
  "$sim" dataset --scene MoveableBalls --frames 2 --seed 1 --server-binary "$server" \
    --out "$dir/$run.csv" 2>"$dir/$run.log"
  check "exit-0-$run" test $? = 0
done
cat "$dir/a.log"
check same-bytes cmp "$dir/a.csv" "$dir/b.csv"
check same-frames cmp "$dir/a.csv.frames" "$dir/b.csv.frames"
"$cmm" --train "$dir/a.csv" >"$dir/cmm.json"
check relmap-cmm-reads-it test $? = 0
check relmap-cmm-48-d grep -q '"dimension":48' "$dir/cmm.json"
check header test "$(head -1 "$dir/a.csv" | cut -d, -f1,2,49)" = "label,f1,f48"
rows=$(($(wc -l <"$dir/a.csv") - 1))
check some-rows test "$rows" -gt 10
check both-classes test "$(tail -n +2 "$dir/a.csv" | cut -d, -f1 | sort -u | tr -d '\n')" = 01
check 48-features-in-0-1 awk -F, 'NR > 1 && (NF != 49 || $1 !~ /^[01]$/) { exit 1 }
  NR > 1 { for (k = 2; k <= NF; ++k) if ($k + 0 < 0 || $k + 0 > 1) exit 1 }' "$dir/a.csv"
check frame-per-row test "$(($(wc -l <"$dir/a.csv.frames") - 1))" = "$rows"
check frames-1-and-2 test "$(tail -n +2 "$dir/a.csv.frames" | cut -d, -f1 | sort -u | tr '\n' ' ')" = "1 2 "
check frames-header test "$(head -1 "$dir/a.csv.frames")" = "frame,body,object"
# The server's objects group rows: fewer objects than rows in a frame, more than one.
check objects-group-rows awk -F, 'NR > 1 && $1 == 1 { rows++; seen[$3] = 1 }
  END { n = length(seen); exit !(n > 1 && n < rows) }' "$dir/a.csv.frames"
# Every moveable row shows a body (the object it is part of).
check moveable-rows-have-a-body test "$(paste -d, <(tail -n +2 "$dir/a.csv" | cut -d, -f1) \
  <(tail -n +2 "$dir/a.csv.frames") | awk -F, '$1 == 1 && $3 < 0' | wc -l)" = 0
check bad-flag-exit-2 test "$("$sim" dataset --scene MoveableBalls --out "$dir/c.csv" \
  --frames 0 >/dev/null 2>&1; echo $?)" = 2
exit $((failures > 0))
