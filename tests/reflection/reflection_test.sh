#!/usr/bin/env bash
# relmap-server through generic gRPC tooling only: scripts/grpcurl-lite, which learns
# the API from server reflection, lists and describes the services and runs
# create → maps → outcome with JSON, then two calls that must fail with their status.
# usage: reflection_test.sh <relmap-server binary> <PCD cloud>
set -euo pipefail
server_binary=$1
cloud=$2
# shellcheck source=harness.sh
source "$(dirname "$0")/harness.sh"
[ -f "$cloud" ] || fail "no cloud at $cloud"

# json_field <dotted.path>: that value of the JSON on stdin, or "" where the JSON has
# none (grpcurl leaves out fields at their default value).
json_field() {
  /usr/bin/python3 -c '
import json, sys
value = json.load(sys.stdin)
for key in sys.argv[1].split("."):
    value = value.get(key, "") if isinstance(value, dict) else ""
print(value)' "$1"
}

# expect_equal <what> <expected> <actual>
expect_equal() {
  [ "$3" = "$2" ] || fail "$1: expected '$2', got '$3'"
  echo "ok   $1"
}

# expect_status <what> <Code> <number> <grpcurl arguments...>: the call fails with that
# status, printed as grpcurl prints it, and exits with 64 + the code's number.
expect_status() {
  local what=$1 code=$2 number=$3
  shift 3
  local stderr exit_status=0
  stderr=$(grpcurl "$@" 2>&1 >/dev/null) || exit_status=$?
  [ "$exit_status" = $((64 + number)) ] ||
    fail "$what: exit status $exit_status, not $((64 + number)) (64 + $code); stderr: $stderr"
  grep -qx "  Code: $code" <<<"$stderr" ||
    fail "$what: expected 'Code: $code' on stderr, got: $stderr"
  echo "ok   $what"
}

start_server "$server_binary"
service=relmap.v1.RelevanceService

services=$(grpcurl -plaintext "$ADDR" list)
for expected in relmap.v1.RelevanceService grpc.health.v1.Health \
  grpc.reflection.v1alpha.ServerReflection; do
  grep -qx "$expected" <<<"$services" || fail "list: $expected missing from: $services"
done
echo "ok   list"

description=$(grpcurl -plaintext "$ADDR" describe $service)
expect_equal "describe: kind" "$service is a service:" "$(head -n 1 <<<"$description")"
compute_maps="  rpc ComputeMaps ( .relmap.v1.ComputeMapsRequest )"
compute_maps+=" returns ( .relmap.v1.ComputeMapsResponse );"
grep -qxF "$compute_maps" <<<"$description" || fail "describe: no ComputeMaps in: $description"
expect_equal "describe: 10 methods" 10 "$(grep -c '^  rpc ' <<<"$description")"

# gRPC C++ does not register its health service's descriptors with reflection
# (grpc/grpc#36665); relmap-server links them (proto/grpc/health/v1/health.proto), so a
# reflection-only client can describe and call it.
grpcurl -plaintext "$ADDR" describe grpc.health.v1.Health | grep -qF 'rpc Check (' ||
  fail "describe grpc.health.v1.Health: no Check"
health=$(grpcurl -plaintext "$ADDR" grpc.health.v1.Health/Check)
expect_equal "health: SERVING" '"status": "SERVING"' "$(grep -F status <<<"$health" | sed 's/^ *//')"

created=$(grpcurl -plaintext -d '{"config": {"seed": "3"}}' "$ADDR" $service/CreateSession)
session=$(json_field sessionId <<<"$created")
token=$(json_field sessionToken <<<"$created")
if [ -z "$session" ] || [ -z "$token" ]; then
  fail "CreateSession: no sessionId or sessionToken in: $created"
fi
expect_equal "CreateSession: the configuration comes back" 3 \
  "$(json_field config.seed <<<"$created")"
auth="authorization: Bearer $token"

