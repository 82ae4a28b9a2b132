#!/usr/bin/env python3
"""The layering rules of docs/architecture.md, checked on the include lines of every
tracked C++ file:

1. Nothing outside server/ includes a server header: clients (client/, sim_backend/,
   robot_adapter/), the shared library (common/) and their tests talk to the server
   over the API and share code through common/ only.
2. common/ includes no PCL, gRPC, ODE or generated proto header: every program can
   link it.
3. server/cmm/, server/exploration/ and server/session/ include no PCL (the session
   reaches perception through its PCL-free headers).
4. Nothing below server/service/ (common, cmm, perception, exploration, session)
   includes gRPC.
5. The server's folders include one another downwards only: SERVER_PARTS names, for
   each folder (each sub-folder of server/session/ a part of its own), the server
   folders whose headers it may include besides its own. The stores include no
   session, the records and their codec nothing of the session at all.
6. In server/, only the SQLite store includes SQLite, only the PostgreSQL store libpq.

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

# The parts of the server, as folders of server/, each with the parts whose headers it
# may include (its own always). Listed bottom first: a part names only parts before it,
# so that the layers have no cycle. A file belongs to the longest folder that holds it,
# so server/session/ means the files of that folder itself. The files of server/ itself
# (main.cpp and the steps beside it) put the parts together and may include any.
RECORDS, STORE, SQLITE, POSTGRES = ("session/records/", "session/store/",
                                    "session/store/sqlite/", "session/store/postgres/")
INTAKE, SESSION, REGISTRY = "session/intake/", "session/", "session/registry/"
SERVER_PARTS = {
    "cmm/": (),
    "exploration/": ("cmm/",),
    "perception/": (),
    # What the store persists, as plain values, and the byte forms of it.
    RECORDS: ("cmm/",),
    # The SessionStore interface; its implementations know no session.
    STORE: (RECORDS, "cmm/"),
    SQLITE: (STORE, RECORDS, "cmm/"),
    POSTGRES: (STORE, RECORDS, "cmm/"),
    # The clouds a server takes in: admission, then decoding.
    INTAKE: ("perception/",),
    # One session, over the store's interface, not a store.
    SESSION: (STORE, RECORDS, "cmm/", "exploration/", "perception/"),
    # The sessions of a server, restored from the store.
    REGISTRY: (SESSION, STORE, RECORDS, "cmm/", "exploration/", "perception/"),
    # The gRPC edge; its use of perception/ headers (decode limits, change detector
    # settings) is the exception docs/architecture.md names.
    "service/": (REGISTRY, SESSION, INTAKE, RECORDS, "cmm/", "exploration/", "perception/"),
    "tools/": ("cmm/", "exploration/", "perception/"),
}
# Headers of outside libraries that only one part of the server may include.
OWN_LIBRARY = {"sqlite3.h": SQLITE, "libpq-fe.h": POSTGRES}


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


def server_part(path):
    """The part of SERVER_PARTS that holds `path` (relative to server/), or None."""
    holders = [part for part in SERVER_PARTS if path.startswith(part)]
    return max(holders, key=len) if holders else None


def included_server_file(path, quoted):
    """The file of server/ (relative to it) that a quoted include of `path`, a file of
    server/, names; None for a header of common/, proto/ or the build."""
    own = ((ROOT / path).parent / quoted).resolve()
    if own.exists():
        inside = (ROOT / "server") in own.parents
        return str(own.relative_to(ROOT / "server")) if inside else None
    if quoted.startswith("server/"):
        return quoted[len("server/"):]
    return quoted if (ROOT / "server" / quoted).exists() else None


def is_grpc(name):
    return name.startswith("grpc") or name.endswith(".grpc.pb.h")


def violations():
    for path in tracked_sources():
        text = (ROOT / path).read_text(errors="replace").splitlines()
        outside_server = not path.startswith("server/") and not path.startswith(SERVER_TESTS)
        part = server_part(path[len("server/"):]) if path.startswith("server/") else None
        for number, line in enumerate(text, 1):
            match = INCLUDE.match(line)
            if not match:
                continue
            quoted, name = match.group(1) == '"', match.group(2)
            where = f"{path}:{number}: {line.strip()}"
            if outside_server and quoted and includes_server_header(path, name):
                yield where + " (a server header outside server/)"
            if path.startswith("common/") and (name.startswith("pcl/") or is_grpc(name) or
                                               name.startswith("ode/") or ".pb.h" in name):
                yield where + " (common/ is for every program: no PCL, gRPC, ODE or proto)"
            if path.startswith(("server/cmm/", "server/exploration/", "server/session/")) and \
                    name.startswith("pcl/"):
                yield where + " (no PCL in cmm/, exploration/ or session/)"
            if path.startswith(BELOW_SERVICE) and is_grpc(name):
                yield where + " (no gRPC below service/)"
            if name in OWN_LIBRARY and path.startswith("server/") and part != OWN_LIBRARY[name]:
                yield where + f" ({name} is server/{OWN_LIBRARY[name]}'s alone)"
            included = included_server_file(path, name) if part and quoted else None
            if included is not None:
                to = server_part(included)
                if to is not None and to != part and to not in SERVER_PARTS[part]:
                    allowed = ", ".join(SERVER_PARTS[part])
                    yield where + (f" (server/{part} may include only {allowed})" if allowed
                                   else f" (server/{part} may include no other part)")


def main():
    parts = list(SERVER_PARTS)
    for index, part in enumerate(parts):
        later = [p for p in SERVER_PARTS[part] if p not in parts[:index]]
        if later:
            print(f"SERVER_PARTS: {part} names {', '.join(later)}, not listed before it")
            return 1
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
