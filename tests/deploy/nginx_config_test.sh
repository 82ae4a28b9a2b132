#!/bin/sh
# deploy/nginx: the template renders into a config that `nginx -t` accepts, and nginx
# runs from it unprivileged-style in the foreground inside one prefix directory
# (pid, temp and logs there), listening where it was told. The committed renderings
# (compose, Kubernetes) need nginx >= 1.27.3 for `resolve`; they are tested only with
# such an nginx. Exit 77 (skipped) without nginx.
#   nginx_config_test.sh <repository root>
set -u
root=$1
render=$root/deploy/nginx/render-conf
if ! command -v nginx >/dev/null 2>&1; then
  echo "nginx is not installed (scripts/install-deps.sh installs it): skipped"
  exit 77
fi
dir=$(mktemp -d)
nginx_pid=""
trap '[ -n "$nginx_pid" ] && kill "$nginx_pid" 2>/dev/null; rm -rf "$dir"' EXIT
failures=0
check() {  # check <name> <command...>
  name=$1
  shift
  if "$@"; then echo "ok   $name"; else echo "FAIL $name"; failures=$((failures + 1)); fi
}

# Free loopback ports: bound by the kernel, then released for nginx and the upstreams.
ports=$(/usr/bin/python3 -c '
import socket
sockets = [socket.socket() for _ in range(3)]
for s in sockets: s.bind(("127.0.0.1", 0))
print(" ".join(str(s.getsockname()[1]) for s in sockets))')
set -- $ports
listen=$1 upstream_a=$2 upstream_b=$3

"$render" --listen "127.0.0.1:$listen" --server "127.0.0.1:$upstream_a" \
  --server "127.0.0.1:$upstream_b" >"$dir/nginx.conf"
check render-has-both-servers test "$(grep -c -e "^ *server 127.0.0.1:$upstream_a " \
  -e "^ *server 127.0.0.1:$upstream_b " "$dir/nginx.conf")" = 2
check render-hashes-on-the-session-header grep -q 'hash $http_x_relmap_session consistent;' "$dir/nginx.conf"
check nginx-t nginx -t -q -p "$dir" -c "$dir/nginx.conf"
check render-without-server-is-usage-error test "$("$render" --listen 1 >/dev/null 2>&1; echo $?)" = 2

# Foreground, everything inside the prefix: it listens, then stops on SIGQUIT.
nginx -p "$dir" -c "$dir/nginx.conf" -g 'daemon off;' 2>"$dir/error.log" &
nginx_pid=$!
listening() {
  /usr/bin/python3 -c 'import socket, sys; socket.create_connection(("127.0.0.1", int(sys.argv[1])), 1)' \
    "$listen" 2>/dev/null
}
for _ in $(seq 50); do listening && break; sleep 0.1; done
check nginx-listens listening
check nginx-pid-in-prefix test -s "$dir/nginx.pid"
check nginx-temp-in-prefix test -d "$dir/client_body_temp"
kill -QUIT "$nginx_pid"
wait "$nginx_pid"
check nginx-stops-cleanly test $? = 0
nginx_pid=""

# The committed renderings are what render-conf makes today (its first line says how).
for rendered in "$root/deploy/nginx/compose.conf" "$root/deploy/k8s/nginx.conf"; do
  arguments=$(sed -n '1s/^# Rendered from relmap.conf.in by: render-conf //p' "$rendered")
  # shellcheck disable=SC2086 # the arguments are words
  "$render" $arguments >"$dir/again.conf"
  check "up-to-date:${rendered#"$root"/}" cmp -s "$rendered" "$dir/again.conf"
  version=$(nginx -v 2>&1 | sed 's|.*nginx/||')
  if printf '%s\n1.27.3\n' "$version" | sort -V -C 2>/dev/null && [ "$version" != 1.27.3 ]; then
    echo "skip nginx-t:${rendered#"$root"/} (nginx $version has no 'resolve')"
  else
    # Their server names resolve only in their own networks: test the syntax with
    # the names pointed at loopback.
    sed -E 's/server [^ ]+:50051/server 127.0.0.1:50051/; s/resolver [^ ]+ /resolver 127.0.0.1 /; s|/dev/stdout|access.log|' \
      "$rendered" >"$dir/resolve.conf"
    check "nginx-t:${rendered#"$root"/}" nginx -t -q -p "$dir" -c "$dir/resolve.conf"
  fi
done

[ "$failures" -eq 0 ]
