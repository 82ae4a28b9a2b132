#!/usr/bin/env python3
"""The pushes where the change detector asked whether the target went with its object
(docs/method.md §5.1, "Whether the target went with its object"): the object showed a move,
the target's own points did not, and a rigid motion was fitted to the object's changed
parts. Per push: the simulator's truth, the target's counts at its old place and where the
motion carries it (still there / seen through / hidden), the z of the two seen-through
shares, and the label the detector gave. Reads DIR/<scene>-<resolution>/replication-*.csv
of relmap-sim run --mode physical (one or more DIRs).
"""
import csv
import glob
import math
import os
import sys


def z_statistic(carried_still, carried_through, still, through):
    """One-sided two-proportion z: carried seen-through share above the target's own."""
    n_carried, n_own = carried_still + carried_through, still + through
    if n_carried == 0 or n_own == 0:
        return 0.0
    pooled = (carried_through + through) / (n_carried + n_own)
    spread = math.sqrt(pooled * (1 - pooled) * (1 / n_carried + 1 / n_own))
    if spread == 0:
        return 0.0
    return (carried_through / n_carried - through / n_own) / spread


def main():
    print("| run | replication | iteration | truth: moved | target: still / through / hidden "
          "| carried | z | label | right |")
    print("|---|---|---|---|---|---|---|---|---|")
    for root in sys.argv[1:]:
        for path in sorted(glob.glob(os.path.join(root, "*", "replication-*.csv"))):
            run = os.path.basename(os.path.dirname(path))
            replication = path.rsplit("-", 1)[1].split(".")[0]
            with open(path, newline="") as f:
                for r in csv.DictReader(f):
                    if r.get("change_object_motion_fitted") != "1" or r["label"] == "":
                        continue
                    n = {k: int(r[f"change_{k}_points"]) for k in (
                        "supported", "vacated", "occluded", "carried_supported",
                        "carried_vacated", "carried_occluded")}
                    z = z_statistic(n["carried_supported"], n["carried_vacated"],
                                    n["supported"], n["vacated"])
                    truth = r["push_target_displaced"]
                    right = "yes" if r["label"] == truth else "no"
                    print(f"| {run} | {replication} | {r['iteration']} | {truth} "
                          f"| {n['supported']} / {n['vacated']} / {n['occluded']} "
                          f"| {n['carried_supported']} / {n['carried_vacated']} / "
                          f"{n['carried_occluded']} | {z:.1f} | {r['label']} | {right} |")


if __name__ == "__main__":
    main()
