#!/usr/bin/env python3
"""The change detector's labels against what the simulator did, per run directory of
relmap-sim run --mode physical (DIR/<scene>-<resolution>/replication-*.csv).

A push counts when it was executed and an outcome was learned. "moved" is the simulator's
truth about the pushed supervoxel: at least half of its points were displaced by more than
the scene's motion threshold, each point moving with the body its ray hit
(push_target_displaced). Exits 1 when a run's wrong labels exceed 5 % of its pushes or any
target that did not move is called moved: a target none of whose points the push displaced
(push_displaced_points = 0). A "moved" for a target that moved in part (some of its points
displaced, fewer than half: a supervoxel straddling a pushed object and one that stayed) is
a wrong label, counted in the rate and shown apart.

"On fixed bodies" counts the "moved" labels of pushes whose target is on a body that cannot
move (the column `truth`, the target's moveability): the labels that teach the classifier
something wrong. A false "moved" of a moveable body nudged less than the threshold is a
wrong label here but a right one for learning.

Side by side, the older truth about one body: the body nearest the supervoxel's centroid
had its centre of mass displaced by more than the threshold (push_target_moved). It misses
an object turned about its centre, and judges a supervoxel that spans two bodies by
whichever is nearer its centroid.
"""
import csv
import glob
import os
import statistics
import sys


def rows_of(run):
    for path in sorted(glob.glob(os.path.join(run, "replication-*.csv"))):
        with open(path, newline="") as f:
            for row in csv.DictReader(f):
                if row["label"] != "" and row["push_executed"] == "1":
                    yield row


def vacated_share(rows):
    """The median share of vacated points among the shown ones, over `rows`."""
    shares = []
    for r in rows:
        if not r.get("change_target_points"):
            continue
        shown = sum(int(r[f"change_{k}_points"]) for k in ("supported", "vacated", "occluded"))
        if shown:
            shares.append(int(r["change_vacated_points"]) / shown)
    return f"{statistics.median(shares):.2f}" if shares else "-"


def wrong_labels(rows, truth):
    """(missed moves, false moved) of `rows` against the 0/1 column `truth`."""
    missed = sum(r["label"] == "0" and r[truth] == "1" for r in rows)
    false_moved = sum(r["label"] == "1" and r[truth] == "0" for r in rows)
    return missed, false_moved


def counts(rows):
    """(wrong labels, "moved" for a target that stayed, "moved" on a fixed body)."""
    missed, false_moved = wrong_labels(rows, "push_target_displaced")
    stayed_moved = sum(r["label"] == "1" and r["push_target_displaced"] == "0"
                       and int(r["push_displaced_points"]) == 0 for r in rows)
    fixed_moved = sum(r["label"] == "1" and r["truth"] == "0" for r in rows)
    return missed + false_moved, stayed_moved, fixed_moved


def runs_of(root):
    """(scene, resolution, rows) per run directory under `root` with labelled pushes."""
    for run in sorted(d for d in glob.glob(os.path.join(root, "*")) if os.path.isdir(d)):
        scene, resolution = os.path.basename(run).rsplit("-", 1)
        rows = list(rows_of(run))
        if rows:
            yield scene, resolution, rows


def main():
    root = sys.argv[1]
    print("| scene | resolution | pushes | moved | missed moves "
          "| false moved: target stayed / moved in part | wrong labels "
          "| wrong by body truth (false moved) | moved on a fixed body "
          "| vacated share, labelled moved / not (median) | detector ms (median, max) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    failed = False
    for scene, resolution, rows in runs_of(root):
        missed, false_moved = wrong_labels(rows, "push_target_displaced")
        wrong, stayed_moved, fixed_moved = counts(rows)
        moved = [r for r in rows if r["push_target_displaced"] == "1"]
        body_missed, body_false_moved = wrong_labels(rows, "push_target_moved")
        times = [float(r["change_ms"]) for r in rows if r.get("change_ms")]
        timing = f"{statistics.median(times):.1f}, {max(times):.1f}" if times else "-"
        rate = wrong / len(rows)
        evidence = " / ".join(vacated_share([r for r in rows if r["label"] == label])
                              for label in ("1", "0"))
        bad = rate > 0.05 or stayed_moved > 0
        failed |= bad
        print(f"| {scene} | {resolution} | {len(rows)} | {len(moved)} | {missed} "
              f"| {stayed_moved} / {false_moved - stayed_moved} "
              f"| {wrong} ({100 * rate:.1f} %){' FAIL' if bad else ''} "
              f"| {body_missed + body_false_moved} ({body_false_moved}) | {fixed_moved} "
              f"| {evidence} | {timing} |")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
