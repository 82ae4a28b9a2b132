#!/usr/bin/env python3
"""The tables of docs/results.md from relmap-sim's summary.json files.

usage: results-sim-table.py OUT_DIR [EXPERIMENT ...]

One row per experiment (default: every OUT_DIR/*/summary.json, in the order of
OUT_DIR/experiments.txt that scripts/results-sim.sh writes, else of November's list): iterations, replications, the thresholded-soft
precision / recall / accuracy of the last iteration as mean (min–max), the soft
accuracy mean, the median final components per class (moveable / non-moveable),
failed runs (final thresholded accuracy < 0.6), mislabelled pushes (physical
mode), and the mean end-to-end iteration time. Nothing is retyped by hand.
"""
import json
import os
import statistics
import sys

ORDER = [
    "MoveableBalls", "MoveableBricks1", "MoveableBricks2", "WhiteMoveableBalls", "SimKitchen",
    "WhiteMoveableBricks-400", "WhiteMoveableBricks-400-corrected_v1",
    "WhiteMoveableBricks-400-alpha1", "MoveableBricks1-corrected_v1", "MoveableBricks1-paper2018",
    "MoveableBricks1-random", "MoveableBalls-physical", "WhiteMoveableBricks-1000",
]


def spread(stat):
    if stat is None or stat.get("mean") is None:
        return "—"
    return f"{stat['mean']:.2f} ({stat['min']:.2f}–{stat['max']:.2f})"


def row(name, summary):
    config = summary["config"]
    final = summary["final"]
    reps = summary["replications"]
    ts = final["thresholded_soft"]
    soft = final["soft"]["accuracy"]
    pos = statistics.median(r["final"]["moveable_components"] for r in reps if r["final"])
    neg = statistics.median(r["final"]["non_moveable_components"] for r in reps if r["final"])
    mislabelled = sum(r["final"]["mislabelled"] for r in reps if r["final"])
    labelled = sum(r["final"]["moveable_samples"] + r["final"]["non_moveable_samples"]
                   for r in reps if r["final"])
    labels = (f"{mislabelled}/{labelled} ({100.0 * mislabelled / labelled:.1f} %)"
              if config["mode"] == "physical" and labelled else "—")
    variant = config["variant"] + (f", α = {config['alpha']}" if config["alpha"] is not None else "")
    if config["sampling"] != "choice":
        variant += f", {config['sampling']} sampling"
    return (f"| {name} | {variant} | {config['mode']} | {config['iterations']} | {len(reps)} | "
            f"{spread(ts['precision'])} | {spread(ts['recall'])} | {spread(ts['accuracy'])} | "
            f"{soft['mean']:.2f} | {pos:g} / {neg:g} | {summary['failed_runs']}/{len(reps)} | "
            f"{labels} | {summary['mean_ms']['iteration']:.0f} |")


HEADER = ("| experiment | classifier | labels | iterations | reps | precision | recall | accuracy | "
          "soft acc. | comp. pos / neg | failed | mislabelled | ms / it. |")


def table(out, names=None):
    """The table's lines: NAMES in that order, or every kept experiment in the listed order."""
    if not names:
        listed = os.path.join(out, "experiments.txt")
        order = open(listed).read().split() if os.path.exists(listed) else ORDER
        names = [n for n in order if os.path.exists(os.path.join(out, n, "summary.json"))]
    lines = [HEADER, "|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for name in names:
        with open(os.path.join(out, name, "summary.json")) as f:
            lines.append(row(name, json.load(f)))
    return lines


def main():
    print("\n".join(table(sys.argv[1], sys.argv[2:])))


if __name__ == "__main__":
    main()
