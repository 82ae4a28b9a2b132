#!/usr/bin/env python3
"""Exploration rules side by side on the benchmark scenes' frames (issue 32).

For each scene, rule and replication r (seed r), relmap-cmm --active --pool-frames lets
the choice map pick `budget` samples one frame at a time, as `relmap-sim run --mode
oracle` does (the frames of `relmap-sim dataset`, labelled by the simulator), then
scores every supervoxel of the test frames (another seed: new object poses). A rule is
`NAME=CONFIG/EXPLORATION[+moved|+object]`: relmap-cmm's --config and --exploration; with
`+moved` a moveable pick also labels the rest of its object (--moved-with-target, as
PostOutcomeRequest.moved_supervoxels), with `+object` every pick labels the rest of its
object with its own label (--object-labels, as `relmap-sim run --labels object` posts
it); `uniform` is `corrected/random=1`, random
sampling. Paired: replication r of every rule sees the same
frames in the same order and the same seed.

Prints, per budget, a Markdown table: per scene and rule, mean balanced accuracy /
thresholded-soft accuracy (docs/method.md §6) and the min of balanced, then in how many
replications the rule's balanced accuracy beats `uniform` and `paper2018`.

usage: exploration-compare.py --data DIR [--scenes A,B] [--budgets 200,400]
       [--replications 10] [--rules NAME=CONFIG/EXPLORATION,...] [--jobs 2]
DIR holds <scene>-s1.csv (+ .frames) to train and <scene>-s2.csv to test, as
scripts/exploration-compare.sh exports them.
"""
import argparse
import json
import os
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor

DEFAULT_RULES = ("default=corrected/paper,novelty=corrected/novelty,"
                 "random0.2=corrected/random=0.2,novelty+random0.2=corrected/novelty,random=0.2,"
                 "uniform=corrected/random=1,paper2018=paper2018/paper,alpha1=corrected:alpha=1/paper")
BASELINES = ("uniform", "paper2018")


def parse_rules(text):
    """NAME=CONFIG/EXPLORATION items; an exploration may itself hold a comma."""
    rules, current = [], None
    for item in text.split(","):
        if "=" in item and "/" in item.split("=", 1)[1]:
            name, rest = item.split("=", 1)
            config, exploration = rest.split("/", 1)
            current = [name, config, exploration]
            rules.append(current)
        elif current is not None:
            current[2] += "," + item
        else:
            sys.exit(f"exploration-compare: rule '{item}' is not NAME=CONFIG/EXPLORATION")
    return rules


def run_one(cmm, data, scene, config, exploration, budget, seed):
    train = os.path.join(data, f"{scene}-s1.csv")
    exploration, _, labels = exploration.partition("+")
    command = [cmm, "--train", train, "--test", os.path.join(data, f"{scene}-s2.csv"),
               "--config", config, "--exploration", exploration, "--active",
               "--pool-frames", train + ".frames", "--budget", str(budget), "--seed", str(seed)]
    if labels:
        command.append({"moved": "--moved-with-target", "object": "--object-labels"}[labels])
    out = subprocess.run(command, check=True, capture_output=True, text=True).stdout
    test = json.loads(out)["test"]
    return test["balanced_accuracy"], test["thresholded_soft"]["accuracy"]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--data", required=True)
    ap.add_argument("--scenes", default="ShelfClutter,Workbench,KitchenCounter")
    ap.add_argument("--budgets", default="200,400")
    ap.add_argument("--replications", type=int, default=10)
    ap.add_argument("--rules", default=DEFAULT_RULES)
    ap.add_argument("--cmm", default="build/server/tools/relmap-cmm")
    ap.add_argument("--jobs", type=int, default=2)
    args = ap.parse_args()
    rules = parse_rules(args.rules)
    scenes = args.scenes.split(",")
    budgets = [int(b) for b in args.budgets.split(",")]
    reps = range(1, args.replications + 1)

    jobs = [(s, name, config, exploration, b, r) for b in budgets for s in scenes
            for name, config, exploration in rules for r in reps]
    results = {}
    with ThreadPoolExecutor(args.jobs) as pool:
        futures = {pool.submit(run_one, args.cmm, args.data, s, c, e, b, r): (s, n, b, r)
                   for s, n, c, e, b, r in jobs}
        for done, (future, key) in enumerate(futures.items(), 1):
            results[key] = future.result()
            print(f"\r{done}/{len(jobs)} runs", end="", file=sys.stderr, flush=True)
    print(file=sys.stderr)

    names = [name for name, _, _ in rules]
    baselines = [b for b in BASELINES if b in names]
    for b in budgets:
        print(f"\n{b} samples, {args.replications} replications:\n")
        print("| scene | " + " | ".join(names) + " |")
        print("|---|" + "---|" * len(names))
        for s in scenes:
            cells = []
            for n in names:
                bal = [results[(s, n, b, r)][0] for r in reps]
                soft = [results[(s, n, b, r)][1] for r in reps]
                wins = " ".join(
                    f"{sum(results[(s, n, b, r)][0] > results[(s, base, b, r)][0] for r in reps)}"
                    f"/{len(reps)}>{base}" for base in baselines if base != n)
                cells.append(f"{sum(bal) / len(bal):.3f} / {sum(soft) / len(soft):.3f} "
                             f"(min {min(bal):.2f}; {wins})")
            print(f"| {s} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
