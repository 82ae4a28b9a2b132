#!/bin/sh
# deploy/systemd/relmap-server.service: `systemd-analyze verify` finds nothing to say
# (unknown keys are only warnings there, so any output fails), and its offline
# security exposure stays at 2.0 or below ("OK"). The unit names /usr/bin, where the
# package installs the server; here it points at the build's binary. Exit 77
# (skipped) without systemd-analyze. systemd does not run the unit here.
#   systemd_unit_test.sh <repository root> <relmap-server>
set -u
root=$1
server=$2
if ! command -v systemd-analyze >/dev/null 2>&1; then
  echo "systemd-analyze is not installed: skipped"
  exit 77
fi
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
unit=$dir/relmap-server.service
sed "s|/usr/bin/relmap-server|$server|" "$root/deploy/systemd/relmap-server.service" >"$unit"
failures=0

output=$(systemd-analyze verify "$unit" 2>&1)
status=$?
if [ "$status" -eq 0 ] && [ -z "$output" ]; then
  echo "ok   verify"
else
  echo "FAIL verify (exit $status): $output"
  failures=$((failures + 1))
fi

if systemd-analyze security --offline=true --threshold=20 "$unit" >"$dir/security.txt" 2>&1; then
  echo "ok   security $(grep -o 'exposure level.*' "$dir/security.txt")"
else
  echo "FAIL security: $(tail -1 "$dir/security.txt")"
  failures=$((failures + 1))
fi

# The settings file it starts with holds only settings relmap-server knows.
if "$server" --config "$root/deploy/systemd/relmap-server.conf" --listen 127.0.0.1:0 \
  --store "sqlite:$dir/relmap.sqlite" --port-file "$dir/port" 2>"$dir/server.log" &
then
  pid=$!
  for _ in $(seq 100); do [ -s "$dir/port" ] && break; sleep 0.05; done
  if [ -s "$dir/port" ]; then echo "ok   the config file starts a server"; else
    echo "FAIL the config file: $(cat "$dir/server.log")"
    failures=$((failures + 1))
  fi
  kill "$pid" 2>/dev/null
  wait "$pid" 2>/dev/null
fi

[ "$failures" -eq 0 ]
