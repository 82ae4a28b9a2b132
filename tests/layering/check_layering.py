#!/usr/bin/env python3
"""The layering rules of docs/architecture.md, checked on the include lines of every
tracked C++ file:

1. Nothing outside server/ includes a server header: clients (client/, sim_backend/,
   robot_adapter/), the shared library (common/) and their tests talk to the server
   over the API and share code through common/ only.
2. common/ includes no PCL, gRPC, ODE or generated proto header: every program can
   link it.
3. server/cmm/ and server/exploration/ include no PCL.
4. Nothing below server/service/ (common, cmm, perception, exploration, session)
   includes gRPC.

Prints each violation as file:line and exits 1 when there is one."""
import pathlib
import re
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]')

# The server's tests include its headers by design; every other file is a client of it.
SERVER_TESTS = ("tests/unit/", "tests/perception/", "tests/session/", "tests/integration/",
                "tests/benchmarks/cmm_benchmark", "tests/benchmarks/learning_cost",
                "tests/benchmarks/session_store",
                "tests/benchmarks/durable_samples", "tests/benchmarks/perception/",
                "tests/support/", "tests/cluster/", "tests/fuzz/")
BELOW_SERVICE = ("common/", "server/cmm/", "server/perception/", "server/exploration/",
                 "server/session/")


def tracked_sources():
    out = subprocess.run(["git", "ls-files", "*.cpp", "*.h", "*.cc", "*.hpp"], cwd=ROOT,
                         check=True, capture_output=True, text=True).stdout
    return [p for p in out.split() if (ROOT / p).exists()]


def includes_server_header(path, quoted):
    """Whether a quoted include of `path` names a header of server/ (and no file of its
    own directory, of the project root or of another include root shadows it)."""
    if quoted.startswith("server/"):
        return True
    if not (ROOT / "server" / quoted).exists():
        return False
    own = (ROOT / path).parent / quoted
    return not own.exists() and not (ROOT / quoted).exists()


def is_grpc(name):
    return name.startswith("grpc") or name.endswith(".grpc.pb.h")


def violations():
    for path in tracked_sources():
        text = (ROOT / path).read_text(errors="replace").splitlines()
        outside_server = not path.startswith("server/") and not path.startswith(SERVER_TESTS)
        for number, line in enumerate(text, 1):
            match = INCLUDE.match(line)
            if not match:
                continue
            quoted, name = match.group(1) == '"', match.group(2)
            where = f"{path}:{number}: #include {match.group(1)}{name}"
            if outside_server and quoted and includes_server_header(path, name):
                yield where + " (a server header outside server/)"
            if path.startswith("common/") and (name.startswith("pcl/") or is_grpc(name) or
                                               name.startswith("ode/") or ".pb.h" in name):
                yield where + " (common/ is for every program: no PCL, gRPC, ODE or proto)"
            if path.startswith(("server/cmm/", "server/exploration/")) and name.startswith("pcl/"):
                yield where + " (no PCL in cmm/ or exploration/)"
            if path.startswith(BELOW_SERVICE) and is_grpc(name):
                yield where + " (no gRPC below service/)"


def main():
    found = list(violations())
    for v in found:
        print(v)
    if found:
        print(f"{len(found)} layering violation(s); the rules: docs/architecture.md")
        return 1
    print("layering: ok")
    return 0


if __name__ == "__main__":
    sys.exit(main())
