#!/usr/bin/env bash
# A cluster on one machine, and a server lost in the middle of an experiment:
# a throw-away PostgreSQL, two relmap-servers sharing it, nginx in front
# (deploy/nginx), relmap-sim through nginx; a few seconds in, the server serving
# the first session is stopped with SIGKILL (or SIGTERM), and the run goes on.
#
#   deploy/try-failover.sh [KILL|TERM] [--iterations 60] [--replications 4] [--after 6]
#
# Needs the build (scripts/configure-build.sh), nginx and PostgreSQL 15's server
# programs (scripts/install-deps.sh installs both). Leaves everything in
# out/failover-<signal>/: the servers' and nginx's logs, relmap-sim's results; prints
# which sessions moved, with how many samples, and what each replication learned.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
signal=KILL
iterations=60
replications=4
after=6
while [ $# -gt 0 ]; do
  case "$1" in
    KILL | TERM) signal=$1; shift ;;
    --iterations) iterations=$2; shift 2 ;;
    --replications) replications=$2; shift 2 ;;
    --after) after=$2; shift 2 ;;
    *) sed -n '2,13p' "$0" >&2; exit 2 ;;
  esac
done

pg_bin=/usr/lib/postgresql/15/bin
out=$root/out/failover-$signal
rm -rf "$out"
mkdir -p "$out/pg" "$out/nginx"
chmod 755 "$out" "$out/nginx"
# initdb refuses to run as root: then PostgreSQL runs as Debian's postgres user.
as_postgres=()
if [ "$(id -u)" -eq 0 ]; then
  chown postgres "$out/pg"
  as_postgres=(runuser -u postgres --)
fi
free_port() { python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])'; }
pg_port=$(free_port)
"${as_postgres[@]}" "$pg_bin/initdb" -D "$out/pg/data" -U postgres --auth=trust --no-sync >/dev/null
"${as_postgres[@]}" "$pg_bin/pg_ctl" -D "$out/pg/data" -l "$out/pg/server.log" -w \
  -o "-p $pg_port -k $out/pg -c listen_addresses=127.0.0.1" start >/dev/null
pids=()
cleanup() {
  kill "${pids[@]}" 2>/dev/null || true
  wait 2>/dev/null || true
  "${as_postgres[@]}" "$pg_bin/pg_ctl" -D "$out/pg/data" -m fast stop >/dev/null || true
}
trap cleanup EXIT
"${as_postgres[@]}" "$pg_bin/createdb" -h 127.0.0.1 -p "$pg_port" -U postgres relmap
store=postgresql://postgres@127.0.0.1:$pg_port/relmap

ports=("$(free_port)" "$(free_port)")
declare -A server_pid
for port in "${ports[@]}"; do
  build/server/relmap-server --listen "127.0.0.1:$port" --store "$store" 2>"$out/server-$port.log" &
  server_pid[$port]=$!
  pids+=($!)
done
nginx_port=$(free_port)
deploy/nginx/render-conf --listen "127.0.0.1:$nginx_port" --access-log "$out/nginx/access.log" \
  --server "127.0.0.1:${ports[0]}" --server "127.0.0.1:${ports[1]}" >"$out/nginx/nginx.conf"
nginx -p "$out/nginx" -c "$out/nginx/nginx.conf" -g 'daemon off;' 2>"$out/nginx/error.log" &
pids+=($!)
sleep 1

echo "try-failover: servers on ${ports[*]}, nginx on $nginx_port, PostgreSQL on $pg_port"
start=$(date +%s.%N)
elapsed() { awk -v now="$(date +%s.%N)" -v start="$start" 'BEGIN { printf "%.1f", now - start }'; }
build/sim_backend/relmap-sim run --scene MoveableBalls --mode oracle --iterations "$iterations" \
  --replications "$replications" --parallel 2 --seed 1 --server "127.0.0.1:$nginx_port" \
  --out "$out/sim" >"$out/sim.out" 2>"$out/sim.err" &
sim=$!
sleep "$after"
victim=""
for port in "${ports[@]}"; do
  if grep -q "rpc=ComputeMaps" "$out/server-$port.log"; then victim=$port; break; fi
done
echo "try-failover: SIG$signal to the server on $victim, $(elapsed) s in"
kill -"$signal" "${server_pid[$victim]}"
sim_status=0
wait "$sim" || sim_status=$?
echo "try-failover: relmap-sim exited $sim_status after $(elapsed) s"
echo "try-failover: sessions taken over (restored with samples > 0):"
grep -h "restored session=" "$out"/server-*.log | grep -v "samples=0 " | sed 's/.*restored /  /'
echo "try-failover: per replication: iterations, outcomes lost with a move, final soft accuracy"
for csv in "$out"/sim/replication-*.csv; do
  python3 - "$csv" <<'EOF'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
lost = sum(1 for row in rows if row["target"] != "" and row["label"] == "")
print(f"  {sys.argv[1].rsplit('/', 1)[1]}: {len(rows)} iterations, {lost} lost, "
      f"soft accuracy {float(rows[-1]['soft_accuracy']):.3f}" if rows else "  (empty)")
EOF
done
exit "$sim_status"
