#!/usr/bin/env bash
# The relmap CLI against a real server: every command, the renderings, the exit codes
# (0 answer, 1 server error, 2 bad arguments), idempotent outcomes and streams.
set -u
server=$1
cli=$2
cloud=$3
dir=$(mktemp -d)
"$server" --listen 127.0.0.1:0 --port-file "$dir/port" --frames-per-session 2 2>"$dir/server.log" &
server_pid=$!
trap 'kill $server_pid 2>/dev/null; wait $server_pid 2>/dev/null; rm -rf "$dir"' EXIT
for _ in $(seq 100); do [ -s "$dir/port" ] && break; sleep 0.05; done
export RELMAP_SERVER=127.0.0.1:$(cat "$dir/port")
failures=0
check() {  # check <name> <condition command...>
  local name=$1
  shift
  if "$@"; then echo "ok   $name"; else echo "FAIL $name"; failures=$((failures + 1)); fi
}
field() {  # field <name> <json>: a top-level string or number field
  sed -E "s/.*\"$1\":\"?([^\",}]*).*/\1/" <<<"$2"
}
exit_code() { "$@" >/dev/null 2>&1; echo $?; }

# Feature sessions: create, show, stream (twice: the second adds nothing), export/import.
created=$("$cli" session create --seed 3 --feature-dimension 2)
check create grep -q '"sessionToken":"' <<<"$created"
session=$(field sessionId "$created")
export RELMAP_TOKEN=$(field sessionToken "$created")
check show grep -q '"featureDimension":2' <<<"$("$cli" session show "$session")"
check list grep -q "$session" <<<"$("$cli" session list)"
check wrong-token-exit-1 test "$(exit_code "$cli" session show "$session" --token nope)" = 1
check wrong-token-message grep -q 'wrong token' <<<"$("$cli" session show "$session" --token nope 2>&1)"
check unknown-flag-exit-2 test "$(exit_code "$cli" session show "$session" --colour red)" = 2
check missing-session-exit-2 test "$(exit_code "$cli" session show)" = 2
paper=$("$cli" session create --colour paper2018 --fpfh raw_points --fpfh-radius 0.04)
check features-colour grep -q '"colour":"COLOUR_VARIANT_PAPER2018"' <<<"$paper"
check features-fpfh grep -q '"fpfhScheme":"FPFH_SCHEME_RAW_POINTS"' <<<"$paper"
check features-radius grep -q '"fpfhRadius":0.04' <<<"$paper"
check unknown-fpfh-exit-2 test "$(exit_code "$cli" session create --fpfh fast)" = 2
check unspecified-colour-exit-2 test "$(exit_code "$cli" session create --colour unspecified)" = 2

{
  echo "label,f1,f2"
  for i in $(seq 0 249); do echo "$((i % 2)),$((i % 2)).$((i % 7)),$((i % 5)).25"; done
} >"$dir/samples.csv"
"$cli" stream "$session" "$dir/samples.csv" --batch 100 >"$dir/stream.json" 2>"$dir/progress.txt"
check stream grep -q '"moveableSamples":"125"' "$dir/stream.json"
check stream-progress grep -q '100% 250/250 samples' "$dir/progress.txt"
check stream-again-adds-nothing grep -q '"moveableSamples":"125"' <<<"$("$cli" stream "$session" "$dir/samples.csv" --batch 100 2>/dev/null)"
printf '1,0.5,0.5\n0,0.5\n' >"$dir/ragged.csv"
check stream-bad-csv-exit-2 test "$(exit_code "$cli" stream "$session" "$dir/ragged.csv")" = 2

check export grep -q '"nonMoveableSamples":"125"' <<<"$("$cli" session export "$session" --out "$dir/state.json")"
imported=$("$cli" session import "$dir/state.json")
check import grep -q '"moveableSamples":"125"' <<<"$imported"
check import-binary grep -q '"moveableSamples":"125"' <<<"$("$cli" session export "$session" --out "$dir/state.pb" >/dev/null && "$cli" session import "$dir/state.pb")"
check wrong-dimension-exit-1 test "$(exit_code "$cli" stream "$session" <(echo 1,0.5,0.5,0.5))" = 1
check maps-on-feature-session-exit-1 test "$(exit_code "$cli" maps "$session" "$cloud")" = 1

# Cloud sessions: maps with renderings, outcomes, idempotence, the after cloud, stale frames.
created=$("$cli" session create --seed 3)
session=$(field sessionId "$created")
export RELMAP_TOKEN=$(field sessionToken "$created")
maps=$("$cli" maps "$session" "$cloud" --png "$dir/relevance.png" --choice-png "$dir/choice.png" --pcd "$dir/coloured.pcd")
check maps grep -q '"frameId":"1"' <<<"$maps"
check maps-without-point-labels grep -q '"pointLabels":\[\]' <<<"$maps"
check relevance-png test "$(head -c 4 "$dir/relevance.png" | tail -c 3)" = PNG
check choice-png test "$(head -c 4 "$dir/choice.png" | tail -c 3)" = PNG
check coloured-pcd grep -aq '^FIELDS x y z rgb$' "$dir/coloured.pcd"
check coloured-pcd-is-a-cloud grep -q '"frameId":"2"' <<<"$("$cli" maps "$session" "$dir/coloured.pcd")"
target=$(field targetSupervoxelId "$maps")
check outcome grep -q '"moveableSamples":"1"' <<<"$("$cli" outcome "$session" 1 "$target" moved --request-id r1)"
check outcome-repeat grep -q '"moveableSamples":"1"' <<<"$("$cli" outcome "$session" 1 "$target" moved --request-id r1)"
check outcome-still grep -q '"nonMoveableSamples":"1"' <<<"$("$cli" outcome "$session" 1 "$target" still)"
check after-cloud-unchanged grep -q '"label":"LABEL_NOT_MOVEABLE"' <<<"$("$cli" outcome "$session" 1 "$target" --after-cloud "$cloud" --request-id r2)"
check stale-frame-exit-1 test "$(exit_code "$cli" outcome "$session" 99 0 moved)" = 1
check stale-frame-message grep -q 'code 9' <<<"$("$cli" outcome "$session" 99 0 moved 2>&1)"
check stale-frame-reason grep -q 'code 9, reason FRAME_GONE)' <<<"$("$cli" outcome "$session" 99 0 moved 2>&1)"
"$cli" maps "$session" "$cloud" >/dev/null && "$cli" maps "$session" "$cloud" >/dev/null
check evicted-frame grep -q 'keeps the last 2 frames' <<<"$("$cli" outcome "$session" 1 "$target" moved 2>&1)"
check bad-outcome-exit-2 test "$(exit_code "$cli" outcome "$session" 1 "$target" maybe)" = 2

check delete test "$(exit_code "$cli" session delete "$session")" = 0
check deleted grep -q 'code 5' <<<"$("$cli" session show "$session" 2>&1)"
check log-has-session grep -q "rpc=GetSession session=$session" "$dir/server.log"
exit $((failures > 0))
