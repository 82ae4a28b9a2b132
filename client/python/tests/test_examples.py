"""examples/explore.py runs a whole exploration, and relmap.LocalServer, which it starts
the server with, reports what goes wrong."""

from __future__ import annotations

import os
import pathlib
import re
import subprocess
import sys

import pytest

import relmap
from conftest import REAL_DATA, SERVER_BINARY

EXPLORE = pathlib.Path(__file__).resolve().parents[1] / "examples" / "explore.py"


def test_explore_pushes_posts_and_prints_a_line_per_push(mug_path):
    frames = [REAL_DATA / f"kinect_static_seq_{i}.pcd" for i in (1, 2)]
    run = subprocess.run(
        [sys.executable, str(EXPLORE), "--server-binary", SERVER_BINARY, "--iterations", "3"]
        + [str(frame) for frame in frames],
        capture_output=True, text=True, timeout=120, env=dict(os.environ))
    assert run.returncode == 0, run.stderr
    pushes = [line.split() for line in run.stdout.splitlines() if line[:4].strip().isdigit()]
    assert [int(push[0]) for push in pushes] == [1, 2, 3]
    assert [push[1] for push in pushes] == [f.name for f in frames + frames[:1]]
    # A static scene: the change detector labels every push of it not moved.
    assert [push[5] for push in pushes] == ["not_moveable"] * 3
    assert [push[6] for push in pushes] == ["0/1", "0/2", "0/3"]
    assert "learned 3 samples over 3 frames" in run.stdout


def test_explore_refuses_a_missing_frame():
    run = subprocess.run([sys.executable, str(EXPLORE), "/no/such.pcd"],
                         capture_output=True, text=True, timeout=60)
    assert run.returncode == 2 and "/no/such.pcd" in run.stderr


def test_local_server_stops_cleanly_and_removes_its_directory():
    server = relmap.LocalServer.start(SERVER_BINARY)  # with a --data-dir in its directory
    with relmap.Client(server.address) as client:
        assert client.check_health() == "SERVING"
    assert (server.directory / "data").is_dir()
    assert server.stop() == 0  # SIGTERM: drained, exit status 0
    assert not server.directory.exists()


def test_local_server_reports_a_missing_binary_and_a_failed_start():
    with pytest.raises(FileNotFoundError):
        relmap.LocalServer.start("/no/such/relmap-server")
    with pytest.raises(RuntimeError) as raised:
        relmap.LocalServer.start(SERVER_BINARY, ["--no-such-flag"])
    assert "exited at start-up with status 2" in str(raised.value)  # bad arguments
    assert "bad argument '--no-such-flag'" in str(raised.value)  # the log's first line


def test_explore_asks_and_learns_a_moved_targets_whole_object():
    frame = REAL_DATA / "kinect_static_seq_1.pcd"
    run = subprocess.run(
        [sys.executable, str(EXPLORE), "--server-binary", SERVER_BINARY, "--iterations", "2",
         "--outcome", "ask", str(frame)],
        input="y\nn\n", capture_output=True, text=True, timeout=120, env=dict(os.environ))
    assert run.returncode == 0, run.stderr
    sizes = [int(size) for size in re.findall(r"on an object of (\d+) supervoxels", run.stdout)]
    assert len(sizes) == 2
    # The first push moved: its object's supervoxels all moveable (those with usable
    # features); the second did not: one more sample, not moveable.
    moveable = int(re.search(r"moveable +(\d+)/0 ", run.stdout).group(1))
    assert 1 <= moveable <= sizes[0] and (moveable > 1) == (sizes[0] > 1)
    assert f"{moveable}/1" in run.stdout
