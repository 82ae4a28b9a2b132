#!/usr/bin/python3
"""A whole exploration with the Python client: create a session, compute the maps of a
frame, push the target the choice map drew, post what the push did, repeat; progress one
line per push.

relmap-sim renders its scenes only inside its own runs (no command writes a scene's
clouds as PCD files), so the frames here are real Kinect clouds: by default PCL's static
sequence kinect_static_seq_{1,2,3}.pcd in ../shared/data/real (RELMAP_REAL_DATA). The
scene is static, so nothing a "push" does moves it: with --outcome after-cloud (the
default) each push is labelled by the server's change detector from the next frame of
the sequence as the after cloud, which says "not moved" unless the camera saw a
change; with --outcome ask you are the robot and say what moved (a moved target's whole
object, as the server's Supervoxel.object sees it, is then learned as moveable).

usage: explore.py [--server HOST:PORT | --server-binary PATH] [--iterations 12]
                  [--seed 1] [--outcome after-cloud|ask] [FRAME.pcd ...]

Example (from the repository, after a build)::

    /usr/bin/python3 client/python/examples/explore.py \\
        --server-binary build/server/relmap-server --iterations 6
"""

from __future__ import annotations

import argparse
import os
import pathlib
import sys
import time
from typing import List, Optional

import numpy as np

import relmap

REAL_DATA = pathlib.Path(os.environ.get(
    "RELMAP_REAL_DATA", pathlib.Path(__file__).resolve().parents[3].parent / "shared/data/real"))
DEFAULT_FRAMES = [REAL_DATA / f"kinect_static_seq_{i}.pcd" for i in (1, 2, 3)]


def ask_moved(target: int, maps: relmap.Maps) -> bool:
    """The operator's label of a push: y (it moved) or n."""
    x, y, z = maps.centroids[target]
    body = int(np.count_nonzero(maps.objects == maps.objects[target]))
    while True:
        answer = input(f"  pushed supervoxel {target} at ({x:.2f}, {y:.2f}, {z:.2f}) m, on an "
                       f"object of {body} supervoxels: did it move? [y/n] ").strip().lower()
        if answer in ("y", "n"):
            return answer == "y"


def explore(client: relmap.Client, frames: List[relmap.CloudLike], names: List[str],
            iterations: int, seed: int, outcome: str) -> relmap.Session:
    """``iterations`` pushes over ``frames`` in turn; returns the session."""
    session = client.create_session(seed=seed)
    print(f"session {session.id} (seed {seed}) on {client.address}")
    print(f"{'push':>4}  {'frame':<26} {'voxels':>6} {'target':>6} {'P(m)':>5}  "
          f"{'label':<12} {'samples m/n':>11} {'components':>10} {'ms':>6}")
    for push in range(1, iterations + 1):
        index = (push - 1) % len(frames)
        started = time.monotonic()
        maps = client.compute_maps(session, frames[index], point_labels=False)
        if maps.target is None:
            print(f"{push:>4}  {names[index]:<26} nothing to push (no usable supervoxel)")
            continue
        relevance = maps.relevance[maps.target]
        try:
            if outcome == "ask":
                moved = ask_moved(maps.target, maps)
                # A push moves the whole object: its other supervoxels are learned as
                # moveable with the target (relmap-sim --labels object does the same).
                body = [int(i) for i in np.flatnonzero(maps.objects == maps.objects[maps.target])
                        if i != maps.target] if moved else []
                answer = client.post_outcome(session, maps.frame_id, maps.target,
                                             moved=moved, moved_with_target=body)
            else:
                after = frames[(index + 1) % len(frames)]
                answer = client.post_outcome(session, maps.frame_id, maps.target,
                                             after_cloud=after)
        except relmap.RelmapError as error:
            if not error.is_frame_gone:
                raise
            print(f"{push:>4}  frame {maps.frame_id} gone from the server: nothing learned")
            continue
        stats = answer.stats
        label = relmap.pb.Label.Name(answer.label)[len("LABEL_"):].lower()
        elapsed_ms = (time.monotonic() - started) * 1000.0
        print(f"{push:>4}  {names[index]:<26} {len(maps.relevance):>6} {maps.target:>6} "
              f"{relevance:>5.2f}  {label:<12} "
              f"{f'{stats.moveable_samples}/{stats.non_moveable_samples}':>11} "
              f"{f'{stats.moveable_components}/{stats.non_moveable_components}':>10} "
              f"{elapsed_ms:>6.0f}")
    return session


def main(argv: List[str]) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    where = parser.add_mutually_exclusive_group()
    where.add_argument("--server", help="a running relmap-server, host:port")
    where.add_argument("--server-binary", help="start this relmap-server on 127.0.0.1 for the run")
    parser.add_argument("--iterations", type=int, default=12)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--outcome", choices=("after-cloud", "ask"), default="after-cloud")
    parser.add_argument("frames", nargs="*", type=pathlib.Path, default=DEFAULT_FRAMES)
    arguments = parser.parse_args(argv)
    missing = [str(path) for path in arguments.frames if not path.is_file()]
    if missing:
        print(f"explore.py: no such PCD file: {', '.join(missing)}", file=sys.stderr)
        return 2
    # Each file read and packed once; the server decodes the packed layout fastest.
    frames: List[relmap.CloudLike] = [relmap.packed_cloud(relmap.read_pcd(path))
                                      for path in arguments.frames]
    names = [path.name for path in arguments.frames]

    server: Optional[relmap.LocalServer] = None
    if arguments.server_binary:
        server = relmap.LocalServer.start(arguments.server_binary, memory_only=True)
    address = server.address if server else (arguments.server or "127.0.0.1:50051")
    try:
        with relmap.Client(address) as client:
            session = explore(client, frames, names, arguments.iterations, arguments.seed,
                              arguments.outcome)
            state = client.export_session(session)
            print(f"learned {len(state.state.samples)} samples over "
                  f"{state.stats.frames} frames; {client.retries} retries")
            client.delete_session(session)
    except relmap.RelmapError as error:
        print(f"explore.py: {error}", file=sys.stderr)
        return 1
    finally:
        if server:
            server.stop()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
