"""Fixtures of the Python client's tests: real relmap-server processes on loopback
(relmap.LocalServer: --listen 127.0.0.1:0, the port read from --port-file, as
tests/integration does), a client on each, and the real Kinect clouds."""

from __future__ import annotations

import os
import pathlib
from typing import Iterator

import pytest

import relmap

REPO = pathlib.Path(__file__).resolve().parents[3]
SERVER_BINARY = os.environ.get("RELMAP_SERVER_BINARY", str(REPO / "build/server/relmap-server"))
REAL_DATA = pathlib.Path(os.environ.get("RELMAP_REAL_DATA", str(REPO.parent / "shared/data/real")))
MUG = REAL_DATA / "table_scene_mug_stereo_textured.pcd"


def start_server(*arguments: str) -> relmap.LocalServer:
    """relmap-server with ``arguments``, sessions in memory only."""
    return relmap.LocalServer.start(SERVER_BINARY, arguments, memory_only=True)


@pytest.fixture(scope="module")
def server() -> Iterator[relmap.LocalServer]:
    """One server for a test module; two cached frames per session, so that FRAME_GONE
    is a few calls away."""
    process = start_server("--frames-per-session", "2")
    yield process
    process.stop()


@pytest.fixture
def client(server: relmap.LocalServer) -> Iterator[relmap.Client]:
    with relmap.Client(server.address, deadline=30.0) as connection:
        yield connection


@pytest.fixture(scope="session")
def mug_path() -> pathlib.Path:
    if not MUG.exists():
        pytest.fail(f"the real Kinect cloud {MUG} is missing (RELMAP_REAL_DATA)")
    return MUG


@pytest.fixture(scope="session")
def mug_points(mug_path: pathlib.Path):
    return relmap.read_pcd(mug_path)
