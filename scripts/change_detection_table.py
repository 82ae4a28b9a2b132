#!/usr/bin/env python3
"""The change detector's labels against what the simulator did, per run directory of
relmap-sim run --mode physical (DIR/<scene>-<resolution>/replication-*.csv).

A push counts when it was executed and an outcome was learned. "moved" is the simulator's
truth: the target's body was displaced by more than the scene's motion threshold. Exits 1
when a run's wrong labels exceed 5 % of its pushes or any unmoved target is called moved.
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


def main():
    root = sys.argv[1]
    print("| scene | resolution | pushes | moved | missed moves | false moved | wrong labels "
          "| vacated share, labelled moved / not (median) | detector ms (median, max) |")
    print("|---|---|---|---|---|---|---|---|---|")
    failed = False
    for run in sorted(d for d in glob.glob(os.path.join(root, "*")) if os.path.isdir(d)):
        scene, resolution = os.path.basename(run).rsplit("-", 1)
        rows = list(rows_of(run))
        if not rows:
            continue
        moved = [r for r in rows if r["push_target_moved"] == "1"]
        missed = sum(r["label"] == "0" for r in moved)
        false_moved = sum(r["label"] == "1" and r["push_target_moved"] == "0" for r in rows)
        wrong = missed + false_moved
        times = [float(r["change_ms"]) for r in rows if r.get("change_ms")]
        timing = f"{statistics.median(times):.1f}, {max(times):.1f}" if times else "-"
        rate = wrong / len(rows)
        evidence = " / ".join(vacated_share([r for r in rows if r["label"] == label])
                              for label in ("1", "0"))
        bad = rate > 0.05 or false_moved > 0
        failed |= bad
        print(f"| {scene} | {resolution} | {len(rows)} | {len(moved)} | {missed} | {false_moved} "
              f"| {wrong} ({100 * rate:.1f} %){' FAIL' if bad else ''} | {evidence} | {timing} |")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
