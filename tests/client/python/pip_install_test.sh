#!/usr/bin/env bash
# `pip install` of the Python client as client/python/README.md says, offline: into a venv
# that sees Debian's grpcio, protobuf and numpy, built with Debian's setuptools and wheel
# (--no-build-isolation; --no-index proves nothing is fetched). A copy of the package is
# installed, so that the source tree gets no build/ or egg-info. Then the installed package
# must import, with its generated stubs.
# Usage: pip_install_test.sh <repository root> <Debian's python3>
set -euo pipefail
root=$1
python=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp -r "$root/client/python" "$work/package"
"$python" -m venv --system-site-packages "$work/venv"
RELMAP_PROTO_DIR="$root/proto" "$work/venv/bin/pip" install --quiet --no-index \
  --no-build-isolation "$work/package"
cd "$work"  # not the repository: the import must find the installed package
"$work/venv/bin/python" - <<'PY'
import relmap
request = relmap.pb.PostOutcomeRequest(object_supervoxels=[3])
assert list(request.object_supervoxels) == [3], request
assert hasattr(relmap, "Client") and hasattr(relmap, "LocalServer")
print("installed:", relmap.__file__)
PY
