# shellcheck shell=bash
# What the reflection tests share (sourced, not run): a relmap-server on a free
# loopback port with a temporary data directory, stopped on every exit, and `grpcurl`
# standing for scripts/grpcurl-lite, the generic reflection client.

repo_root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)

# Debian's python, where python3-grpcio and python3-protobuf are installed (a python3
# earlier on PATH, such as pyenv's, would not have them).
grpcurl() { /usr/bin/python3 "$repo_root/scripts/grpcurl-lite" "$@"; }

fail() {
  echo "FAIL $*" >&2
  exit 1
}

# describe_failure <exit status>: what a test adds to the server log when it fails.
describe_failure() { :; }

# start_server <relmap-server binary>: sets ADDR and workdir (removed on exit).
start_server() {
  workdir=$(mktemp -d)
  # The caller's RELMAP_* settings (an admin key, say) would change the server's
  # answers, so the server starts without them.
  local -a clean_env=(env)
  local name
  for name in $(compgen -e | grep '^RELMAP_' || true); do clean_env+=(-u "$name"); done
  "${clean_env[@]}" "$1" --listen 127.0.0.1:0 --port-file "$workdir/port" \
    --data-dir "$workdir/data" 2>"$workdir/server.log" &
  server_pid=$!
  trap stop_server EXIT
  trap 'exit 130' INT
  trap 'exit 143' TERM
  for _ in $(seq 200); do
    [ -s "$workdir/port" ] && break
    kill -0 "$server_pid" 2>/dev/null || break
    sleep 0.05
  done
  [ -s "$workdir/port" ] || fail "relmap-server did not start: $(cat "$workdir/server.log")"
  ADDR=127.0.0.1:$(cat "$workdir/port")
  export ADDR
}

stop_server() {
  local status=$?
  # set -e still holds in this trap: a server that is gone already must not end it.
  kill -TERM "$server_pid" 2>/dev/null || true
  wait "$server_pid" 2>/dev/null || true
  if [ "$status" -ne 0 ]; then
    describe_failure "$status"
    echo "--- server log" >&2
    tail -n 20 "$workdir/server.log" >&2
  fi
  rm -rf "$workdir"
  exit "$status"
}
