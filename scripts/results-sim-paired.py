#!/usr/bin/env python3
"""Each ablation of scripts/results-sim.sh against the default classifier with the choice
map (and physical labelling of the moved object against physical labelling), replication by
replication (the same seed per replication for both): the mean
difference of the final balanced accuracy (thresholded, as docs/results.md's "accuracy"),
its range, and in how many replications the default did better and worse by more than
0.005 (closer is a tie: the last iteration's accuracy moves by more from one push).

  scripts/results-sim-paired.py [KEEP_DIR]   (default docs/results/kinect)
"""
import json
import os
import sys

# (baseline, other): the experiments' suffixes after the setup's name.
COMPARISONS = (("", "-alpha1"), ("", "-paper2018"), ("", "-random"), ("", "-object"),
               ("-physical", "-physical-object"), ("", "-balanced"), ("", "-balanced-object"),
               ("-object", "-balanced-object"), ("-random", "-balanced"),
               ("-paper2018", "-balanced"), ("-random", "-balanced-object"),
               ("-paper2018", "-balanced-object"))
# What a push labels beyond its target (docs/method.md §4.5), and the exploration ablations
# under the moved labels.
LABEL_COMPARISONS = (("", "-moved"), ("", "-near"), ("-object", "-near"), ("-moved", "-near"),
                     ("-moved", "-random-moved"), ("-moved", "-paper2018-moved"),
                     ("-moved", "-physical-moved"))
TIE = 0.005


def final_accuracies(root, name):
    path = os.path.join(root, name, "summary.json")
    if not os.path.exists(path):
        return None
    with open(path) as f:
        summary = json.load(f)
    return [r["final"]["thresholded_soft"]["accuracy"] if r.get("final") else None
            for r in summary["replications"]]


def table(root, setups=None, comparisons=COMPARISONS):
    """The table's lines: each comparison whose two experiments are kept, setup by setup
    (default: every setup of ROOT/experiments.txt, in its order)."""
    if setups is None:
        with open(os.path.join(root, "experiments.txt")) as f:
            setups = [n for n in (line.strip() for line in f) if n and "-" not in n]
    lines = ["| baseline | other | mean difference (other − baseline) | range "
             "| baseline better / worse |", "|---|---|---|---|---|"]
    for setup in setups:
        for baseline, ablation in comparisons:
            default = final_accuracies(root, setup + baseline)
            other = final_accuracies(root, setup + ablation)
            if default is None or other is None:
                continue
            pairs = [(a, d) for a, d in zip(other, default) if a is not None and d is not None]
            differences = [a - d for a, d in pairs]
            better = sum(d - a > TIE for a, d in pairs)
            worse = sum(a - d > TIE for a, d in pairs)
            lines.append(f"| {setup}{baseline} | {ablation[1:]} "
                         f"| {sum(differences) / len(differences):+.3f} "
                         f"| {min(differences):+.2f} to {max(differences):+.2f} "
                         f"| {better} / {worse} of {len(pairs)} |")
    return lines


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else "docs/results/kinect"
    print("\n".join(table(root) + [""] + table(root, comparisons=LABEL_COMPARISONS)))


if __name__ == "__main__":
    main()