# Bytes fields are base64 in JSON; the request goes on stdin, too large for argv.
maps=$(printf '{"sessionId": "%s", "cloud": {"pcd": "%s"}}' "$session" \
  "$(base64 -w0 "$cloud")" | grpcurl -plaintext -H "$auth" -d @ "$ADDR" $service/ComputeMaps)
frame=$(json_field frameId <<<"$maps")
expect_equal "ComputeMaps: first frame" 1 "$frame"
counts=$(/usr/bin/python3 -c '
import json, sys
maps = json.load(sys.stdin)
print(len(maps["supervoxels"]) > 0, len(maps["pointLabels"]))' <<<"$maps")
expect_equal "ComputeMaps: supervoxels, and a label per point of the 640×480 cloud" \
  "True 307200" "$counts"
target=$(json_field targetSupervoxelId <<<"$maps")
target=${target:-0} # absent means supervoxel 0

outcome=$(grpcurl -plaintext -H "$auth" -d @ "$ADDR" $service/PostOutcome <<EOF
{"sessionId": "$session", "frameId": "$frame", "supervoxelId": $target,
 "label": "LABEL_MOVEABLE", "requestId": "push-1"}
EOF
)
expect_equal "PostOutcome: label" LABEL_MOVEABLE "$(json_field label <<<"$outcome")"

session_json="{\"sessionId\": \"$session\"}"
stats=$(grpcurl -plaintext -H "$auth" -d "$session_json" "$ADDR" $service/GetSession)
expect_equal "GetSession: 1 moveable sample" 1 "$(json_field stats.moveableSamples <<<"$stats")"
expect_equal "GetSession: no non-moveable sample" "" \
  "$(json_field stats.nonMoveableSamples <<<"$stats")"

# grpcurl's other spellings and its usage errors.
dotted=$(grpcurl -plaintext -H "$auth" -d "$session_json" "$ADDR" $service.GetSession)
expect_equal "Service.Method spelling" "$session" "$(json_field sessionId <<<"$dotted")"
usage_exit=0
grpcurl "$ADDR" list 2>/dev/null || usage_exit=$?
expect_equal "no -plaintext: a usage error (exit 2)" 2 "$usage_exit"

expect_status "wrong token → PermissionDenied" PermissionDenied 7 -plaintext \
  -H "authorization: Bearer not-the-token" -d "$session_json" "$ADDR" $service/GetSession
unknown_frame="{\"sessionId\": \"$session\", \"frameId\": \"99\", \"label\": \"LABEL_MOVEABLE\"}"
expect_status "unknown frame → FailedPrecondition" FailedPrecondition 9 -plaintext \
  -H "$auth" -d "$unknown_frame" "$ADDR" $service/PostOutcome

# The reason a client acts on, in the status's details: a google.rpc.ErrorInfo, whose
# type the server's reflection serves, printed as grpcurl prints details. An error no
# client acts on has none.
frame_gone=$(grpcurl -plaintext -H "$auth" -d "$unknown_frame" "$ADDR" $service/PostOutcome \
  2>&1 >/dev/null) || true
for expected in '  Details:' '"@type": "type.googleapis.com/google.rpc.ErrorInfo",' \
  '"reason": "FRAME_GONE",' '"domain": "relmap.v1",' '"frameId": "99",'; do
  grep -qF -- "$expected" <<<"$frame_gone" || fail "unknown frame: no '$expected' in: $frame_gone"
done
echo "ok   unknown frame → reason FRAME_GONE in the details"
wrong_token=$(grpcurl -plaintext -H "authorization: Bearer not-the-token" -d "$session_json" \
  "$ADDR" $service/GetSession 2>&1 >/dev/null) || true
if grep -qF 'Details:' <<<"$wrong_token"; then fail "wrong token: details in: $wrong_token"; fi
echo "ok   wrong token → no details"
echo "grpc_reflection: all checks passed"
