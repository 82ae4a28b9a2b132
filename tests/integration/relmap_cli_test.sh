#!/usr/bin/env bash
# The relmap CLI against a real server: create, maps (if the real clouds are
# present), post, idempotent repost, get, wrong token, delete.
set -u
server=$1
cli=$2
cloud=$3
dir=$(mktemp -d)
"$server" --listen 127.0.0.1:0 --port-file "$dir/port" 2>"$dir/server.log" &
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

created=$("$cli" create --seed 3 --feature-dimension 2)
check create grep -q '"sessionToken":"' <<<"$created"
export RELMAP_SESSION=$(sed -E 's/.*"sessionId":"([^"]*)".*/\1/' <<<"$created")
export RELMAP_TOKEN=$(sed -E 's/.*"sessionToken":"([^"]*)".*/\1/' <<<"$created")
check get grep -q '"featureDimension":2' <<<"$("$cli" get)"
check wrong-token test "$("$cli" get --token nope 2>&1 >/dev/null | grep -c 'wrong token')" = 1
"$cli" get --token nope >/dev/null 2>&1
check wrong-token-exit test $? = 1
check maps-on-feature-session test "$("$cli" maps --cloud /dev/null 2>&1 | grep -c 'code 9\|code 3')" = 1
check bad-label test "$("$cli" post --frame 1 --supervoxel 0 --label maybe 2>&1 | grep -c 'moveable or not-moveable')" = 1
check list grep -q "$RELMAP_SESSION" <<<"$("$cli" list)"

if [ -f "$cloud" ]; then
  created=$("$cli" create --seed 3)
  export RELMAP_SESSION=$(sed -E 's/.*"sessionId":"([^"]*)".*/\1/' <<<"$created")
  export RELMAP_TOKEN=$(sed -E 's/.*"sessionToken":"([^"]*)".*/\1/' <<<"$created")
  maps=$("$cli" maps --cloud "$cloud")
  check maps grep -q '"frameId":"1"' <<<"$maps"
  target=$(sed -E 's/.*"targetSupervoxelId":([0-9]+).*/\1/' <<<"$maps")
  check post grep -q '"moveableSamples":"1"' <<<"$("$cli" post --frame 1 --supervoxel "$target" --label moveable --request-id r1)"
  check repost grep -q '"moveableSamples":"1"' <<<"$("$cli" post --frame 1 --supervoxel "$target" --label moveable --request-id r1)"
  check after-cloud-unchanged grep -q '"label":"LABEL_NOT_MOVEABLE"' <<<"$("$cli" post --frame 1 --supervoxel "$target" --after-cloud "$cloud" --request-id r2)"
  check stale-frame test "$("$cli" post --frame 99 --supervoxel 0 --label moveable 2>&1 | grep -c 'code 9')" = 1
else
  echo "skip maps/post: $cloud not found"
fi
"$cli" delete >/dev/null
check delete test $? = 0
check deleted test "$("$cli" get 2>&1 | grep -c 'code 5')" = 1
check log-has-session grep -q "rpc=GetSession session=$RELMAP_SESSION" "$dir/server.log"
exit $((failures > 0))
